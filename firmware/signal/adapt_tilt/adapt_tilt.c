/*
 * adapt_tilt.c - the patented method end to end: kf_adapt on six axes, then tilt (see
 * inclino/adapt_tilt.h and docs/kalman.md).
 */
#include "inclino/adapt_tilt.h"

#include <stddef.h>

#include "inclino/fx128.h"

/* sqrt(2 / pi) in Q30: E|x| = sd sqrt(2/pi) for a zero-mean Gaussian x. */
#define SQRT_2_OVER_PI_Q30 856722024
/* sin(5 deg) in Q16 g. */
#define SIN_5_DEG_Q16 5712

void adapt_tilt_noise_default(struct adapt_tilt_noise *noise)
{
    if (noise == NULL) return;
    noise->accel_sd_g = 262;               /* 4 mg */
    noise->gyro_sd_dps = FX_Q16_ONE / 2;   /* 0.5 deg/s */
    noise->accel_step_g = SIN_5_DEG_Q16;   /* a 5 deg tilt change on x or y */
    noise->gyro_step_dps = FX_Q16_INT(20); /* a 20 deg/s rate change */
    noise->n_equiv = 82u;
    noise->window = 32u;
}

/* round(num / den) for den > 0, saturated to int64 (den <= 2^62 here). */
static int64_t div128_round(fx_i128_t num, int64_t den)
{
    int64_t q;
    (void)fx_i128_div_i64(num, den, &q); /* saturates on INC_ERR_RANGE; den > 0 always */
    return q;
}

/*
 * One axis of the tuning procedure. sd, step in raw Q16; step 0: no adaptation.
 *   A = sd^2 in P format (raw^2 * 2^16)           exact
 *   Qr = Ks^2 A / (1 - Ks), Ks = 2^31 / (n + 1) Q30 rounded: relative error <= 2^-29 / Ks
 *   C = Qr / 10; mdz = sd sqrt(2/pi) sqrt(k/(k-1)) in raw * 2^16: relative error < 1e-6
 *   D = 0.9 Qr / mdz (unit * 2^32), B = -A 2^16 / (C + D step) (Q16, >= -32767)
 */
static void tune_axis(struct kf_adapt_config *c, fx_q16_t sd, fx_q16_t step, uint32_t n, uint32_t k)
{
    const int64_t a = ((int64_t)sd * sd) * 65536;
    const int64_t ks = (int64_t)((2ull << 30) + (n + 1u) / 2u) / (int64_t)(n + 1u); /* Q30 */
    int64_t qr, cc, mdz, d, qs, b;
    uint64_t ratio;
    qr = div128_round(fx_i128_mul(a, ks * ks), (FX_Q30_ONE - ks) * (int64_t)FX_Q30_ONE);
    if (qr < 1) qr = 1;
    if (qr > KF_P_MAX) qr = KF_P_MAX;
    c->window = k;
    c->a = a;
    c->p0 = a;
    if (step == 0) {
        c->c = qr;
        c->d = 0;
        c->b = 0;
        return;
    }
    cc = (qr + 5) / 10;
    if (cc < 1) cc = 1;
    /* sqrt(k / (k - 1)) in Q30 = isqrt(k / (k - 1) in Q60), k / (k - 1) = 1 + 1 / (k - 1). */
    ratio = (1ull << 60) + ((1ull << 60) + (k - 1u) / 2u) / (uint64_t)(k - 1u);
    mdz = fx_i128_rshift_round(
        fx_i128_mul((int64_t)sd * SQRT_2_OVER_PI_Q30, (int64_t)fx_isqrt64_round(ratio)), 44u,
        NULL); /* raw * 2^16: 16 bits below the raw LSB */
    if (mdz < 1) mdz = 1;
    d = div128_round(fx_i128_mul(qr - cc, 65536), mdz); /* P / raw = unit * 2^32 */
    if (d > KF_P_MAX) d = KF_P_MAX;
    /* D step is in P format (unit * 2^32 times unit * 2^16); saturated at KF_P_MAX. */
    qs = fx_i128_rshift_round(fx_i128_mul(d, step), 0u, NULL);
    qs = qs > KF_P_MAX - cc ? KF_P_MAX : cc + qs;
    b = -div128_round(fx_i128_mul(a, 65536), qs);
    if (b < -32767 * 65536) b = -32767 * 65536;
    c->c = cc;
    c->d = d;
    c->b = (fx_q16_t)b;
}

