/*
 * app_eol.c - the on-device end-of-line steps of the EPB application (see app.h).
 *
 * The faces are averaged from the RAW samples (nominal-scaled, no calibration applied, whatever
 * record is loaded): the calibration is being made from them. [ADI-EPB]'s flip gives offset and
 * gain per axis (cal_six_position, which also checks that each face is the one claimed); the
 * gyro offset comes from the same still intervals ([ADI-IMU-QS]: zero rotation, thermally settled),
 * as the mean of the six faces' means so that gravity's small effect on a gyro (g-sensitivity)
 * averages out over opposite faces.
 */
#include "inclino/app.h"

#include <stddef.h>

/* app_eol_face's measurement in the block's memory (app.h); checked arguments. */
static int eol_face(struct app *a, uint32_t n, fx_q16_t max_span_g, fx_q16_t max_span_dps,
                    struct app_face *out)
{
    struct fx_sum temp;
    uint32_t k, flags = SENSOR_S_HAVE_GYRO | SENSOR_S_HAVE_TEMP;
    fx_q16_t acc_mean[3], gyro_mean[3] = {0, 0, 0}, temp_mean = 0;
    unsigned i;
    int err;
    cal_avg_reset(&a->eol_a);
    cal_avg_reset(&a->eol_g);
    fx_sum_reset(&temp);
    for (k = 0; k < n; k++) {
        struct sensor_sample s;
        err = sensor_next(&a->sensor, 0u, &s);
        if (err != INC_OK) {
            return err;
        }
        flags &= s.flags;
        (void)cal_avg_add(&a->eol_a, s.accel_g);
        (void)cal_avg_add(&a->eol_g, s.gyro_dps);
        (void)fx_sum_add(&temp, s.temp_c);
    }
    err = cal_avg_mean(&a->eol_a, max_span_g, acc_mean);
    if (err != INC_OK) {
        return err;
    }
    if ((flags & SENSOR_S_HAVE_GYRO) != 0u) {
        err = cal_avg_mean(&a->eol_g, max_span_dps, gyro_mean);
        if (err != INC_OK) {
            return err;
        }
    }
    if ((flags & SENSOR_S_HAVE_TEMP) != 0u) {
        (void)fx_sum_mean(&temp, &temp_mean);
    }
    for (i = 0; i < 3u; i++) {
        out->accel_g[i] = acc_mean[i];
        out->gyro_dps[i] = gyro_mean[i];
    }
    out->temp_c = temp_mean;
    out->n = n;
    out->flags = flags & (SENSOR_S_HAVE_GYRO | SENSOR_S_HAVE_TEMP);
    return INC_OK;
}

int app_eol_face(struct app *a, uint32_t n, fx_q16_t max_span_g, fx_q16_t max_span_dps,
                 struct app_face *out)
{
    int err;
    if (a == NULL || out == NULL) {
        return INC_ERR_NULL;
    }
    if (!a->ready) {
        return INC_ERR_STATE;
    }
    if (n == 0u || n > FX_SUM_MAX_COUNT) {
        return INC_ERR_INVAL;
    }
    err = eol_face(a, n, max_span_g, max_span_dps, out);
    app_restart(a); /* the block's sums are gone */
    return err;
}

int app_eol_six_position(const struct app_face face[CAL_FACES], struct calrec *rec)
{
    fx_q16_t means[CAL_FACES][3], off[3], goff[3] = {0, 0, 0};
    fx_q30_t gain[3];
    bool gyro = true;
    unsigned f, i;
    int err;
    if (face == NULL || rec == NULL) {
        return INC_ERR_NULL;
    }
    for (f = 0; f < CAL_FACES; f++) {
        for (i = 0; i < 3u; i++) {
            means[f][i] = face[f].accel_g[i];
        }
        gyro = gyro && (face[f].flags & SENSOR_S_HAVE_GYRO) != 0u;
    }
    err = cal_six_position((const fx_q16_t(*)[3])means, off, gain);
    if (err != INC_OK) {
        return err;
    }
    if (gyro) {
        for (i = 0; i < 3u; i++) {
            struct fx_sum s;
            fx_sum_reset(&s);
            for (f = 0; f < CAL_FACES; f++) {
                (void)fx_sum_add(&s, face[f].gyro_dps[i]);
            }
            (void)fx_sum_mean(&s, &goff[i]);
            if (fx_abs(goff[i]) > CAL_GYRO_OFFSET_MAX) {
                return INC_ERR_RANGE;
            }
        }
    }
    for (i = 0; i < 3u; i++) {
        rec->acc_offset[i] = off[i];
        rec->acc_gain[i] = gain[i];
        if (gyro) {
            rec->gyro_offset[i] = goff[i];
        }
    }
    return INC_OK;
}

int app_eol_save(struct app *a, struct calrec *rec, struct calstore *store,
                 struct calstore_info *info)
{
    if (a == NULL || rec == NULL || store == NULL) {
        return INC_ERR_NULL;
    }
    if (!a->ready) {
        return INC_ERR_STATE;
    }
    rec->binding = a->id;
    return calstore_save(store, rec, info);
}

int app_eol_fit_save(struct app *a, const struct app_face face[CAL_FACES], struct calstore *store,
                     struct calstore_info *info)
{
    int err;
    if (a == NULL || face == NULL || store == NULL) {
        return INC_ERR_NULL;
    }
    if (!a->ready) {
        return INC_ERR_STATE;
    }
    /* From here on a->rec is work space: the instance cannot measure with it any more. */
    a->ready = false;
    calrec_set_default(&a->rec);
    err = app_eol_six_position(face, &a->rec);
    if (err == INC_OK) {
        a->rec.binding = a->id;
        err = calstore_save(store, &a->rec, info);
    }
    return err;
}

int app_eol_verify(struct app *a, const struct app_face *f, int face, fx_q16_t tol_g,
                   fx_q16_t *dev_g)
{
    struct cal_acc acc;
    fx_q16_t out[3];
    int64_t dev = 0;
    unsigned i;
    int err;
    if (a == NULL || f == NULL) {
        return INC_ERR_NULL;
    }
    if (!a->ready) {
        return INC_ERR_STATE;
    }
    if (face < 0 || face >= CAL_FACES || tol_g < 0) {
        return INC_ERR_INVAL;
    }
    if (!a->acc.calibrated || !a->rec.valid) {
        return INC_ERR_NOT_CALIBRATED;
    }
    /* a copy evaluated at the face's temperature: the running state is left as it is */
    acc = a->acc;
    if ((f->flags & SENSOR_S_HAVE_TEMP) != 0u) {
        err = cal_acc_set_temp(&acc, f->temp_c);
        if (err != INC_OK) {
            return err == INC_ERR_RANGE ? INC_ERR_NOT_CALIBRATED : err;
        }
    }
    err = cal_acc_apply(&acc, f->accel_g, out);
    if (err != INC_OK) {
        return INC_ERR_RANGE;
    }
    for (i = 0; i < 3u; i++) {
        int64_t ideal = 0, d;
        if ((unsigned)face / 2u == i) {
            ideal = (face & 1) != 0 ? -(int64_t)FX_Q16_ONE : (int64_t)FX_Q16_ONE;
        }
        d = (int64_t)out[i] - ideal;
        d = d < 0 ? -d : d;
        if (d > dev) {
            dev = d;
        }
    }
    if (dev_g != NULL) {
        *dev_g = dev > INT32_MAX ? INT32_MAX : (fx_q16_t)dev;
    }
    return dev <= tol_g ? INC_OK : INC_ERR_RANGE;
}
