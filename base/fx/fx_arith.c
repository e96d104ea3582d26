/*
 * fx_arith.c - rounding shifts, multiply, divide and accumulation (see inclino/fx.h).
 *
 * Why the code looks the way it does:
 *  - Rounding works on the magnitude (uint32/uint64) and re-applies the sign. That gives "ties
 *    away from zero" with exact odd symmetry, never adds a rounding constant that could
 *    overflow near INT64_MAX, and needs no right shift of a negative number (implementation-
 *    defined in C11, 6.5.7p5).
 *  - Products are formed in int64: |int32 * int32| <= 2^62, so they are exact.
 *  - Division works on magnitudes too, so C's truncating '/' and '%' on negatives never enter
 *    the rounding decision.
 */
#include "inclino/fx.h"

#include <stddef.h>

/* round(m / 2^s) of a magnitude, ties up (= away from zero once the sign is re-applied).
 * 1 <= s <= 63. The result is <= 2^62 + 1 for m <= 2^63. */
static inline uint64_t round_mag64(uint64_t m, unsigned s)
{
    return (m >> s) + ((m >> (s - 1u)) & 1u);
}

int32_t fx_rshift_round32(int32_t x, unsigned s)
{
    uint32_t m, r;
    if (s == 0u) return x;
    if (s > 32u) return 0; /* |x| / 2^33 <= 0.25 */
    m = fx_uabs32(x);
    if (s == 32u) {
        r = m >> 31; /* only |x| = 2^31 is a tie (0.5), which rounds away to 1 */
    } else {
        r = (m >> s) + ((m >> (s - 1u)) & 1u); /* <= 2^30 + 1 */
    }
    return x < 0 ? -(int32_t)r : (int32_t)r;
}

int64_t fx_rshift_round64(int64_t x, unsigned s)
{
    uint64_t m, r;
    if (s == 0u) return x;
    if (s > 64u) return 0;
    m = fx_uabs64(x);
    r = (s == 64u) ? (m >> 63) : round_mag64(m, s);
    return x < 0 ? -(int64_t)r : (int64_t)r;
}

/* round(a*b / 2^s) saturated; s in [1, 63]. Inlined with a constant s by the Q16/Q30 forms. */
static inline int32_t mul_round_sat(int32_t a, int32_t b, unsigned s)
{
    int64_t p = (int64_t)a * b;
    uint64_t r = round_mag64(fx_uabs64(p), s);
    if (p < 0) {
        return r >= 0x80000000u ? INT32_MIN : -(int32_t)r;
    }
    return r > (uint64_t)INT32_MAX ? INT32_MAX : (int32_t)r;
}

int32_t fx_mul_shift(int32_t a, int32_t b, unsigned shift)
{
    if (shift == 0u) return fx_sat32((int64_t)a * b);
    return fx_sat32(fx_rshift_round64((int64_t)a * b, shift));
}

fx_q16_t fx_mul_q16(fx_q16_t a, fx_q16_t b)
{
    return mul_round_sat(a, b, FX_Q16_SHIFT);
}

fx_q30_t fx_mul_q30(fx_q30_t a, fx_q30_t b)
{
    return mul_round_sat(a, b, FX_Q30_SHIFT);
}

int fx_div(int32_t num, int32_t den, unsigned frac_bits, int32_t *quot)
{
    uint64_t n, d, q, r;
    bool neg;

    if (quot == NULL) return INC_ERR_NULL;
    if (frac_bits > 31u) {
        *quot = 0;
        return INC_ERR_INVAL;
    }
    if (den == 0) {
        *quot = num > 0 ? INT32_MAX : (num < 0 ? INT32_MIN : 0);
        return INC_ERR_INVAL;
    }
    neg = (num < 0) != (den < 0);
    n = (uint64_t)fx_uabs32(num) << frac_bits; /* <= 2^62 */
    d = fx_uabs32(den);
    if ((n >> 32) == 0u) {
        /* 32-bit division: one UDIV on Cortex-M3/M4 and rv32imac instead of a libgcc call. */
        q = (uint32_t)n / (uint32_t)d;
    } else {
        q = n / d;
    }
    r = n - q * d;
    if (r >= d - r) q++; /* remainder >= d/2: round up the magnitude (tie -> away from zero) */
    if (neg) {
        if (q > 0x80000000u) {
            *quot = INT32_MIN;
            return INC_ERR_RANGE;
        }
        *quot = q == 0x80000000u ? INT32_MIN : -(int32_t)q;
    } else {
        if (q > (uint64_t)INT32_MAX) {
            *quot = INT32_MAX;
            return INC_ERR_RANGE;
        }
        *quot = (int32_t)q;
    }
    return INC_OK;
}

