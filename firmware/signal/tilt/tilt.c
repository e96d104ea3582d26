/*
 * tilt.c - roll and pitch estimation, [CN110567483] step 4 and the two-state Kalman filter (see
 * inclino/tilt.h and docs/kalman.md).
 *
 * Both seed forms run the second Kalman stage as the generic filter with one state (A = 1,
 * B = dt, u = w - off, H = 1, Q = Q2, R = R2), which is exactly the patent's P2-, K2, X2, P2
 * sequence; the modes differ only in how the offset is formed after the update, from the
 * correction c = theta(k) - w_theta(k) that the update applied:
 *   printed  ([CN110567483], 4a/4b)  off = c / dt. Substituted into 4c this cancels the previous
 *            correction, w_theta(k+1) = w_theta(k) + w(k+1) dt, so the offset never learns the
 *            bias (docs/references.md, [CN110567483]).
 *   feedback off = off - Kb c / dt. A positive bias makes w_theta run ahead of the
 *            accelerometer, c < 0, off grows toward the bias: the sign is right and the integral
 *            removes a constant bias completely (a PI loop: proportional K2 / dt, integral
 *            Kb K2 / dt^2 per unit angle error; Kb = K2 / 4 is critical damping).
 * The offset keeps 32 fractional bits (deg/s): Kb c / dt is ~1e-4 deg/s per step, far below the
 * Q16 LSB; rounded to Q16 each step the integral would stall. The gyro input to the filter is
 * w - round(off) in Q16 (the gyro's own resolution); the rounding residue is a constant that the
 * integral loop removes with the bias.
 */
#include "inclino/tilt.h"

#include <stddef.h>

#include "inclino/compiler.h"
#include "inclino/fx128.h"

#define NS_PER_S 1000000000u

/* ---- accelerometer angles --------------------------------------------------------------- */

void tilt_accel_angles(const fx_q16_t accel_g[3], fx_q16_t *roll_deg, fx_q16_t *pitch_deg)
{
    uint64_t ax = fx_uabs32(accel_g[0]);
    uint64_t ay = fx_uabs32(accel_g[1]), az = fx_uabs32(accel_g[2]);
    uint64_t s = ay * ay + az * az; /* <= 2^63 */
    uint64_t root;
    unsigned e = 0;
    int32_t num;

    if (roll_deg != NULL) *roll_deg = fx_atan2_deg(accel_g[1], accel_g[2]);
    if (pitch_deg == NULL) return;
    /* pitch = atan2(-a_x, sqrt(a_y^2 + a_z^2)). Both legs are scaled up by 2^e while they stay
     * below 2^30, so that the rounding of the square root (0.5 LSB of the scaled value) costs
     * nothing: at 1 g it is 2^-31 relative instead of 2^-17 (which would be 29 LSB Q16 of
     * angle). atan2 needs only the ratio. */
    while (e < 15u && (s >> 58) == 0u && (ax >> 29) == 0u) {
        s <<= 2;
        ax <<= 1;
        e++;
    }
    root = fx_isqrt64_round(s);
    /* Inputs beyond any real acceleration (> 23 000 g) can leave int32: halve both legs. */
    while (root > (uint64_t)INT32_MAX || ax > (uint64_t)INT32_MAX) {
        root >>= 1;
        ax >>= 1;
    }
    num = (int32_t)ax;
    if (accel_g[0] > 0) num = -num;
    *pitch_deg = fx_atan2_deg(num, (int32_t)root);
}

/* ---- configuration ----------------------------------------------------------------------- */

static bool axis_ok(const struct tilt_axis_config *a, fx_q16_t gyro_limit)
{
    if (a->q_angle < 1 || a->q_angle > KF_P_MAX) return false;
    if (a->q_bias < 0 || a->q_bias > KF_P_MAX) return false;
    if (a->r_angle < 1 || a->r_angle > KF_P_MAX) return false;
    if (a->p0_angle < 0 || a->p0_angle > TILT_VAR_CAP) return false;
    if (a->p0_bias < 0 || a->p0_bias > KF_P_MAX) return false;
    if (a->bias_gain < 0 || a->bias_gain > FX_Q30_ONE) return false;
    if (fx_abs(a->bias0_dps) >= gyro_limit) return false;
    return true;
}

