/* test_cli.c - every rule of tools/lib/cli (inclino/tool_cli.h). */
#include "inclino/error.h"
#include "inclino/tool_cli.h"
#include "unit.h"

#include <dirent.h>
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static char dir[256];

static int has(const char *text)
{
    return strstr(cli_last_error(), text) != NULL;
}

static void path_in(char *buf, size_t size, const char *name)
{
    (void)snprintf(buf, size, "%s/%s", dir, name);
}

static void write_file(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    if (f == NULL) return;
    (void)fputs(text, f);
    (void)fclose(f);
}

static int file_is(const char *path, const char *text)
{
    char buf[256];
    size_t n;
    FILE *f = fopen(path, "r");
    if (f == NULL) return 0;
    n = fread(buf, 1, sizeof buf - 1u, f);
    (void)fclose(f);
    buf[n] = '\0';
    return strcmp(buf, text) == 0;
}

/* Number of entries in dir whose name starts with '.' and is not . or .. (temporary files). */
static int temp_files(void)
{
    int n = 0;
    struct dirent *e;
    DIR *d = opendir(dir);
    if (d == NULL) return -1;
    while ((e = readdir(d)) != NULL) {
        if (e->d_name[0] == '.' && strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0) {
            n++;
        }
    }
    (void)closedir(d);
    return n;
}

static void u64_decimal_full_field(void)
{
    uint64_t v = 7;
    CHECK_OK(cli_parse_u64("--n", "10", 0, 100, &v));
    CHECK(v == 10u);
    CHECK_OK(cli_parse_u64("--n", "010", 0, 100, &v)); /* decimal, not octal 8 */
    CHECK(v == 10u);
    CHECK_OK(cli_parse_u64("--n", "18446744073709551615", 0, UINT64_MAX, &v));
    CHECK(v == UINT64_MAX);
    v = 7;
    CHECK_ERR(cli_parse_u64("--n", "+1", 0, 100, &v), INC_ERR_INVAL);
    CHECK_ERR(cli_parse_u64("--n", " 1", 0, 100, &v), INC_ERR_INVAL);
    CHECK_ERR(cli_parse_u64("--n", "1 ", 0, 100, &v), INC_ERR_INVAL);
    CHECK_ERR(cli_parse_u64("--n", "", 0, 100, &v), INC_ERR_INVAL);
    CHECK_ERR(cli_parse_u64("--n", "0x10", 0, 100, &v), INC_ERR_INVAL);
    CHECK_ERR(cli_parse_u64("--n", "1e3", 0, 10000, &v), INC_ERR_INVAL);
    CHECK_ERR(cli_parse_u64("--n", "12abc", 0, 100, &v), INC_ERR_INVAL);
    CHECK_ERR(cli_parse_u64("--n", "-1", 0, 100, &v), INC_ERR_INVAL); /* never 2^64-1 */
    CHECK(has("--n") && has("'-1'") && has("0..100"));
    CHECK_ERR(cli_parse_u64("--n", NULL, 0, 100, &v), INC_ERR_INVAL);
    CHECK(v == 7u); /* untouched on every refusal */
}

static void u64_range(void)
{
    uint64_t v = 7;
    CHECK_ERR(cli_parse_u64("--n", "0", 1, 100, &v), INC_ERR_RANGE);
    CHECK(has("kf_test: --n: '0' is out of range (accepted: an integer in 1..100)"));
    CHECK_ERR(cli_parse_u64("--n", "101", 1, 100, &v), INC_ERR_RANGE);
    CHECK_ERR(cli_parse_u64("--n", "18446744073709551616", 0, UINT64_MAX, &v), INC_ERR_RANGE);
    CHECK_ERR(cli_parse_u64("--n", "99999999999999999999999999", 0, UINT64_MAX, &v), INC_ERR_RANGE);
    CHECK(v == 7u);
}

static void u32_and_int(void)
{
    uint32_t u = 3;
    int i = 3;
    CHECK_OK(cli_parse_u32("--cs-pin", "63", 0, 63, &u));
    CHECK(u == 63u);
    CHECK_ERR(cli_parse_u32("--cs-pin", "70000", 0, 63, &u), INC_ERR_RANGE);
    CHECK_ERR(cli_parse_u32("--cs-pin", "abc", 0, 63, &u), INC_ERR_INVAL);
    CHECK(has("--cs-pin") && has("'abc'") && has("0..63"));
    CHECK_ERR(cli_parse_u32("--x", "4294967296", 0, UINT32_MAX, &u), INC_ERR_RANGE);
    CHECK(u == 63u);
    CHECK_OK(cli_parse_int("--k", "-40", -40, 85, &i));
    CHECK_EQ_INT(i, -40);
    CHECK_ERR(cli_parse_int("--k", "-41", -40, 85, &i), INC_ERR_RANGE);
    CHECK(has("-40..85"));
    CHECK_ERR(cli_parse_int("--k", "2147483648", INT32_MIN, INT32_MAX, &i), INC_ERR_RANGE);
    CHECK_EQ_INT(i, -40);
}

