/*
 * adis_imu_sensor.c - the ADIS1636x/1640x driver as a struct sensor (see adis_imu.h,
 * "Settings in force and the sensor interface"; docs/drivers-adis-imu.md, "Sensor interface").
 *
 * One sample = one data-ready edge + one burst read: the burst returns every output of one
 * sample set in one CS period, so the axes are coherent (docs/sensor-facts.md §3.1).
 * Conversions are the driver's, exact to 0.5 LSB Q16.
 */
#include <stddef.h>

#include "adis_imu_regs.h"
#include "inclino/adis_imu.h"
#include "inclino/fx.h"

/* Ends of the 14-bit output range: a count there may be a clipped value. */
#define COUNT_MIN (-8192)
#define COUNT_MAX 8191

static bool at_end(int32_t c)
{
    return c <= COUNT_MIN || c >= COUNT_MAX;
}

int adis_imu_get_settings(const struct adis_imu *dev, struct adis_imu_settings *out)
{
    if (dev == NULL || out == NULL) {
        return INC_ERR_NULL;
    }
    out->smpl_prd = 0u;
    out->sens_avg = 0u;
    out->taps_log2 = 0u;
    out->range = 0u;
    out->dr_enabled = false;
    if (!dev->ready) {
        return INC_ERR_STATE;
    }
    out->smpl_prd = (uint8_t)dev->smpl_prd;
    out->sens_avg = dev->sens_avg;
    out->taps_log2 = (uint8_t)(dev->sens_avg & ADIS_IMU_SENS_AVG_M_MASK);
    out->range = (uint8_t)adis_imu_gyro_range(dev);
    out->dr_enabled = dev->dr_enabled;
    return INC_OK;
}

const struct hal *adis_imu_hal(const struct adis_imu *dev)
{
    return dev != NULL ? dev->cfg.hal : NULL;
}

int adis_imu_read_identity(struct adis_imu *dev, struct sensor_identity *out)
{
    uint16_t prod = 0, serial = 0, lot1 = 0, lot2 = 0;
    int err;
    if (dev == NULL || out == NULL) {
        return INC_ERR_NULL;
    }
    sensor_identity_clear(out);
    if (!dev->ready || dev->info == NULL) {
        return INC_ERR_STATE;
    }
    err = adis_imu_found(dev, &prod, NULL);
    if (err == INC_OK && dev->info->family == (uint8_t)ADIS_IMU_FAMILY_1636X) {
        /* The 1636x has a serial number and lot ids (the calrec.h binding table). */
        err = adis_imu_read_known(dev, ADIS1636X_REG_SERIAL_NUM, &serial);
        if (err == INC_OK) err = adis_imu_read_known(dev, ADIS1636X_REG_LOT_ID1, &lot1);
        if (err == INC_OK) err = adis_imu_read_known(dev, ADIS1636X_REG_LOT_ID2, &lot2);
    }
    if (err != INC_OK) {
        return err;
    }
    out->family = (uint32_t)SENSOR_FAMILY_ADIS163XX;
    out->product = prod;
    out->serial = serial;
    out->lot_id1 = lot1;
    out->lot_id2 = lot2;
    return INC_OK;
}

/* ---- the ops ------------------------------------------------------------------------------ */

static int op_init(void *ctx, const void *cfg)
{
    return adis_imu_init(ctx, cfg);
}

static int op_wait_ready(void *ctx, uint32_t timeout_ns)
{
    struct adis_imu *dev = ctx;
    uint32_t missed = 0;
    int err;
    if (dev == NULL) {
        return INC_ERR_NULL;
    }
    err = adis_imu_wait_ready(dev, timeout_ns, &missed);
    if (err == INC_OK) {
        dev->sensor_missed += missed;
    } else {
        dev->sensor_missed = 0u; /* the caller drops this sample: start counting afresh */
    }
    return err;
}

static int op_read(void *ctx, struct sensor_sample *out)
{
    struct adis_imu *dev = ctx;
    struct adis_imu_sample s;
    enum adis_imu_family fam;
    unsigned i;
    int err;
    if (dev == NULL || out == NULL) {
        return INC_ERR_NULL;
    }
    err = adis_imu_read_sample(dev, &s);
    if (err != INC_OK) {
        /* ND clear: the edge came before the part had updated every register (or a read in
         * between cleared ND): that sample is lost; the caller takes the next one. */
        dev->sensor_missed = err == INC_ERR_STALE ? dev->sensor_missed + 1u : 0u;
        return err;
    }
    /* A burst that returned 0 has every channel valid. */
    fam = (enum adis_imu_family)dev->info->family;
    out->flags = SENSOR_S_HAVE_ACCEL | SENSOR_S_HAVE_GYRO | SENSOR_S_HAVE_TEMP;
    for (i = 0; i < 3u && err == INC_OK; i++) {
        const int32_t ca = s.counts[ADIS_IMU_CH_ACCEL_X + i], cg = s.counts[ADIS_IMU_CH_GYRO_X + i];
        err = adis_imu_accel_g_from_counts(ca, dev->info->accel_lsb_ug, &out->accel_g[i]);
        if (err == INC_OK) {
            err = adis_imu_gyro_dps_from_counts(cg, (enum adis_imu_range)s.gyro_range,
                                                &out->gyro_dps[i]);
        }
        if (at_end(ca)) out->flags |= SENSOR_S_ACCEL_SAT_X << i;
        if (at_end(cg)) out->flags |= SENSOR_S_GYRO_SAT_X << i;
    }
    if (err == INC_OK && fam == ADIS_IMU_FAMILY_1640X) {
        err = adis_imu_temp_c_from_counts(s.counts[ADIS_IMU_CH_TEMP0], fam, &out->temp_c);
    } else if (err == INC_OK) {
        /* Three gyro temperatures on the 1636x: their mean, rounded (ties away from zero). */
        struct fx_sum t;
        fx_sum_reset(&t);
        for (i = 0; i < 3u && err == INC_OK; i++) {
            int32_t c = 0;
            err = adis_imu_temp_c_from_counts(s.counts[ADIS_IMU_CH_TEMP0 + i], fam, &c);
            (void)fx_sum_add(&t, c);
        }
        (void)fx_sum_mean(&t, &out->temp_c);
    }
    if (err != INC_OK) {
        return err; /* the wrapper (sensor_read) zeroes the sample */
    }
    out->missed = dev->sensor_missed;
    out->t_ns = s.t_ns;
    dev->sensor_missed = 0u;
    return INC_OK;
}