int tilt_config_check(const struct tilt_config *cfg)
{
    unsigned i;
    if (cfg == NULL) return INC_ERR_NULL;
    if (cfg->mode != TILT_MODE_FEEDBACK && cfg->mode != TILT_MODE_SEED_PRINTED &&
        cfg->mode != TILT_MODE_KF2) {
        return INC_ERR_INVAL;
    }
    if (cfg->accel_tol_g <= 0 || cfg->accel_tol_g > FX_Q16_HALF) return INC_ERR_INVAL;
    if (cfg->gyro_limit_dps <= 0) return INC_ERR_INVAL;
    if (cfg->dt_max_ns == 0u || cfg->dt_max_ns > NS_PER_S) return INC_ERR_INVAL;
    for (i = 0; i < TILT_AXES; i++) {
        if (!axis_ok(&cfg->axis[i], cfg->gyro_limit_dps)) return INC_ERR_INVAL;
    }
    return INC_OK;
}

/* dt in seconds as Q30: round(ns * 2^30 / 10^9); ns <= 10^9 gives <= 2^30. */
static int64_t dt_q30(uint32_t ns)
{
    uint64_t n = (uint64_t)ns << 30, q = n / NS_PER_S, r = n - q * NS_PER_S;
    if (r >= NS_PER_S - r) q++;
    return (int64_t)q;
}

/* round(v * dt), v in P format per second, dt Q30 seconds: a variance for one step. */
static int64_t per_step(int64_t v, int64_t dtq)
{
    bool sat = false;
    int64_t r = fx_i128_rshift_round(fx_i128_mul(v, dtq), FX_Q30_SHIFT, &sat);
    return r > KF_P_MAX ? KF_P_MAX : r;
}

/* sqrt(x) ~ *root / 2^*shift with >= 30 significant bits: x is scaled by 4^k into [2^60, 2^62). */
static uint64_t sqrt_scaled(uint64_t x, unsigned *shift)
{
    unsigned k = 0;
    while (k < 31u && (x >> 60) == 0u) {
        x <<= 2;
        k++;
    }
    *shift = k;
    return fx_isqrt64_round(x);
}

int tilt_feedback_gain(int64_t q_angle, int64_t r_angle, uint32_t dt_ns, fx_q30_t *gain)
{
    int64_t q, pm, k2, d, kb;
    uint64_t ra, rb, prod, root;
    unsigned sa, sb, sh;
    fx_q30_t s;
    if (gain == NULL) return INC_ERR_NULL;
    if (q_angle < 1 || q_angle > KF_P_MAX || r_angle < 1 || r_angle > KF_P_MAX || dt_ns == 0u ||
        dt_ns > NS_PER_S) {
        return INC_ERR_INVAL;
    }
    q = per_step(q_angle, dt_q30(dt_ns));
    if (q < 1) q = 1;
    /* Steady state of the second stage: P- = P + Q, P = P- R / (P- + R) give
     * P-^2 - Q P- - Q R = 0, so P- = (Q + sqrt(Q (Q + 4R))) / 2 and K2 = P- / (P- + R).
     * sqrt(Q (Q + 4R)) = sqrt(Q) sqrt(Q + 4R), each root to >= 30 bits. */
    ra = sqrt_scaled((uint64_t)q, &sa);
    rb = sqrt_scaled((uint64_t)q + 4u * (uint64_t)r_angle, &sb); /* < 2^63 */
    prod = ra * rb;                                              /* each root < 2^31 */
    sh = sa + sb;
    root = sh == 0u ? prod : (prod >> sh) + ((prod >> (sh - 1u)) & 1u);
    pm = (q + (int64_t)root + 1) / 2;
    (void)fx_i128_div_i64(fx_i128_mul(pm, (int64_t)1 << FX_Q30_SHIFT), pm + r_angle, &k2);
    /* The error dynamics of the feedback loop with a constant gain K (e: angle error, g: offset
     * error times dt): e' = (1 - K)(e - g), g' = g + Kb K (e - g). Its poles coincide (critical
     * damping) when (2 - K - Kb K)^2 = 4 (1 - K), i.e. Kb = (1 - sqrt(1 - K))^2 / K, about K / 4
     * for a small K (docs/kalman.md). Written as Kb = K / (1 + sqrt(1 - K))^2 it has no
     * cancellation: Q30 * 2^60 / Q60. */
    if (k2 <= 0) {
        *gain = 0;
        return INC_OK;
    }
    s = fx_sqrt_q30((fx_q30_t)(FX_Q30_ONE - k2));
    d = (int64_t)FX_Q30_ONE + s; /* 1 + sqrt(1 - K), Q30, [1, 2] */
    (void)fx_i128_div_i64(fx_i128_mul(k2, (int64_t)1 << 60), d * d, &kb);
    *gain = (fx_q30_t)(kb > FX_Q30_ONE ? FX_Q30_ONE : kb);
    return INC_OK;
}

