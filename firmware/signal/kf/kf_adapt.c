/*
 * kf_adapt.c - the adaptive per-axis Kalman filter of [CN110567483] steps 1 to 3 (see
 * inclino/kf_adapt.h and docs/kalman.md).
 *
 * Why it works: dz measures how far the newest sample stands from the recent ones. On a still
 * axis it is noise-sized, Q stays near C and the gain K settles small (heavy smoothing). When the
 * signal moves (a tilt step), |dz| jumps, Q and so P- grow, K approaches 1 and the estimate
 * follows within a few samples; R = |A + B Q| lets the measurement noise follow Q as well (B < 0
 * trusts the measurement more while the signal moves). The patent leaves the constants open;
 * docs/kalman.md gives the tuning procedure.
 *
 * Fixed point: the same formats as the generic filter (kf.h: P format raw^2 * 2^16, estimate with
 * 16 extra bits). The scalar step is the patent's P = (1 - K) P-, not Joseph: with one state and
 * 0 <= K <= 1 (guaranteed by K = P- / (P- + R) with P-, R >= 0 and by the rounding, which cannot
 * leave [0, 2^30]) it cannot lose positivity, and it is one product cheaper.
 */
#include "inclino/kf_adapt.h"

#include <stddef.h>

#include "inclino/fx128.h"

int kf_adapt_config_check(const struct kf_adapt_config *cfg)
{
    if (cfg == NULL) return INC_ERR_NULL;
    if (cfg->window < 2u || cfg->window > KF_ADAPT_WIN_MAX) return INC_ERR_INVAL;
    if (cfg->c < 1 || cfg->c > KF_P_MAX) return INC_ERR_INVAL;
    if (cfg->d < 0 || cfg->d > KF_P_MAX) return INC_ERR_INVAL;
    if (cfg->a < -KF_P_MAX || cfg->a > KF_P_MAX) return INC_ERR_INVAL;
    if (cfg->p0 < 0 || cfg->p0 > KF_P_MAX) return INC_ERR_INVAL;
    return INC_OK;
}

void kf_adapt_restart(struct kf_adapt *f)
{
    unsigned i;
    if (f == NULL) return;
    for (i = 0; i < KF_ADAPT_WIN_MAX; i++)
        f->hist[i] = 0;
    f->sum = 0;
    f->x = 0;
    f->p = f->cfg.p0;
    f->head = 0;
    f->count = 0;
}

int kf_adapt_init(struct kf_adapt *f, const struct kf_adapt_config *cfg)
{
    int err;
    if (f == NULL) return INC_ERR_NULL;
    f->ready = false;
    err = kf_adapt_config_check(cfg);
    if (err != INC_OK) return err;
    f->cfg = *cfg;
    kf_adapt_restart(f);
    f->ready = true;
    return INC_OK;
}

/* round(num / den), ties away from zero, den in 1..2^31, saturated to int32. */
static int32_t div_round_sat32(int64_t num, uint32_t den)
{
    uint64_t m = fx_uabs64(num), q, r;
    if ((m >> 32) == 0u) {
        q = (uint32_t)m / den; /* one UDIV where the core has one */
    } else {
        q = m / den;
    }
    r = m - q * den;
    if (r >= den - r) q++;
    if (num < 0) return q >= 0x80000000u ? INT32_MIN : -(int32_t)q;
    return q > (uint64_t)INT32_MAX ? INT32_MAX : (int32_t)q;
}

static int64_t clamp_p(int64_t v)
{
    return v > KF_P_MAX ? KF_P_MAX : (v < -KF_P_MAX ? -KF_P_MAX : v);
}

