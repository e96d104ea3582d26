/*
 * test_app_esc.c - the ESC run mode and the parked/driving mode manager (inclino/app_esc.h) on
 * scripted samples: parked outputs are the EPB slope estimates, driving outputs the attitude
 * every out_div samples with its bound, the switch by speed and by stillness, the EPB block
 * dropped when the car moves, the autonull request and the processor-side gyro correction, bad
 * calls. Host and QEMU (integer only apart from the scripted sine waves).
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "inclino/app_esc.h"
#include "unit.h"

#define RATE_MHZ 819200u
#define DEG (3.14159265358979323846 / 180.0)

static int script_wait(void *dev, uint32_t timeout_ns)
{
    (void)dev;
    (void)timeout_ns;
    return INC_ERR_UNSUPPORTED;
}

static int script_read(void *dev, struct sensor_sample *out)
{
    (void)dev;
    (void)out;
    return INC_ERR_UNSUPPORTED; /* samples are fed with app_esc_step */
}

static int script_identity(void *dev, struct sensor_identity *out)
{
    (void)dev;
    memset(out, 0, sizeof(*out));
    out->family = SENSOR_FAMILY_ADIS163XX;
    out->product = 16405u;
    return INC_OK;
}

static const struct sensor_ops script_ops = {NULL, script_wait,     script_read, NULL,
                                             NULL, script_identity, NULL};
static struct app app;
static struct app_esc esc;
static uint32_t rng = 99u;

static double noise(double sd)
{
    double s = 0;
    int i;
    for (i = 0; i < 4; i++)
        s += (unit_rand32(&rng) >> 8) / 16777216.0;
    return (s - 2.0) * 1.7320508 * sd;
}

/* A sample of a part at roll r, pitch p (deg), with a gyro rate and a bias on every axis. */
static void sample(struct sensor_sample *s, double r, double p, const double w[3], double bias)
{
    unsigned i;
    memset(s, 0, sizeof(*s));
    s->accel_g[0] = (int32_t)lround((-sin(p * DEG) + noise(0.002)) * 65536.0);
    s->accel_g[1] = (int32_t)lround((sin(r * DEG) * cos(p * DEG) + noise(0.002)) * 65536.0);
    s->accel_g[2] = (int32_t)lround((cos(r * DEG) * cos(p * DEG) + noise(0.002)) * 65536.0);
    for (i = 0; i < 3u; i++)
        s->gyro_dps[i] = (int32_t)lround((w[i] + bias + noise(0.1)) * 65536.0);
    s->flags = SENSOR_S_HAVE_ACCEL | SENSOR_S_HAVE_GYRO;
}

static void setup(struct app_esc_cfg *ec)
{
    struct app_cfg cfg;
    const struct sensor sensor = {&script_ops, NULL};
    REQUIRE(app_cfg_default(&cfg, RATE_MHZ) == INC_OK);
    REQUIRE(app_init(&app, &cfg, &sensor, NULL) == INC_OK);
    REQUIRE(app_esc_cfg_default(ec, RATE_MHZ) == INC_OK);
    ec->autonull_after_s = FX_Q16_INT(5);
    REQUIRE(app_esc_init(&esc, ec) == INC_OK);
}

