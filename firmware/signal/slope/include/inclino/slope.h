/*
 * slope.h - EPB slope estimator: the road slope under a parked vehicle, in degrees and percent
 * grade, with a validity flag and a worst-case error bound (module inclino_slope, prefix slope_).
 *
 * Input: the calibrated acceleration averaged over a standstill window (the averaging and
 * stillness modules produce it), the number of samples averaged, and the error budget of the
 * calibrated part. The estimate is
 *   single axis:  theta = asin(A_s)                 (A_s: the axis along the slope, in g)
 *   two axes:     theta = atan2(A_s, sign(A_g) * sqrt(A_g^2 + A_c^2))
 *                 (A_g: the axis along gravity when level, A_c the third (cross) axis: with a
 *                 cross slope the gravity left perpendicular to the slope axis is shared by both;
 *                 the bound takes A_g and A_c each +- their e_a)
 * and the bound follows [ADI-EPB]'s error budget, summed worst case (as its Table 1 does):
 *   e_a = |A| * sensitivity + offset + nonlinearity + temperature + k * sigma / sqrt(N)
 * where k is the noise factor ("6 sigma" in [ADI-EPB]; slope_sigma_factor() derives it from the
 * lifetime exceedance rule E = M * r). The angle bound is exact for that acceleration box: the
 * largest change of asin (two candidates) or atan2 (four corners) over A +- e_a.
 * Why the sensing axis should be perpendicular to gravity: docs/slope.md.
 *
 * All values fixed point (docs/fixed-point.md): accelerations Q16.16 g, angles Q16.16 degrees,
 * grade Q16.16 percent, ratios Q30.
 */
#ifndef INCLINO_SLOPE_H
#define INCLINO_SLOPE_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/error.h"
#include "inclino/fx.h"

