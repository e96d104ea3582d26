/*
 * sca3000_sensor.c - the SCA3000 driver as a struct sensor (see sca3000.h, the end of the file;
 * docs/drivers-sca3000.md, "Sensor interface").
 *
 * No source describes a new-data interrupt for direct measurement mode, so the output data rate
 * paces the reads (sca3000_wait_ready). The part latches X, Y, Z together when CS falls (one CS
 * period reads a coherent set: the driver reads them in one burst). Being late by whole periods
 * is reported as missed samples; a sample lost within one period cannot be seen without a
 * data-ready line.
 */
#include <stddef.h>

#include "inclino/fx.h"
#include "inclino/sca3000.h"

/* Ends of the 13-bit output range. */
#define COUNT_MIN (-4096)
#define COUNT_MAX 4095

static const uint32_t product_code[4] = {SCA3000_PRODUCT_D01, SCA3000_PRODUCT_E02,
                                         SCA3000_PRODUCT_E04, SCA3000_PRODUCT_E05};

static int op_init(void *ctx, const void *cfg)
{
    return sca3000_init(ctx, cfg);
}

static int op_wait_ready(void *ctx, uint32_t timeout_ns)
{
    return sca3000_wait_ready(ctx, timeout_ns, NULL);
}

static int op_read(void *ctx, struct sensor_sample *out)
{
    struct sca3000 *dev = ctx;
    struct sca3000_sample s;
    unsigned i;
    int err;
    if (dev == NULL || out == NULL) {
        return INC_ERR_NULL;
    }
    err = sca3000_read_sample(dev, &s);
    if (err != INC_OK) {
        return err;
    }
    out->flags = SENSOR_S_HAVE_ACCEL;
    for (i = 0; i < 3u && err == INC_OK; i++) {
        err = sca3000_accel_g_from_counts(s.xyz[i], dev->variant, &out->accel_g[i]);
        out->gyro_dps[i] = 0;
        if (s.xyz[i] <= COUNT_MIN || s.xyz[i] >= COUNT_MAX) {
            out->flags |= SENSOR_S_ACCEL_SAT_X << i;
        }
    }
    out->temp_c = 0;
    if (err == INC_OK && s.temp_valid) {
        err = sca3000_temp_c_from_counts(s.temp_raw, &out->temp_c);
        out->flags |= SENSOR_S_HAVE_TEMP;
    }
    if (err != INC_OK) {
        return err; /* the wrapper (sensor_read) zeroes the sample */
    }
    out->missed = dev->pace_missed;
    out->t_ns = dev->sample_ns;
    return INC_OK;
}

static int op_read_diag(void *ctx, struct sensor_diag *out)
{
    struct sca3000 *dev = ctx;
    uint8_t st = 0;
    int err;
    if (dev == NULL || out == NULL) {
        return INC_ERR_NULL;
    }
    sensor_diag_clear(out);
    err = sca3000_read_diag(dev, &st);
    if (err != INC_OK && err != INC_ERR_DEVICE) {
        return err;
    }
    /* INC_ERR_DEVICE: the part reports an error; the read itself worked */
    if ((st & SCA3000_STATUS_FRAME) != 0u) out->flags |= SENSOR_D_BUS;
    if ((st & SCA3000_STATUS_EEPROM) != 0u) out->flags |= SENSOR_D_MEMORY;
    out->raw = st;
    return INC_OK;
}

/* The signature is the ops table's (ctx is not const there). */
/* cppcheck-suppress constParameter */
static int op_self_test(void *ctx, struct sensor_diag *out)
{
    if (ctx == NULL || out == NULL) {
        return INC_ERR_NULL;
    }
    sensor_diag_clear(out);
    return INC_ERR_UNSUPPORTED;
}

static int op_identity(void *ctx, struct sensor_identity *out)
{
    const struct sca3000 *dev = ctx;
    if (dev == NULL || out == NULL) {
        return INC_ERR_NULL;
    }
    sensor_identity_clear(out);
    if (!dev->ready) {
        return INC_ERR_STATE;
    }
    if ((unsigned)dev->variant >= 4u) {
        return INC_ERR_UNSUPPORTED;
    }
    out->family = (uint32_t)SENSOR_FAMILY_SCA3000;
    out->product = product_code[dev->variant];
    out->revision = sca3000_revid(dev);
    return INC_OK;
}

static int op_info(void *ctx, struct sensor_info *out)
{
    const struct sca3000 *dev = ctx;
    if (dev == NULL || out == NULL) {
        return INC_ERR_NULL;
    }
    out->accel_fs_g = 0;
    out->gyro_fs_dps = 0;
    out->rate_mhz = 0u;
    if (!dev->ready) {
        return INC_ERR_STATE;
    }
    /* 4096 counts x the LSB (ug) in g Q16 */
    out->accel_fs_g = fx_div64((int64_t)4096 * sca3000_ug_per_lsb(dev->variant) * 65536, 1000000u);
    out->rate_mhz = sca3000_odr_mhz(dev);
    return INC_OK;
}

const struct sensor_ops sca3000_sensor_ops = {op_init,      op_wait_ready, op_read, op_read_diag,
                                              op_self_test, op_identity,   op_info};
