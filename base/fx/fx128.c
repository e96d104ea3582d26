/*
 * fx128.c - 128-bit signed integer helpers for the Kalman covariance arithmetic
 * (see inclino/fx128.h).
 *
 * Why the code looks the way it does:
 *  - Everything is done on unsigned words: two's complement wrap-around of uint64 is defined,
 *    signed overflow is not. Signs are handled on magnitudes (uint128 as two words), so the
 *    rounding is symmetric (ties away from zero) like fx_arith.c, and no negative value is ever
 *    right-shifted.
 *  - The multiply uses four 32x32->64 partial products: plain C that every target compiles
 *    (Cortex-M0+ has no 64-bit multiply instruction; gcc calls __aeabi_lmul from libgcc there).
 *  - The division is a restoring shift-subtract over the quotient bits only. |den| <= 2^63 and
 *    the running remainder stays below |den|, so 2 * rem + 1 < 2^64 never overflows.
 */
#include "inclino/fx128.h"

#include <stddef.h>

#include "fx_internal.h"

/* An unsigned 128-bit magnitude (internal). */
typedef struct {
    uint64_t lo, hi;
} u128;

static u128 neg_u(u128 x) /* two's complement negation, modulo 2^128 */
{
    u128 r;
    uint64_t carry = x.lo == 0u ? 1u : 0u; /* ~lo + 1 carries into hi only when lo is 0 */
    r.lo = ~x.lo + 1u;
    r.hi = ~x.hi + carry;
    return r;
}

static u128 mag(fx_i128_t x) /* |x|, exact (|-2^127| = 2^127 fits unsigned) */
{
    u128 r;
    r.lo = x.lo;
    r.hi = x.hi;
    return fx_i128_is_neg(x) ? neg_u(r) : r;
}

static fx_i128_t from_u(u128 m, bool neg) /* +-m, m <= 2^127 (2^127 only with neg) */
{
    fx_i128_t r;
    if (neg) m = neg_u(m);
    r.lo = m.lo;
    r.hi = m.hi;
    return r;
}

static u128 mul_u64(uint64_t a, uint64_t b)
{
    uint64_t a0 = (uint32_t)a, a1 = a >> 32, b0 = (uint32_t)b, b1 = b >> 32;
    uint64_t p00 = a0 * b0, mid;
    u128 r;
    /* Operands that fit 32 bits (Q30 coefficients, small values) skip their partial products:
     * each 32x32->64 product is a libgcc call on Cortex-M0+. The result is the same. */
    if (a1 == 0u && b1 == 0u) {
        r.lo = p00;
        r.hi = 0u;
        return r;
    }
    if (a1 == 0u || b1 == 0u) {
        uint64_t x = a1 == 0u ? a0 : b0;  /* the 32-bit operand */
        uint64_t y1 = a1 == 0u ? b1 : a1; /* high word of the other */
        uint64_t p1 = x * y1;
        mid = (p00 >> 32) + (uint32_t)p1; /* < 2^33 */
        r.lo = (mid << 32) | (uint32_t)p00;
        r.hi = (p1 >> 32) + (mid >> 32);
        return r;
    }
    {
        uint64_t p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
        mid = (p00 >> 32) + (uint32_t)p01 + (uint32_t)p10; /* < 3 * 2^32 */
        r.lo = (mid << 32) | (uint32_t)p00;
        r.hi = p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
    }
    return r;
}

fx_i128_t fx_i128_mul(int64_t a, int64_t b)
{
    uint64_t ua = a < 0 ? 0u - (uint64_t)a : (uint64_t)a;
    uint64_t ub = b < 0 ? 0u - (uint64_t)b : (uint64_t)b;
    return from_u(mul_u64(ua, ub), (a < 0) != (b < 0)); /* |a * b| <= 2^126 */
}

static const fx_i128_t I128_MAX = {UINT64_MAX, UINT64_MAX >> 1};
static const fx_i128_t I128_MIN = {0u, (uint64_t)1 << 63};

fx_i128_t fx_i128_add(fx_i128_t a, fx_i128_t b)
{
    fx_i128_t r;
    r.lo = a.lo + b.lo;
    r.hi = a.hi + b.hi + (r.lo < a.lo ? 1u : 0u);
    /* Overflow only when both operands have the same sign and the sum's sign differs. */
    if (fx_i128_is_neg(a) == fx_i128_is_neg(b) && fx_i128_is_neg(r) != fx_i128_is_neg(a)) {
        return fx_i128_is_neg(a) ? I128_MIN : I128_MAX;
    }
    return r;
}

fx_i128_t fx_i128_sub(fx_i128_t a, fx_i128_t b)
{
    fx_i128_t r;
    r.lo = a.lo - b.lo;
    r.hi = a.hi - b.hi - (a.lo < b.lo ? 1u : 0u);
    /* Overflow only when the operands have different signs and the result's sign is b's. */
    if (fx_i128_is_neg(a) != fx_i128_is_neg(b) && fx_i128_is_neg(r) != fx_i128_is_neg(a)) {
        return fx_i128_is_neg(a) ? I128_MIN : I128_MAX;
    }
    return r;
}

fx_i128_t fx_i128_mac(fx_i128_t acc, int64_t a, int64_t b)
{
    return fx_i128_add(acc, fx_i128_mul(a, b));
}

