/*
 * att.h - 3D attitude (inclination) estimator of Inclino (module inclino_att, prefix att_).
 *
 * Freestanding C11, integer only (no FP types), no libc, no heap; uses inclino/fx.h conventions
 * (Q16.16 physical quantities in g, deg/s, deg, s, Hz; Q2.30 ratios; every dropped bit rounds
 * to nearest with ties away from zero; results that do not fit saturate; negative values are
 * shifted only through fx_asr or on magnitudes). Outputs are bit-identical on every C11 target.
 *
 * WHAT IT ESTIMATES
 *   The orientation of the sensor frame relative to an earth frame with z up, as a unit
 *   quaternion q (sensor to earth: v_earth = q v_sensor q^-1), of which only the inclination
 *   (direction of gravity) is observable from gyro + accelerometer; the heading is arbitrary
 *   and drifts. Roll and pitch (deg, Q16) are derived on demand (att_get_euler).
 *   Every update also yields att_bound_deg, a 99.9 % bound of the inclination error, and
 *   att_valid = (bound <= configured limit) && initialised && no sensor fault.
 *
 * METHOD (own formulation, after the structure of VQF, Laidig & Seel 2023, Information Fusion 91)
 *   1. Strapdown: q_g <- q_g (x) dq with dq = [cos(|h|), sin(|h|)/|h| h], h = (w - b) dt / 2,
 *      all three axes at once (the exact rotation of the step, by series in |h|^2 to Q30
 *      precision: <= 4 LSB per step measured, see att.c strapdown), renormalised by a Newton
 *      step every 4th sample (|q| stays within 4 LSB of 1). q_g is the "gyro frame": almost
 *      inertial, it only drifts by the residual gyro error.
 *   2. The accelerometer is rotated into the gyro frame and low-pass filtered there by a
 *      2nd-order Butterworth (tau_acc, default 3 s) realised as two integrators. Zero-mean
 *      linear accelerations (shaking, vibration, translations: their integral is a velocity
 *      change that returns to 0) average out, so no per-sample rejection is needed (it would
 *      break that cancellation; measured on the BROAD trials: rejecting |a| > 4 g raises the
 *      mean RMS error from 0.69 to 2.4 deg). Samples with a saturated accelerometer axis are
 *      not fed to the filter (it holds); that time counts as time without correction.
 *      At rest (accel trustworthy) the filter runs with tau_acc_rest (default 1.5 s): faster
 *      re-convergence when the part comes to rest.
 *   3. The estimate is q = q_a (x) q_g, q_a the smallest rotation that takes the filtered
 *      gravity to earth z. When the filtered gravity leaves a cone of 8 deg about z, the gyro
 *      frame is re-based (q_g, the filter states rotated by q_a): no singularity, no gimbal lock.
 *   4. Gyro bias b: a scalar Kalman filter at rest (rest = gyro and accel deviations from their
 *      own low-pass below thresholds for rest_min_s, and |low-passed gyro| <= bias_max), and an
 *      integral term in motion from the inclination correction rate rotated back to the sensor
 *      frame (observable only for the horizontal axes), weighted down to 0 as the horizontal
 *      residual acceleration grows (trust). b is clamped to +-bias_max.
 *   5. Bound = floor (accel vs. true "up" at rest, residual accel bias) + drift (gyro scale /
 *      misalignment x |w| + k x bias sigma + saturated axes, integrated and forgotten with the
 *      correction time constant; not forgotten while the accel is held) + k_lin x the mean
 *      horizontal residual acceleration (what the low-pass may still contain) + |w| x the
 *      output's time-tag uncertainty. Before the filter is initialised (first tau_acc s) and
 *      on gravity/input faults the bound is 180 deg / valid is false.
 *   6. Optional vehicle aiding (speed along sensor x, yaw rate about sensor z; the sensor is
 *      assumed aligned with the vehicle): dv/dt and yaw rate x speed are subtracted from the
 *      accelerometer before everything else; speed >= 0.2 m/s also vetoes rest.
 * LIMITATION: a sustained, non-zero-mean acceleration that is not given as aiding (e.g. a long
 *   acceleration without speed input) tilts the filtered gravity and is not visible in the
 *   residual: a 6D filter cannot observe it; the bound does not cover it.
 *
 * RAM: sizeof(struct att) = 320 bytes on Cortex-M (arm-none-eabi); no other static or heap
 * memory. Stack: att_update 248 bytes + 72 for its deepest callee (Cortex-M3, -Os). Flash:
 * 9.8 kB (Cortex-M3, -Os, the whole module).
 * COST (QEMU -icount, instructions per att_update, -Os): Cortex-M3 ~1730 mean / ~1850 worst
 * single sample, Cortex-M0+ ~5530 / ~5820; the first sample (exact seed, re-base) ~3250 / ~11400,
 * a re-base in operation ~2230 / ~8620 (rare); att_get_quat ~160 / ~900, att_get_euler
 * ~1740 / ~3210 (call them at the output rate).
 */