/* Parked, then driving (speed), then parked again (speed 0 and at rest). */
static void test_modes(void)
{
    static const double zero[3] = {0, 0, 0};
    struct app_esc_cfg ec;
    struct app_vehicle veh = {true, 0, 0};
    struct sensor_sample s;
    struct app_esc_output o;
    unsigned i, parked_out = 0u, driving_out = 0u, gap_max = 0u, since = 0u;
    double worst = 0.0;
    bool have;
    setup(&ec);
    CHECK_EQ_INT(app_esc_mode(&esc), APP_MODE_PARKED);
    /* 8 s parked on a 4 deg roll: EPB blocks (2.5 s) come out, tagged PARKED. */
    for (i = 0; i < 8u * 819u; i++) {
        sample(&s, 4.0, 0.0, zero, 0.0);
        REQUIRE(app_esc_step(&esc, &app, &s, INC_OK, &veh, &o, &have) == INC_OK);
        if (have) {
            CHECK_EQ_INT(o.mode, APP_MODE_PARKED);
            parked_out++;
        }
    }
    CHECK(parked_out >= 2u);
    CHECK(app_esc_autonull_due(&esc)); /* 5 s parked since the start */
    /* Driving at 15 m/s while rolling 4 +- 10 deg at 0.2 Hz: attitude every 8 samples. */
    veh.speed_mps = FX_Q16_INT(15);
    for (i = 0; i < 20u * 819u; i++) {
        const double t = i / 819.2, roll = 4.0 + 10.0 * sin(2 * 3.14159265358979 * 0.2 * t);
        const double w[3] = {
            10.0 * 2 * 3.14159265358979 * 0.2 * cos(2 * 3.14159265358979 * 0.2 * t), 0, 0};
        sample(&s, roll, 0.0, w, 0.0);
        REQUIRE(app_esc_step(&esc, &app, &s, INC_OK, &veh, &o, &have) == INC_OK);
        since++;
        if (have) {
            const double err = fabs(o.roll_deg / 65536.0 - roll);
            CHECK_EQ_INT(o.mode, APP_MODE_DRIVING);
            CHECK(o.bound_deg > 0);
            if (since > gap_max) gap_max = since;
            since = 0u;
            driving_out++;
            if (o.valid && err > o.bound_deg / 65536.0) {
                worst = err;
                printf("t %.3f s: roll %.3f, estimate %.3f, bound %.3f deg\n", t, roll,
                       o.roll_deg / 65536.0, o.bound_deg / 65536.0);
            }
        }
    }
    CHECK_EQ_INT(app_esc_mode(&esc), APP_MODE_DRIVING);
    CHECK(!app_esc_autonull_due(&esc));
    CHECK_NEAR(driving_out, 20u * 819u / 8u, 2);
    CHECK_EQ_INT(gap_max, 8);
    CHECK(worst == 0.0); /* no valid output outside its bound */
    /* Stop: speed 0 and at rest on a 2 deg pitch: PARKED after the detector's windows + 2 s. */
    veh.speed_mps = 0;
    parked_out = 0u;
    for (i = 0; i < 8u * 819u; i++) {
        sample(&s, 0.0, 2.0, zero, 0.0);
        REQUIRE(app_esc_step(&esc, &app, &s, INC_OK, &veh, &o, &have) == INC_OK);
        if (have && o.mode == APP_MODE_PARKED) parked_out++;
    }
    CHECK_EQ_INT(app_esc_mode(&esc), APP_MODE_PARKED);
    CHECK(parked_out >= 1u);
}

/* Without a speed input the stillness detector alone switches to DRIVING, and no driving
 * output is valid (a sustained acceleration cannot be told from a tilt without the speed). */
static void test_no_speed(void)
{
    struct app_esc_cfg ec;
    struct sensor_sample s;
    struct app_esc_output o;
    unsigned i, driving = 0u, valid = 0u;
    bool have;
    setup(&ec);
    for (i = 0; i < 3u * 819u; i++) {
        const double w[3] = {0, 0, 30.0 * sin(i / 40.0)};
        sample(&s, 0.0, 0.0, w, 0.0);
        REQUIRE(app_esc_step(&esc, &app, &s, INC_OK, NULL, &o, &have) == INC_OK);
        if (have && o.mode == APP_MODE_DRIVING) {
            driving++;
            valid += o.valid ? 1u : 0u;
        }
    }
    CHECK_EQ_INT(app_esc_mode(&esc), APP_MODE_DRIVING);
    CHECK(driving > 10u);
    CHECK_EQ_INT(valid, 0);
}

/* The processor-side correction (1/320 deg/s) removes a known gyro bias before the estimator:
 * with the bias corrected the estimator's own bias estimate stays near 0. */
