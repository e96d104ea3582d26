/*
 * vehicle.c - the vehicle scenario generator (sim/vehicle.h, docs/vehicle-scenarios.md).
 *
 * Every state advances from sample k to k + 1 with the trapezoidal rule (Tustin for the linear
 * modes), and every rate the generator reports is the exact derivative its own state carries
 * (a = dv/dt, r = dpsi/dt, the oscillators' velocities): integrating the reported rates with the
 * trapezoidal rule reproduces the reported attitude.
 */
#include "inclino/sim/vehicle.h"

#include <math.h>
#include <string.h>

#include "inclino/error.h"

#define PI 3.14159265358979323846
#define DEG (PI / 180.0)

#define SIDESLIP_TAU_S 0.12 /* tyre relaxation of the sideslip angle */
#define NOISE_LP_HZ 40.0    /* road excitation bandwidth */
#define ROAD_HP_S 0.5       /* road profile high-pass (keeps the profile zero-mean) */
#define ROUGH_V_REF 13.9    /* m/s (50 km/h): roughness levels are stated at this speed */
#define ENG_IDLE_HZ 26.0    /* second engine order at 780 rpm (four cylinders) */
#define ENG_HZ_PER_MPS 2.2
#define ENG_MAX_HZ 95.0
#define ENG_TAU_S 0.3
#define ENG_ROLL_DEG 0.004 /* engine vibration amplitudes at the sensor */
#define ENG_PITCH_DEG 0.002
#define ENG_Z_G 0.03
#define ENG_Y_G 0.01
#define ENG_START_DEG 0.5 /* quasi-static roll of the crank torque pulse */
#define ENG_START_S 0.35
#define MOVE_HANGOVER_S 1.0

/* Road excitation gains per roughness level (road profile rate, unit/s rms per unit noise):
 * heave m/s, roll and pitch rad/s; tuned for the figures in docs/vehicle-scenarios.md. */
static const double ROAD_GAIN[3] = {0.18, 0.10, 0.05};

void veh_config_default(struct veh_config *c)
{
    memset(c, 0, sizeof(*c));
    c->rate_hz = VEH_RATE_ADIS;
    c->seed = 1;
    c->sensor_errors = true;
    c->wheelbase_m = 2.70;
    c->track_m = 1.55;
    c->l_rear_m = 1.40;
    c->sideslip_deg_per_g = 2.5;
    c->roll_grad_deg_per_g = 4.0;
    c->pitch_grad_deg_per_g = 2.0;
    c->roll_hz = 1.6;
    c->roll_zeta = 0.45;
    c->pitch_hz = 1.5;
    c->pitch_zeta = 0.45;
    c->heave_hz = 1.3;
    c->heave_zeta = 0.3;
    c->wheel_hz = 11.0;
    c->wheel_zeta = 0.15;
    c->accel_lag_s = 0.2;
    /* ADIS16405 class */
    c->gyro_range_dps = 300.0;
    c->accel_range_g = 18.0;
    c->gyro_lsb_dps = 0.05;
    c->accel_lsb_g = 0.00333;
    c->temp_lsb_c = 0.14;
    c->gyro_bias_sd_dps = 0.3;
    c->gyro_tc_dps_per_c = 0.01;
    c->gyro_white = 0.05 / 1.41421356237; /* Allan N for a 0.05 deg/s/sqrt(Hz) density */
    c->gyro_bi = 0.007;
    c->gyro_rrw = SIM_NOISE_ADIS_GYRO_RRW;
    c->gyro_g_sens = 0.05;
    c->gyro_scale_sd = 0.003;
    c->accel_bias_sd_g = 0.005;
    c->accel_tc_g_per_c = 0.0001;
    c->accel_white = 0.0005 / 1.41421356237;
    c->accel_bi = 0.0002;
    c->accel_scale_sd = 0.002;
    /* ESC */
    c->wheel_update_hz = 50.0;
    c->wheel_circ_m = 1.95;
    c->wheel_teeth = 48.0;
    c->wheel_scale_sd = 0.005;
    c->wheel_tooth_sd = 0.003;
    c->wheel_min_mps = 0.1;
    c->wheel_lsb_mps = 0.01 / 3.6;
    c->slip_stiffness = 20.0;
    c->yaw_update_hz = 100.0;
    c->yaw_bias_sd_dps = 0.2;
    c->yaw_noise_dps = 0.1;
    c->yaw_lsb_dps = 0.01;
}

/* ---- quaternions --------------------------------------------------------------------------- */

void veh_quat_mul(const double a[4], const double b[4], double o[4])
{
    double w = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
    double x = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
    double y = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
    double z = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
    o[0] = w;
    o[1] = x;
    o[2] = y;
    o[3] = z;
}

void veh_quat_rotate(const double q[4], const double v[3], double o[3])
{
    /* v' = v + 2 w (u x v) + 2 u x (u x v), u = vector part */
    double ux = q[1], uy = q[2], uz = q[3], w = q[0];
    double tx = 2.0 * (uy * v[2] - uz * v[1]);
    double ty = 2.0 * (uz * v[0] - ux * v[2]);
    double tz = 2.0 * (ux * v[1] - uy * v[0]);
    o[0] = v[0] + w * tx + (uy * tz - uz * ty);
    o[1] = v[1] + w * ty + (uz * tx - ux * tz);
    o[2] = v[2] + w * tz + (ux * ty - uy * tx);
}

