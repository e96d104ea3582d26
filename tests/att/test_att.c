/*
 * test_att.c - unit tests of firmware/signal/att (the 3D attitude estimator).
 *
 * The file includes att.c to reach its static pieces (exact multiply, rounding, the strapdown
 * step, the quaternion renormalisation) and checks them against double-precision math with the
 * error bounds stated in att.c; then the behaviour through the public API: configuration
 * validation and errors, rest convergence and bias, an upside-down start and a tumble through
 * every attitude, bound growth without trustworthy accelerometer (saturation) and its recovery,
 * vehicle aiding, the Euler output. Every measured maximum is printed ("MEASURED ...").
 *
 * Host and QEMU Cortex-M (libm for the references). On the emulated MCU and in the sanitizer
 * build the random sweeps and the tumble are shorter (UNIT_SIZE); the bounds are the same.
 * The bit-identity fingerprint of a long integer-only run is test_att_bitident.c.
 */
#include "../../firmware/signal/att/att.c"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "unit.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

#define FS_BROAD (2000.0 / 7.0) /* 285.714 Hz, the BROAD rate */

static uint64_t rs = 88172645463325252ull;

static double urand(void)
{
    rs ^= rs << 13;
    rs ^= rs >> 7;
    rs ^= rs << 17;
    return (double)(rs >> 11) / 9007199254740992.0;
}

static int32_t lcg32(void)
{
    rs = rs * 6364136223846793005ull + 1u;
    return (int32_t)(uint32_t)(rs >> 32);
}

static int32_t q16(double x)
{
    return (int32_t)lround(x * 65536.0);
}

static int32_t q30(double x)
{
    return (int32_t)lround(x * 1073741824.0);
}

static double fq30(int32_t x)
{
    return x / 1073741824.0;
}

static double fq16(int32_t x)
{
    return x / 65536.0;
}

static void dqmul(const double *a, const double *b, double *o)
{
    double r[4];
    r[0] = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
    r[1] = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
    r[2] = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
    r[3] = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
    memcpy(o, r, sizeof r);
}

/* mul64 exact, mulr/mulrs round to nearest with ties away from zero (mulrs saturating), against
 * an exact integer reference. */
static void test_rounding(void)
{
    const int n = UNIT_SIZE(1000000, 100000);
    int k, bad = 0;
    for (k = 0; k < n; k++) {
        const int32_t a = lcg32(), b = lcg32();
        const unsigned s = 1u + (unsigned)(k % 40);
        const int64_t p = (int64_t)a * b;
        const uint64_t m = p < 0 ? (uint64_t)0 - (uint64_t)p : (uint64_t)p;
        const uint64_t r = (m + ((uint64_t)1 << (s - 1))) >> s;
        const int64_t ref = p < 0 ? -(int64_t)r : (int64_t)r;
        const int32_t sat_ref = ref > INT32_MAX ? INT32_MAX
                                                : (ref < INT32_MIN ? INT32_MIN : (int32_t)ref);
        if (mul64(a, b) != p) bad++;
        if (mulrs(a, b, s) != sat_ref) bad++;
        if (ref >= INT32_MIN && ref <= INT32_MAX && mulr(a, b, s) != (int32_t)ref) bad++;
    }
    printf("MEASURED mul64/mulr/mulrs: %d mismatches in %d random operand pairs\n", bad, n);
    CHECK_EQ_INT(bad, 0);
    CHECK_EQ_INT(rnd(3, 1), 2);
    CHECK_EQ_INT(rnd(-3, 1), -2);
    CHECK_EQ_INT(rnd(1, 1), 1);
    CHECK_EQ_INT(rnd(-1, 1), -1);
    CHECK_EQ_INT(rnd(-2, 2), -1);
    CHECK_EQ_INT(rnd(2, 2), 1);
    CHECK_EQ_INT(rnd(-1, 2), 0);
    CHECK_EQ_INT(rnd32(3, 1), 2);
    CHECK_EQ_INT(rnd32(-3, 1), -2);
    CHECK_EQ_INT(rnd32(-5, 2), -1);
    CHECK_EQ_INT(rnd32(6, 2), 2);
    CHECK_EQ_INT(rnd32(-6, 2), -2);
    CHECK_EQ_INT(rnds((int64_t)1 << 62, 1), INT32_MAX);
    CHECK_EQ_INT(rnds(-((int64_t)1 << 62), 1), INT32_MIN);
}