int tilt_config_default(struct tilt_config *cfg, uint32_t dt_nominal_ns)
{
    unsigned i;
    if (cfg == NULL) return INC_ERR_NULL;
    if (dt_nominal_ns == 0u || dt_nominal_ns > 100000000u) return INC_ERR_INVAL;
    cfg->mode = TILT_MODE_FEEDBACK;
    cfg->accel_tol_g = FX_Q16_ONE / 10;    /* 0.1 g */
    cfg->gyro_limit_dps = FX_Q16_INT(295); /* ADIS1636x/1640x +-300 deg/s, 5 deg/s margin */
    cfg->dt_max_ns = 100000000u;           /* 100 ms */
    for (i = 0; i < TILT_AXES; i++) {
        struct tilt_axis_config *a = &cfg->axis[i];
        a->q_angle = KF_P_ONE_Q16 / 1000;   /* 1e-3 deg^2/s: ARW 0.031 deg/sqrt(s) */
        a->q_bias = KF_P_ONE_Q16 / 5000000; /* 2e-7 (deg/s)^2/s: RRW 0.00045 deg/s/sqrt(s) */
        a->r_angle = KF_P_ONE_Q16;          /* 1 deg^2 */
        a->p0_angle = a->r_angle;
        a->p0_bias = KF_P_ONE_Q16; /* 1 (deg/s)^2 */
        a->bias0_dps = 0;
        int err = tilt_feedback_gain(a->q_angle, a->r_angle, dt_nominal_ns, &a->bias_gain);
        if (err != INC_OK) return err;
    }
    return INC_OK;
}

/* ---- set-up ---------------------------------------------------------------------------- */

void tilt_restart(struct tilt *t)
{
    if (t == NULL) return;
    t->started = false;
    t->have_time = false;
}

int tilt_init(struct tilt *t, const struct tilt_config *cfg)
{
    unsigned i;
    int err;
    if (t == NULL) return INC_ERR_NULL;
    t->ready = false;
    err = tilt_config_check(cfg);
    if (err != INC_OK) return err;
    t->cfg = *cfg;
    for (i = 0; i < TILT_AXES; i++) {
        /* The angle is not known yet (started == false); the offset is. */
        const struct tilt_axis_config *a = &cfg->axis[i];
        int64_t p0[4];
        int32_t x0[2];
        p0[0] = a->p0_angle;
        p0[1] = 0;
        p0[2] = 0;
        p0[3] = a->p0_bias;
        x0[0] = 0;
        x0[1] = a->bias0_dps;
        t->ax[i].off = (int64_t)a->bias0_dps * ((int64_t)1 << 16);
        if (cfg->mode == TILT_MODE_KF2) {
            (void)kf_init(&t->ax[i].kf, 2u, x0, p0);
        } else {
            (void)kf_init(&t->ax[i].kf, 1u, x0, p0);
        }
    }
    t->last_ns = 0;
    t->dt_ns_cached = 0;
    t->dt_q30_cached = 0;
    tilt_restart(t);
    t->ready = true;
    return INC_OK;
}

/* Start (or restart) axis i at the accelerometer angle. The offset (seed forms: s->off; KF2:
 * the bias state and its variance) is kept from before: tilt_init set it from bias0_dps. */
