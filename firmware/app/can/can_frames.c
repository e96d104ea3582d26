/* can_frames.c - the application's CAN frames; see inclino/can_frames.h and inclino.dbc. */
#include "inclino/can_frames.h"

#define CAN_E2E_CFG(id)                                                \
    {                                                                  \
        .data_id = (id), .len = CAN_DLC, .max_delta_counter_init = 2u, \
        .max_no_new_or_repeated = 3u, .sync_counter_init = 2u          \
    }

static const struct e2e_p01_cfg cfg_slope = CAN_E2E_CFG(CAN_DATAID_SLOPE);
static const struct e2e_p01_cfg cfg_att = CAN_E2E_CFG(CAN_DATAID_ATTITUDE);
static const struct e2e_p01_cfg cfg_status = CAN_E2E_CFG(CAN_DATAID_STATUS);
static const struct e2e_p01_cfg cfg_speed = CAN_E2E_CFG(CAN_DATAID_SPEED);

const struct e2e_p01_cfg *can_e2e_cfg(uint32_t id)
{
    switch (id) {
    case CAN_ID_SLOPE: return &cfg_slope;
    case CAN_ID_ATTITUDE: return &cfg_att;
    case CAN_ID_STATUS: return &cfg_status;
    case CAN_ID_SPEED: return &cfg_speed;
    default: return NULL;
    }
}

int can_tx_init(struct can_tx *tx)
{
    if (tx == NULL) {
        return INC_ERR_NULL;
    }
    (void)e2e_p01_protect_init(&tx->slope);
    (void)e2e_p01_protect_init(&tx->att);
    (void)e2e_p01_protect_init(&tx->status);
    return INC_OK;
}

/* round(v * scale / 2^16), ties away from zero, saturated to int16 (*sat set when clipped) */
static int16_t to_raw_s16(fx_q16_t v, uint32_t scale, bool *sat)
{
    int64_t p = (int64_t)v * (int64_t)scale;
    int64_t r = p >= 0 ? (p + 32768) >> 16 : -((-p + 32768) >> 16);
    if (r > INT16_MAX) {
        *sat = true;
        return INT16_MAX;
    }
    if (r < INT16_MIN) {
        *sat = true;
        return INT16_MIN;
    }
    return (int16_t)r;
}

/* ceil(v * scale / 2^16) for a bound, saturated to uint16; a negative bound is not a bound */
static uint16_t to_raw_bound(fx_q16_t v, uint32_t scale, bool *sat)
{
    if (v < 0) {
        *sat = true;
        return UINT16_MAX;
    }
    int64_t r = ((int64_t)v * (int64_t)scale + 65535) >> 16;
    if (r > UINT16_MAX) {
        *sat = true;
        return UINT16_MAX;
    }
    return (uint16_t)r;
}

static void put16(uint8_t *d, uint16_t v)
{
    d[0] = (uint8_t)(v & 0xFFu);
    d[1] = (uint8_t)(v >> 8);
}

static uint16_t get16(const uint8_t *d)
{
    return (uint16_t)((unsigned)d[0] | ((unsigned)d[1] << 8));
}

static void frame_start(struct can_frame *f, uint32_t id)
{
    f->id = id;
    f->dlc = CAN_DLC;
    for (unsigned i = 0; i < 8u; i++) {
        f->data[i] = 0;
    }
}

uint32_t can_fault_word(uint32_t app_flags, uint32_t slope_flags, uint8_t att_fault, uint32_t extra)
{
    return (app_flags & 0xFFu) | ((slope_flags & 0xFFu) << 8) | ((uint32_t)att_fault << 16) |
           (extra & 0xFF000000u);
}

int can_pack_slope(struct can_tx *tx, const struct slope_result *s, uint8_t mode,
                   struct can_frame *f, struct can_slope_sig *sig, bool *scaling_fault)
{
    if (tx == NULL || s == NULL || f == NULL) {
        return INC_ERR_NULL;
    }
    bool sat = false;
    struct can_slope_sig v;
    v.slope = to_raw_s16(s->slope_deg, CAN_SCALE_ANGLE, &sat);
    v.grade = to_raw_s16(s->grade_pct, CAN_SCALE_GRADE, &sat);
    v.bound = to_raw_bound(s->bound_deg, CAN_SCALE_BOUND, &sat);
    v.valid = s->valid && !sat;
    v.mode = mode != 0u ? 1u : 0u;
    frame_start(f, CAN_ID_SLOPE);
    f->data[1] = (uint8_t)((v.valid ? CAN_B1_VALID : 0u) | (v.mode != 0u ? CAN_B1_MODE : 0u));
    put16(&f->data[2], (uint16_t)v.slope);
    put16(&f->data[4], (uint16_t)v.grade);
    put16(&f->data[6], v.bound);
    if (sig != NULL) {
        *sig = v;
    }
    if (scaling_fault != NULL) {
        *scaling_fault = sat;
    }
    return e2e_p01_protect(&cfg_slope, &tx->slope, f->data, CAN_DLC);
}

