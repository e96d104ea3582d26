/*
 * bench_fx_cm.c - instruction counts of base/fx on Cortex-M under QEMU (not a test).
 *
 * QEMU does not model the DWT cycle counter, but with -icount shift=S,align=off its virtual
 * time advances 2^S ns per executed instruction, and the mps2-an385/an386 SysTick, clocked by the
 * 25 MHz processor clock, then counts instructions * 2^S / 40 (docs/benchmarks.md, "Cortex-M"). Each function
 * runs BENCH_CM_N times over prepared inputs; the same loop around an empty noinline function of
 * the same signature is subtracted, both called from the same loop code (loop2/loop1 below), so
 * the figure is the function's own instructions per call less the empty function's two (callee
 * side, without the caller's loop, argument set-up and call). Instructions, not cycles.
 * Run with benches/fx/bench_fx_cm.sh <cross build dir>.
 */
#include <stdio.h>

#include "inclino/fx.h"
#include "unit.h"

#define BENCH_CM_N 256
#define SYST_CSR (*(volatile uint32_t *)0xE000E010u)
#define SYST_RVR (*(volatile uint32_t *)0xE000E014u)
#define SYST_CVR (*(volatile uint32_t *)0xE000E018u)

static int32_t in_a[BENCH_CM_N], in_b[BENCH_CM_N], in_deg[BENCH_CM_N], in_ratio[BENCH_CM_N];
static int32_t in_acc[BENCH_CM_N], in_pos[BENCH_CM_N], in_rpos[BENCH_CM_N];
static int32_t in_acc2[BENCH_CM_N];
static uint32_t in_u32[BENCH_CM_N];
static volatile int32_t sink;

static int32_t i32(uint32_t u)
{
    return (u & 0x80000000u) ? (int32_t)(u - 0x80000000u) + INT32_MIN : (int32_t)u;
}

/* Baselines: same signatures, no work. */
__attribute__((noinline)) static int32_t empty2(int32_t a, int32_t b)
{
    __asm__ volatile("" ::: "memory");
    return a ^ b;
}

__attribute__((noinline)) static int32_t empty1(int32_t a)
{
    __asm__ volatile("" ::: "memory");
    return a;
}

__attribute__((noinline)) static uint32_t empty1u(uint32_t a)
{
    __asm__ volatile("" ::: "memory");
    return a;
}

static void ticks_reset(void)
{
    SYST_CSR = 0;
    SYST_RVR = 0x00FFFFFFu;
    SYST_CVR = 0;
    SYST_CSR = 5u; /* ENABLE | CLKSOURCE = processor clock, no interrupt */
}

static uint32_t ticks_now(void)
{
    return SYST_CVR;
}

/*
 * One timed loop per signature. The function under test and its baseline run through the SAME
 * loop code (one function, called through a pointer), so the instructions around the call -
 * loads, the accumulate, the loop counter, the call itself - are identical in both runs and
 * cancel exactly. (Two copies of the loop, one per callee, let gcc allocate registers
 * differently: on the M0+ the baseline loop re-made its bound inside the loop, two
 * instructions more than the measured one, and every figure read 2 low.) noipa keeps gcc from
 * cloning the loop for a known callee, which would bring the two copies back.
 */
typedef int32_t (*bench_fn2)(int32_t, int32_t);
typedef int32_t (*bench_fn1)(int32_t);
typedef uint32_t (*bench_fn1u)(uint32_t);

__attribute__((noipa)) static uint32_t loop2(bench_fn2 fn, const int32_t *a, const int32_t *b)
{
    uint32_t t0, t1;
    int i;
    t0 = ticks_now();
    for (i = 0; i < BENCH_CM_N; i++)
        sink += fn(a[i], b[i]);
    t1 = ticks_now();
    return (t0 - t1) & 0xFFFFFFu; /* SysTick counts down */
}

