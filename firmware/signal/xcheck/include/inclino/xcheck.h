/*
 * xcheck.h - integrity cross-checks of the driving (ESC) attitude output (module inclino_xcheck,
 * prefix xcheck_). docs/safety.md, "The driving matrix".
 *
 * Three pieces, each a plain function of its inputs and a caller-owned state (no heap, no libc):
 *
 *   1. xcheck_flat: the flat-line detector. A MEMS output always carries its white noise (the
 *      ADIS16405: about 3 LSB rms on each accelerometer axis, 20 LSB on each gyro axis); a
 *      channel whose value repeats exactly for n_max samples is stuck (the sensing element, the
 *      output register or the sample path froze).
 *   2. xcheck_kin_residual: the vehicle-level residual r = a - up - k, the measured specific
 *      force a minus the estimated gravity direction up (the attitude estimator's "up" in the
 *      sensor frame, a unit vector) minus the kinematic acceleration from the wheel speed,
 *      k = (dv/dt, yaw rate x v, 0) / g0. With a good sensor and a good estimate only the
 *      estimate's own error (at most its bound, in g: sin(bound)), the lever's acceleration and
 *      road vibration remain; an accelerometer bias, a stuck or drifting axis, or a gyro error
 *      that tilted the estimate shows up in it.
 *   3. xcheck_mon: a residual monitor: second-order low-pass (two equal first-order stages) of
 *      a 3-axis residual, the largest
 *      |component| of the selected axes against a threshold, a persistence count. The vehicle
 *      check feeds it r (axes x, y); the two-sensor cross-check feeds it the difference of two
 *      calibrated accelerations (same quantity).
 *
 * Formats: Q16.16 g, m/s, deg/s, Hz (inclino/fx.h); the up vector Q2.30; the monitor's state
 * Q8.24 g. Rounding: every dropped bit rounds to nearest, ties away from zero. Saturation as
 * stated per function. Freestanding C11, integer only.
 */
#ifndef INCLINO_XCHECK_H
#define INCLINO_XCHECK_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/error.h"
#include "inclino/fx.h"

