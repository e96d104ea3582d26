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
    return INC_OK;
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
            app_restart(a);
        } else if (e->since_cal_n < UINT32_MAX) {
            e->since_cal_n++;
        }
    } else if (e->still_n >= e->park_n) {
        e->mode = APP_MODE_PARKED;
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
    if (e->mode == APP_MODE_DRIVING) {
        if (++e->n_out < e->cfg.out_div) return INC_OK;
        e->n_out = 0u;
        out->mode = APP_MODE_DRIVING;
        att_get_quat(&e->att, out->q);
        att_get_euler(&e->att, &out->roll_deg, &out->pitch_deg);
        out->bound_deg = att_get_bound(&e->att);
        out->valid = att_get_valid(&e->att); /* with require_aiding: never without the speed */
        out->att_fault = att_get_status(&e->att);
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
