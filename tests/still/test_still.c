/*
 * Stillness and thermal settling (firmware/signal/still): configuration checks, exact window statistics
 * and threshold boundaries, the state machine, each test's trigger (variance, steady rotation,
 * steady acceleration, slow tilt, overrange) with int32 extremes, and simulated ADIS1636x-like
 * data (white noise of the [ADI-IMU-QS] density, 0.05 deg/s and 1 mg per LSB): at rest -> AT_REST
 * with no false alarm, vibration / rotation / tilt -> MOVING; a warming part -> settled only once
 * the temperature stops moving.
 * Host and QEMU (fewer simulated windows where UNIT_REDUCED: QEMU, sanitizers).
 */
#include "inclino/still.h"
#include "inclino/sim/inertial.h"
#include "inclino/sim/noise.h"
#include "unit.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#if UNIT_REDUCED
#define SIM_WINDOWS 12u
#else
#define SIM_WINDOWS 120u
#endif

static struct still_cfg base_cfg(void)
{
    struct still_cfg c;
    memset(&c, 0, sizeof(c));
    c.window = 4;
    c.windows_required = 1;
    c.gyro_var_max = 2;
    c.accel_var_max = 2;
    return c;
}

static void push_const(struct still *s, int32_t g, int32_t a, uint32_t n)
{
    const int32_t gy[3] = {g, g, g}, ac[3] = {a, a, a};
    uint32_t i;
    for (i = 0; i < n; i++) {
        (void)still_push(s, gy, ac, NULL);
    }
}

static void test_config(void)
{
    struct still s;
    struct still_cfg c = base_cfg();
    const int32_t z[3] = {0, 0, 0};
    memset(&s, 0, sizeof(s));
    CHECK_ERR(still_push(&s, z, z, NULL), INC_ERR_STATE); /* never initialised */
    c.window = 1;
    CHECK_ERR(still_init(&s, &c), INC_ERR_INVAL);
    CHECK_ERR(still_push(&s, z, z, NULL), INC_ERR_STATE); /* failed init refuses */
    c.window = STILL_WINDOW_MAX + 1u;
    CHECK_ERR(still_init(&s, &c), INC_ERR_INVAL);
    c = base_cfg();
    c.windows_required = 0;
    CHECK_ERR(still_init(&s, &c), INC_ERR_INVAL);
    c = base_cfg();
    c.gyro_var_max = STILL_VAR_LIMIT + 1u;
    CHECK_ERR(still_init(&s, &c), INC_ERR_INVAL);
    c = base_cfg();
    c.accel_one_g = -1;
    CHECK_ERR(still_init(&s, &c), INC_ERR_INVAL);
    c.accel_one_g = (int32_t)STILL_ONE_G_MAX + 1;
    CHECK_ERR(still_init(&s, &c), INC_ERR_INVAL);
    c.accel_one_g = 1000;
    c.accel_norm_tol = 1000;
    CHECK_ERR(still_init(&s, &c), INC_ERR_INVAL);
    c.accel_norm_tol = 999;
    CHECK_OK(still_init(&s, &c));
    CHECK_ERR(still_init(NULL, &c), INC_ERR_NULL);
    CHECK_ERR(still_push(&s, NULL, z, NULL), INC_ERR_NULL);
    CHECK(still_state_get(NULL) == STILL_UNKNOWN);
    CHECK(still_last(&s) == NULL);
}

/* W = 4, gyro x = 1, 2, 3, 4: mean 2.5 -> 3, variance 1.25 -> 1; exact thresholds. */
static void test_exact_window(void)
{
    struct still s;
    struct still_cfg c = base_cfg();
    const int32_t xs[4] = {1, 2, 3, 4}, ys[4] = {0, 0, 2, 2}, zs[4] = {-1, -2, -3, -4};
    const struct still_window *w;
    bool done = false;
    unsigned i;
    c.gyro_var_max = 1; /* 1.25 > 1: not quiet */
    REQUIRE(still_init(&s, &c) == INC_OK);
    for (i = 0; i < 4u; i++) {
        const int32_t g[3] = {xs[i], ys[i], zs[i]}, a[3] = {5, 5, 5};
        CHECK_OK(still_push(&s, g, a, &done));
        CHECK_EQ_INT(done, i == 3u);
    }
    w = still_last(&s);
    REQUIRE(w != NULL);
    CHECK_EQ_INT(w->gyro_mean[0], 3);
    CHECK_EQ_INT(w->gyro_mean[1], 1);
    CHECK_EQ_INT(w->gyro_mean[2], -3); /* -2.5: ties away from zero */
    CHECK_EQ_INT(w->gyro_var[0], 1);
    CHECK_EQ_INT(w->gyro_var[1], 1); /* exactly 1 */
    CHECK_EQ_INT(w->accel_var[0], 0);
    CHECK_EQ_INT(w->accel_mean[2], 5);
    CHECK(!w->quiet);
    CHECK_EQ_HEX(w->why, STILL_WHY_GYRO_VAR);
    CHECK(still_state_get(&s) == STILL_MOVING);
    /* variance exactly at the limit is quiet: y axis alone (var 1 == 1) */
    for (i = 0; i < 4u; i++) {
        const int32_t g[3] = {0, ys[i], 0}, a[3] = {0, 0, 0};
        CHECK_OK(still_push(&s, g, a, NULL));
    }
    CHECK(still_last(&s)->quiet);
    CHECK(still_at_rest(&s));
}

