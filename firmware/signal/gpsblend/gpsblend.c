/* gpsblend.c - speed across GPS gaps (see gpsblend.h; [KF-SCA3000]). */
#include "inclino/gpsblend.h"

#include <stddef.h>

struct gpsb_cfg gpsb_default_cfg(fx_q16_t q_noise_g)
{
    struct gpsb_cfg c;
    c.q_noise_g = q_noise_g;
    c.rounds = 1;
    c.max_gap_ns = 3000000000u;
    c.max_step_ns = 100000000u;
    return c;
}

int gpsb_init(struct gpsb *s, const struct gpsb_cfg *cfg)
{
    if (s == NULL || cfg == NULL) {
        return INC_ERR_NULL;
    }
    s->ready = false;
    if (cfg->q_noise_g <= 0 || cfg->rounds > GPSB_MAX_ROUNDS || cfg->max_gap_ns == 0u ||
        cfg->max_step_ns == 0u || cfg->max_step_ns > 1000000000u) {
        return INC_ERR_INVAL;
    }
    s->cfg = *cfg;
    s->v_q32 = 0;
    s->v_gps_q32 = 0;
    s->since_fix_ns = 0;
    s->have_fix = false;
    s->last_k = 0;
    s->ready = true;
    return INC_OK;
}

fx_q30_t gpsb_factor(fx_q16_t a_g, fx_q16_t q_g, unsigned rounds)
{
    /* |a| of INT32_MIN is 2^31, one more than fx_div takes: saturate it (the ratio moves by
     * 2^-31, far below the result's LSB). */
    const int32_t a = fx_abs(a_g), q = q_g > 0 ? q_g : 0;
    int32_t r = 0, su, k = 0;
    unsigned i;
    if (q == 0) {
        return FX_Q30_ONE;
    }
    if (a == 0) {
        return 0;
    }
    /* K = |a| / sqrt(a^2 + q^2), computed on the ratio r = min/max <= 1 so that no precision is
     * lost at either end: K = 1/sqrt(1 + r^2) when |a| >= q, r/sqrt(1 + r^2) when |a| < q.
     * (Squaring a and q and taking the square root of the sum would lose all of K for a << q.) */
    if (a >= q) {
        (void)fx_div(q, a, FX_Q30_SHIFT, &r);
    } else {
        (void)fx_div(a, q, FX_Q30_SHIFT, &r);
    }
    su = fx_sqrt_q30(fx_add(FX_Q30_ONE, fx_mul_q30(r, r))); /* in [1, 1.4143) */
    (void)fx_div(a >= q ? FX_Q30_ONE : r, su, FX_Q30_SHIFT, &k);
    for (i = 0; i < rounds; i++) {
        /* K + (1 - K) K = 2K - K^2. */
        k = fx_sat32(2 * (int64_t)k - fx_mul_q30(k, k));
    }
    return k;
}

int gpsb_fix(struct gpsb *s, fx_q16_t v_mps)
{
    if (s == NULL) {
        return INC_ERR_NULL;
    }
    if (!s->ready) {
        return INC_ERR_STATE;
    }
    s->v_gps_q32 = (int64_t)v_mps * 65536;
    s->v_q32 = s->v_gps_q32;
    s->since_fix_ns = 0;
    s->have_fix = true;
    return INC_OK;
}

static fx_q16_t to_q16(int64_t v_q32)
{
    return fx_sat32(fx_rshift_round64(v_q32, 16));
}

int gpsb_step(struct gpsb *s, fx_q16_t a_g, uint32_t dt_ns, fx_q16_t *v_mps)
{
    int64_t acc, dv, v_acc, diff;
    fx_q30_t k;
    if (s == NULL) {
        return INC_ERR_NULL;
    }
    if (!s->ready || !s->have_fix) {
        if (v_mps != NULL) {
            *v_mps = 0;
        }
        return INC_ERR_STATE;
    }
    if (dt_ns == 0u || dt_ns > s->cfg.max_step_ns) {
        if (v_mps != NULL) {
            *v_mps = to_q16(s->v_q32);
        }
        return INC_ERR_RANGE;
    }
    /* dv = a * g0 * dt in Q32 m/s with one rounding. a * g0 in Q16 m/s^2 (|a| clamped to
     * 16 g: < 2^24), times dt_ns (<= 1e9 < 2^30) times 2^16 / 1e9 = 128 / 1953125: the product
     * stays below 2^61. */
    acc = fx_mul_q16(fx_clamp(a_g, -FX_Q16_INT(16), FX_Q16_INT(16)), GPSB_G0_Q16);
    {
        const int64_t num = (int64_t)acc * (int64_t)dt_ns * 128;
        dv = num / 1953125;
        if (2 * fx_uabs64(num % 1953125) >= 1953125u) {
            dv += num < 0 ? -1 : 1;
        }
    }
    v_acc = s->v_q32 + dv;
    k = gpsb_factor(a_g, s->cfg.q_noise_g, s->cfg.rounds);
    s->last_k = k;
    diff = v_acc - s->v_gps_q32;
    /* v = v_gps + K * diff. diff (Q32 m/s, < 2^48 for speeds < 32768 m/s) times K (< 2^31)
     * would overflow int64: split diff into its Q16 part and the remaining 16 bits. */
    {
        const int64_t hi = fx_asr64(diff, 16); /* Q16 part */
        const int64_t lo = diff - hi * 65536;  /* 0..65535 */
        /* hi * k: Q16 * Q30 = Q46; lo * k: Q32 * Q30 = Q62, / 2^16 = Q46. Back to Q32: / 2^14. */
        const int64_t t = hi * k + fx_asr64(lo * k, 16);
        s->v_q32 = s->v_gps_q32 + fx_rshift_round64(t, 14);
    }
    s->since_fix_ns += dt_ns;
    if (v_mps != NULL) {
        *v_mps = to_q16(s->v_q32);
    }
    return s->since_fix_ns > s->cfg.max_gap_ns ? INC_ERR_TIMEOUT : INC_OK;
}

bool gpsb_speed(const struct gpsb *s, fx_q16_t *v_mps)
{
    if (s == NULL || !s->ready) {
        return false;
    }
    if (v_mps != NULL) {
        *v_mps = to_q16(s->v_q32);
    }
    return s->have_fix && s->since_fix_ns <= s->cfg.max_gap_ns;
}