int can_pack_attitude(struct can_tx *tx, const struct app_esc_output *o, struct can_frame *f,
                      struct can_att_sig *sig, bool *scaling_fault)
{
    if (tx == NULL || o == NULL || f == NULL) {
        return INC_ERR_NULL;
    }
    bool sat = false;
    struct can_att_sig v;
    v.roll = to_raw_s16(o->roll_deg, CAN_SCALE_ANGLE, &sat);
    v.pitch = to_raw_s16(o->pitch_deg, CAN_SCALE_ANGLE, &sat);
    v.bound = to_raw_bound(o->bound_deg, CAN_SCALE_BOUND, &sat);
    v.valid = o->valid && !sat;
    v.mode = o->mode != 0u ? 1u : 0u;
    frame_start(f, CAN_ID_ATTITUDE);
    f->data[1] = (uint8_t)((v.valid ? CAN_B1_VALID : 0u) | (v.mode != 0u ? CAN_B1_MODE : 0u));
    put16(&f->data[2], (uint16_t)v.roll);
    put16(&f->data[4], (uint16_t)v.pitch);
    put16(&f->data[6], v.bound);
    if (sig != NULL) {
        *sig = v;
    }
    if (scaling_fault != NULL) {
        *scaling_fault = sat;
    }
    return e2e_p01_protect(&cfg_att, &tx->att, f->data, CAN_DLC);
}

int can_pack_status(struct can_tx *tx, uint8_t mode, bool speed_ok, uint32_t fault,
                    fx_q16_t grade_bound_pct, struct can_frame *f, struct can_status_sig *sig)
{
    if (tx == NULL || f == NULL) {
        return INC_ERR_NULL;
    }
    bool sat = false;
    struct can_status_sig v;
    v.grade_bound = to_raw_bound(grade_bound_pct, CAN_SCALE_GBOUND, &sat);
    v.mode = mode != 0u ? 1u : 0u;
    v.speed_ok = speed_ok;
    v.fault = fault | (sat ? CAN_FAULT_SCALING : 0u);
    frame_start(f, CAN_ID_STATUS);
    f->data[1] = (uint8_t)((v.mode != 0u ? CAN_B1_ST_MODE : 0u) |
                           (speed_ok ? CAN_B1_ST_SPEED : 0u));
    put16(&f->data[2], (uint16_t)(v.fault & 0xFFFFu));
    put16(&f->data[4], (uint16_t)(v.fault >> 16));
    put16(&f->data[6], v.grade_bound);
    if (sig != NULL) {
        *sig = v;
    }
    return e2e_p01_protect(&cfg_status, &tx->status, f->data, CAN_DLC);
}

int can_pack_output(struct can_tx *tx, const struct app_esc_output *o, bool speed_ok,
                    struct can_frame frames[2], size_t *n)
{
    if (tx == NULL || o == NULL || frames == NULL || n == NULL) {
        return INC_ERR_NULL;
    }
    *n = 0;
    bool sat = false;
    int rc;
    uint32_t fault;
    fx_q16_t gbound = 0;
    if (o->mode == APP_MODE_PARKED) {
        rc = can_pack_slope(tx, &o->epb.slope, APP_MODE_PARKED, &frames[0], NULL, &sat);
        fault = can_fault_word(o->epb.flags, o->epb.slope.flags, 0u, 0u);
        gbound = o->epb.slope.bound_pct;
    } else if (o->mode == APP_MODE_DRIVING) {
        rc = can_pack_attitude(tx, o, &frames[0], NULL, &sat);
        fault = can_fault_word(0u, 0u, o->att_fault, speed_ok ? 0u : CAN_FAULT_SPEED_INPUT);
    } else {
        return INC_ERR_INVAL;
    }
    if (rc != INC_OK) {
        return rc;
    }
    rc = can_pack_status(tx, o->mode, speed_ok, fault | (sat ? CAN_FAULT_SCALING : 0u), gbound,
                         &frames[1], NULL);
    if (rc != INC_OK) {
        return rc;
    }
    *n = 2;
    return INC_OK;
}

static int check_frame(const struct can_frame *f, uint32_t id)
{
    if (f == NULL) {
        return INC_ERR_NULL;
    }
    return (f->id == id && f->dlc == CAN_DLC) ? INC_OK : INC_ERR_INVAL;
}

int can_unpack_slope(const struct can_frame *f, struct can_slope_sig *s)
{
    int rc = check_frame(f, CAN_ID_SLOPE);
    if (rc != INC_OK || s == NULL) {
        return rc != INC_OK ? rc : INC_ERR_NULL;
    }
    s->valid = (f->data[1] & CAN_B1_VALID) != 0u;
    s->mode = (f->data[1] & CAN_B1_MODE) != 0u ? 1u : 0u;
    s->slope = (int16_t)get16(&f->data[2]);
    s->grade = (int16_t)get16(&f->data[4]);
    s->bound = get16(&f->data[6]);
    return INC_OK;
}

