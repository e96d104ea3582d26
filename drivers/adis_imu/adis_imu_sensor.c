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
    /* The 1636x has a serial number and lot ids (the calrec.h binding table). */
    static const uint8_t addrs[3] = {ADIS1636X_REG_SERIAL_NUM, ADIS1636X_REG_LOT_ID1,
                                     ADIS1636X_REG_LOT_ID2};
    uint16_t id[3] = {0, 0, 0};
    unsigned i, n;
    int err = INC_OK;
    if (dev == NULL || out == NULL) {
        return INC_ERR_NULL;
    }
    sensor_identity_clear(out);
    if (!dev->ready || dev->info == NULL) {
        return INC_ERR_STATE;
    }
    n = dev->info->family == (uint8_t)ADIS_IMU_FAMILY_1636X ? 3u : 0u;
    for (i = 0; i < n && err == INC_OK; i++) {
        err = adis_imu_read_known(dev, addrs[i], &id[i]);
    }
    if (err != INC_OK) {
        return err;
    }
    out->family = (uint32_t)SENSOR_FAMILY_ADIS163XX;
    out->product = dev->found_id; /* adis_imu_found's: a ready driver has identified its part */
    out->serial = id[0];
    out->lot_id1 = id[1];
    out->lot_id2 = id[2];
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
    const struct adis_imu_variant_info *vi;
    enum adis_imu_family fam;
    uint32_t flags;
    int32_t sum = 0; /* three temperatures: |sum| < 2^31 (each < 10000 C in Q16) */
    unsigned i, nt;
    int err, bad = 0;
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
    /* A burst that returned 0 has every channel valid. The conversions fail only with
     * INC_ERR_INVAL (a range, LSB or family outside the driver's tables): `bad` collects them. */
    vi = dev->info;
    fam = (enum adis_imu_family)vi->family;
    flags = SENSOR_S_HAVE_ACCEL | SENSOR_S_HAVE_GYRO | SENSOR_S_HAVE_TEMP;
    for (i = 0; i < 3u; i++) {
        bad |= adis_imu_accel_g_from_counts(s.counts[ADIS_IMU_CH_ACCEL_X + i], vi->accel_lsb_ug,
                                            &out->accel_g[i]);
        bad |= adis_imu_gyro_dps_from_counts(s.counts[ADIS_IMU_CH_GYRO_X + i],
                                             (enum adis_imu_range)s.gyro_range, &out->gyro_dps[i]);
    }
    /* SENSOR_S_GYRO_SAT_X << axis for GYRO_X + axis, SENSOR_S_ACCEL_SAT_X << axis for ACCEL_X +
     * axis. */
    for (i = ADIS_IMU_CH_GYRO_X; i <= (unsigned)ADIS_IMU_CH_ACCEL_Z; i++) {
        if (at_end(s.counts[i])) {
            flags |= (i <= (unsigned)ADIS_IMU_CH_GYRO_Z
                          ? SENSOR_S_GYRO_SAT_X >> ADIS_IMU_CH_GYRO_X
                          : SENSOR_S_ACCEL_SAT_X >> ADIS_IMU_CH_ACCEL_X)
                     << i;
        }
    }
    /* TEMP_OUT on the 1640x; the three gyro temperatures on the 1636x: their mean, rounded (ties
     * away from zero; the mean of one is that value). */
    nt = fam == ADIS_IMU_FAMILY_1640X ? 1u : 3u;
    for (i = 0; i < nt; i++) {
        int32_t c = 0;
        bad |= adis_imu_temp_c_from_counts(s.counts[ADIS_IMU_CH_TEMP0 + i], fam, &c);
        sum += c;
    }
    if (bad != 0) {
        return INC_ERR_INVAL; /* the wrapper (sensor_read) zeroes the sample */
    }
    out->temp_c = fx_div64(sum, nt);
    out->flags = flags;
    out->missed = dev->sensor_missed;
    out->t_ns = s.t_ns;
    dev->sensor_missed = 0u;
    return INC_OK;
}

/* DIAG_STAT bits behind SENSOR_D_SUPPLY, _SELF_TEST, _OVERRANGE, _BUS, _MEMORY, _ALARM (bits 0..5
 * of the flags, in this order). */
static const uint16_t diag_bits[6] = {
    ADIS_IMU_DIAG_SUPPLY_LOW | ADIS_IMU_DIAG_SUPPLY_HIGH,
    ADIS_IMU_DIAG_SELF_TEST_BITS,
    ADIS_IMU_DIAG_OVERRANGE,
    ADIS_IMU_DIAG_SPI_FAIL,
    ADIS_IMU_DIAG_FLASH_UPDATE | ADIS_IMU_DIAG_FLASH_CHECKSUM,
    ADIS_IMU_DIAG_ALARM1 | ADIS_IMU_DIAG_ALARM2,
};
_Static_assert(SENSOR_D_SUPPLY == 1u << 0 && SENSOR_D_SELF_TEST == 1u << 1 &&
                   SENSOR_D_OVERRANGE == 1u << 2 && SENSOR_D_BUS == 1u << 3 &&
                   SENSOR_D_MEMORY == 1u << 4 && SENSOR_D_ALARM == 1u << 5,
               "diag_bits is indexed by the SENSOR_D_* bit");

static uint32_t diag_flags(uint16_t d)
{
    uint32_t f = 0u;
    unsigned i;
    for (i = 0; i < 6u; i++) {
        if ((d & diag_bits[i]) != 0u) {
            f |= 1u << i;
        }
    }
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
        if (err == INC_ERR_DEVICE) {
            out->flags |= SENSOR_D_SELF_TEST; /* a failed self-test, whatever bits it set */
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
    if (dev == NULL || out == NULL) {
        return INC_ERR_NULL;
    }
    out->accel_fs_g = 0;
    out->gyro_fs_dps = 0;
    out->rate_mhz = 0u;
    if (!dev->ready) {
        return INC_ERR_STATE; /* as adis_imu_get_settings */
    }
    /* 8192 counts x the LSB: 27.3 g at 3333 ug, 2.7 g at 333 ug, 8.2 g at 1000 ug */
    out->accel_fs_g = fx_div64((int64_t)8192 * dev->info->accel_lsb_ug * 65536, 1000000u);
    /* The range codes 1, 2, 4 (adis_imu_gyro_range gives no other) are 75, 150, 300 / 75. */
    out->gyro_fs_dps = FX_Q16_INT(75) * (int32_t)adis_imu_gyro_range(dev);
    out->rate_mhz = adis_imu_sample_rate_msps((uint8_t)dev->smpl_prd);
    return INC_OK;
}

const struct sensor_ops adis_imu_sensor_ops = {op_init,      op_wait_ready, op_read, op_read_diag,
                                               op_self_test, op_identity,   op_info};
