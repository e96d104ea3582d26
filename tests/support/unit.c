/* unit.c - see unit.h. */
#include "unit.h"

#include <stdarg.h>
#include <stdio.h>

unsigned unit_checks;
unsigned unit_failures;
static const char *unit_case = "(none)";

void unit_begin(const char *name)
{
    unit_case = name;
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

int unit_report(void)
{
    printf("%u checks, %u failed\n", unit_checks, unit_failures);
    fflush(stdout);
    /* A test that checked nothing cannot fail, so it counts as a failure. */
    if (unit_checks == 0) {
        printf("FAIL: no checks ran\n");
        return 1;
    }
    return unit_failures > 125u ? 125 : (int)unit_failures;
}
