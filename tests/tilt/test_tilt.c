/*
 * test_tilt.c - roll/pitch estimation (inclino/tilt.h): accelerometer angles, the three modes on
 * a tilted sensor with a gyro bias (the [CN110567483] step-4 question), rejection of accelerometer and
 * gyro samples, sample gaps and bad input. Host and QEMU Cortex-M (uses libm for the simulated
 * inputs and the double reference angles). The runs are shorter on the emulated MCU
 * (TILT_SECONDS); the bounds are the same.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "inclino/tilt.h"
#include "unit.h"

#if UNIT_REDUCED
#define ON_TARGET 1
#else
#define ON_TARGET 0
#endif

#define FS 819.2
#define DT_NS 1220703u /* 1 / 819.2 Hz */
#define DEG (3.14159265358979323846 / 180.0)

static int32_t q16(double v)
{
    return (int32_t)lround(v * 65536.0);
}
static double d16(int32_t v)
{
    return v / 65536.0;
}

/* Deterministic approximately Gaussian noise (sum of 4 uniforms, unit variance). */
static uint32_t rng = 12345u;
static double gauss(void)
{
    double s = 0;
    int i;
    for (i = 0; i < 4; i++) {
        rng = rng * 1664525u + 1013904223u;
        s += (rng >> 8) / 16777216.0;
    }
    return (s - 2.0) * 1.7320508;
}

/* Specific force of a sensor at roll r, pitch p (deg), at rest: the frame of tilt.h. */
static void accel_of(double roll, double pitch, double g_scale, double noise, int32_t a[3])
{
    double r = roll * DEG, p = pitch * DEG;
    a[0] = q16(g_scale * -sin(p) + noise * gauss());
    a[1] = q16(g_scale * sin(r) * cos(p) + noise * gauss());
    a[2] = q16(g_scale * cos(r) * cos(p) + noise * gauss());
}

static void input(struct tilt_input *in, double roll, double pitch, double wx, double wy,
                  double noise)
{
    accel_of(roll, pitch, 1.0, noise, in->accel_g);
    in->gyro_dps[0] = q16(wx);
    in->gyro_dps[1] = q16(wy);
    in->gyro_dps[2] = 0;
    in->flags = 0;
}

static void test_accel_angles_exact(void)
{
    int32_t a[3];
    fx_q16_t r, p;
    const int32_t one = FX_Q16_ONE;
    a[0] = 0;
    a[1] = 0;
    a[2] = one;
    tilt_accel_angles(a, &r, &p);
    CHECK_EQ_INT(r, 0);
    CHECK_EQ_INT(p, 0);
    a[0] = 0;
    a[1] = one;
    a[2] = one;
    tilt_accel_angles(a, &r, &p);
    CHECK_EQ_INT(r, FX_DEG_45);
    CHECK_EQ_INT(p, 0);
    a[0] = -one;
    a[1] = 0;
    a[2] = one;
    tilt_accel_angles(a, &r, &p);
    CHECK_EQ_INT(p, FX_DEG_45);
    a[0] = one;
    a[1] = 0;
    a[2] = 0;
    tilt_accel_angles(a, &r, &p);
    CHECK_EQ_INT(p, -FX_DEG_90);
    a[0] = 0;
    a[1] = -one;
    a[2] = 0;
    tilt_accel_angles(a, &r, &p);
    CHECK_EQ_INT(r, -FX_DEG_90);
    a[0] = 0;
    a[1] = 0;
    a[2] = -one;
    tilt_accel_angles(a, &r, &p);
    CHECK_EQ_INT(r, FX_DEG_180);
    a[0] = 0;
    a[1] = 0;
    a[2] = 0;
    tilt_accel_angles(a, &r, &p);
    CHECK_EQ_INT(r, 0);
    CHECK_EQ_INT(p, 0);
    /* extreme inputs are defined */
    a[0] = INT32_MIN;
    a[1] = INT32_MIN;
    a[2] = INT32_MIN;
    tilt_accel_angles(a, &r, &p);
    CHECK_NEAR_INT(p, q16(35.2643897), 2);
    tilt_accel_angles(a, NULL, NULL);
}