/* One strapdown step against the exact rotation (renormalised as the step is): att.c states
 * <= 4 LSB Q30 per component and | |q| - 1 | <= 2 LSB after the renormalisation, up to
 * 1.125 x full scale on every axis at 100 to 1000 Hz. */
static void test_strapdown_step(void)
{
    static const double rates[] = {FS_BROAD, 100.0, 150.0, 1000.0};
    const int n = UNIT_SIZE(200000, 10000);
    int ri;
    for (ri = 0; ri < 4; ri++) {
        struct att_config c;
        struct att a;
        const double fs = rates[ri], wmax = 2000;
        double maxe = 0, maxn = 0;
        int k;
        CHECK_OK(att_config_default(&c, q16(fs)));
        c.gyro_fs_dps = q16(wmax);
        REQUIRE(att_init(&a, &c) == 0);
        for (k = 0; k < n; k++) {
            int32_t q[4], w[3];
            double qd[4], nrm = 0, wd[3], wn, th, dq[4], ex[4], nn = 0;
            int i;
            for (i = 0; i < 4; i++) {
                qd[i] = 2 * urand() - 1;
                nrm += qd[i] * qd[i];
            }
            nrm = sqrt(nrm);
            for (i = 0; i < 4; i++) {
                q[i] = q30(qd[i] / nrm);
                qd[i] = fq30(q[i]);
            }
            /* every 4th step up to 1.125 x full scale per axis (the rejection limit), else slow */
            for (i = 0; i < 3; i++) {
                w[i] = q16((2 * urand() - 1) * 1.125 * wmax * (k % 4 == 0 ? 1.0 : 0.05));
                wd[i] = fq16(w[i]);
            }
            wn = sqrt(wd[0] * wd[0] + wd[1] * wd[1] + wd[2] * wd[2]) * M_PI / 180;
            th = wn / fs;
            dq[0] = cos(th / 2);
            for (i = 0; i < 3; i++) {
                dq[1 + i] = wn > 0 ? sin(th / 2) * wd[i] * M_PI / 180 / wn : 0;
            }
            dqmul(qd, dq, ex);
            nrm = sqrt(ex[0] * ex[0] + ex[1] * ex[1] + ex[2] * ex[2] + ex[3] * ex[3]);
            strapdown(q, w, a.kh_m, a.kh_s, true);
            for (i = 0; i < 4; i++) {
                const double e = fabs(fq30(q[i]) - ex[i] / nrm) * 1073741824.0;
                if (e > maxe) maxe = e;
                nn += fq30(q[i]) * fq30(q[i]);
            }
            nn = fabs(sqrt(nn) - 1) * 1073741824.0;
            if (nn > maxn) maxn = nn;
        }
        printf("MEASURED strapdown fs=%.1f Hz (|w| <= 1.125 x %g deg/s per axis, %d steps): max "
               "error %.2f LSB Q30 (bound 4), max | |q|-1 | %.2f LSB (bound 2)\n",
               fs, wmax, n, maxe, maxn);
        CHECK(maxe <= 4.0);
        CHECK(maxn <= 2.0);
    }
}