static void start_axis(struct tilt *t, unsigned i, fx_q16_t angle)
{
    const struct tilt_axis_config *c = &t->cfg.axis[i];
    struct tilt_axis_state *s = &t->ax[i];
    if (t->cfg.mode == TILT_MODE_KF2) {
        int64_t bias = s->kf.x[1], pb = s->kf.p[1][1];
        int64_t p0[4];
        p0[0] = c->p0_angle;
        p0[1] = 0;
        p0[2] = 0;
        p0[3] = pb;
        (void)kf_init(&s->kf, 2u, NULL, p0); /* ranges checked by tilt_config_check */
        s->kf.x[0] = (int64_t)angle * 65536;
        s->kf.x[1] = bias;
    } else {
        (void)kf_init(&s->kf, 1u, &angle, &c->p0_angle);
    }
}

static bool accel_ok(const struct tilt *t, const struct tilt_input *in)
{
    /* | |a| - 1 | <= tol  <=>  (1 - tol)^2 <= |a|^2 <= (1 + tol)^2, all in Q32 (no square root). */
    uint64_t a2 = 0, lo, hi;
    uint64_t one_m = (uint64_t)(FX_Q16_ONE - t->cfg.accel_tol_g);
    uint64_t one_p = (uint64_t)(FX_Q16_ONE + t->cfg.accel_tol_g);
    unsigned i;
    if (in->flags & TILT_IN_ACCEL_SAT) return false;
    for (i = 0; i < 3u; i++) {
        uint64_t m = fx_uabs32(in->accel_g[i]);
        if (m > 0x10000000u) return false; /* > 4096 g: nonsense; also keeps the sum < 2^63 */
        a2 += m * m;
    }
    lo = one_m * one_m;
    hi = one_p * one_p;
    return a2 >= lo && a2 <= hi;
}

/* Wrap an angle into (-180, 180] deg (Q16, internal scale 2^16 more). */
static int64_t wrap_internal(int64_t x)
{
    const int64_t full = (int64_t)FX_DEG_360 * 65536, half = (int64_t)FX_DEG_180 * 65536;
    while (x > half)
        x -= full;
    while (x <= -half)
        x += full;
    return x;
}

static void fill_axis_output(const struct tilt *t, unsigned i, struct tilt_output *out)
{
    const struct tilt_axis_state *s = &t->ax[i];
    out->angle_deg[i] = kf_x(&s->kf, 0);
    out->sigma_deg[i] = kf_sigma(&s->kf, 0);
    if (t->cfg.mode == TILT_MODE_KF2) {
        out->bias_dps[i] = kf_x(&s->kf, 1);
    } else {
        out->bias_dps[i] = (fx_q16_t)fx_rshift_round64(s->off, 16u);
    }
}

static void clear_output(struct tilt_output *out)
{
    unsigned i;
    for (i = 0; i < TILT_AXES; i++) {
        out->angle_deg[i] = 0;
        out->sigma_deg[i] = 0;
        out->bias_dps[i] = 0;
        out->accel_angle_deg[i] = 0;
    }
    out->flags = 0;
    out->valid = false;
}

/* The accelerometer angle (Q16 deg) as a measurement on the same turn as the state x (internal
 * scale): roll wraps at +-180, so a reading across the wrap is moved by 360 deg. */
static int32_t same_turn(fx_q16_t acc_angle, int64_t x)
{
    const int64_t d = (int64_t)acc_angle * 65536 - x;
    int32_t z = acc_angle;
    if (d > (int64_t)FX_DEG_180 * 65536) z -= FX_DEG_360;
    if (d < -(int64_t)FX_DEG_180 * 65536) z += FX_DEG_360;
    return z;
}

/* One axis, one step (the filter has started, 0 < dt <= dt_max). Kept out of line so that its
 * model arrays do not add to tilt_step's frame (INC_NOINLINE, inclino/compiler.h). */