static void test_gyro_correction(void)
{
    static const double zero[3] = {0, 0, 0};
    struct app_esc_cfg ec;
    struct gyrocal_correction gc = {{-320, -320, -320}, true};
    struct sensor_sample s;
    struct app_esc_output o;
    fx_q16_t bias[3], sig;
    unsigned i;
    bool have;
    setup(&ec);
    REQUIRE(app_esc_set_gyro_correction(&esc, &gc) == INC_OK);
    CHECK(!app_esc_autonull_due(&esc));
    for (i = 0; i < 10u * 819u; i++) {
        sample(&s, 0.0, 0.0, zero, 1.0); /* 1 deg/s bias on every axis */
        REQUIRE(app_esc_step(&esc, &app, &s, INC_OK, NULL, &o, &have) == INC_OK);
    }
    att_get_bias(&esc.att, bias, &sig);
    CHECK_NEAR(bias[0] / 65536.0, 0.0, 0.05);
    CHECK_NEAR(bias[1] / 65536.0, 0.0, 0.05);
    CHECK_EQ_INT(app_esc_set_gyro_correction(NULL, &gc), INC_ERR_NULL);
}

static void test_bad_calls(void)
{
    struct app_esc_cfg ec;
    struct app_esc e2;
    struct app_esc_output o;
    struct sensor_sample s;
    bool have;
    CHECK_EQ_INT(app_esc_cfg_default(NULL, RATE_MHZ), INC_ERR_NULL);
    CHECK_EQ_INT(app_esc_cfg_default(&ec, 50000u), INC_ERR_INVAL);
    REQUIRE(app_esc_cfg_default(&ec, RATE_MHZ) == INC_OK);
    ec.out_div = 0u;
    CHECK_EQ_INT(app_esc_init(&e2, &ec), INC_ERR_INVAL);
    CHECK_EQ_INT(app_esc_step(&e2, &app, &s, INC_OK, NULL, &o, &have), INC_ERR_STATE);
    REQUIRE(app_esc_cfg_default(&ec, RATE_MHZ) == INC_OK);
    ec.att.tau_acc_s = 0;
    CHECK_EQ_INT(app_esc_init(&e2, &ec), INC_ERR_INVAL);
    CHECK_EQ_INT(app_esc_init(NULL, &ec), INC_ERR_NULL);
    CHECK_EQ_INT(app_esc_mode(NULL), APP_MODE_PARKED);
    CHECK(!app_esc_autonull_due(NULL));
}

/* The driving diagnostics (app_esc_diag_default): none fires on a clean drive; then each one
 * fires on its fault (a flat gyro channel, an accelerometer bias step against the wheel speed,
 * the second accelerometer disagreeing), latches, and takes the validity of every later DRIVING
 * output; bad values are refused. */
static void drive_case(int fault, uint8_t want)
{
    struct app_esc_cfg ec;
    struct app_vehicle veh = {true, 0, 0};
    struct sensor_sample s;
    struct app_esc_output o;
    unsigned i, valid_before = 0u, valid_after = 0u, out_before = 0u, first = 0u;
    uint8_t seen = 0u;
    bool have;
    setup(&ec);
    REQUIRE(app_esc_diag_default(&ec) == INC_OK);
    CHECK_EQ_INT(ec.flat_n, 16);
    CHECK_EQ_INT(ec.diag_shift, 8);
    CHECK_EQ_INT(ec.diag_persist_n, 41);
    REQUIRE(app_esc_init(&esc, &ec) == INC_OK);
    for (i = 0; i < 24u * 819u; i++) {
        /* 8 s parked, then driving at 15 m/s rolling 4 +- 10 deg at 0.2 Hz; the fault at 16 s */
        const double t = i / 819.2, td = t < 8.0 ? 0.0 : t - 8.0;
        const double roll = 4.0 + 10.0 * sin(2 * 3.14159265358979 * 0.2 * td);
        const double w[3] = {t < 8.0 ? 0.0
                                     : 10.0 * 2 * 3.14159265358979 * 0.2 *
                                           cos(2 * 3.14159265358979 * 0.2 * td),
                             0, 0};
        const bool on = t >= 16.0;
        veh.speed_mps = t < 8.0 ? 0 : FX_Q16_INT(15);
        fx_q16_t aux[3];
        sample(&s, roll, 0.0, w, 0.0);
        aux[0] = s.accel_g[0];
        aux[1] = s.accel_g[1];
        aux[2] = s.accel_g[2];
        if (on && fault == 1) s.gyro_dps[2] = FX_Q16_ONE / 10; /* a stuck yaw-rate channel */
        if (on && fault == 2) s.accel_g[0] += FX_Q16_ONE / 10; /* 100 mg on x */
        if (on && fault == 3) aux[0] += FX_Q16_ONE / 20;       /* 50 mg on the second part */
        REQUIRE(app_esc_set_aux_accel(&esc, aux, fault != 2) == INC_OK);
        REQUIRE(app_esc_step(&esc, &app, &s, INC_OK, &veh, &o, &have) == INC_OK);
        if (!have || o.mode != APP_MODE_DRIVING) continue;
        if (!on) {
            out_before++;
            valid_before += o.valid ? 1u : 0u;
            CHECK_EQ_INT(o.diag, 0);
        } else {
            valid_after += o.valid ? 1u : 0u;
            if (o.diag != 0u && first == 0u) first = i;
            seen |= o.diag;
        }
    }
    printf("  fault %d: valid %u/%u before, %u after; diag 0x%02x, %u samples after the onset\n",
           fault, valid_before, out_before, valid_after, seen,
           first > 0u ? first - 16u * 819u : 0u);
    CHECK(valid_before > out_before * 3u / 4u);
    CHECK_EQ_INT(seen, want);
    if (want != 0u) {
        CHECK(first > 0u && first - 16u * 819u <= 819u); /* within 1 s */
        CHECK(valid_after <= 819u / 8u + 1u);            /* none valid after it */
    } else {
        CHECK(valid_after > 0u);
    }
}

