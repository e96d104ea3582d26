/*
 * Host benchmark driver for callgrind instruction counts of the 3D attitude estimator and the
 * per-axis estimators (benches/att/bench_att.sh). `bench_att <case>` runs WARM + BENCH_N samples
 * of the integer-generated motion of benches/att/bench_att_cm.c (noise on 1 g, triangle rates of
 * +-300 deg/s from sample 1000) through one estimator at 285.7 Hz; callgrind counts only the
 * named function, which the driver calls through a wrapper only for the BENCH_N samples after
 * the warm-up (the wrapper's name is what bench_att.sh counts), so the count per call is the
 * steady-state cost per sample. Not a test: it checks nothing (the tests are tests/att).
 */
#include <stdio.h>
#include <string.h>

#include "inclino/adapt_tilt.h"
#include "inclino/att.h"
#include "inclino/tilt.h"

#define BENCH_N 100000
#define WARM 2000
#define DT_NS 3500000u
#define RATE_Q16 18724571

static uint32_t lcg = 12345u;
static volatile int32_t sink;
static struct att est;
static struct tilt tl;
static struct adapt_tilt ad;

static void gen(struct att_sample *s, int k)
{
    int i;
    memset(s, 0, sizeof *s);
    for (i = 0; i < 3; i++) {
        const int32_t per = 2000 * (i + 2) / 2, ph = k % per;
        const int32_t tri = ph < per / 2 ? ph : per - ph;
        const int32_t rate = k > 1000 ? (tri * 4 - per) * (300 * 65536 / per) : 0;
        lcg = lcg * 1664525u + 1013904223u;
        s->gyro_dps[i] = (int32_t)(lcg >> 9) - (1 << 22) + rate;
        lcg = lcg * 1664525u + 1013904223u;
        s->acc_g[i] = ((int32_t)(lcg >> 16) - 32768) / 8 + (i == 2 ? 65536 : 0);
    }
}

/* The counted wrappers (callgrind --toggle-collect=<name>): called only after the warm-up. */
__attribute__((noinline)) int32_t bench_att_update(const struct att_sample *s);
__attribute__((noinline)) int32_t bench_att_update(const struct att_sample *s)
{
    return att_update(&est, s);
}

__attribute__((noinline)) int32_t bench_att_quat(void);
__attribute__((noinline)) int32_t bench_att_quat(void)
{
    int32_t q[4];
    att_get_quat(&est, q);
    return q[0];
}

__attribute__((noinline)) int32_t bench_att_euler(void);
__attribute__((noinline)) int32_t bench_att_euler(void)
{
    fx_q16_t r, p;
    att_get_euler(&est, &r, &p);
    return r + p;
}

__attribute__((noinline)) int32_t bench_tilt_step(const struct tilt_input *t);
__attribute__((noinline)) int32_t bench_tilt_step(const struct tilt_input *t)
{
    struct tilt_output o;
    (void)tilt_step(&tl, t, DT_NS, &o);
    return o.angle_deg[0];
}

__attribute__((noinline)) int32_t bench_adapt_tilt_step(const struct tilt_input *t);
__attribute__((noinline)) int32_t bench_adapt_tilt_step(const struct tilt_input *t)
{
    struct tilt_output o;
    (void)adapt_tilt_step(&ad, t, DT_NS, &o, NULL);
    return o.angle_deg[0];
}

int main(int argc, char **argv)
{
    static struct tilt_config tc;
    struct att_config c;
    struct adapt_tilt_noise nz;
    struct adapt_tilt_config ac;
    const char *k = argc > 1 ? argv[1] : "";
    int n, i, which;
    if (strcmp(k, "update") == 0)
        which = 0;
    else if (strcmp(k, "quat") == 0)
        which = 1;
    else if (strcmp(k, "euler") == 0)
        which = 2;
    else if (strcmp(k, "tilt") == 0)
        which = 3;
    else if (strcmp(k, "adapt") == 0)
        which = 4;
    else {
        fprintf(stderr, "usage: bench_att update|quat|euler|tilt|adapt\n");
        return 1;
    }
    (void)att_config_default(&c, RATE_Q16);
    (void)att_init(&est, &c);
    (void)tilt_config_default(&tc, DT_NS);
    tc.mode = TILT_MODE_FEEDBACK;
    (void)tilt_init(&tl, &tc);
    adapt_tilt_noise_default(&nz);
    (void)adapt_tilt_config_default(&ac, &nz, DT_NS);
    (void)adapt_tilt_init(&ad, &ac);
    for (n = 0; n < WARM + BENCH_N; n++) {
        struct att_sample s;
        struct tilt_input t;
        const int counted = n >= WARM;
        gen(&s, n);
        for (i = 0; i < 3; i++) {
            t.accel_g[i] = s.acc_g[i];
            t.gyro_dps[i] = s.gyro_dps[i];
        }
        t.flags = 0;
        if (which <= 2) {
            if (which == 0 && counted)
                sink += bench_att_update(&s);
            else
                sink += att_update(&est, &s);
            if (which == 1 && counted) sink += bench_att_quat();
            if (which == 2 && counted) sink += bench_att_euler();
        } else if (which == 3) {
            if (counted)
                sink += bench_tilt_step(&t);
            else {
                struct tilt_output o;
                (void)tilt_step(&tl, &t, DT_NS, &o);
            }
        } else {
            if (counted)
                sink += bench_adapt_tilt_step(&t);
            else {
                struct tilt_output o;
                (void)adapt_tilt_step(&ad, &t, DT_NS, &o, NULL);
            }
        }
    }
    return 0;
}
