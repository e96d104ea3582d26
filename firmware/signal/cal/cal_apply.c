/*
 * cal_apply.c - per-temperature and per-sample correction with a calibration record (see
 * inclino/cal.h for the chain and the bounds).
 *
 * The split follows the cost: the temperature models (divisions, the Lorentz quotient) change
 * with the temperature only, so cal_acc_set_temp folds them into one offset and one reciprocal
 * scale per axis; a sample then needs no division at all (Cortex-M0+ has no divider). The
 * nonlinearity is applied per element, before the misalignment matrix, because it belongs to
 * the sensing element (the station fits it that way, docs/calibration.md); the record's
 * matrix mixes the linearised element outputs.
 */
#include "inclino/cal.h"

#include <stddef.h>

static void acc_passthrough(struct cal_acc *st)
{
    unsigned i;
    for (i = 0; i < 3u; i++) {
        st->off[i] = 0;
        st->inv_gain[i] = FX_Q30_ONE;
    }
    st->calibrated = false;
}

int cal_acc_init(struct cal_acc *st, const struct calrec *rec, fx_q16_t t_c)
{
    if (st == NULL) {
        return INC_ERR_NULL;
    }
    st->rec = NULL;
    st->t_c = t_c;
    acc_passthrough(st);
    if (rec == NULL || !rec->valid) {
        return INC_ERR_NOT_CALIBRATED;
    }
    if (calrec_check(rec) != INC_OK) {
        return INC_ERR_RANGE;
    }
    st->rec = rec;
    return cal_acc_set_temp(st, t_c);
}

int cal_acc_set_temp(struct cal_acc *st, fx_q16_t t_c)
{
    fx_q16_t off[3];
    fx_q30_t inv[3];
    unsigned i;
    if (st == NULL) {
        return INC_ERR_NULL;
    }
    if (st->rec == NULL) {
        return INC_ERR_NOT_CALIBRATED;
    }
    st->t_c = t_c;
    for (i = 0; i < 3u; i++) {
        int32_t b, s;
        fx_q30_t k;
        int err = cal_tmodel_eval(&st->rec->acc_tbias[i], t_c, &b);
        if (err == INC_OK) {
            err = cal_tmodel_eval(&st->rec->acc_tscale[i], t_c, &s);
        }
        if (err != INC_OK) {
            acc_passthrough(st);
            return err;
        }
        off[i] = fx_add(st->rec->acc_offset[i], b);
        k = fx_mul_q30(st->rec->acc_gain[i], fx_add(FX_Q30_ONE, s));
        if (off[i] > CAL_BEFF_MAX || off[i] < -CAL_BEFF_MAX || k < CAL_KEFF_MIN ||
            k > CAL_KEFF_MAX) {
            acc_passthrough(st);
            return INC_ERR_RANGE;
        }
        (void)fx_recip_q30(k, &inv[i]); /* k >= 0.625: 1/k <= 1.6 fits Q30 */
    }
    for (i = 0; i < 3u; i++) {
        st->off[i] = off[i];
        st->inv_gain[i] = inv[i];
    }
    st->calibrated = true;
    return INC_OK;
}

int cal_acc_apply(const struct cal_acc *st, const fx_q16_t in[3], fx_q16_t out[3])
{
    fx_q16_t n[3];
    bool range = false;
    unsigned i;
    if (st == NULL || in == NULL || out == NULL) {
        return INC_ERR_NULL;
    }
    if (!st->calibrated || st->rec == NULL) {
        for (i = 0; i < 3u; i++) {
            out[i] = in[i];
        }
        return INC_ERR_NOT_CALIBRATED;
    }
    for (i = 0; i < 3u; i++) {
        const int32_t *c = st->rec->acc_nonlin[i];
        fx_q16_t v, x;
        int32_t h;
        range = range || in[i] > CAL_ACC_IN_MAX || in[i] < -CAL_ACC_IN_MAX;
        /* [ADI-EPB]: a_true = (a_out - offset) / gain, with the temperature-corrected terms. */
        v = fx_mul_q16_q30(fx_sub(in[i], st->off[i]), st->inv_gain[i]);
        /* Cubic in Q30 (c in Q30, x in Q16 g): ((c3 x + c2) x + c1) x + c0; every partial sum
         * stays below 1.03 for |x| <= 1.25 g and coefficients within the record limits. */
        x = fx_clamp(v, -CAL_NONLIN_X_MAX, CAL_NONLIN_X_MAX);
        h = fx_add(fx_mul_shift(c[3], x, FX_Q16_SHIFT), c[2]);
        h = fx_add(fx_mul_shift(h, x, FX_Q16_SHIFT), c[1]);
        h = fx_add(fx_mul_shift(h, x, FX_Q16_SHIFT), c[0]);
        n[i] = fx_add(v, fx_q30_to_q16(h));
    }
    for (i = 0; i < 3u; i++) {
        const int32_t *m = st->rec->acc_misalign[i];
        /* |row sum of M| <= 1.5 (record limits), |n| < 2^31: the sum stays below 1.5 * 2^61. */
        const int64_t acc = (int64_t)m[0] * n[0] + (int64_t)m[1] * n[1] + (int64_t)m[2] * n[2];
        out[i] = fx_sat32(fx_rshift_round64(acc, FX_Q30_SHIFT));
    }
    return range ? INC_ERR_RANGE : INC_OK;
}

int cal_gyro_init(struct cal_gyro *g, const struct calrec *rec)
{
    fx_q30_t inv[3];
    unsigned i;
    if (g == NULL) {
        return INC_ERR_NULL;
    }
    for (i = 0; i < 3u; i++) {
        g->off[i] = 0;
        g->inv_scale[i] = FX_Q30_ONE;
    }
    g->calibrated = false;
    if (rec == NULL || !rec->valid) {
        return INC_ERR_NOT_CALIBRATED;
    }
    if (calrec_check(rec) != INC_OK) {
        return INC_ERR_RANGE;
    }
    for (i = 0; i < 3u; i++) {
        (void)fx_recip_q30(rec->gyro_scale[i], &inv[i]); /* scale in [0.75, 1.25] */
    }
    for (i = 0; i < 3u; i++) {
        g->off[i] = rec->gyro_offset[i];
        g->inv_scale[i] = inv[i];
    }
    g->calibrated = true;
    return INC_OK;
}

int cal_gyro_apply(const struct cal_gyro *g, const fx_q16_t in[3], fx_q16_t out[3])
{
    bool range = false;
    unsigned i;
    if (g == NULL || in == NULL || out == NULL) {
        return INC_ERR_NULL;
    }
    if (!g->calibrated) {
        for (i = 0; i < 3u; i++) {
            out[i] = in[i];
        }
        return INC_ERR_NOT_CALIBRATED;
    }
    for (i = 0; i < 3u; i++) {
        range = range || in[i] > CAL_GYRO_IN_MAX || in[i] < -CAL_GYRO_IN_MAX;
        out[i] = fx_mul_q16_q30(fx_sub(in[i], g->off[i]), g->inv_scale[i]);
    }
    return range ? INC_ERR_RANGE : INC_OK;
}
