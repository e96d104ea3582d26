/*
 * Vehicle scenarios (sim/vehicle): physics consistency of the truth, determinism per seed, the
 * presets. Host only (docs/vehicle-scenarios.md lists what each check proves).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "inclino/error.h"
#include "inclino/sim/vehicle.h"
#include "unit.h"

#define PI 3.14159265358979323846
#define DEG (PI / 180.0)

static struct veh_scenario sc;
static struct veh_sim sim, sim2;

static void setup(const char *name, bool errors, double rate)
{
    struct veh_config cfg;
    veh_config_default(&cfg);
    cfg.sensor_errors = errors;
    cfg.rate_hz = rate;
    CHECK_OK(veh_preset_by_name(name, &sc));
    CHECK_OK(veh_sim_init(&sim, &sc, &cfg));
}

/* Advance to the first sample at or after t; returns 0 at the end. */
static int skip_to(struct veh_sample *o, double t)
{
    while (veh_sim_next(&sim, o)) {
        if (o->t_s >= t - 1e-12) return 1;
    }
    return 0;
}

/* Mean of the samples in [t0, t1) (the fields the checks use). */
static void window_mean(double t0, double t1, struct veh_sample *m)
{
    struct veh_sample o;
    double n = 0.0;
    int i;
    memset(m, 0, sizeof(*m));
    if (!skip_to(&o, t0)) return;
    do {
        for (i = 0; i < 3; i++) {
            m->true_acc_g[i] += o.true_acc_g[i];
            m->road_f_g[i] += o.road_f_g[i];
            m->path_acc_g[i] += o.path_acc_g[i];
        }
        m->roll_deg += o.roll_deg;
        m->pitch_deg += o.pitch_deg;
        m->body_roll_deg += o.body_roll_deg;
        m->body_pitch_deg += o.body_pitch_deg;
        m->true_speed_mps += o.true_speed_mps;
        m->true_yaw_rate_dps += o.true_yaw_rate_dps;
        m->sideslip_deg += o.sideslip_deg;
        n += 1.0;
    } while (veh_sim_next(&sim, &o) && o.t_s < t1);
    for (i = 0; i < 3; i++) {
        m->true_acc_g[i] /= n;
        m->road_f_g[i] /= n;
        m->path_acc_g[i] /= n;
    }
    m->roll_deg /= n;
    m->pitch_deg /= n;
    m->body_roll_deg /= n;
    m->body_pitch_deg /= n;
    m->true_speed_mps /= n;
    m->true_yaw_rate_dps /= n;
    m->sideslip_deg /= n;
}

static void test_presets(void)
{
    size_t i;
    CHECK_EQ_INT(veh_preset_count(), 10);
    for (i = 0; i < veh_preset_count(); i++) {
        struct veh_sample o;
        REQUIRE(veh_preset_build(i, &sc) == INC_OK);
        CHECK(strcmp(sc.name, veh_preset_name(i)) == 0);
        CHECK(veh_scenario_duration(&sc) > 30.0);
        setup(sc.name, true, VEH_RATE_ADIS);
        while (veh_sim_next(&sim, &o) && o.t_s < VEH_REST_S) {
            if (o.movement != 0 || o.true_speed_mps != 0.0) {
                unit_fail(__FILE__, __LINE__, "%s moves at %.3f s", sc.name, o.t_s);
                break;
            }
        }
    }
    CHECK_ERR(veh_preset_by_name("no_such", &sc), INC_ERR_INVAL);
    CHECK_ERR(veh_preset_by_name(NULL, &sc), INC_ERR_NULL);
    REQUIRE(veh_preset_by_name("drive_20min", &sc) == INC_OK);
    CHECK_NEAR(veh_scenario_duration(&sc), 1200.0, 1e-9);
    CHECK_NEAR(sc.temp0_c, 10.0, 0.0);
    CHECK_NEAR(sc.temp1_c, 40.0, 0.0);
}

static void test_bad_config(void)
{
    struct veh_config cfg;
    CHECK_OK(veh_preset_by_name("braking", &sc));
    veh_config_default(&cfg);
    cfg.rate_hz = 5.0;
    CHECK_ERR(veh_sim_init(&sim, &sc, &cfg), INC_ERR_INVAL);
    veh_config_default(&cfg);
    cfg.mount_deg[1] = 11.0;
    CHECK_ERR(veh_sim_init(&sim, &sc, &cfg), INC_ERR_INVAL);
    CHECK_ERR(veh_sim_init(NULL, &sc, &cfg), INC_ERR_NULL);
}

