/*
 * bench_att_cm.c - instructions per update of the 3D attitude estimator on Cortex-M under QEMU
 * (not a test), beside the per-axis estimators on the same inputs.
 *
 * The method of benches/kf/bench_kf_cm.c (cmake/scripts/bench_icount.sh): with -icount
 * shift=6,align=off SysTick (25 MHz) counts instructions * 64 / 40. Inputs are integer-generated
 * at 285.7 Hz (the BROAD rate), the generator of tests/att/test_att_bitident.c: LCG noise
 * (gyro +-64 deg/s, accel +-0.06 g) on 1 g, plus (motion case) from sample 3000 triangle rates of
 * +-300 deg/s on the three axes (motion). Each estimator first runs WARM samples (past att's
 * init phase of tau_acc = 3 s: steady state; the warm-up is not counted), then BENCH_N = 256
 * consecutive updates are timed (in chunks of 32, summed), minus the same loop around an empty
 * function:
 *   att_update rest     at rest (no rotation, noise only), WARM = 2000 samples (7 s)
 *   att_update motion   rotating, after WARM = 4000 samples (1000 of them rotating)
 *   att_get_quat, att_get_euler   the getters after the motion block (output rate)
 *   att_update worst single       the largest single update of the motion block (timed one by
 *                                 one; printed as BENCH_N x that update so the script's
 *                                 per-iteration formula yields it)
 *   tilt_step FEEDBACK, adapt_tilt_step   the per-axis filter att replaces as the default and the
 *                                 patented method (adapt_tilt, defaults), on the same motion block
 * Instructions, not cycles. Run with benches/att/bench_att_cm.sh <dir> [machine].
 */
#include <stdbool.h>
#include <stdio.h>
#include <string.h>

#include "inclino/adapt_tilt.h"
#include "inclino/att.h"
#include "inclino/tilt.h"
#include "unit.h"

#define BENCH_N 256
#define WARM_REST 2000
#define WARM_MOTION 4000
#define DT_NS 3500000u    /* 285.714 Hz */
#define RATE_Q16 18724571 /* the same in Q16 Hz */
#define SYST_CSR (*(volatile uint32_t *)0xE000E010u)
#define SYST_RVR (*(volatile uint32_t *)0xE000E014u)
#define SYST_CVR (*(volatile uint32_t *)0xE000E018u)

static struct att_sample in[BENCH_N];
static struct tilt_input tin[BENCH_N];
static struct att est;
static struct tilt tl;
static struct adapt_tilt ad;
static volatile int32_t sink;
static uint32_t lcg;

static void gen(struct att_sample *s, int k, int rot_from)
{
    int i;
    memset(s, 0, sizeof *s);
    for (i = 0; i < 3; i++) {
        const int32_t per = 2000 * (i + 2) / 2, ph = k % per;
        const int32_t tri = ph < per / 2 ? ph : per - ph;
        const int32_t rate = k > rot_from ? (tri * 4 - per) * (300 * 65536 / per) : 0;
        lcg = lcg * 1664525u + 1013904223u;
        s->gyro_dps[i] = (int32_t)(lcg >> 9) - (1 << 22) + rate;
        lcg = lcg * 1664525u + 1013904223u;
        s->acc_g[i] = ((int32_t)(lcg >> 16) - 32768) / 8 + (i == 2 ? 65536 : 0);
    }
}

static void to_tilt(const struct att_sample *s, struct tilt_input *t)
{
    int i;
    for (i = 0; i < 3; i++) {
        t->accel_g[i] = s->acc_g[i];
        t->gyro_dps[i] = s->gyro_dps[i];
    }
    t->flags = 0;
}

__attribute__((noinline)) static int32_t empty(int i)
{
    __asm__ volatile("" ::: "memory");
    return in[i].gyro_dps[0];
}

__attribute__((noinline)) static int32_t up_att(int i)
{
    return att_update(&est, &in[i]);
}

__attribute__((noinline)) static int32_t get_quat(int i)
{
    int32_t q[4];
    (void)i;
    att_get_quat(&est, q);
    return q[0] + q[3];
}

__attribute__((noinline)) static int32_t get_euler(int i)
{
    fx_q16_t r, p;
    (void)i;
    att_get_euler(&est, &r, &p);
    return r + p;
}

__attribute__((noinline)) static int32_t up_tilt(int i)
{
    struct tilt_output o;
    (void)tilt_step(&tl, &tin[i], DT_NS, &o);
    return o.angle_deg[0];
}

__attribute__((noinline)) static int32_t up_adapt(int i)
{
    struct tilt_output o;
    (void)adapt_tilt_step(&ad, &tin[i], DT_NS, &o, NULL);
    return o.angle_deg[0];
}

