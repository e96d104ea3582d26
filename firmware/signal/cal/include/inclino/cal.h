/*
 * cal.h - accelerometer and gyro calibration (module inclino_cal, prefix cal_): the on-device
 * procedures (one-point offset, +-1 g flip, six-position, gyro still interval and turns), the
 * temperature-model evaluation, and the per-sample correction with the coefficients of a
 * calibration record (inclino/calrec.h). Least-squares fits (misalignment, nonlinearity,
 * temperature) are not here: the calibration-station tool makes them (tools/calstation,
 * docs/calibration.md); this module only applies their coefficients.
 *
 * Freestanding C11, integer only. Formats (docs/fixed-point.md): fx_q16_t Q16.16 for physical
 * quantities (acceleration in g as scaled by the part's NOMINAL sensitivity, rate in deg/s,
 * temperature in degC, angle in deg); fx_q30_t Q2.30 for gains and ratios. Rounding is to
 * nearest, ties away from zero, everywhere (fx); results that do not fit saturate, never wrap.
 * "LSB" below is one unit of the output's last place (2^-16 for Q16, 2^-30 for Q30). Every
 * error bound is against exact math on the exact input values and is proven by tests/cal
 * (host and QEMU).
 *
 * The correction (the contract the station fits; docs/calibration.md):
 *   per axis i, with T the temperature and r_i the nominal-scaled reading (g):
 *     b_i = acc_offset_i + tbias_i(T)                 (g)
 *     k_i = acc_gain_i * (1 + tscale_i(T))            (g/g)
 *     v_i = (r_i - b_i) / k_i                         [ADI-EPB]: a_true = (a_out - offset) / gain
 *     n_i = v_i + c0 + c1*x + c2*x^2 + c3*x^3,  x = clamp(v_i, -CAL_NONLIN_X_MAX, +CAL_NONLIN_X_MAX)
 *   a = M * n                                          (3x3 misalignment / cross-axis matrix)
 *   b and 1/k are computed once per temperature change (cal_acc_set_temp); a sample costs one
 *   subtract and one multiply per axis, a cubic per axis and a 3x3 product (cal_acc_apply).
 */
#ifndef INCLINO_CAL_H
#define INCLINO_CAL_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/calrec.h"
#include "inclino/error.h"
#include "inclino/fx.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- Limits and constants ------------------------------------------------------------------- */

#define CAL_ONE_G FX_Q16_ONE                 /* 1 g in Q16 */
#define CAL_OFFSET_MAX CALREC_LIM_ACC_OFFSET /* |offset| <= 0.5 g from a procedure (Q16) */
#define CAL_GAIN_MIN CALREC_LIM_GAIN_MIN     /* procedure gains in [0.75, 1.25] (Q30) */
#define CAL_GAIN_MAX CALREC_LIM_GAIN_MAX
#define CAL_GYRO_OFFSET_MAX CALREC_LIM_GYRO_OFFSET /* |gyro offset| <= 30 deg/s (Q16) */

/* Inputs of cal_acc_apply beyond +-64 g (no supported part measures that: ADIS1640x +-18 g)
 * are reported as INC_ERR_RANGE; the output is still computed (saturating). */
#define CAL_ACC_IN_MAX FX_Q16_INT(64)
/* Inputs of cal_gyro_apply and the turn accumulator beyond +-2000 deg/s: INC_ERR_RANGE. */
#define CAL_GYRO_IN_MAX FX_Q16_INT(2000)
/* The cubic nonlinearity correction is evaluated at x = v clamped to +-1.25 g: the station fits
 * it from data within +-1 g (faces and +-30 deg sweeps); beyond, the correction is held, so a
 * shock never meets an extrapolated cubic. This also bounds every Horner term below 2 in Q30. */
#define CAL_NONLIN_X_MAX (FX_Q16_ONE + FX_Q16_ONE / 4)
/* Plausibility of the temperature-corrected coefficients: an effective scale factor k outside
 * [0.625, 1.5] or an effective offset beyond +-1 g means the record cannot describe this part
 * at this temperature: the state goes uncalibrated (INC_ERR_RANGE) rather than apply it. */
#define CAL_KEFF_MIN ((fx_q30_t)671088640)  /* 0.625 in Q30 */
#define CAL_KEFF_MAX ((fx_q30_t)1610612736) /* 1.5 in Q30 */
#define CAL_BEFF_MAX FX_Q16_ONE             /* 1 g in Q16 */
/* Temperatures outside the record's temperature range [-100, 200] degC are clamped to it. */
#define CAL_T_MIN CALREC_LIM_T_MIN
#define CAL_T_MAX CALREC_LIM_T_MAX