static void test_state_machine(void)
{
    struct still s;
    struct still_cfg c = base_cfg();
    c.windows_required = 3;
    REQUIRE(still_init(&s, &c) == INC_OK);
    CHECK(still_state_get(&s) == STILL_UNKNOWN);
    push_const(&s, 7, -9, 3);
    CHECK(still_state_get(&s) == STILL_UNKNOWN); /* no complete window yet */
    push_const(&s, 7, -9, 1);
    CHECK(still_state_get(&s) == STILL_SETTLING);
    push_const(&s, 7, -9, 4);
    CHECK(still_state_get(&s) == STILL_SETTLING);
    push_const(&s, 7, -9, 4);
    CHECK(still_state_get(&s) == STILL_AT_REST);
    CHECK_EQ_INT(still_motion_count(&s), 0);
    push_const(&s, 7, -9, 3);
    push_const(&s, 100, -9, 1); /* one jolt */
    CHECK(still_state_get(&s) == STILL_MOVING);
    CHECK_EQ_INT(still_motion_count(&s), 1);
    push_const(&s, 7, -9, 4);
    CHECK(still_state_get(&s) == STILL_SETTLING);
    still_reset(&s);
    CHECK(still_state_get(&s) == STILL_UNKNOWN);
    CHECK_EQ_INT(still_motion_count(&s), 0);
}

static void test_mean_norm_drift(void)
{
    struct still s;
    struct still_cfg c = base_cfg();
    const int32_t g0[3] = {0, 0, 0};
    /* steady rotation: no variance, caught by the mean test */
    c.gyro_mean_max = 60;
    REQUIRE(still_init(&s, &c) == INC_OK);
    push_const(&s, 61, 0, 4);
    CHECK_EQ_HEX(still_last(&s)->why, STILL_WHY_GYRO_MEAN);
    push_const(&s, -60, 0, 4);
    CHECK(still_last(&s)->quiet);
    /* accel norm: 1 g = 1000, tolerance 50 */
    c = base_cfg();
    c.accel_one_g = 1000;
    c.accel_norm_tol = 50;
    REQUIRE(still_init(&s, &c) == INC_OK);
    {
        const int32_t cases[6][3] = {
            {0, 0, 1000}, {600, 0, 800}, {0, 0, 1051}, {0, 0, 0}, {INT32_MAX, INT32_MIN, INT32_MAX},
            {0, -950, 0}};
        const bool quiet[6] = {true, true, false, false, false, true};
        unsigned k, i;
        for (k = 0; k < 6u; k++) {
            for (i = 0; i < 4u; i++) {
                CHECK_OK(still_push(&s, g0, cases[k], NULL));
            }
            CHECK_EQ_INT(still_last(&s)->quiet, quiet[k]);
            if (!quiet[k]) {
                CHECK_EQ_HEX(still_last(&s)->why, STILL_WHY_ACCEL_NORM);
            }
        }
    }
    /* drift between windows: 0 -> 3 is allowed (limit 3), 3 -> 7 is not */
    c = base_cfg();
    c.accel_drift_max = 3;
    REQUIRE(still_init(&s, &c) == INC_OK);
    push_const(&s, 0, 0, 4);
    CHECK(still_last(&s)->quiet); /* no previous window: no drift test */
    push_const(&s, 0, 3, 4);
    CHECK(still_last(&s)->quiet);
    push_const(&s, 0, 7, 4);
    CHECK_EQ_HEX(still_last(&s)->why, STILL_WHY_ACCEL_DRIFT);
}

