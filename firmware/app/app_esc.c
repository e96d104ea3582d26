/*
 * app_esc.c - the ESC run mode and the parked/driving mode manager (see inclino/app_esc.h).
 */
#include "inclino/app_esc.h"

#include <stddef.h>

/* seconds (Q16) x rate (milli-samples/s) -> samples, rounded; saturates at UINT32_MAX. */
static uint32_t samples_of(fx_q16_t s, uint32_t rate_mhz)
{
    const uint64_t n = ((uint64_t)(uint32_t)s * rate_mhz + 500u * 65536u) / (1000u * 65536u);
    return n > UINT32_MAX ? UINT32_MAX : (uint32_t)n;
}

int app_esc_cfg_default(struct app_esc_cfg *cfg, uint32_t rate_mhz)
{
    int err;
    if (cfg == NULL) return INC_ERR_NULL;
    if (rate_mhz < 100000u || rate_mhz > 4000000u) return INC_ERR_INVAL;
    /* rate in Q16 Hz: rate_mhz * 65536 / 1000, rounded */
    err = att_config_default(&cfg->att, (fx_q16_t)(((uint64_t)rate_mhz * 65536u + 500u) / 1000u));
    if (err != INC_OK) return err;
    cfg->att.require_aiding = 1u; /* a car: valid only with the speed (att.h) */
    cfg->out_div = 8u;
    cfg->drive_speed_mps = FX_Q16_HALF;
    cfg->park_s = FX_Q16_INT(2);
    cfg->autonull_after_s = FX_Q16_INT(60);
    cfg->flat_n = 0u; /* the driving diagnostics off: app_esc_diag_default */
    cfg->veh_margin_g = 0;
    cfg->veh_bound_k = FX_Q16_HALF;
    cfg->veh_dyn_k = (fx_q16_t)((FX_Q16_ONE * 3 + 5) / 10);
    cfg->veh_min_mps = FX_Q16_INT(3);
    cfg->xchk_thr_g = 0;
    cfg->veh_gyro_dps = 0;
    cfg->xchk_margin_g = 0;
    cfg->diag_shift = 8u;
    cfg->diag_persist_n = 41u;
    return INC_OK;
}

int app_esc_diag_default(struct app_esc_cfg *cfg)
{
    /* the rate in samples/s (Q16 Hz, rounded); 0.05 s and 0.3125 s in samples */
    uint32_t fs, n, sh = 1u;
    if (cfg == NULL) return INC_ERR_NULL;
    fs = (uint32_t)(((uint64_t)(uint32_t)cfg->att.sample_rate_hz + 32768u) >> 16);
    cfg->flat_n = 16u;
    cfg->veh_margin_g = (fx_q16_t)((FX_Q16_ONE * 15 + 500) / 1000); /* 0.015 g */
    cfg->veh_bound_k = FX_Q16_HALF;
    cfg->veh_dyn_k = (fx_q16_t)((FX_Q16_ONE * 3 + 5) / 10);
    cfg->veh_min_mps = FX_Q16_INT(3);
    cfg->xchk_thr_g = (fx_q16_t)((FX_Q16_ONE * 3 + 50) / 100); /* 0.03 g */
    cfg->veh_gyro_dps = FX_Q16_INT(2);
    cfg->xchk_margin_g = (fx_q16_t)((FX_Q16_ONE + 50) / 100); /* 0.01 g */
    n = (fs + 10u) / 20u;                                     /* 0.05 s */
    cfg->diag_persist_n = n < 2u ? 2u : n;
    n = (fs * 5u + 8u) / 16u; /* 0.3125 s: the nearest power of two, geometrically */
    while (sh < 16u && (uint64_t)n * n >= ((uint64_t)1 << (2u * sh + 1u)))
        sh++;
    cfg->diag_shift = (uint8_t)sh;
    return INC_OK;
}

