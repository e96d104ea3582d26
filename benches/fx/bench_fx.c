/*
 * bench_fx.c - host benchmark driver for base/fx (not a test; see benches/fx/bench_fx.sh).
 *
 * Calls each function BENCH_N times over representative inputs prepared beforehand, so that
 * valgrind --tool=callgrind --collect-atstart=no --toggle-collect=<function> counts only the
 * instructions executed inside that function (and its callees). The inline helpers of fx.h are
 * measured through the noinline wrappers bench_<name> (their count includes the wrapper's ret).
 * Usage: bench_fx [function]   (no argument: run every function once over its inputs)
 */
#include <stdio.h>
#include <string.h>

#include "inclino/fx.h"
#include "unit.h"

#define BENCH_N 100000

static int32_t in_a[BENCH_N], in_b[BENCH_N], in_deg[BENCH_N], in_ratio[BENCH_N], in_acc[BENCH_N];
static uint32_t in_u32[BENCH_N];
static uint64_t in_u64[BENCH_N];
static volatile int64_t sink;
static struct fx_sum acc;

static int32_t i32(uint32_t u)
{
    return (u & 0x80000000u) ? (int32_t)(u - 0x80000000u) + INT32_MIN : (int32_t)u;
}

static void prepare(void)
{
    uint32_t s = 0x2468ACEu;
    int i;
    for (i = 0; i < BENCH_N; i++) {
        /* a, b: random values with random magnitudes */
        in_a[i] = fx_asr32(i32(unit_rand32(&s)), unit_rand32(&s) % 24u);
        in_b[i] = fx_asr32(i32(unit_rand32(&s)), unit_rand32(&s) % 24u) | 1;
        in_u32[i] = unit_rand32(&s);
        in_u64[i] = ((uint64_t)unit_rand32(&s) << 32) | unit_rand32(&s);
        in_deg[i] = fx_asr32(i32(unit_rand32(&s)), 6);   /* about +-360 deg in Q16 */
        in_ratio[i] = fx_asr32(i32(unit_rand32(&s)), 1); /* [-1, 1) in Q30 */
        in_acc[i] = fx_asr32(i32(unit_rand32(&s)), 14);  /* +-2 g in Q16 */
        acc.sum += in_a[i]; /* filled directly: fx_sum_add is itself measured */
    }
    acc.count = BENCH_N;
}

/* Wrappers for the inline functions, so that callgrind can toggle on a symbol. */
__attribute__((noinline)) int32_t bench_fx_add(int32_t a, int32_t b);
__attribute__((noinline)) int32_t bench_fx_add(int32_t a, int32_t b)
{
    return fx_add(a, b);
}
__attribute__((noinline)) int32_t bench_fx_asr32(int32_t a, unsigned s);
__attribute__((noinline)) int32_t bench_fx_asr32(int32_t a, unsigned s)
{
    return fx_asr32(a, s);
}
__attribute__((noinline)) int32_t bench_fx_abs(int32_t a);
__attribute__((noinline)) int32_t bench_fx_abs(int32_t a)
{
    return fx_abs(a);
}

int main(int argc, char **argv)
{
    const char *only = argc > 1 ? argv[1] : NULL;
    int i;
    int32_t q;
    fx_q30_t s, c;
#define RUN(name, expr)                            \
    if (only == NULL || strcmp(only, name) == 0) { \
        for (i = 0; i < BENCH_N; i++)              \
            sink += (expr);                        \
    }
    prepare();
    RUN("bench_fx_add", bench_fx_add(in_a[i], in_b[i]));
    RUN("bench_fx_asr32", bench_fx_asr32(in_a[i], (unsigned)i & 31u));
    RUN("bench_fx_abs", bench_fx_abs(in_a[i]));
    RUN("fx_rshift_round32", fx_rshift_round32(in_a[i], (unsigned)i & 31u));
    RUN("fx_rshift_round64", fx_rshift_round64((int64_t)in_a[i] * in_b[i], (unsigned)i & 63u));
    RUN("fx_mul_q16", fx_mul_q16(in_a[i], in_b[i]));
    RUN("fx_mul_q30", fx_mul_q30(in_a[i], in_b[i]));
    RUN("fx_mul_shift", fx_mul_shift(in_a[i], in_b[i], (unsigned)i & 31u));
    RUN("fx_div", fx_div(in_a[i], in_b[i], 16, &q) + q);
    RUN("fx_sum_add", fx_sum_add(&acc, in_a[i]));
    RUN("fx_sum_mean", fx_sum_mean(&acc, &q) + q);
    RUN("fx_isqrt32", fx_isqrt32(in_u32[i]));
    RUN("fx_isqrt64", fx_isqrt64(in_u64[i]));
    RUN("fx_isqrt64_round", fx_isqrt64_round(in_u64[i] >> 2));
    RUN("fx_sqrt_q16", fx_sqrt_q16(in_a[i] & INT32_MAX));
    RUN("fx_sqrt_q30", fx_sqrt_q30(in_ratio[i] & INT32_MAX));
    RUN("fx_atan2_deg", fx_atan2_deg(in_acc[i], in_acc[(i + 1) % BENCH_N]));
    RUN("fx_asin_deg", fx_asin_deg(in_ratio[i]));
    RUN("fx_sin_deg", fx_sin_deg(in_deg[i]));
    RUN("fx_cos_deg", fx_cos_deg(in_deg[i]));
    if (only == NULL || strcmp(only, "fx_sincos_deg") == 0) {
        for (i = 0; i < BENCH_N; i++) {
            fx_sincos_deg(in_deg[i], &s, &c);
            sink += s + c;
        }
    }
    printf("calls per function: %d\n", BENCH_N);
    return 0;
}
