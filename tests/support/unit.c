/* unit.c - see unit.h. */
#include "unit.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

unsigned unit_checks;
unsigned unit_failures;
static const char *unit_case = "(none)";

/* The command line: the --case names (pointers into argv) and --list. */
#define UNIT_MAX_SELECT 16
static const char *unit_select[UNIT_MAX_SELECT];
static bool unit_select_hit[UNIT_MAX_SELECT];
static unsigned unit_nselect;
static bool unit_list;
static bool unit_bad_args;
static unsigned unit_cases_run;

void unit_args(int argc, char **argv)
{
    int i;
    if (argv == NULL) return;
    for (i = 1; i < argc && argv[i] != NULL; i++) {
        if (strcmp(argv[i], "--list") == 0) {
            unit_list = true;
        } else if (strcmp(argv[i], "--case") == 0) {
            if (i + 1 >= argc || argv[i + 1] == NULL) {
                printf("FAIL: --case needs a case name (--list shows them)\n");
                unit_bad_args = true;
            } else if (unit_nselect == UNIT_MAX_SELECT) {
                printf("FAIL: more than %d --case options\n", UNIT_MAX_SELECT);
                unit_bad_args = true;
                i++;
            } else {
                unit_select[unit_nselect++] = argv[++i];
            }
        }
    }
}

#if defined(__GLIBC__) && !UNIT_ON_TARGET
/* glibc calls the functions of .init_array with main's argc, argv and envp, so the options are
 * known before main() runs, whatever its signature. */
static void unit_ctor(int argc, char **argv, char **envp)
{
    (void)envp;
    unit_args(argc, argv);
}
__attribute__((section(".init_array"),
               used)) static void (*const unit_ctor_entry)(int, char **, char **) = unit_ctor;
#endif

bool unit_begin(const char *name)
{
    unsigned i;
    bool run = unit_nselect == 0u;
    unit_case = name;
    for (i = 0; i < unit_nselect; i++) {
        if (strcmp(unit_select[i], name) == 0) {
            unit_select_hit[i] = true;
            run = true;
        }
    }
    if (unit_list) {
        printf("%s\n", name);
        return false;
    }
    if (run) unit_cases_run++;
    return run;
}

void unit_fail(const char *file, int line, const char *fmt, ...)
{
    va_list ap;
    unit_failures++;
    printf("FAIL %s:%d [%s] ", file, line, unit_case);
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
    printf("\n");
    fflush(stdout);
}

void unit_fail_err(const char *file, int line, const char *expr, const char *want_expr,
                   long long got, long long want)
{
    /* Codes outside int print as ERR_UNKNOWN with their value. */
    const int g = (got >= -32768 && got <= 32767) ? (int)got : 1;
    const int w = (want >= -32768 && want <= 32767) ? (int)want : 1;
    unit_fail(file, line, "%s == %s: %s (%lld) != %s (%lld)", expr, want_expr, inc_err_name(g), got,
              inc_err_name(w), want);
}

int unit_report(void)
{
    unsigned i;
    int status;
    if (unit_bad_args) {
        fflush(stdout);
        return 1;
    }
    if (unit_list) {
        fflush(stdout);
        return 0;
    }
    status = unit_failures > 125u ? 125 : (int)unit_failures;
    for (i = 0; i < unit_nselect; i++) {
        if (!unit_select_hit[i]) {
            printf("FAIL: no case named '%s' (--list shows the cases)\n", unit_select[i]);
            if (status == 0) status = 1;
        }
    }
    printf("%u cases, %u checks, %u failed\n", unit_cases_run, unit_checks, unit_failures);
    fflush(stdout);
    /* A test that checked nothing cannot fail, so it counts as a failure. */
    if (unit_checks == 0) {
        printf("FAIL: no checks ran\n");
        return 1;
    }
    return status;
}