#ifndef INCLINO_ATT_H
#define INCLINO_ATT_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "inclino/error.h"
#include "inclino/fx.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Configuration. Every field is validated by att_init (INC_ERR_INVAL outside its range). */
struct att_config {
    fx_q16_t sample_rate_hz; /* Q16 Hz, [100, 4000]; default: the att_config_default argument */
    fx_q16_t tau_acc_s;      /* Q16 s, accel low-pass time constant, [0.5, 30], and
                                  * tau_acc * rate >= 64; default 3 */
    fx_q16_t tau_acc_rest_s; /* Q16 s, the same at rest (accel trustworthy: faster
                                  * re-convergence), 0 = tau_acc, else [0.5, tau_acc] and
                                  * x rate >= 64; default 1.5 */
    fx_q16_t rest_tau_s;     /* Q16 s, rest-detection low-pass, [0.05, 5]; default 0.5 */
    fx_q16_t rest_gyro_dps;  /* Q16 deg/s, gyro deviation threshold (0, 50]; default 2 */
    fx_q16_t rest_acc_g;     /* Q16 g, accel deviation threshold (0, 1]; default 0.05 */
    fx_q16_t rest_min_s;     /* Q16 s, time below thresholds before rest, [0, 60]; default 1.5 */
    fx_q16_t bias_max_dps;   /* Q16 deg/s, bias clamp (the part's bias range), (0, 20]; default 2 */
    fx_q16_t bias_sigma0_dps; /* Q16 deg/s, initial bias sigma, (0, 0.99]; default 0.5 */
    fx_q16_t
        bias_sigma_rest_dps; /* Q16 deg/s, rest-update noise parameter, [0.001, sigma0]; default 0.03 */
    fx_q16_t bias_forget_s;      /* Q16 s, bias variance grows by (0.1 deg/s)^2 in this time,
                                  * [1, 10000]; default 100 */
    fx_q16_t bias_motion_tau_s;  /* Q16 s, motion bias time constant, 0 = off or
                                  * [2 tau_acc, 10000]; default 25 */
    fx_q16_t bias_motion_gate_g; /* Q16 g, mean horizontal residual at which the motion update
                                  * weight reaches 0, [0.01, 16]; default 1 */
    fx_q16_t gyro_fs_dps;        /* Q16 deg/s, gyro full scale, [100, 4000] and <= 20 x rate;
                                  * default 2000 */
    fx_q16_t acc_fs_g;           /* Q16 g, accel full scale, [1, 16]; default 16 */
    fx_q16_t bound_floor_deg;    /* Q16 deg, [0, 10]; default 0.6 */
    fx_q30_t bound_gyro_sf; /* Q30 ratio, gyro scale+misalignment error, [0, 0.1]; default 0.002 */
    fx_q16_t bound_bias_k;  /* Q16, multiplier on the bias sigma, [0, 10]; default 3 */
    fx_q16_t
        bound_lin_k; /* Q16, multiplier on the mean horizontal residual, [0, 100]; default 0.05 */
    fx_q16_t bound_lin_tau_s;   /* Q16 s, averaging of the residual, [0.1, 100]; default 3 */
    fx_q16_t bound_arw_dps_rts; /* Q16 deg/sqrt(s), gyro angle random walk N, [0, 1]: 3 N sqrt(t)
                                  * <= 3 N (t / tau + 1) sqrt(tau) / 2 adds the rate 1.5 N / sqrt(tau)
                                  * to the drift and 1.5 N sqrt(tau) to the floor; default 0.01 */
    fx_q16_t bound_latency_s;   /* Q16 s, time-tag uncertainty of the output (sampling skew,
                                  * one-sample latency): adds |w| x this, [0, 0.1]; default 0.004 */
    fx_q16_t bound_sat_dps;     /* Q16 deg/s, drift rate added per saturated gyro axis, [0, 4000];
                                  * default 200 */
    fx_q16_t bound_limit_deg;   /* Q16 deg, valid only if bound <= this, (0, 90]; default 5 */
    fx_q16_t fault_hold_s;      /* Q16 s, att_valid stays false this long after a fault, [0, 60];
                                  * default 1 */
    fx_q16_t bound_lever_m;     /* Q16 m, with vehicle aiding: the largest distance of the
                                  * sensor from the point whose speed the aiding uses (the rear
                                  * axle's centre), [0, 10]: the aiding misses the acceleration
                                  * of that lever, d (w^2 + |dw/dt|) with the yaw rate w, and
                                  * the bound counts it; default 2 */
    uint32_t require_aiding;    /* 1: a vehicle, which sustains accelerations (cornering,
                                  * braking) longer than tau_acc; without the speed they can
                                  * even look like rest, and the bound cannot hold them: valid
                                  * only on samples with vehicle aiding (veh_valid). 0 or 1;
                                  * default 0 (a free-moving platform) */
};

