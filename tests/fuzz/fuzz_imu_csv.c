/*
 * Mutation sweep of the imu_replay CSV reader (imu_csv_read, tools/imu_replay), plain host
 * build and ASan+UBSan.
 *
 * Seeds: the first 40 lines of the committed example recording, the gap example, and a
 * 7-column file without a header. Every case is read from memory (fmemopen). On success the
 * table is checked against the bytes of the mutated file itself: the row count equals the data
 * lines counted here, every row's line holds exactly cols fields that strtod reads whole to the
 * very values stored (so a NUL, a cut or a merged field cannot pass unseen), times are in
 * [0, IMU_CSV_TIME_MAX_S] and increase strictly. Certainly broken cases (NaN/inf/empty field,
 * extra field, a duplicated data row, a data row cut before its last field, a NUL/0xFF/'n' byte in
 * a data row, a line over the limit, a negative time) must be refused with a message naming the
 * line.
 */
#include "fuzz_mut.h"
#include "inclino/error.h"
#include "inclino/sim/imu_csv.h"
#include "unit.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef REPLAY_DIR
#error "REPLAY_DIR must be defined (tests/epb/replay)"
#endif

/* Line `line` (1-based) of text, trimmed as the reader trims, into buf; false when it holds NUL. */
static bool get_line(const char *text, size_t len, long line, char *buf, size_t cap)
{
    size_t e, s = fuzz_line_span(text, len, (size_t)(line - 1), &e), n;
    bool nul = false;
    if (e > s && text[e - 1] == '\n') e--;
    n = e - s < cap - 1u ? e - s : cap - 1u;
    for (size_t i = s; i < e; i++)
        nul = nul || text[i] == '\0';
    memcpy(buf, text + s, n);
    buf[n] = '\0';
    return !nul;
}

static char *trim(char *s)
{
    char *e;
    while (*s == ' ' || *s == '\t')
        s++;
    e = s + strlen(s);
    while (e > s && (e[-1] == ' ' || e[-1] == '\t' || e[-1] == '\r'))
        e--;
    *e = '\0';
    return s;
}

static bool whole_number(const char *s, double *v)
{
    char *end;
    if (*s == '\0') return false;
    *v = strtod(s, &end);
    return *end == '\0' && isfinite(*v);
}

/* Number of data rows in text, counted independently (header: the first content line when its
 * first field is not a number). */
static size_t count_data_rows(const char *text, size_t len)
{
    static char buf[8192];
    const size_t lines = fuzz_count_lines(text, len);
    size_t l, rows = 0;
    bool first = true;
    for (l = 1; l <= lines; l++) {
        char *s, *comma;
        double d;
        get_line(text, len, (long)l, buf, sizeof buf);
        s = trim(buf);
        if (*s == '\0' || *s == '#') continue;
        comma = strchr(s, ',');
        if (comma != NULL) *comma = '\0';
        if (first && !whole_number(trim(s), &d)) {
            first = false;
            continue;
        }
        first = false;
        rows++;
    }
    return rows;
}

/* Is offset pos on a data row of the seed (content, not a comment, first field a number)? */
static bool on_data_row(const char *seed, size_t len, size_t pos, size_t *start, size_t *last_comma)
{
    static char buf[8192];
    size_t s = pos, e = pos;
    char *t, *c;
    double d;
    while (s > 0 && seed[s - 1] != '\n')
        s--;
    while (e < len && seed[e] != '\n')
        e++;
    *start = s;
    *last_comma = s;
    for (size_t i = s; i < e; i++) {
        if (seed[i] == ',') *last_comma = i;
    }
    if (e - s >= sizeof buf) return false;
    memcpy(buf, seed + s, e - s);
    buf[e - s] = '\0';
    t = trim(buf);
    if (*t == '#' || *t == '\0') return false;
    c = strchr(t, ',');
    if (c != NULL) *c = '\0';
    return whole_number(t, &d);
}

