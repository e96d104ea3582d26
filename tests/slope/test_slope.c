/*
 * EPB slope estimator: [ADI-EPB]'s worked error budget, exact cases, every flag, the error bounds
 * of the fixed-point arithmetic against double precision, the lifetime-exceedance noise factor.
 */
#include "inclino/slope.h"
#include "unit.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#if UNIT_REDUCED
#define SWEEP 400 /* QEMU: soft-float references are slow */
#else
#define SWEEP 20000
#endif

static const double D2R = 3.14159265358979323846 / 180.0;

static double q16(int32_t x)
{
    return x / 65536.0;
}
static int32_t to_q16(double x)
{
    return (int32_t)lround(x * 65536.0);
}

static double k_exact(double r)
{
    double lo = 0.0, hi = 40.0;
    int i;
    for (i = 0; i < 200; i++) {
        double m = 0.5 * (lo + hi);
        if (erfc(m / sqrt(2.0)) > r)
            lo = m;
        else
            hi = m;
    }
    return 0.5 * (lo + hi);
}

static struct slope_cfg base_cfg(void)
{
    struct slope_cfg c;
    memset(&c, 0, sizeof(c));
    c.method = SLOPE_SINGLE_AXIS;
    c.slope_axis = 0;
    c.gravity_axis = 2;
    c.budget.k_sigma = FX_Q16_INT(6);
    c.max_slope_deg = FX_Q16_INT(30);
    c.max_bound_deg = FX_Q16_INT(5);
    c.magnitude_tol_g = to_q16(0.05);
    return c;
}

static struct slope_input level_input(double ax, double ay, double az)
{
    struct slope_input in;
    in.accel_g[0] = to_q16(ax);
    in.accel_g[1] = to_q16(ay);
    in.accel_g[2] = to_q16(az);
    in.n_samples = 100;
    in.still = true;
    in.calibrated = true;
    return in;
}

/* [ADI-EPB], Table 1 "after calibration": 10 mg nonlinearity + 10 mg drift + 2.4 mg noise
 * (0.4 mg rms after a 100x average, i.e. 4 mg per sample, times 6) = 22.4 mg -> 1.28 deg. */
static void test_adi_epb_budget(void)
{
    struct slope_cfg c = base_cfg();
    struct slope_input in = level_input(0.0, 0.0, 1.0);
    struct slope_result r;
    c.budget.nonlinearity_g = to_q16(0.010);
    c.budget.temperature_g = to_q16(0.010);
    c.budget.noise_sigma_g = to_q16(0.004);
    CHECK_OK(slope_estimate(&c, &in, &r));
    CHECK(r.valid);
    CHECK_EQ_INT(r.flags, 0);
    CHECK_EQ_INT(r.slope_deg, 0);
    CHECK_EQ_INT(r.grade_pct, 0);
    CHECK_NEAR(q16(r.noise_g), 6 * 0.004 / 10.0, 2.0 / 65536);
    CHECK(q16(r.noise_g) >= 6 * q16(to_q16(0.004)) / 10.0); /* never rounded down */
    CHECK_NEAR(q16(r.accel_bound_g), 0.0224, 3.0 / 65536);
    CHECK_NEAR(q16(r.bound_deg), asin(0.0224) / D2R, 4.0 / 65536); /* 1.2836 deg */
    printf("[ADI-EPB] budget: e_a = %.5f g, bound = %.4f deg (seed: 22.4 mg, 1.28 deg)\n",
           q16(r.accel_bound_g), q16(r.bound_deg));
    /* Before calibration: 30 mg sensitivity (3 % of 1 g on the axis: at 0 g it is 0) + 15 mg
     * offset + 10 mg nonlinearity + 50 mg drift + 24 mg noise; the article sums 129 mg at full
     * scale. On a 30 deg slope the sensitivity term is 3 % of 0.5 g = 15 mg. */
    c.budget.sensitivity = (fx_q30_t)lround(0.03 * 1073741824.0);
    c.budget.offset_g = to_q16(0.015);
    c.budget.temperature_g = to_q16(0.050);
    c.budget.noise_sigma_g = to_q16(0.004);
    in.n_samples = 1;
    in.accel_g[0] = to_q16(0.5);
    CHECK_OK(slope_estimate(&c, &in, &r));
    CHECK_NEAR(q16(r.accel_bound_g), 0.015 + 0.015 + 0.010 + 0.050 + 0.024, 4.0 / 65536);
    CHECK_NEAR(q16(r.slope_deg), 30.0, 1.0 / 65536);
    CHECK(r.flags == SLOPE_F_BOUND); /* 7.8 deg > the 5 deg allowed */
    CHECK(!r.valid);
}