int app_esc_set_aux_accel(struct app_esc *e, const fx_q16_t acc_g[3], bool valid)
{
    if (e == NULL || acc_g == NULL) return INC_ERR_NULL;
    e->aux_acc[0] = acc_g[0];
    e->aux_acc[1] = acc_g[1];
    e->aux_acc[2] = acc_g[2];
    e->aux_valid = valid;
    return INC_OK;
}

/* pi/180 in Q16, rounded up: bound_deg x this >= sin(bound) in g per g */
#define DEG2RAD_Q16_UP 1144

/*
 * The bound's floor (app_esc_cfg.veh_gyro_dps) for the threshold's part rest = margin + dyn x
 * klev (Q16 g, [0, 33 g]): the error e (rad) at which e = rest + k e, e = rest / (1 - k), in
 * degrees (x 180/pi rounded up: e is an upper bound), + the delay's share; at most 180 deg.
 * rest x inv < 2^22 x 2^32; the product with 180/pi (Q16 3754937, rounded up) is taken in two
 * steps so that no intermediate passes 2^63.
 */
#define RAD2DEG_Q16_UP 3754937
static fx_q16_t veh_floor_of(const struct app_esc *e, fx_q16_t rest)
{
    uint64_t fg, fdeg;
    if (e->cfg.veh_gyro_dps == 0) return 0;
    if (e->veh_inv_q16 == 0u) return FX_DEG_180;
    fg = ((uint64_t)(uint32_t)rest * e->veh_inv_q16 + 0xFFFFu) >> 16; /* Q16 rad, rounded up */
    if (fg > ((uint64_t)FX_DEG_180 << 16) / RAD2DEG_Q16_UP) return FX_DEG_180;
    fdeg = (fg * RAD2DEG_Q16_UP + 0xFFFFu) >> 16;
    fdeg += (uint64_t)e->veh_lag_deg;
    return fdeg > (uint64_t)FX_DEG_180 ? FX_DEG_180 : (fx_q16_t)fdeg;
}

/*
 * The cross-check's term in the DRIVING bound (app_esc_cfg.xchk_margin_g), Q16 deg, for the
 * estimate's up u (Q30, |u| = 1): T = thr + margin (Q16 g, <= 2 g); a bias b passes the check
 * unseen while its x-y norm and |b_z| are both <= T, so |b| <= sqrt(2) T and its component
 * across u is at most P = T (1 + s), s = sqrt(u_x^2 + u_y^2) (the sensor z axis's part across
 * u); the tilt it makes, atan(P / (1 - |b|)) <= P / (1 - sqrt(2) T) rad, in degrees. Every
 * step rounds up, so the result is >= the exact value, by at most about 3 LSB Q16 deg plus the
 * 180/pi constant's 1.2e-6 relative; 180 deg when sqrt(2) T >= 1 g.
 */
#define SQRT2_Q16_UP 92682
static fx_q16_t xchk_term_of(const struct app_esc *e, const int32_t up[3])
{
    const uint64_t t = (uint64_t)(uint32_t)e->cfg.xchk_thr_g + (uint32_t)e->cfg.xchk_margin_g;
    const uint64_t s2 = (uint64_t)((int64_t)up[0] * up[0]) + (uint64_t)((int64_t)up[1] * up[1]);
    uint64_t r, p, bsum, q, deg;
    r = fx_isqrt64(s2); /* Q30: s2 <= 2^61 */
    if (r * r < s2) r++;
    p = (t * (((uint64_t)1 << 30) + r) + (((uint64_t)1 << 30) - 1u)) >> 30; /* Q16 g */
    bsum = (t * SQRT2_Q16_UP + 0xFFFFu) >> 16;                              /* Q16 g */
    if (bsum >= (uint64_t)FX_Q16_ONE) return FX_DEG_180;
    q = ((p << 16) + ((uint64_t)FX_Q16_ONE - bsum) - 1u) / ((uint64_t)FX_Q16_ONE - bsum);
    if (q > ((uint64_t)FX_DEG_180 << 16) / RAD2DEG_Q16_UP) return FX_DEG_180;
    deg = (q * RAD2DEG_Q16_UP + 0xFFFFu) >> 16; /* Q16 deg */
    return deg > (uint64_t)FX_DEG_180 ? FX_DEG_180 : (fx_q16_t)deg;
}

