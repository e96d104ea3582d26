/*
 * sim/vehicle.h - deterministic vehicle scenarios with truth for attitude estimators (module
 * inclino_sim_vehicle, prefix veh_). docs/vehicle-scenarios.md describes the model.
 *
 * A scenario is a list of segments (driver commands: target speed, curvature, road grade and
 * bank, roughness, engine on/off) and road events (potholes, speed bumps, engine start). A
 * struct veh_sim turns it into samples at a fixed rate: the true attitude of an IMU mounted in
 * the car, its true angular rate and specific force, and what the sensors report (an
 * ADIS16405-class IMU, the ESC's wheel speed and yaw-rate sensor).
 *
 * Frames: earth = east-north-up; vehicle body = x forward, y left, z up; sensor = body rotated
 * by the mounting misalignment. Truth quaternion q (Hamilton, w first): v_earth = q v_sensor q^-1.
 * Attitude chain: q = Rz(yaw) Ry(-grade) Rx(bank) Rx(body roll) Ry(body pitch) mount, where a
 * positive rotation about y is nose DOWN (right hand, y left) and about x is right side down.
 *
 * All randomness comes from sim_rng streams derived from the seed: the same seed gives the same
 * samples on every host. Double precision (simulation code).
 */
#ifndef INCLINO_SIM_VEHICLE_H
#define INCLINO_SIM_VEHICLE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "inclino/sim/inertial.h"
#include "inclino/sim/noise.h"