/* |error| against double atan2 of the same quantised inputs <= 0.85 LSB Q16. */
static void test_accel_angles_accuracy(void)
{
    double worst = 0;
    int i, j, step = ON_TARGET ? 7 : 1;
    for (i = -180; i <= 180; i += step) {
        for (j = -89; j <= 89; j += step) {
            int32_t a[3];
            fx_q16_t r, p;
            double rr, pr;
            accel_of(i + 0.37, j + 0.21, 0.97, 0, a);
            tilt_accel_angles(a, &r, &p);
            rr = atan2(d16(a[1]), d16(a[2])) / DEG;
            pr = atan2(-d16(a[0]), sqrt(d16(a[1]) * d16(a[1]) + d16(a[2]) * d16(a[2]))) / DEG;
            if (fabs(d16(r) - rr) * 65536 > worst && fabs(rr) < 179.999)
                worst = fabs(d16(r) - rr) * 65536;
            if (fabs(d16(p) - pr) * 65536 > worst) worst = fabs(d16(p) - pr) * 65536;
        }
    }
    printf("accel angles: worst error %.3f LSB Q16\n", worst);
    CHECK(worst <= 0.85);
}

static struct tilt_config config(uint32_t mode)
{
    struct tilt_config c;
    (void)tilt_config_default(&c, DT_NS);
    c.mode = mode;
    c.axis[0].r_angle = KF_P_ONE_Q16 / 4; /* the test's accelerometer noise: 0.5 deg */
    c.axis[1].r_angle = KF_P_ONE_Q16 / 4;
    (void)tilt_feedback_gain(c.axis[0].q_angle, c.axis[0].r_angle, DT_NS, &c.axis[0].bias_gain);
    c.axis[1].bias_gain = c.axis[0].bias_gain;
    c.axis[0].p0_angle = c.axis[1].p0_angle = KF_P_ONE_Q16 / 4;
    return c;
}

#define TILT_SECONDS (ON_TARGET ? 20.0 : 60.0)

/* Static tilt roll 3, pitch -5 deg; gyro biases +0.2 and -0.3 deg/s; accelerometer noise 8.7 mg
 * (0.5 deg). Returns the errors at the end; the printed form's drift rate is measured too. */
struct run_result {
    double err[2], bias[2], slope[2];
    bool valid;
    uint32_t flags;
};

static struct run_result run_static(uint32_t mode, double seconds)
{
    struct tilt t;
    struct tilt_config c = config(mode);
    struct tilt_output o;
    struct tilt_input in;
    struct run_result res;
    const double roll = 3, pitch = -5, bx = 0.2, by = -0.3;
    long n = (long)(seconds * FS), k;
    double e1[2] = {0, 0}, e2[2] = {0, 0};
    long n1 = 0, n2 = 0;
    memset(&res, 0, sizeof res);
    rng = 777u;
    if (tilt_init(&t, &c) != INC_OK) return res;
    for (k = 0; k < n; k++) {
        input(&in, roll, pitch, bx, by, 0.0087);
        if (tilt_step(&t, &in, DT_NS, &o) != INC_OK) res.flags |= 0x80000000u;
        res.flags |= o.flags;
        /* mean error over 50 % .. 60 % and 90 % .. 100 % of the run (drift measurement, after
         * the offset loops have settled) */
        if (k >= n / 2 && k < n * 6 / 10) {
            e1[0] += d16(o.angle_deg[0]) - roll;
            e1[1] += d16(o.angle_deg[1]) - pitch;
            n1++;
        }
        if (k >= n * 9 / 10) {
            e2[0] += d16(o.angle_deg[0]) - roll;
            e2[1] += d16(o.angle_deg[1]) - pitch;
            n2++;
        }
    }
    res.err[0] = e2[0] / n2;
    res.err[1] = e2[1] / n2;
    res.slope[0] = (e2[0] / n2 - e1[0] / n1) / (seconds * 0.4);
    res.slope[1] = (e2[1] / n2 - e1[1] / n1) / (seconds * 0.4);
    res.bias[0] = d16(o.bias_dps[0]);
    res.bias[1] = d16(o.bias_dps[1]);
    res.valid = o.valid;
    return res;
}