INC_NOINLINE static bool step_axis(struct tilt *t, unsigned i, fx_q16_t w, bool gyro_ok,
                                   bool acc_ok, fx_q16_t acc_angle, int64_t dtq)
{
    const struct tilt_axis_config *c = &t->cfg.axis[i];
    struct tilt_axis_state *s = &t->ax[i];
    bool overflow = false;
    int64_t q00 = s->q_angle_step;
    int err;

    if (!gyro_ok) {
        /* Unknown rate: hold the angle and let its variance grow by (limit dt)^2. */
        int64_t step = fx_i128_rshift_round(fx_i128_mul(t->cfg.gyro_limit_dps, dtq), 30u,
                                            &overflow);
        q00 += kf_var_from_sigma((int32_t)(step > INT32_MAX ? INT32_MAX : step));
    }
    /* Coasting never raises the angle variance above TILT_VAR_CAP. */
    if (s->kf.p[0][0] + q00 > TILT_VAR_CAP) q00 = TILT_VAR_CAP - s->kf.p[0][0];
    if (q00 < 0) q00 = 0;

    if (t->cfg.mode == TILT_MODE_KF2) {
        fx_q30_t a[4], b[2];
        int64_t q[4];
        int32_t u = w;
        struct kf_model m;
        a[0] = FX_Q30_ONE;
        a[1] = gyro_ok ? (fx_q30_t)-dtq : 0;
        a[2] = 0;
        a[3] = FX_Q30_ONE;
        b[0] = gyro_ok ? (fx_q30_t)dtq : 0;
        b[1] = 0;
        q[0] = q00;
        q[1] = 0;
        q[2] = 0;
        q[3] = s->q_bias_step;
        m.n = 2;
        m.nu = 1;
        m.a = a;
        m.b = b;
        m.q = q;
        err = kf_predict(&s->kf, &m, &u);
        if (err == INC_ERR_OVERFLOW) overflow = true;
        if (acc_ok) {
            static const fx_q30_t h[2] = {FX_Q30_ONE, 0};
            err = kf_update_row(&s->kf, h, c->r_angle, same_turn(acc_angle, s->kf.x[0]));
            if (err == INC_ERR_OVERFLOW) overflow = true;
        }
    } else {
        fx_q30_t a = FX_Q30_ONE, b = gyro_ok ? (fx_q30_t)dtq : 0;
        int32_t u = gyro_ok ? fx_sub(w, (fx_q16_t)fx_rshift_round64(s->off, 16u)) : 0;
        int64_t corr, x_pred;
        struct kf_model m;
        m.n = 1;
        m.nu = 1;
        m.a = &a;
        m.b = &b;
        m.q = &q00;
        err = kf_predict(&s->kf, &m, &u); /* 4c/4d: w_theta(k) */
        if (err == INC_ERR_OVERFLOW) overflow = true;
        x_pred = s->kf.x[0];
        if (acc_ok) {
            static const fx_q30_t h1 = FX_Q30_ONE;
            /* second stage: theta(k) */
            err = kf_update_row(&s->kf, &h1, c->r_angle, same_turn(acc_angle, x_pred));
            if (err == INC_ERR_OVERFLOW) overflow = true;
        }
        corr = s->kf.x[0] - x_pred; /* theta(k) - w_theta(k), deg * 2^32 */
        if (t->cfg.mode == TILT_MODE_SEED_PRINTED) {
            /* 4a/4b as printed: off(k+1) = (theta(k) - w_theta(k)) / dt. */
            int64_t off;
            if (fx_i128_div_i64(fx_i128_mul(corr, (int64_t)1 << 30), dtq, &off) != INC_OK) {
                overflow = true;
            }
            s->off = off;
        } else if (gyro_ok && acc_ok) {
            /* Corrected: off(k+1) = off(k) - Kb (theta(k) - w_theta(k)) / dt. */
            int64_t doff;
            if (fx_i128_div_i64(fx_i128_mul(corr, c->bias_gain), dtq, &doff) != INC_OK) {
                overflow = true;
            }
            s->off -= doff;
        }
    }
    s->kf.x[0] = wrap_internal(s->kf.x[0]);
    return overflow || s->kf.overflow;
}