static void test_exact_cases(void)
{
    struct slope_cfg c = base_cfg();
    struct slope_input in = level_input(0.5, 0.0, 0.8660254);
    struct slope_result r;
    c.max_slope_deg = FX_Q16_INT(45);
    CHECK_OK(slope_estimate(&c, &in, &r));
    CHECK_EQ_INT(r.slope_deg, FX_Q16_INT(30)); /* asin(0.5) is exact in fx */
    CHECK_NEAR(q16(r.grade_pct), 100.0 * tan(30.0 * D2R), 1.0 / 65536);
    CHECK_EQ_INT(r.bound_deg, 0); /* an empty budget */
    CHECK(r.valid);
    /* The same slope with the axis mounted the other way round. */
    in.accel_g[0] = -in.accel_g[0];
    c.slope_axis_negative = true;
    CHECK_OK(slope_estimate(&c, &in, &r));
    CHECK_EQ_INT(r.slope_deg, FX_Q16_INT(30));
    /* Two-axis: 10 % grade = atan(0.1) = 5.7106 deg. */
    c = base_cfg();
    c.method = SLOPE_TWO_AXIS;
    in = level_input(0.1 / sqrt(1.01), 0.0, 1.0 / sqrt(1.01));
    CHECK_OK(slope_estimate(&c, &in, &r));
    /* against the angle of the Q16 inputs; the inputs' own rounding moves it by 5 LSB */
    CHECK_NEAR(q16(r.slope_deg), atan2(q16(in.accel_g[0]), q16(in.accel_g[2])) / D2R, 1.0 / 65536);
    CHECK_NEAR(q16(r.slope_deg), atan(0.1) / D2R, 8.0 / 65536);
    CHECK_NEAR(q16(r.grade_pct), 10.0, 20.0 / 65536);
    CHECK(r.valid);
    /* Two-axis does not care about a sensitivity error common to both axes. */
    in.accel_g[0] = to_q16(1.04 * 0.1 / sqrt(1.01));
    in.accel_g[2] = to_q16(1.04 * 1.0 / sqrt(1.01));
    CHECK_OK(slope_estimate(&c, &in, &r));
    CHECK_NEAR(q16(r.slope_deg), atan(0.1) / D2R, 8.0 / 65536);
    CHECK(r.valid);
    in.accel_g[0] = to_q16(1.06 * 0.1 / sqrt(1.01));
    in.accel_g[2] = to_q16(1.06 * 1.0 / sqrt(1.01));
    CHECK_OK(slope_estimate(&c, &in, &r));
    CHECK_EQ_INT(r.flags, SLOPE_F_MAGNITUDE); /* but 1.06 g is not gravity alone (tol 0.05) */
}

static void test_flags(void)
{
    struct slope_cfg c = base_cfg();
    struct slope_input in = level_input(0.1, 0.0, 0.995);
    struct slope_result r;
    in.still = false;
    CHECK_OK(slope_estimate(&c, &in, &r));
    CHECK_EQ_INT(r.flags, SLOPE_F_NOT_STILL);
    CHECK(!r.valid);
    CHECK(r.slope_deg != 0); /* the estimate is still reported, flagged */
    in.still = true;
    in.calibrated = false;
    CHECK_OK(slope_estimate(&c, &in, &r));
    CHECK_EQ_INT(r.flags, SLOPE_F_NOT_CALIBRATED);
    in.calibrated = true;
    in.accel_g[0] = to_q16(0.6); /* 36.9 deg > 30 */
    CHECK_OK(slope_estimate(&c, &in, &r));
    CHECK_EQ_INT(r.flags, SLOPE_F_OUT_OF_RANGE);
    in.accel_g[0] = to_q16(1.2); /* more than 1 g on one axis: accelerating */
    CHECK_OK(slope_estimate(&c, &in, &r));
    CHECK(r.flags & SLOPE_F_MAGNITUDE);
    CHECK_EQ_INT(r.slope_deg, FX_DEG_90); /* clamped, and flagged */
    /* Two-axis, vehicle braking hard: 0.4 g along x on top of gravity. */
    c.method = SLOPE_TWO_AXIS;
    in = level_input(0.4, 0.0, 1.0);
    CHECK_OK(slope_estimate(&c, &in, &r));
    CHECK_EQ_INT(r.flags, SLOPE_F_MAGNITUDE);
    /* No gravity on the gravity axis (sensor on its side). */
    in = level_input(0.0, 1.0, 0.0);
    CHECK_OK(slope_estimate(&c, &in, &r));
    CHECK(r.flags & SLOPE_F_MAGNITUDE);
}