/* Newton renormalisation from a 1e-6 relative norm error: within 2 LSB of 1. */
static void test_renorm(void)
{
    const int n = UNIT_SIZE(100000, 10000);
    double maxn = 0;
    int k;
    for (k = 0; k < n; k++) {
        int32_t q[4];
        double qd[4], nrm = 0, nn = 0;
        const double sc = 1 + (2 * urand() - 1) * 1e-6;
        int i;
        for (i = 0; i < 4; i++) {
            qd[i] = 2 * urand() - 1;
            nrm += qd[i] * qd[i];
        }
        nrm = sqrt(nrm);
        for (i = 0; i < 4; i++)
            q[i] = q30(qd[i] / nrm * sc);
        quat_renorm(q);
        for (i = 0; i < 4; i++)
            nn += fq30(q[i]) * fq30(q[i]);
        nn = fabs(sqrt(nn) - 1) * 1073741824.0;
        if (nn > maxn) maxn = nn;
    }
    printf("MEASURED renorm from 1e-6: max | |q|-1 | %.2f LSB (bound 2)\n", maxn);
    CHECK(maxn <= 2.0);
}

/* Long integration: a constant 300 deg/s about a tilted axis for 350 s (100000 steps; 50000 on
 * target). A constant input repeats the same rounding of h every step (<= 0.5 LSB Q30 per axis,
 * 2.6e-5 deg/s at 285.7 Hz): <= 0.009 deg after 350 s; checked < 0.01 deg. */
static void test_strapdown_long(void)
{
    struct att_config c;
    struct att a;
    int32_t q[4] = {ONE30, 0, 0, 0}, w[3];
    const double ax[3] = {0.48, -0.6, 0.64};
    const int n = UNIT_SIZE(100000, 50000);
    double qd[4], wd[3], wn = 0, th, err;
    int k, i;
    CHECK_OK(att_config_default(&c, q16(FS_BROAD)));
    REQUIRE(att_init(&a, &c) == 0);
    for (i = 0; i < 3; i++)
        w[i] = q16(300 * ax[i]);
    for (k = 0; k < n; k++)
        strapdown(q, w, a.kh_m, a.kh_s, true);
    for (i = 0; i < 3; i++) {
        wd[i] = fq16(w[i]);
        wn += wd[i] * wd[i];
    }
    wn = sqrt(wn);
    th = wn * M_PI / 180 * n / FS_BROAD;
    qd[0] = cos(th / 2);
    for (i = 0; i < 3; i++)
        qd[1 + i] = sin(th / 2) * wd[i] / wn;
    {
        const double qc[4] = {qd[0], -qd[1], -qd[2], -qd[3]};
        const double qq[4] = {fq30(q[0]), fq30(q[1]), fq30(q[2]), fq30(q[3])};
        double r[4];
        dqmul(qc, qq, r);
        err = 2 * asin(fmin(1, sqrt(r[1] * r[1] + r[2] * r[2] + r[3] * r[3]))) * 180 / M_PI;
    }
    printf("MEASURED %d steps at 300 deg/s: attitude error %.2e deg (bound 0.01)\n", n, err);
    CHECK(err < 0.01);
}

static int feed(struct att *a, double gx, double gy, double gz, double ax, double ay, double az,
                int n)
{
    struct att_sample s;
    int k, rc = 0;
    memset(&s, 0, sizeof s);
    s.gyro_dps[0] = q16(gx);
    s.gyro_dps[1] = q16(gy);
    s.gyro_dps[2] = q16(gz);
    s.acc_g[0] = q16(ax);
    s.acc_g[1] = q16(ay);
    s.acc_g[2] = q16(az);
    for (k = 0; k < n; k++)
        rc |= att_update(a, &s);
    return rc;
}

/* Inclination error between the estimate and an "up" vector given in the sensor frame. */
static double incl_err(const struct att *a, const double up_true[3])
{
    int32_t up[3];
    const double n = sqrt(up_true[0] * up_true[0] + up_true[1] * up_true[1] +
                          up_true[2] * up_true[2]);
    double d;
    att_get_up(a, up);
    d = (fq30(up[0]) * up_true[0] + fq30(up[1]) * up_true[1] + fq30(up[2]) * up_true[2]) / n;
    return acos(fmin(1, d)) * 180 / M_PI;
}