/* The [CN110567483] step-4 question. As printed, the offset cancels the previous correction: the
 * prediction is the pure gyro integral and the angle error grows as (1 - K2) b t. The corrected
 * feedback and the two-state filter estimate the bias and hold the angle. */
static void test_step4_printed_drifts(void)
{
    struct run_result r = run_static(TILT_MODE_SEED_PRINTED, TILT_SECONDS);
    struct tilt_config c = config(TILT_MODE_SEED_PRINTED);
    fx_q30_t kb;
    double k2;
    /* (1 - K2inf): recover K2inf from the critical gain Kb = (1 - sqrt(1 - K))^2 / K */
    (void)tilt_feedback_gain(c.axis[0].q_angle, c.axis[0].r_angle, DT_NS, &kb);
    k2 = 4.0 * kb / 1073741824.0; /* ~K/4 to first order */
    printf(
        "printed: drift %.4f / %.4f deg/s (biases 0.2 / -0.3, (1-K2) ~ %.5f), error after %.0f s "
        "%.3f / %.3f deg\n",
        r.slope[0], r.slope[1], 1 - k2, TILT_SECONDS, r.err[0], r.err[1]);
    CHECK_NEAR(r.slope[0], 0.2 * (1 - k2), 0.2 * 0.02);
    CHECK_NEAR(r.slope[1], -0.3 * (1 - k2), 0.3 * 0.02);
    CHECK(fabs(r.err[0]) > 0.9 * 0.2 * TILT_SECONDS * 0.9);
    CHECK(r.valid);
}

static void test_step4_feedback_removes_bias(void)
{
    struct run_result r = run_static(TILT_MODE_FEEDBACK, TILT_SECONDS);
    printf("feedback: error %.4f / %.4f deg, bias %.4f / %.4f deg/s\n", r.err[0], r.err[1],
           r.bias[0], r.bias[1]);
    CHECK(fabs(r.err[0]) < 0.05);
    CHECK(fabs(r.err[1]) < 0.05);
    CHECK_NEAR(r.bias[0], 0.2, 0.02);
    CHECK_NEAR(r.bias[1], -0.3, 0.02);
    CHECK(fabs(r.slope[0]) < 0.002);
    CHECK(r.valid);
    CHECK_EQ_INT(r.flags, 0);
}

static void test_kf2_removes_bias(void)
{
    struct run_result r = run_static(TILT_MODE_KF2, TILT_SECONDS);
    printf("kf2: error %.4f / %.4f deg, bias %.4f / %.4f deg/s\n", r.err[0], r.err[1], r.bias[0],
           r.bias[1]);
    CHECK(fabs(r.err[0]) < 0.05);
    CHECK(fabs(r.err[1]) < 0.05);
    CHECK_NEAR(r.bias[0], 0.2, 0.02);
    CHECK_NEAR(r.bias[1], -0.3, 0.02);
    CHECK(r.valid);
    CHECK_EQ_INT(r.flags, 0);
}

/* |a| far from 1 g (vehicle accelerating at 0.3 g for 2 s): every sample rejected and flagged,
 * the angle follows the gyro alone (exactly the integral of w - off), and stays put. */