/* Six-position face order: the axis pointing up (reading +1 g) / down (-1 g). */
enum cal_face {
    CAL_FACE_XP = 0,
    CAL_FACE_XN,
    CAL_FACE_YP,
    CAL_FACE_YN,
    CAL_FACE_ZP,
    CAL_FACE_ZN,
};
#define CAL_FACES 6

/* ---- Averaging with a still check ------------------------------------------------------------ */

/*
 * Running mean of 3-axis samples (any one Q format) with the span max - min per axis, for the
 * still intervals of the procedures. Caller-owned; cal_avg_reset before use. Exact (int64 sums).
 */
struct cal_avg {
    struct fx_sum sum[3];
    int32_t min[3];
    int32_t max[3];
};

void cal_avg_reset(struct cal_avg *a);

/* Add one sample. INC_ERR_NULL; INC_ERR_OVERFLOW after FX_SUM_MAX_COUNT samples (not added). */
int cal_avg_add(struct cal_avg *a, const int32_t s[3]);

/*
 * mean[i] = round(sum / count) per axis (same format as the samples, |error| <= 0.5 LSB).
 * INC_ERR_NULL; INC_ERR_STATE when empty; INC_ERR_MOTION when any axis spans more than
 * max_span (max - min > max_span: the part moved, the interval is not still). mean is written
 * only on success.
 */
int cal_avg_mean(const struct cal_avg *a, int32_t max_span, int32_t mean[3]);

/* ---- On-device accelerometer procedures ------------------------------------------------------ */

/*
 * One-point calibration ([ADI-EPB]): with the part still in a known field expect[i] (g Q16, e.g.
 * 0, 0, +1 g level), offset[i] = mean[i] - expect[i], exact. Removes the offset only; the gain
 * error stays ([ADI-EPB]: "simple but not accurate enough"). INC_ERR_NULL; INC_ERR_RANGE when any
 * |offset| > CAL_OFFSET_MAX (0.5 g) or |expect| > 1 g: offset untouched.
 */
int cal_one_point(const fx_q16_t mean[3], const fx_q16_t expect[3], fx_q16_t offset[3]);

/*
 * Two-point +-1 g flip of one axis ([ADI-EPB]): a_pos, a_neg are the still means (g Q16) with the
 * axis up (+1 g) and down (-1 g):
 *     offset = (a_pos + a_neg) / 2        Q16, rounded (|error| <= 0.5 LSB)
 *     gain   = (a_pos - a_neg) / 2        Q30, exact ((a_pos - a_neg) * 2^13)
 * [ADI-EPB] prints the gain as 0.5 * (A+ - A-) / 2; that 0.5 is a misprint (with it an ideal
 * part would get gain 0.5 and read double): the correct form is used. Then a_true =
 * (a_out - offset) / gain. Errors (outputs untouched): INC_ERR_NULL; INC_ERR_DEGENERATE when
 * a_pos <= a_neg (+1 g and -1 g swapped, or a dead axis); INC_ERR_RANGE when the gain is outside
 * [0.75, 1.25] or |offset| > 0.5 g.
 */
int cal_flip(fx_q16_t a_pos, fx_q16_t a_neg, fx_q16_t *offset, fx_q30_t *gain);

/*
 * Six-position calibration: face[f][i] is the still mean (g Q16) of axis i on face f (enum
 * cal_face order). Per axis, the flip of its two faces (same formulas and bounds as cal_flip).
 * Each face is first checked to be the one claimed: the axis under test must read the largest
 * magnitude of the three with the expected sign, else INC_ERR_DEGENERATE (faces out of order or
 * swapped). The cross-axis terms are a host least-squares fit (the station): not here.
 * INC_ERR_NULL, INC_ERR_DEGENERATE, INC_ERR_RANGE as cal_flip; outputs written only when all
 * three axes pass.
 */
int cal_six_position(const fx_q16_t face[CAL_FACES][3], fx_q16_t offset[3], fx_q30_t gain[3]);

/* ---- On-device gyro procedures --------------------------------------------------------------- */

/*
 * Gyro offset from a still interval (samples deg/s Q16 accumulated in *still): the mean, with the
 * still check of cal_avg_mean (max_span in deg/s Q16). |error| <= 0.5 LSB. INC_ERR_NULL,
 * INC_ERR_STATE, INC_ERR_MOTION; INC_ERR_RANGE when |offset| > 30 deg/s. offset untouched on
 * error.
 */
int cal_gyro_offset(const struct cal_avg *still, int32_t max_span, fx_q16_t offset[3]);