static struct att_config cfg_base, cfg_bad;
static struct att g_att;

static void check_bad(fx_q16_t *field, fx_q16_t val)
{
    struct att_sample s;
    memset(&s, 0, sizeof s);
    s.acc_g[2] = 65536;
    cfg_bad = cfg_base;
    *field = val;
    CHECK_ERR(att_init(&g_att, &cfg_bad), INC_ERR_INVAL);
    CHECK_ERR(att_update(&g_att, &s), INC_ERR_STATE); /* a failed init leaves it unusable */
}

#define BAD(f, v) check_bad(&cfg_bad.f, (v))

/* NULL arguments, use before init, every field's range, out-of-range inputs. */
static void test_config_and_errors(void)
{
    struct att_sample s;
    memset(&g_att, 0, sizeof g_att);
    memset(&s, 0, sizeof s);
    CHECK_ERR(att_config_default(NULL, 0), INC_ERR_NULL);
    CHECK_OK(att_config_default(&cfg_base, q16(FS_BROAD)));
    CHECK_ERR(att_init(NULL, &cfg_base), INC_ERR_NULL);
    CHECK_ERR(att_init(&g_att, NULL), INC_ERR_NULL);
    CHECK_ERR(att_update(&g_att, &s), INC_ERR_STATE);
    CHECK_ERR(att_reset(&g_att), INC_ERR_STATE);
    CHECK_ERR(att_reset(NULL), INC_ERR_NULL);
    CHECK_OK(att_init(&g_att, &cfg_base));
    CHECK_ERR(att_update(NULL, &s), INC_ERR_NULL);
    CHECK_ERR(att_update(&g_att, NULL), INC_ERR_NULL);
    BAD(sample_rate_hz, q16(50));
    BAD(sample_rate_hz, q16(5000));
    BAD(tau_acc_s, 0);
    BAD(tau_acc_s, q16(31));
    BAD(rest_tau_s, 0);
    BAD(rest_gyro_dps, 0);
    BAD(rest_acc_g, q16(2));
    BAD(bias_max_dps, 0);
    BAD(bias_sigma0_dps, q16(1.5));
    BAD(bias_sigma_rest_dps, q16(0.6)); /* > sigma0 */
    BAD(bias_forget_s, 0);
    BAD(bias_motion_tau_s, q16(3)); /* < 2 tau_acc */
    BAD(bias_motion_gate_g, 0);
    BAD(gyro_fs_dps, q16(50));
    BAD(gyro_fs_dps, q16(8000));
    BAD(acc_fs_g, q16(32));
    BAD(bound_floor_deg, -1);
    BAD(bound_gyro_sf, -1);
    BAD(bound_limit_deg, 0);
    BAD(bound_latency_s, q16(1));
    BAD(fault_hold_s, q16(100));
    cfg_bad = cfg_base;
    cfg_bad.sample_rate_hz = q16(100);
    cfg_bad.gyro_fs_dps = q16(4000); /* > 20 x rate */
    CHECK_ERR(att_init(&g_att, &cfg_bad), INC_ERR_INVAL);
    cfg_bad = cfg_base;
    cfg_bad.bias_motion_tau_s = 0; /* off is allowed */
    CHECK_OK(att_init(&g_att, &cfg_bad));
    CHECK_OK(att_init(&g_att, &cfg_base));

    /* An out-of-range input is rejected (INC_ERR_RANGE) and makes the output invalid for
     * fault_hold_s (1 s); the unknown rotation of the lost samples decays with tau_acc. */
    CHECK_OK(feed(&g_att, 0, 0, 0, 0, 0, 1, 2000));
    CHECK(att_get_valid(&g_att));
    s.acc_g[2] = q16(1);
    s.gyro_dps[0] = q16(3000); /* > 1.125 x 2000 */
    CHECK_ERR(att_update(&g_att, &s), INC_ERR_RANGE);
    CHECK(!att_get_valid(&g_att));
    CHECK((att_get_status(&g_att) & ATT_FAULT_INPUT) != 0);
    s.gyro_dps[0] = 0;
    s.acc_g[0] = q16(19); /* > 1.125 x 16 */
    CHECK_ERR(att_update(&g_att, &s), INC_ERR_RANGE);
    CHECK_OK(feed(&g_att, 0, 0, 0, 0, 0, 1, 200));
    CHECK(!att_get_valid(&g_att)); /* within fault_hold_s */
    CHECK_OK(feed(&g_att, 0, 0, 0, 0, 0, 1, 200));
    CHECK_EQ_INT(att_get_status(&g_att), 0); /* cleared after fault_hold_s */
    CHECK_OK(feed(&g_att, 0, 0, 0, 0, 0, 1, 10 * 286));
    CHECK(att_get_valid(&g_att));
    s.acc_g[0] = 0;
    s.veh_valid = true;
    s.speed_mps = q16(250); /* > 200 m/s */
    CHECK_ERR(att_update(&g_att, &s), INC_ERR_RANGE);
    CHECK_OK(att_reset(&g_att));
    CHECK(!att_get_valid(&g_att));
    CHECK_EQ_INT(att_get_bound(&g_att), FX_DEG_180);
    CHECK_OK(feed(&g_att, 0, 0, 0, 0, 0, 1, 10));
    CHECK(!att_get_valid(&g_att)); /* the init phase (first tau_acc) is never valid */
}