static void test_accel_rejected(void)
{
    uint32_t modes[3] = {TILT_MODE_FEEDBACK, TILT_MODE_SEED_PRINTED, TILT_MODE_KF2};
    unsigned m;
    for (m = 0; m < 3; m++) {
        struct tilt t;
        struct tilt_config c = config(modes[m]);
        struct tilt_output o;
        struct tilt_input in;
        long k;
        unsigned rejected = 0;
        double start[2];
        REQUIRE(tilt_init(&t, &c) == INC_OK);
        rng = 99u;
        for (k = 0; k < (long)(20 * FS); k++) { /* the offset loops settle */
            input(&in, 2, 1, 0, 0, 0.0087);
            CHECK_OK(tilt_step(&t, &in, DT_NS, &o));
        }
        start[0] = d16(o.angle_deg[0]);
        start[1] = d16(o.angle_deg[1]);
        for (k = 0; k < (long)(2 * FS); k++) {
            int64_t before = t.ax[0].kf.x[0];
            input(&in, 2, 1, 0, 0, 0.0087);
            in.accel_g[0] += q16(0.3); /* longitudinal acceleration */
            in.accel_g[2] += q16(0.2);
            CHECK_OK(tilt_step(&t, &in, DT_NS, &o));
            if (o.flags & TILT_F_ACCEL_REJECTED) rejected++;
            if (modes[m] == TILT_MODE_SEED_PRINTED && k > 0) {
                /* printed: after one coasting step off = 0, and w = 0: the angle stands still */
                CHECK_EQ_INT(t.ax[0].kf.x[0], before);
            }
        }
        CHECK_EQ_INT(rejected, (unsigned)(long)(2 * FS));
        CHECK(o.valid);
        /* coasting on a still gyro: the angle does not move (by more than the learnt offset
         * noise times 2 s) */
        CHECK_NEAR(d16(o.angle_deg[0]), start[0], 0.05);
        CHECK_NEAR(d16(o.angle_deg[1]), start[1], 0.05);
        if (modes[m] != TILT_MODE_SEED_PRINTED) {
            /* (the printed form keeps (1 - K2) of its start error for ever: its prediction is the
             * gyro integral from the first sample, so it is not checked against the truth) */
            CHECK_NEAR(d16(o.angle_deg[0]), 2.0, 0.05);
            CHECK_NEAR(d16(o.angle_deg[1]), 1.0, 0.05);
        }
        CHECK_EQ_INT(o.accel_angle_deg[0], 0);
        /* the saturation flag of the driver rejects as well */
        input(&in, 2, 1, 0, 0, 0);
        in.flags = TILT_IN_ACCEL_SAT;
        CHECK_OK(tilt_step(&t, &in, DT_NS, &o));
        CHECK(o.flags & TILT_F_ACCEL_REJECTED);
    }
}

/* A roll of 20 deg at 400 deg/s with the gyro clipped at its 300 deg/s range (flagged by the
 * driver): the clipped samples are rejected and flagged, the angle converges back to the
 * accelerometer, nothing diverges. Then 60 s with the gyro saturated and the accelerometer
 * rejected: the variance stops at TILT_VAR_CAP, no overflow, and the filter recovers. */
