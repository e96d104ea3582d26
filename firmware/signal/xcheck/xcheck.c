/*
 * xcheck.c - integrity cross-checks of the driving attitude output (see inclino/xcheck.h).
 */
#include "inclino/xcheck.h"

#include <stddef.h>

/* 1 / g0 in Q30 (g0 = 9.80665 m/s^2) and pi / 180 / g0 in Q30: g per (m/s x deg/s). */
#define XC_INV_G0_Q30 ((int64_t)109491195)
#define XC_CENT_Q30 ((int64_t)1910982)
#define XC_G32_Q16 ((int32_t)32 << 16)
#define XC_G64_Q16 ((int32_t)64 << 16)

/* round(x / 2^s), ties away from zero, 1 <= s <= 62 (negative values never shifted). */
static int64_t rnd64(int64_t x, unsigned s)
{
    const int64_t h = (int64_t)1 << (s - 1u);
    return x >= 0 ? (x + h) >> s : -((-x + h) >> s);
}

static int32_t clamp32(int64_t x, int32_t lim)
{
    return x > lim ? lim : (x < -(int64_t)lim ? -lim : (int32_t)x);
}

static int32_t abs32(int32_t x)
{
    return x < 0 ? -x : x; /* callers pass |x| <= 2^30 */
}

int xcheck_flat_init(struct xcheck_flat *f, uint32_t n_max, uint8_t mask)
{
    if (f == NULL) return INC_ERR_NULL;
    if (n_max < 2u || n_max > 65535u || (mask & ~0x3Fu) != 0u) return INC_ERR_INVAL;
    f->n_max = n_max;
    f->mask = mask;
    xcheck_flat_reset(f);
    return INC_OK;
}

void xcheck_flat_reset(struct xcheck_flat *f)
{
    unsigned i;
    if (f == NULL) return;
    for (i = 0; i < XCHECK_FLAT_CH; i++) {
        f->last[i] = 0;
        f->run[i] = 0u;
    }
    f->have = false;
}

uint8_t xcheck_flat_step(struct xcheck_flat *f, const int32_t v[XCHECK_FLAT_CH])
{
    uint8_t out = 0u;
    unsigned i;
    if (f == NULL || v == NULL) return 0u;
    for (i = 0; i < XCHECK_FLAT_CH; i++) {
        if (f->have && v[i] == f->last[i]) {
            if (f->run[i] < f->n_max) f->run[i]++;
        } else {
            f->run[i] = 1u;
            f->last[i] = v[i];
        }
        if ((f->mask & (1u << i)) != 0u && f->run[i] >= f->n_max) out |= (uint8_t)(1u << i);
    }
    f->have = true;
    return out;
}

int xcheck_kin_residual(const fx_q16_t acc_g[3], const int32_t up_q30[3], fx_q16_t dv_mps,
                        fx_q16_t rate_hz, fx_q16_t speed_mps, fx_q16_t yaw_dps, fx_q16_t r[3])
{
    int64_t p;
    int32_t kx, ky, vy8, v, dv;
    unsigned i;
    if (r != NULL) r[0] = r[1] = r[2] = 0;
    if (acc_g == NULL || up_q30 == NULL || r == NULL) return INC_ERR_NULL;
    if (rate_hz < FX_Q16_ONE) return INC_ERR_INVAL; /* < 32768 Hz by the type */
    /* k_x: dv (clamped to +-256 m/s, 2^24 Q16) x rate (< 2^31 Q16) < 2^55, Q32 m/s^2 */
    dv = clamp32(dv_mps, (int32_t)256 << 16);
    p = rnd64((int64_t)dv * rate_hz, 16); /* Q16 m/s^2 */
    /* clamped to +-400 m/s^2 (> 32 g; 2^24.7 Q16): x 1/g0 (2^26.7 Q30) < 2^52 */
    p = clamp32(p, (int32_t)400 << 16);
    kx = clamp32(rnd64(p * XC_INV_G0_Q30, 30), XC_G32_Q16);
    /* k_y: v (clamped to +-256 m/s) x yaw (Q16) < 2^55 -> Q8 (m/s x deg/s), then x pi/180/g0 */
    v = clamp32(speed_mps, (int32_t)256 << 16);
    vy8 = clamp32(rnd64((int64_t)v * yaw_dps, 24), INT32_MAX);
    ky = clamp32(rnd64((int64_t)vy8 * XC_CENT_Q30, 22), XC_G32_Q16);
    for (i = 0; i < 3u; i++) {
        const int32_t a = clamp32(acc_g[i], XC_G32_Q16);
        const int32_t u = (int32_t)rnd64(up_q30[i], 14); /* Q16, |.| <= 2^17 */
        const int32_t k = i == 0u ? kx : (i == 1u ? ky : 0);
        r[i] = clamp32((int64_t)a - u - k, XC_G64_Q16);
    }
    return INC_OK;
}

int xcheck_mon_init(struct xcheck_mon *m, uint8_t shift, uint32_t persist_n)
{
    if (m == NULL) return INC_ERR_NULL;
    if (shift < 1u || shift > 16u || persist_n < 1u || persist_n > (1u << 24)) return INC_ERR_INVAL;
    m->sh = shift;
    m->persist_n = persist_n;
    xcheck_mon_reset(m);
    return INC_OK;
}

void xcheck_mon_reset(struct xcheck_mon *m)
{
    if (m == NULL) return;
    m->lp[0] = m->lp[1] = m->lp[2] = 0;
    m->lp1[0] = m->lp1[1] = m->lp1[2] = 0;
    m->over_n = 0u;
}

fx_q16_t xcheck_mon_step(struct xcheck_mon *m, const fx_q16_t d[3], uint8_t axes, fx_q16_t thr_g,
                         bool *fail)
{
    int32_t level = 0;
    unsigned i;
    if (fail != NULL) *fail = false;
    if (m == NULL || d == NULL) return 0;
    for (i = 0; i < 3u; i++) {
        /* d clamped to +-32 g: Q24 within +-2^29, lp1 and lp within +-2^29 (averages of it), the
         * differences within +-2^30 */
        const int32_t x = clamp32(d[i], XC_G32_Q16) * 256;
        m->lp1[i] += (int32_t)rnd64((int64_t)x - m->lp1[i], m->sh);
        m->lp[i] += (int32_t)rnd64((int64_t)m->lp1[i] - m->lp[i], m->sh);
        if ((axes & (1u << i)) != 0u) {
            const int32_t l = (int32_t)rnd64(abs32(m->lp[i]), 8);
            if (l > level) level = l;
        }
    }
    if ((axes & XCHECK_MON_XY_NORM) != 0u) {
        /* |lp| <= 2^29 Q24: the sum of two squares < 2^59; the root <= 2^29.5, rounded up to
         * Q24 and then to Q16: <= 2^21.6 */
        const uint64_t ss = (uint64_t)((int64_t)m->lp[0] * m->lp[0]) +
                            (uint64_t)((int64_t)m->lp[1] * m->lp[1]);
        uint64_t r = fx_isqrt64(ss);
        if (r * r < ss) r++;
        r = (r + 255u) >> 8;
        if ((int32_t)r > level) level = (int32_t)r;
    }
    if (level > thr_g) {
        if (m->over_n < m->persist_n) m->over_n++;
    } else {
        m->over_n = 0u;
    }
    if (fail != NULL) *fail = m->over_n >= m->persist_n;
    return level;
}