/* One input sample. */
struct att_sample {
    fx_q16_t gyro_dps[3];  /* Q16 deg/s, sensor x y z */
    fx_q16_t acc_g[3];     /* Q16 g (specific force; about (0, 0, +1) at rest, z up) */
    uint8_t sat;           /* saturation reported by the part: bits 0-2 gyro x y z,
                                  * bits 3-5 accel x y z (OR'ed with att's own detection at
                                  * |value| >= full scale - full scale / 256) */
    bool veh_valid;        /* vehicle aiding present (speed, yaw rate) */
    fx_q16_t speed_mps;    /* Q16 m/s, longitudinal speed along sensor x, [-200, 200] */
    fx_q16_t yaw_rate_dps; /* Q16 deg/s, vehicle yaw rate about sensor z (left positive) */
};

#define ATT_SAT_GYRO_MASK 0x07u
#define ATT_SAT_ACC_MASK 0x38u

/* Fault bits (att_get_status). */
#define ATT_FAULT_INPUT 0x01u   /* a sample was rejected (out of range) within fault_hold_s */
#define ATT_FAULT_GRAVITY 0x02u /* filtered gravity magnitude implausible (< 0.125 g or > 2.8 g) */

/* The estimator state: a fixed struct, caller-owned, no heap. Fields are private. */
struct att {
    /* configuration-derived coefficients (att_init) */
    int32_t kh_m;             /* half angle per deg/s: h_Q30 = w_Q16 * kh_m / 2^kh_s */
    int32_t k1_m[2], k2_m[2]; /* low-pass integrator gains, mantissas: [0] motion, [1] rest */
    int32_t leak[2];          /* Q30 dt / tau_acc, dt / tau_acc_rest */
    int32_t dt_q30;           /* Q30 s (dt <= 0.01 s) */
    int32_t P0, V;            /* Q30 (deg/s)^2 */
    int32_t W_n;              /* W / 2^pw_e, Q30 */
    int32_t g_mb;             /* Q24 deg/s per rad: motion bias gain (0 = off) */
    int32_t ig_mb;            /* Q20 1/g: 1 / bias_motion_gate */
    int32_t c_lin;            /* Q16 deg: bound_lin_k * 180/pi */
    int32_t sf;               /* Q30 bound_gyro_sf */
    int32_t kb;               /* Q16 bound_bias_k */
    int32_t lat;              /* Q30 s bound_latency */
    int32_t arw_rate;         /* Q16 deg/s: 1.5 N / sqrt(tau_acc) */
    int32_t bsat;             /* Q16 deg/s per saturated axis */
    int32_t floor_q16, limit_q16;
    int32_t bmax24;            /* Q24 deg/s bias clamp */
    int32_t bmax16;            /* Q16 deg/s */
    int32_t gyro_lim, acc_lim; /* Q16: saturation thresholds */
    int32_t gyro_max, acc_max; /* Q16: rejection thresholds (full scale + 1/8) */
    int32_t gap_deg20; /* Q20 deg: full scale x dt, added to the drift per rejected sample */
    int32_t fs_q16;    /* Q16 Hz */
    int32_t fsg;       /* Q16 (fs / 9.80665): m/s per step -> g */
    int32_t rest_thg2, rest_tha2; /* thresholds squared, Q16 (deg/s Q8)^2 and Q24 (g Q12)^2 */
    uint32_t rest_min_n, init_n, fault_hold_n;
    uint8_t k1_s[2], k2_s[2], kh_s, pw_e;
    uint8_t kr_sh, kl_sh; /* rest / residual averaging gains 2^-n */
    uint8_t ky_sh;        /* yaw-rate low-pass gain 2^-n (0.25 s) for dw/dt */
    int32_t lev_c1;       /* Q40 g per (deg/s)^2: lever x (pi/180)^2 / g0 */
    int32_t lev_c2;       /* Q30 g per deg/s of (yaw - its low-pass): lever x pi/180 / g0 / tau */
    int32_t yaw_lp;       /* Q16 deg/s low-passed yaw rate */
    int32_t AL;           /* Q26 g: the lever acceleration the aiding misses, low-passed */
    /* state */
    int32_t q[4];           /* Q30 gyro-frame quaternion */
    int32_t y[3];           /* Q26 g, filtered gravity in the gyro frame */
    int32_t u[3];           /* Q32 g per step, filter rate state */
    int32_t ry;             /* Q28 1/|y| */
    int32_t gf[3];          /* Q30 unit filtered gravity (gyro frame) */
    int32_t su[3];          /* Q30 g: sum of u/4 over the motion-bias window (4 samples) */
    int32_t glp[3], alp[3]; /* Q16 rest low-passes */
    int32_t b[3];           /* Q24 deg/s bias */
    int32_t P;              /* Q30 (deg/s)^2 bias variance */
    int32_t rpw;            /* Q24 1 / ((P + W) / 2^pw_e) */
    int32_t zb;             /* Q16 1/sqrt(P) (1 / (deg/s)) */
    int32_t sigb;           /* Q30 deg/s sqrt(P) */
    int32_t D;              /* Q20 deg drift bound */
    int32_t L;              /* Q26 g mean horizontal residual */
    int32_t bound;          /* Q16 deg */
    int32_t v_prev;         /* Q16 m/s */
    uint32_t n_init;        /* samples averaged so far; init_n + 1 = done */
    uint32_t rest_n, fault_n;
    uint8_t flags; /* bit0 initialised (att_init done), bit1 rest, bit2 valid,
                                  * bit3 v_prev valid, bit4 rest low-passes seeded */
    uint8_t fault; /* ATT_FAULT_* */
    uint8_t tick;  /* sample counter mod 4 (decimated tasks) */
    bool mb_ok;    /* every sample of the current window allows a motion-bias update */
    bool mb_pend;  /* cr holds a correction for the second half of the update */
    bool need_aid; /* require_aiding */
    int32_t cr[3]; /* Q30 rad: the window's correction, gyro frame (then gain-weighted) */
    int32_t gw;    /* Q24 deg/s per rad: the window's weighted gain */
};