static void test_gyro_saturation(void)
{
    uint32_t modes[3] = {TILT_MODE_FEEDBACK, TILT_MODE_SEED_PRINTED, TILT_MODE_KF2};
    unsigned m;
    for (m = 0; m < 3; m++) {
        struct tilt t;
        struct tilt_config c = config(modes[m]);
        struct tilt_output o;
        struct tilt_input in;
        double roll = 0;
        long k;
        unsigned flagged = 0;
        REQUIRE(tilt_init(&t, &c) == INC_OK);
        rng = 5u;
        for (k = 0; k < 1000; k++) {
            input(&in, roll, 0, 0, 0, 0.0087);
            CHECK_OK(tilt_step(&t, &in, DT_NS, &o));
        }
        for (k = 0; roll < 20.0; k++) {
            roll += 400.0 / FS;
            input(&in, roll, 0, 300.0, 0, 0.0087);
            in.flags = TILT_IN_GYRO_SAT_X;
            CHECK_OK(tilt_step(&t, &in, DT_NS, &o));
            if (o.flags & TILT_F_GYRO_REJ_ROLL) flagged++;
            CHECK(!(o.flags & TILT_F_GYRO_REJ_PITCH));
        }
        CHECK_EQ_INT(flagged, (unsigned)k);
        for (k = 0; k < (long)(10 * FS); k++) {
            input(&in, roll, 0, 0, 0, 0.0087);
            CHECK_OK(tilt_step(&t, &in, DT_NS, &o));
        }
        if (modes[m] == TILT_MODE_SEED_PRINTED) {
            /* The printed form cannot recover the rotation the gyro missed: its prediction is the
             * gyro integral from the angle it was re-anchored on (the held angle), so the error
             * left by the outage stays. Bounded, not divergent. */
            printf("printed after a gyro outage: error %.3f deg (stays)\n",
                   d16(o.angle_deg[0]) - roll);
            CHECK(fabs(d16(o.angle_deg[0]) - roll) < 3.0);
        } else {
            CHECK_NEAR(d16(o.angle_deg[0]), roll, 0.1);
        }
        CHECK(o.valid);
        /* a rate above the configured limit without a driver flag is rejected as well */
        input(&in, roll, 0, 0, 296.0, 0.0087);
        CHECK_OK(tilt_step(&t, &in, DT_NS, &o));
        CHECK(o.flags & TILT_F_GYRO_REJ_PITCH);
        /* both rejected for a long time */
        for (k = 0; k < (long)(30 * FS); k++) { /* (295 deg/s dt)^2 per step: the cap in 19 s */
            input(&in, roll, 0, 500.0, -500.0, 0);
            in.accel_g[2] += q16(1.0);
            CHECK_OK(tilt_step(&t, &in, DT_NS, &o));
        }
        CHECK(t.ax[0].kf.p[0][0] <= TILT_VAR_CAP);
        CHECK(t.ax[0].kf.p[0][0] > TILT_VAR_CAP / 2);
        CHECK(!(o.flags & TILT_F_OVERFLOW));
        CHECK(o.valid);
        CHECK_NEAR(d16(o.sigma_deg[0]), 45.0, 0.01);
        for (k = 0; k < (long)(5 * FS); k++) {
            input(&in, roll, 0, 0, 0, 0.0087);
            CHECK_OK(tilt_step(&t, &in, DT_NS, &o));
        }
        if (modes[m] != TILT_MODE_SEED_PRINTED) {
            CHECK_NEAR(d16(o.angle_deg[0]), roll, 0.2);
            CHECK_NEAR(d16(o.angle_deg[1]), 0, 0.2);
        } else {
            CHECK(fabs(d16(o.angle_deg[0]) - roll) < 45.0);
        }
    }
}

/* Missed data-ready: a step of 3 periods integrates 3 periods of rate. With the accelerometer
 * rejected (pure gyro), rotating at 10 deg/s, the angle after a 3-period step equals the angle
 * after three 1-period steps (dt is exact: 3 * 5/4096 s). */