static void ticks_reset(void)
{
    SYST_CSR = 0;
    SYST_RVR = 0x00FFFFFFu;
    SYST_CVR = 0;
    SYST_CSR = 5u;
}

/* BENCH_N calls in chunks of CHUNK, each timed on its own (SysTick has 24 bits: 2^24 ticks are
 * 10.5 M instructions, less than 256 updates of adapt_tilt_step on an M0+), the ticks summed. */
#define CHUNK 32
static uint32_t block(int32_t (*fn)(int))
{
    uint32_t sum = 0;
    int i, j;
    for (j = 0; j < BENCH_N; j += CHUNK) {
        uint32_t t0, t1;
        ticks_reset();
        t0 = SYST_CVR;
        for (i = j; i < j + CHUNK; i++)
            sink += fn(i);
        t1 = SYST_CVR;
        sum += (t0 - t1) & 0xFFFFFFu;
    }
    return sum;
}

static void report(const char *name, uint32_t t, uint32_t base)
{
    printf("BENCH %s %lu %lu\n", name, (unsigned long)t, (unsigned long)base);
}

/* att warmed up on the generated sequence to sample `warm`, the next BENCH_N samples in in[] */
static void prepare(int warm, int rot_from)
{
    struct att_config c;
    struct att_sample s;
    int k;
    lcg = 12345u;
    (void)att_config_default(&c, RATE_Q16);
    (void)att_init(&est, &c);
    for (k = 0; k < warm; k++) {
        gen(&s, k, rot_from);
        (void)att_update(&est, &s);
    }
    for (k = 0; k < BENCH_N; k++) {
        gen(&in[k], warm + k, rot_from);
        to_tilt(&in[k], &tin[k]);
    }
}

int main(void)
{
    static struct tilt_config tc;
    struct adapt_tilt_noise nz;
    struct adapt_tilt_config ac;
    uint32_t base;
    int k, rc_tilt = 0, rc_adapt = 0, rc_init;
    printf("BENCH_N %d\n", BENCH_N);
    base = block(empty);

    prepare(WARM_REST, 1 << 30); /* never rotating */
    report("att_update rest", block(up_att), base);

    prepare(WARM_MOTION, WARM_MOTION - 1000);
    report("att_update motion", block(up_att), base);
    report("att_get_quat", block(get_quat), base);
    report("att_get_euler", block(get_euler), base);

    /* the same motion block again, one update at a time: the worst single update */
    prepare(WARM_MOTION, WARM_MOTION - 1000);
    {
        uint32_t t0, t1, b1, mx = 0, sum = 0;
        int kmax = 0, nover = 0;
        ticks_reset();
        t0 = SYST_CVR;
        sink += empty(0);
        t1 = SYST_CVR;
        b1 = (t0 - t1) & 0xFFFFFFu;
        for (k = 0; k < BENCH_N; k++) {
            uint32_t d;
            ticks_reset();
            t0 = SYST_CVR;
            sink += up_att(k);
            t1 = SYST_CVR;
            d = (t0 - t1) & 0xFFFFFFu;
            if (d > mx) {
                mx = d;
                kmax = k;
            }
            sum += d;
            if ((d - b1) * 40u / 64u > 2000u) nover++;
        }
        report("att_update worst single (motion)", mx * BENCH_N, b1 * BENCH_N);
        printf("NOTE worst single at block sample %d (of %d); %d of them above 2000 instructions; "
               "mean of the single updates %lu\n",
               kmax, BENCH_N, nover, (unsigned long)((sum - b1 * BENCH_N) * 40u / 64u / BENCH_N));
    }

    /* the per-axis estimators on the same motion block, warmed up on the same sequence */
    (void)tilt_config_default(&tc, DT_NS);
    tc.mode = TILT_MODE_FEEDBACK;
    (void)tilt_init(&tl, &tc);
    adapt_tilt_noise_default(&nz);
    rc_init = adapt_tilt_config_default(&ac, &nz, DT_NS);
    rc_init |= adapt_tilt_init(&ad, &ac);
    lcg = 12345u;
    for (k = 0; k < WARM_MOTION; k++) {
        struct att_sample s;
        struct tilt_input t;
        struct tilt_output o;
        gen(&s, k, WARM_MOTION - 1000);
        to_tilt(&s, &t);
        rc_tilt |= tilt_step(&tl, &t, DT_NS, &o);
        rc_adapt |= adapt_tilt_step(&ad, &t, DT_NS, &o, NULL);
    }
    printf("NOTE warm-up return codes: tilt_step %d, adapt_tilt_step %d (init %d)\n", rc_tilt,
           rc_adapt, rc_init);
    report("tilt_step FEEDBACK", block(up_tilt), base);
    report("adapt_tilt_step", block(up_adapt), base);
    return 0;
}
