/*
 * app_sca3000.c - sensor adapter for the SCA3000 driver (see app_sca3000.h).
 *
 * No source describes a new-data interrupt for direct measurement mode (docs/sensor-facts.md §1.6), so
 * the output data rate paces the reads: a read waits until one output period after the
 * previous one. The part latches X, Y, Z together when CS falls (one CS period reads a coherent
 * set: the driver reads them in one burst). Being late by whole periods is reported as missed
 * samples; a sample lost within one period cannot be seen without a data-ready line.
 */
#include "inclino/app_sca3000.h"

#include <stddef.h>

/* Ends of the 13-bit output range (docs/sensor-facts.md §1.4). */
#define APP_SCA3000_COUNT_MIN (-4096)
#define APP_SCA3000_COUNT_MAX 4095

static const uint32_t variant_code[4] = {CALREC_SCA3000_D01, CALREC_SCA3000_E02, CALREC_SCA3000_E04,
                                         CALREC_SCA3000_E05};

static int sca_read(void *ctx, struct app_sample *out)
{
    struct app_sca3000 *ad = ctx;
    struct sca3000_sample s;
    uint64_t now = hal_now_ns(ad->hal);
    uint32_t missed = 0;
    unsigned i;
    int err;
    if (!ad->started) {
        /* The first read waits one period: the part may still hold a sample from before the
         * adapter started (its registers keep the last one), which would not belong here. */
        ad->next_ns = now + ad->period_ns;
        ad->started = true;
    }
    if (now < ad->next_ns) {
        hal_delay_until(ad->hal, ad->next_ns);
        now = ad->next_ns;
    } else {
        const uint64_t late = (now - ad->next_ns) / ad->period_ns;
        missed = late > UINT32_MAX ? UINT32_MAX : (uint32_t)late;
    }
    ad->next_ns = now + ad->period_ns;
    err = sca3000_read_sample(ad->dev, &s);
    if (err != INC_OK) {
        return err;
    }
    out->flags = 0;
    for (i = 0; i < 3u; i++) {
        int32_t g;
        err = sca3000_accel_to_q16_g(s.xyz[i], ad->dev->variant, &g);
        if (err != INC_OK) {
            return err;
        }
        out->accel_g[i] = g;
        out->gyro_dps[i] = 0;
        if (s.xyz[i] <= APP_SCA3000_COUNT_MIN || s.xyz[i] >= APP_SCA3000_COUNT_MAX) {
            out->flags |= APP_S_ACCEL_SAT;
        }
    }
    out->temp_c = 0;
    if (s.temp_valid) {
        err = sca3000_temp_to_q16_c(s.temp_raw, &out->temp_c);
        if (err != INC_OK) {
            return err;
        }
        out->flags |= APP_S_HAVE_TEMP;
    }
    out->missed = missed;
    out->t_ns = now;
    ad->reads++;
    return INC_OK;
}

static int sca_identity(void *ctx, struct calrec_binding *out)
{
    const struct app_sca3000 *ad = ctx;
    if ((unsigned)ad->dev->variant >= 4u) {
        return INC_ERR_UNSUPPORTED;
    }
    out->family = CALREC_FAMILY_SCA3000;
    out->product = variant_code[ad->dev->variant];
    out->revision = sca3000_revid(ad->dev);
    out->serial = 0u;
    out->lot_id1 = 0u;
    out->lot_id2 = 0u;
    return INC_OK;
}

static const struct app_sensor_ops sca_ops = {sca_read, sca_identity};

int app_sca3000_sensor(struct app_sca3000 *ad, struct sca3000 *dev, const struct hal *hal,
                       struct app_sensor *out)
{
    uint32_t odr;
    if (ad == NULL || dev == NULL || hal == NULL || out == NULL) {
        return INC_ERR_NULL;
    }
    if (hal_check(hal) != INC_OK) {
        return INC_ERR_NULL;
    }
    odr = sca3000_odr_mhz(dev);
    if (!dev->ready || odr == 0u) {
        return INC_ERR_STATE;
    }
    ad->dev = dev;
    ad->hal = hal;
    /* ceil(1e12 / odr_mhz) ns: never shorter than the part's period. */
    ad->period_ns = (uint32_t)((1000000000000ull + odr - 1u) / odr);
    ad->started = false;
    ad->next_ns = 0;
    ad->reads = 0;
    out->ops = &sca_ops;
    out->ctx = ad;
    return INC_OK;
}