/* At rest, level, engine idling: the mean specific force is (0, 0, 1) g, the attitude level. */
static void test_rest_level(void)
{
    struct veh_sample m;
    setup("braking", false, VEH_RATE_ADIS);
    window_mean(0.0, 4.0, &m);
    CHECK_NEAR(m.true_acc_g[0], 0.0, 1e-3);
    CHECK_NEAR(m.true_acc_g[1], 0.0, 1e-3);
    CHECK_NEAR(m.true_acc_g[2], 1.0, 1e-3);
    CHECK_NEAR(m.roll_deg, 0.0, 1e-3);
    CHECK_NEAR(m.pitch_deg, 0.0, 1e-3);
    CHECK_NEAR(m.true_speed_mps, 0.0, 0.0);
}

/* Engine off on a slope: the specific force is exactly gravity seen through the truth. */
static void test_rest_slope_gravity(void)
{
    struct veh_sample o;
    setup("idle_slope", false, VEH_RATE_ADIS);
    while (veh_sim_next(&sim, &o) && o.t_s < 4.0) {
        double up[3] = {0.0, 0.0, 1.0}, qc[4] = {o.q[0], -o.q[1], -o.q[2], -o.q[3]}, g[3];
        veh_quat_rotate(qc, up, g);
        CHECK_NEAR(o.true_acc_g[0], g[0], 1e-9);
        CHECK_NEAR(o.true_acc_g[1], g[1], 1e-9);
        CHECK_NEAR(o.true_acc_g[2], g[2], 1e-9);
    }
    /* the body sits 2 deg/g * sin(grade) further nose up, 4 deg/g * sin(bank) further rolled */
    CHECK_NEAR(-o.pitch_deg, atan(0.10) / DEG + 2.0 * sin(atan(0.10)), 0.01);
    CHECK_NEAR(o.roll_deg, 2.0 + 4.0 * sin(2.0 * DEG), 0.01);
}

/* Steady cornering: lateral specific force in the road frame = v^2 / R (v along the path,
 * R the CG's radius v / r), 0.5 g; the sensor sees it through the body roll. */
static void test_steady_cornering(void)
{
    struct veh_sample m;
    double v, ay, roll;
    setup("cornering", false, VEH_RATE_ADIS);
    window_mean(35.0, 45.0, &m);
    v = m.true_speed_mps / cos(m.sideslip_deg * DEG); /* CG speed */
    ay = v * m.true_yaw_rate_dps * DEG / VEH_G;       /* v^2 / R with R = v / r */
    CHECK_NEAR(m.road_f_g[1], ay, 0.003);
    CHECK_NEAR(m.road_f_g[1], 0.5, 0.005);
    CHECK_NEAR(m.road_f_g[2], 1.0, 0.001);
    CHECK_NEAR(m.body_roll_deg, 4.0 * 0.5, 0.02); /* roll gradient 4 deg/g */
    roll = m.body_roll_deg * DEG;
    CHECK_NEAR(m.true_acc_g[1], cos(roll) * m.road_f_g[1] + sin(roll) * m.road_f_g[2], 0.002);
    CHECK_NEAR(m.true_acc_g[2], -sin(roll) * m.road_f_g[1] + cos(roll) * m.road_f_g[2], 0.002);
    /* an accelerometer-only tilt is wrong by about atan(0.5) */
    CHECK(atan2(m.true_acc_g[1], m.true_acc_g[2]) / DEG > 25.0);
}

/* 0.8 g braking from 100 km/h: the longitudinal specific force is -0.8 g on the plateau, the
 * nose dips by the pitch gradient, the car comes to rest. */
static void test_braking(void)
{
    struct veh_sample m, o;
    double th;
    setup("braking", false, VEH_RATE_ADIS);
    /* rest 5 s, to 100 km/h by ~16.5 s, braking from 20.5 s, at rest from ~24.3 s */
    window_mean(21.8, 23.8, &m);
    CHECK_NEAR(m.road_f_g[0], -0.8, 0.003);
    CHECK_NEAR(m.path_acc_g[0], -0.8, 0.003);
    CHECK_NEAR(m.body_pitch_deg, 2.0 * 0.8, 0.03); /* nose down (positive about y) */
    th = m.body_pitch_deg * DEG;
    CHECK_NEAR(m.true_acc_g[0], cos(th) * m.road_f_g[0] - sin(th) * m.road_f_g[2], 0.003);
    CHECK(skip_to(&o, 26.0));
    CHECK_NEAR(o.true_speed_mps, 0.0, 0.0);
}