static void test_invalid(void)
{
    struct slope_cfg c = base_cfg(), bad;
    struct slope_input in = level_input(0.1, 0.0, 0.995);
    struct slope_result r;
    memset(&r, 0x5A, sizeof(r));
    CHECK_ERR(slope_estimate(NULL, &in, &r), INC_ERR_NULL);
    CHECK(!r.valid && r.slope_deg == 0 && r.bound_deg == 0);
    CHECK_ERR(slope_estimate(&c, NULL, &r), INC_ERR_NULL);
    CHECK_ERR(slope_estimate(&c, &in, NULL), INC_ERR_NULL);
    in.n_samples = 0;
    memset(&r, 0x5A, sizeof(r));
    CHECK_ERR(slope_estimate(&c, &in, &r), INC_ERR_INVAL);
    CHECK(!r.valid && r.flags == 0 && r.grade_pct == 0);
    bad = c;
    bad.slope_axis = 3;
    CHECK_ERR(slope_cfg_check(&bad), INC_ERR_INVAL);
    bad = c;
    bad.method = SLOPE_TWO_AXIS;
    bad.gravity_axis = 0;
    CHECK_ERR(slope_cfg_check(&bad), INC_ERR_INVAL);
    bad = c;
    bad.method = (enum slope_method)7;
    CHECK_ERR(slope_cfg_check(&bad), INC_ERR_INVAL);
    bad = c;
    bad.budget.offset_g = -1;
    CHECK_ERR(slope_cfg_check(&bad), INC_ERR_INVAL);
    bad = c;
    bad.budget.sensitivity = FX_Q30_HALF;
    CHECK_ERR(slope_cfg_check(&bad), INC_ERR_INVAL);
    bad = c;
    bad.budget.k_sigma = 0;
    CHECK_ERR(slope_cfg_check(&bad), INC_ERR_INVAL);
    bad = c;
    bad.max_slope_deg = FX_DEG_90 + 1;
    CHECK_ERR(slope_cfg_check(&bad), INC_ERR_INVAL);
    bad = c;
    bad.max_bound_deg = 0;
    CHECK_ERR(slope_cfg_check(&bad), INC_ERR_INVAL);
    bad = c;
    bad.magnitude_tol_g = 0;
    CHECK_ERR(slope_cfg_check(&bad), INC_ERR_INVAL);
    CHECK_ERR(slope_cfg_check(NULL), INC_ERR_NULL);
    CHECK_OK(slope_cfg_check(&c));
}

/* Pseudo-random but reproducible inputs. */
static uint32_t lcg = 12345u;
static double urand(void)
{
    lcg = lcg * 1664525u + 1013904223u;
    return (lcg >> 8) / 16777216.0;
}