__attribute__((noipa)) static uint32_t loop1(bench_fn1 fn, const int32_t *a)
{
    uint32_t t0, t1;
    int i;
    t0 = ticks_now();
    for (i = 0; i < BENCH_CM_N; i++)
        sink += fn(a[i]);
    t1 = ticks_now();
    return (t0 - t1) & 0xFFFFFFu;
}

__attribute__((noipa)) static uint32_t loop1u(bench_fn1u fn, const uint32_t *a)
{
    uint32_t t0, t1;
    int i;
    t0 = ticks_now();
    for (i = 0; i < BENCH_CM_N; i++)
        sink += (int32_t)fn(a[i]);
    t1 = ticks_now();
    return (t0 - t1) & 0xFFFFFFu;
}

#define MEASURE2(name, fn, A, B)                                                  \
    do {                                                                          \
        uint32_t m_, b_;                                                          \
        ticks_reset();                                                            \
        m_ = loop2(fn, A, B);                                                     \
        b_ = loop2(empty2, A, B);                                                 \
        printf("BENCH %s %lu %lu\n", name, (unsigned long)m_, (unsigned long)b_); \
    } while (0)

#define MEASURE1(name, fn, A)                                                     \
    do {                                                                          \
        uint32_t m_, b_;                                                          \
        ticks_reset();                                                            \
        m_ = loop1(fn, A);                                                        \
        b_ = loop1(empty1, A);                                                    \
        printf("BENCH %s %lu %lu\n", name, (unsigned long)m_, (unsigned long)b_); \
    } while (0)

#define MEASURE1U(name, fn, A)                                                    \
    do {                                                                          \
        uint32_t m_, b_;                                                          \
        ticks_reset();                                                            \
        m_ = loop1u(fn, A);                                                       \
        b_ = loop1u(empty1u, A);                                                  \
        printf("BENCH %s %lu %lu\n", name, (unsigned long)m_, (unsigned long)b_); \
    } while (0)

static int32_t div_q16(int32_t a, int32_t b)
{
    int32_t q = 0;
    (void)fx_div_q16(a, b, &q);
    return q;
}

int main(void)
{
    uint32_t s = 0x2468ACEu;
    int i;
    for (i = 0; i < BENCH_CM_N; i++) {
        in_a[i] = fx_asr32(i32(unit_rand32(&s)), unit_rand32(&s) % 24u);
        in_b[i] = fx_asr32(i32(unit_rand32(&s)), unit_rand32(&s) % 24u) | 1;
        in_u32[i] = unit_rand32(&s);
        in_deg[i] = fx_asr32(i32(unit_rand32(&s)), 6);
        in_ratio[i] = fx_asr32(i32(unit_rand32(&s)), 1);
        in_acc[i] = fx_asr32(i32(unit_rand32(&s)), 14);
        in_pos[i] = in_a[i] & INT32_MAX;
        in_rpos[i] = in_ratio[i] & INT32_MAX;
    }
    for (i = 0; i < BENCH_CM_N; i++)
        in_acc2[i] = in_acc[(i + 1) % BENCH_CM_N]; /* as bench_fx.c */
    printf("BENCH_N %d\n", BENCH_CM_N);
    MEASURE2("fx_mul_q16", fx_mul_q16, in_a, in_b);
    MEASURE2("fx_mul_q30", fx_mul_q30, in_a, in_b);
    MEASURE2("fx_div", div_q16, in_a, in_b); /* fx_div(a, b, 16, &q) plus a 4-argument wrapper */
    MEASURE1U("fx_isqrt32", fx_isqrt32, in_u32);
    MEASURE1("fx_sqrt_q16", fx_sqrt_q16, in_pos);
    MEASURE1("fx_sqrt_q30", fx_sqrt_q30, in_rpos);
    MEASURE2("fx_atan2_deg", fx_atan2_deg, in_acc, in_acc2);
    MEASURE1("fx_asin_deg", fx_asin_deg, in_ratio);
    MEASURE1("fx_sin_deg", fx_sin_deg, in_deg);
    MEASURE1("fx_cos_deg", fx_cos_deg, in_deg);
    return 0;
}
