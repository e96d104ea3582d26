/*
 * app.h - the EPB application (module inclino_app, prefix app_): what runs on the ECU.
 *
 * Pipeline, per sample of the sensor (struct sensor, inclino/sensor.h: any driver's ops table,
 * or a replay's):
 *   nominal-scaled sample -> calibration of the record loaded from calstore (cal_acc_apply with
 *   the temperature models evaluated at the sample's temperature, cal_gyro_apply) -> stillness
 *   detection (inclino/still.h) -> block average of avg_n samples;
 * and per block: the slope estimate (inclino/slope.h) in degrees and percent grade with its
 * validity flag and the error bound of [ADI-EPB]'s budget, composed from
 *   - the calibration residuals of the part type (struct app_budget, set by the integrator from
 *     the end-of-line process; docs/epb-demo.md shows how the demo derives them),
 *   - the temperature term that applies: compensated only when the record has a temperature
 *     model covering the present temperature and the part reports one,
 *   - the noise: the larger of the rated per-sample rms and the rms measured in the stillness
 *     windows of the block (engine vibration included), with N = the samples averaged and the
 *     factor k from the lifetime exceedance rule E = M * r (slope_sigma_factor).
 * The calibration record is bound to the sensor: a missing, corrupt, unsupported or foreign
 * record (calstore_load != 0) leaves the application running UNCALIBRATED: the samples pass
 * through, every estimate carries SLOPE_F_NOT_CALIBRATED and APP_F_NOT_CALIBRATED and is never
 * valid, and the budget switches to the uncalibrated terms.
 *
 * End of line (on-device steps; the station's host-side fits are not here): average a still
 * face (app_eol_face), offset and gain from the six faces (cal_six_position) and the gyro offset
 * from the same still intervals (app_eol_six_position), and store the record bound to the
 * sensor through calstore (app_eol_save). A "power cycle" is a fresh app_init.
 *
 * Arithmetic (tests/app prove each against exact values): the block means are round(sum / N) of
 * exact int64 sums, ties away from zero, |error| <= 0.5 LSB Q16, never saturating; the correction
 * is cal_acc_apply's and cal_gyro_apply's (cal.h bounds); the measured rms is
 * ceil(sqrt((v + 1) * W / (W - 1))) from the detector's rounded-down window variance v, so never
 * below the exact rms; the budget terms are copied, the sensitivity sum saturates below 0.5
 * (a bound that wide is flagged anyway); slope, grade and bound are slope_estimate's (slope.h).
 *
 * Units: Q16.16 g, deg/s, degC, deg, % (inclino/fx.h); ratios Q30. Freestanding C11, integer
 * only, no heap; struct app is caller-allocated (docs/benchmarks.md, "EPB demo", gives its
 * size). Not re-entrant per instance.
 */
#ifndef INCLINO_APP_H
#define INCLINO_APP_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/cal.h"
#include "inclino/calrec.h"
#include "inclino/calstore.h"
#include "inclino/error.h"
#include "inclino/fx.h"
#include "inclino/sensor.h"
#include "inclino/slope.h"
#include "inclino/still.h"