/* The fixed-point angle and bound against double precision on the same (Q16) inputs. */
static void test_against_double(void)
{
    struct slope_cfg c = base_cfg();
    struct slope_result r;
    double worst_t = 0, worst_b = 0, worst_g = 0, worst_gb = 0;
    int i, m;
    c.max_slope_deg = FX_Q16_INT(60);
    c.budget.sensitivity = (fx_q30_t)lround(0.002 * 1073741824.0);
    c.budget.offset_g = to_q16(0.003);
    c.budget.nonlinearity_g = to_q16(0.002);
    c.budget.temperature_g = to_q16(0.004);
    c.budget.noise_sigma_g = to_q16(0.01);
    for (m = 0; m < 2; m++) {
        c.method = m ? SLOPE_TWO_AXIS : SLOPE_SINGLE_AXIS;
        for (i = 0; i < SWEEP; i++) {
            double th = (urand() * 2.0 - 1.0) * 55.0 * D2R;
            struct slope_input in = level_input(sin(th), 0.0, cos(th));
            double s = q16(in.accel_g[0]), g = q16(in.accel_g[2]), t, b = 0, e_exact;
            double gr, gb = 0; /* the exact grade for these inputs and its exact bound */
            in.n_samples = 1u + (uint32_t)(urand() * 5000.0);
            REQUIRE(slope_estimate(&c, &in, &r) == 0);
            e_exact = fabs(s) * 0.002 + q16(c.budget.offset_g) + q16(c.budget.nonlinearity_g) +
                      q16(c.budget.temperature_g) +
                      6.0 * q16(c.budget.noise_sigma_g) / sqrt(in.n_samples);
            /* e_a is rounded up, by at most 3 LSB */
            CHECK(q16(r.accel_bound_g) >= e_exact - 1e-9);
            CHECK(q16(r.accel_bound_g) <= e_exact + 3.0 / 65536);
            {
                /* the exact bound, with e_a unrounded */
                double e_s = e_exact, e_g = e_exact - fabs(s) * 0.002 + fabs(g) * 0.002;
                if (m == 0) {
                    t = asin(s) / D2R;
                    b = fmax(asin(fmin(1.0, s + e_s)) / D2R - t,
                             t - asin(fmax(-1.0, s - e_s)) / D2R);
                    /* 100 tan(asin(x)) = 100 x / sqrt(1 - x^2), monotonic: the two ends */
                    gr = 100.0 * s / sqrt(1.0 - s * s);
                    gb = fmax(100.0 * (s + e_s) / sqrt(1.0 - (s + e_s) * (s + e_s)) - gr,
                              gr - 100.0 * (s - e_s) / sqrt(1.0 - (s - e_s) * (s - e_s)));
                } else {
                    /* the cross axis reads 0 +- its own e_a (no sensitivity share): the
                     * gravity left perpendicular to the slope axis, |(A_g, A_c)|, lies in
                     * [|g| - e_g, hypot(|g| + e_g, e_c)] */
                    int k;
                    const double e_c = e_exact - fabs(s) * 0.002;
                    const double h_lo = fabs(g) - e_g, h_hi = hypot(fabs(g) + e_g, e_c);
                    t = atan2(s, g) / D2R;
                    gr = 100.0 * s / g; /* the cross axis reads 0: A_h = g */
                    for (k = 0; k < 4; k++) {
                        const double cs = s + ((k & 1) ? e_s : -e_s), ch = (k & 2) ? h_hi : h_lo;
                        double d = fabs(atan2(cs, ch) / D2R - t);
                        b = fmax(b, d);
                        gb = fmax(gb, fabs(100.0 * cs / ch - gr));
                    }
                }
            }
            worst_t = fmax(worst_t, fabs(q16(r.slope_deg) - t) * 65536.0);
            worst_b = fmax(worst_b, (q16(r.bound_deg) - b) * 65536.0);
            CHECK_NEAR(q16(r.slope_deg), t, 1.0 / 65536);
            CHECK(q16(r.bound_deg) >= b - 2.0 / 65536); /* never under-bounds */
            CHECK(q16(r.bound_deg) <= b + 0.003 / cos(t * D2R) + 2.0 / 65536);
            /* the grade: 100 A_s / A_h of the same inputs, rounded (slope.h: 0.5 LSB + the
             * norm's rounding); against the reported angle, the angle's 1 LSB through tan */
            worst_g = fmax(worst_g, fabs(q16(r.grade_pct) - gr) * 65536.0);
            CHECK_NEAR(q16(r.grade_pct), gr, 0.51 / 65536);
            CHECK_NEAR(q16(r.grade_pct), 100.0 * tan(q16(r.slope_deg) * D2R),
                       (100.0 * (1.0 + tan(t * D2R) * tan(t * D2R)) * D2R + 1.0) / 65536);
            /* its bound holds the exact one (never under-bounds) and exceeds it only by e_a's
             * round-up (3 LSB of g, through d grade / d a <= 100 (1 + |grade| / 100) / A_h on
             * each axis) and the 2 LSB of GRADE_BOUND_ROUNDING */
            worst_gb = fmax(worst_gb, (q16(r.bound_pct) - gb) * 65536.0);
            CHECK(q16(r.bound_pct) >= gb);
            CHECK(q16(r.bound_pct) <= gb +
                                          2.0 * 3.0 / 65536 * 100.0 * (1.0 + fabs(gr) / 100.0) /
                                              (m == 0 ? sqrt(1.0 - s * s) : fabs(g)) *
                                              (1.0 + fabs(gr) / 100.0) +
                                          2.5 / 65536);
        }
    }
    printf("max |slope error| %.2f LSB; bound above the exact one by at most %.1f LSB "
           "(e_a rounded up) over %d cases\n",
           worst_t, worst_b, 2 * SWEEP);
    printf("grade: max |error| %.3f LSB against 100 A_s / A_h; its bound above the exact one by "
           "at most %.1f LSB\n",
           worst_g, worst_gb);
}

