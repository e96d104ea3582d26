/*
 * tilt.h - roll and pitch from a 3-axis accelerometer and the x/y gyro (module inclino_tilt,
 * prefix tilt_). [CN110567483] step 4, with the classic two-state Kalman filter as the alternative.
 *
 * Per axis (roll about x, pitch about y), every sample:
 *   gyro prediction      w_theta(k) = theta(k-1) + (w(k) - off(k)) dt
 *   accelerometer angle  a_theta(k): roll = atan2(a_y, a_z), pitch = atan2(-a_x, sqrt(a_y^2 + a_z^2))
 *   second Kalman stage  P2- = P2 + Q2, K2 = P2- / (P2- + R2),
 *                        theta(k) = w_theta(k) + K2 (a_theta(k) - w_theta(k)), P2 = (1 - K2) P2-
 * and the modes differ in the gyro offset off(k) (docs/kalman.md, "[CN110567483] step 4"):
 *   TILT_MODE_FEEDBACK      (default) off(k+1) = off(k) - Kb (theta(k) - w_theta(k)) / dt:
 *                           the patent's offset with its sign corrected and integrated, which
 *                           estimates and removes a constant gyro bias.
 *   TILT_MODE_SEED_PRINTED  off(k+1) = (theta(k) - w_theta(k)) / dt, exactly as printed. Then
 *                           w_theta(k+1) = w_theta(k) + w(k+1) dt: the prediction is the pure
 *                           gyro integral and a gyro bias b makes the angle drift as
 *                           (1 - K2) b t without bound (tests/tilt prove it). For comparison only.
 *   TILT_MODE_KF2           the state (angle, bias) with A = [1 -dt; 0 1], B = [dt; 0], u = w,
 *                           H = [1 0], Q = diag(q_angle dt, q_bias dt), R = R2 (inclino/kf.h).
 * The patent's per-axis form assumes small angles and a small yaw rate: the roll rate is taken as
 * w_x and the pitch rate as w_y (the Euler-rate coupling w_z tan(pitch) is neglected; it matters
 * when turning on a slope, see docs/kalman.md).
 *
 * FRAME: right-handed sensor frame; at rest and level the accelerometer reads (0, 0, +1 g).
 *   Positive roll turns +y toward +z (a_y = +sin(roll)); positive pitch turns +z toward +x
 *   (a_x = -sin(pitch)). Gyro rates are right-handed about x, y (z is not used).
 *
 * REJECTION (flagged in the output, the filter coasts and never diverges):
 *   accelerometer   | |a| - 1 g | > accel_tol_g, or TILT_IN_ACCEL_SAT: no accelerometer update
 *                   this step; the angle follows the gyro alone.
 *   gyro (per axis) |w| >= gyro_limit_dps, or TILT_IN_GYRO_SAT_X/Y: the rate is unknown, so the
 *                   angle is held and its variance grows by (gyro_limit_dps dt)^2 on top of Q2, so
 *                   that the next accepted accelerometer samples pull it back; the offset is not
 *                   learnt from that step.
 * TIME: every step takes dt (ns) since the previous sample, so a missed data-ready (a gap of
 *   2, 3 ... periods) integrates over the real interval. dt == 0 is refused (INC_ERR_INVAL,
 *   nothing changes). dt > dt_max_ns (a gap too long to integrate one gyro sample over)
 *   restarts the angles from the accelerometer (TILT_F_GAP_RESTART), keeping the offset.
 *
 * FORMATS: angles Q16 deg, rates Q16 deg/s, accelerations Q16 g (inclino/fx.h); variances in the
 *   P format of inclino/kf.h (unit^2 * 2^48 for Q16 quantities, KF_P_ONE_Q16 = 1 unit^2);
 *   densities (per second) likewise per second. Internally the angle keeps 16 extra bits and the
 *   offset is deg/s * 2^32. Accelerometer angles (tilt_accel_angles): |error| <= 0.85 LSB Q16
 *   against exact math on the same input (fx_atan2_deg's 0.81 LSB plus < 0.01 LSB from the
 *   scaled square root; measured 0.54 LSB). The filter: tests/kf/test_kf_ref.cpp compares
 *   10^6-step runs with the double-precision reference (sim/kfref): within 0.005 deg (measured
 *   5e-6 deg, printed form 8e-5 deg).
 * RANGES: see tilt_config_check. Angles are meant for |pitch| < 90 deg; roll wraps at +-180.
 */