static void quat_rotate_inv(const double q[4], const double v[3], double o[3])
{
    double c[4] = {q[0], -q[1], -q[2], -q[3]};
    veh_quat_rotate(c, v, o);
}

void veh_quat_euler_zyx(const double q[4], double *roll, double *pitch, double *yaw)
{
    double s = 2.0 * (q[0] * q[2] - q[3] * q[1]);
    if (s > 1.0) s = 1.0;
    if (s < -1.0) s = -1.0;
    *roll = atan2(2.0 * (q[0] * q[1] + q[2] * q[3]), 1.0 - 2.0 * (q[1] * q[1] + q[2] * q[2]));
    *pitch = asin(s);
    *yaw = atan2(2.0 * (q[0] * q[3] + q[1] * q[2]), 1.0 - 2.0 * (q[2] * q[2] + q[3] * q[3]));
}

static void quat_axis(int axis, double angle, double q[4])
{
    q[0] = cos(0.5 * angle);
    q[1] = q[2] = q[3] = 0.0;
    q[1 + axis] = sin(0.5 * angle);
}

/*
 * q = q_0 q_1 ... q_{n-1}, each an elementary rotation about body axis axes[i] by ang[i] with
 * rate rate[i]; *w gets the angular rate of the last frame in its own coordinates:
 * w = sum_i R(q_{i+1} ... q_{n-1})^T e_i rate_i.
 */
static void chain(const int *axes, const double *ang, const double *rate, int n, double q[4],
                  double w[3])
{
    double tail[4] = {1.0, 0.0, 0.0, 0.0};
    int i;
    w[0] = w[1] = w[2] = 0.0;
    for (i = n - 1; i >= 0; i--) {
        double e[3] = {0.0, 0.0, 0.0}, er[3], qi[4], t[4];
        e[axes[i]] = rate[i];
        quat_rotate_inv(tail, e, er);
        w[0] += er[0];
        w[1] += er[1];
        w[2] += er[2];
        quat_axis(axes[i], ang[i], qi);
        veh_quat_mul(qi, tail, t);
        memcpy(tail, t, sizeof(t));
    }
    memcpy(q, tail, sizeof(tail));
}

/* ---- small pieces -------------------------------------------------------------------------- */

static double smooth(double x) /* raised cosine 0 -> 1 on [0, 1] */
{
    if (x <= 0.0) return 0.0;
    if (x >= 1.0) return 1.0;
    return 0.5 * (1.0 - cos(PI * x));
}

static double smooth_d(double x) /* its derivative */
{
    if (x <= 0.0 || x >= 1.0) return 0.0;
    return 0.5 * PI * sin(PI * x);
}

/*
 * One Tustin step of x'' = w^2 (b - x) + 2 z w (b' - x') + f, with the inputs u = w^2 b +
 * 2 z w b' + f at the old (u0) and new (u1) instant.
 */
static void osc_step(struct veh_osc *o, double hz, double zeta, double u0, double u1, double dt)
{
    double w = 2.0 * PI * hz, h = 0.5 * dt;
    double det = 1.0 + 2.0 * h * zeta * w + h * h * w * w;
    double px = o->x + h * o->v;
    double pv = -h * w * w * o->x + (1.0 - 2.0 * h * zeta * w) * o->v + h * (u0 + u1);
    o->x = ((1.0 + 2.0 * h * zeta * w) * px + h * pv) / det;
    o->v = (-h * w * w * px + pv) / det;
}

static double osc_input(double hz, double zeta, double b, double bd, double f)
{
    double w = 2.0 * PI * hz;
    return w * w * b + 2.0 * zeta * w * bd + f;
}

static double osc_acc(const struct veh_osc *o, double hz, double zeta, double u)
{
    double w = 2.0 * PI * hz;
    return u - w * w * o->x - 2.0 * zeta * w * o->v;
}

static double quantise(double v, double lsb)
{
    return lsb > 0.0 ? floor(v / lsb + 0.5) * lsb : v;
}

static double clampd(double v, double lim)
{
    return v > lim ? lim : (v < -lim ? -lim : v);
}

/* ---- driver -------------------------------------------------------------------------------- */

double veh_scenario_duration(const struct veh_scenario *sc)
{
    double d = 0.0;
    size_t i;
    for (i = 0; i < sc->n_seg; i++) {
        d += sc->seg[i].duration_s;
    }
    return d;
}

static const struct veh_segment *cur_seg(const struct veh_sim *s)
{
    return &s->sc.seg[s->seg];
}

/* Advance the segment index to the one containing time t (recording start values). */
static void seg_at(struct veh_sim *s, double t)
{
    while (s->seg + 1 < s->sc.n_seg && t >= s->seg_t0 + s->sc.seg[s->seg].duration_s - 1e-12) {
        s->seg_t0 += s->sc.seg[s->seg].duration_s;
        s->seg++;
        s->kap0 = s->kappa;
        s->grade0 = s->grade;
        s->bank0 = s->bank;
    }
}