/* Banked curve on a grade: true roll = bank + body roll, true pitch = -grade + body pitch. */
static void test_banked(void)
{
    struct veh_sample o;
    int n = 0;
    setup("banked_slope", false, VEH_RATE_ADIS);
    while (veh_sim_next(&sim, &o)) {
        if (o.t_s < 30.0 || o.t_s > 40.0) continue;
        CHECK_NEAR(o.bank_deg, -6.0, 1e-9);
        CHECK_NEAR(o.grade_deg, atan(0.05) / DEG, 1e-9);
        CHECK_NEAR(o.roll_deg, o.bank_deg + o.body_roll_deg, 0.03);
        CHECK_NEAR(o.pitch_deg, -o.grade_deg + o.body_pitch_deg, 0.03);
        n++;
    }
    CHECK(n > 8000);
}

/* Unit norm of the truth quaternion on the 20-minute drive (first 300 s). */
static void test_unit_norm(void)
{
    struct veh_sample o;
    double worst = 0.0;
    setup("drive_20min", true, VEH_RATE_LOW);
    while (veh_sim_next(&sim, &o) && o.t_s < UNIT_SIZE(300.0, 60.0)) {
        double n = sqrt(o.q[0] * o.q[0] + o.q[1] * o.q[1] + o.q[2] * o.q[2] + o.q[3] * o.q[3]);
        if (fabs(n - 1.0) > worst) worst = fabs(n - 1.0);
    }
    CHECK(worst < 1e-12);
}

/* q (x) exp(w dt / 2) with w = mean of the two samples plus the coning term. */
static void integrate_step(double q[4], const double w0[3], const double w1[3], double dt)
{
    double th[3], a, s, dq[4], out[4], n;
    int i;
    th[0] = 0.5 * (w0[0] + w1[0]) * dt + (w0[1] * w1[2] - w0[2] * w1[1]) * dt * dt / 12.0;
    th[1] = 0.5 * (w0[1] + w1[1]) * dt + (w0[2] * w1[0] - w0[0] * w1[2]) * dt * dt / 12.0;
    th[2] = 0.5 * (w0[2] + w1[2]) * dt + (w0[0] * w1[1] - w0[1] * w1[0]) * dt * dt / 12.0;
    a = sqrt(th[0] * th[0] + th[1] * th[1] + th[2] * th[2]);
    s = a > 1e-15 ? sin(0.5 * a) / a : 0.5;
    dq[0] = cos(0.5 * a);
    for (i = 0; i < 3; i++) {
        dq[1 + i] = s * th[i];
    }
    veh_quat_mul(q, dq, out);
    n = sqrt(out[0] * out[0] + out[1] * out[1] + out[2] * out[2] + out[3] * out[3]);
    for (i = 0; i < 4; i++) {
        q[i] = out[i] / n;
    }
}

static double quat_angle_deg(const double a[4], const double b[4])
{
    double d = fabs(a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3]);
    return d >= 1.0 ? 0.0 : 2.0 * acos(d) / DEG;
}

/* Integrating the true gyro rate from the initial truth reproduces the truth (< 0.01 deg over
 * 60 s), at both rates, with a mounting misalignment. */
static void check_integration(const char *name, double rate, double t0)
{
    struct veh_config cfg;
    struct veh_sample o;
    double q[4], w0[3], worst = 0.0, dt = 1.0 / rate;
    int i, first = 1;
    veh_config_default(&cfg);
    cfg.sensor_errors = false;
    cfg.rate_hz = rate;
    cfg.mount_deg[0] = 1.0;
    cfg.mount_deg[1] = -0.5;
    cfg.mount_deg[2] = 2.0;
    REQUIRE(veh_preset_by_name(name, &sc) == INC_OK);
    REQUIRE(veh_sim_init(&sim, &sc, &cfg) == INC_OK);
    while (veh_sim_next(&sim, &o)) {
        double w1[3];
        if (o.t_s < t0) continue;
        if (o.t_s > t0 + 60.0) break;
        for (i = 0; i < 3; i++) {
            w1[i] = o.true_gyr_dps[i] * DEG;
        }
        if (first) {
            memcpy(q, o.q, sizeof(q));
            first = 0;
        } else {
            double e;
            integrate_step(q, w0, w1, dt);
            e = quat_angle_deg(q, o.q);
            if (e > worst) worst = e;
        }
        memcpy(w0, w1, sizeof(w0));
    }
    if (!(worst < 0.01)) {
        unit_fail(__FILE__, __LINE__, "%s at %.3f Hz: integrated attitude off by %.4f deg", name,
                  rate, worst);
    }
    CHECK(worst < 0.01);
}