/* Static tilt with a gyro bias: rest detected, bias converged, inclination exact, bound near its
 * floor, Euler angles; a rate beyond bias_max is no rest and the bias stays clamped. */
static void test_rest_bias(void)
{
    struct att_config c;
    struct att a;
    const double r = 25 * M_PI / 180, p = -40 * M_PI / 180;
    const double up[3] = {-sin(p), sin(r) * cos(p), cos(r) * cos(p)}; /* accel at rest */
    fx_q16_t b[3], sig, roll, pitch;
    CHECK_OK(att_config_default(&c, q16(FS_BROAD)));
    REQUIRE(att_init(&a, &c) == 0);
    CHECK_OK(feed(&a, 0.6, -0.4, 0.9, up[0], up[1], up[2], 20 * 286));
    att_get_bias(&a, b, &sig);
    printf("MEASURED rest 20 s, bias (0.6, -0.4, 0.9): estimate (%.4f, %.4f, %.4f) sigma %.4f, "
           "incl err %.4f deg, bound %.3f deg\n",
           fq16(b[0]), fq16(b[1]), fq16(b[2]), fq16(sig), incl_err(&a, up),
           fq16(att_get_bound(&a)));
    CHECK(att_get_rest(&a));
    CHECK_NEAR(fq16(b[0]), 0.6, 0.02);
    CHECK_NEAR(fq16(b[1]), -0.4, 0.02);
    CHECK_NEAR(fq16(b[2]), 0.9, 0.02);
    CHECK(incl_err(&a, up) < 0.01);
    CHECK(att_get_valid(&a));
    CHECK(att_get_bound(&a) < q16(1.0));
    att_get_euler(&a, &roll, &pitch);
    printf("MEASURED euler at rest: roll %.5f (25), pitch %.5f (-40)\n", fq16(roll), fq16(pitch));
    CHECK_NEAR(fq16(roll), 25, 0.01);
    CHECK_NEAR(fq16(pitch), -40, 0.01);
    /* a 5 deg/s "bias" is beyond bias_max (2): no rest, the estimate stays within the clamp */
    REQUIRE(att_init(&a, &c) == 0);
    CHECK_OK(feed(&a, 5, 0, 0, 0, 0, 1, 10 * 286));
    att_get_bias(&a, b, &sig);
    CHECK(!att_get_rest(&a));
    CHECK(b[0] <= q16(2.0) && b[0] >= -q16(2.0));
}