int adapt_tilt_config_default(struct adapt_tilt_config *cfg, const struct adapt_tilt_noise *noise,
                              uint32_t dt_nominal_ns)
{
    unsigned i;
    if (cfg == NULL || noise == NULL) return INC_ERR_NULL;
    if (noise->accel_sd_g <= 0 || noise->accel_sd_g > FX_Q16_ONE || noise->gyro_sd_dps <= 0 ||
        noise->gyro_sd_dps > FX_Q16_INT(50) || noise->accel_step_g <= 0 ||
        noise->accel_step_g > FX_Q16_INT(16) || noise->gyro_step_dps <= 0 ||
        noise->gyro_step_dps > FX_Q16_INT(2000) || noise->n_equiv < 2u || noise->n_equiv > 10000u ||
        noise->window < 2u || noise->window > KF_ADAPT_WIN_MAX)
        return INC_ERR_INVAL;
    for (i = 0; i < 3u; i++) {
        tune_axis(&cfg->axis[ADAPT_TILT_GX + i], noise->gyro_sd_dps, noise->gyro_step_dps,
                  noise->n_equiv, noise->window);
        tune_axis(&cfg->axis[ADAPT_TILT_AX + i], noise->accel_sd_g,
                  i == 2u ? 0 : noise->accel_step_g, noise->n_equiv, noise->window);
    }
    return tilt_config_default(&cfg->tilt, dt_nominal_ns);
}

int adapt_tilt_init(struct adapt_tilt *a, const struct adapt_tilt_config *cfg)
{
    int err;
    if (a == NULL || cfg == NULL) return INC_ERR_NULL;
    a->ready = false;
    err = kf_adapt6_init(&a->filt, cfg->axis);
    if (err == INC_OK) err = tilt_init(&a->tilt, &cfg->tilt);
    if (err == INC_OK) a->ready = true;
    return err;
}

void adapt_tilt_restart(struct adapt_tilt *a)
{
    unsigned i;
    if (a == NULL || !a->ready) return;
    for (i = 0; i < KF_ADAPT_AXES; i++)
        kf_adapt_restart(&a->filt.axis[i]);
    tilt_restart(&a->tilt);
}

int adapt_tilt_step(struct adapt_tilt *a, const struct tilt_input *in, uint32_t dt_ns,
                    struct tilt_output *out, int32_t filtered[KF_ADAPT_AXES])
{
    int32_t z[KF_ADAPT_AXES], est[KF_ADAPT_AXES];
    struct tilt_input f;
    uint32_t use = 0x3Fu;
    unsigned i;
    int err;
    if (a == NULL || in == NULL || out == NULL) return INC_ERR_NULL;
    if (!a->ready) return INC_ERR_STATE;
    for (i = 0; i < 3u; i++) {
        z[ADAPT_TILT_GX + i] = in->gyro_dps[i];
        z[ADAPT_TILT_AX + i] = in->accel_g[i];
    }
    /* A saturated axis says nothing about the true value: its filter coasts. */
    if ((in->flags & TILT_IN_GYRO_SAT_X) != 0u) use &= ~(1u << ADAPT_TILT_GX);
    if ((in->flags & TILT_IN_GYRO_SAT_Y) != 0u) use &= ~(1u << ADAPT_TILT_GY);
    if ((in->flags & TILT_IN_ACCEL_SAT) != 0u)
        use &= ~((1u << ADAPT_TILT_AX) | (1u << ADAPT_TILT_AY) | (1u << ADAPT_TILT_AZ));
    err = kf_adapt6_process(&a->filt, z, use, est);
    if (err != INC_OK) return err;
    for (i = 0; i < 3u; i++) {
        f.gyro_dps[i] = est[ADAPT_TILT_GX + i];
        f.accel_g[i] = est[ADAPT_TILT_AX + i];
    }
    f.flags = in->flags;
    if (filtered != NULL)
        for (i = 0; i < KF_ADAPT_AXES; i++)
            filtered[i] = est[i];
    return tilt_step(&a->tilt, &f, dt_ns, out);
}