int tilt_step(struct tilt *t, const struct tilt_input *in, uint32_t dt_ns, struct tilt_output *out)
{
    fx_q16_t acc_angle[TILT_AXES];
    bool acc_ok, overflow = false;
    unsigned i;

    if (t == NULL || in == NULL || out == NULL) return INC_ERR_NULL;
    clear_output(out);
    if (!t->ready) return INC_ERR_STATE;
    if (t->started && dt_ns == 0u) {
        for (i = 0; i < TILT_AXES; i++)
            fill_axis_output(t, i, out);
        return INC_ERR_INVAL;
    }

    acc_ok = accel_ok(t, in);
    if (acc_ok) {
        tilt_accel_angles(in->accel_g, &acc_angle[TILT_ROLL], &acc_angle[TILT_PITCH]);
        out->accel_angle_deg[TILT_ROLL] = acc_angle[TILT_ROLL];
        out->accel_angle_deg[TILT_PITCH] = acc_angle[TILT_PITCH];
    } else {
        out->flags |= TILT_F_ACCEL_REJECTED;
        acc_angle[TILT_ROLL] = 0;
        acc_angle[TILT_PITCH] = 0;
    }

    if (t->started && dt_ns > t->cfg.dt_max_ns) {
        /* A gap too long to bridge with one gyro sample: start again from the accelerometer. */
        out->flags |= TILT_F_GAP_RESTART;
        t->started = false;
    }
    if (!t->started) {
        if (!acc_ok) {
            out->flags |= TILT_F_NOT_STARTED;
            return INC_OK;
        }
        for (i = 0; i < TILT_AXES; i++)
            start_axis(t, i, acc_angle[i]);
        t->started = true;
    } else {
        int64_t dtq;
        if (dt_ns != t->dt_ns_cached) {
            /* A new interval (the first step, or a gap): convert it and the per-step noise once;
             * at a steady rate this happens once. */
            t->dt_ns_cached = dt_ns;
            t->dt_q30_cached = dt_q30(dt_ns);
            for (i = 0; i < TILT_AXES; i++) {
                t->ax[i].q_angle_step = per_step(t->cfg.axis[i].q_angle, t->dt_q30_cached);
                t->ax[i].q_bias_step = per_step(t->cfg.axis[i].q_bias, t->dt_q30_cached);
            }
        }
        dtq = t->dt_q30_cached;
        for (i = 0; i < TILT_AXES; i++) {
            fx_q16_t w = in->gyro_dps[i];
            uint32_t sat_flag = i == TILT_ROLL ? TILT_IN_GYRO_SAT_X : TILT_IN_GYRO_SAT_Y;
            bool gyro_ok = (in->flags & sat_flag) == 0u && fx_abs(w) < t->cfg.gyro_limit_dps;
            if (!gyro_ok)
                out->flags |= i == TILT_ROLL ? TILT_F_GYRO_REJ_ROLL : TILT_F_GYRO_REJ_PITCH;
            if (step_axis(t, i, w, gyro_ok, acc_ok, acc_angle[i], dtq)) overflow = true;
        }
    }
    for (i = 0; i < TILT_AXES; i++)
        fill_axis_output(t, i, out);
    if (overflow) out->flags |= TILT_F_OVERFLOW;
    out->valid = !overflow;
    return INC_OK;
}

int tilt_step_at(struct tilt *t, const struct tilt_input *in, uint64_t t_ns,
                 struct tilt_output *out)
{
    uint32_t dt = 0;
    int err;
    if (t == NULL || in == NULL || out == NULL) return INC_ERR_NULL;
    if (t->ready && !t->have_time) {
        /* No time reference yet (first call, or after tilt_step without time): start from the
         * accelerometer at this sample. */
        t->started = false;
    } else if (t->ready) {
        uint64_t d = t_ns > t->last_ns ? t_ns - t->last_ns : 0u;
        dt = d > UINT32_MAX ? UINT32_MAX : (uint32_t)d;
        if (dt == 0u && t->started) {
            clear_output(out);
            return INC_ERR_INVAL;
        }
    }
    err = tilt_step(t, in, dt, out);
    if (err == INC_OK) {
        t->last_ns = t_ns;
        t->have_time = true;
    }
    return err;
}