static bool must_fail(const char *seed, size_t len, const struct fuzz_case *c)
{
    size_t start, lc, e;
    switch (c->family) {
    case FUZZ_BYTE: {
        const unsigned char b = fuzz_bytes[c->arg];
        if ((unsigned char)seed[c->where] == b) return false;
        return (b == 0u || b == 0xFFu || b == 'n') && on_data_row(seed, len, c->where, &start, &lc);
    }
    case FUZZ_TRUNC:
        return c->where > 0 && on_data_row(seed, len, c->where - 1u, &start, &lc) &&
               c->where <= lc + 1u && seed[c->where - 1u] != '\n';
    case FUZZ_TOKEN: {
        const char *t = fuzz_tokens[c->arg];
        if (!on_data_row(seed, len, c->where, &start, &lc)) return false;
        if (strcmp(t, "nan") == 0 || strcmp(t, "inf") == 0 || strcmp(t, "-inf") == 0 ||
            t[0] == '\0')
            return true;
        /* a negative time */
        return c->where == start && t[0] == '-' && strcmp(t, "-0") != 0;
    }
    case FUZZ_EXTRA:
    case FUZZ_DUPLINE: {
        const size_t s = fuzz_line_span(seed, len, c->where, &e);
        return s < len && on_data_row(seed, len, s, &start, &lc);
    }
    case FUZZ_LONG: return true;
    default: return false;
    }
}

static unsigned n_cases, n_ok, n_must;

static void check_table(const char *label, unsigned long k, const struct fuzz_case *c,
                        const struct imu_csv_table *t)
{
    static char buf[8192];
    size_t i;
    const size_t want_rows = count_data_rows(c->data, c->len);
    bool ok = (t->cols == 7 || t->cols == 8) && t->n >= 2u && t->n == want_rows;
    for (i = 0; ok && i < t->n; i++) {
        const struct imu_csv_row *r = &t->rows[i];
        char *fields[20], *p;
        int nf = 0, j;
        if (r->line < 1 || (i > 0 && r->line <= t->rows[i - 1].line) ||
            !get_line(c->data, c->len, r->line, buf, sizeof buf)) {
            ok = false;
            break;
        }
        p = trim(buf);
        while (nf < 20) {
            char *comma = strchr(p, ',');
            fields[nf++] = trim(p);
            if (comma == NULL) break;
            *comma = '\0';
            p = comma + 1;
        }
        ok = nf == t->cols;
        for (j = 0; ok && j < nf; j++) {
            double v;
            ok = whole_number(fields[j], &v) && v == r->v[j];
        }
        ok = ok && r->v[0] >= 0.0 && r->v[0] <= IMU_CSV_TIME_MAX_S &&
             (i == 0 || r->v[0] > t->rows[i - 1].v[0]);
        if (!ok) {
            unit_fail(__FILE__, __LINE__,
                      "%s case %lu (%s at %zu, arg %u): row %zu (line %ld) does not match "
                      "its line",
                      label, k, fuzz_family_name(c->family), c->where, c->arg, i, r->line);
            return;
        }
    }
    unit_checks++;
    if (!ok) {
        unit_fail(__FILE__, __LINE__,
                  "%s case %lu (%s at %zu, arg %u): %zu rows of %d columns, %zu data lines", label,
                  k, fuzz_family_name(c->family), c->where, c->arg, t->n, t->cols, want_rows);
    }
}

static int read_buf(const char *d, size_t len, struct imu_csv_table *t, char *msg, size_t msg_len)
{
    FILE *f = len ? fmemopen((void *)(uintptr_t)d, len, "r") : tmpfile();
    int err;
    if (f == NULL) return INC_ERR_IO;
    err = imu_csv_read(f, "in.csv", t, msg, msg_len);
    fclose(f);
    return err;
}

static void sweep(const char *label, const char *seed, size_t len)
{
    struct fuzz_case c = {NULL, 0, FUZZ_END, 0, 0};
    struct imu_csv_table t;
    char msg[600];
    unsigned long k;
    size_t stride = UNIT_SIZE(len / 300u, len / 150u);
    if (stride == 0) stride = 1;
    REQUIRE(read_buf(seed, len, &t, msg, sizeof msg) == INC_OK);
    CHECK(t.n == count_data_rows(seed, len) && t.n > 10u);
    imu_csv_free(&t);
    for (k = 0; fuzz_mutate(seed, len, k, stride, UNIT_SIZE(300u, 60u), &c) != FUZZ_END; k++) {
        const int err = read_buf(c.data, c.len, &t, msg, sizeof msg);
        n_cases++;
        if (err == INC_OK) {
            n_ok++;
            check_table(label, k, &c, &t);
        } else {
            unit_checks++;
            if (err != INC_ERR_FORMAT || t.rows != NULL || t.n != 0 ||
                (strstr(msg, "in.csv line ") == NULL && strstr(msg, "data rows") == NULL)) {
                unit_fail(__FILE__, __LINE__,
                          "%s case %lu (%s at %zu, arg %u): error %d, message '%s'", label, k,
                          fuzz_family_name(c.family), c.where, c.arg, err, msg);
            }
        }
        if (must_fail(seed, len, &c)) {
            n_must++;
            unit_checks++;
            if (err == INC_OK) {
                unit_fail(__FILE__, __LINE__,
                          "%s case %lu (%s at %zu, arg %u): a certainly broken file was "
                          "accepted",
                          label, k, fuzz_family_name(c.family), c.where, c.arg);
            }
        }
        imu_csv_free(&t);
    }
    fuzz_case_free(&c);
}

