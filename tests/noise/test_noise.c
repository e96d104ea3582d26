/*
 * The seeded error models of sim/noise.h: configuration checks, reproducibility, each term's
 * statistics (white density, random-walk increments, quantisation step, constant and thermal
 * bias exactly), the Gauss-Markov flicker layout and its flat Allan floor, the analytic Allan
 * variance in its limits, and the ADIS1636x/1640x preset against [ADI-IMU-QS]'s curve.
 * Sizes are small enough for QEMU (the long Allan runs are in tests/allan, host only).
 */
#include "inclino/error.h"
#include "inclino/sim/noise.h"
#include "unit.h"

#include <math.h>
#include <string.h>

#define DT_ADIS (1.0 / 819.2)

/* Samples per statistics check: fewer under QEMU (soft-float doubles on Cortex-M3 are slow);
 * the tolerances below scale with the count (6 sigma of the estimate), so both stay tight. */
#if UNIT_REDUCED
#define STAT_N 10000
#else
#define STAT_N 40000
#endif
#define SD_TOL (6.0 / sqrt(2.0 * STAT_N)) /* relative sd of a sample sd, times 6 */

static void test_config_rejected(void)
{
    struct sim_noise n;
    struct sim_noise_cfg cfg;
    memset(&cfg, 0, sizeof(cfg));
    CHECK_ERR(sim_noise_init(NULL, &cfg), INC_ERR_NULL);
    CHECK_ERR(sim_noise_init(&n, NULL), INC_ERR_NULL);
    CHECK_OK(sim_noise_init(&n, &cfg));
    cfg.ch[1].white = -0.1;
    CHECK_ERR(sim_noise_init(&n, &cfg), INC_ERR_INVAL);
    cfg.ch[1].white = NAN;
    CHECK_ERR(sim_noise_init(&n, &cfg), INC_ERR_INVAL);
    cfg.ch[1].white = 0.0;
    cfg.ch[4].bias_instability = 0.01; /* no correlation-time range */
    CHECK_ERR(sim_noise_init(&n, &cfg), INC_ERR_INVAL);
    cfg.ch[4].bi_tc_min_s = 10.0;
    cfg.ch[4].bi_tc_max_s = 5.0; /* reversed */
    CHECK_ERR(sim_noise_init(&n, &cfg), INC_ERR_INVAL);
    cfg.ch[4].bi_tc_max_s = 10.0 * 2e5; /* > 5 decades */
    CHECK_ERR(sim_noise_init(&n, &cfg), INC_ERR_INVAL);
    cfg.ch[4].bi_tc_max_s = 10.0 * 1e5; /* exactly 5 decades: 16 components */
    CHECK_OK(sim_noise_init(&n, &cfg));
    CHECK_EQ_INT(n.ch[4].n_gm, 16);
    cfg.ch[4].rrw = -1e-3;
    CHECK_ERR(sim_noise_init(&n, &cfg), INC_ERR_INVAL);
    cfg.ch[4].rrw = 0.0;
    cfg.temp_white_c = -1.0;
    CHECK_ERR(sim_noise_init(&n, &cfg), INC_ERR_INVAL);
}

/* An all-zero configuration is the ideal part: out == in, bit for bit. */
static void test_ideal(void)
{
    struct sim_noise n;
    struct sim_noise_cfg cfg;
    struct sim_inertial_input in, out;
    struct sim_error_model hook;
    memset(&cfg, 0, sizeof(cfg));
    REQUIRE(sim_noise_init(&n, &cfg) == INC_OK);
    hook = sim_noise_hook(&n);
    CHECK(hook.apply == sim_noise_apply);
    CHECK(hook.ctx == &n);
    sim_inertial_at_rest(&in);
    in.rate_dps[0] = 12.5;
    in.accel_g[1] = -0.25;
    in.temp_c = 40.0;
    in.supply_v = 4.9;
    hook.apply(hook.ctx, &in, &out, 0, DT_ADIS);
    CHECK(memcmp(&in, &out, sizeof(in)) == 0);
}

