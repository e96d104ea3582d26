/*
 * app_adis.c - sensor adapter for the ADIS1636x/1640x driver (see app_adis.h).
 *
 * One sample = one data-ready edge + one burst read (docs/sensor-facts.md §3.1: the burst returns every
 * output of one sample set in one CS period, so the axes are coherent). Conversions are the
 * driver's, exact to 0.5 LSB Q16.
 */
#include "inclino/app_adis.h"

#include <stddef.h>

/* End of the 14-bit output range: a count there may be a clipped value. */
#define APP_ADIS_COUNT_MIN (-8192)
#define APP_ADIS_COUNT_MAX 8191

static bool at_end(int32_t c)
{
    return c <= APP_ADIS_COUNT_MIN || c >= APP_ADIS_COUNT_MAX;
}

static int adis_read(void *ctx, struct app_sample *out)
{
    struct app_adis *ad = ctx;
    struct adis_imu_sample s;
    uint32_t missed = 0, more = 0;
    unsigned i;
    int err = adis_imu_wait_dr(ad->imu, 0u, &missed);
    if (err == INC_OK) {
        err = adis_imu_read_burst(ad->imu, &s);
        if (err == INC_ERR_STALE) {
            /* ND clear: the edge came before the part had updated every register (or a read
             * in between cleared ND). Take the next sample instead. */
            ad->stale_retries++;
            err = adis_imu_wait_dr(ad->imu, 0u, &more);
            if (err == INC_OK) {
                missed += more + 1u;
                err = adis_imu_read_burst(ad->imu, &s);
            }
        }
    }
    if (err != INC_OK) {
        return err;
    }
    ad->reads++;
    /* A burst that returned 0 has every channel valid; the driver's conversions (as
     * adis_imu_to_phys, without its whole-sample struct on the stack). */
    out->flags = APP_S_HAVE_GYRO | APP_S_HAVE_TEMP;
    for (i = 0; i < 3u; i++) {
        out->accel_g[i] = adis_imu_accel_g_q16(s.counts[ADIS_IMU_CH_ACCEL_X + i],
                                               ad->imu->info->accel_lsb_ug);
        out->gyro_dps[i] = adis_imu_gyro_dps_q16(s.counts[ADIS_IMU_CH_GYRO_X + i],
                                                 (enum adis_imu_range)s.gyro_range);
        if (at_end(s.counts[ADIS_IMU_CH_ACCEL_X + i])) {
            out->flags |= APP_S_ACCEL_SAT;
        }
        if (at_end(s.counts[ADIS_IMU_CH_GYRO_X + i])) {
            out->flags |= APP_S_GYRO_SAT;
        }
    }
    if (ad->imu->info->family == (uint8_t)ADIS_IMU_FAMILY_1640X) {
        out->temp_c = adis_imu_temp_c_q16(s.counts[ADIS_IMU_CH_TEMP0], ADIS_IMU_FAMILY_1640X);
    } else {
        /* Three gyro temperatures on the 1636x: their mean, rounded (ties away from zero). */
        struct fx_sum t;
        fx_sum_reset(&t);
        for (i = 0; i < 3u; i++) {
            (void)fx_sum_add(
                &t, adis_imu_temp_c_q16(s.counts[ADIS_IMU_CH_TEMP0 + i], ADIS_IMU_FAMILY_1636X));
        }
        (void)fx_sum_mean(&t, &out->temp_c);
    }
    out->missed = missed;
    out->t_ns = s.t_ns;
    return INC_OK;
}

static int adis_identity(void *ctx, struct calrec_binding *out)
{
    struct app_adis *ad = ctx;
    uint16_t prod = 0, serial = 0, lot1 = 0, lot2 = 0;
    int err = adis_imu_found(ad->imu, &prod, NULL);
    if (err != INC_OK) {
        return err;
    }
    if (ad->imu->info->family == (uint8_t)ADIS_IMU_FAMILY_1636X) {
        /* The 1636x has a serial number and lot ids (calrec.h binding table). */
        err = adis_imu_read_reg(ad->imu, ADIS1636X_REG_SERIAL_NUM, &serial);
        if (err == INC_OK) err = adis_imu_read_reg(ad->imu, ADIS1636X_REG_LOT_ID1, &lot1);
        if (err == INC_OK) err = adis_imu_read_reg(ad->imu, ADIS1636X_REG_LOT_ID2, &lot2);
        if (err != INC_OK) {
            return err;
        }
    }
    out->family = CALREC_FAMILY_ADIS163XX;
    out->product = prod;
    out->revision = 0u;
    out->serial = serial;
    out->lot_id1 = lot1;
    out->lot_id2 = lot2;
    return INC_OK;
}

static const struct app_sensor_ops adis_ops = {adis_read, adis_identity};

int app_adis_sensor(struct app_adis *ad, struct adis_imu *imu, struct app_sensor *out)
{
    if (ad == NULL || imu == NULL || out == NULL) {
        return INC_ERR_NULL;
    }
    if (!imu->ready || imu->info == NULL || !imu->dr_enabled) {
        return INC_ERR_STATE;
    }
    ad->imu = imu;
    ad->reads = 0;
    ad->stale_retries = 0;
    out->ops = &adis_ops;
    out->ctx = ad;
    return INC_OK;
}