/* Curvature, grade and bank (with rates) commanded at time t in the current segment. */
static void road_cmd(struct veh_sim *s, double t)
{
    const struct veh_segment *g = cur_seg(s);
    double tau = t - s->seg_t0;
    double x, g1 = atan(g->grade_pct / 100.0), b1 = g->bank_deg * DEG;
    x = g->kappa_ramp_s > 0.0 ? tau / g->kappa_ramp_s : 1.0;
    s->kappa = s->kap0 + (g->kappa_1pm - s->kap0) * smooth(x);
    if (g->kappa_sine != 0.0 && g->duration_s > 0.0) {
        s->kappa += g->kappa_sine * sin(2.0 * PI * tau / g->duration_s);
    }
    if (g->road_ramp_s > 0.0) {
        x = tau / g->road_ramp_s;
        s->grade = s->grade0 + (g1 - s->grade0) * smooth(x);
        s->bank = s->bank0 + (b1 - s->bank0) * smooth(x);
        s->grade_dot = (g1 - s->grade0) * smooth_d(x) / g->road_ramp_s;
        s->bank_dot = (b1 - s->bank0) * smooth_d(x) / g->road_ramp_s;
    } else {
        s->grade = g1;
        s->bank = b1;
        s->grade_dot = s->bank_dot = 0.0;
    }
}

static double beta_target(const struct veh_sim *s)
{
    return atan(s->cfg.l_rear_m * s->kappa) -
           s->cfg.sideslip_deg_per_g * DEG * s->v * s->v * s->kappa / VEH_G;
}

/*
 * Road frame (heading, grade, bank): its quaternion, its rate in its own axes, the path
 * acceleration in road axes and gravity's specific force in road axes (m/s^2).
 */
static void road_frame(const struct veh_sim *s, double qr[4], double wr[3], double ar[3],
                       double gr[3])
{
    static const int axes[3] = {2, 1, 0};
    double ang[3] = {s->psi, -s->grade, s->bank};
    double rate[3] = {s->r, -s->grade_dot, s->bank_dot};
    double cb = cos(s->beta), sb = sin(s->beta);
    const double vr[3] = {s->v * cb, s->v * sb, 0.0};
    const double vd[3] = {s->a * cb - s->v * sb * s->beta_dot, s->a * sb + s->v * cb * s->beta_dot,
                          0.0};
    double up[3] = {0.0, 0.0, VEH_G};
    chain(axes, ang, rate, 3, qr, wr);
    ar[0] = vd[0] + wr[1] * vr[2] - wr[2] * vr[1];
    ar[1] = vd[1] + wr[2] * vr[0] - wr[0] * vr[2];
    ar[2] = vd[2] + wr[0] * vr[1] - wr[1] * vr[0];
    quat_rotate_inv(qr, up, gr);
}

/* Base excitation of the three modes by the road events at the current odometer. */
static void event_profile(double x, const struct veh_event *e, double *z, double *dz)
{
    double L = e->length_m;
    *z = *dz = 0.0;
    if (x < 0.0 || x > L || L <= 0.0) return;
    if (e->kind == VEH_EV_BUMP) {
        *z = e->height_m * 0.5 * (1.0 - cos(2.0 * PI * x / L));
        *dz = e->height_m * PI / L * sin(2.0 * PI * x / L);
    } else {
        double edge = L / 4.0 < 0.06 ? L / 4.0 : 0.06;
        if (x < edge) {
            *z = -e->height_m * smooth(x / edge);
            *dz = -e->height_m * smooth_d(x / edge) / edge;
        } else if (x > L - edge) {
            *z = -e->height_m * smooth((L - x) / edge);
            *dz = e->height_m * smooth_d((L - x) / edge) / edge;
        } else {
            *z = -e->height_m;
        }
    }
}

static void events_base(struct veh_sim *s, double t)
{
    size_t i;
    double L = s->cfg.wheelbase_m, T = s->cfg.track_m;
    s->base[0] = s->base[1] = s->base[2] = 0.0;
    s->based[0] = s->based[1] = s->based[2] = 0.0;
    for (i = 0; i < s->sc.n_ev; i++) {
        const struct veh_event *e = &s->sc.ev[i];
        double zf, dzf, zr, dzr, xf;
        double left, right;
        if (e->kind == VEH_EV_ENGINE_START || t < e->t_s) continue;
        if (!s->ev_started[i]) {
            s->ev_started[i] = true;
            s->ev_s0[i] = s->s_odo;
        }
        xf = s->s_odo - s->ev_s0[i];
        event_profile(xf, e, &zf, &dzf);
        event_profile(xf - L, e, &zr, &dzr);
        /* z' = dz/dx * |v| (the odometer grows with |v|) */
        dzf *= fabs(s->v);
        dzr *= fabs(s->v);
        left = e->kind == VEH_EV_POTHOLE_RIGHT ? 0.0 : 1.0;
        right = e->kind == VEH_EV_POTHOLE_LEFT ? 0.0 : 1.0;
        /* wheels fl, fr, rl, rr = zf*left, zf*right, zr*left, zr*right */
        s->base[0] += (left + right) * (zf + zr) / 4.0;
        s->based[0] += (left + right) * (dzf + dzr) / 4.0;
        s->base[1] += (left - right) * (zf + zr) / (2.0 * T);
        s->based[1] += (left - right) * (dzf + dzr) / (2.0 * T);
        s->base[2] += (left + right) * (zr - zf) / (2.0 * L);
        s->based[2] += (left + right) * (dzr - dzf) / (2.0 * L);
    }
}