/* A cross slope does not change the two-axis slope: the gravity perpendicular to the slope axis
 * is |(A_g, A_c)|. Before this, atan2(A_s, A_g) read atan(tan(theta) / cos(phi)): 21.65 deg of
 * slope with 18.67 deg of roll came out 22.69 deg, valid, outside its bound of 0.81 deg (the
 * accuracy campaign, docs/campaign.md). And the bound still holds the truth over the box. */
static void test_cross_slope(void)
{
    struct slope_cfg c = base_cfg();
    struct slope_result r;
    double th, ph;
    c.method = SLOPE_TWO_AXIS;
    c.budget.offset_g = to_q16(0.005);
    for (th = -30.0; th <= 30.0; th += 7.5) {
        for (ph = -30.0; ph <= 30.0; ph += 5.0) {
            struct slope_input in = level_input(sin(th * D2R), cos(th * D2R) * sin(ph * D2R),
                                                cos(th * D2R) * cos(ph * D2R));
            REQUIRE(slope_estimate(&c, &in, &r) == 0);
            CHECK_NEAR(q16(r.slope_deg), th, 0.001); /* inputs rounded to Q16 g */
            CHECK((r.flags & SLOPE_F_MAGNITUDE) == 0u);
            {
                /* 4.9 mg on every axis, each sign: the truth stays inside the bound */
                unsigned k;
                for (k = 0; k < 8u; k++) {
                    struct slope_input e = in;
                    struct slope_result re;
                    e.accel_g[0] += (k & 1u) ? to_q16(0.0049) : -to_q16(0.0049);
                    e.accel_g[1] += (k & 2u) ? to_q16(0.0049) : -to_q16(0.0049);
                    e.accel_g[2] += (k & 4u) ? to_q16(0.0049) : -to_q16(0.0049);
                    REQUIRE(slope_estimate(&c, &e, &re) == 0);
                    CHECK(fabs(q16(re.slope_deg) - th) <= q16(re.bound_deg) + 1e-6);
                }
            }
        }
    }
    {
        /* 18.67 deg of roll, the case the campaign found */
        struct slope_input in = level_input(sin(21.65 * D2R), cos(21.65 * D2R) * sin(18.67 * D2R),
                                            cos(21.65 * D2R) * cos(18.67 * D2R));
        REQUIRE(slope_estimate(&c, &in, &r) == 0);
        CHECK_NEAR(q16(r.slope_deg), 21.65, 0.001);
    }
}