/* A sample far from the window's first: overrange (clamped sums), even across the int32 range. */
static void test_overrange(void)
{
    struct still s;
    struct still_cfg c = base_cfg();
    const int32_t lo[3] = {INT32_MIN, INT32_MIN, INT32_MIN},
                  hi[3] = {INT32_MAX, INT32_MAX, INT32_MAX};
    const int32_t z[3] = {0, 0, 0};
    c.gyro_var_max = STILL_VAR_LIMIT;
    c.accel_var_max = STILL_VAR_LIMIT;
    REQUIRE(still_init(&s, &c) == INC_OK);
    CHECK_OK(still_push(&s, lo, z, NULL));
    CHECK_OK(still_push(&s, hi, z, NULL));
    CHECK_OK(still_push(&s, lo, z, NULL));
    CHECK_OK(still_push(&s, hi, z, NULL));
    CHECK(!still_last(&s)->quiet);
    CHECK(still_last(&s)->why & STILL_WHY_OVERRANGE);
    /* 2^20 exactly is still in range; with the largest limits the window is quiet */
    {
        const int32_t a[3] = {0, 0, 0}, b[3] = {1 << 20, 1 << 20, 1 << 20};
        CHECK_OK(still_push(&s, a, b, NULL));
        CHECK_OK(still_push(&s, b, a, NULL));
        CHECK_OK(still_push(&s, a, b, NULL));
        CHECK_OK(still_push(&s, b, a, NULL));
        CHECK(still_last(&s)->quiet);
        CHECK_EQ_INT(still_last(&s)->gyro_var[0], (uint64_t)1 << 38); /* (2^20 / 2)^2 */
    }
    /* the largest window at the largest deviation: exact, no overflow */
    c.window = STILL_WINDOW_MAX;
    REQUIRE(still_init(&s, &c) == INC_OK);
    {
        uint32_t i;
        for (i = 0; i < STILL_WINDOW_MAX; i++) {
            const int32_t v = (i % 2u) ? (1 << 20) : 0;
            const int32_t g[3] = {v, -v, v};
            CHECK_OK(still_push(&s, g, g, NULL));
        }
        CHECK_EQ_INT(still_last(&s)->gyro_var[1], (uint64_t)1 << 38);
        CHECK_EQ_INT(still_last(&s)->gyro_mean[1], -(1 << 19));
        CHECK(still_last(&s)->quiet);
    }
}

/* ---- simulated ADIS-like data -------------------------------------------------------------- */

#define FS 819.2
#define GYRO_LSB 0.05   /* deg/s */
#define ACCEL_LSB 0.001 /* g (ADIS16364) */
#define W 819u          /* 1 s windows */

enum motion { REST, VIBRATION, TILT, SPIN };

/* Push SIM_WINDOWS windows of the part under `mo`; returns how many windows were quiet. */
static unsigned simulate(struct still *s, struct sim_noise *nm, enum motion mo)
{
    unsigned quiet = 0, win;
    uint32_t k = 0;
    for (win = 0; win < SIM_WINDOWS; win++) {
        uint32_t i;
        for (i = 0; i < W; i++, k++) {
            struct sim_inertial_input in, out;
            const double t = k / FS;
            int32_t g[3], a[3];
            unsigned ax;
            bool done = false;
            sim_inertial_at_rest(&in);
            in.rate_dps[2] = 0.0;
            if (mo == VIBRATION) {
                in.rate_dps[0] = 2.0 * sin(2.0 * 3.14159265358979 * 15.0 * t);
                in.accel_g[2] += 0.02 * sin(2.0 * 3.14159265358979 * 23.0 * t);
            } else if (mo == TILT) {
                /* 0.5 deg/s about x: gravity moves into y */
                const double ang = 0.5 * t * 3.14159265358979 / 180.0;
                in.rate_dps[0] = 0.5;
                in.accel_g[1] = sin(ang);
                in.accel_g[2] = cos(ang);
            } else if (mo == SPIN) {
                in.rate_dps[2] = 5.0; /* about gravity: accel unchanged */
            }
            sim_noise_apply(nm, &in, &out, 0, 1.0 / FS);
            for (ax = 0; ax < 3u; ax++) {
                g[ax] = sim_quantise(out.rate_dps[ax], GYRO_LSB, 14, NULL);
                a[ax] = sim_quantise(out.accel_g[ax], ACCEL_LSB, 14, NULL);
            }
            (void)still_push(s, g, a, &done);
            if (done && still_last(s)->quiet) {
                quiet++;
            }
        }
    }
    return quiet;
}

