/*
 * test_adapt_tilt.c - the patented method end to end (inclino/adapt_tilt.h): the integer tuning
 * against the formulas of docs/kalman.md in double, a tilted sensor with noise and a gyro bias
 * (the estimate converges inside its bound), a tilt step (followed faster than a moving average
 * of the same steady-state noise), saturated axes coasting, bad input. Host and QEMU Cortex-M.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>

#include "inclino/adapt_tilt.h"
#include "unit.h"

#define DT_NS 1220703u /* 1 / 819.2 Hz */
#define DEG (3.14159265358979323846 / 180.0)
#define P_ONE 281474976710656.0 /* 2^48: P format of one unit^2 */

static int32_t q16(double v)
{
    return (int32_t)lround(v * 65536.0);
}

static uint32_t rng = 777u;
static double gauss(void)
{
    double s = 0;
    int i;
    for (i = 0; i < 4; i++)
        s += (unit_rand32(&rng) >> 8) / 16777216.0;
    return (s - 2.0) * 1.7320508;
}

static void sample(struct tilt_input *in, double roll, double pitch, double bias_dps,
                   double accel_sd, double gyro_sd)
{
    double r = roll * DEG, p = pitch * DEG;
    unsigned i;
    in->accel_g[0] = q16(-sin(p) + accel_sd * gauss());
    in->accel_g[1] = q16(sin(r) * cos(p) + accel_sd * gauss());
    in->accel_g[2] = q16(cos(r) * cos(p) + accel_sd * gauss());
    for (i = 0; i < 3u; i++)
        in->gyro_dps[i] = q16(bias_dps + gyro_sd * gauss());
    in->flags = 0u;
}

/* The integer tuning within 0.1 % of the formulas in double. */
static void test_tuning(void)
{
    struct adapt_tilt_noise nz;
    struct adapt_tilt_config cfg;
    unsigned ax;
    adapt_tilt_noise_default(&nz);
    REQUIRE(adapt_tilt_config_default(&cfg, &nz, DT_NS) == INC_OK);
    for (ax = 0; ax < KF_ADAPT_AXES; ax++) {
        const bool gyro = ax < 3u;
        const double sd = (gyro ? nz.gyro_sd_dps : nz.accel_sd_g) / 65536.0;
        const double step = ax == ADAPT_TILT_AZ
                                ? 0.0
                                : (gyro ? nz.gyro_step_dps : nz.accel_step_g) / 65536.0;
        const double a = sd * sd, ks = 2.0 / (nz.n_equiv + 1.0), qr = ks * ks * a / (1.0 - ks);
        const struct kf_adapt_config *c = &cfg.axis[ax];
        CHECK_EQ_INT(c->window, nz.window);
        CHECK_NEAR(c->a / P_ONE, a, 1e-12);
        CHECK_NEAR(c->p0 / P_ONE, a, 1e-12);
        if (step == 0.0) {
            CHECK_NEAR(c->c / P_ONE, qr, 1e-3 * qr);
            CHECK_EQ_INT(c->d, 0);
            CHECK_EQ_INT(c->b, 0);
        } else {
            const double k = nz.window,
                         mdz = sd * sqrt(2.0 / 3.14159265358979323846) * sqrt(k / (k - 1.0));
            const double cc = qr / 10.0, d = 0.9 * qr / mdz, b = -a / (cc + d * step);
            CHECK_NEAR(c->c / P_ONE, cc, 1e-3 * cc);
            CHECK_NEAR(c->d / 4294967296.0, d, 1e-3 * d); /* raw * 2^16 = unit * 2^32 */
            CHECK_NEAR(c->b / 65536.0, b, 1e-3 * fabs(b) + 1.0 / 65536.0);
        }
        CHECK(kf_adapt_config_check(c) == INC_OK);
    }
    CHECK(tilt_config_check(&cfg.tilt) == INC_OK);
    CHECK_EQ_INT(cfg.tilt.mode, TILT_MODE_FEEDBACK);
}

