/*
 * adis16255_sensor.c - the ADIS16250/16255 driver as a struct sensor (see adis16255.h, the
 * end of the file; docs/drivers-adis16255.md, "Sensor interface").
 *
 * A single-axis gyro: its rate goes to gyro_dps[2] (z, the axis normal to the package top),
 * with TEMP_OUT; there is no accelerometer.
 */
#include <stddef.h>

#include "inclino/adis16255.h"
#include "inclino/fx.h"

#define GYRO_AXIS 2u /* z */

/* Ends of the 14-bit GYRO_OUT range: a count there may be a clipped value. */
#define COUNT_MIN (-8192)
#define COUNT_MAX 8191

static int op_init(void *ctx, const void *cfg)
{
    return adis16255_init(ctx, cfg);
}

static int op_wait_ready(void *ctx, uint32_t timeout_ns)
{
    struct adis16255 *dev = ctx;
    uint32_t missed = 0;
    int err;
    if (dev == NULL) {
        return INC_ERR_NULL;
    }
    err = adis16255_wait_ready(dev, timeout_ns, &missed);
    dev->sensor_missed = err == INC_OK ? dev->sensor_missed + missed : 0u;
    return err;
}

static int op_read(void *ctx, struct sensor_sample *out)
{
    struct adis16255 *dev = ctx;
    struct adis16255_sample s;
    int32_t c;
    int err;
    if (dev == NULL || out == NULL) {
        return INC_ERR_NULL;
    }
    err = adis16255_read_sample(dev, &s);
    if (err != INC_OK) {
        dev->sensor_missed = err == INC_ERR_STALE ? dev->sensor_missed + 1u : 0u;
        return err;
    }
    sensor_sample_clear(out);
    out->gyro_dps[GYRO_AXIS] = s.rate_dps_q16;
    out->temp_c = s.temp_c_q16;
    out->flags = SENSOR_S_HAVE_GYRO | SENSOR_S_HAVE_TEMP;
    c = adis_sign_extend(s.gyro_word, ADIS16255_GYRO_BITS);
    if (c <= COUNT_MIN || c >= COUNT_MAX) {
        out->flags |= SENSOR_S_GYRO_SAT_X << GYRO_AXIS;
    }
    out->missed = dev->sensor_missed;
    out->t_ns = s.t_ns;
    dev->sensor_missed = 0u;
    return INC_OK;
}

static uint32_t diag_flags(const struct adis16255_status *st)
{
    uint32_t f = 0u;
    if (st->supply_low || st->supply_high) f |= SENSOR_D_SUPPLY;
    if (st->self_test_fail) f |= SENSOR_D_SELF_TEST;
    if (st->overrange) f |= SENSOR_D_OVERRANGE;
    if (st->spi_fail) f |= SENSOR_D_BUS;
    if (st->flash_update_fail || st->flash_checksum) f |= SENSOR_D_MEMORY;
    if (st->alarm1 || st->alarm2) f |= SENSOR_D_ALARM;
    return f;
}

static int op_read_diag(void *ctx, struct sensor_diag *out)
{
    struct adis16255 *dev = ctx;
    struct adis16255_status st;
    int32_t v = 0;
    int err;
    if (dev == NULL || out == NULL) {
        return INC_ERR_NULL;
    }
    sensor_diag_clear(out);
    err = adis16255_read_diag(dev, &st);
    if (err == INC_OK) {
        err = adis16255_read_supply(dev, &v);
        if (err == INC_ERR_STALE) {
            err = INC_OK; /* no new supply reading since the last one: none reported */
        }
    }
    if (err != INC_OK) {
        return err;
    }
    out->flags = diag_flags(&st);
    out->raw = st.raw;
    out->supply_v = v;
    return INC_OK;
}

static int op_self_test(void *ctx, struct sensor_diag *out)
{
    struct adis16255 *dev = ctx;
    int err;
    if (dev == NULL || out == NULL) {
        return INC_ERR_NULL;
    }
    sensor_diag_clear(out);
    err = adis16255_self_test(dev);
    if (err == INC_OK || err == INC_ERR_DEVICE) {
        out->flags = diag_flags(&dev->status);
        out->raw = dev->status.raw;
    }
    return err;
}

static int op_identity(void *ctx, struct sensor_identity *out)
{
    const struct adis16255 *dev = ctx;
    if (dev == NULL || out == NULL) {
        return INC_ERR_NULL;
    }
    sensor_identity_clear(out);
    if (!dev->ready) {
        return INC_ERR_STATE;
    }
    out->family = (uint32_t)SENSOR_FAMILY_ADIS1625X;
    out->product = 16255u;
    return INC_OK;
}

static int op_info(void *ctx, struct sensor_info *out)
{
    const struct adis16255 *dev = ctx;
    uint32_t us;
    if (dev == NULL || out == NULL) {
        return INC_ERR_NULL;
    }
    out->accel_fs_g = 0;
    out->gyro_fs_dps = 0;
    out->rate_mhz = 0u;
    if (!dev->ready) {
        return INC_ERR_STATE;
    }
    /* range code 1, 2, 4 = +-80, 160, 320 deg/s */
    out->gyro_fs_dps = FX_Q16_INT(80 * (int32_t)dev->cfg.range);
    us = adis16255_sample_period_us((uint8_t)dev->smpl_prd);
    out->rate_mhz = us != 0u ? (uint32_t)((1000000000ull + us / 2u) / us) : 0u;
    return INC_OK;
}

const struct sensor_ops adis16255_sensor_ops = {op_init,      op_wait_ready, op_read, op_read_diag,
                                                op_self_test, op_identity,   op_info};
