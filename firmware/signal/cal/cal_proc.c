/*
 * cal_proc.c - the on-device calibration procedures (see inclino/cal.h).
 *
 * [ADI-EPB] ("tilt accuracy with accelerometers", ADI): one-point 0 g offset; +-1 g flip with
 * offset = (A+ + A-)/2 and gain = (A+ - A-)/2. The article prints the gain as 0.5 * (A+ - A-)/2;
 * with A+ = +1 g and A- = -1 g that gives 0.5 for a perfect part, so a_true = a_out / gain would
 * read double: the 0.5 is a misprint (docs/references.md, [ADI-EPB]). Six-position = one flip per
 * axis, with a check that each face is the one claimed. The gyro offset comes from a still
 * interval and the scale from a turn of a known angle ([ADI-IMU-QS] does the same with its autonull
 * and manual calibration).
 */
#include "inclino/cal.h"

#include <stddef.h>

void cal_avg_reset(struct cal_avg *a)
{
    unsigned i;
    if (a == NULL) {
        return;
    }
    for (i = 0; i < 3u; i++) {
        fx_sum_reset(&a->sum[i]);
        a->min[i] = INT32_MAX;
        a->max[i] = INT32_MIN;
    }
}

int cal_avg_add(struct cal_avg *a, const int32_t s[3])
{
    unsigned i;
    if (a == NULL || s == NULL) {
        return INC_ERR_NULL;
    }
    if (a->sum[0].count >= FX_SUM_MAX_COUNT) {
        return INC_ERR_OVERFLOW; /* all three counts move together */
    }
    for (i = 0; i < 3u; i++) {
        (void)fx_sum_add(&a->sum[i], s[i]);
        a->min[i] = s[i] < a->min[i] ? s[i] : a->min[i];
        a->max[i] = s[i] > a->max[i] ? s[i] : a->max[i];
    }
    return INC_OK;
}

int cal_avg_mean(const struct cal_avg *a, int32_t max_span, int32_t mean[3])
{
    int32_t m[3];
    unsigned i;
    if (a == NULL || mean == NULL) {
        return INC_ERR_NULL;
    }
    if (max_span < 0) {
        return INC_ERR_INVAL;
    }
    if (a->sum[0].count == 0u) {
        return INC_ERR_STATE;
    }
    for (i = 0; i < 3u; i++) {
        /* The span in int64: max - min can reach 2^32 - 1. */
        if ((int64_t)a->max[i] - a->min[i] > max_span) {
            return INC_ERR_MOTION;
        }
        (void)fx_sum_mean(&a->sum[i], &m[i]);
    }
    for (i = 0; i < 3u; i++) {
        mean[i] = m[i];
    }
    return INC_OK;
}

int cal_one_point(const fx_q16_t mean[3], const fx_q16_t expect[3], fx_q16_t offset[3])
{
    int64_t o[3];
    unsigned i;
    if (mean == NULL || expect == NULL || offset == NULL) {
        return INC_ERR_NULL;
    }
    for (i = 0; i < 3u; i++) {
        if (expect[i] > CAL_ONE_G || expect[i] < -CAL_ONE_G) {
            return INC_ERR_RANGE;
        }
        o[i] = (int64_t)mean[i] - expect[i];
        if (o[i] > CAL_OFFSET_MAX || o[i] < -CAL_OFFSET_MAX) {
            return INC_ERR_RANGE;
        }
    }
    for (i = 0; i < 3u; i++) {
        offset[i] = (fx_q16_t)o[i];
    }
    return INC_OK;
}

/* The flip of one axis without writing anything: 0 or the error. */
static int flip(fx_q16_t a_pos, fx_q16_t a_neg, fx_q16_t *offset, fx_q30_t *gain)
{
    int64_t diff, g, o;
    if (a_pos <= a_neg) {
        return INC_ERR_DEGENERATE;
    }
    /* gain = (A+ - A-)/2 in g/g; from Q16 to Q30 that is (A+ - A-) * 2^13, exact. diff <= 2^32,
     * so the product stays below 2^45. */
    diff = (int64_t)a_pos - a_neg;
    g = diff * 8192;
    if (g < CAL_GAIN_MIN || g > CAL_GAIN_MAX) {
        return INC_ERR_RANGE;
    }
    o = fx_rshift_round64((int64_t)a_pos + a_neg, 1u);
    if (o > CAL_OFFSET_MAX || o < -CAL_OFFSET_MAX) {
        return INC_ERR_RANGE;
    }
    *offset = (fx_q16_t)o;
    *gain = (fx_q30_t)g;
    return INC_OK;
}

int cal_flip(fx_q16_t a_pos, fx_q16_t a_neg, fx_q16_t *offset, fx_q30_t *gain)
{
    fx_q16_t o;
    fx_q30_t g;
    int err;
    if (offset == NULL || gain == NULL) {
        return INC_ERR_NULL;
    }
    err = flip(a_pos, a_neg, &o, &g);
    if (err == INC_OK) {
        *offset = o;
        *gain = g;
    }
    return err;
}