static void i64_signs(void)
{
    int64_t v = 5;
    CHECK_OK(cli_parse_i64("--seed", "-9223372036854775808", INT64_MIN, INT64_MAX, &v));
    CHECK(v == INT64_MIN);
    CHECK_OK(cli_parse_i64("--seed", "9223372036854775807", INT64_MIN, INT64_MAX, &v));
    CHECK(v == INT64_MAX);
    CHECK_ERR(cli_parse_i64("--seed", "9223372036854775808", INT64_MIN, INT64_MAX, &v),
              INC_ERR_RANGE);
    CHECK_ERR(cli_parse_i64("--seed", "-9223372036854775809", INT64_MIN, INT64_MAX, &v),
              INC_ERR_RANGE);
    CHECK_ERR(cli_parse_i64("--seed", "-", INT64_MIN, INT64_MAX, &v), INC_ERR_INVAL);
    CHECK_ERR(cli_parse_i64("--seed", "--5", INT64_MIN, INT64_MAX, &v), INC_ERR_INVAL);
    CHECK_ERR(cli_parse_i64("--seed", "+5", INT64_MIN, INT64_MAX, &v), INC_ERR_INVAL);
    CHECK_ERR(cli_parse_i64("--seed", "-1", 0, 10, &v), INC_ERR_RANGE);
    CHECK(v == INT64_MAX);
}

static void double_rules(void)
{
    double d = 9.0;
    CHECK_OK(cli_parse_double("--c-frac", "0.5", 0.0, 1.0, 0, &d));
    CHECK(d == 0.5);
    CHECK_OK(cli_parse_double("--c-frac", ".25", 0.0, 1.0, 0, &d));
    CHECK(d == 0.25);
    CHECK_OK(cli_parse_double("--c-frac", "1.", 0.0, 1.0, 0, &d));
    CHECK(d == 1.0);
    CHECK_OK(cli_parse_double("--x", "-2.5e-3", -1.0, 1.0, 0, &d));
    CHECK(d == -2.5e-3);
    CHECK_OK(cli_parse_double("--x", "0e5", -1.0, 1.0, 0, &d));
    CHECK(d == 0.0);
    d = 9.0;
    CHECK_ERR(cli_parse_double("--c-frac", "nan", 0.0, 1.0, 0, &d), INC_ERR_RANGE);
    CHECK(has("--c-frac") && has("'nan'") && has("finite"));
    CHECK_ERR(cli_parse_double("--c-frac", "NaN", 0.0, 1.0, 0, &d), INC_ERR_RANGE);
    CHECK_ERR(cli_parse_double("--c-frac", "inf", 0.0, 1.0, 0, &d), INC_ERR_RANGE);
    CHECK_ERR(cli_parse_double("--c-frac", "-Infinity", 0.0, 1.0, 0, &d), INC_ERR_RANGE);
    CHECK_ERR(cli_parse_double("--x", "1e999", -HUGE_VAL, HUGE_VAL, 0, &d), INC_ERR_RANGE);
    CHECK_ERR(cli_parse_double("--x", "1e-400", -1.0, 1.0, 0, &d), INC_ERR_RANGE);
    CHECK_ERR(cli_parse_double("--x", "1e-310", -1.0, 1.0, 0, &d), INC_ERR_RANGE); /* denormal */
    CHECK_ERR(cli_parse_double("--x", "0x1p3", -100.0, 100.0, 0, &d), INC_ERR_INVAL);
    CHECK_ERR(cli_parse_double("--x", " 1", -100.0, 100.0, 0, &d), INC_ERR_INVAL);
    CHECK_ERR(cli_parse_double("--x", "+1", -100.0, 100.0, 0, &d), INC_ERR_INVAL);
    CHECK_ERR(cli_parse_double("--x", "1,5", -100.0, 100.0, 0, &d), INC_ERR_INVAL);
    CHECK_ERR(cli_parse_double("--x", ".", -100.0, 100.0, 0, &d), INC_ERR_INVAL);
    CHECK_ERR(cli_parse_double("--x", "1e", -100.0, 100.0, 0, &d), INC_ERR_INVAL);
    CHECK_ERR(cli_parse_double("--x", "", -100.0, 100.0, 0, &d), INC_ERR_INVAL);
    CHECK_ERR(cli_parse_double("--c-frac", "2", 0.0, 1.0, 0, &d), INC_ERR_RANGE);
    CHECK(has("--c-frac: '2' is out of range (accepted: a decimal number in 0..1)"));
    CHECK(d == 9.0);
    CHECK_OK(cli_parse_double("--x", "nan", 0.0, 1.0, CLI_ALLOW_NONFINITE, &d));
    CHECK(isnan(d));
    CHECK_OK(cli_parse_double("--x", "-inf", 0.0, 1.0, CLI_ALLOW_NONFINITE, &d));
    CHECK(isinf(d) && d < 0.0);
}