int app_esc_init(struct app_esc *e, const struct app_esc_cfg *cfg)
{
    uint32_t rate_mhz;
    int err;
    if (e == NULL || cfg == NULL) return INC_ERR_NULL;
    e->ready = false;
    if (cfg->out_div < 1u || cfg->out_div > 65535u || cfg->drive_speed_mps <= 0 ||
        cfg->drive_speed_mps > FX_Q16_INT(10) || cfg->park_s < 0 || cfg->park_s > FX_Q16_INT(60) ||
        cfg->autonull_after_s < FX_Q16_ONE || cfg->autonull_after_s > FX_Q16_INT(3600))
        return INC_ERR_INVAL;
    if (cfg->flat_n == 1u || cfg->flat_n > 65535u || cfg->veh_margin_g < 0 ||
        cfg->veh_margin_g > FX_Q16_ONE || cfg->veh_bound_k <= 0 || cfg->veh_bound_k > FX_Q16_ONE ||
        cfg->veh_dyn_k < 0 || cfg->veh_dyn_k > FX_Q16_ONE || cfg->veh_min_mps < 0 ||
        cfg->veh_min_mps > FX_Q16_INT(20) || cfg->xchk_thr_g < 0 || cfg->xchk_thr_g > FX_Q16_ONE ||
        cfg->veh_gyro_dps < 0 || cfg->veh_gyro_dps > FX_Q16_INT(50) || cfg->xchk_margin_g < 0 ||
        cfg->xchk_margin_g > FX_Q16_ONE || cfg->diag_shift < 1u || cfg->diag_shift > 16u ||
        cfg->diag_persist_n < 1u || cfg->diag_persist_n > (1u << 24))
        return INC_ERR_INVAL;
    err = att_init(&e->att, &cfg->att);
    if (err != INC_OK) return err;
    e->cfg = *cfg;
    /* milli-samples/s from the estimator's Q16 Hz (validated by att_init: 100..4000 Hz) */
    rate_mhz = (uint32_t)(((uint64_t)(uint32_t)cfg->att.sample_rate_hz * 1000u + 32768u) >> 16);
    e->park_n = samples_of(cfg->park_s, rate_mhz);
    e->autonull_n = samples_of(cfg->autonull_after_s, rate_mhz);
    e->gcorr.valid = false;
    e->gcorr.corr[0] = e->gcorr.corr[1] = e->gcorr.corr[2] = 0;
    e->n_out = 0u;
    e->still_n = 0u;
    e->since_cal_n = 0u;
    e->mode = APP_MODE_PARKED;
    if (cfg->flat_n != 0u) {
        err = xcheck_flat_init(&e->flat, cfg->flat_n, 0x3Fu);
        if (err != INC_OK) return err;
    }
    err = xcheck_mon_init(&e->vmon, cfg->diag_shift, cfg->diag_persist_n);
    if (err == INC_OK) err = xcheck_mon_init(&e->kmon, cfg->diag_shift, cfg->diag_persist_n);
    if (err == INC_OK) err = xcheck_mon_init(&e->xmon, cfg->diag_shift, cfg->diag_persist_n);
    if (err != INC_OK) return err;
    e->v_prev = 0;
    e->v_prev_ok = false;
    e->aux_acc[0] = e->aux_acc[1] = e->aux_acc[2] = 0;
    e->aux_valid = false;
    e->veh_level = e->xchk_level = e->veh_thr = 0;
    e->veh_floor = 0;
    {
        /* G x (2^(shift+1) + persist) samples / rate: G <= 50 deg/s (2^21.7 Q16), the samples
         * <= 2^24.01, x 2^16: < 2^62; rate >= 100 Hz (att_init) */
        const int64_t n = ((int64_t)1 << (cfg->diag_shift + 1u)) + (int64_t)cfg->diag_persist_n;
        const int64_t lag = ((int64_t)cfg->veh_gyro_dps * n * 65536 + cfg->att.sample_rate_hz / 2) /
                            cfg->att.sample_rate_hz;
        e->veh_lag_deg = lag > FX_DEG_180 ? FX_DEG_180 : (fx_q16_t)lag;
    }
    e->veh_inv_q16 = cfg->veh_bound_k >= FX_Q16_ONE
                         ? 0u
                         : (uint32_t)((((uint64_t)1 << 32) +
                                       (uint64_t)(FX_Q16_ONE - cfg->veh_bound_k) - 1u) /
                                      (uint64_t)(FX_Q16_ONE - cfg->veh_bound_k));
    /* G / rate per sample, rounded up: G <= 2^21.7 Q16, x 2^16 < 2^38; rate >= 100 Hz */
    e->veh_step = (fx_q16_t)(((int64_t)cfg->veh_gyro_dps * 65536 + cfg->att.sample_rate_hz - 1) /
                             cfg->att.sample_rate_hz);
    e->veh_rest = veh_floor_of(e, cfg->veh_margin_g);
    e->veh_hold = e->veh_rest;
    e->diag = 0u;
    e->ready = true;
    return INC_OK;
}