int cal_six_position(const fx_q16_t face[CAL_FACES][3], fx_q16_t offset[3], fx_q30_t gain[3])
{
    fx_q16_t o[3];
    fx_q30_t g[3];
    unsigned f, i, j;
    if (face == NULL || offset == NULL || gain == NULL) {
        return INC_ERR_NULL;
    }
    for (f = 0; f < CAL_FACES; f++) {
        const unsigned axis = f / 2u;
        const bool up = (f % 2u) == 0u;
        const fx_q16_t v = face[f][axis];
        /* The axis under test reads about +-1 g, the others about 0 g (within the offset and
         * cross-axis limits): a face recorded in the wrong slot shows up here. */
        if (up ? v <= 0 : v >= 0) {
            return INC_ERR_DEGENERATE;
        }
        for (j = 0; j < 3u; j++) {
            if (j != axis && fx_uabs32(face[f][j]) >= fx_uabs32(v)) {
                return INC_ERR_DEGENERATE;
            }
        }
    }
    for (i = 0; i < 3u; i++) {
        const int err = flip(face[2u * i][i], face[2u * i + 1u][i], &o[i], &g[i]);
        if (err != INC_OK) {
            return err;
        }
    }
    for (i = 0; i < 3u; i++) {
        offset[i] = o[i];
        gain[i] = g[i];
    }
    return INC_OK;
}

int cal_gyro_offset(const struct cal_avg *still, int32_t max_span, fx_q16_t offset[3])
{
    int32_t m[3];
    unsigned i;
    int err;
    if (still == NULL || offset == NULL) {
        return INC_ERR_NULL;
    }
    err = cal_avg_mean(still, max_span, m);
    if (err != INC_OK) {
        return err;
    }
    for (i = 0; i < 3u; i++) {
        if (m[i] > CAL_GYRO_OFFSET_MAX || m[i] < -CAL_GYRO_OFFSET_MAX) {
            return INC_ERR_RANGE;
        }
    }
    for (i = 0; i < 3u; i++) {
        offset[i] = m[i];
    }
    return INC_OK;
}

/* 2^30 degrees in Q32: the accumulated angle never passes it (a turn is a few hundred degrees;
 * the margin keeps the int64 sum away from overflow for any sample). */
#define TURN_ANGLE_MAX ((int64_t)1 << 62)

int cal_turn_start(struct cal_turn *t, const fx_q16_t offset[3], fx_q30_t dt)
{
    unsigned i;
    if (t == NULL || offset == NULL) {
        return INC_ERR_NULL;
    }
    if (dt <= 0 || dt > FX_Q30_ONE) {
        return INC_ERR_INVAL;
    }
    for (i = 0; i < 3u; i++) {
        t->angle_q32[i] = 0;
        t->offset[i] = offset[i];
    }
    t->dt = dt;
    t->n = 0;
    return INC_OK;
}

int cal_turn_add(struct cal_turn *t, const fx_q16_t rate[3])
{
    int64_t inc[3];
    unsigned i;
    if (t == NULL || rate == NULL) {
        return INC_ERR_NULL;
    }
    if (t->n == UINT32_MAX) {
        return INC_ERR_OVERFLOW;
    }
    for (i = 0; i < 3u; i++) {
        if (rate[i] > CAL_GYRO_IN_MAX || rate[i] < -CAL_GYRO_IN_MAX) {
            return INC_ERR_RANGE;
        }
        /* (rate - offset) in deg/s Q16 (|.| < 2^28) times dt in s Q30 (<= 2^30) is exact in
         * int64 (< 2^58); rounded to Q32 degrees it is < 2^44 per sample. */
        inc[i] = fx_rshift_round64(((int64_t)rate[i] - t->offset[i]) * t->dt, 14u);
        if (t->angle_q32[i] + inc[i] > TURN_ANGLE_MAX ||
            t->angle_q32[i] + inc[i] < -TURN_ANGLE_MAX) {
            return INC_ERR_OVERFLOW;
        }
    }
    for (i = 0; i < 3u; i++) {
        t->angle_q32[i] += inc[i];
    }
    t->n++;
    return INC_OK;
}

int cal_turn_scale(const struct cal_turn *t, unsigned axis, fx_q16_t known_deg, fx_q30_t *scale)
{
    int64_t a;
    int32_t s;
    if (t == NULL || scale == NULL) {
        return INC_ERR_NULL;
    }
    if (axis > 2u || fx_uabs32(known_deg) < (uint32_t)FX_DEG_90) {
        return INC_ERR_INVAL;
    }
    if (t->n == 0u) {
        return INC_ERR_STATE;
    }
    a = fx_rshift_round64(t->angle_q32[axis], 16u); /* Q32 -> Q16 degrees */
    if (a > INT32_MAX || a < INT32_MIN) {
        return INC_ERR_RANGE;
    }
    if (a == 0 || (a < 0) != (known_deg < 0)) {
        return INC_ERR_DEGENERATE;
    }
    if (fx_div((int32_t)a, known_deg, FX_Q30_SHIFT, &s) != INC_OK || s < CAL_GAIN_MIN ||
        s > CAL_GAIN_MAX) {
        return INC_ERR_RANGE;
    }
    *scale = s;
    return INC_OK;
}