static void test_driving_diagnostics(void)
{
    struct app_esc_cfg ec;
    const fx_q16_t a3[3] = {0, 0, FX_Q16_ONE};
    drive_case(0, 0u);
    drive_case(1, APP_ESC_D_FLAT);
    drive_case(2, APP_ESC_D_VEH);
    drive_case(3, APP_ESC_D_XCHK);
    setup(&ec);
    CHECK_ERR(app_esc_diag_default(NULL), INC_ERR_NULL);
    CHECK_ERR(app_esc_set_aux_accel(NULL, a3, true), INC_ERR_NULL);
    CHECK_ERR(app_esc_set_aux_accel(&esc, NULL, true), INC_ERR_NULL);
    REQUIRE(app_esc_diag_default(&ec) == INC_OK);
    ec.flat_n = 1u;
    CHECK_ERR(app_esc_init(&esc, &ec), INC_ERR_INVAL);
    REQUIRE(app_esc_diag_default(&ec) == INC_OK);
    ec.veh_bound_k = 0;
    CHECK_ERR(app_esc_init(&esc, &ec), INC_ERR_INVAL);
    REQUIRE(app_esc_diag_default(&ec) == INC_OK);
    ec.xchk_thr_g = FX_Q16_INT(2);
    CHECK_ERR(app_esc_init(&esc, &ec), INC_ERR_INVAL);
    REQUIRE(app_esc_diag_default(&ec) == INC_OK);
    ec.diag_shift = 17u;
    CHECK_ERR(app_esc_init(&esc, &ec), INC_ERR_INVAL);
    REQUIRE(app_esc_diag_default(&ec) == INC_OK);
    CHECK_OK(app_esc_init(&esc, &ec));
}

/* The cross-check's term (app_esc_cfg.xchk_margin_g) in double: T = thr + margin for the
 * x-y norm and for z, the bias component across up at most T (1 + s), s = sqrt(u_x^2 + u_y^2),
 * as the angle T (1 + s) / (1 - sqrt(2) T) rad, in degrees. */
static double xterm_deg(const struct app_esc_cfg *ec, const int32_t up_q30[3])
{
    const double t = (ec->xchk_thr_g + ec->xchk_margin_g) / 65536.0;
    const double ux = up_q30[0] / 1073741824.0, uy = up_q30[1] / 1073741824.0;
    if (ec->xchk_thr_g == 0) return 0.0;
    return t * (1.0 + sqrt(ux * ux + uy * uy)) / (1.0 - sqrt(2.0) * t) / DEG;
}

/* The published DRIVING bound against what it should be, computed here in double: the att
 * bound + the cross-check's term (xterm_deg), or the floor when larger. */
