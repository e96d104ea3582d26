/*
 * cal_tmodel.c - evaluation of the record's temperature models (see inclino/cal.h, calrec.h).
 *
 * The models come from the calibration station ([ADI-EPB]'s three-point parabola, [TEMP-LORENTZ]'s
 * linear and Lorentz fits, a knot table, Lorentz + cubic). Here they are only evaluated, once per
 * temperature change. Why it is written this way:
 *  - The polynomial argument u = (Th - t_ref) / t_span is Q30 with |u| <= 1 (T held in the
 *    calibrated range, record version 2), so every Horner step is one fx_mul_shift(.., u, 30)
 *    that keeps the y format of the coefficients (g Q16 or ratio Q30) and rounds once.
 *  - The Lorentz quotient w^2 / (w^2 + 4 d^2) is formed exactly in 64 bits (d <= 300 degC after
 *    the clamp: 4 d^2 < 2^50.4, w^2 < 2^49.3), then both terms are scaled down by the same power
 *    of two until the denominator fits 31 bits, and divided once: no overflow for any T, and no
 *    loss beyond 1 LSB Q30.
 *  - Fields that the arithmetic depends on (spans, width, centre, knot count) are checked again
 *    here, so an unchecked model cannot cause a division by zero or an overflow; the y
 *    parameters need no check (every step saturates).
 */
#include "inclino/cal.h"

#include <stddef.h>

static bool in_range(int32_t v, int32_t lo, int32_t hi)
{
    return v >= lo && v <= hi;
}

/* u = (Th - t_ref) / span in Q30 and Th = T held in [t_ref - span, t_ref + span]. */
static fx_q30_t norm_u(fx_q16_t t, int32_t t_ref, int32_t span, fx_q16_t *th)
{
    const int64_t d = (int64_t)t - t_ref;
    fx_q30_t u;
    if (d >= span) {
        *th = t_ref + span; /* <= 400 degC: no overflow */
        return FX_Q30_ONE;
    }
    if (d <= -span) {
        *th = t_ref - span;
        return -FX_Q30_ONE;
    }
    *th = t;
    (void)fx_div((int32_t)d, span, FX_Q30_SHIFT, &u); /* |d| < span: |u| <= 1, never fails */
    return u;
}

/* 1 / (1 + (2 (t - tc) / w)^2) = w^2 / (w^2 + 4 (t - tc)^2) in Q30; t, tc within [-100, 200]
 * degC and w within [1, 400] degC (checked by the caller). */
static fx_q30_t lorentz_q30(fx_q16_t t, int32_t w, int32_t tc)
{
    const int64_t d = (int64_t)t - tc;
    const uint64_t w2 = (uint64_t)((int64_t)w * w);
    const uint64_t den = w2 + 4u * (uint64_t)(d * d);
    unsigned s = 0;
    fx_q30_t l;
    /* After rounding the denominator must still fit int32: keep it below 2^31 - 1 first. */
    while ((den >> s) >= 0x7FFFFFFFu) {
        s++;
    }
    (void)fx_div((int32_t)fx_rshift_round64((int64_t)w2, s),
                 (int32_t)fx_rshift_round64((int64_t)den, s), FX_Q30_SHIFT, &l);
    return l;
}

/* y += p * q / 2^30, saturating (q a Q30 factor: u, L or a fraction). */
static int32_t mac_q30(int32_t y, int32_t p, fx_q30_t q)
{
    return fx_add(y, fx_mul_shift(p, q, FX_Q30_SHIFT));
}

static bool poly_fields_ok(const struct calrec_tmodel *m)
{
    return m->n == 0 && in_range(m->t_ref, CALREC_LIM_T_MIN, CALREC_LIM_T_MAX) &&
           in_range(m->t_span, CALREC_LIM_SPAN_MIN, CALREC_LIM_SPAN_MAX);
}

static bool lorentz_fields_ok(const struct calrec_tmodel *m)
{
    return in_range(m->p[2], CALREC_LIM_SPAN_MIN, CALREC_LIM_WIDTH_MAX) &&
           in_range(m->p[3], CALREC_LIM_T_MIN, CALREC_LIM_T_MAX);
}

int cal_tmodel_eval(const struct calrec_tmodel *m, fx_q16_t t_c, int32_t *y)
{
    fx_q16_t t, th;
    fx_q30_t u;
    int32_t h;
    if (m == NULL || y == NULL) {
        return INC_ERR_NULL;
    }
    *y = 0;
    t = fx_clamp(t_c, CAL_T_MIN, CAL_T_MAX);
    switch (m->kind) {
    case CALREC_TM_NONE: return INC_OK;
    case CALREC_TM_LINEAR:
        if (!poly_fields_ok(m)) {
            return INC_ERR_INVAL;
        }
        u = norm_u(t, m->t_ref, m->t_span, &th);
        *y = mac_q30(m->p[0], m->p[1], u);
        return INC_OK;
    case CALREC_TM_PARABOLA:
        if (!poly_fields_ok(m)) {
            return INC_ERR_INVAL;
        }
        /* [ADI-EPB]'s a t^2 + b t + c in the normalised argument, Horner: p0 + u (p1 + u p2). */
        u = norm_u(t, m->t_ref, m->t_span, &th);
        h = mac_q30(m->p[1], m->p[2], u);
        *y = mac_q30(m->p[0], h, u);
        return INC_OK;
    case CALREC_TM_LORENTZ:
        if (m->n != 0 || !lorentz_fields_ok(m)) {
            return INC_ERR_INVAL;
        }
        *y = mac_q30(m->p[0], m->p[1], lorentz_q30(t, m->p[2], m->p[3]));
        return INC_OK;
    case CALREC_TM_LORENTZ_CUBIC:
        if (!poly_fields_ok(m) || !lorentz_fields_ok(m)) {
            return INC_ERR_INVAL;
        }
        u = norm_u(t, m->t_ref, m->t_span, &th);
        h = mac_q30(m->p[5], m->p[6], u);
        h = mac_q30(m->p[4], h, u);
        *y = mac_q30(mac_q30(m->p[0], m->p[1], lorentz_q30(th, m->p[2], m->p[3])), h, u);
        return INC_OK;
    case CALREC_TM_PWL: {
        int32_t last, off, i, frac;
        fx_q30_t f;
        if (!in_range(m->n, 2, CALREC_TM_PARAMS) ||
            !in_range(m->t_ref, CALREC_LIM_T_MIN, CALREC_LIM_T_MAX) ||
            !in_range(m->t_span, CALREC_LIM_SPAN_MIN, CALREC_LIM_SPAN_MAX)) {
            return INC_ERR_INVAL;
        }
        /* (n - 1) * span <= 15 * 200 degC and t_ref <= 200 degC: the sum fits int32. */
        last = m->t_ref + (m->n - 1) * m->t_span;
        th = fx_clamp(t, m->t_ref, last);
        off = th - m->t_ref; /* 0 .. (n - 1) * span */
        i = (int32_t)((uint32_t)off / (uint32_t)m->t_span);
        if (i > m->n - 2) {
            i = m->n - 2; /* T on the last knot */
        }
        frac = off - i * m->t_span; /* 0 .. span */
        (void)fx_div(frac, m->t_span, FX_Q30_SHIFT, &f);
        *y = mac_q30(m->p[i], fx_sub(m->p[i + 1], m->p[i]), f);
        return INC_OK;
    }
    default: return INC_ERR_INVAL;
    }
}