uint8_t app_esc_mode(const struct app_esc *e)
{
    return e != NULL && e->ready ? e->mode : (uint8_t)APP_MODE_PARKED;
}

bool app_esc_autonull_due(const struct app_esc *e)
{
    return e != NULL && e->ready && e->mode == APP_MODE_PARKED && e->since_cal_n >= e->autonull_n;
}

int app_esc_set_gyro_correction(struct app_esc *e, const struct gyrocal_correction *c)
{
    if (e == NULL || c == NULL) return INC_ERR_NULL;
    e->gcorr = *c;
    e->since_cal_n = 0u;
    return INC_OK;
}

/* The saturation bits of att_sample.sat (0-2 gyro x y z, 3-5 accel) from the sample's per-axis
 * flags (inclino/sensor.h). */
static uint8_t sat_bits(uint32_t flags)
{
    uint8_t s = 0u;
    unsigned i;
    for (i = 0; i < 3u; i++) {
        if ((flags & (SENSOR_S_GYRO_SAT_X << i)) != 0u) s |= (uint8_t)(1u << i);
        if ((flags & (SENSOR_S_ACCEL_SAT_X << i)) != 0u) s |= (uint8_t)(8u << i);
    }
    return s;
}

static void update_mode(struct app_esc *e, struct app *a, const struct app_vehicle *veh)
{
    const bool have_speed = veh != NULL && veh->valid;
    const bool fast = have_speed && fx_abs(veh->speed_mps) > e->cfg.drive_speed_mps;
    const bool rest = still_at_rest(&a->still);
    if (rest && !fast) {
        if (e->still_n < UINT32_MAX) e->still_n++;
    } else {
        e->still_n = 0u;
    }
    if (e->mode == APP_MODE_PARKED) {
        /* Moving: the speed says so, or (without speed) the detector left rest. */
        if (fast || (!have_speed && !rest && still_state_get(&a->still) == STILL_MOVING)) {
            e->mode = APP_MODE_DRIVING;
            e->n_out = 0u;
            e->veh_hold = e->veh_rest; /* the floor starts from its value at rest */
            app_restart(a);
        } else if (e->since_cal_n < UINT32_MAX) {
            e->since_cal_n++;
        }
    } else if (e->still_n >= e->park_n) {
        e->mode = APP_MODE_PARKED;
    }
}

