/*
 * adapt_tilt.h - the patented method end to end (module inclino_adapt_tilt, prefix adapt_tilt_):
 * the adaptive per-axis Kalman filter (inclino/kf_adapt.h, steps 1 to 3: dz, Q = C + D |dz|,
 * R = |A + B Q|) on each of the six raw axes, feeding the angle step and the second Kalman stage
 * (inclino/tilt.h, step 4). Source: the adaptive-Kalman patent of docs/references.md
 * ([PAT-ADAPT]); docs/kalman.md describes both halves and their corrections.
 *
 * Every sample:
 *   1. each axis (gyro x, y, z, accel x, y, z) passes through its kf_adapt filter; a saturated
 *      axis (input flags) coasts instead (its estimate is held, its P grows by C);
 *   2. the filtered rates and specific forces go to tilt_step, whose mode is FEEDBACK by
 *      default (the offset fed back with its sign corrected) or the printed form
 *      (TILT_MODE_SEED_PRINTED) or KF2; saturation flags pass through to tilt's rejection.
 * The output is tilt's (roll, pitch, 1-sigma, flags, valid), with tilt's frame and meaning.
 * Like tilt, this is the per-axis small-angle method the patent describes; the 3D estimator
 * (inclino/att.h) is the default attitude path. Both are compared in docs/benchmarks.md.
 *
 * FORMATS: as inclino/kf_adapt.h and inclino/tilt.h (Q16 g, Q16 deg/s, Q16 deg; P format). The
 *   filtered samples are rounded to Q16 (|error| <= 0.5 LSB, kf_adapt.h). No operation here adds
 *   an error of its own beyond the two modules' stated bounds.
 * RAM: sizeof(struct adapt_tilt) (6 kf_adapt axes + tilt).
 */
#ifndef INCLINO_ADAPT_TILT_H
#define INCLINO_ADAPT_TILT_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/error.h"
#include "inclino/fx.h"
#include "inclino/kf_adapt.h"
#include "inclino/tilt.h"

#ifdef __cplusplus
extern "C" {
#endif

enum {
    ADAPT_TILT_GX = 0,
    ADAPT_TILT_GY,
    ADAPT_TILT_GZ,
    ADAPT_TILT_AX,
    ADAPT_TILT_AY,
    ADAPT_TILT_AZ
};

struct adapt_tilt_config {
    struct kf_adapt_config axis[KF_ADAPT_AXES]; /* gyro x, y, z, accel x, y, z */
    struct tilt_config tilt;                    /* the angle step and second stage */
};

/* What the defaults are tuned for: the part's noise per sample and the changes that must be
 * followed at full speed. */
struct adapt_tilt_noise {
    fx_q16_t accel_sd_g;    /* 1-sigma of one accelerometer sample at rest, g. (0, 1] */
    fx_q16_t gyro_sd_dps;   /* 1-sigma of one gyro sample at rest, deg/s. (0, 100] */
    fx_q16_t accel_step_g;  /* accel change to follow at once (x, y; z is not adapted). (0, 16] */
    fx_q16_t gyro_step_dps; /* gyro change to follow at once. (0, 2000] */
    uint32_t n_equiv;       /* steady-state smoothing: gain 2 / (n + 1), as a moving average of
                              n. 2 .. 10000 */
    uint32_t window;        /* k of kf_adapt, 2 .. KF_ADAPT_WIN_MAX */
};

/* The tuning procedure of docs/kalman.md ("Tuning procedure") applied to white noise of the given
 * sigmas, in integer arithmetic: A = p0 = sd^2, Qr = Ks^2 A / (1 - Ks) with Ks = 2 / (n + 1),
 * C = Qr / 10, D = 0.9 Qr / E|dz| with E|dz| = sd sqrt(2/pi) sqrt(k / (k - 1)) (white noise),
 * B = -A / (C + D step); the accelerometer z axis gets no adaptation (D = 0, B = 0, C = Qr).
 * tilt as tilt_config_default(dt_nominal_ns). Each constant within 0.1 % of the formula.
 * 0, INC_ERR_NULL, INC_ERR_INVAL (a field of *noise outside its range, or dt as tilt). */
int adapt_tilt_config_default(struct adapt_tilt_config *cfg, const struct adapt_tilt_noise *noise,
                              uint32_t dt_nominal_ns);

/* The noise of an ADIS1640x-class part at 819.2 SPS (docs/kalman.md): accel 4 mg, gyro 0.5 deg/s
 * per sample, steps sin 5 deg g and 20 deg/s, n = 82, k = 32. */
void adapt_tilt_noise_default(struct adapt_tilt_noise *noise);

struct adapt_tilt {
    struct kf_adapt6 filt;
    struct tilt tilt;
    bool ready;
};

/* Set up. INC_ERR_NULL / INC_ERR_INVAL as kf_adapt6_init and tilt_init. */
int adapt_tilt_init(struct adapt_tilt *a, const struct adapt_tilt_config *cfg);

/* Forget the filters' history and the angles (the offsets are kept, as tilt_restart). */
void adapt_tilt_restart(struct adapt_tilt *a);

/* One sample dt_ns after the previous one: steps 1 and 2 above. filtered (may be NULL) receives
 * the six filtered axes in Q16. Errors as tilt_step; INC_ERR_STATE before a successful init. */
int adapt_tilt_step(struct adapt_tilt *a, const struct tilt_input *in, uint32_t dt_ns,
                    struct tilt_output *out, int32_t filtered[KF_ADAPT_AXES]);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_ADAPT_TILT_H */