static void value_of_option(void)
{
    char a0[] = "tool", a1[] = "--n", a2[] = "5";
    char *argv[] = {a0, a1, a2, NULL};
    int i = 1;
    CHECK(cli_value(3, argv, &i) == argv[2]);
    CHECK_EQ_INT(i, 2);
    i = 1;
    CHECK(cli_value(2, argv, &i) == NULL);
    CHECK(has("--n needs a value"));
    CHECK_EQ_INT(i, 1);
}

static void out_new_and_replace(void)
{
    char path[512];
    struct cli_out o;
    struct stat st;
    path_in(path, sizeof path, "new.txt");
    CHECK_OK(cli_out_open(&o, "--out", path, NULL, 0));
    REQUIRE(o.f != NULL);
    CHECK(access(path, F_OK) != 0); /* nothing at the target before the commit */
    CHECK(fprintf(o.f, "hello\n") > 0);
    CHECK_OK(cli_out_close(&o));
    CHECK(o.f == NULL);
    CHECK(file_is(path, "hello\n"));
    CHECK_EQ_INT(temp_files(), 0);
    /* an existing regular file is replaced and keeps its mode */
    REQUIRE(chmod(path, 0640) == 0);
    CHECK_OK(cli_out_open(&o, "--out", path, NULL, 0));
    REQUIRE(o.f != NULL);
    (void)fputs("again\n", o.f);
    CHECK_OK(cli_out_close(&o));
    CHECK(file_is(path, "again\n"));
    REQUIRE(stat(path, &st) == 0);
    CHECK_EQ_INT((int)(st.st_mode & 0777), 0640);
    /* discarded: the target is unchanged, no temporary file left */
    CHECK_OK(cli_out_open(&o, "--out", path, NULL, 0));
    REQUIRE(o.f != NULL);
    (void)fputs("half", o.f);
    cli_out_discard(&o);
    CHECK(file_is(path, "again\n"));
    CHECK_EQ_INT(temp_files(), 0);
    CHECK_OK(cli_out_close(&o)); /* not open: nothing to do */
}

static void out_refuses_non_regular(void)
{
    char path[512], link[512], target[512];
    struct cli_out o;
    struct stat st;
    path_in(path, sizeof path, "fifo");
    REQUIRE(mkfifo(path, 0600) == 0);
    CHECK_ERR(cli_out_open(&o, "--out", path, NULL, 0), INC_ERR_IO);
    CHECK(o.f == NULL);
    CHECK(has("--out") && has("a FIFO") && has("refusing"));
    REQUIRE(lstat(path, &st) == 0);
    CHECK(S_ISFIFO(st.st_mode));
    (void)unlink(path);

    path_in(target, sizeof target, "real.txt");
    path_in(link, sizeof link, "link.txt");
    write_file(target, "keep\n");
    REQUIRE(symlink(target, link) == 0);
    CHECK_ERR(cli_out_open(&o, "--out", link, NULL, 0), INC_ERR_IO);
    CHECK(has("a symbolic link"));
    CHECK(file_is(target, "keep\n"));
    REQUIRE(lstat(link, &st) == 0);
    CHECK(S_ISLNK(st.st_mode));
    (void)unlink(link);
    (void)unlink(target);

    CHECK_ERR(cli_out_open(&o, "--out", "/dev/null", NULL, 0), INC_ERR_IO);
    CHECK(has("a character device"));
    CHECK_ERR(cli_out_open(&o, "--out", dir, NULL, 0), INC_ERR_IO);
    CHECK(has("a directory"));
    CHECK_ERR(cli_out_open(&o, "--out", "", NULL, 0), INC_ERR_INVAL);
    CHECK_ERR(cli_out_open(&o, "--out", "/nonexistent-dir-xyz/out.txt", NULL, 0), INC_ERR_IO);
    CHECK(has("cannot create"));
    CHECK_EQ_INT(temp_files(), 0);
}

