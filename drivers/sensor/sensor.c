/*
 * sensor.c - call wrappers of the sensor interface (see inclino/sensor.h).
 */
#include "inclino/sensor.h"

#include <stddef.h>

void sensor_sample_clear(struct sensor_sample *out)
{
    if (out == NULL) return;
    unsigned i;
    for (i = 0; i < 3u; i++) {
        out->accel_g[i] = 0;
        out->gyro_dps[i] = 0;
    }
    out->temp_c = 0;
    out->flags = 0u;
    out->missed = 0u;
    out->t_ns = 0u;
}

int sensor_init(const struct sensor *s, const void *cfg)
{
    if (s == NULL || s->ops == NULL || s->ops->init == NULL) return INC_ERR_NULL;
    return s->ops->init(s->dev, cfg);
}

int sensor_wait_ready(const struct sensor *s, uint32_t timeout_ns)
{
    if (s == NULL || s->ops == NULL || s->ops->wait_ready == NULL) return INC_ERR_NULL;
    return s->ops->wait_ready(s->dev, timeout_ns);
}

int sensor_read(const struct sensor *s, struct sensor_sample *out)
{
    int err;
    if (out == NULL) return INC_ERR_NULL;
    if (s == NULL || s->ops == NULL || s->ops->read == NULL) {
        sensor_sample_clear(out);
        return INC_ERR_NULL;
    }
    err = s->ops->read(s->dev, out);
    if (err != INC_OK) sensor_sample_clear(out);
    return err;
}

int sensor_read_diag(const struct sensor *s, struct sensor_diag *out)
{
    if (s == NULL || s->ops == NULL || s->ops->read_diag == NULL || out == NULL)
        return INC_ERR_NULL;
    return s->ops->read_diag(s->dev, out);
}

int sensor_self_test(const struct sensor *s, struct sensor_diag *out)
{
    if (s == NULL || s->ops == NULL || s->ops->self_test == NULL || out == NULL)
        return INC_ERR_NULL;
    return s->ops->self_test(s->dev, out);
}

int sensor_get_identity(const struct sensor *s, struct sensor_identity *out)
{
    if (s == NULL || s->ops == NULL || s->ops->identity == NULL || out == NULL) return INC_ERR_NULL;
    return s->ops->identity(s->dev, out);
}

int sensor_get_info(const struct sensor *s, struct sensor_info *out)
{
    if (s == NULL || s->ops == NULL || s->ops->info == NULL || out == NULL) return INC_ERR_NULL;
    return s->ops->info(s->dev, out);
}

int sensor_next(const struct sensor *s, uint32_t timeout_ns, struct sensor_sample *out)
{
    int err;
    if (out == NULL) {
        return INC_ERR_NULL; /* before the wait: no sample is consumed for nothing */
    }
    err = sensor_wait_ready(s, timeout_ns);
    if (err == INC_OK) {
        err = sensor_read(s, out);
        if (err == INC_ERR_STALE) {
            err = sensor_wait_ready(s, timeout_ns);
            if (err == INC_OK) err = sensor_read(s, out);
        }
    }
    if (err != INC_OK) sensor_sample_clear(out);
    return err;
}

void sensor_identity_clear(struct sensor_identity *out)
{
    if (out == NULL) return;
    out->family = (uint32_t)SENSOR_FAMILY_NONE;
    out->product = 0u;
    out->revision = 0u;
    out->serial = 0u;
    out->lot_id1 = 0u;
    out->lot_id2 = 0u;
}

void sensor_diag_clear(struct sensor_diag *out)
{
    if (out == NULL) return;
    out->flags = 0u;
    out->raw = 0u;
    out->supply_v = 0;
}