static void check_bound(const struct app_esc_cfg *ec, const struct app_esc_output *o,
                        double floor_deg)
{
    int32_t up[3];
    double want;
    att_get_up(&esc.att, up);
    want = att_get_bound(&esc.att) / 65536.0 + xterm_deg(ec, up);
    if (floor_deg > want) {
        /* floor_deg is derived from the reported threshold, itself rounded: within 0.002 */
        CHECK(fabs(o->bound_deg / 65536.0 - floor_deg) < 0.002);
    } else {
        /* the firmware rounds every step up: at or above the exact value, by a few LSB */
        CHECK(o->bound_deg / 65536.0 >= want - 2e-5);
        CHECK(o->bound_deg / 65536.0 <= want + 0.002);
    }
}

/* Level-ish at (roll, pitch) for 8 s at rest, then at 15 m/s: while the vehicle-level check
 * runs the published bound is the larger of the att bound + the cross-check's term and the
 * floor, the error computed here from the threshold the output reports. */
static void floor_case(fx_q16_t gyro_dps, fx_q16_t xthr, double roll, double pitch,
                       unsigned *n_checked)
{
    struct app_esc_cfg ec;
    struct app_vehicle veh = {true, 0, 0};
    struct sensor_sample s;
    struct app_esc_output o;
    const double w[3] = {0, 0, 0};
    const double lag = gyro_dps / 65536.0 * (512.0 + 41.0) / 819.2; /* 2^(8+1) + 41 samples */
    unsigned i;
    bool have;
    setup(&ec);
    REQUIRE(app_esc_diag_default(&ec) == INC_OK);
    CHECK_EQ_INT(ec.veh_gyro_dps, FX_Q16_INT(2));
    CHECK_EQ_INT(ec.xchk_margin_g, 655); /* 0.01 g */
    ec.veh_gyro_dps = gyro_dps;
    ec.xchk_thr_g = xthr;
    REQUIRE(app_esc_init(&esc, &ec) == INC_OK);
    for (i = 0; i < 20u * 819u; i++) {
        const double t = i / 819.2;
        veh.speed_mps = t < 8.0 ? 0 : FX_Q16_INT(15);
        sample(&s, roll, pitch, w, 0.0);
        REQUIRE(app_esc_step(&esc, &app, &s, INC_OK, &veh, &o, &have) == INC_OK);
        if (!have || o.mode != APP_MODE_DRIVING || o.veh_thr_g == 0) continue;
        {
            const double b_att = att_get_bound(&esc.att) / 65536.0;
            const double rest = o.veh_thr_g / 65536.0 - 0.5 * b_att * DEG;
            check_bound(&ec, &o, gyro_dps == 0 ? 0.0 : rest / 0.5 / DEG + lag);
            if (gyro_dps != 0) {
                /* at a steady speed: the margin's 15 mg alone is 1.72 deg */
                CHECK(o.bound_deg / 65536.0 >= 0.015 / 0.5 / DEG + lag - 0.002);
            }
            if (xthr != 0) {
                /* 40 mg across up: at least 40 mg as an angle, 2.3 deg */
                CHECK(o.bound_deg / 65536.0 >= b_att + 0.04 / DEG - 0.002);
            }
            (*n_checked)++;
        }
    }
}

/* The floor without the check: at 15 m/s for 10 s (the check runs), then at 1 m/s (below
 * veh_min_mps, still DRIVING): the floor grows from its last value by veh_gyro_dps per second;
 * back at 15 m/s it is the check's again. From PARKED straight to 1 m/s it starts from the
 * floor at rest (the margin's share + the delay's, 3.07 deg). */