/* Constant bias and temperature coefficient are exact (no randomness in them). */
static void test_bias_and_temperature(void)
{
    struct sim_noise n;
    struct sim_noise_cfg cfg;
    struct sim_inertial_input in, out;
    memset(&cfg, 0, sizeof(cfg));
    cfg.ch[SIM_NOISE_GYRO(2)].bias = 0.5;
    cfg.ch[SIM_NOISE_GYRO(2)].temp_coeff = -0.01;
    cfg.ch[SIM_NOISE_ACCEL(0)].bias = 0.002;
    REQUIRE(sim_noise_init(&n, &cfg) == INC_OK);
    sim_inertial_at_rest(&in);
    in.temp_c = 45.0;
    sim_noise_apply(&n, &in, &out, 0, DT_ADIS);
    CHECK_NEAR(out.rate_dps[2], 0.5 - 0.01 * 20.0, 1e-15);
    CHECK_NEAR(out.accel_g[0], 0.002, 1e-18);
    CHECK_NEAR(out.rate_dps[0], 0.0, 0.0);
    CHECK_NEAR(sim_noise_bias_now(&n, SIM_NOISE_GYRO(2)), 0.3, 1e-15);
    CHECK_NEAR(sim_noise_bias_now(&n, 99), 0.0, 0.0);
    CHECK_EQ_INT(n.samples, 1);
}

/* Same seed, same stream (bit-identical); another seed, another stream. */
static void test_reproducible(void)
{
    static struct sim_noise a, b, c;
    struct sim_noise_cfg cfg;
    struct sim_inertial_input in, oa, ob, oc;
    int k, same = 1, differ = 0;
    sim_noise_adis_cfg(&cfg, 7);
    cfg.temp_white_c = 0.05;
    REQUIRE(sim_noise_init(&a, &cfg) == INC_OK);
    REQUIRE(sim_noise_init(&b, &cfg) == INC_OK);
    cfg.seed = 8;
    REQUIRE(sim_noise_init(&c, &cfg) == INC_OK);
    sim_inertial_at_rest(&in);
    for (k = 0; k < 500; k++) {
        sim_noise_apply(&a, &in, &oa, 0, DT_ADIS);
        sim_noise_apply(&b, &in, &ob, 0, DT_ADIS);
        sim_noise_apply(&c, &in, &oc, 0, DT_ADIS);
        same &= memcmp(&oa, &ob, sizeof(oa)) == 0;
        differ |= oa.rate_dps[0] != oc.rate_dps[0];
    }
    CHECK(same);
    CHECK(differ);
    CHECK(oa.temp_c != 25.0);
    CHECK_NEAR(oa.supply_v, 5.0, 0.0);
}

/* White noise: per-sample sd = N / sqrt(dt) within 6 sigma of the estimate (2.1 % on the host,
 * 4.2 % under QEMU); the mean within 4 sigma. */
static void test_white_density(void)
{
    static struct sim_noise n;
    struct sim_noise_cfg cfg;
    const double dt = 0.01, nd = 0.2;
    double s = 0.0, s2 = 0.0, sd;
    int k;
    const int cnt = STAT_N;
    memset(&cfg, 0, sizeof(cfg));
    cfg.ch[0].white = nd;
    cfg.seed = 3;
    REQUIRE(sim_noise_init(&n, &cfg) == INC_OK);
    for (k = 0; k < cnt; k++) {
        const double v = sim_noise_step(&n, 0, 0.0, 25.0, dt);
        s += v;
        s2 += v * v;
    }
    sd = sqrt(s2 / cnt - (s / cnt) * (s / cnt));
    CHECK_NEAR(sd, nd / sqrt(dt), SD_TOL * nd / sqrt(dt));
    CHECK_NEAR(s / cnt, 0.0, 4.0 * (nd / sqrt(dt)) / sqrt((double)cnt));
    /* no correlated bias with white noise only */
    CHECK_NEAR(sim_noise_bias_now(&n, 0), 0.0, 0.0);
}

/* Rate random walk: the correlated bias moves by N(0, K^2 dt) per sample, starting at 0. */
static void test_random_walk(void)
{
    static struct sim_noise n;
    struct sim_noise_cfg cfg;
    const double dt = 0.1, k_rrw = 0.01;
    double prev, s2 = 0.0, sd;
    int k;
    const int cnt = STAT_N;
    memset(&cfg, 0, sizeof(cfg));
    cfg.ch[3].rrw = k_rrw;
    cfg.seed = 4;
    REQUIRE(sim_noise_init(&n, &cfg) == INC_OK);
    CHECK_NEAR(sim_noise_step(&n, 3, 1.0, 25.0, dt), 1.0, 0.0); /* x[0] = 0 */
    prev = sim_noise_bias_now(&n, 3);
    for (k = 0; k < cnt; k++) {
        double b;
        (void)sim_noise_step(&n, 3, 0.0, 25.0, dt);
        b = sim_noise_bias_now(&n, 3);
        s2 += (b - prev) * (b - prev);
        prev = b;
    }
    sd = sqrt(s2 / cnt);
    CHECK_NEAR(sd, k_rrw * sqrt(dt), SD_TOL * k_rrw * sqrt(dt));
}