#ifndef INCLINO_TILT_H
#define INCLINO_TILT_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/error.h"
#include "inclino/fx.h"
#include "inclino/kf.h"

#ifdef __cplusplus
extern "C" {
#endif

enum tilt_mode {
    TILT_MODE_FEEDBACK = 0,     /* [CN110567483] step 4, offset fed back with the sign corrected */
    TILT_MODE_SEED_PRINTED = 1, /* [CN110567483] step 4 as printed (drifts with a gyro bias) */
    TILT_MODE_KF2 = 2,          /* two-state (angle, gyro bias) Kalman filter */
};

enum { TILT_ROLL = 0, TILT_PITCH = 1, TILT_AXES = 2 };

/* Input flags (from the drivers). */
#define TILT_IN_GYRO_SAT_X (1u << 0) /* the x gyro sample is saturated / over range */
#define TILT_IN_GYRO_SAT_Y (1u << 1) /* the y gyro sample is saturated / over range */
#define TILT_IN_ACCEL_SAT (1u << 2)  /* an accelerometer axis is at its range limit */

/* Output flags. */
#define TILT_F_ACCEL_REJECTED (1u << 0) /* no accelerometer update this step (|a| or saturation) */
#define TILT_F_GYRO_REJ_ROLL (1u << 1)  /* gyro x rejected: roll held, variance inflated */
#define TILT_F_GYRO_REJ_PITCH (1u << 2) /* gyro y rejected: pitch held, variance inflated */
#define TILT_F_GAP_RESTART (1u << 3)    /* dt > dt_max: angles restarted from the accelerometer */
#define TILT_F_NOT_STARTED (1u << 4)    /* no accepted accelerometer sample yet: no estimate */
#define TILT_F_OVERFLOW (1u << 5)       /* a filter value saturated (see kf.h RANGES) */

/* The angle variance is never raised above this by coasting (2025 deg^2 = (45 deg)^2): a held
 * angle is then simply "unknown", and the P format keeps its headroom (KF_P_MAX is 4096 deg^2). */
#define TILT_VAR_CAP (KF_P_ONE_Q16 * 2025)

/* Tuning of one axis. */
struct tilt_axis_config {
    int64_t q_angle;  /* angle process noise density, deg^2/s * 2^48 (the gyro's ARW^2);
                         * Q2 = q_angle * dt per step. 1 .. KF_P_MAX */
    int64_t q_bias;   /* KF2: bias random-walk density, (deg/s)^2/s * 2^48 (RRW^2). 0 .. KF_P_MAX */
    int64_t r_angle;  /* R2: variance of the accelerometer angle, deg^2 * 2^48. 1 .. KF_P_MAX */
    int64_t p0_angle; /* angle variance at (re)start, deg^2 * 2^48. 0 .. TILT_VAR_CAP */
    int64_t p0_bias;  /* KF2: bias variance at start, (deg/s)^2 * 2^48. 0 .. KF_P_MAX */
    fx_q30_t bias_gain; /* FEEDBACK: Kb in [0, 1] (Q30); tilt_feedback_gain() gives the
                         * critically damped value K2/4 */
    fx_q16_t bias0_dps; /* offset at start (e.g. from calibration), deg/s, |.| < gyro_limit_dps */
};

struct tilt_config {
    uint32_t mode;                           /* enum tilt_mode */
    struct tilt_axis_config axis[TILT_AXES]; /* roll, pitch */
    fx_q16_t accel_tol_g;                    /* | |a| - 1 g | above this: rejected. (0, 0.5] g */
    fx_q16_t gyro_limit_dps;                 /* |w| at or above: rejected as saturated. > 0 */
    uint32_t dt_max_ns;                      /* longer steps restart. 1 .. 10^9 ns */
};

/* One sample. */
struct tilt_input {
    fx_q16_t accel_g[3];  /* calibrated specific force, g, sensor frame */
    fx_q16_t gyro_dps[3]; /* calibrated angular rate, deg/s; [2] (z) is not used */
    uint32_t flags;       /* TILT_IN_* */
};

struct tilt_output {
    fx_q16_t angle_deg[TILT_AXES];       /* roll, pitch */
    fx_q16_t sigma_deg[TILT_AXES];       /* 1-sigma of the estimate (sqrt of the variance) */
    fx_q16_t bias_dps[TILT_AXES];        /* gyro offset estimate (PRINTED: the patent's off) */
    fx_q16_t accel_angle_deg[TILT_AXES]; /* the accelerometer's angles (0 when rejected) */
    uint32_t flags;                      /* TILT_F_* */
    bool valid;                          /* started, no overflow: the angles may be used */
};

struct tilt_axis_state {
    struct kf kf;                      /* n = 1 (FEEDBACK, SEED_PRINTED) or 2 (KF2: angle, bias) */
    int64_t off;                       /* FEEDBACK, SEED_PRINTED: gyro offset, deg/s * 2^32 */
    int64_t q_angle_step, q_bias_step; /* q_angle dt, q_bias dt for dt_ns_cached (P format) */
};

struct tilt {
    struct tilt_config cfg;
    struct tilt_axis_state ax[TILT_AXES];
    uint64_t last_ns;      /* tilt_step_at: time of the previous sample */
    int64_t dt_q30_cached; /* dt_ns_cached in seconds, Q30 (the conversion is a 64-bit division) */
    uint32_t dt_ns_cached; /* 0: nothing cached */
    bool have_time;        /* tilt_step_at: last_ns is set */
    bool started;          /* an accepted accelerometer sample has started the angles */
    bool ready;            /* initialised */
};

/* A documented baseline (docs/kalman.md, "Default tuning"): FEEDBACK, ADIS1636x/1640x-class gyro
 * (q_angle = 1e-3 deg^2/s, q_bias = 2e-7 (deg/s)^2/s), R2 = 1 deg^2 (engine-idle vibration),
 * p0_angle = R2, p0_bias = 1 (deg/s)^2, Kb = tilt_feedback_gain at dt_nominal_ns, accel_tol
 * 0.1 g, gyro_limit 295 deg/s, dt_max 100 ms. dt_nominal_ns in 1..dt_max. */
int tilt_config_default(struct tilt_config *cfg, uint32_t dt_nominal_ns);

/* 0, or INC_ERR_NULL / INC_ERR_INVAL (mode unknown or a field outside its range above). */
int tilt_config_check(const struct tilt_config *cfg);

/* The critically damped feedback gain Kb = K2inf / 4, where K2inf is the steady-state gain of
 * the second stage with Q2 = q_angle dt and R2 = r_angle (continuous-time approximation of the
 * loop; docs/kalman.md). Q30, |error| <= 1e-3 relative + 1 LSB. INC_ERR_NULL,
 * INC_ERR_INVAL (q_angle or r_angle < 1 or > KF_P_MAX, dt_ns 0 or > 10^9). */
int tilt_feedback_gain(int64_t q_angle, int64_t r_angle, uint32_t dt_ns, fx_q30_t *gain);

/* Set up. INC_ERR_NULL / INC_ERR_INVAL as tilt_config_check; on error every step is refused. */
int tilt_init(struct tilt *t, const struct tilt_config *cfg);

/* Forget the angles (the next accepted accelerometer sample restarts them) and the time; the
 * offsets are kept. */
void tilt_restart(struct tilt *t);

/* One sample, dt_ns after the previous one (ignored until the filter has started). Returns 0
 * and fills *out; INC_ERR_NULL; INC_ERR_STATE (not initialised); INC_ERR_INVAL (dt_ns == 0 after
 * the start: nothing changes, *out says valid = false). Rejections and restarts are not errors:
 * they are reported in out->flags. */
int tilt_step(struct tilt *t, const struct tilt_input *in, uint32_t dt_ns, struct tilt_output *out);

/* The same with a timestamp: dt = t_ns - the previous call's t_ns. A timestamp that does not
 * increase gives INC_ERR_INVAL (as dt == 0); a step of more than 2^32 - 1 ns counts as a gap. */
int tilt_step_at(struct tilt *t, const struct tilt_input *in, uint64_t t_ns,
                 struct tilt_output *out);

/* Accelerometer angles alone (no filter): roll = atan2(a_y, a_z), pitch = atan2(-a_x,
 * sqrt(a_y^2 + a_z^2)), Q16 deg from Q16 g, |error| <= 0.85 LSB (FORMATS). Any input is defined
 * (a = 0 gives 0, 0). roll_deg or pitch_deg may be NULL. */
void tilt_accel_angles(const fx_q16_t accel_g[3], fx_q16_t *roll_deg, fx_q16_t *pitch_deg);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_TILT_H */