int kf_adapt_process(struct kf_adapt *f, int32_t z, int32_t *est, struct kf_adapt_step *step)
{
    const struct kf_adapt_config *c;
    int32_t dz = 0;
    int64_t q, r, pm, s, kq, innov, dx;
    fx_i128_t t;
    bool unused = false;

    if (f == NULL || est == NULL) return INC_ERR_NULL;
    if (!f->ready) return INC_ERR_STATE;
    c = &f->cfg;

    /* Step 1: the window of the last k samples (including this one), with its exact sum. */
    if (f->count == c->window) {
        f->sum -= f->hist[f->head];
    } else {
        f->count++;
    }
    f->hist[f->head] = z;
    f->sum += z;
    f->head = (f->head + 1u) % c->window;

    if (f->count == 1u) {
        /* First sample: it is the estimate; P starts at p0. */
        f->x = (int64_t)z * ((int64_t)1 << KF_X_FRAC);
        f->p = c->p0;
        *est = z;
        if (step != NULL) {
            step->dz = 0;
            step->q = 0;
            step->r = 0;
            step->k = FX_Q30_ONE;
        }
        return INC_OK;
    }

    /* Step 2: dz = (n Z - sum) / (n - 1) over the n samples in the window. */
    dz = div_round_sat32((int64_t)f->count * z - f->sum, f->count - 1u);
    t = fx_i128_mac(fx_i128_from_i64(c->c), c->d, (int64_t)fx_uabs32(dz));
    q = fx_i128_rshift_round(t, 0u, &unused);
    q = q > KF_P_MAX ? KF_P_MAX : q;                               /* C >= 1, D >= 0: q >= 1 */
    t = fx_i128_mac(fx_i128_mul(c->a, (int64_t)1 << 16), c->b, q); /* (A 2^16 + B Q) */
    r = fx_i128_rshift_round(t, 16u, &unused);
    r = clamp_p(r);
    r = r < 0 ? -r : r;

    /* Step 3: prediction = previous estimate, P- = P + Q, K = P- / (P- + R). */
    pm = f->p + q; /* each <= 2^60 */
    pm = pm > KF_P_MAX ? KF_P_MAX : pm;
    s = pm + r;                                                                 /* >= q >= 1 */
    (void)fx_i128_div_i64(fx_i128_mul(pm, (int64_t)1 << FX_Q30_SHIFT), s, &kq); /* [0, 2^30] */
    innov = (int64_t)z * ((int64_t)1 << KF_X_FRAC) - f->x;                      /* |.| <= 2^48 */
    dx = fx_i128_rshift_round(fx_i128_mul(kq, innov), FX_Q30_SHIFT, &unused);
    f->x += dx; /* between x and z */
    f->p = fx_i128_rshift_round(fx_i128_mul(FX_Q30_ONE - kq, pm), FX_Q30_SHIFT, &unused);

    *est = (int32_t)fx_rshift_round64(f->x, KF_X_FRAC);
    if (step != NULL) {
        step->dz = dz;
        step->q = q;
        step->r = r;
        step->k = (fx_q30_t)kq;
    }
    return INC_OK;
}

int kf_adapt_coast(struct kf_adapt *f, int32_t *est)
{
    if (f == NULL || est == NULL) return INC_ERR_NULL;
    if (!f->ready) return INC_ERR_STATE;
    if (f->count > 0u) {
        int64_t pm = f->p + f->cfg.c;
        f->p = pm > KF_P_MAX ? KF_P_MAX : pm;
    }
    *est = (int32_t)fx_rshift_round64(f->x, KF_X_FRAC);
    return INC_OK;
}

int32_t kf_adapt_estimate(const struct kf_adapt *f)
{
    if (f == NULL || !f->ready || f->count == 0u) return 0;
    return (int32_t)fx_rshift_round64(f->x, KF_X_FRAC);
}

int kf_adapt6_init(struct kf_adapt6 *f, const struct kf_adapt_config cfg[KF_ADAPT_AXES])
{
    unsigned i;
    if (f == NULL || cfg == NULL) return INC_ERR_NULL;
    for (i = 0; i < KF_ADAPT_AXES; i++)
        f->axis[i].ready = false;
    for (i = 0; i < KF_ADAPT_AXES; i++) {
        int err = kf_adapt_init(&f->axis[i], &cfg[i]);
        if (err != INC_OK) {
            unsigned j;
            for (j = 0; j < KF_ADAPT_AXES; j++)
                f->axis[j].ready = false;
            return err;
        }
    }
    return INC_OK;
}

int kf_adapt6_process(struct kf_adapt6 *f, const int32_t z[KF_ADAPT_AXES], uint32_t use_mask,
                      int32_t est[KF_ADAPT_AXES])
{
    unsigned i;
    int err;
    if (f == NULL || z == NULL || est == NULL) return INC_ERR_NULL;
    for (i = 0; i < KF_ADAPT_AXES; i++) {
        if (use_mask & (1u << i)) {
            err = kf_adapt_process(&f->axis[i], z[i], &est[i], NULL);
        } else {
            err = kf_adapt_coast(&f->axis[i], &est[i]);
        }
        if (err != INC_OK) return err;
    }
    return INC_OK;
}
