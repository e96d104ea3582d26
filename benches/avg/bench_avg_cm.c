/*
 * bench_avg_cm.c - instructions per sample of the averaging filters and the stillness/thermal
 * detectors on Cortex-M under QEMU (not a test; benches/avg/bench_avg_cm.sh runs it).
 *
 * With -icount shift=S,align=off QEMU's virtual time advances 2^S ns per executed instruction
 * and the mps2 SysTick (25 MHz processor clock) counts instructions x 2^S / 40
 * (docs/benchmarks.md, "Cortex-M"). Each case pushes BENCH_N prepared samples through one filter; the same
 * loop around an empty noinline function of the same signature is subtracted, so the figure is
 * the push function's own instructions per sample (callee side). Instructions, not cycles.
 */
#include <stdio.h>
#include <string.h>

#include "inclino/avg.h"
#include "inclino/still.h"
#include "bench_avg_cfg.h"
#include "unit.h"

#define BENCH_N 1024u
#define SYST_CSR (*(volatile uint32_t *)0xE000E010u)
#define SYST_RVR (*(volatile uint32_t *)0xE000E014u)
#define SYST_CVR (*(volatile uint32_t *)0xE000E018u)

static int32_t in[BENCH_N], in3[BENCH_N][6];
static int32_t line[1024];
static int64_t lines[4 * 64];
static struct avg_bartlett bt;
static struct still st;
static struct still_thermal th;
static volatile int32_t sink;

static void ticks_reset(void)
{
    SYST_CSR = 0;
    SYST_RVR = 0x00FFFFFFu;
    SYST_CVR = 0;
    SYST_CSR = 5u; /* ENABLE | CLKSOURCE = processor clock */
}

static uint32_t ticks(void)
{
    return 0x00FFFFFFu - SYST_CVR;
}

/* Baselines with the push functions' shapes. */
__attribute__((noinline)) static int empty4(const void *p, int32_t x, int32_t *y, bool *f)
{
    __asm__ volatile("" ::: "memory");
    *y = x;
    *f = p != NULL;
    return 0;
}

__attribute__((noinline)) static int empty5(const void *p, int32_t x, int32_t *y, bool *r, bool *f)
{
    __asm__ volatile("" ::: "memory");
    *y = x;
    *r = *f = p != NULL;
    return 0;
}

__attribute__((noinline)) static int empty_still(const void *p, const int32_t *g, const int32_t *a,
                                                 bool *f)
{
    __asm__ volatile("" ::: "memory");
    *f = p != NULL && g != a;
    return 0;
}

__attribute__((noinline)) static int empty_th(const void *p, int32_t t, bool *f)
{
    __asm__ volatile("" ::: "memory");
    *f = p != NULL && t != 0;
    return 0;
}

/* Ticks of BENCH_N calls of FN(STATE, in[i], &y, &f). */
#define RUN4(FN, STATE, OUT)                   \
    do {                                       \
        int32_t y_ = 0;                        \
        bool f_ = false;                       \
        uint32_t i_;                           \
        ticks_reset();                         \
        for (i_ = 0; i_ < BENCH_N; i_++) {     \
            (void)FN(STATE, in[i_], &y_, &f_); \
        }                                      \
        (OUT) = ticks();                       \
        sink = y_;                             \
    } while (0)

static void report(const char *name, uint32_t t, uint32_t base)
{
    printf("BENCH %s %lu %lu\n", name, (unsigned long)t, (unsigned long)base);
}

int main(void)
{
    struct avg_block b;
    struct avg_moving m;
    struct avg_cascade c;
    uint32_t i, s = 2463534242u, t, base4, base5, t0;
    int32_t y = 0;
    bool f = false, r = false;
    for (i = 0; i < BENCH_N; i++) {
        unsigned k;
        (void)unit_rand32(&s);
        in[i] = (int32_t)(s >> 18) - 8192;
        for (k = 0; k < 6u; k++) {
            in3[i][k] = (int32_t)((s >> (k * 4u)) & 31u) - 16 + (k == 5u ? 1000 : 0);
        }
    }
    printf("BENCH_N %u\n", (unsigned)BENCH_N);
    RUN4(empty4, (void *)&b, base4);

    (void)avg_block_init(&b, 1024);
    RUN4(avg_block_push, &b, t);
    report("avg_block_push(N=1024)", t, base4);
    (void)avg_moving_init(&m, line, 1024, 64);
    RUN4(avg_moving_push, &m, t);
    report("avg_moving_push(W=64)", t, base4);
    (void)avg_moving_init(&m, line, 1024, 50);
    RUN4(avg_moving_push, &m, t);
    report("avg_moving_push(W=50)", t, base4);
    (void)avg_cascade_init(&c, lines, 4 * 64, 16, 4);
    RUN4(avg_cascade_push, &c, t);
    report("avg_cascade_push(W=16,P=4)", t, base4);
    (void)avg_cascade_init(&c, lines, 4 * 64, 10, 2);
    RUN4(avg_cascade_push, &c, t);
    report("avg_cascade_push(W=10,P=2)", t, base4);

    ticks_reset();
    for (i = 0; i < BENCH_N; i++) {
        (void)empty5(&bt, in[i], &y, &r, &f);
    }
    base5 = ticks();
    (void)avg_bartlett_init(&bt, 6, 1);
    ticks_reset();
    for (i = 0; i < BENCH_N; i++) {
        (void)avg_bartlett_push(&bt, in[i], &y, &r, &f);
    }
    report("avg_bartlett_push(M=6,D=1)", ticks(), base5);
    (void)avg_bartlett_init(&bt, 4, 16);
    ticks_reset();
    for (i = 0; i < BENCH_N; i++) {
        (void)avg_bartlett_push(&bt, in[i], &y, &r, &f);
    }
    report("avg_bartlett_push(M=4,D=16)", ticks(), base5);

    {
        struct still_cfg cfg;
        bench_still_cfg(&cfg);
        (void)still_init(&st, &cfg);
        ticks_reset();
        for (i = 0; i < BENCH_N; i++) {
            (void)empty_still(&st, &in3[i][0], &in3[i][3], &f);
        }
        t0 = ticks();
        ticks_reset();
        for (i = 0; i < BENCH_N; i++) {
            (void)still_push(&st, &in3[i][0], &in3[i][3], &f);
        }
        report("still_push(W=819,all_tests)", ticks(), t0);
    }
    {
        (void)still_thermal_init(&th, &bench_thermal_cfg);
        ticks_reset();
        for (i = 0; i < BENCH_N; i++) {
            (void)empty_th(&th, in[i], &f);
        }
        t0 = ticks();
        ticks_reset();
        for (i = 0; i < BENCH_N; i++) {
            (void)still_thermal_push(&th, in[i], &f);
        }
        report("still_thermal_push(avg_n=819,span=30)", ticks(), t0);
    }
    return 0;
}