static void test_gaps(void)
{
    uint32_t modes[3] = {TILT_MODE_FEEDBACK, TILT_MODE_SEED_PRINTED, TILT_MODE_KF2};
    unsigned m;
    for (m = 0; m < 3; m++) {
        struct tilt a, b;
        struct tilt_config c = config(modes[m]);
        struct tilt_output oa, ob;
        struct tilt_input in;
        int i;
        REQUIRE(tilt_init(&a, &c) == INC_OK);
        REQUIRE(tilt_init(&b, &c) == INC_OK);
        input(&in, 1, 2, 0, 0, 0);
        CHECK_OK(tilt_step(&a, &in, DT_NS, &oa));
        CHECK_OK(tilt_step(&b, &in, DT_NS, &ob));
        input(&in, 1, 2, 10.0, -20.0, 0);
        in.accel_g[2] += q16(0.5); /* rejected: gyro only */
        for (i = 0; i < 3; i++)
            CHECK_OK(tilt_step(&a, &in, DT_NS, &oa));
        CHECK_OK(tilt_step(&b, &in, 3 * DT_NS + 1, &ob)); /* 3662110 ns -> the same Q30 dt */
        CHECK_EQ_INT(oa.angle_deg[0], ob.angle_deg[0]);
        CHECK_EQ_INT(oa.angle_deg[1], ob.angle_deg[1]);
        CHECK_NEAR(d16(ob.angle_deg[0]), 1.0 + 30.0 / FS, 2e-4);
        CHECK_NEAR(d16(ob.angle_deg[1]), 2.0 - 60.0 / FS, 2e-4);
        /* dt == 0: refused, nothing changes */
        {
            int64_t x0 = b.ax[0].kf.x[0], p0 = b.ax[0].kf.p[0][0];
            CHECK_ERR(tilt_step(&b, &in, 0, &ob), INC_ERR_INVAL);
            CHECK(!ob.valid);
            CHECK_EQ_INT(b.ax[0].kf.x[0], x0);
            CHECK_EQ_INT(b.ax[0].kf.p[0][0], p0);
        }
        /* a gap beyond dt_max restarts from the accelerometer, keeping the offset */
        {
            fx_q16_t bias = ob.bias_dps[1];
            input(&in, -4, 6, 0, 0, 0);
            CHECK_OK(tilt_step(&b, &in, c.dt_max_ns + 1, &ob));
            CHECK(ob.flags & TILT_F_GAP_RESTART);
            CHECK_EQ_INT(ob.angle_deg[0], ob.accel_angle_deg[0]);
            CHECK_EQ_INT(ob.angle_deg[1], ob.accel_angle_deg[1]);
            CHECK_NEAR(d16(ob.angle_deg[0]), -4, 2e-3);
            if (modes[m] != TILT_MODE_SEED_PRINTED) CHECK_EQ_INT(ob.bias_dps[1], bias);
            CHECK(ob.valid);
        }
        /* a gap with a rejected accelerometer: not started until a good sample */
        input(&in, -4, 6, 0, 0, 0);
        in.accel_g[0] += q16(1.0);
        CHECK_OK(tilt_step(&b, &in, UINT32_MAX, &ob));
        CHECK(ob.flags & TILT_F_GAP_RESTART);
        CHECK(ob.flags & TILT_F_NOT_STARTED);
        CHECK(!ob.valid);
        input(&in, -4, 6, 0, 0, 0);
        CHECK_OK(tilt_step(&b, &in, DT_NS, &ob));
        CHECK(ob.valid);
    }
}

static void test_timestamps(void)
{
    struct tilt a, b;
    struct tilt_config c = config(TILT_MODE_FEEDBACK);
    struct tilt_output oa, ob;
    struct tilt_input in;
    uint64_t t0 = 5000000000ull;
    int i;
    REQUIRE(tilt_init(&a, &c) == INC_OK);
    REQUIRE(tilt_init(&b, &c) == INC_OK);
    rng = 3u;
    for (i = 0; i < 200; i++) {
        uint32_t dt = (i % 7 == 3) ? 2 * DT_NS : DT_NS;
        input(&in, 1, 2, 5.0, 0, 0.01);
        t0 += dt;
        CHECK_OK(tilt_step(&a, &in, dt, &oa));
        CHECK_OK(tilt_step_at(&b, &in, t0, &ob));
        CHECK_EQ_INT(oa.angle_deg[0], ob.angle_deg[0]);
        CHECK_EQ_INT(oa.angle_deg[1], ob.angle_deg[1]);
    }
    CHECK_ERR(tilt_step_at(&b, &in, t0, &ob), INC_ERR_INVAL);     /* same time */
    CHECK_ERR(tilt_step_at(&b, &in, t0 - 1, &ob), INC_ERR_INVAL); /* backwards */
    CHECK(!ob.valid);
    CHECK_OK(tilt_step_at(&b, &in, t0 + DT_NS, &ob));
    CHECK(ob.valid);
    CHECK_ERR(tilt_step_at(NULL, &in, t0, &ob), INC_ERR_NULL);
}

/* Roll through +-180 (upside down): no 360-degree excursion. */
static void test_roll_wrap(void)
{
    struct tilt t;
    struct tilt_config c = config(TILT_MODE_KF2);
    struct tilt_output o;
    struct tilt_input in;
    double roll = 175;
    int i;
    REQUIRE(tilt_init(&t, &c) == INC_OK);
    for (i = 0; i < 3000; i++) {
        input(&in, roll, 0, 0, 0, 0);
        CHECK_OK(tilt_step(&t, &in, DT_NS, &o));
    }
    for (i = 0; i < 819; i++) { /* 10 deg at 10 deg/s */
        double d;
        roll += 10.0 / FS;
        input(&in, roll, 0, 10.0, 0, 0);
        CHECK_OK(tilt_step(&t, &in, DT_NS, &o));
        d = d16(o.angle_deg[0]) - (roll > 180 ? roll - 360 : roll);
        if (d > 180) d -= 360;
        if (d < -180) d += 360;
        CHECK(fabs(d) < 0.05);
        CHECK(o.angle_deg[0] > -FX_DEG_180 && o.angle_deg[0] <= FX_DEG_180);
    }
}