static uint32_t diag_flags(uint16_t d)
{
    uint32_t f = 0u;
    if ((d & (ADIS_IMU_DIAG_SUPPLY_LOW | ADIS_IMU_DIAG_SUPPLY_HIGH)) != 0u) f |= SENSOR_D_SUPPLY;
    if ((d & ADIS_IMU_DIAG_SELF_TEST_BITS) != 0u) f |= SENSOR_D_SELF_TEST;
    if ((d & ADIS_IMU_DIAG_OVERRANGE) != 0u) f |= SENSOR_D_OVERRANGE;
    if ((d & ADIS_IMU_DIAG_SPI_FAIL) != 0u) f |= SENSOR_D_BUS;
    if ((d & (ADIS_IMU_DIAG_FLASH_UPDATE | ADIS_IMU_DIAG_FLASH_CHECKSUM)) != 0u) {
        f |= SENSOR_D_MEMORY;
    }
    if ((d & (ADIS_IMU_DIAG_ALARM1 | ADIS_IMU_DIAG_ALARM2)) != 0u) f |= SENSOR_D_ALARM;
    return f;
}

static int op_read_diag(void *ctx, struct sensor_diag *out)
{
    struct adis_imu *dev = ctx;
    uint16_t d = 0, w = 0;
    int err;
    if (dev == NULL || out == NULL) {
        return INC_ERR_NULL;
    }
    sensor_diag_clear(out);
    err = adis_imu_read_diag(dev, &d);
    if (err == INC_OK) {
        err = adis_imu_read_known(dev, ADIS_IMU_REG_SUPPLY_OUT, &w);
    }
    if (err != INC_OK) {
        return err;
    }
    out->flags = diag_flags(d);
    out->raw = d;
    out->supply_v = adis_imu_supply_v_from_counts(adis_field(w, dev->info->supply_bits));
    return INC_OK;
}

static int op_self_test(void *ctx, struct sensor_diag *out)
{
    struct adis_imu *dev = ctx;
    uint16_t d = 0;
    int err;
    if (dev == NULL || out == NULL) {
        return INC_ERR_NULL;
    }
    sensor_diag_clear(out);
    err = adis_imu_self_test(dev, &d);
    if (err == INC_OK || err == INC_ERR_DEVICE) {
        out->flags = diag_flags(d);
        out->raw = d;
        if (err == INC_ERR_DEVICE && (out->flags & SENSOR_D_SELF_TEST) == 0u) {
            out->flags |= SENSOR_D_SELF_TEST;
        }
    }
    return err;
}

static int op_identity(void *ctx, struct sensor_identity *out)
{
    return adis_imu_read_identity(ctx, out);
}

static int op_info(void *ctx, struct sensor_info *out)
{
    const struct adis_imu *dev = ctx;
    struct adis_imu_settings st;
    int err;
    if (dev == NULL || out == NULL) {
        return INC_ERR_NULL;
    }
    out->accel_fs_g = 0;
    out->gyro_fs_dps = 0;
    out->rate_mhz = 0u;
    err = adis_imu_get_settings(dev, &st);
    if (err != INC_OK) {
        return err;
    }
    /* 8192 counts x the LSB: 27.3 g at 3333 ug, 2.7 g at 333 ug, 8.2 g at 1000 ug */
    out->accel_fs_g = fx_div64((int64_t)8192 * dev->info->accel_lsb_ug * 65536, 1000000u);
    out->gyro_fs_dps = st.range == (uint8_t)ADIS_IMU_RANGE_75    ? FX_Q16_INT(75)
                       : st.range == (uint8_t)ADIS_IMU_RANGE_150 ? FX_Q16_INT(150)
                                                                 : FX_Q16_INT(300);
    out->rate_mhz = adis_imu_sample_rate_msps(st.smpl_prd);
    return INC_OK;
}

const struct sensor_ops adis_imu_sensor_ops = {op_init,      op_wait_ready, op_read, op_read_diag,
                                               op_self_test, op_identity,   op_info};
