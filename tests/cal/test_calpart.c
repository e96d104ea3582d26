/* The simulated calibration part (sim/calpart.h): curve formula, the paper's magnitudes after
 * normalisation, hysteresis branches, the error-model formula, determinism. Host and QEMU. */
#include "inclino/sim/calpart.h"
#include "unit.h"

#include <math.h>
#include <string.h>

static void test_tcurve_formula(void)
{
    const struct sim_calpart_tcurve c = {0.01, 0.02, 10.0, 40.0, 0.003, -0.001, 0.0002};
    /* At the centre the Lorentz term is the full height; u = (10 - 20) / 40 = -0.25. */
    CHECK_NEAR(sim_calpart_tcurve_eval(&c, 10.0, 0.0),
               0.01 + 0.02 + 0.003 * -0.25 - 0.001 * -0.015625, 1e-15);
    /* Half a width away: half the height (FWHM); u = 0.25. Hysteresis +1 adds hyst. */
    CHECK_NEAR(sim_calpart_tcurve_eval(&c, 30.0, 1.0),
               0.01 + 0.01 + 0.003 * 0.25 - 0.001 * 0.015625 + 0.0002, 1e-15);
    CHECK_NEAR(sim_calpart_tcurve_eval(&c, 30.0, -1.0) - sim_calpart_tcurve_eval(&c, 30.0, 1.0),
               -0.0004, 1e-15);
}

static void test_paper_magnitudes(void)
{
    struct sim_calpart_params p;
    int a;
    sim_calpart_paper(&p);
    for (a = 0; a < 3; a++) {
        /* [TEMP-LORENTZ]: raw bias spread 14 mg, scale factor 151.6 ppm/degC over -20..60 degC. */
        CHECK_NEAR(sim_calpart_bias_spread(&p, a), 0.014, 1e-12);
        CHECK_NEAR(sim_calpart_scale_ppm_per_c(&p, a), 151.6, 1e-6);
        /* Falling bias with temperature, like the paper's fig. 1. */
        CHECK(sim_calpart_tcurve_eval(&p.acc_bias[a], -20.0, 0.0) >
              sim_calpart_tcurve_eval(&p.acc_bias[a], 60.0, 0.0));
        CHECK_NEAR(p.acc_bias[a].hyst, 0.0001, 1e-15);
    }
    sim_calpart_seeded(&p, 2);
    for (a = 0; a < 3; a++) {
        CHECK_NEAR(sim_calpart_bias_spread(&p, a), 0.014, 1e-12);
        CHECK_NEAR(sim_calpart_scale_ppm_per_c(&p, a), 151.6, 1e-6);
        CHECK(p.acc_bias[a].hyst >= 0.00005 && p.acc_bias[a].hyst <= 0.0001);
    }
}

static void test_seeds_differ(void)
{
    struct sim_calpart_params a, b, c;
    sim_calpart_seeded(&a, 2);
    sim_calpart_seeded(&b, 3);
    sim_calpart_seeded(&c, 2);
    CHECK(a.acc_bias[0].centre_c != b.acc_bias[0].centre_c);
    CHECK(memcmp(&a, &c, sizeof a) == 0);
}