static void test_not_started_and_bad_input(void)
{
    struct tilt t;
    struct tilt_config c = config(TILT_MODE_FEEDBACK), bad;
    struct tilt_output o;
    struct tilt_input in;
    fx_q30_t g;
    input(&in, 0, 0, 0, 0, 0);
    CHECK_ERR(tilt_init(NULL, &c), INC_ERR_NULL);
    CHECK_ERR(tilt_init(&t, NULL), INC_ERR_NULL);
    CHECK_ERR(tilt_step(&t, &in, DT_NS, &o), INC_ERR_STATE);
    CHECK(!o.valid);
    bad = c;
    bad.mode = 7;
    CHECK_ERR(tilt_init(&t, &bad), INC_ERR_INVAL);
    bad = c;
    bad.accel_tol_g = 0;
    CHECK_ERR(tilt_config_check(&bad), INC_ERR_INVAL);
    bad = c;
    bad.accel_tol_g = FX_Q16_HALF + 1;
    CHECK_ERR(tilt_config_check(&bad), INC_ERR_INVAL);
    bad = c;
    bad.gyro_limit_dps = 0;
    CHECK_ERR(tilt_config_check(&bad), INC_ERR_INVAL);
    bad = c;
    bad.dt_max_ns = 0;
    CHECK_ERR(tilt_config_check(&bad), INC_ERR_INVAL);
    bad = c;
    bad.dt_max_ns = 1000000001u;
    CHECK_ERR(tilt_config_check(&bad), INC_ERR_INVAL);
    bad = c;
    bad.axis[1].q_angle = 0;
    CHECK_ERR(tilt_config_check(&bad), INC_ERR_INVAL);
    bad = c;
    bad.axis[0].r_angle = 0;
    CHECK_ERR(tilt_config_check(&bad), INC_ERR_INVAL);
    bad = c;
    bad.axis[0].q_bias = -1;
    CHECK_ERR(tilt_config_check(&bad), INC_ERR_INVAL);
    bad = c;
    bad.axis[0].p0_angle = TILT_VAR_CAP + 1;
    CHECK_ERR(tilt_config_check(&bad), INC_ERR_INVAL);
    bad = c;
    bad.axis[0].bias_gain = FX_Q30_ONE + 1;
    CHECK_ERR(tilt_config_check(&bad), INC_ERR_INVAL);
    bad = c;
    bad.axis[1].bias0_dps = c.gyro_limit_dps;
    CHECK_ERR(tilt_config_check(&bad), INC_ERR_INVAL);
    CHECK_ERR(tilt_config_check(NULL), INC_ERR_NULL);
    CHECK_ERR(tilt_config_default(NULL, DT_NS), INC_ERR_NULL);
    CHECK_ERR(tilt_config_default(&bad, 0), INC_ERR_INVAL);
    CHECK_ERR(tilt_feedback_gain(0, KF_P_ONE_Q16, DT_NS, &g), INC_ERR_INVAL);
    CHECK_ERR(tilt_feedback_gain(KF_P_ONE_Q16, 0, DT_NS, &g), INC_ERR_INVAL);
    CHECK_ERR(tilt_feedback_gain(KF_P_ONE_Q16, KF_P_ONE_Q16, 0, &g), INC_ERR_INVAL);
    CHECK_ERR(tilt_feedback_gain(KF_P_ONE_Q16, KF_P_ONE_Q16, DT_NS, NULL), INC_ERR_NULL);
    CHECK_ERR(tilt_step(&t, &in, DT_NS, &o), INC_ERR_STATE); /* the refused init */

    REQUIRE(tilt_init(&t, &c) == INC_OK);
    CHECK_ERR(tilt_step(&t, NULL, DT_NS, &o), INC_ERR_NULL);
    CHECK_ERR(tilt_step(&t, &in, DT_NS, NULL), INC_ERR_NULL);
    /* first samples rejected: not started, not valid, no angles */
    in.accel_g[2] = q16(1.5);
    CHECK_OK(tilt_step(&t, &in, DT_NS, &o));
    CHECK(o.flags & TILT_F_NOT_STARTED);
    CHECK(o.flags & TILT_F_ACCEL_REJECTED);
    CHECK(!o.valid);
    CHECK_OK(tilt_step(&t, &in, 0, &o)); /* dt is ignored before the start */
    CHECK(!o.valid);
    input(&in, 10, -20, 0, 0, 0);
    CHECK_OK(tilt_step(&t, &in, 0, &o)); /* the first good sample starts it */
    CHECK(o.valid);
    CHECK_NEAR(d16(o.angle_deg[0]), 10, 2e-3); /* Q16 accelerometer quantisation */
    CHECK_NEAR(d16(o.angle_deg[1]), -20, 2e-3);
    CHECK_NEAR(d16(o.sigma_deg[0]), 0.5, 1e-4);
    tilt_restart(&t);
    in.accel_g[2] = 0;
    CHECK_OK(tilt_step(&t, &in, DT_NS, &o));
    CHECK(!o.valid);
    tilt_restart(NULL);
}