static void test_gyro_integration(void)
{
    check_integration("cornering", VEH_RATE_ADIS, 0.0);
    check_integration("lane_change", VEH_RATE_LOW, 0.0);
    check_integration("banked_slope", VEH_RATE_ADIS, 5.0);
    check_integration("rough_road", VEH_RATE_ADIS, 5.0);
    check_integration("speed_bumps", VEH_RATE_LOW, 0.0);
    check_integration("parking", VEH_RATE_ADIS, 0.0);
}

/* The same seed gives the same samples; another seed other sensor errors, the same truth. */
static void test_determinism(void)
{
    struct veh_config cfg;
    struct veh_sample a, b;
    int same = 1, diff_meas = 0, same_truth = 1;
    veh_config_default(&cfg);
    cfg.seed = 42;
    REQUIRE(veh_preset_by_name("rough_road", &sc) == INC_OK);
    REQUIRE(veh_sim_init(&sim, &sc, &cfg) == INC_OK);
    REQUIRE(veh_sim_init(&sim2, &sc, &cfg) == INC_OK);
    while (veh_sim_next(&sim, &a) && veh_sim_next(&sim2, &b) && a.t_s < 20.0) {
        if (memcmp(&a, &b, sizeof(a)) != 0) same = 0;
    }
    CHECK(same);
    cfg.seed = 43;
    REQUIRE(veh_sim_init(&sim, &sc, &cfg) == INC_OK);
    cfg.seed = 42;
    REQUIRE(veh_sim_init(&sim2, &sc, &cfg) == INC_OK);
    while (veh_sim_next(&sim, &a) && veh_sim_next(&sim2, &b) && a.t_s < 4.0) {
        if (a.gyr_dps[0] != b.gyr_dps[0]) diff_meas = 1;
        if (memcmp(a.q, b.q, sizeof(a.q)) != 0) same_truth = 0;
    }
    CHECK(diff_meas);
    CHECK(same_truth); /* at rest the truth does not depend on the road-noise stream */
}

/* Sensor errors: the noise at rest is ADIS16405-like, the ESC signals track the truth. */
static void test_sensors(void)
{
    struct veh_sample o;
    double s = 0.0, s2 = 0.0, n = 0.0, vs = 0.0, vt = 0.0;
    setup("braking", true, VEH_RATE_ADIS);
    while (veh_sim_next(&sim, &o)) {
        if (o.t_s < 4.0) {
            s += o.acc_g[0];
            s2 += o.acc_g[0] * o.acc_g[0];
            n += 1.0;
        }
        if (o.t_s >= 19.0 && o.t_s < 22.0) { /* cruising at 100 km/h */
            vs += o.speed_mps;
            vt += o.true_speed_mps;
        }
        CHECK(fabs(o.gyr_dps[0]) <= 300.0 && fabs(o.acc_g[2]) <= 18.0);
        CHECK(fabs(remainder(o.gyr_dps[1], 0.05)) < 1e-9);
    }
    s /= n;
    /* accel x: white 0.5 mg/sqrt(Hz) density -> about 10 mg rms per sample, plus quantisation */
    CHECK_NEAR(sqrt(s2 / n - s * s), 0.0101, 0.002);
    CHECK(fabs(vs / vt - 1.0) < 0.03); /* tyre scale 0.5 % (1 sigma) and tooth errors */
}

int main(void)
{
    UNIT_RUN(test_presets);
    UNIT_RUN(test_bad_config);
    UNIT_RUN(test_rest_level);
    UNIT_RUN(test_rest_slope_gravity);
    UNIT_RUN(test_steady_cornering);
    UNIT_RUN(test_braking);
    UNIT_RUN(test_banked);
    UNIT_RUN(test_unit_norm);
    UNIT_RUN(test_gyro_integration);
    UNIT_RUN(test_determinism);
    UNIT_RUN(test_sensors);
    return unit_report();
}