/*
 * Gyro scale from a turn of a known angle. The turn accumulator integrates (rate - offset) * dt
 * per axis in int64 Q32 degrees: each sample adds round((rate - offset) * dt / 2^14) (error
 * <= 0.5 * 2^-32 deg per sample). Caller-owned.
 */
struct cal_turn {
    int64_t angle_q32[3]; /* integrated angle, deg Q32 */
    fx_q16_t offset[3];   /* deg/s Q16 */
    fx_q30_t dt;          /* sample period, s Q30 */
    uint32_t n;           /* samples added */
};

/* Start a turn: offset (deg/s Q16, from cal_gyro_offset), dt in (0, 1] s Q30.
 * INC_ERR_NULL; INC_ERR_INVAL for dt outside (0, 1 s]. */
int cal_turn_start(struct cal_turn *t, const fx_q16_t offset[3], fx_q30_t dt);

/* Add one 3-axis sample (deg/s Q16). INC_ERR_NULL; INC_ERR_RANGE when |rate| > 2000 deg/s on
 * any axis, INC_ERR_OVERFLOW when an angle would pass 2^30 deg: the sample is not added. */
int cal_turn_add(struct cal_turn *t, const fx_q16_t rate[3]);

/*
 * scale = measured angle / known angle about `axis` (0..2), Q30: the gyro's sensitivity ratio,
 * the same sense as the accelerometer gain (the correction divides by it; cal_gyro_apply).
 * known_deg Q16, |known| >= 90 deg. The measured angle is rounded to Q16 (<= 0.5 LSB) and
 * divided with fx_div (<= 0.5 LSB Q30): |scale - A/known| <= 0.5 LSB + E / |known| * 2^30 LSB,
 * with A the exact integral of the samples and E = 2^-17 + n * 2^-33 deg (for a 360 deg turn of
 * 10^6 samples: 370 LSB = 0.34 ppm).
 * INC_ERR_NULL; INC_ERR_INVAL (axis, |known| < 90 deg); INC_ERR_STATE (no sample);
 * INC_ERR_RANGE when |measured| >= 32768 deg or the scale is outside [0.75, 1.25];
 * INC_ERR_DEGENERATE when measured and known have opposite signs (axis or direction swapped).
 * scale untouched on error.
 */
int cal_turn_scale(const struct cal_turn *t, unsigned axis, fx_q16_t known_deg, fx_q30_t *scale);

/* ---- Temperature models (record kinds, calrec.h) --------------------------------------------- */

/*
 * y = m(T): evaluate one temperature model of a record at T (degC Q16; clamped to [-100, 200]
 * degC first). The y format is the model's (bias g Q16, or scale deviation Q30); the arithmetic
 * is the same. Semantics (record version 2): LINEAR/PARABOLA/LORENTZ_CUBIC at Th = T held in
 * [t_ref - t_span, t_ref + t_span]; PWL held at the end knots; LORENTZ at T.
 * Maximum error against the exact model (double) on the same parameter words, for parameters
 * within the calrec limits (|y parameters| <= 2^27 raw, the Q30 scale limit; Q16 bias
 * parameters are far smaller): NONE exact; LINEAR <= 0.57 LSB; PARABOLA <= 1.25 LSB; LORENTZ
 * <= 0.75 LSB; PWL <= 0.63 LSB; LORENTZ_CUBIC <= 2.7 LSB. The Lorentz quotient is computed
 * from the exact 64-bit w^2 and w^2 + 4 (T - Tc)^2, normalised to 31 bits (<= 1 LSB Q30) and
 * divided (<= 0.5 LSB Q30).
 * Cost: one 32-bit division for u, one more for the Lorentz kinds; called per temperature
 * change, never per sample.
 * INC_ERR_NULL; INC_ERR_INVAL for a kind or field a checked record cannot hold (n for PWL,
 * spans < 1 degC, w < 1 degC): *y = 0. Records from calrec_decode always pass.
 */
int cal_tmodel_eval(const struct calrec_tmodel *m, fx_q16_t t_c, int32_t *y);

/* ---- Per-sample application ------------------------------------------------------------------- */

/*
 * Accelerometer correction state. Caller-owned; holds a pointer to the record, which must stay
 * valid and unchanged while the state is used.
 *   off[i]       b_i at the last temperature, g Q16
 *   inv_gain[i]  1 / k_i at the last temperature, Q30: round(2^60 / k_i), k_i itself rounded to
 *                Q30 (see cal_acc_set_temp)
 *   calibrated   false: no valid record (or it failed at this temperature); cal_acc_apply then
 *                passes the input through and says INC_ERR_NOT_CALIBRATED
 */