/* Quantisation: every output is a whole multiple of the step (half away from zero), and with
 * noise much larger than the step the mean is kept. */
static void test_quantum(void)
{
    static struct sim_noise n;
    struct sim_noise_cfg cfg;
    const double q = 0.25;
    double s = 0.0;
    int k, whole = 1;
    const int cnt = STAT_N / 2;
    memset(&cfg, 0, sizeof(cfg));
    cfg.ch[1].white = 0.2;
    cfg.ch[1].quantum = q;
    cfg.seed = 5;
    REQUIRE(sim_noise_init(&n, &cfg) == INC_OK);
    for (k = 0; k < cnt; k++) {
        const double v = sim_noise_step(&n, 1, 0.3, 25.0, 0.01);
        const double c = v / q;
        whole &= c == floor(c);
        s += v;
    }
    CHECK(whole);
    CHECK_NEAR(s / cnt, 0.3, 4.0 * 2.0 / sqrt((double)cnt));
    /* exact rounding on a noiseless channel */
    memset(&cfg, 0, sizeof(cfg));
    cfg.ch[0].quantum = 0.25;
    REQUIRE(sim_noise_init(&n, &cfg) == INC_OK);
    CHECK_NEAR(sim_noise_step(&n, 0, 0.37, 25.0, 0.01), 0.25, 0.0);
    CHECK_NEAR(sim_noise_step(&n, 0, 0.125, 25.0, 0.01), 0.25, 0.0); /* tie: away from zero */
    CHECK_NEAR(sim_noise_step(&n, 0, -0.125, 25.0, 0.01), -0.25, 0.0);
    CHECK_NEAR(sim_noise_step(&n, 0, 0.1249, 25.0, 0.01), 0.0, 0.0);
}

/* Gauss-Markov layout: 3 per decade, geometric, and the analytic floor of the sum is flat at
 * 0.664 B within 3 % over [10 tc_min, tc_max / 4]. */
static void test_gm_layout(void)
{
    struct sim_noise_axis ax;
    double tc[SIM_NOISE_GM_MAX], sigma, t;
    unsigned n_gm;
    memset(&ax, 0, sizeof(ax));
    ax.bias_instability = 0.01;
    ax.bi_tc_min_s = 0.5;
    ax.bi_tc_max_s = 2000.0;
    REQUIRE(sim_noise_gm_layout(&ax, &n_gm, tc, &sigma) == INC_OK);
    CHECK_EQ_INT(n_gm, 12); /* ceil(3 * log10(4000)) + 1 */
    CHECK_NEAR(tc[0], 0.5, 1e-12);
    CHECK_NEAR(tc[11], 2000.0, 1e-9);
    CHECK_NEAR(tc[1] / tc[0], tc[11] / tc[10], 1e-9);
    CHECK(sigma > 0.0);
    for (t = 5.0; t <= 500.0; t *= 1.25) {
        CHECK_NEAR(sim_noise_adev(&ax, t, DT_ADIS), 0.664 * 0.01, 0.03 * 0.664 * 0.01);
    }
    /* outside the band it rolls off (a single component's slope +1/2 far below tc_min) */
    CHECK(sim_noise_adev(&ax, 0.05, DT_ADIS) < 0.5 * 0.664 * 0.01);
    ax.bias_instability = 0.0;
    REQUIRE(sim_noise_gm_layout(&ax, &n_gm, tc, &sigma) == INC_OK);
    CHECK_EQ_INT(n_gm, 0);
    CHECK_ERR(sim_noise_gm_layout(NULL, &n_gm, tc, &sigma), INC_ERR_NULL);
}

/* Analytic Allan variance in its limits: white N^2/tau, random walk K^2 tau/3, one
 * Gauss-Markov component 2 s^2 tau / (3 tc) for tau << tc and 2 s^2 tc / tau for tau >> tc. */