/* The driving diagnostics of one sample (after att_update and the mode): see app_esc.h. */
static void diag_step(struct app_esc *e, const struct sensor_sample *raw,
                      const struct att_sample *as, const struct app_vehicle *veh)
{
    const bool have_speed = veh != NULL && veh->valid;
    const bool acc_sat = (as->sat & ATT_SAT_ACC_MASK) != 0u;
    bool fail = false;
    if (e->cfg.flat_n != 0u && raw != NULL) {
        /* the driver's values, before the record's temperature models can move them */
        const int32_t v[XCHECK_FLAT_CH] = {raw->gyro_dps[0], raw->gyro_dps[1], raw->gyro_dps[2],
                                           raw->accel_g[0],  raw->accel_g[1],  raw->accel_g[2]};
        if (xcheck_flat_step(&e->flat, v) != 0u) e->diag |= APP_ESC_D_FLAT;
    }
    bool ran = false;
    e->veh_level = e->veh_thr = 0;
    if (e->cfg.veh_margin_g != 0 && e->mode == APP_MODE_DRIVING && have_speed &&
        fx_abs(veh->speed_mps) >= e->cfg.veh_min_mps) {
        const fx_q16_t bound = att_get_bound(&e->att);
        if (e->v_prev_ok && !acc_sat && bound < FX_DEG_180) {
            static const fx_q16_t zero3[3] = {0, 0, 0};
            static const int32_t zero_up[3] = {0, 0, 0};
            int32_t up[3];
            fx_q16_t r[3], kin[3], klev, thr;
            /* |speed| <= 200 m/s (att's input range; beyond it att rejects the sample and the
             * residual clamps): the difference fits */
            const fx_q16_t dv = fx_sub(veh->speed_mps, e->v_prev);
            att_get_up(&e->att, up);
            (void)xcheck_kin_residual(as->acc_g, up, dv, e->cfg.att.sample_rate_hz, veh->speed_mps,
                                      veh->yaw_rate_dps, r);
            /* -k alone: a and up 0 */
            (void)xcheck_kin_residual(zero3, zero_up, dv, e->cfg.att.sample_rate_hz, veh->speed_mps,
                                      veh->yaw_rate_dps, kin);
            klev = xcheck_mon_step(&e->kmon, kin, 1u, INT32_MAX, NULL); /* dv/dt only */
            /* bound <= 180 deg (2^23.5 Q16) x 1144 / 2^16 <= 3.15 g; klev <= 32 g; each
             * product with a Q16 factor <= 1 and their sum (+ margin <= 1 g) fit */
            const fx_q16_t rest = e->cfg.veh_margin_g +
                                  (fx_q16_t)(((int64_t)klev * e->cfg.veh_dyn_k + 32768) >> 16);
            thr = rest + (fx_q16_t)(((int64_t)bound * DEG2RAD_Q16_UP * e->cfg.veh_bound_k +
                                     ((int64_t)1 << 31)) >>
                                    32);
            e->veh_level = xcheck_mon_step(&e->vmon, r, 3u, thr, &fail);
            e->veh_thr = thr;
            e->veh_floor = e->veh_hold = veh_floor_of(e, rest);
            ran = true;
            if (fail) e->diag |= APP_ESC_D_VEH;
            e->v_prev = veh->speed_mps;
        } else if (!e->v_prev_ok) {
            e->v_prev = veh->speed_mps; /* (a held sample keeps v_prev: its dv goes into the
                                           next residual) */
        }
        e->v_prev_ok = true;
    } else {
        xcheck_mon_reset(&e->vmon);
        xcheck_mon_reset(&e->kmon);
        e->v_prev_ok = false;
    }
    if (!ran) {
        /* no check: a gyro error up to veh_gyro_dps adds up to that much per sample unseen */
        const bool grow = e->cfg.veh_gyro_dps != 0 && e->mode == APP_MODE_DRIVING;
        if (grow) {
            e->veh_hold = e->veh_hold > FX_DEG_180 - e->veh_step ? FX_DEG_180
                                                                 : e->veh_hold + e->veh_step;
        }
        e->veh_floor = grow ? e->veh_hold : 0;
    }
    e->xchk_level = 0;
    if (e->cfg.xchk_thr_g != 0 && e->aux_valid && !acc_sat) {
        fx_q16_t d[3];
        unsigned i;
        for (i = 0; i < 3u; i++)
            d[i] = fx_sub(as->acc_g[i], e->aux_acc[i]);
        /* z on its own, x and y as a norm (the tilt is what a bias across up makes) */
        e->xchk_level = xcheck_mon_step(&e->xmon, d, 4u | XCHECK_MON_XY_NORM, e->cfg.xchk_thr_g,
                                        &fail);
        if (fail) e->diag |= APP_ESC_D_XCHK;
    }
}