/* Fills cfg with the defaults above for sample_rate_hz (Q16 Hz). INC_ERR_NULL for cfg == NULL.
 * The rate is only stored; att_init validates it. */
int att_config_default(struct att_config *cfg, fx_q16_t sample_rate_hz);

/* Validates cfg, derives the coefficients and resets the state. Returns 0, INC_ERR_NULL, or
 * INC_ERR_INVAL (a field outside its range; *a is then marked uninitialised and every later
 * att_update returns INC_ERR_STATE). Uses divisions (init only). */
int att_init(struct att *a, const struct att_config *cfg);

/* Resets the state (attitude, filter, bias, bound) keeping the configuration.
 * INC_ERR_NULL, INC_ERR_STATE (not initialised). */
int att_reset(struct att *a);

/* One sample. Returns
 *   0             the state advanced; outputs updated;
 *   INC_ERR_NULL  a or s NULL;
 *   INC_ERR_STATE not initialised;
 *   INC_ERR_RANGE an input beyond full scale + 1/8 (or |speed| > 200 m/s): the sample is not
 *                 used, the attitude is not propagated, the bound grows by full scale x dt,
 *                 att_valid is false (and stays false for fault_hold_s).
 * Cost: docs/benchmarks.md ("Attitude (3D estimator)"); no division except during the first tau_acc seconds (running mean)
 * and on re-basing (rare, bounded: at most once per sample). */
int att_update(struct att *a, const struct att_sample *s);

/* Output quaternion, Q30 w x y z (sensor to earth, z up, heading arbitrary), composed on demand
 * as q_a (x) q_g (about 20 products: call at the output rate). |q| = 1 within 8 LSB Q30; its
 * inclination is that of the filtered gravity to < 1e-7 deg (series truncation 0.1 LSB plus
 * 7 roundings of 0.5 LSB). Before the first sample: identity. Nothing is written for NULL. */
void att_get_quat(const struct att *a, int32_t q[4]);

/* Inclination error bound (99.9 %), Q16 deg, in [0, 180]; 180 until initialised. */
fx_q16_t att_get_bound(const struct att *a);

/* bound <= limit && initialised && no fault. */
bool att_get_valid(const struct att *a);

/* ATT_FAULT_* bits currently set. */
uint8_t att_get_status(const struct att *a);

/* Rest detected. */
bool att_get_rest(const struct att *a);

/* Gyro bias estimate, Q16 deg/s (rounded from Q24), and its sigma, Q16 deg/s. */
void att_get_bias(const struct att *a, fx_q16_t bias_dps[3], fx_q16_t *sigma_dps);

/* Earth "up" in the sensor frame, Q30 unit vector (= the normalised accel at rest). */
void att_get_up(const struct att *a, int32_t up[3]);

/* Roll = atan2(up_y, up_z), pitch = asin(-up_x), Q16 deg (|error| <= 2 LSB Q16 beyond the
 * quaternion's own rounding: fx_atan2_deg / fx_asin_deg 0.81 LSB each plus up-vector rounding).
 * Costs two fx trig calls (~1-2k instructions on M3): call at the output rate. Either pointer may
 * be NULL. */
void att_get_euler(const struct att *a, fx_q16_t *roll_deg, fx_q16_t *pitch_deg);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_ATT_H */