/* The critically damped gain against the double formulas: K2inf from the Riccati fixed point,
 * Kb = (1 - sqrt(1 - K))^2 / K; error <= 1e-3 relative + 1 LSB Q30. */
static void test_feedback_gain(void)
{
    static const double qs[] = {1e-6, 1e-4, 1e-3, 0.1, 10.0};
    static const double rs[] = {1e-4, 0.01, 1.0, 100.0};
    static const uint32_t dts[] = {1000u, DT_NS, 10000000u, 1000000000u};
    unsigned i, j, k;
    double worst = 0;
    for (i = 0; i < 5; i++)
        for (j = 0; j < 4; j++)
            for (k = 0; k < 4; k++) {
                int64_t qf = (int64_t)llround(qs[i] * 281474976710656.0);
                int64_t rf = (int64_t)llround(rs[j] * 281474976710656.0);
                double dt = dts[k] * 1e-9, q = qs[i] * dt, r = rs[j];
                double pm = (q + sqrt(q * q + 4 * q * r)) / 2, kk = pm / (pm + r);
                double kb = (1 - sqrt(1 - kk)) * (1 - sqrt(1 - kk)) / kk;
                fx_q30_t g;
                if (q * 281474976710656.0 < 1e4) continue; /* Q2 below 1e4 LSB: not meaningful */
                CHECK_OK(tilt_feedback_gain(qf, rf, dts[k], &g));
                /* bound: 1e-3 relative plus 1 LSB of the Q30 output */
                {
                    double e = fabs(g / 1073741824.0 - kb) / (1e-3 * kb + 1.0 / 1073741824.0);
                    if (e > worst) worst = e;
                }
            }
    printf("feedback gain: worst error %.3f of (1e-3 relative + 1 LSB)\n", worst);
    CHECK(worst <= 1.0);
}

int main(void)
{
    UNIT_RUN(test_accel_angles_exact);
    UNIT_RUN(test_accel_angles_accuracy);
    UNIT_RUN(test_step4_printed_drifts);
    UNIT_RUN(test_step4_feedback_removes_bias);
    UNIT_RUN(test_kf2_removes_bias);
    UNIT_RUN(test_accel_rejected);
    UNIT_RUN(test_gyro_saturation);
    UNIT_RUN(test_gaps);
    UNIT_RUN(test_timestamps);
    UNIT_RUN(test_roll_wrap);
    UNIT_RUN(test_not_started_and_bad_input);
    UNIT_RUN(test_feedback_gain);
    return unit_report();
}