/* Upside-down start (180 deg about x), then a slow tumble through every attitude (no gimbal
 * lock, no singularity of the gravity frame): inclination error < 0.1 deg, output |q| within
 * 8 LSB Q30 of 1. 120 s (60 s on target). */
static void test_tumble(void)
{
    struct att_config c;
    struct att a;
    struct att_sample s;
    double q[4] = {0, 1, 0, 0}, maxe = 0, maxn = 0;
    const double fs = FS_BROAD;
    const int n = (int)(UNIT_SIZE(120, 60) * fs);
    int k, i;
    CHECK_OK(att_config_default(&c, q16(fs)));
    REQUIRE(att_init(&a, &c) == 0);
    memset(&s, 0, sizeof s);
    for (k = 0; k < n; k++) {
        double w[3] = {0, 0, 0}, up[3], dq[4], th, wn;
        const double t = k / fs;
        if (t > 10) {
            w[0] = 40 * sin(0.1 * t);
            w[1] = 60 * cos(0.07 * t);
            w[2] = 30;
        }
        wn = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]) * M_PI / 180;
        th = wn / fs;
        dq[0] = cos(th / 2);
        for (i = 0; i < 3; i++)
            dq[1 + i] = wn > 0 ? sin(th / 2) * w[i] * M_PI / 180 / wn : 0;
        dqmul(q, dq, q);
        /* up in the sensor frame = q^-1 z */
        up[0] = 2 * (q[1] * q[3] - q[0] * q[2]);
        up[1] = 2 * (q[2] * q[3] + q[0] * q[1]);
        up[2] = 1 - 2 * (q[1] * q[1] + q[2] * q[2]);
        for (i = 0; i < 3; i++) {
            s.gyro_dps[i] = q16(w[i]);
            s.acc_g[i] = q16(up[i]);
        }
        if (att_update(&a, &s) != 0) {
            CHECK_OK(att_update(&a, &s));
            return;
        }
        if (t > 5) {
            const double e = incl_err(&a, up);
            int32_t qo[4];
            double nq = 0;
            if (e > maxe) maxe = e;
            att_get_quat(&a, qo);
            for (i = 0; i < 4; i++)
                nq += fq30(qo[i]) * fq30(qo[i]);
            nq = fabs(sqrt(nq) - 1) * 1073741824.0;
            if (nq > maxn) maxn = nq;
        }
    }
    printf("MEASURED output quaternion: max | |q|-1 | %.2f LSB Q30 (bound 8)\n", maxn);
    printf("MEASURED upside-down start + %.0f s tumble (all attitudes, up to 76 deg/s): max "
           "incl error %.4f deg (bound 0.1)\n",
           n / fs - 10, maxe);
    CHECK(maxn <= 8.0);
    CHECK(maxe < 0.1);
}

/* The bound grows monotonically while the accelerometer cannot correct (saturated on z), by at
 * least the scale-factor term x |w| x t; a saturated gyro axis adds >= 200 deg/s x t and makes
 * the output invalid; at rest again the bound returns to its floor. */