int can_unpack_attitude(const struct can_frame *f, struct can_att_sig *s)
{
    int rc = check_frame(f, CAN_ID_ATTITUDE);
    if (rc != INC_OK || s == NULL) {
        return rc != INC_OK ? rc : INC_ERR_NULL;
    }
    s->valid = (f->data[1] & CAN_B1_VALID) != 0u;
    s->mode = (f->data[1] & CAN_B1_MODE) != 0u ? 1u : 0u;
    s->roll = (int16_t)get16(&f->data[2]);
    s->pitch = (int16_t)get16(&f->data[4]);
    s->bound = get16(&f->data[6]);
    return INC_OK;
}

int can_unpack_status(const struct can_frame *f, struct can_status_sig *s)
{
    int rc = check_frame(f, CAN_ID_STATUS);
    if (rc != INC_OK || s == NULL) {
        return rc != INC_OK ? rc : INC_ERR_NULL;
    }
    s->mode = (f->data[1] & CAN_B1_ST_MODE) != 0u ? 1u : 0u;
    s->speed_ok = (f->data[1] & CAN_B1_ST_SPEED) != 0u;
    s->fault = (uint32_t)get16(&f->data[2]) | ((uint32_t)get16(&f->data[4]) << 16);
    s->grade_bound = get16(&f->data[6]);
    return INC_OK;
}

int can_pack_speed(struct e2e_p01_protect_state *st, bool speed_valid, fx_q16_t speed_mps,
                   bool yaw_valid, fx_q16_t yaw_rate_dps, struct can_frame *f)
{
    if (st == NULL || f == NULL) {
        return INC_ERR_NULL;
    }
    bool sp_sat = false, yr_sat = false;
    int16_t sp = to_raw_s16(speed_mps, CAN_SCALE_SPEED, &sp_sat);
    int16_t yr = to_raw_s16(yaw_rate_dps, CAN_SCALE_YAW, &yr_sat);
    frame_start(f, CAN_ID_SPEED);
    f->data[1] = (uint8_t)((speed_valid && !sp_sat ? CAN_B1_VALID : 0u) |
                           (yaw_valid && !yr_sat ? CAN_B1_MODE : 0u));
    put16(&f->data[2], (uint16_t)sp);
    put16(&f->data[4], (uint16_t)yr);
    return e2e_p01_protect(&cfg_speed, st, f->data, CAN_DLC);
}

int can_speed_rx_init(struct can_speed_rx *rx, uint32_t timeout_cycles)
{
    if (rx == NULL) {
        return INC_ERR_NULL;
    }
    if (timeout_cycles == 0u) {
        return INC_ERR_INVAL;
    }
    (void)e2e_p01_check_init(&rx->e2e);
    rx->last.valid = false;
    rx->last.speed_mps = 0;
    rx->last.yaw_rate_dps = 0;
    rx->age = 0;
    rx->timeout_cycles = timeout_cycles;
    rx->have = false;
    rx->usable = 0;
    rx->rejected = 0;
    return INC_OK;
}

/* raw * 2^16 / 100, rounded to nearest (ties away from zero); exact for |raw| <= 32768 */
static fx_q16_t from_raw_centi(int16_t raw)
{
    int64_t p = (int64_t)raw * 65536;
    int64_t r = p >= 0 ? (p + 50) / 100 : -((-p + 50) / 100);
    return (fx_q16_t)r;
}

int can_speed_rx_cycle(struct can_speed_rx *rx, const struct can_frame *f, struct app_vehicle *out)
{
    if (rx == NULL || out == NULL) {
        return INC_ERR_NULL;
    }
    out->valid = false;
    out->speed_mps = 0;
    out->yaw_rate_dps = 0;
    if (rx->timeout_cycles == 0u) {
        return INC_ERR_STATE;
    }
    int rc;
    if (f == NULL) {
        rc = e2e_p01_check(&cfg_speed, &rx->e2e, NULL, 0u, false);
    } else {
        /* another identifier or length never passes: it is checked as a frame of length 0 */
        size_t len = (f->id == CAN_ID_SPEED && f->dlc <= 8u) ? f->dlc : 0u;
        rc = e2e_p01_check(&cfg_speed, &rx->e2e, f->data, len, true);
    }
    if (rc != INC_OK) {
        rx->have = false;
        return rc;
    }
    if (rx->age < UINT32_MAX) {
        rx->age++;
    }
    if (f != NULL) {
        bool ok = e2e_p01_usable(rx->e2e.status);
        int16_t sp = (int16_t)get16(&f->data[2]);
        int16_t yr = (int16_t)get16(&f->data[4]);
        ok = ok && (f->data[1] & CAN_B1_VALID) != 0u && (f->data[1] & CAN_B1_MODE) != 0u &&
             sp <= CAN_SPEED_MAX_RAW && sp >= -CAN_SPEED_MAX_RAW;
        if (ok) {
            rx->last.valid = true;
            rx->last.speed_mps = from_raw_centi(sp);
            rx->last.yaw_rate_dps = from_raw_centi(yr);
            rx->age = 0;
            rx->have = true;
            rx->usable++;
        } else {
            rx->rejected++;
        }
    }
    if (rx->have && rx->age <= rx->timeout_cycles) {
        *out = rx->last;
    }
    return INC_OK;
}