static void test_hysteresis(void)
{
    struct sim_calpart_params p;
    struct sim_calpart part;
    struct sim_inertial_input in, out;
    sim_calpart_ideal(&p);
    p.acc_bias[0].hyst = 0.001;
    p.hyst_travel_c = 4.0;
    sim_calpart_init(&part, &p, 1);
    sim_inertial_at_rest(&in);
    in.accel_g[2] = 0.0;
    sim_calpart_apply(&part, &in, &out, 0, 0.001);
    CHECK_NEAR(out.accel_g[0], 0.0, 1e-15); /* m = 0 at start */
    in.temp_c += 1.0;                       /* heating 1 degC: m = 2 * 1 / 4 = 0.5 */
    sim_calpart_apply(&part, &in, &out, 0, 0.001);
    CHECK_NEAR(part.m, 0.5, 1e-15);
    CHECK_NEAR(out.accel_g[0], 0.0005, 1e-15);
    in.temp_c += 10.0; /* saturates at the heating branch */
    sim_calpart_apply(&part, &in, &out, 0, 0.001);
    CHECK_NEAR(out.accel_g[0], 0.001, 1e-15);
    in.temp_c -= 2.0; /* cooling 2 degC: back to 0 */
    sim_calpart_apply(&part, &in, &out, 0, 0.001);
    CHECK_NEAR(part.m, 0.0, 1e-15);
    in.temp_c -= 3.0;
    sim_calpart_apply(&part, &in, &out, 0, 0.001);
    CHECK_NEAR(out.accel_g[0], -0.001, 1e-15);
    sim_calpart_set_hysteresis(&part, 7.0);
    CHECK_NEAR(part.m, 1.0, 0.0);
}

static void test_error_formula(void)
{
    struct sim_calpart_params p;
    struct sim_calpart part;
    struct sim_inertial_input in, out;
    struct sim_error_model em;
    double x;
    sim_calpart_ideal(&p);
    p.acc_bias[1].y0 = 0.02;
    p.acc_scale[1].y0 = 1.03;
    p.acc_axis[1][0] = 0.01; /* element y senses a little of x */
    p.acc_nl2[1] = 0.008;
    p.acc_nl3[1] = 0.012;
    p.gyro_bias_dps[2] = 0.5;
    p.gyro_scale[2] = 0.99;
    sim_calpart_init(&part, &p, 5);
    em = sim_calpart_error_model(&part);
    CHECK(em.apply == sim_calpart_apply);
    CHECK(em.ctx == &part);
    sim_inertial_at_rest(&in);
    in.accel_g[0] = 0.5;
    in.accel_g[1] = 0.25;
    in.rate_dps[2] = 100.0;
    em.apply(em.ctx, &in, &out, 0, 0.001);
    x = 0.01 * 0.5 + 0.25;
    CHECK_NEAR(out.accel_g[1], 0.02 + 1.03 * (x + 0.008 * x * x + 0.012 * x * x * x), 1e-15);
    CHECK_NEAR(out.accel_g[0], 0.5, 1e-15); /* ideal axis, no noise */
    CHECK_NEAR(out.rate_dps[2], 0.5 + 99.0, 1e-12);
    CHECK_NEAR(out.temp_c, in.temp_c, 0.0);
}

static void test_noise_deterministic(void)
{
    struct sim_calpart_params p;
    struct sim_calpart a, b;
    struct sim_inertial_input in, oa, ob;
    double s = 0.0, s2 = 0.0;
    int i;
    const int n = 4000;
    sim_calpart_ideal(&p);
    p.acc_noise_g = 0.003;
    sim_calpart_init(&a, &p, 77);
    sim_calpart_init(&b, &p, 77);
    sim_inertial_at_rest(&in);
    for (i = 0; i < n; i++) {
        sim_calpart_apply(&a, &in, &oa, 0, 0.001);
        sim_calpart_apply(&b, &in, &ob, 0, 0.001);
        CHECK(oa.accel_g[0] == ob.accel_g[0]);
        s += oa.accel_g[0];
        s2 += oa.accel_g[0] * oa.accel_g[0];
    }
    CHECK_NEAR(s / n, 0.0, 0.0003);
    CHECK_NEAR(sqrt(s2 / n), 0.003, 0.0002);
}

int main(void)
{
    UNIT_RUN(test_tcurve_formula);
    UNIT_RUN(test_paper_magnitudes);
    UNIT_RUN(test_seeds_differ);
    UNIT_RUN(test_hysteresis);
    UNIT_RUN(test_error_formula);
    UNIT_RUN(test_noise_deterministic);
    return unit_report();
}