static void test_avar_limits(void)
{
    struct sim_noise_axis ax;
    double tc[SIM_NOISE_GM_MAX], sigma;
    unsigned n_gm;
    memset(&ax, 0, sizeof(ax));
    ax.white = 0.03;
    CHECK_NEAR(sim_noise_avar(&ax, 4.0, 0.01), 0.03 * 0.03 / 4.0, 1e-18);
    ax.white = 0.0;
    ax.rrw = 0.002;
    CHECK_NEAR(sim_noise_avar(&ax, 30.0, 0.01), 0.002 * 0.002 * 10.0, 1e-18);
    ax.rrw = 0.0;
    ax.quantum = 0.05;
    CHECK_NEAR(sim_noise_avar(&ax, 1.0, 0.01), 0.05 * 0.05 / 12.0 * 0.01, 1e-18);
    ax.quantum = 0.0;
    CHECK(sim_noise_avar(&ax, 0.0, 0.01) < 0.0);
    CHECK(sim_noise_avar(&ax, 1.0, 0.0) < 0.0);
    CHECK(sim_noise_avar(NULL, 1.0, 0.01) < 0.0);
    /* A two-component layout (tc 1 and 2 s, narrow band); check the limits of the sum. */
    ax.bias_instability = 0.01;
    ax.bi_tc_min_s = 1.0;
    ax.bi_tc_max_s = 2.0;
    REQUIRE(sim_noise_gm_layout(&ax, &n_gm, tc, &sigma) == INC_OK);
    REQUIRE(n_gm == 2u);
    {
        const double s2 = sigma * sigma;
        const double small = 1e-3, big = 1e4;
        CHECK_NEAR(sim_noise_avar(&ax, small, 0.01),
                   s2 * (2.0 * small / 3.0) * 1.5, /* 1/tc1 + 1/tc2 = 1 + 1/2 */
                   0.01 * s2 * small);
        CHECK_NEAR(sim_noise_avar(&ax, big, 0.01), s2 * 2.0 * (1.0 + 2.0) / big,
                   0.01 * s2 * 6.0 / big);
        /* the series / closed-form switch at x = 1e-4 is continuous */
        CHECK_NEAR(sim_noise_avar(&ax, 0.99999e-4, 0.01), sim_noise_avar(&ax, 1.00001e-4, 0.01),
                   1e-4 * sim_noise_avar(&ax, 1e-4, 0.01));
    }
}

/* The ADIS1636x/1640x gyro preset against the Allan curve behind [ADI-IMU-QS] (figure 6). */
static void test_adis_preset(void)
{
    struct sim_noise_axis ax;
    double t, best = 1.0, tbest = 0.0;
    sim_noise_adis_gyro_axis(&ax);
    CHECK_NEAR(sim_noise_adev(&ax, 0.15, DT_ADIS), 0.080, 0.004);   /* seed: about 0.08 */
    CHECK_NEAR(sim_noise_adev(&ax, 30.0, DT_ADIS), 0.0074, 0.0002); /* seed: about 0.008 */
    CHECK_NEAR(sim_noise_adev(&ax, 100.0, DT_ADIS), 0.0061, 0.0002);
    for (t = 10.0; t < 1000.0; t *= 1.03) {
        const double v = sim_noise_adev(&ax, t, DT_ADIS);
        if (v < best) {
            best = v;
            tbest = t;
        }
    }
    CHECK_NEAR(best, 0.006, 0.0003);      /* seed: minimum about 0.006 */
    CHECK(tbest > 80.0 && tbest < 160.0); /* seed: near 100 s */
    /* [ADI-IMU-QS]: unfiltered gyro noise below 1 deg/s rms */
    CHECK(ax.white / sqrt(DT_ADIS) < 1.0);
    CHECK_NEAR(ax.white / sqrt(DT_ADIS), 0.887, 0.005);
}

int main(void)
{
    UNIT_RUN(test_config_rejected);
    UNIT_RUN(test_ideal);
    UNIT_RUN(test_bias_and_temperature);
    UNIT_RUN(test_reproducible);
    UNIT_RUN(test_white_density);
    UNIT_RUN(test_random_walk);
    UNIT_RUN(test_quantum);
    UNIT_RUN(test_gm_layout);
    UNIT_RUN(test_avar_limits);
    UNIT_RUN(test_adis_preset);
    return unit_report();
}