static double engine_start_force(const struct veh_sim *s, double t)
{
    size_t i;
    double f = 0.0, w = 2.0 * PI * s->cfg.roll_hz;
    for (i = 0; i < s->sc.n_ev; i++) {
        const struct veh_event *e = &s->sc.ev[i];
        if (e->kind == VEH_EV_ENGINE_START && t >= e->t_s && t < e->t_s + ENG_START_S) {
            f += w * w * ENG_START_DEG * DEG * sin(PI * (t - e->t_s) / ENG_START_S);
        }
    }
    return f;
}

static bool event_active(const struct veh_sim *s, double t)
{
    size_t i;
    for (i = 0; i < s->sc.n_ev; i++) {
        const struct veh_event *e = &s->sc.ev[i];
        if (t >= e->t_s && t < e->t_s + 2.0) return true;
    }
    return false;
}

/* Body-mode forcing (suspension response to the road-frame specific force, crank torque). */
static void body_forcing(struct veh_sim *s, double t)
{
    double wr = 2.0 * PI * s->cfg.roll_hz, wp = 2.0 * PI * s->cfg.pitch_hz;
    s->fbody[0] = 0.0;
    s->fbody[1] = wr * wr * s->cfg.roll_grad_deg_per_g * DEG * s->fr[1] / VEH_G +
                  engine_start_force(s, t);
    s->fbody[2] = -wp * wp * s->cfg.pitch_grad_deg_per_g * DEG * s->fr[0] / VEH_G;
}

static void update_fr(struct veh_sim *s)
{
    double qr[4], wr[3], ar[3], gr[3];
    road_frame(s, qr, wr, ar, gr);
    s->fr[0] = ar[0] + gr[0];
    s->fr[1] = ar[1] + gr[1];
    s->fr[2] = ar[2] + gr[2];
}

static void mode_params(const struct veh_sim *s, int m, double *hz, double *zeta)
{
    if (m == 0) {
        *hz = s->cfg.heave_hz;
        *zeta = s->cfg.heave_zeta;
    } else if (m == 1) {
        *hz = s->cfg.roll_hz;
        *zeta = s->cfg.roll_zeta;
    } else {
        *hz = s->cfg.pitch_hz;
        *zeta = s->cfg.pitch_zeta;
    }
}

static double temp_at(const struct veh_sim *s, double t)
{
    double tau = s->sc.temp_tau_s > 0.0 ? s->sc.temp_tau_s : 1e9;
    double den = 1.0 - exp(-s->duration / tau);
    double x = den > 0.0 ? (1.0 - exp(-t / tau)) / den : 0.0;
    return s->sc.temp0_c + (s->sc.temp1_c - s->sc.temp0_c) * x;
}

/* ---- init ---------------------------------------------------------------------------------- */

static int check_cfg(const struct veh_config *c)
{
    int i;
    if (!(c->rate_hz >= 10.0 && c->rate_hz <= 10000.0)) return -1;
    for (i = 0; i < 3; i++) {
        if (!(fabs(c->mount_deg[i]) <= 10.0)) return -1;
    }
    if (!(c->wheelbase_m > 0.5 && c->track_m > 0.5 && c->l_rear_m > 0.0)) return -1;
    if (!(c->roll_hz > 0.0 && c->pitch_hz > 0.0 && c->heave_hz > 0.0 && c->wheel_hz > 0.0))
        return -1;
    if (!(c->accel_lag_s > 0.0 && c->wheel_update_hz > 0.0 && c->yaw_update_hz > 0.0)) return -1;
    if (!(c->wheel_teeth >= 4.0 && c->wheel_teeth <= 128.0 && c->wheel_circ_m > 0.5)) return -1;
    return 0;
}