static void test_grade(void)
{
    int32_t d;
    double worst = 0;
    for (d = -FX_Q16_INT(60); d <= FX_Q16_INT(60); d += 997) {
        double e = fabs(q16(slope_grade_pct(d)) - 100.0 * tan(q16(d) * D2R)) * 65536.0;
        worst = fmax(worst, e);
    }
    CHECK(worst <= 1.0);
    printf("grade: max error %.3f LSB Q16 over +-60 deg\n", worst);
    CHECK_EQ_INT(slope_grade_pct(FX_DEG_45), FX_Q16_INT(100));
    CHECK_EQ_INT(slope_grade_pct(0), 0);
    CHECK_EQ_INT(slope_grade_pct(FX_DEG_90), INT32_MAX);
    CHECK_EQ_INT(slope_grade_pct(-FX_DEG_90), INT32_MIN);
    {
        /* slope_estimate's grade at the edges: the part on end (single axis, A_s = 1 g: no
         * gravity left across it) saturates, and so does the bound of a box reaching it; two
         * axes with no gravity at all read 0 % with a saturated bound; upside down (A_g < 0)
         * the grade is the tangent of the angle past 90 deg */
        struct slope_cfg c = base_cfg();
        struct slope_input in = level_input(1.0, 0.0, 0.0);
        struct slope_result r;
        c.budget.offset_g = to_q16(0.01);
        REQUIRE(slope_estimate(&c, &in, &r) == 0);
        CHECK_EQ_INT(r.grade_pct, INT32_MAX);
        in = level_input(-0.995, 0.0, 0.0);
        REQUIRE(slope_estimate(&c, &in, &r) == 0);
        CHECK(r.grade_pct < -FX_Q16_INT(900));
        CHECK_EQ_INT(r.bound_pct, INT32_MAX);
        c.method = SLOPE_TWO_AXIS;
        in = level_input(0.0, 0.0, 0.0);
        REQUIRE(slope_estimate(&c, &in, &r) == 0);
        CHECK_EQ_INT(r.grade_pct, 0);
        CHECK_EQ_INT(r.bound_pct, INT32_MAX);
        CHECK((r.flags & SLOPE_F_MAGNITUDE) != 0u);
        in = level_input(0.5, 0.0, -0.866);
        REQUIRE(slope_estimate(&c, &in, &r) == 0);
        CHECK_NEAR(q16(r.grade_pct), 100.0 * q16(in.accel_g[0]) / q16(in.accel_g[2]), 0.51 / 65536);
        CHECK_NEAR(q16(r.grade_pct), 100.0 * tan(q16(r.slope_deg) * D2R), 3.0 / 65536);
    }
}

static void test_sigma_factor(void)
{
    fx_q16_t k = 0;
    double worst = 0;
    uint32_t runs;
    int e;
    for (runs = 16; runs < 4000000000u / 7u; runs = runs * 7u + 3u) {
        for (e = 1; e <= 65536; e *= 3) {
            double r = (e / 65536.0) / runs;
            int err = slope_sigma_factor(runs, e, &k);
            if (r > 1.0 / 16.0) {
                CHECK_ERR(err, INC_ERR_INVAL);
                continue;
            }
            CHECK_OK(err);
            worst = fmax(worst, fabs(q16(k) - k_exact(r)));
        }
    }
    CHECK(worst <= 0.005);
    printf("sigma factor: max |k error| %.5f\n", worst);
    /* [ADI-EPB]'s 6 sigma: r = 1.97e-9; e.g. 1e-3 expected exceedances over 507 000 runs. */
    CHECK_OK(slope_sigma_factor(506800u, to_q16(0.001), &k));
    CHECK_NEAR(q16(k), 6.0, 0.005);
    CHECK_ERR(slope_sigma_factor(0, 100, &k), INC_ERR_INVAL);
    CHECK_ERR(slope_sigma_factor(100, 0, &k), INC_ERR_INVAL);
    CHECK_OK(slope_sigma_factor(100, 65536, &k)); /* r = 1 %: k = 2.576 */
    CHECK_NEAR(q16(k), 2.5758, 0.005);
    CHECK_ERR(slope_sigma_factor(100, 65536 * 7, &k), INC_ERR_INVAL); /* r = 7 % > 2^-4 */
    CHECK_NEAR(q16(k), 2.5758, 0.005);                                /* untouched */
    CHECK_OK(slope_sigma_factor(4294967295u, 1, &k));                 /* the smallest r: 2^-48 */
    CHECK_NEAR(q16(k), k_exact(1.0 / 65536.0 / 4294967295.0), 0.005);
    CHECK_ERR(slope_sigma_factor(100, 100, NULL), INC_ERR_NULL);
}

int main(void)
{
    UNIT_RUN(test_adi_epb_budget);
    UNIT_RUN(test_exact_cases);
    UNIT_RUN(test_flags);
    UNIT_RUN(test_invalid);
    UNIT_RUN(test_against_double);
    UNIT_RUN(test_cross_slope);
    UNIT_RUN(test_grade);
    UNIT_RUN(test_sigma_factor);
    return unit_report();
}