static void test_sweep(void)
{
    size_t len = 0, glen = 0, cut = 0;
    unsigned i, lines = 0;
    char *ex = fuzz_read_file(REPLAY_DIR "/example_adis16405.csv", &len);
    char *gap = fuzz_read_file(REPLAY_DIR "/gap.csv", &glen);
    static char plain[4096];
    size_t pn = 0;
    REQUIRE(ex != NULL && gap != NULL);
    while (cut < len && lines < 40u)
        lines += ex[cut++] == '\n';
    sweep("example_adis16405.csv[1..40]", ex, cut);
    sweep("gap.csv", gap, glen);
    /* 7 columns, no header, blank and comment lines between rows */
    for (i = 0; i < 30u; i++) {
        pn += (size_t)snprintf(plain + pn, sizeof plain - pn,
                               "%s%.3f,%d.5,-0.25,0,%.4f,0.01,0.99\n", i == 10 ? "\n# note\n" : "",
                               1.5 + 0.01 * i, (int)i - 15, 0.1 - 0.001 * i);
    }
    sweep("plain7", plain, pn);
    free(ex);
    free(gap);
    printf("imu_csv: %u cases, %u accepted, %u that must be refused\n", n_cases, n_ok, n_must);
    CHECK(n_cases > UNIT_SIZE(12000u, 6000u));
    CHECK(n_must > n_cases / 10u);
    CHECK(n_ok > n_cases / 10u);
}

/* Named regression inputs: each was accepted before the fix. */
static void test_regressions(void)
{
    static const struct {
        const char *text;
        size_t len; /* 0: strlen */
        const char *msg;
    } cases[] = {
        /* a NUL in the last line (no newline): read as 0.99 */
        {"0,0,0,0,0,0,1\n0.01,0,0,0,0,0,0.99\0"
         "5",
         36, "line 2: NUL byte"},
        /* negative time: undefined behaviour in the tool's conversion to uint64 ns */
        {"-0.02,0,0,0,0,0,1\n-0.01,0,0,0,0,0,1\n", 0, "line 1: time -0.02 s outside"},
        {"1e308,0,0,0,0,0,1\n2e308,0,0,0,0,0,1\n", 0, "line 1: time 1e+308 s outside"},
        /* the first row's time empty or garbled: taken for a header and dropped */
        {",0,0,0,0,0,1\n0.01,0,0,0,0,0,1\n0.02,0,0,0,0,0,1\n", 0,
         "line 1: field 1 (time) '' is not a number"},
        {"n.5,0,0,0,0,0,1\n0.01,0,0,0,0,0,1\n0.02,0,0,0,0,0,1\n", 0,
         "line 1: field 1 (time) 'n.5' is not a number"},
    };
    unsigned i;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        struct imu_csv_table t;
        char msg[600] = "";
        const size_t len = cases[i].len ? cases[i].len : strlen(cases[i].text);
        CHECK_ERR(read_buf(cases[i].text, len, &t, msg, sizeof msg), INC_ERR_FORMAT);
        if (strstr(msg, cases[i].msg) == NULL) {
            unit_fail(__FILE__, __LINE__, "case %u: message '%s', want '%s'", i, msg, cases[i].msg);
        }
        unit_checks++;
        CHECK(t.rows == NULL && t.n == 0u);
    }
    /* and the documented accepted forms still pass: header, CRLF, 8 columns */
    {
        static const char ok[] =
            "t,gx,gy,gz,ax,ay,az,temp\r\n0,0,0,0,0,0,1,25\r\n0.01,0,0,0,0,0,1,25.5\r\n";
        struct imu_csv_table t;
        char msg[600];
        REQUIRE(read_buf(ok, sizeof ok - 1u, &t, msg, sizeof msg) == INC_OK);
        CHECK_EQ_INT(t.n, 2);
        CHECK_EQ_INT(t.cols, 8);
        CHECK_EQ_INT(t.rows[1].line, 3);
        CHECK_NEAR(t.rows[1].v[7], 25.5, 0.0);
        imu_csv_free(&t);
    }
}

int main(void)
{
    UNIT_RUN(test_regressions);
    UNIT_RUN(test_sweep);
    return unit_report();
}