#ifdef __cplusplus
extern "C" {
#endif

#define XCHECK_FLAT_CH 6u /* channels of the flat-line detector (gyro x y z, accel x y z) */

struct xcheck_flat {
    int32_t last[XCHECK_FLAT_CH];
    uint32_t run[XCHECK_FLAT_CH]; /* samples equal to last, including the first (<= n_max) */
    uint32_t n_max;
    uint8_t mask; /* channels checked (bit i: channel i) */
    bool have;
};

/* n_max in [2, 65535] (the number of equal consecutive samples that is a flat line), mask: the
 * channels to check (bits 0..5). INC_ERR_NULL, INC_ERR_INVAL. */
int xcheck_flat_init(struct xcheck_flat *f, uint32_t n_max, uint8_t mask);

/* Forget the history (the next sample starts every run at 1). Nothing for NULL. */
void xcheck_flat_reset(struct xcheck_flat *f);

/* One sample (v: XCHECK_FLAT_CH raw or calibrated values, compared exactly). Returns the channels
 * (bits) of the mask whose value has now been the same for >= n_max consecutive samples; 0 for
 * NULL arguments. Exact (no arithmetic beyond comparison); the run counts saturate at n_max. */
uint8_t xcheck_flat_step(struct xcheck_flat *f, const int32_t v[XCHECK_FLAT_CH]);

/*
 * The vehicle-level residual r = a - up - k (Q16 g, sensor frame, x forward, y left, z up):
 *   acc_g     measured specific force, Q16 g (calibrated);
 *   up_q30    the estimate's earth "up" in the sensor frame, Q30 unit vector (att_get_up);
 *   dv_mps    speed change since the previous sample, Q16 m/s; rate_hz the sample rate, Q16 Hz
 *             in [1, 32768): k_x = dv x rate / g0 (g0 = 9.80665 m/s^2);
 *   speed_mps, yaw_dps  Q16 m/s, Q16 deg/s: k_y = yaw x pi/180 x v / g0 (centripetal);
 *   k_z = 0 (the vertical is not used by the check).
 * Range: dv and speed are clamped to +-256 m/s, dv x rate to +-400 m/s^2; |acc|, k_x and k_y
 * are each clamped to 32 g before the subtraction and every component of r to +-64 g.
 * Rounding: k_x is dv x rate rounded to Q16 m/s^2 and then x 1/g0 (Q30) rounded to Q16 g
 * (0.5/g0 + 0.5 LSB); k_y is v x yaw rounded to Q8 and then x pi/180/g0 (Q30) rounded to Q16
 * (0.23 + 0.5 LSB); up is rounded from Q30 to Q16 (0.5 LSB); each Q30 constant is within
 * 0.5 LSB (relative 3e-7 for pi/180/g0, 5e-9 for 1/g0). |error of each component|
 * <= 1.3 LSB Q16 (2e-5 g) plus 3e-7 x |k| (tests/xcheck proves 2 LSB + 3e-7 |k|).
 * INC_ERR_NULL, INC_ERR_INVAL (rate outside its range); r is all 0 on error.
 */
int xcheck_kin_residual(const fx_q16_t acc_g[3], const int32_t up_q30[3], fx_q16_t dv_mps,
                        fx_q16_t rate_hz, fx_q16_t speed_mps, fx_q16_t yaw_dps, fx_q16_t r[3]);

struct xcheck_mon {
    int32_t lp1[3]; /* Q24 g, the first stage, |.| <= 32 g */
    int32_t lp[3];  /* Q24 g, the low-passed residual (second stage), |.| <= 32 g */
    uint32_t over_n, persist_n;
    uint8_t sh;
};

/* shift in [1, 16]: each stage's gain 2^-shift per sample (time constant 2^shift samples each,
 * group delay 2^(shift+1) samples);
 * persist_n in [1, 2^24]: consecutive samples above the threshold that make a failure.
 * INC_ERR_NULL, INC_ERR_INVAL. */
int xcheck_mon_init(struct xcheck_mon *m, uint8_t shift, uint32_t persist_n);

/* Start again (the low-pass from 0, no count). Nothing for NULL. */
void xcheck_mon_reset(struct xcheck_mon *m);

/*
 * One sample: d (Q16 g, each component clamped to +-32 g) into the two stages
 * lp1 <- lp1 + round((d x 2^8 - lp1) / 2^shift), lp <- lp + round((lp1 - lp) / 2^shift) (Q24;
 * both start at 0 after init/reset: a residual that comes in steps, such as a speed change held
 * between its frames, is not taken for its first value; the second stage takes the ripple of
 * such steps down by another factor of about 2^shift / (steps' period)), level = max |lp_i|
 * over the axes of the mask (bits 0..2), rounded to Q16; with XCHECK_MON_XY_NORM in the mask
 * also the Euclidean norm sqrt(lp_x^2 + lp_y^2), rounded up to Q16 (at most 1 LSB Q16 above
 * the exact norm of the Q24 values, never below it). *fail (when not NULL) is true once
 * level > thr_g (Q16 g) has held for persist_n consecutive samples.
 * Returns level (Q16 g, [0, 32 g]); 0 for NULL m or d.
 * Accuracy: a constant input is reached to within 2^(shift-1) LSB Q24 per stage (2^shift LSB
 * Q24 in all: <= 2^-8 g at shift 16, 1.5e-5 g at shift 8); the output rounding adds 0.5 LSB Q16;
 * for white noise of sigma per sample the output's sigma is sigma sqrt(g (2 - 2g + g^2) / (2 -
 * g)^3) with g = 2^-shift (0.031 sigma at shift 8).
 */
#define XCHECK_MON_XY_NORM 0x08u /* xcheck_mon_step's mask: the x-y norm is a level too */

fx_q16_t xcheck_mon_step(struct xcheck_mon *m, const fx_q16_t d[3], uint8_t axes, fx_q16_t thr_g,
                         bool *fail);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_XCHECK_H */