#ifdef __cplusplus
extern "C" {
#endif

enum slope_method {
    SLOPE_SINGLE_AXIS = 0, /* asin(A_s / 1 g) */
    SLOPE_TWO_AXIS = 1,    /* atan2(A_s, |(A_g, A_c)|): independent of the sensitivity common to
                              the axes, and of the cross slope */
};

/* Residual errors of the calibrated part, one axis, worst case ([ADI-EPB] Table 1 "after"). */
struct slope_budget {
    fx_q30_t sensitivity;    /* relative sensitivity error, e.g. 0.001 = 0.1 % (Q30, >= 0, < 0.5) */
    fx_q16_t offset_g;       /* offset residual (Q16 g, >= 0) */
    fx_q16_t nonlinearity_g; /* nonlinearity residual within +-30 deg (Q16 g, >= 0) */
    fx_q16_t temperature_g;  /* offset drift over temperature after compensation (Q16 g, >= 0) */
    fx_q16_t noise_sigma_g;  /* rms noise of ONE sample (Q16 g, >= 0) */
    fx_q16_t k_sigma;        /* noise factor k (Q16, > 0): 6.0 in [ADI-EPB] */
};

struct slope_cfg {
    enum slope_method method;
    uint8_t slope_axis;       /* 0..2: axis along the vehicle's length (its slope) */
    uint8_t gravity_axis;     /* 0..2, != slope_axis: axis along gravity when level (two-axis) */
    bool slope_axis_negative; /* the axis points downhill when the nose is up */
    bool gravity_axis_negative;
    struct slope_budget budget;
    fx_q16_t max_slope_deg;   /* beyond this |theta| the estimate is flagged out of range
                                  (the budget's nonlinearity is only valid within it); 0..90 */
    fx_q16_t max_bound_deg;   /* an estimate whose bound exceeds this is not valid; > 0 */
    fx_q16_t magnitude_tol_g; /* two-axis: |(A_s, A_g, A_c)| must be within 1 g +- this (a vehicle
                                  that accelerates or is jolted is not parked); single axis:
                                  |A_s| must be <= 1 g + this */
};

/* Reasons an estimate is not valid (bit flags in slope_result.flags). */
enum slope_flag {
    SLOPE_F_NOT_STILL = 1u << 0,      /* the caller's stillness detector says it was moving */
    SLOPE_F_NOT_CALIBRATED = 1u << 1, /* no valid calibration: the budget does not apply */
    SLOPE_F_OUT_OF_RANGE = 1u << 2,   /* |theta| > max_slope_deg */
    SLOPE_F_MAGNITUDE = 1u << 3,      /* the acceleration is not gravity alone (see cfg) */
    SLOPE_F_BOUND = 1u << 4,          /* the error bound exceeds max_bound_deg */
};

struct slope_input {
    fx_q16_t accel_g[3]; /* mean calibrated acceleration per axis over the window (Q16 g) */
    uint32_t n_samples;  /* samples in the mean (>= 1) */
    bool still;          /* the stillness detector's verdict over the same window */
    bool calibrated;     /* a valid calibration record was applied */
};

struct slope_result {
    bool valid;             /* true only when flags == 0 */
    uint32_t flags;         /* enum slope_flag bits */
    fx_q16_t slope_deg;     /* theta, positive nose up (Q16 deg) */
    fx_q16_t grade_pct;     /* 100 * tan(theta) = 100 A_s / A_h (Q16 %; saturated at 90 deg) */
    fx_q16_t bound_deg;     /* |true theta - slope_deg| <= bound_deg given the budget (Q16 deg) */
    fx_q16_t bound_pct;     /* |true grade - grade_pct| <= bound_pct given the budget (Q16 %;
                               INT32_MAX when the box reaches 90 deg) */
    fx_q16_t accel_bound_g; /* e_a, the acceleration error bound of the slope axis (Q16 g) */
    fx_q16_t noise_g;       /* its noise term k * sigma / sqrt(N) (Q16 g) */
};

/*
 * Check a configuration: axes 0..2 and distinct for two-axis, budget terms >= 0 (sensitivity
 * < 0.5, k > 0), 0 < max_slope_deg <= 90 deg, max_bound_deg > 0, magnitude_tol_g > 0.
 * Returns 0, INC_ERR_NULL or INC_ERR_INVAL.
 */
int slope_cfg_check(const struct slope_cfg *cfg);

/*
 * Estimate the slope. Returns 0 with *out filled (out->valid tells whether to use it), or
 * INC_ERR_NULL / INC_ERR_INVAL (bad cfg, n_samples == 0) with *out set to valid = false and all
 * values 0. Arithmetic against exact math, for the same inputs:
 *   slope_deg: |error| <= 1 LSB Q16 (fx_asin_deg / fx_atan2_deg, 0.81 LSB);
 *   accel_bound_g: never below the exact e_a, at most 3 LSB Q16 above it (each term is rounded
 *     up, so the bound never shrinks through rounding); noise_g likewise (rounded up);
 *   bound_deg: never below the exact angle bound minus 2 LSB, and above it only by the effect of
 *     e_a's round-up (< 3 LSB of g, i.e. < 0.003 deg / cos(theta));
 *   grade: 1 LSB Q16 for |theta| <= 60 deg.
 * Saturation: e_a saturates at 2 g (a bound that large is flagged anyway).
 */
int slope_estimate(const struct slope_cfg *cfg, const struct slope_input *in,
                   struct slope_result *out);

/*
 * The noise factor k for the lifetime exceedance rule of [ADI-EPB], E = M * r: with M runs over
 * the vehicle's life and E the expected number of runs whose noise exceeds k sigma, the two-sided
 * Gaussian tail must be r = E / M, i.e. k = sqrt(2) * erfc^-1(E / M).
 * runs >= 1, expected_q16 > 0 (Q16, e.g. 0.001 = 66) and r = E/M <= 2^-4 (k >= 1.86); these
 * types limit r to > 2^-48 (k < 9.83). Result Q16 in *k; |error| <= 0.005 (a table of k at
 * r = 2^-n, n = 0..48, interpolated in n = log2(1/r); log2 from a 33-entry table, |error in n|
 * <= 2e-4). Returns 0, INC_ERR_NULL, or INC_ERR_INVAL (runs == 0, E <= 0, r > 2^-4; *k untouched).
 */
int slope_sigma_factor(uint32_t runs, fx_q16_t expected_q16, fx_q16_t *k);

/* 100 * tan(deg) in Q16 percent, rounded to nearest (ties away from zero). (slope_estimate
 * takes its grade from the components instead, without the angle.) |error| <= 1 LSB Q16
 * (1.5e-5 %) for |deg| <= 60 deg: 0.5 LSB rounding plus the Q30 sin/cos errors (< 2.3e-7 %).
 * Saturates (INT32_MAX/MIN) within 0.002 deg of +-90 deg. */
fx_q16_t slope_grade_pct(fx_q16_t deg);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_SLOPE_H */