#ifdef __cplusplus
extern "C" {
#endif

#define VEH_G 9.80665 /* m/s^2 per g */
#define VEH_RATE_ADIS 819.2
#define VEH_RATE_LOW 285.714
#define VEH_MAX_SEGMENTS 160u
#define VEH_MAX_EVENTS 64u
#define VEH_NAME_MAX 32u
#define VEH_REST_S 5.0 /* every scenario starts with this long at rest (movement = 0) */

/* One driver segment. Transitions start at the segment's beginning. */
struct veh_segment {
    double duration_s;
    double v_target_mps; /* signed speed target (negative: reversing) */
    double a_max_mps2;   /* acceleration magnitude used to reach it */
    double jerk_mps3;    /* taper near the target: |a| <= sqrt(2 jerk |dv|) */
    double kappa_1pm;    /* rear-axle path curvature target, 1/m (positive: turning left) */
    double kappa_ramp_s; /* raised-cosine transition time of kappa */
    double kappa_sine;   /* added kappa_sine * sin(2 pi t / duration) (lane changes) */
    double grade_pct;    /* road grade target, % (positive: uphill ahead) */
    double bank_deg;     /* road bank target, deg (positive: right side low) */
    double road_ramp_s;  /* raised-cosine transition time of grade and bank */
    double rough;        /* road roughness level (0 smooth, 1 rough, 2 very rough) */
    bool engine;         /* engine running */
    bool event;          /* the segment is the scenario's event: movement = 1 even at rest */
};

enum veh_event_kind {
    VEH_EV_POTHOLE_LEFT = 1, /* a pothole under the left wheels */
    VEH_EV_POTHOLE_RIGHT,
    VEH_EV_BUMP,        /* a speed bump across the lane */
    VEH_EV_ENGINE_START /* the rocking of the body when the engine cranks and fires */
};

struct veh_event {
    double t_s;      /* front axle reaches the feature (engine start: crank time) */
    int kind;        /* enum veh_event_kind */
    double height_m; /* depth of a pothole, height of a bump (positive) */
    double length_m; /* length along the road */
};

struct veh_scenario {
    char name[VEH_NAME_MAX];
    const char *summary;
    double heading_deg;                  /* initial heading: 0 = east, 90 = north */
    double temp0_c, temp1_c, temp_tau_s; /* die temperature from temp0 to temp1 over the run */
    size_t n_seg, n_ev;
    struct veh_segment seg[VEH_MAX_SEGMENTS];
    struct veh_event ev[VEH_MAX_EVENTS];
};

/* Number of presets, and preset i built into *sc (0 or INC_ERR_INVAL / INC_ERR_NULL). */
size_t veh_preset_count(void);
const char *veh_preset_name(size_t i);
const char *veh_preset_summary(size_t i);
int veh_preset_build(size_t i, struct veh_scenario *sc);
/* By name: 0, INC_ERR_NULL, or INC_ERR_INVAL for an unknown name. */
int veh_preset_by_name(const char *name, struct veh_scenario *sc);
/* Total duration of a scenario, s. */
double veh_scenario_duration(const struct veh_scenario *sc);

/* Vehicle and sensor configuration (veh_config_default fills the documented values). */
struct veh_config {
    double rate_hz; /* output rate, 10..10000 */
    uint64_t seed;
    bool sensor_errors;  /* false: every output is the truth, unquantised */
    double mount_deg[3]; /* mounting misalignment roll, pitch, yaw (deg), applied as
                                Rz(yaw) Ry(pitch) Rx(roll) after the body; |each| <= 10 */
    /* vehicle */
    double wheelbase_m, track_m, l_rear_m; /* geometry; l_rear = CG to rear axle */
    double sideslip_deg_per_g;             /* tyre-compliance sideslip gradient */
    double roll_grad_deg_per_g, pitch_grad_deg_per_g;
    double roll_hz, roll_zeta, pitch_hz, pitch_zeta, heave_hz, heave_zeta, wheel_hz, wheel_zeta;
    double accel_lag_s; /* brake/drive torque build-up time constant */
    /* IMU (ADIS16405 class) */
    double gyro_range_dps, accel_range_g, gyro_lsb_dps, accel_lsb_g, temp_lsb_c;
    double gyro_bias_sd_dps, gyro_tc_dps_per_c, gyro_white, gyro_bi, gyro_rrw, gyro_g_sens;
    double gyro_scale_sd;
    double accel_bias_sd_g, accel_tc_g_per_c, accel_white, accel_bi, accel_scale_sd;
    /* ESC signals */
    double wheel_update_hz, wheel_circ_m, wheel_teeth, wheel_scale_sd, wheel_tooth_sd;
    double wheel_min_mps, wheel_lsb_mps, slip_stiffness;
    double yaw_update_hz, yaw_bias_sd_dps, yaw_noise_dps, yaw_lsb_dps;
};
void veh_config_default(struct veh_config *cfg);

/* One output sample (measured values and the truth behind them). */
struct veh_sample {
    double t_s;
    double gyr_dps[3], acc_g[3]; /* what the IMU reports */
    double q[4];                 /* truth quaternion w, x, y, z (sensor to ENU) */
    int movement;                /* 1 while moving or during the scenario's event */
    double speed_mps;            /* wheel-speed based longitudinal speed (signed) */
    double yaw_rate_dps;         /* ESC yaw-rate sensor */
    double temp_c;               /* die temperature as reported */
    /* truth */
    double true_gyr_dps[3], true_acc_g[3]; /* sensor frame */
    double true_speed_mps;                 /* CG speed along its path (signed) */
    double true_yaw_rate_dps;              /* body z rate */
    double true_temp_c;
    double roll_deg, pitch_deg, yaw_deg;  /* ZYX Euler angles of q (pitch: nose down +) */
    double body_roll_deg, body_pitch_deg; /* suspension angles relative to the road */
    double grade_deg, bank_deg;           /* road */
    double road_f_g[3];   /* specific force in the road frame (no body angles, no vibration) */
    double path_acc_g[3]; /* kinematic acceleration of the path in the road frame */
    double pos_enu_m[3];  /* position of the path point (no heave) */
    double sideslip_deg, kappa_1pm;
};

/* Internal state of one second-order mode (Tustin integration). */
struct veh_osc {
    double x, v;
};

struct veh_sim {
    struct veh_scenario sc;
    struct veh_config cfg;
    double dt, duration;
    uint64_t k, n;
    /* driver */
    size_t seg;
    double seg_t0;
    double kap0, grade0, bank0; /* values at the start of the current segment */
    double v, a, s_odo, psi, kappa, beta, grade, bank;
    double r, beta_dot, grade_dot, bank_dot;
    double pos[3];
    double vel_e[3];
    /* suspension and road */
    struct veh_osc wheel[3], body[3]; /* 0 heave (m), 1 roll (rad), 2 pitch (rad) */
    double road_n[3], road_w[3], road_gain[3], road_z[3], road_zd[3];
    double ev_s0[VEH_MAX_EVENTS];
    bool ev_started[VEH_MAX_EVENTS];
    double fr[3];             /* road-frame specific force, m/s^2, of the current sample */
    double fbody[3];          /* forcing of the body modes at the current sample */
    double base[3], based[3]; /* event base excitation (wheel modes) at the current sample */
    double heave_acc;
    /* engine */
    double eng_amp, eng_phase, eng_omega;
    /* sensors */
    struct sim_rng rng_road, rng_esc;
    struct sim_noise noise;
    double gyro_scale[3], accel_scale[3], gyro_gs[3];
    double wheel_scale, tooth_err[128];
    double ws_dist;
    long ws_edge; /* index of the last edge passed (signed) */
    double ws_edge_t, ws_prev_edge_t;
    long ws_prev_edge;
    double ws_next_update, ws_out;
    int ws_dir;
    double yaw_bias, yaw_next_update, yaw_out;
    double last_move_t; /* last instant with nonzero speed */
};

/* Initialise a run of scenario *sc with *cfg (both copied). 0, INC_ERR_NULL, INC_ERR_INVAL. */
int veh_sim_init(struct veh_sim *s, const struct veh_scenario *sc, const struct veh_config *cfg);
/* Number of samples of the run. */
uint64_t veh_sim_samples(const struct veh_sim *s);
/* The next sample into *out: 1 when written, 0 at the end of the run. */
int veh_sim_next(struct veh_sim *s, struct veh_sample *out);

/* Quaternion helpers (w, x, y, z). */
void veh_quat_mul(const double a[4], const double b[4], double out[4]);
void veh_quat_rotate(const double q[4], const double v[3], double out[3]);            /* q v q^-1 */
void veh_quat_euler_zyx(const double q[4], double *roll, double *pitch, double *yaw); /* rad */

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_SIM_VEHICLE_H */