int veh_sim_init(struct veh_sim *s, const struct veh_scenario *sc, const struct veh_config *cfg)
{
    struct sim_noise_cfg nc;
    struct sim_rng par;
    int i;
    if (s == NULL || sc == NULL || cfg == NULL) return INC_ERR_NULL;
    memset(s, 0, sizeof(*s));
    if (sc->n_seg == 0 || sc->n_seg > VEH_MAX_SEGMENTS || sc->n_ev > VEH_MAX_EVENTS ||
        check_cfg(cfg) != 0) {
        return INC_ERR_INVAL;
    }
    s->sc = *sc;
    s->cfg = *cfg;
    s->dt = 1.0 / cfg->rate_hz;
    s->duration = veh_scenario_duration(sc);
    if (!(s->duration > 0.0)) return INC_ERR_INVAL;
    s->n = (uint64_t)ceil(s->duration * cfg->rate_hz - 1e-9);
    s->psi = sc->heading_deg * DEG;
    s->grade0 = s->grade = atan(sc->seg[0].grade_pct / 100.0);
    s->bank0 = s->bank = sc->seg[0].bank_deg * DEG;
    s->kap0 = s->kappa = sc->seg[0].kappa_1pm;
    road_cmd(s, 0.0);
    update_fr(s);
    body_forcing(s, 0.0);
    for (i = 0; i < 3; i++) {
        double hz, zeta, w;
        mode_params(s, i, &hz, &zeta);
        w = 2.0 * PI * hz;
        s->body[i].x = s->fbody[i] / (w * w);
    }
    s->eng_amp = sc->seg[0].engine ? 1.0 : 0.0;
    s->eng_omega = 2.0 * PI * ENG_IDLE_HZ;
    /* random streams */
    sim_rng_seed(&par, cfg->seed * 4u + 1u);
    sim_rng_seed(&s->rng_road, cfg->seed * 4u + 2u);
    sim_rng_seed(&s->rng_esc, cfg->seed * 4u + 3u);
    memset(&nc, 0, sizeof(nc));
    nc.seed = cfg->seed * 4u + 4u;
    for (i = 0; i < 3; i++) {
        struct sim_noise_axis *g = &nc.ch[SIM_NOISE_GYRO(i)], *a = &nc.ch[SIM_NOISE_ACCEL(i)];
        g->bias = cfg->gyro_bias_sd_dps * sim_rng_gauss(&par);
        g->temp_coeff = cfg->gyro_tc_dps_per_c * (2.0 * sim_rng_uniform(&par) - 1.0);
        g->white = cfg->gyro_white;
        g->bias_instability = cfg->gyro_bi;
        g->bi_tc_min_s = SIM_NOISE_ADIS_GYRO_TC_MIN;
        g->bi_tc_max_s = SIM_NOISE_ADIS_GYRO_TC_MAX;
        g->rrw = cfg->gyro_rrw;
        a->bias = cfg->accel_bias_sd_g * sim_rng_gauss(&par);
        a->temp_coeff = cfg->accel_tc_g_per_c * (2.0 * sim_rng_uniform(&par) - 1.0);
        a->white = cfg->accel_white;
        a->bias_instability = cfg->accel_bi;
        a->bi_tc_min_s = SIM_NOISE_ADIS_GYRO_TC_MIN;
        a->bi_tc_max_s = SIM_NOISE_ADIS_GYRO_TC_MAX;
        s->gyro_scale[i] = cfg->gyro_scale_sd * sim_rng_gauss(&par);
        s->accel_scale[i] = cfg->accel_scale_sd * sim_rng_gauss(&par);
        s->gyro_gs[i] = cfg->gyro_g_sens * (2.0 * sim_rng_uniform(&par) - 1.0);
    }
    if (sim_noise_init(&s->noise, &nc) != INC_OK) return INC_ERR_INVAL;
    s->wheel_scale = cfg->wheel_scale_sd * sim_rng_gauss(&par);
    for (i = 0; i < (int)cfg->wheel_teeth; i++) {
        s->tooth_err[i] = cfg->wheel_tooth_sd * sim_rng_gauss(&par);
    }
    s->yaw_bias = cfg->yaw_bias_sd_dps * sim_rng_gauss(&par);
    /* between edge 0 and edge 1 */
    s->ws_dist = 0.5 * cfg->wheel_circ_m / cfg->wheel_teeth;
    s->ws_edge = 0;
    s->ws_prev_edge = 0;
    s->ws_edge_t = s->ws_prev_edge_t = -1.0;
    s->ws_next_update = 0.0;
    s->yaw_next_update = 0.0;
    return INC_OK;
}

uint64_t veh_sim_samples(const struct veh_sim *s)
{
    return s->n;
}

/* ---- advance ------------------------------------------------------------------------------- */

static double edge_pos(const struct veh_sim *s, long i)
{
    double p = s->cfg.wheel_circ_m / s->cfg.wheel_teeth;
    long nt = (long)s->cfg.wheel_teeth;
    long m = ((i % nt) + nt) % nt;
    return ((double)i + s->tooth_err[m]) * p;
}

static void wheel_edges(struct veh_sim *s, double d0, double d1, double t0)
{
    if (d1 == d0) return;
    while (d1 >= edge_pos(s, s->ws_edge + 1)) {
        s->ws_edge++;
        s->ws_edge_t = t0 + (edge_pos(s, s->ws_edge) - d0) / (d1 - d0) * s->dt;
    }
    while (d1 < edge_pos(s, s->ws_edge)) {
        s->ws_edge_t = t0 + (edge_pos(s, s->ws_edge) - d0) / (d1 - d0) * s->dt;
        s->ws_edge--;
    }
}