static void test_bound_growth(void)
{
    struct app_esc_cfg ec;
    struct app_vehicle veh = {true, 0, 0};
    struct sensor_sample s;
    struct app_esc_output o;
    const double w[3] = {0, 0, 0};
    const double rest = 0.015 / 0.5 / DEG + 2.0 * (512.0 + 41.0) / 819.2;
    double last = 0.0;
    unsigned i, slow_n = 0u, grown = 0u, first = 0u;
    bool have;
    setup(&ec);
    REQUIRE(app_esc_diag_default(&ec) == INC_OK);
    ec.xchk_thr_g = 0; /* the floor alone */
    REQUIRE(app_esc_init(&esc, &ec) == INC_OK);
    for (i = 0; i < 20u * 819u; i++) {
        const double t = i / 819.2;
        veh.speed_mps = t < 2.0    ? FX_Q16_INT(1)
                        : t < 6.0  ? 0
                        : t < 16.0 ? FX_Q16_INT(15)
                                   : FX_Q16_INT(1);
        sample(&s, 3.0, -2.0, w, 0.0);
        REQUIRE(app_esc_step(&esc, &app, &s, INC_OK, &veh, &o, &have) == INC_OK);
        if (t >= 16.0) slow_n++;
        if (!have || o.mode != APP_MODE_DRIVING) continue;
        if (t < 2.0) {
            /* from PARKED at 1 m/s: the floor at rest + 2 deg/s since, sample by sample */
            const double b_att = att_get_bound(&esc.att) / 65536.0;
            const double grow = rest + 2.0 * (i + 1u) / 819.2;
            const double want = grow > b_att ? grow : b_att;
            CHECK(o.bound_deg / 65536.0 >= want - 0.002);
            CHECK(o.bound_deg / 65536.0 <= want + 0.002 + (i + 1u) / 65536.0);
            first++;
        } else if (t < 16.0 && o.veh_thr_g != 0) {
            last = o.bound_deg / 65536.0; /* the check's floor (test_bound_floor) */
        } else if (t >= 16.0) {
            const double want = last + 2.0 * slow_n / 819.2;
            CHECK_EQ_INT(o.veh_thr_g, 0);
            CHECK(o.bound_deg / 65536.0 >= want - 0.01);
            CHECK(o.bound_deg / 65536.0 <= want + 0.01 + slow_n / 65536.0);
            grown++;
        }
    }
    CHECK(first > 150u);
    CHECK(grown > 350u); /* 4 s of outputs at about 100 Hz */
    CHECK(last > 3.0 && last < 3.2);
    CHECK(o.bound_deg / 65536.0 > last + 7.9); /* 4 s x 2 deg/s */
}

static void test_bound_floor(void)
{
    struct app_esc_cfg ec;
    unsigned n = 0u;
    const fx_q16_t thr = (fx_q16_t)((FX_Q16_ONE * 3 + 50) / 100);
    floor_case(FX_Q16_INT(2), thr, 3.0, -2.0, &n);
    CHECK(n > 800u); /* 12 s of outputs at about 100 Hz, the check running */
    n = 0u;
    floor_case(FX_Q16_INT(2), 0, 3.0, -2.0, &n);
    CHECK(n > 800u);
    n = 0u;
    floor_case(0, thr, 3.0, -2.0, &n);
    CHECK(n > 800u);
    n = 0u;
    floor_case(0, 0, 3.0, -2.0, &n); /* att's bound alone */
    CHECK(n > 800u);
    n = 0u;
    floor_case(FX_Q16_INT(2), thr, 25.0, 20.0, &n); /* up off the z axis: s = 0.53 */
    CHECK(n > 800u);
    n = 0u;
    floor_case(0, thr, -28.0, 15.0, &n);
    CHECK(n > 800u);
    setup(&ec);
    REQUIRE(app_esc_diag_default(&ec) == INC_OK);
    ec.veh_gyro_dps = FX_Q16_INT(50) + 1;
    CHECK_ERR(app_esc_init(&esc, &ec), INC_ERR_INVAL);
    ec.veh_gyro_dps = -1;
    CHECK_ERR(app_esc_init(&esc, &ec), INC_ERR_INVAL);
    ec.veh_gyro_dps = FX_Q16_INT(50);
    CHECK_OK(app_esc_init(&esc, &ec));
    ec.xchk_margin_g = -1;
    CHECK_ERR(app_esc_init(&esc, &ec), INC_ERR_INVAL);
    ec.xchk_margin_g = FX_Q16_ONE + 1;
    CHECK_ERR(app_esc_init(&esc, &ec), INC_ERR_INVAL);
    ec.xchk_margin_g = FX_Q16_ONE;
    CHECK_OK(app_esc_init(&esc, &ec));
}

int main(void)
{
    UNIT_RUN(test_modes);
    UNIT_RUN(test_no_speed);
    UNIT_RUN(test_gyro_correction);
    UNIT_RUN(test_bad_calls);
    UNIT_RUN(test_driving_diagnostics);
    UNIT_RUN(test_bound_floor);
    UNIT_RUN(test_bound_growth);
    return unit_report();
}