static void test_bound(void)
{
    struct att_config c;
    struct att a;
    int k, mono = 1;
    int32_t prev;
    CHECK_OK(att_config_default(&c, q16(FS_BROAD)));
    REQUIRE(att_init(&a, &c) == 0);
    CHECK_OK(feed(&a, 0, 0, 0, 0, 0, 1, 20 * 286));
    prev = att_get_bound(&a);
    CHECK(att_get_valid(&a));
    CHECK(prev < q16(1.0));
    for (k = 0; k < 10 * 286; k++) {
        (void)feed(&a, 0, 0, 100, 0, 0, 16, 1);
        if (att_get_bound(&a) < prev) mono = 0;
        prev = att_get_bound(&a);
    }
    printf("MEASURED bound after 10 s of saturated accel at 100 deg/s: %.3f deg\n", fq16(prev));
    CHECK(mono);
    CHECK(prev > q16(0.6 + 0.002 * 100 * 10 * 0.9));
    REQUIRE(att_init(&a, &c) == 0);
    CHECK_OK(feed(&a, 0, 0, 0, 0, 0, 1, 10 * 286));
    (void)feed(&a, 2000, 0, 0, 0, 0, 1, 29);
    printf("MEASURED bound after 0.1 s of a saturated gyro axis: %.3f deg\n",
           fq16(att_get_bound(&a)));
    CHECK(att_get_bound(&a) > q16(0.6 + 200 * 0.1 * 0.9));
    CHECK(!att_get_valid(&a));
    CHECK_OK(feed(&a, 0, 0, 0, 0, 0, 1, 30 * 286));
    printf("MEASURED bound after 30 s at rest again: %.3f deg\n", fq16(att_get_bound(&a)));
    CHECK(att_get_valid(&a));
    CHECK(att_get_bound(&a) < q16(1.0));
}

/* Vehicle aiding: a level car accelerating at 0.3 g, then cornering at 10 deg/s at 20.6 m/s
 * (0.37 g lateral). Without aiding the kinematic acceleration tilts the estimate (> 5 deg);
 * with speed and yaw rate it is removed (< 0.2 deg). */
static double run_vehicle(bool aid)
{
    struct att_config c;
    struct att a;
    struct att_sample s;
    const double fs = 100, up[3] = {0, 0, 1};
    double v = 0, maxe = 0;
    int k;
    (void)att_config_default(&c, q16(fs));
    if (att_init(&a, &c) != 0) return 1e9;
    memset(&s, 0, sizeof s);
    for (k = 0; k < (int)(40 * fs); k++) {
        const double t = k / fs;
        double ax = 0, ay, yaw = 0;
        if (t >= 10 && t < 17) ax = 0.3;
        if (t >= 20 && t < 40) yaw = 10;
        v += ax * 9.80665 / fs;
        ay = yaw * M_PI / 180 * v / 9.80665;
        s.gyro_dps[2] = q16(yaw);
        s.acc_g[0] = q16(ax);
        s.acc_g[1] = q16(ay);
        s.acc_g[2] = q16(1);
        s.veh_valid = aid;
        s.speed_mps = q16(v);
        s.yaw_rate_dps = q16(yaw);
        (void)att_update(&a, &s);
        if (t > 5) {
            const double e = incl_err(&a, up);
            if (e > maxe) maxe = e;
        }
    }
    return maxe;
}

static void test_vehicle(void)
{
    const double e0 = run_vehicle(false), e1 = run_vehicle(true);
    printf("MEASURED vehicle (0.3 g acceleration, 0.37 g cornering): max incl error %.3f deg "
           "without aiding, %.3f with\n",
           e0, e1);
    CHECK(e0 > 5);
    CHECK(e1 < 0.2);
}

int main(void)
{
    printf("sizeof(struct att) = %u, sizeof(struct att_config) = %u, sizeof(struct att_sample) "
           "= %u bytes\n",
           (unsigned)sizeof(struct att), (unsigned)sizeof(struct att_config),
           (unsigned)sizeof(struct att_sample));
    UNIT_RUN(test_rounding);
    UNIT_RUN(test_strapdown_step);
    UNIT_RUN(test_renorm);
    UNIT_RUN(test_strapdown_long);
    UNIT_RUN(test_config_and_errors);
    UNIT_RUN(test_rest_bias);
    UNIT_RUN(test_tumble);
    UNIT_RUN(test_bound);
    UNIT_RUN(test_vehicle);
    return unit_report();
}
