/*
 * app_esc.h - the driving (ESC) run mode of the application and the parked/driving mode manager
 * (module inclino_app, prefix app_esc_). docs/attitude.md, "The ESC run mode".
 *
 * Per data-ready sample, after app_step has read and calibrated it (inclino/app.h: the record's
 * correction with its temperature models, the stillness detector, the EPB block):
 *   1. the gyro gets the processor-side correction of the last gyro calibration (gyrocal's
 *      1/320 deg/s path, inclino/gyrocal.h: gyrocal_correct_q16), when one is set;
 *   2. the attitude estimator (inclino/att.h) takes the sample, with the vehicle's speed and yaw
 *      rate when the vehicle network gives them (aiding), and the per-axis saturation flags;
 *   3. the mode: DRIVING while |speed| > drive_speed_mps (or, without a speed input, while the
 *      stillness detector is not at rest); PARKED once the detector has been at rest and the
 *      speed below drive_speed_mps for park_s. Entering DRIVING drops the EPB block in progress
 *      (app_restart): a block that saw the car move is never an estimate;
 *   4. the output: in DRIVING, the attitude (quaternion, roll, pitch, bound, validity) every
 *      out_div samples, valid only when the vehicle input (speed, yaw rate) was there: a car
 *      sustains accelerations longer than the estimator's filter, which without the speed it
 *      can neither remove nor bound; in PARKED, the EPB slope estimate of each completed block (unchanged:
 *      the EPB path is app_step's). Every output says which mode it came from.
 *   5. the driving diagnostics, when configured (app_esc_diag_default; off by default): the
 *      flat-line check, the vehicle-level check and the two-sensor cross-check
 *      (inclino/xcheck.h); a failed one latches its APP_ESC_D_* bit and takes the validity of
 *      every later DRIVING output (docs/safety.md, "The driving matrix").
 * While parked long enough (autonull_after_s at rest since the last calibration), the mode
 * manager asks for a gyro autonull (app_esc_autonull_due): the board runs the part's autonull
 * and the processor-side correction (gyrocal_run) and hands the result over with
 * app_esc_set_gyro_correction; the estimator's own bias estimate keeps working meanwhile.
 *
 * Units: Q16.16 (inclino/fx.h). Freestanding C11, integer only, no heap; caller-allocated.
 */
#ifndef INCLINO_APP_ESC_H
#define INCLINO_APP_ESC_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/app.h"
#include "inclino/att.h"
#include "inclino/error.h"
#include "inclino/fx.h"
#include "inclino/gyrocal.h"
#include "inclino/xcheck.h"