static void test_bad_input(void)
{
    struct adapt_tilt_noise nz;
    struct adapt_tilt_config cfg;
    struct adapt_tilt a;
    struct tilt_input in = {{0, 0, FX_Q16_ONE}, {0, 0, 0}, 0u};
    struct tilt_output out;
    adapt_tilt_noise_default(&nz);
    CHECK_EQ_INT(adapt_tilt_config_default(NULL, &nz, DT_NS), INC_ERR_NULL);
    CHECK_EQ_INT(adapt_tilt_config_default(&cfg, NULL, DT_NS), INC_ERR_NULL);
    nz.window = 1u;
    CHECK_EQ_INT(adapt_tilt_config_default(&cfg, &nz, DT_NS), INC_ERR_INVAL);
    adapt_tilt_noise_default(&nz);
    nz.accel_sd_g = 0;
    CHECK_EQ_INT(adapt_tilt_config_default(&cfg, &nz, DT_NS), INC_ERR_INVAL);
    adapt_tilt_noise_default(&nz);
    nz.gyro_sd_dps = FX_Q16_INT(51);
    CHECK_EQ_INT(adapt_tilt_config_default(&cfg, &nz, DT_NS), INC_ERR_INVAL);
    adapt_tilt_noise_default(&nz);
    CHECK_EQ_INT(adapt_tilt_config_default(&cfg, &nz, 0u), INC_ERR_INVAL);
    REQUIRE(adapt_tilt_config_default(&cfg, &nz, DT_NS) == INC_OK);
    cfg.axis[2].window = 0u;
    CHECK_EQ_INT(adapt_tilt_init(&a, &cfg), INC_ERR_INVAL);
    CHECK_EQ_INT(adapt_tilt_step(&a, &in, DT_NS, &out, NULL), INC_ERR_STATE);
    CHECK_EQ_INT(adapt_tilt_init(NULL, &cfg), INC_ERR_NULL);
    REQUIRE(adapt_tilt_config_default(&cfg, &nz, DT_NS) == INC_OK);
    REQUIRE(adapt_tilt_init(&a, &cfg) == INC_OK);
    CHECK_EQ_INT(adapt_tilt_step(&a, NULL, DT_NS, &out, NULL), INC_ERR_NULL);
    CHECK_EQ_INT(adapt_tilt_step(&a, &in, DT_NS, NULL, NULL), INC_ERR_NULL);
}

/* A sensor at roll 10, pitch -6 deg with the default part's noise and a 1 deg/s gyro bias: after
 * 20 s both angles are within 4 sigma of the truth and the bias is learnt (FEEDBACK). */
static void test_converges(void)
{
    struct adapt_tilt_noise nz;
    struct adapt_tilt_config cfg;
    struct adapt_tilt a;
    struct tilt_input in;
    struct tilt_output out;
    int32_t filt[KF_ADAPT_AXES];
    const unsigned n = 20u * 819u; /* the same on every target: convergence needs the 20 s */
    unsigned i;
    adapt_tilt_noise_default(&nz);
    REQUIRE(adapt_tilt_config_default(&cfg, &nz, DT_NS) == INC_OK);
    REQUIRE(adapt_tilt_init(&a, &cfg) == INC_OK);
    for (i = 0; i < n; i++) {
        sample(&in, 10.0, -6.0, 1.0, 0.004, 0.5);
        REQUIRE(adapt_tilt_step(&a, &in, DT_NS, &out, filt) == INC_OK);
    }
    CHECK(out.valid);
    CHECK_NEAR(out.angle_deg[TILT_ROLL] / 65536.0, 10.0,
               fmax(0.1, 4.0 * out.sigma_deg[0] / 65536.0));
    CHECK_NEAR(out.angle_deg[TILT_PITCH] / 65536.0, -6.0,
               fmax(0.1, 4.0 * out.sigma_deg[1] / 65536.0));
    CHECK_NEAR(out.bias_dps[TILT_ROLL] / 65536.0, 1.0, 0.2);
    /* The filtered accelerometer is far quieter than the input (4 mg per sample). */
    CHECK_NEAR(filt[ADAPT_TILT_AY] / 65536.0, sin(10.0 * DEG) * cos(6.0 * DEG), 0.002);
}