int fx_i128_cmp(fx_i128_t a, fx_i128_t b)
{
    bool na = fx_i128_is_neg(a), nb = fx_i128_is_neg(b);
    if (na != nb) return na ? -1 : 1;
    /* Same sign: two's complement order equals unsigned order of the words. */
    if (a.hi != b.hi) return a.hi < b.hi ? -1 : 1;
    if (a.lo != b.lo) return a.lo < b.lo ? -1 : 1;
    return 0;
}

/* m >> s for s in 0..127. */
static u128 shr_u(u128 m, unsigned s)
{
    u128 r;
    if (s == 0u) return m;
    if (s < 64u) {
        r.lo = (m.lo >> s) | (m.hi << (64u - s));
        r.hi = m.hi >> s;
    } else {
        r.lo = m.hi >> (s - 64u);
        r.hi = 0u;
    }
    return r;
}

/* +-m saturated to int64 (m a magnitude); *sat set on saturation. */
static int64_t sat_i64(u128 m, bool neg, bool *sat)
{
    if (neg) {
        if (m.hi != 0u || m.lo > ((uint64_t)1 << 63)) {
            if (sat != NULL) *sat = true;
            return INT64_MIN;
        }
        return m.lo == ((uint64_t)1 << 63) ? INT64_MIN : -(int64_t)m.lo;
    }
    if (m.hi != 0u || m.lo > (uint64_t)INT64_MAX) {
        if (sat != NULL) *sat = true;
        return INT64_MAX;
    }
    return (int64_t)m.lo;
}

int64_t fx_i128_rshift_round(fx_i128_t x, unsigned s, bool *sat)
{
    bool neg = fx_i128_is_neg(x);
    u128 m = mag(x), r;
    if (s == 0u) return sat_i64(m, neg, sat);
    if (s > 128u) return 0;
    if (s == 128u) {
        /* |x| / 2^128 <= 1/2: only |x| = 2^127 is a tie, which rounds away to 1. */
        r.lo = m.hi >> 63;
        r.hi = 0u;
    } else {
        u128 half = shr_u(m, s - 1u); /* floor(m / 2^(s-1)) */
        r = shr_u(half, 1u);
        if (half.lo & 1u) { /* the dropped bits are >= 1/2: round the magnitude up */
            r.lo += 1u;
            if (r.lo == 0u) r.hi += 1u;
        }
    }
    return sat_i64(r, neg, sat);
}

/* Bit length of a non-zero uint64 (1..64), portable (fx_msb32 has no builtin either). */
static unsigned bitlen64(uint64_t x)
{
    return (x >> 32) != 0u ? 33u + fx_msb32((uint32_t)(x >> 32)) : 1u + fx_msb32((uint32_t)x);
}

int fx_i128_div_i64(fx_i128_t num, int64_t den, int64_t *quot)
{
    bool neg, sat = false;
    u128 n, qm;
    uint64_t d, q, rem;

    if (quot == NULL) return INC_ERR_NULL;
    if (den == 0) {
        bool zero = num.lo == 0u && num.hi == 0u;
        *quot = zero ? 0 : (fx_i128_is_neg(num) ? INT64_MIN : INT64_MAX);
        return INC_ERR_INVAL;
    }
    neg = fx_i128_is_neg(num) != (den < 0);
    n = mag(num);
    d = den < 0 ? 0u - (uint64_t)den : (uint64_t)den; /* 1 .. 2^63 */

    if (n.hi >= d) {
        /* The quotient is >= 2^64: far outside int64. */
        *quot = neg ? INT64_MIN : INT64_MAX;
        return INC_ERR_RANGE;
    }
    if (n.hi == 0u) {
        q = n.lo / d;
        rem = n.lo - q * d;
    } else {
        /* Quotient bits: bitlen(n) - bitlen(d) + 1, and never more than 64 (n.hi < d, so the
         * quotient is < 2^64). rem starts as n >> steps, which is < d in both cases. */
        unsigned nb = 64u + bitlen64(n.hi), db = bitlen64(d);
        unsigned steps = nb - db + 1u, i;
        uint64_t bits;
        if (steps > 64u) steps = 64u;
        rem = shr_u(n, steps).lo;
        /* The bits still to bring down are the low `steps` bits of n (all in n.lo), left-aligned
         * in `bits`: each step takes the top one with constant shifts (a variable 64-bit shift
         * is a libgcc call on Cortex-M0+). */
        bits = steps == 64u ? n.lo : n.lo << (64u - steps);
        q = 0u;
        for (i = 0; i < steps; i++) {
            rem = (rem << 1) | (bits >> 63); /* < 2d <= 2^64 */
            bits <<= 1;
            q <<= 1;
            if (rem >= d) {
                rem -= d;
                q |= 1u;
            }
        }
    }
    /* Round the magnitude: up when rem >= d/2 (a tie rounds away from zero). */
    qm.lo = q;
    qm.hi = 0u;
    if (rem >= d - rem) {
        if (q == UINT64_MAX) {
            qm.lo = 0u; /* 2^64: out of range, sat_i64 saturates it */
            qm.hi = 1u;
        } else {
            qm.lo = q + 1u;
        }
    }
    *quot = sat_i64(qm, neg, &sat);
    return sat ? INC_ERR_RANGE : INC_OK;
}