static void out_refuses_an_input(void)
{
    char in[512], hard[512], other[512];
    struct cli_out o;
    const char *inputs[3];
    path_in(in, sizeof in, "in.vcd");
    path_in(hard, sizeof hard, "hard.vcd");
    path_in(other, sizeof other, "other.txt");
    write_file(in, "input\n");
    write_file(other, "other\n");
    REQUIRE(link(in, hard) == 0);
    inputs[0] = NULL;
    inputs[1] = "-";
    inputs[2] = in;
    CHECK_ERR(cli_out_open(&o, "OUT", in, inputs, 3), INC_ERR_INVAL);
    CHECK(has("same file as the input"));
    CHECK_ERR(cli_out_open(&o, "OUT", hard, inputs, 3), INC_ERR_INVAL); /* same inode */
    CHECK(file_is(in, "input\n"));
    CHECK_OK(cli_out_open(&o, "OUT", other, inputs, 3));
    CHECK_OK(cli_out_close(&o));
    CHECK(file_is(other, ""));
    (void)unlink(in);
    (void)unlink(hard);
    (void)unlink(other);
}

/* ENOSPC for real: the temporary file's descriptor is pointed at /dev/full. */
static void out_full_disk_file(void)
{
    char path[512];
    struct cli_out o;
    int full;
    path_in(path, sizeof path, "full.txt");
    write_file(path, "old\n");
    CHECK_OK(cli_out_open(&o, "--out", path, NULL, 0));
    REQUIRE(o.f != NULL);
    full = open("/dev/full", O_WRONLY);
    REQUIRE(full >= 0);
    REQUIRE(dup2(full, fileno(o.f)) >= 0);
    (void)close(full);
    (void)fputs("new contents\n", o.f);
    CHECK_ERR(cli_out_close(&o), INC_ERR_IO);
    CHECK(has("write error") && has("full.txt") && has("No space left"));
    CHECK(file_is(path, "old\n"));
    CHECK_EQ_INT(temp_files(), 0); /* the temporary file was removed */
}

/* stdout on a full disk: "-" and cli_stdout_check report it. */
static void out_full_disk_stdout(void)
{
    struct cli_out o;
    int saved, full;
    (void)fflush(stdout);
    saved = dup(fileno(stdout));
    full = open("/dev/full", O_WRONLY);
    REQUIRE(saved >= 0 && full >= 0);
    REQUIRE(dup2(full, fileno(stdout)) >= 0);
    (void)close(full);
    CHECK_OK(cli_out_open(&o, "--out", "-", NULL, 0));
    CHECK(o.f == stdout);
    (void)fputs("data\n", o.f);
    {
        const int rc = cli_out_close(&o);
        (void)dup2(saved, fileno(stdout));
        clearerr(stdout);
        CHECK_ERR(rc, INC_ERR_IO);
    }
    CHECK(has("standard output"));
    full = open("/dev/full", O_WRONLY);
    REQUIRE(full >= 0);
    REQUIRE(dup2(full, fileno(stdout)) >= 0);
    (void)close(full);
    (void)fputs("more\n", stdout);
    {
        const int rc = cli_stdout_check();
        (void)dup2(saved, fileno(stdout));
        clearerr(stdout);
        CHECK_ERR(rc, INC_ERR_IO);
    }
    (void)close(saved);
    CHECK_OK(cli_stdout_check());
}

int main(void)
{
    char cmd[300];
    (void)snprintf(dir, sizeof dir, "/tmp/inclino_cli.XXXXXX");
    if (mkdtemp(dir) == NULL) return 1;
    cli_set_program("/some/path/kf_test");
    cli_set_quiet(1);
    UNIT_RUN(u64_decimal_full_field);
    UNIT_RUN(u64_range);
    UNIT_RUN(u32_and_int);
    UNIT_RUN(i64_signs);
    UNIT_RUN(double_rules);
    UNIT_RUN(value_of_option);
    UNIT_RUN(out_new_and_replace);
    UNIT_RUN(out_refuses_non_regular);
    UNIT_RUN(out_refuses_an_input);
    UNIT_RUN(out_full_disk_file);
    UNIT_RUN(out_full_disk_stdout);
    (void)snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    (void)system(cmd);
    return unit_report();
}
