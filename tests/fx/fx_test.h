/*
 * fx_test.h - helpers of the tests/fx sweep programs: everything of fx_test_int.h plus max-error
 * bookkeeping against double-precision references (libm: glibc on the host, newlib under QEMU).
 */
#ifndef INCLINO_FX_TEST_H
#define INCLINO_FX_TEST_H

#include <math.h>

#include "fx_test_int.h"

#define FXT_PI 3.14159265358979323846
#define FXT_Q16 65536.0
#define FXT_Q30 1073741824.0
/* Degrees per radian, scaled to Q16 degrees. */
#define FXT_RAD_TO_Q16DEG (180.0 / FXT_PI * FXT_Q16)

/* Worst error of a sweep and where it happened. */
struct fxt_err {
    double max;
    double at_a, at_b;
    unsigned long count;
};

static inline void fxt_err_add(struct fxt_err *e, double err, double a, double b)
{
    err = fabs(err);
    e->count++;
    if (err > e->max) {
        e->max = err;
        e->at_a = a;
        e->at_b = b;
    }
}

/* Print a non-negative double with 6 decimals using integer formatting only (newlib-nano's
 * printf has no %f). */
static inline void fxt_print_fixed(double v)
{
    long long micro = (long long)(v * 1e6 + 0.5);
    printf("%lld.%06lld", micro / 1000000, micro % 1000000);
}

/* Print a non-negative double as d.ddde[+-]N, integer formatting only. */
static inline void fxt_print_sci(double v)
{
    int e = 0;
    long long m;
    if (!(v > 0.0)) {
        printf("0");
        return;
    }
    while (v < 1.0) {
        v *= 10.0;
        e--;
    }
    while (v >= 10.0) {
        v /= 10.0;
        e++;
    }
    m = (long long)(v * 1000.0 + 0.5);
    if (m >= 10000) {
        m /= 10;
        e++;
    }
    printf("%lld.%03llde%d", m / 1000, m % 1000, e);
}

/* "MEASURED name: max |error| = X LSB = Y unit over N points, worst at (a, b)" */
static inline void fxt_report(const char *name, const struct fxt_err *e, double lsb_in_unit,
                              const char *unit)
{
    printf("MEASURED %s: max |error| = ", name);
    fxt_print_fixed(e->max);
    printf(" LSB = ");
    fxt_print_sci(e->max * lsb_in_unit);
    printf("%s%s over %lu points, worst at (%lld, %lld)\n", unit[0] ? " " : "", unit, e->count,
           (long long)e->at_a, (long long)e->at_b);
    fflush(stdout);
}

/* Assert a sweep's worst error against its bound, naming the worst input on failure. */
#define FXT_CHECK_ERR(e, bound)                                                              \
    do {                                                                                     \
        unit_checks++;                                                                       \
        if (!((e).max <= (bound)) || (e).count == 0u)                                        \
            unit_fail(__FILE__, __LINE__,                                                    \
                      "max error %.6g > bound %.6g (or no points) at (%lld, %lld)", (e).max, \
                      (double)(bound), (long long)(e).at_a, (long long)(e).at_b);            \
    } while (0)

#endif /* INCLINO_FX_TEST_H */