#ifdef __cplusplus
extern "C" {
#endif

/*
 * Error budget of the part type ([ADI-EPB] Table 1), per axis, worst case, Q16 g unless noted.
 * Every term >= 0. The "after calibration" terms apply when the record is valid; the "_uncal"
 * terms ([ADI-EPB] "before") replace sensitivity and offset when it is not.
 */
struct app_budget {
    fx_q30_t sensitivity;       /* relative gain residual after calibration (Q30, < 0.5) */
    fx_q16_t offset_g;          /* offset residual after calibration */
    fx_q16_t offset_drift_g;    /* offset change after calibration the part type may show over
                                   its life (stress, ageing; [ADI-EPB]: the 20 % of the 50 mg
                                   total offset change that is not temperature, 10 mg). Added to
                                   the offset term of a calibrated estimate; also the tolerance of
                                   the offset-change check (APP_F_OFFSET_STEP); 0: neither term
                                   nor check (a part that cannot age: scripted or ideal) */
    fx_q16_t nonlinearity_g;    /* nonlinearity the record leaves within +-max_slope_deg */
    fx_q16_t temp_comp_g;       /* offset drift left by the record's temperature model, inside
                                   the range the model was calibrated over */
    fx_q16_t temp_uncomp_g;     /* offset drift without compensation: no model, no temperature
                                   output, or the temperature outside the calibrated range */
    fx_q30_t tscale_uncomp;     /* relative scale-factor drift without compensation (same
                                   cases, from the record's scale models); added to the
                                   sensitivity term (Q30, < 0.5) */
    fx_q30_t sensitivity_uncal; /* uncalibrated part: sensitivity error (Q30, < 0.5) */
    fx_q16_t offset_uncal_g;    /* uncalibrated part: initial offset */
    fx_q16_t noise_sigma_g;     /* rated rms noise of ONE output sample */
    uint32_t lifetime_runs;     /* M: slope measurements over the vehicle's life, >= 1 */
    fx_q16_t exceed_expected;   /* E: expected runs beyond k sigma over that life (Q16, > 0);
                                   E / M <= 2^-4 (slope_sigma_factor) */
};

struct app_cfg {
    uint32_t avg_n;         /* samples per estimate, a multiple of still.window, 1..2^31 */
    struct still_cfg still; /* in the sample units: Q16 deg/s and Q16 g */
    struct slope_cfg slope; /* method, axes, limits; its budget is composed per estimate
                                   (the one given here is ignored) */
    struct app_budget budget;
    fx_q16_t temp_default_c;    /* temperature assumed for a part without temperature output */
    fx_q16_t temp_step_c;       /* re-evaluate the temperature models when the temperature moved
                                   this much since the last evaluation (> 0, e.g. 0.5 degC) */
    fx_q16_t temp_margin_c;     /* a model still counts as covering a temperature this far outside
                                   its calibrated range (>= 0; the models hold their end values
                                   there, and temp_comp_g must be characterised over the range
                                   widened by it) */
    uint32_t max_sensor_errors; /* read errors tolerated per block; more: APP_F_SENSOR */
    fx_q16_t noise_floor_g;     /* the noise-floor check (APP_F_QUIET): a stillness window of an
                                   accelerometer axis with an rms below this is a frozen or stuck
                                   output; the part's rated rms per sample / APP_QUIET_DIV
                                   (0: no check, for noiseless scripted or ideal parts) */
    /* Plausibility of the loaded record against the part type's limits (app_init): a record
     * beyond them leaves the application uncalibrated (cal_status INC_ERR_RANGE). 0: no check. */
    fx_q16_t rec_offset_max_g; /* |acc_offset| per axis */
    fx_q30_t rec_gain_tol;     /* |acc_gain - 1| per axis */
    fx_q30_t rec_misalign_max; /* |off-diagonal acc_misalign| */
    /* Plausibility of the part's temperature (APP_F_TEMP_IMPLAUSIBLE), per block of a part with
     * a temperature output: the block mean outside [temp_min_c, temp_max_c]; a change of more
     * than temp_step_max_c since the previous block; more than temp_ref_tol_c from the second
     * source (app_set_temp_ref) when one is fitted. temp_step_max_c, temp_ref_tol_c 0: off. */
    fx_q16_t temp_min_c, temp_max_c;
    fx_q16_t temp_step_max_c;
    fx_q16_t temp_ref_tol_c;
};

/* Why an application result is not valid, besides the slope flags (app_result.flags). */
#define APP_F_NOT_CALIBRATED 0x01u /* no valid calibration record for this sensor */
#define APP_F_TEMP_UNCOMP \
    0x02u                     /* temperature drift not compensated (not an error by
                                      itself: the budget took temp_uncomp_g) */
#define APP_F_SENSOR 0x04u    /* more read errors in the block than max_sensor_errors */
#define APP_F_SATURATED 0x08u /* a sample of the block was at the end of its range */
#define APP_F_NOT_STILL \
    0x10u /* a stillness window of the block was not quiet, or the
                                      detector was not at rest at its end */
#define APP_F_QUIET \
    0x20u /* an accelerometer axis was quieter than the part's noise floor over a
                             stillness window: frozen or stuck output (never valid) */

/*
 * The noise-floor check: a real MEMS output always shows its white noise, a frozen or stuck
 * one shows none. A stillness window of W samples whose variance on any accelerometer axis is
 * below noise_floor_g^2 (noise_floor_g = rated rms / APP_QUIET_DIV) sets APP_F_QUIET. With W >= 64 the sample variance of
 * Gaussian noise has a relative spread sqrt(2 / (W - 1)) <= 0.18, so 1/16 of the rated variance
 * lies more than 5 spreads below it: a healthy part never trips it; the quantisation of a
 * frozen output gives variance 0. app_cfg_default sets the floor from its rated 4 mg (1 mg);
 * an integrator sets noise_floor_g = rated / APP_QUIET_DIV for the part it fits.
 */
#define APP_QUIET_DIV 4

#define APP_F_TEMP_IMPLAUSIBLE \
    0x80u /* the part's temperature out of range, changing faster
                                        than a die can, or disagreeing with the second source */
/*
 * Defaults of the temperature plausibility (app_cfg_default), degC: the automotive range with
 * 5 degC of margin (-45..+130: the SCA3000's and ADIS1640x's own ranges are not confirmed here);
 * 2 degC per block (0.8 degC/s at 2.5 s blocks: a module in a parked car warms or cools by
 * degrees per minute, a stuck or broken sensor jumps); 15 degC between the die and the ECU's
 * board sensor (self-heating and the board's gradient are a few degC; the reading stuck at
 * 25 degC in a car at -20 degC is 45 off).
 */
#define APP_TEMP_MIN_C (-45)
#define APP_TEMP_MAX_C 130
#define APP_TEMP_STEP_MAX_C 2
#define APP_TEMP_REF_TOL_C 15

#define APP_F_OFFSET_STEP \
    0x40u /* the offset-change check: since the reference block the
                                   slope- or gravity-axis mean moved by more than the bound's
                                   offset-change term allows (a bias jump, a drift, a stuck bit);
                                   latched until app_restart or app_init */

/*
 * The offset-change check. The first still, valid, calibrated block after app_init or
 * app_restart is the reference (its means on the slope and gravity axes, and its noise term
 * n_ref = k sigma / sqrt(N)). Every later still block with noise term n compares its means:
 * |mean - ref| > offset_drift_g - n - n_ref on either axis (or n + n_ref >= offset_drift_g:
 * the check cannot tell) sets APP_F_OFFSET_STEP and latches it. So an offset change b that is
 * not detected satisfies |b| <= |mean - ref| + n + n_ref <= offset_drift_g, the term the bound
 * carries: every valid estimate stays inside its bound under any offset change since the
 * reference. A real tilt of the parked car by more than about offset_drift_g (0.5 deg at 10 mg)
 * while the block stays still trips it too: the estimate is then not valid until the
 * application restarts (the safe side). An offset change before the reference is the part's
 * ageing, which the term covers only up to offset_drift_g (docs/safety.md).
 */

/* One estimate (one block of avg_n samples). */
struct app_result {
    bool valid;                 /* slope.valid, and neither APP_F_SENSOR nor APP_F_SATURATED */
    uint32_t flags;             /* APP_F_* */
    struct slope_result slope;  /* estimate, bound, SLOPE_F_* flags */
    struct slope_budget budget; /* the budget the bound was computed with */
    fx_q16_t accel_g[3];        /* calibrated mean acceleration */
    fx_q16_t gyro_dps[3];       /* calibrated mean rate */
    fx_q16_t temp_c;            /* mean temperature (the default when the part has none) */
    fx_q16_t sigma_meas_g;      /* rms per sample measured on the slope axes (largest window) */
    uint32_t n;                 /* samples averaged */
    uint32_t missed;            /* part samples lost (missed data-ready) during the block */
    uint32_t sensor_errors;     /* failed reads during the block */
    uint32_t motion_windows;    /* stillness windows of the block that were not quiet */
    uint8_t still_state;        /* enum still_state at the end of the block */
    int cal_status;             /* calstore_load's status at app_init (0: calibrated) */
};

/* A calibrated sample, as app_step passes it on (e.g. to the tilt filter). */
struct app_corrected {
    fx_q16_t accel_g[3];
    fx_q16_t gyro_dps[3];
    fx_q16_t temp_c;
    uint32_t flags; /* SENSOR_S_* of the sample */
};

struct app {
    struct app_cfg cfg;
    struct sensor sensor;
    struct calrec_binding id; /* the sensor's identity (sensor_identity), read at init */
    struct calrec rec;        /* the record in use (safe default when uncalibrated) */
    struct cal_acc acc;
    struct cal_gyro gyro;
    struct still still;
    fx_q16_t k_sigma;     /* noise factor from the lifetime exceedance rule */
    bool ref_set;         /* the offset-change check's reference is taken */
    bool offset_fault;    /* APP_F_OFFSET_STEP latched */
    fx_q16_t ref_a[3];    /* reference block means, Q16 g */
    fx_q16_t ref_noise_g; /* its noise term k sigma / sqrt(N), Q16 g */
    bool temp_prev_set;   /* a previous block's mean temperature is known */
    fx_q16_t temp_prev_c;
    bool temp_ref_set; /* the second temperature source (app_set_temp_ref) */
    fx_q16_t temp_ref_c;
    int cal_status;        /* calstore_load status */
    bool temp_set;         /* the models were evaluated at least once */
    fx_q16_t temp_applied; /* temperature of that evaluation */
    /* The block in progress and app_eol_face's sums share their memory (the small images' RAM):
     * app_eol_face drops the block (app_restart), and a block never runs inside it. */
    union {
        struct {
            struct fx_sum sum_a[3], sum_g[3], sum_t;
        };
        struct {
            struct cal_avg eol_a, eol_g; /* here, not on the stack: the M0+ image's is small */
        };
    };
    uint32_t n, missed, errors, motion_start, flags;
    uint64_t var_max; /* largest window variance on the slope axes, Q16 g^2 */
    bool ready;
};

/*
 * A starting configuration for a part sampling at rate_mhz (milli-samples/s, 10 000 .. 10^7):
 *   stillness windows of W = round(rate * 5 / 16 s) samples (0.31 s; 256 at 819.2 SPS), at rest
 *   after 2 quiet windows; limits: accel sd 30 mg (engine idle passes, driving does not), gyro
 *   sd 0.5 deg/s, |gyro mean| 1 deg/s, | |a| - 1 g | 50 mg, window-to-window drift 15 mg;
 *   blocks of avg_n = 8 W samples (2.5 s);
 *   two-axis slope (x along the vehicle, nose up = +x; z up), |slope| <= 30 deg, bound <= 2 deg,
 *   magnitude 1 g +- 50 mg;
 *   [ADI-EPB]'s Table 1 as the budget: after calibration sensitivity 0, offset 0, nonlinearity
 *   10 mg, total offset change 10 mg after three-point calibration, all of it the stress and
 *   ageing share that the offset-change term carries (offset_drift_g 10 mg, temp_comp_g 0:
 *   [ADI-EPB] takes the three-point models to remove the 80 % temperature share of its 50 mg) or
 *   50 mg without compensation (temp_uncomp_g, on top of the 10 mg term), scale drift 0.5 %; before it 3 % and
 *   15 mg; noise 4 mg per sample ([ADI-EPB]: 0.4 mg after averaging 100); k from M = 200 000
 *   parkings and E = 0.001 (k = 5.9);
 *   temperature 25 degC when the part has none, models re-evaluated every 0.5 degC, a margin of
 *   1 degC around the calibrated temperature range, no read error tolerated in a block.
 * An integrator replaces the budget with the residuals its end-of-line process achieves.
 * 0, INC_ERR_NULL, INC_ERR_INVAL (rate).
 */
int app_cfg_default(struct app_cfg *cfg, uint32_t rate_mhz);

/*
 * Check cfg: avg_n in 1..2^31 and a multiple of still.window, still_init's and slope_cfg_check's
 * rules (with the composed budget), budget terms >= 0, temp_step_c > 0, temp_margin_c >= 0. 0, INC_ERR_NULL,
 * INC_ERR_INVAL.
 */
int app_cfg_check(const struct app_cfg *cfg);

/*
 * Start the application: read the sensor's identity, load its calibration from store (NULL:
 * none), bind the correction to it. Returns 0 when the application runs, calibrated or not
 * (a->cal_status tells: 0, or calstore_load's code; INC_ERR_NOT_CALIBRATED without a store);
 * INC_ERR_NULL (a, cfg, sensor, or an ops table without wait_ready, read or identity),
 * INC_ERR_INVAL (cfg), or the identity read's error (a is then not
 * ready and every call returns INC_ERR_STATE).
 */
int app_init(struct app *a, const struct app_cfg *cfg, const struct sensor *sensor,
             struct calstore *store);

/* True when a valid record is applied (at the last evaluated temperature). */
bool app_calibrated(const struct app *a);

/*
 * Feed one sample (from the sensor, or from a replay). It is calibrated (out, may be NULL),
 * pushed to the stillness detector and into the block. When it completes a block, *done is true
 * and *res holds the estimate; the next block starts. read_err != 0 counts a failed read instead
 * (s is not used, may be NULL). INC_ERR_NULL, INC_ERR_STATE.
 */
int app_step(struct app *a, const struct sensor_sample *s, int read_err, struct app_corrected *out,
             bool *done, struct app_result *res);

/*
 * Read samples from the sensor (sensor_next with the driver's default timeout: the next
 * data-ready, or the next output period) until one block is complete and return its estimate.
 * Read errors are counted (APP_F_SENSOR beyond max_sensor_errors); after 4 * avg_n reads without
 * a complete block the last read error is returned. 0, INC_ERR_NULL, INC_ERR_STATE, or that
 * error.
 */
int app_measure(struct app *a, struct app_result *res);

/* The second temperature source (e.g. the ECU's board sensor), degC Q16, for the plausibility
 * check of the blocks that end from now on; valid false: none fitted (the default). */
void app_set_temp_ref(struct app *a, fx_q16_t t_c, bool valid);

/* Drop the block in progress and restart the stillness windows (e.g. after the vehicle moved). */
void app_restart(struct app *a);

/*
 * Defaults of the record plausibility (app_cfg_default): the part type's limits with margin.
 * [ADI-EPB]'s example part has an initial offset of 15 mg and a sensitivity error of 3 %; the
 * simulated part A already has 34 mg and 3.1 %, and the ADIS16405's own accelerometer bias and
 * sensitivity limits are not confirmed here (docs/unconfirmed-facts.md): 100 mg, 10 % and
 * 35 mrad (2 deg) of cross-axis are loose enough for every part the project simulates and catch
 * a record that is grossly wrong (a field of another unit, a sign, a scale). A wrong offset
 * inside them is for the end-of-line verification (app_eol_verify, docs/safety.md).
 */
#define APP_REC_OFFSET_MAX_MG 100
#define APP_REC_GAIN_TOL_PPM 100000
#define APP_REC_MISALIGN_MAX_URAD 35000

/* ---- End of line ------------------------------------------------------------------------- */

/* A still face: raw (uncalibrated, nominal-scaled) means, exact to 0.5 LSB. */
struct app_face {
    fx_q16_t accel_g[3];
    fx_q16_t gyro_dps[3]; /* 0 for a part without gyro */
    fx_q16_t temp_c;      /* 0 for a part without temperature */
    uint32_t n;           /* samples averaged */
    uint32_t flags;       /* SENSOR_S_HAVE_GYRO / SENSOR_S_HAVE_TEMP as the part has them */
};

/*
 * Average n (1..2^31) samples of a face held still. Every read must succeed; any axis whose
 * span (max - min) exceeds max_span_g (accelerometer) or max_span_dps (gyro) makes it
 * INC_ERR_MOTION (the part moved). INC_ERR_NULL, INC_ERR_STATE, INC_ERR_INVAL (n == 0), a read
 * error. *out written only on success. Once it has started reading (every return but those
 * three) it has dropped the block in progress and restarted the stillness windows as
 * app_restart does: the sums it used are the block's.
 */
int app_eol_face(struct app *a, uint32_t n, fx_q16_t max_span_g, fx_q16_t max_span_dps,
                 struct app_face *out);

/*
 * On-device offset and gain: cal_six_position on the faces' accelerometer means (enum cal_face
 * order) into rec->acc_offset / acc_gain, and the gyro offset = the mean of the six faces' gyro
 * means (rounded, |error| <= 0.5 LSB) into rec->gyro_offset when the part has a gyro. Other
 * fields of rec are left as they are. INC_ERR_NULL; cal_six_position's errors; INC_ERR_RANGE
 * for a gyro offset beyond 30 deg/s. rec untouched on error.
 */
int app_eol_six_position(const struct app_face face[CAL_FACES], struct calrec *rec);

/*
 * Bind rec to the sensor (its identity read at app_init) and store it as the newest record
 * (calstore_save). The running instance keeps its current calibration; the record is used after
 * the next app_init. INC_ERR_NULL, INC_ERR_STATE, calstore_save's errors.
 */
int app_eol_save(struct app *a, struct calrec *rec, struct calstore *store,
                 struct calstore_info *info);

/*
 * The whole on-device save without a record of the caller's (a 640 B struct calrec that a small
 * image's stack would have to hold): the safe default (calrec_set_default), the six faces' offset,
 * gain and gyro offset (app_eol_six_position), bound and stored (app_eol_save), all built in a's
 * own record in use. That record is then gone, so a is left NOT READY (every call returns
 * INC_ERR_STATE) until the caller runs app_init again, which loads what the store holds: the new
 * record after a successful save, the one before after a failed save (a power cycle gives the
 * same). Returns app_eol_six_position's or calstore_save's code; INC_ERR_NULL (a, face or store;
 * a stays ready); INC_ERR_STATE (a not ready). info may be NULL.
 */
int app_eol_fit_save(struct app *a, const struct app_face face[CAL_FACES], struct calstore *store,
                     struct calstore_info *info);

/*
 * End-of-line verification, after the record is saved and loaded again (a fresh app_init): the
 * calibrated reading of a still face f (raw means from app_eol_face; the correction applied at
 * the face's temperature) against the face's ideal specific force (enum cal_face: +-1 g on one
 * axis, 0 on the others). *dev_g (may be NULL) = the largest |calibrated - ideal| over the
 * axes. Returns 0 when *dev_g <= tol_g, INC_ERR_RANGE beyond (the station rejects the unit),
 * INC_ERR_NOT_CALIBRATED when no record is applied, INC_ERR_NULL, INC_ERR_STATE, INC_ERR_INVAL
 * (face, tol_g < 0). This is what catches a record with a correct CRC but a wrong value: the
 * CRC only proves the record is the one written.
 */
int app_eol_verify(struct app *a, const struct app_face *f, int face, fx_q16_t tol_g,
                   fx_q16_t *dev_g);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_APP_H */