/* A 5 deg roll step is followed within 50 ms by the adaptive stage (the change it is tuned to
 * follow at once), where the moving average of the same noise (n = 82) needs 100 ms. */
static void test_step(void)
{
    struct adapt_tilt_noise nz;
    struct adapt_tilt_config cfg;
    struct adapt_tilt a;
    struct tilt_input in;
    struct tilt_output out;
    int32_t filt[KF_ADAPT_AXES];
    unsigned i, settle = 0u;
    const double target = sin(5.0 * DEG);
    adapt_tilt_noise_default(&nz);
    REQUIRE(adapt_tilt_config_default(&cfg, &nz, DT_NS) == INC_OK);
    REQUIRE(adapt_tilt_init(&a, &cfg) == INC_OK);
    for (i = 0; i < 2000u; i++) {
        sample(&in, 0.0, 0.0, 0.0, 0.001, 0.1);
        REQUIRE(adapt_tilt_step(&a, &in, DT_NS, &out, filt) == INC_OK);
    }
    for (i = 0; i < 400u; i++) {
        sample(&in, 5.0, 0.0, 0.0, 0.001, 0.1);
        REQUIRE(adapt_tilt_step(&a, &in, DT_NS, &out, filt) == INC_OK);
        if (settle == 0u && filt[ADAPT_TILT_AY] / 65536.0 > 0.9 * target) settle = i + 1u;
    }
    CHECK(settle > 0u);
    CHECK(settle <= 41u); /* 50 ms at 819.2 SPS */
}

/* Saturated axes coast: the filtered value holds, the angle does not jump. */
static void test_saturated(void)
{
    struct adapt_tilt_noise nz;
    struct adapt_tilt_config cfg;
    struct adapt_tilt a;
    struct tilt_input in;
    struct tilt_output out;
    int32_t filt[KF_ADAPT_AXES], held;
    unsigned i;
    adapt_tilt_noise_default(&nz);
    REQUIRE(adapt_tilt_config_default(&cfg, &nz, DT_NS) == INC_OK);
    REQUIRE(adapt_tilt_init(&a, &cfg) == INC_OK);
    for (i = 0; i < 1000u; i++) {
        sample(&in, 3.0, 0.0, 0.0, 0.002, 0.2);
        REQUIRE(adapt_tilt_step(&a, &in, DT_NS, &out, filt) == INC_OK);
    }
    held = filt[ADAPT_TILT_AY];
    for (i = 0; i < 100u; i++) {
        sample(&in, 3.0, 0.0, 0.0, 0.002, 0.2);
        in.accel_g[1] = FX_Q16_INT(18);
        in.gyro_dps[0] = FX_Q16_INT(300);
        in.flags = TILT_IN_ACCEL_SAT | TILT_IN_GYRO_SAT_X;
        REQUIRE(adapt_tilt_step(&a, &in, DT_NS, &out, filt) == INC_OK);
        CHECK_EQ_INT(filt[ADAPT_TILT_AY], held);
        CHECK((out.flags & TILT_F_ACCEL_REJECTED) != 0u);
    }
    CHECK_NEAR(out.angle_deg[TILT_ROLL] / 65536.0, 3.0, 0.3);
}

int main(void)
{
    UNIT_RUN(test_tuning);
    UNIT_RUN(test_bad_input);
    UNIT_RUN(test_converges);
    UNIT_RUN(test_step);
    UNIT_RUN(test_saturated);
    return unit_report();
}