static double wheel_speed_true(const struct veh_sim *s)
{
    double vx = s->v * cos(s->beta);
    double slip = s->a < 0.0 ? s->a / (s->cfg.slip_stiffness * VEH_G) : 0.0;
    return vx * (1.0 + s->wheel_scale) * (1.0 + slip);
}

static void advance(struct veh_sim *s)
{
    const struct veh_segment *g;
    double t0 = (double)s->k * s->dt, t1 = (double)(s->k + 1) * s->dt;
    double dt = s->dt, h = 0.5 * dt;
    double v0 = s->v, a0 = s->a, r0 = s->r, bt0 = beta_target(s), bt1, dv, acmd, e;
    double u_w0[3], u_b0[3], n0[3], vw0, d0;
    double qr[4], wr[3], ar[3], gr[3], ve0[3], ve1[3], vr[3];
    double amp0 = s->eng_amp, om0 = s->eng_omega, eamp_t, wc;
    int m;

    /* inputs at the old instant */
    for (m = 0; m < 3; m++) {
        double hz, zeta;
        mode_params(s, m, &hz, &zeta);
        u_w0[m] = osc_input(s->cfg.wheel_hz, s->cfg.wheel_zeta, s->road_z[m] + s->base[m],
                            s->road_zd[m] + s->based[m], 0.0);
        u_b0[m] = osc_input(hz, zeta, s->wheel[m].x, s->wheel[m].v, s->fbody[m]);
        n0[m] = s->road_n[m];
    }
    road_frame(s, qr, wr, ar, gr);
    vr[0] = s->v * cos(s->beta);
    vr[1] = s->v * sin(s->beta);
    vr[2] = 0.0;
    veh_quat_rotate(qr, vr, ve0);
    vw0 = wheel_speed_true(s);
    d0 = s->ws_dist;

    seg_at(s, t1);
    g = cur_seg(s);

    /* longitudinal: speed target through a jerk taper and the torque lag */
    dv = g->v_target_mps - v0;
    acmd = 0.0;
    if (dv != 0.0) {
        double lim = g->jerk_mps3 > 0.0 ? sqrt(2.0 * g->jerk_mps3 * fabs(dv)) : g->a_max_mps2;
        acmd = (dv > 0.0 ? 1.0 : -1.0) * (lim < g->a_max_mps2 ? lim : g->a_max_mps2);
    }
    e = exp(-dt / s->cfg.accel_lag_s);
    s->a = acmd + (a0 - acmd) * e;
    s->v = v0 + h * (a0 + s->a);
    if (g->v_target_mps == 0.0 && (v0 == 0.0 || v0 * s->v <= 0.0)) {
        s->v = 0.0; /* stopped: the brakes hold */
        s->a = 0.0;
    }
    s->s_odo += h * (fabs(v0) + fabs(s->v));

    /* road and path at t1 */
    road_cmd(s, t1);
    bt1 = beta_target(s);
    {
        double q = h / SIDESLIP_TAU_S;
        s->beta = ((1.0 - q) * s->beta + q * (bt0 + bt1)) / (1.0 + q);
        s->beta_dot = (bt1 - s->beta) / SIDESLIP_TAU_S;
    }
    s->r = s->v * cos(s->beta) * s->kappa;
    s->psi += h * (r0 + s->r);
    road_frame(s, qr, wr, ar, gr);
    vr[0] = s->v * cos(s->beta);
    vr[1] = s->v * sin(s->beta);
    veh_quat_rotate(qr, vr, ve1);
    for (m = 0; m < 3; m++) {
        s->pos[m] += h * (ve0[m] + ve1[m]);
    }
    s->fr[0] = ar[0] + gr[0];
    s->fr[1] = ar[1] + gr[1];
    s->fr[2] = ar[2] + gr[2];
    body_forcing(s, t1);
    events_base(s, t1);

    /* road roughness: low-passed white noise n -> road profile rate z' = gain n - z / tau_hp,
     * gain growing with sqrt(speed) (a spatially white profile rate seen at speed v) */
    wc = 2.0 * PI * NOISE_LP_HZ;
    {
        double sig = sqrt(2.0 / (wc * dt)), q = h * wc, qh = h / ROAD_HP_S;
        double lvl = g->rough * sqrt(fabs(s->v) / ROUGH_V_REF);
        for (m = 0; m < 3; m++) {
            double w1 = sim_rng_gauss(&s->rng_road) * sig;
            double n1 = ((1.0 - q) * n0[m] + q * (s->road_w[m] + w1)) / (1.0 + q);
            double gain1 = ROAD_GAIN[m] * lvl;
            s->road_z[m] = ((1.0 - qh) * s->road_z[m] +
                            h * (s->road_gain[m] * n0[m] + gain1 * n1)) /
                           (1.0 + qh);
            s->road_zd[m] = gain1 * n1 - s->road_z[m] / ROAD_HP_S;
            s->road_n[m] = n1;
            s->road_w[m] = w1;
            s->road_gain[m] = gain1;
        }
    }

    /* suspension: wheel modes (base = road + events), then body modes (base = wheel) */
    for (m = 0; m < 3; m++) {
        double hz, zeta, u1;
        mode_params(s, m, &hz, &zeta);
        u1 = osc_input(s->cfg.wheel_hz, s->cfg.wheel_zeta, s->road_z[m] + s->base[m],
                       s->road_zd[m] + s->based[m], 0.0);
        osc_step(&s->wheel[m], s->cfg.wheel_hz, s->cfg.wheel_zeta, u_w0[m], u1, dt);
        u1 = osc_input(hz, zeta, s->wheel[m].x, s->wheel[m].v, s->fbody[m]);
        osc_step(&s->body[m], hz, zeta, u_b0[m], u1, dt);
    }

    /* engine */
    eamp_t = g->engine ? 1.0 : 0.0;
    s->eng_amp = eamp_t + (amp0 - eamp_t) * exp(-dt / ENG_TAU_S);
    {
        double f = ENG_IDLE_HZ + ENG_HZ_PER_MPS * fabs(s->v);
        s->eng_omega = 2.0 * PI * (f < ENG_MAX_HZ ? f : ENG_MAX_HZ);
    }
    s->eng_phase += h * (om0 + s->eng_omega);
    if (s->eng_phase > 2.0e4 * PI) s->eng_phase -= 2.0e4 * PI;

    /* wheel travel for the wheel-speed sensor */
    s->ws_dist += h * (vw0 + wheel_speed_true(s));
    wheel_edges(s, d0, s->ws_dist, t0);
    s->k++;
}