#ifdef __cplusplus
extern "C" {
#endif

enum app_mode {
    APP_MODE_PARKED = 0,  /* the EPB path: slope from block averages */
    APP_MODE_DRIVING = 1, /* the ESC path: attitude per sample */
};

/* What the vehicle network says (wheel speed, the ESC's yaw rate), per sample. */
struct app_vehicle {
    bool valid;            /* false: no vehicle input (the mode uses stillness alone) */
    fx_q16_t speed_mps;    /* longitudinal speed along sensor x, m/s, |.| <= 200 */
    fx_q16_t yaw_rate_dps; /* about sensor z, deg/s */
};

struct app_esc_cfg {
    struct att_config att;
    uint32_t out_div;          /* an attitude output every out_div samples, 1..65535 */
    fx_q16_t drive_speed_mps;  /* above: driving. (0, 10] m/s */
    fx_q16_t park_s;           /* at rest and slow this long: parked. [0, 60] s */
    fx_q16_t autonull_after_s; /* parked this long since the last gyro calibration: autonull
                                  due. [1, 3600] s */
    /* The driving diagnostics (docs/safety.md, "The driving matrix"; inclino/xcheck.h). Each
     * one only ever takes validity away: when its check fails it sets its APP_ESC_D_* bit,
     * latched until app_esc_init, and every DRIVING output after it is not valid. The attitude
     * itself (att) is never touched. app_esc_cfg_default leaves them off (0);
     * app_esc_diag_default sets the values in brackets. */
    uint32_t flat_n;         /* flat line: a gyro or accelerometer channel of the driver's sample
                              (before calibration) equal for flat_n consecutive samples (a MEMS output always shows
                              its noise: ADIS16405 3 LSB rms accel, 20 LSB gyro). 0: off, else
                              [2, 65535] [16: P(false) < 1e-15 per channel-sample at 3 LSB] */
    fx_q16_t veh_margin_g;   /* vehicle-level check: fails when the low-passed residual
                              a - up - (dv/dt, yaw x v, 0)/g0, x or y, exceeds
                              veh_bound_k x the output's own bound in g (bound_deg x pi/180 >=
                              sin(bound)) + veh_dyn_k x the low-passed kinematic acceleration
                              (wheel slip and the speed's delay grow with it) + this margin
                              (the speed's 0.01 m/s steps, vibration). 0: off, else (0, 1] g
                              [0.015: over the eight fault-free scenarios the low-passed residual
                              exceeds the other two terms by at most 4.6 mg] */
    fx_q16_t veh_bound_k;    /* Q16, (0, 1] [0.5: the check is to fire while the error is still
                              within the bound; the margin below was measured with this factor] */
    fx_q16_t veh_dyn_k;      /* Q16, [0, 1] [0.3; longitudinal only: the yaw rate x speed term
                              has neither slip nor delay of that size] */
    fx_q16_t veh_min_mps;    /* the check runs only above this speed (the wheel-speed sensors'
                              edges are too sparse below a few m/s, down to no speed at all
                              below their minimum), [0, 20] m/s [3] */
    fx_q16_t xchk_thr_g;     /* two-sensor cross-check: fails when the low-passed difference of
                              the second accelerometer (app_esc_set_aux_accel) and the IMU's,
                              its x-y norm or its z axis, exceeds this. 0: off, else (0, 1] g [0.03: both parts'
                              offset-change terms, 10 mg each, + 5 x the low-passed noise of
                              both (ADIS 10 mg, SCA3000 5 mg rms per sample: 2.5 mg) + 7.5 mg
                              for their sampling skew and placement under vibration] */
    fx_q16_t veh_gyro_dps;   /* the vehicle-level check's floor under the DRIVING bound: a gyro
                              error (bias step or drift) tilts the estimate without any sign in
                              the att filter's own bound, and the check only fails once the
                              low-passed residual passes its threshold. While the check runs,
                              the published bound is at least the error it can leave undetected:
                              asin^-1 of (threshold - veh_bound_k x bound) / (1 - veh_bound_k)
                              (the error at which the threshold would be passed, taken as
                              radians: >= its asin), in degrees, + veh_gyro_dps x the check's
                              delay (the low-pass's 2^(diag_shift+1) samples + diag_persist_n),
                              for gyro errors up to veh_gyro_dps. While DRIVING without the
                              check (below veh_min_mps, a held sample), the floor grows from its
                              last value by veh_gyro_dps per second (from the floor at rest,
                              the margin's share + the delay's, on entering DRIVING): the error
                              such a gyro error can add unseen. 0: no floor, else
                              (0, 50] deg/s [2: the fault matrix's bias step] */
    fx_q16_t xchk_margin_g;  /* the cross-check's term in the DRIVING bound: an accelerometer
                              bias whose x-y norm and z part are each up to T = xchk_thr_g +
                              this passes the check unseen (this: the healthy parts' low-passed
                              disagreement); its tilt error, at most T (1 + s) / (1 - sqrt(2) T)
                              rad with s = sqrt(u_x^2 + u_y^2) of the estimate's up u (T for a
                              level sensor), is added to the att bound. Only with xchk_thr_g
                              on. [0, 1] g [0.01: the fault-free drives' largest low-passed
                              disagreement is 4.6 mg] */
    uint8_t diag_shift;      /* the residuals' two-stage low-pass, 2^-shift per sample and stage,
                              [1, 16] [8: 0.31 s per stage at 819.2 SPS, group delay 0.62 s] */
    uint32_t diag_persist_n; /* samples above the threshold that make a failure,
                                [1, 2^24] [41: 50 ms at 819.2 SPS] */
};

/* The driving diagnostics' bits (struct app_esc_output.diag). D_FLAT, D_VEH and D_XCHK are
 * latched faults; D_NO_SPEED is the state of this output (no usable vehicle input: with
 * require_aiding the output is not valid, att.h). */
#define APP_ESC_D_FLAT 0x01u     /* a channel flat-lined (xcheck_flat) */
#define APP_ESC_D_VEH 0x02u      /* the vehicle-level check failed */
#define APP_ESC_D_XCHK 0x04u     /* the two accelerometers disagree */
#define APP_ESC_D_NO_SPEED 0x08u /* this DRIVING output had no vehicle input */

/* The output of one sample (app_esc_step sets *have_out when there is one). */
struct app_esc_output {
    uint8_t mode; /* enum app_mode it came from */
    bool valid;   /* DRIVING: att_get_valid; PARKED: the EPB result's validity */
    int32_t q[4]; /* DRIVING: sensor to earth, Q30 w x y z */
    fx_q16_t roll_deg, pitch_deg;
    fx_q16_t bound_deg; /* DRIVING: the larger of the att filter's 99.9 % inclination-error
                           bound + the cross-check's term (xchk_margin_g) and the vehicle-level
                           check's floor (veh_gyro_dps): the error a single fault the checks
                           cannot see yet can add; PARKED: slope bound */
    uint8_t att_fault;  /* ATT_FAULT_* */
    uint8_t diag;       /* APP_ESC_D_* (DRIVING outputs; the latched bits in both modes) */
    fx_q16_t veh_level_g, xchk_level_g; /* the diagnostics' low-passed residuals now (Q16 g;
                                           0 while a check is off or not running) */
    fx_q16_t veh_thr_g;                 /* the vehicle-level check's threshold now (Q16 g) */
    struct app_result epb;              /* PARKED: the slope estimate (valid only then) */
};

struct app_esc {
    struct app_esc_cfg cfg;
    struct att att;
    struct gyrocal_correction gcorr;
    uint32_t park_n, autonull_n; /* thresholds in samples */
    uint32_t n_out;              /* samples since the last attitude output */
    uint32_t still_n;            /* samples at rest and slow */
    uint32_t since_cal_n;        /* samples parked since the last gyro calibration */
    uint8_t mode;
    bool ready;
    /* the driving diagnostics */
    struct xcheck_flat flat;
    struct xcheck_mon vmon, kmon, xmon;
    fx_q16_t v_prev;     /* the previous sample's speed (v_prev_ok) */
    fx_q16_t aux_acc[3]; /* the second accelerometer's latest calibrated sample */
    fx_q16_t veh_level, xchk_level, veh_thr;
    fx_q16_t veh_floor;   /* the bound's floor from the vehicle-level check now (0: none) */
    fx_q16_t veh_hold;    /* the floor carried while the check does not run, Q16 deg */
    fx_q16_t veh_rest;    /* the floor at rest (margin only), Q16 deg */
    fx_q16_t veh_step;    /* veh_gyro_dps per sample, Q16 deg, rounded up */
    fx_q16_t veh_lag_deg; /* veh_gyro_dps x the check's delay, Q16 deg */
    uint32_t veh_inv_q16; /* 1 / (1 - veh_bound_k), Q16 (0: veh_bound_k = 1, no floor possible) */
    uint8_t diag;         /* latched APP_ESC_D_* */
    bool v_prev_ok, aux_valid;
};

/* Defaults for a part at rate_mhz (milli-samples/s): att_config_default at that rate, an output
 * every 8 samples (about 100 Hz at 819.2 SPS), driving above 0.5 m/s, parked after 2 s at rest,
 * autonull due after 60 s parked. INC_ERR_NULL, INC_ERR_INVAL (rate outside 100..4000 SPS). */
int app_esc_cfg_default(struct app_esc_cfg *cfg, uint32_t rate_mhz);

/* The driving diagnostics on, with the values in brackets in struct app_esc_cfg, scaled to the
 * configured sample rate (persistence 50 ms, low-pass 2^8 samples at 819.2 SPS, halved per
 * halving of the rate, at least 2). Call after app_esc_cfg_default. INC_ERR_NULL. */
int app_esc_diag_default(struct app_esc_cfg *cfg);

/* The second accelerometer's latest calibrated sample (Q16 g, the IMU's frame; an SCA3000
 * beside the ADIS), for the two-sensor cross-check of the next app_esc_step calls; valid false
 * (not fitted, a read error, a saturated axis) holds the check. INC_ERR_NULL. */
int app_esc_set_aux_accel(struct app_esc *e, const fx_q16_t acc_g[3], bool valid);

/* Validate cfg (att_init's checks included) and start PARKED with no gyro correction.
 * INC_ERR_NULL, INC_ERR_INVAL; on error every step is refused (INC_ERR_STATE). */
int app_esc_init(struct app_esc *e, const struct app_esc_cfg *cfg);

/*
 * One sample: app_step(a, s, read_err, ...) and then steps 1-4 above. veh may be NULL (no
 * vehicle input). *have_out is true when *out holds an output. A failed read (read_err != 0) is
 * counted by app_step and feeds nothing to the estimator. INC_ERR_NULL, INC_ERR_STATE, or
 * app_step's error; att_update's INC_ERR_RANGE (an input beyond full scale) is not an error here:
 * the estimator marks itself invalid and says so in att_fault.
 */
int app_esc_step(struct app_esc *e, struct app *a, const struct sensor_sample *s, int read_err,
                 const struct app_vehicle *veh, struct app_esc_output *out, bool *have_out);

/* The mode now (enum app_mode); APP_MODE_PARKED for NULL. */
uint8_t app_esc_mode(const struct app_esc *e);

/* True when a gyro autonull should run now (parked long enough since the last one). */
bool app_esc_autonull_due(const struct app_esc *e);

/* Take the processor-side correction of a gyro calibration (gyrocal_correction_get) and restart
 * the autonull interval. A correction with valid == false removes it. INC_ERR_NULL. */
int app_esc_set_gyro_correction(struct app_esc *e, const struct gyrocal_correction *c);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_APP_ESC_H */