static void test_simulated_adis(void)
{
    static struct sim_noise nm;
    struct sim_noise_cfg nc;
    struct still s;
    struct still_cfg c;
    unsigned a;
    const double gsd = SIM_NOISE_ADIS_GYRO_ARW * sqrt(FS) / GYRO_LSB;     /* 17.7 LSB */
    const double asd = SIM_NOISE_ADIS_ACCEL_WHITE * sqrt(FS) / ACCEL_LSB; /* 5.7 LSB */
    memset(&nc, 0, sizeof(nc));
    for (a = 0; a < 3u; a++) {
        nc.ch[SIM_NOISE_GYRO(a)].white = SIM_NOISE_ADIS_GYRO_ARW;
        nc.ch[SIM_NOISE_GYRO(a)].bias = 0.4 * (a + 1u); /* an uncalibrated bias */
        nc.ch[SIM_NOISE_ACCEL(a)].white = SIM_NOISE_ADIS_ACCEL_WHITE;
    }
    nc.seed = 99;
    REQUIRE(sim_noise_init(&nm, &nc) == INC_OK);
    /* thresholds from the noise (docs/averaging.md): s^2 (1 + 6 sqrt(2/(W-1))) + q^2/12 */
    memset(&c, 0, sizeof(c));
    c.window = W;
    c.windows_required = 3;
    c.gyro_var_max = (uint64_t)ceil((gsd * gsd + 1.0 / 12.0) * (1.0 + 6.0 * sqrt(2.0 / (W - 1))));
    c.accel_var_max = (uint64_t)ceil((asd * asd + 1.0 / 12.0) * (1.0 + 6.0 * sqrt(2.0 / (W - 1))));
    c.gyro_mean_max = 60; /* 3 deg/s: above any uncalibrated bias */
    c.accel_one_g = 1000;
    c.accel_norm_tol = 50;
    c.accel_drift_max = 3; /* 3 mg between 1 s windows (mean noise 0.2 mg) */
    printf("  thresholds: gyro var %u LSB^2 (sd %.1f), accel var %u LSB^2 (sd %.1f)\n",
           (unsigned)c.gyro_var_max, gsd, (unsigned)c.accel_var_max, asd);
    REQUIRE(still_init(&s, &c) == INC_OK);
    CHECK_EQ_INT(simulate(&s, &nm, REST), SIM_WINDOWS);
    CHECK(still_at_rest(&s));
    CHECK_EQ_INT(still_motion_count(&s), 0);
    still_reset(&s);
    CHECK_EQ_INT(simulate(&s, &nm, VIBRATION), 0);
    CHECK(still_last(&s)->why & STILL_WHY_GYRO_VAR);
    CHECK(still_last(&s)->why & STILL_WHY_ACCEL_VAR);
    still_reset(&s);
    CHECK(simulate(&s, &nm, TILT) <= 1u); /* the first window has no drift reference */
    CHECK(still_last(&s)->why & STILL_WHY_ACCEL_DRIFT);
    still_reset(&s);
    CHECK_EQ_INT(simulate(&s, &nm, SPIN), 0);
    CHECK_EQ_HEX(still_last(&s)->why, STILL_WHY_GYRO_MEAN);
    CHECK(still_state_get(&s) == STILL_MOVING);
}

/* ---- thermal -------------------------------------------------------------------------------- */