/* ---- output -------------------------------------------------------------------------------- */

static void esc_signals(struct veh_sim *s, double t, double true_yaw_dps, struct veh_sample *o)
{
    const struct veh_config *c = &s->cfg;
    double p = c->wheel_circ_m / c->wheel_teeth;
    if (!c->sensor_errors) {
        o->speed_mps = s->v * cos(s->beta);
        o->yaw_rate_dps = true_yaw_dps;
        return;
    }
    if (t >= s->ws_next_update - 1e-12) {
        long dn = s->ws_edge - s->ws_prev_edge;
        double v = 0.0;
        if (dn != 0 && s->ws_prev_edge_t >= 0.0 && s->ws_edge_t > s->ws_prev_edge_t) {
            v = (double)dn * p / (s->ws_edge_t - s->ws_prev_edge_t);
        } else if (dn == 0 && s->ws_edge_t >= 0.0 && t > s->ws_edge_t) {
            double lim = p / (t - s->ws_edge_t);
            v = fabs(s->ws_out) < lim ? s->ws_out : (s->ws_out < 0.0 ? -lim : lim);
        }
        if (fabs(v) < c->wheel_min_mps) v = 0.0;
        if (dn != 0) {
            s->ws_prev_edge = s->ws_edge;
            s->ws_prev_edge_t = s->ws_edge_t;
        }
        if (s->ws_prev_edge_t < 0.0 && s->ws_edge_t >= 0.0) {
            s->ws_prev_edge = s->ws_edge;
            s->ws_prev_edge_t = s->ws_edge_t;
        }
        s->ws_out = quantise(v, c->wheel_lsb_mps);
        s->ws_next_update += 1.0 / c->wheel_update_hz;
    }
    if (t >= s->yaw_next_update - 1e-12) {
        double y = true_yaw_dps + s->yaw_bias + c->yaw_noise_dps * sim_rng_gauss(&s->rng_esc);
        s->yaw_out = quantise(y, c->yaw_lsb_dps);
        s->yaw_next_update += 1.0 / c->yaw_update_hz;
    }
    o->speed_mps = s->ws_out;
    o->yaw_rate_dps = s->yaw_out;
}

