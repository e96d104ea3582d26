/*
 * fx_test.h - shared helpers of the tests/fx programs: sweep density, a deterministic generator,
 * exact integer rounding references and max-error bookkeeping.
 *
 * The references are double-precision libm (glibc on the host, newlib under QEMU) for the
 * transcendental functions, and exact integer arithmetic, written independently of
 * firmware/fx, for the rounding operations.
 */
#ifndef INCLINO_FX_TEST_H
#define INCLINO_FX_TEST_H

#include <math.h>
#include <stdint.h>
#include <stdio.h>

#include "inclino/fx.h"
#include "unit.h"

/* Sweep density. The host runs the full dense sweeps; on an emulated MCU (QEMU, soft-float
 * libm, 30-100x slower) each test uses the reduced count so that it stays under ~20 s.
 * FX_DENSITY(host, target) picks one; docs/fixed-point.md lists both per test. */
#if defined(__arm__) || defined(__riscv)
#define FX_TEST_ON_TARGET 1
#else
#define FX_TEST_ON_TARGET 0
#endif
#define FX_DENSITY(host, target) (FX_TEST_ON_TARGET ? (target) : (host))

#define FXT_PI 3.14159265358979323846
#define FXT_Q16 65536.0
#define FXT_Q30 1073741824.0
/* Degrees per radian, scaled to Q16 degrees. */
#define FXT_RAD_TO_Q16DEG (180.0 / FXT_PI * FXT_Q16)

/* xorshift32: the same sequence on every target. */
static inline uint32_t fxt_rand(uint32_t *state)
{
    uint32_t x = *state;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    *state = x;
    return x;
}

/* A random int32 with a random magnitude (2^0 .. 2^31) and sign, so that every scale is hit;
 * includes INT32_MIN and INT32_MAX. */
static inline int32_t fxt_rand_scaled(uint32_t *state)
{
    uint32_t r = fxt_rand(state);
    unsigned sh = fxt_rand(state) % 32u;
    int32_t m = (int32_t)((r >> 1) >> sh); /* [0, 2^31 - 1] */
    return (r & 1u) ? -m - 1 : m;
}

/* Bit pattern -> int32 (two's complement), defined. */
static inline int32_t fxt_i32(uint32_t u)
{
    return (u & 0x80000000u) ? (int32_t)(u - 0x80000000u) + INT32_MIN : (int32_t)u;
}

/* Exact round(n / d), ties away from zero, for d > 0, by a route independent of firmware/fx:
 * floor division with a non-negative remainder, then compare 2*rem with d. |n| < 2^62. */
static inline int64_t fxt_round_div(int64_t n, int64_t d)
{
    int64_t q = n / d, rem = n % d;
    if (rem < 0) {
        q -= 1;
        rem += d;
    }
    /* n/d = q + rem/d with 0 <= rem < d */
    if (2 * rem > d || (2 * rem == d && n >= 0)) q += 1;
    return q;
}

static inline int32_t fxt_sat(int64_t v)
{
    return v > INT32_MAX ? INT32_MAX : (v < INT32_MIN ? INT32_MIN : (int32_t)v);
}

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
    while (v < 1.0) { v *= 10.0; e--; }
    while (v >= 10.0) { v /= 10.0; e++; }
    m = (long long)(v * 1000.0 + 0.5);
    if (m >= 10000) { m /= 10; e++; }
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
#define FXT_CHECK_ERR(e, bound)                                                             \
    do {                                                                                    \
        unit_checks++;                                                                      \
        if (!((e).max <= (bound)) || (e).count == 0u)                                       \
            unit_fail(__FILE__, __LINE__, "max error %.6g > bound %.6g (or no points) at (%lld, %lld)", \
                      (e).max, (double)(bound), (long long)(e).at_a, (long long)(e).at_b);  \
    } while (0)

#endif /* INCLINO_FX_TEST_H */