static void test_thermal_basic(void)
{
    struct still_thermal t;
    struct still_thermal_cfg c = {4, 3, 1};
    uint32_t ch = 0, i;
    int32_t last = 0;
    bool done = false;
    CHECK_ERR(still_thermal_init(&t, NULL), INC_ERR_NULL);
    c.span = 1;
    CHECK_ERR(still_thermal_init(&t, &c), INC_ERR_INVAL);
    CHECK_ERR(still_thermal_push(&t, 0, NULL), INC_ERR_STATE);
    c.span = STILL_THERMAL_SPAN_MAX + 1u;
    CHECK_ERR(still_thermal_init(&t, &c), INC_ERR_INVAL);
    c.span = 3;
    c.avg_n = 0;
    CHECK_ERR(still_thermal_init(&t, &c), INC_ERR_INVAL);
    c.avg_n = 0x80000001u;
    CHECK_ERR(still_thermal_init(&t, &c), INC_ERR_OVERFLOW);
    c.avg_n = 4;
    REQUIRE(still_thermal_init(&t, &c) == INC_OK);
    CHECK_ERR(still_thermal_last(&t, &last), INC_ERR_STATE);
    /* points: mean of 4 samples each. 10,10,10,11 -> 10.25 -> 10 */
    for (i = 0; i < 8u; i++) {
        CHECK_OK(still_thermal_push(&t, 10 + (i % 4u == 3u), &done));
        CHECK_EQ_INT(done, i % 4u == 3u);
    }
    CHECK_OK(still_thermal_last(&t, &last));
    CHECK_EQ_INT(last, 10);
    CHECK(!still_thermal_settled(&t)); /* 2 of 3 points */
    CHECK_ERR(still_thermal_change(&t, &ch), INC_ERR_STATE);
    for (i = 0; i < 4u; i++) {
        CHECK_OK(still_thermal_push(&t, 12, NULL)); /* point 12: change 2 > 1 */
    }
    CHECK_OK(still_thermal_change(&t, &ch));
    CHECK_EQ_INT(ch, 2);
    CHECK(!still_thermal_settled(&t));
    for (i = 0; i < 8u; i++) {
        CHECK_OK(still_thermal_push(&t, 11, NULL)); /* window 12, 11, 11: change 1 */
    }
    CHECK_OK(still_thermal_change(&t, &ch));
    CHECK_EQ_INT(ch, 1);
    CHECK(still_thermal_settled(&t));
    /* extremes: INT32_MIN and INT32_MAX points, change 2^32 - 1 */
    c.avg_n = 1;
    c.max_change = UINT32_MAX;
    REQUIRE(still_thermal_init(&t, &c) == INC_OK);
    CHECK_OK(still_thermal_push(&t, INT32_MIN, NULL));
    CHECK_OK(still_thermal_push(&t, INT32_MAX, NULL));
    CHECK_OK(still_thermal_push(&t, 0, NULL));
    CHECK_OK(still_thermal_change(&t, &ch));
    CHECK_EQ_INT(ch, UINT32_MAX);
    CHECK(still_thermal_settled(&t));
    still_thermal_reset(&t);
    CHECK(!still_thermal_settled(&t));
}

/* A warming part (25 -> 33 degC, time constant 120 s), TEMP_OUT at 0.14 degC per LSB with
 * 0.05 degC noise, 10 readings per second: 1 s points, 30 s window, 1 LSB allowed. Not settled
 * during the warm-up; settled once the rounded points over 30 s differ by at most 1 LSB (true
 * change below about 2 LSB = 0.28 degC: about 260 s);
 * a 2 degC step later unsettles it. */
static void test_thermal_warmup(void)
{
    struct still_thermal t;
    const struct still_thermal_cfg c = {10, 30, 1};
    struct sim_rng r;
    double first_settled = -1.0;
    unsigned k;
    sim_rng_seed(&r, 5);
    REQUIRE(still_thermal_init(&t, &c) == INC_OK);
    for (k = 0; k < 7000u; k++) {
        const double ts = k / 10.0;
        double temp = 25.0 + 8.0 * (1.0 - exp(-ts / 120.0)) + 0.05 * sim_rng_gauss(&r);
        if (ts >= 650.0) {
            temp += 2.0 * (ts - 650.0 < 10.0 ? (ts - 650.0) / 10.0 : 1.0);
        }
        (void)still_thermal_push(&t, sim_quantise(temp - 25.0, 0.14, 12, NULL), NULL);
        if (ts < 200.0) {
            CHECK(!still_thermal_settled(&t));
        }
        if (first_settled < 0.0 && still_thermal_settled(&t)) {
            first_settled = ts;
        }
        if (ts > 655.0 && ts < 670.0) {
            CHECK(!still_thermal_settled(&t));
        }
    }
    printf("  thermal: settled first at %.1f s\n", first_settled);
    CHECK(first_settled > 200.0 && first_settled < 600.0);
    CHECK(still_thermal_settled(&t)); /* 30 s after the step it settles again */
}

int main(void)
{
    UNIT_RUN(test_config);
    UNIT_RUN(test_exact_window);
    UNIT_RUN(test_state_machine);
    UNIT_RUN(test_mean_norm_drift);
    UNIT_RUN(test_overrange);
    UNIT_RUN(test_simulated_adis);
    UNIT_RUN(test_thermal_basic);
    UNIT_RUN(test_thermal_warmup);
    return unit_report();
}