int veh_sim_next(struct veh_sim *s, struct veh_sample *o)
{
    static const int axes[6] = {2, 1, 0, 0, 1, 0};
    const struct veh_config *c;
    const struct veh_segment *g;
    double t, qr[4], wr[3], ar[3], gr[3];
    double ang[6], rate[6], qb[4], wb[3], qm[4], qz[4], qy[4], qx[4], tmp[4];
    double eroll, epitch, eroll_d, epitch_d, amp_d, sph, cph, f_r[3], f_b[3], u;
    double hz, zeta;
    int i;
    if (s == NULL || o == NULL || s->k >= s->n) return 0;
    c = &s->cfg;
    memset(o, 0, sizeof(*o));
    t = (double)s->k * s->dt;
    g = cur_seg(s);
    o->t_s = t;

    /* engine vibration angles and their exact rates */
    amp_d = ((g->engine ? 1.0 : 0.0) - s->eng_amp) / ENG_TAU_S;
    sph = sin(s->eng_phase);
    cph = cos(s->eng_phase);
    eroll = s->eng_amp * ENG_ROLL_DEG * DEG * sph;
    eroll_d = ENG_ROLL_DEG * DEG * (amp_d * sph + s->eng_amp * s->eng_omega * cph);
    epitch = s->eng_amp * ENG_PITCH_DEG * DEG * sin(s->eng_phase + 0.7);
    epitch_d = ENG_PITCH_DEG * DEG *
               (amp_d * sin(s->eng_phase + 0.7) +
                s->eng_amp * s->eng_omega * cos(s->eng_phase + 0.7));

    /* the attitude chain: road (yaw, grade, bank), body (roll, pitch), mount */
    ang[0] = s->psi;
    rate[0] = s->r;
    ang[1] = -s->grade;
    rate[1] = -s->grade_dot;
    ang[2] = s->bank;
    rate[2] = s->bank_dot;
    ang[3] = s->body[1].x + eroll;
    rate[3] = s->body[1].v + eroll_d;
    ang[4] = s->body[2].x + epitch;
    rate[4] = s->body[2].v + epitch_d;
    ang[5] = 0.0;
    rate[5] = 0.0;
    chain(axes, ang, rate, 5, qb, wb); /* vehicle body */
    quat_axis(2, c->mount_deg[2] * DEG, qz);
    quat_axis(1, c->mount_deg[1] * DEG, qy);
    quat_axis(0, c->mount_deg[0] * DEG, qx);
    veh_quat_mul(qz, qy, tmp);
    veh_quat_mul(tmp, qx, qm);
    veh_quat_mul(qb, qm, o->q);

    /* specific force: path acceleration + heave + engine, minus gravity, in body axes */
    road_frame(s, qr, wr, ar, gr);
    mode_params(s, 0, &hz, &zeta);
    u = osc_input(hz, zeta, s->wheel[0].x, s->wheel[0].v, s->fbody[0]);
    s->heave_acc = osc_acc(&s->body[0], hz, zeta, u);
    f_r[0] = ar[0] + gr[0];
    f_r[1] = ar[1] + gr[1] + s->eng_amp * ENG_Y_G * VEH_G * sin(s->eng_phase + 2.1);
    f_r[2] = ar[2] + gr[2] + s->heave_acc + s->eng_amp * ENG_Z_G * VEH_G * sin(s->eng_phase + 1.3);
    {
        double qrel[4], qrc[4] = {qr[0], -qr[1], -qr[2], -qr[3]}, qs_rel[4];
        veh_quat_mul(qrc, qb, qrel); /* body relative to road */
        veh_quat_mul(qrel, qm, qs_rel);
        quat_rotate_inv(qs_rel, f_r, f_b);
    }
    {
        double wsens[3];
        quat_rotate_inv(qm, wb, wsens);
        for (i = 0; i < 3; i++) {
            o->true_gyr_dps[i] = wsens[i] / DEG;
            o->true_acc_g[i] = f_b[i] / VEH_G;
            o->road_f_g[i] = (ar[i] + gr[i]) / VEH_G;
            o->path_acc_g[i] = ar[i] / VEH_G;
            o->pos_enu_m[i] = s->pos[i];
        }
    }
    o->true_yaw_rate_dps = wb[2] / DEG;
    o->true_speed_mps = s->v * cos(s->beta);
    o->true_temp_c = temp_at(s, t);
    {
        double rr, pp, yy;
        veh_quat_euler_zyx(o->q, &rr, &pp, &yy);
        o->roll_deg = rr / DEG;
        o->pitch_deg = pp / DEG;
        o->yaw_deg = yy / DEG;
    }
    o->body_roll_deg = s->body[1].x / DEG;
    o->body_pitch_deg = s->body[2].x / DEG;
    o->grade_deg = s->grade / DEG;
    o->bank_deg = s->bank / DEG;
    o->sideslip_deg = s->beta / DEG;
    o->kappa_1pm = s->kappa;

    /* movement flag */
    if (s->v != 0.0) s->last_move_t = t;
    o->movement = (s->v != 0.0 || g->event || event_active(s, t) ||
                   (s->last_move_t > 0.0 && t - s->last_move_t < MOVE_HANGOVER_S))
                      ? 1
                      : 0;
    if (t < VEH_REST_S) o->movement = 0;

    /* sensors */
    if (c->sensor_errors) {
        struct sim_inertial_input in, out;
        memset(&in, 0, sizeof(in));
        for (i = 0; i < 3; i++) {
            in.rate_dps[i] = o->true_gyr_dps[i] * (1.0 + s->gyro_scale[i]) +
                             s->gyro_gs[i] * o->true_acc_g[i];
            in.accel_g[i] = o->true_acc_g[i] * (1.0 + s->accel_scale[i]);
        }
        in.temp_c = o->true_temp_c;
        in.supply_v = 5.0;
        sim_noise_apply(&s->noise, &in, &out, 0, s->dt);
        for (i = 0; i < 3; i++) {
            o->gyr_dps[i] = quantise(clampd(out.rate_dps[i], c->gyro_range_dps), c->gyro_lsb_dps);
            o->acc_g[i] = quantise(clampd(out.accel_g[i], c->accel_range_g), c->accel_lsb_g);
        }
        o->temp_c = quantise(o->true_temp_c, c->temp_lsb_c);
    } else {
        for (i = 0; i < 3; i++) {
            o->gyr_dps[i] = o->true_gyr_dps[i];
            o->acc_g[i] = o->true_acc_g[i];
        }
        o->temp_c = o->true_temp_c;
    }
    esc_signals(s, t, o->true_yaw_rate_dps, o);
    advance(s);
    return 1;
}