int app_esc_step(struct app_esc *e, struct app *a, const struct sensor_sample *s, int read_err,
                 const struct app_vehicle *veh, struct app_esc_output *out, bool *have_out)
{
    struct app_corrected c;
    struct app_result res;
    struct att_sample as;
    bool done = false;
    unsigned i;
    int err;
    if (e == NULL || a == NULL || out == NULL || have_out == NULL) return INC_ERR_NULL;
    *have_out = false;
    if (!e->ready) return INC_ERR_STATE;
    err = app_step(a, s, read_err, &c, &done, &res);
    if (err != INC_OK || read_err != INC_OK) return err;
    for (i = 0; i < 3u; i++) {
        as.gyro_dps[i] = gyrocal_correct_q16(&e->gcorr, i, c.gyro_dps[i]);
        as.acc_g[i] = c.accel_g[i];
    }
    as.sat = sat_bits(c.flags);
    as.veh_valid = veh != NULL && veh->valid;
    as.speed_mps = as.veh_valid ? veh->speed_mps : 0;
    as.yaw_rate_dps = as.veh_valid ? veh->yaw_rate_dps : 0;
    err = att_update(&e->att, &as);
    if (err != INC_OK && err != INC_ERR_RANGE) return err;
    update_mode(e, a, veh);
    diag_step(e, s, &as, veh);
    out->diag = e->diag;
    out->veh_level_g = e->veh_level;
    out->veh_thr_g = e->veh_thr;
    out->xchk_level_g = e->xchk_level;
    if (e->mode == APP_MODE_DRIVING) {
        if (++e->n_out < e->cfg.out_div) return INC_OK;
        e->n_out = 0u;
        out->mode = APP_MODE_DRIVING;
        att_get_quat(&e->att, out->q);
        att_get_euler(&e->att, &out->roll_deg, &out->pitch_deg);
        out->bound_deg = att_get_bound(&e->att);
        if (e->cfg.xchk_thr_g != 0) { /* xchk_margin_g: an accelerometer bias the check misses */
            int32_t up[3];
            att_get_up(&e->att, up);
            out->bound_deg = fx_add(out->bound_deg, xchk_term_of(e, up));
            if (out->bound_deg > FX_DEG_180) out->bound_deg = FX_DEG_180;
        }
        if (e->veh_floor > out->bound_deg) out->bound_deg = e->veh_floor; /* veh_gyro_dps */
        out->valid = att_get_valid(&e->att); /* with require_aiding: never without the speed */
        out->att_fault = att_get_status(&e->att);
        if (e->diag != 0u) out->valid = false; /* a latched driving diagnostic */
        if (!as.veh_valid) out->diag |= APP_ESC_D_NO_SPEED;
        out->epb.valid = false;
        *have_out = true;
    } else if (done) {
        out->mode = APP_MODE_PARKED;
        out->epb = res;
        out->valid = res.valid;
        out->bound_deg = res.slope.bound_deg;
        att_get_quat(&e->att, out->q);
        att_get_euler(&e->att, &out->roll_deg, &out->pitch_deg);
        out->att_fault = att_get_status(&e->att);
        *have_out = true;
    }
    return INC_OK;
}