/* round(sum / count), ties away from zero; count >= 1. The mean of int32 samples is inside
 * [INT32_MIN, INT32_MAX], so the final conversion cannot saturate. */
static int32_t mean_round(int64_t sum, uint32_t count)
{
    uint64_t m = fx_uabs64(sum), q, r;
    if (m <= UINT32_MAX) {
        /* The same quotient with a 32-bit division (the M0+'s libgcc: a short loop, against a
         * 64-bit one of several hundred instructions). */
        const uint32_t m32 = (uint32_t)m;
        uint32_t q32 = m32 / count;
        const uint32_t r32 = m32 - q32 * count;
        if (r32 >= count - r32) q32++;
        return fx_sat32(sum < 0 ? -(int64_t)q32 : (int64_t)q32); /* no wrap: q32 < 2^32 */
    }
    q = m / count;
    r = m - q * count;
    if (r >= count - r) q++;
    return fx_sat32(sum < 0 ? -(int64_t)q : (int64_t)q);
}

int32_t fx_div64(int64_t num, uint32_t den)
{
    if (den == 0u) return num > 0 ? INT32_MAX : (num < 0 ? INT32_MIN : 0);
    /* |INT64_MIN| / den >= 2^31 saturates like |INT64_MIN + 1| / den: the same result, and
     * mean_round never negates 2^63. */
    if (num < -INT64_MAX) num = -INT64_MAX;
    return mean_round(num, den);
}

int32_t fx_muldiv(int64_t x, uint32_t m, uint32_t d)
{
    const uint64_t ax = fx_uabs64(x);
    if (d != 0u && ax <= 0xFFFFu && m <= 0xFFFFu) {
        /* |x| m < 2^32: one 32-bit division. */
        const uint32_t f = (uint32_t)ax * m;
        uint32_t q = f / d;
        const uint32_t r = f - q * d;
        if (r >= d - r) q++;
        return fx_sat32(x < 0 ? -(int64_t)q : (int64_t)q);
    }
    if (d != 0u && ax <= UINT32_MAX && (uint64_t)(d - 1u) * m <= UINT32_MAX) {
        /* |x| m / d = q m + r m / d with |x| = q d + r: q m is whole, so the rounding is that of
         * r m / d alone, and r m <= (d - 1) m fits 32 bits. */
        const uint32_t a = (uint32_t)ax;
        const uint32_t q = a / d;
        const uint32_t f = (a - q * d) * m;
        uint32_t q2 = f / d;
        const uint32_t r2 = f - q2 * d;
        uint64_t mag;
        if (r2 >= d - r2) q2++;
        mag = (uint64_t)q * m + q2; /* < 2^32 * 2^32: no overflow */
        return fx_sat32(x < 0 ? -(int64_t)mag : (int64_t)mag);
    }
    return fx_div64(x * (int64_t)m, d);
}

void fx_sum_reset(struct fx_sum *acc)
{
    if (acc == NULL) return;
    acc->sum = 0;
    acc->count = 0;
}

int fx_sum_add(struct fx_sum *acc, int32_t x)
{
    if (acc == NULL) return INC_ERR_NULL;
    if (acc->count >= FX_SUM_MAX_COUNT) return INC_ERR_OVERFLOW;
    acc->sum += x; /* |sum| <= 2^31 * 2^31 = 2^62 */
    acc->count++;
    return INC_OK;
}

int fx_sum_mean(const struct fx_sum *acc, int32_t *mean)
{
    if (acc == NULL || mean == NULL) return INC_ERR_NULL;
    if (acc->count == 0u) return INC_ERR_STATE;
    *mean = mean_round(acc->sum, acc->count);
    return INC_OK;
}

int fx_mean_i32(const int32_t *x, uint32_t n, int32_t *mean)
{
    int64_t sum = 0;
    uint32_t i;
    if (x == NULL || mean == NULL) return INC_ERR_NULL;
    if (n == 0u || n > FX_SUM_MAX_COUNT) return INC_ERR_INVAL;
    for (i = 0; i < n; i++)
        sum += x[i];
    *mean = mean_round(sum, n);
    return INC_OK;
}