struct cal_acc {
    const struct calrec *rec;
    fx_q16_t off[3];
    fx_q30_t inv_gain[3];
    fx_q16_t t_c;
    bool calibrated;
};

/*
 * Bind a state to a record and evaluate it at temperature t_c (cal_acc_set_temp). rec == NULL,
 * !rec->valid or a record that fails calrec_check: the state is uncalibrated (pass-through) and
 * the return is INC_ERR_NOT_CALIBRATED (or INC_ERR_RANGE for a failing check). INC_ERR_NULL for
 * st == NULL.
 */
int cal_acc_init(struct cal_acc *st, const struct calrec *rec, fx_q16_t t_c);

/*
 * Re-evaluate the temperature models at t_c (degC Q16): call when the temperature reading
 * changes (e.g. at most once per second; the ADIS TEMP_OUT LSB is 0.136 degC). Per axis:
 *   off = fx_add(acc_offset, tbias(T))                     (tbias error as cal_tmodel_eval)
 *   k   = round(acc_gain * (1 + tscale(T)) / 2^30)         (<= 0.5 LSB + tscale error)
 *   inv_gain = round(2^60 / k)                              (<= 0.5 LSB)
 * If |off| > CAL_BEFF_MAX or k is outside [CAL_KEFF_MIN, CAL_KEFF_MAX] on any axis, the state
 * becomes uncalibrated and INC_ERR_RANGE is returned (a wrong correction is never applied).
 * INC_ERR_NULL; INC_ERR_NOT_CALIBRATED when the state has no valid record.
 */
int cal_acc_set_temp(struct cal_acc *st, fx_q16_t t_c);

/*
 * Correct one 3-axis sample: in = nominal-scaled reading (g Q16), out = calibrated (g Q16),
 * following the chain at the top of this file with the state's off and inv_gain.
 * Error against exact math with the same off, inv_gain and record words (exact v = (in - off) *
 * inv_gain / 2^30, exact cubic and matrix): |error| <= 3.5 LSB (53 ug) for any coefficients
 * within the calrec limits: 0.5 (v) carried through the cubic's slope (<= 2.86 at the limits)
 * and the matrix row sum (<= 1.5), plus 0.5 each for the cubic and matrix roundings. With
 * typical coefficients (|c2|, |c3| <= 0.05, diagonal <= 1.02, off-diagonal <= 0.02) it is
 * <= 1.75 LSB (27 ug).
 * Including cal_acc_set_temp, against the double-precision model of the record at that
 * temperature: the offset error (tbias <= 2.01 LSB for Q16 bias parameters) divided by k (>= 0.625)
 * joins the 0.5 above: <= 18 LSB (0.27 mg) within the limits, <= 5 LSB (76 ug) typical.
 * tests/cal test_cal_apply proves the four bounds (measured maxima in docs/calibration.md).
 * Returns 0; INC_ERR_NULL; INC_ERR_NOT_CALIBRATED (out = in, uncalibrated); INC_ERR_RANGE when
 * |in| > CAL_ACC_IN_MAX on any axis (out computed, saturating, and not to be trusted).
 * Cost: 3 + 9 + 9 multiplies (32x32->64), no division (docs/benchmarks.md, Calibration).
 */
int cal_acc_apply(const struct cal_acc *st, const fx_q16_t in[3], fx_q16_t out[3]);

/*
 * Gyro correction state: rate = (in - gyro_offset) / gyro_scale per axis, with the reciprocal
 * computed once at init (Q30, <= 0.5 LSB). No temperature model in the record for the gyro.
 */
struct cal_gyro {
    fx_q16_t off[3];
    fx_q30_t inv_scale[3];
    bool calibrated;
};

/* Bind to a record (copied; the record need not outlive the state). rec NULL, !valid or failing
 * calrec_check: uncalibrated, INC_ERR_NOT_CALIBRATED / INC_ERR_RANGE. INC_ERR_NULL. */
int cal_gyro_init(struct cal_gyro *g, const struct calrec *rec);

/*
 * out = (in - off) * inv_scale (deg/s Q16). |error| <= 0.6 LSB against the exact
 * (in - gyro_offset) / gyro_scale for |in| <= CAL_GYRO_IN_MAX (0.5 rounding + |in - off| times
 * the reciprocal's 0.5 LSB Q30 / scale). INC_ERR_NULL; INC_ERR_NOT_CALIBRATED (out = in);
 * INC_ERR_RANGE for |in| > CAL_GYRO_IN_MAX (out computed, saturating).
 */
int cal_gyro_apply(const struct cal_gyro *g, const fx_q16_t in[3], fx_q16_t out[3]);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_CAL_H */
