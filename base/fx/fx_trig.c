/*
 * fx_trig.c - atan2, asin, sin and cos in Q16 degrees (see inclino/fx.h, docs/fixed-point.md).
 *
 * atan2 - CORDIC vectoring. The first octant is reached exactly by taking magnitudes and
 *   swapping (|y| <= |x|); the larger magnitude is normalised to [2^29, 2^30) so every input,
 *   from 1 to 2^31, gets the same 29-30 significant bits. 28 rotations by atan(2^-i) drive y to 0
 *   and accumulate the angle in Q24 degrees (2^-24 deg). Why CORDIC: shifts, adds and a 112-byte
 *   table only - no divider, no 64-bit multiply - so the cost is the same on Cortex-M0+ (no
 *   UDIV, no UMULL) as on M3/M4 and rv32imac, and the error is bounded by construction:
 *     residual after 28 steps   atan(2^-27) rad = 4.3e-7 deg   0.028 LSB Q16
 *     table rounding            28 * 0.5 * 2^-24 deg            0.055 LSB
 *     truncated shifts          <= 2 * 28 units / 2^29 rad      0.2 LSB (worst case)
 *     normalisation (>> <= 2)   3 / 2^29 rad                    0.02 LSB
 *     output rounding Q24->Q16                                  0.5 LSB
 *   sum < 0.81 LSB = 1.2e-5 deg; the requirement is 0.001 deg (65.5 LSB).
 *
 * asin - atan2(x, sqrt((1 - x)(1 + x))). The product is exact in 64 bits (each factor is in
 *   [0, 2^31]), its rounded square root has error <= 0.5 * 2^-30, and d(atan2)/d(c) <= 1 rad per
 *   unit, so the cosine leg adds < 3e-8 deg. Near +-1, where d(asin)/dx is unbounded, nothing is
 *   lost: the slope acts on the exact input, not on a rounded 1 - x^2.
 *
 * sin/cos - the angle is reduced modulo 360 deg in integers (exact), then to a quadrant and to
 *   the octant [0, 45] deg by symmetry. There t (Q16 degrees, <= 2949120 < 2^22) is turned into
 *   u = t / 2^22 exactly (u_q32 = t << 10), so the polynomial variable carries no conversion
 *   error; the polynomials are the Taylor series of sin(a u) and cos(a u) with a = 64 degrees in
 *   radians (16 pi / 45), truncated where the next term is < 7e-12 (0.008 LSB Q30). Each Horner
 *   coefficient is stored unsigned at the largest scale that fits 32 bits (Q32..Q58), and each
 *   step is one 32x32->64 multiply with a rounded shift, so the internal error stays below
 *   0.065 LSB Q30 (largest parts: rounding s = u^2 to Q33, 0.04 LSB in cos; coefficient and
 *   step rounding, about 0.01 LSB each) and the total is 0.5 LSB output rounding + < 0.065 LSB.
 *   The coefficients and the CORDIC table come from tests/fx/gen_fx_consts.py (exact decimal
 *   arithmetic); the tests compare every result with libm.
 */
#include "inclino/fx.h"

#include <stddef.h>

#include "fx_internal.h"

/* ---- atan2 -------------------------------------------------------------------------------- */

#define FX_CORDIC_STEPS 28

/* atan(2^-i) in degrees, Q24, i = 0..27 (gen_fx_consts.py). */
static const uint32_t fx_atan_tab[FX_CORDIC_STEPS] = {
    754974720u, 445687602u, 235489088u, 119537938u, 60000934u, 30029717u, 15018523u,
    7509720u,   3754917u,   1877466u,   938734u,    469367u,   234684u,   117342u,
    58671u,     29335u,     14668u,     7334u,      3667u,     1833u,     917u,
    458u,       229u,       115u,       57u,        29u,       14u,       7u,
};

/* atan(small / big) in Q16 degrees, for 0 <= small <= big, big != 0. Result in [0, 45 deg]. */
static int32_t atan_octant(uint32_t big, uint32_t small)
{
    uint32_t x;
    int32_t y, z;
    unsigned p, i;

    if (small == 0u) return 0;
    if (small == big) return FX_DEG_45;

    /* Normalise big to [2^29, 2^30): x then stays below K * sqrt(2) * 2^30 = 2.5e9 < 2^32
     * (K = 1.6468, the CORDIC gain) and |y| below 2^31. */
    p = fx_msb32(big);
    if (p > 29u) {
        big >>= p - 29u;
        small >>= p - 29u;
    } else {
        big <<= 29u - p;
        small <<= 29u - p;
    }

    /* Step 0 (rotate by -45 deg) is known to go this way because y >= 0. */
    x = big + small;                   /* <= 2^31 */
    y = (int32_t)small - (int32_t)big; /* in [-2^30, 0] */
    z = (int32_t)fx_atan_tab[0];
    for (i = 1u; i < FX_CORDIC_STEPS; i++) {
        int32_t ys = fx_asr32(y, i);
        int32_t xs = (int32_t)(x >> i); /* x < 2^32, i >= 1: fits */
        if (y >= 0) {
            x += (uint32_t)ys;
            y -= xs;
            z += (int32_t)fx_atan_tab[i];
        } else {
            x += (uint32_t)(-ys); /* ys < 0 */
            y += xs;
            z -= (int32_t)fx_atan_tab[i];
        }
    }
    /* Q24 -> Q16; clamp the last fraction of an LSB the residual could leave outside [0, 45]. */
    return fx_clamp(fx_rshift_round32(z, 8), 0, FX_DEG_45);
}

fx_q16_t fx_atan2_deg(int32_t y, int32_t x)
{
    uint32_t ax = fx_uabs32(x), ay = fx_uabs32(y);
    int32_t a;

    if (ay <= ax) {
        if (ax == 0u) return 0; /* atan2(0, 0) := 0 */
        a = atan_octant(ax, ay);
    } else {
        a = FX_DEG_90 - atan_octant(ay, ax);
    }
    if (x < 0) a = FX_DEG_180 - a;
    return y < 0 ? -a : a;
}

fx_q16_t fx_asin_deg(fx_q30_t x)
{
    uint64_t p;
    uint32_t c;

    x = fx_clamp(x, -FX_Q30_ONE, FX_Q30_ONE);
    /* (1 - x)(1 + x) in Q60: each factor in [0, 2^31], product <= 2^60. */
    p = (uint64_t)((int64_t)FX_Q30_ONE - x) * (uint64_t)((int64_t)FX_Q30_ONE + x);
    c = fx_isqrt64_round(p); /* sqrt(1 - x^2) in Q30, <= 2^30 */
    return fx_atan2_deg(x, (int32_t)c);
}

/* ---- sin / cos ---------------------------------------------------------------------------- */

/* Polynomial coefficients (gen_fx_consts.py), a = 16 pi / 45, c_k = a^k / k!, s = u^2:
 *   sin(a u) = u (1 + R),  R = (a-1) - s (c3 - s (c5 - s (c7 - s (c9 - s c11))))
 *   cos(a u) = 1 - s/2 - s e2 + s^2 (c4 - s (c6 - s (c8 - s (c10 - s c12)))),  e2 = c2 - 1/2
 * Every Horner value stays positive, so the arithmetic is unsigned. Splitting c2 = 1/2 + e2 lets
 * the largest cos term s/2 be exact and e2 be stored in Q35 instead of Q32. */
#define FX_SIN_A1 4020457769u  /* a - 1, Q35 (1.170e-01) */
#define FX_SIN_C3 3990622317u  /* Q34 (2.323e-01) */
#define FX_SIN_C5 3983320919u  /* Q38 (1.449e-02) */
#define FX_SIN_C7 3786697981u  /* Q43 (4.305e-04) */
#define FX_SIN_C9 2099872051u  /* Q48 (7.460e-06) */
#define FX_SIN_C11 3048770972u /* Q55 (8.462e-08) */
#define FX_COS_E2 4255676101u  /* c2 - 1/2, Q35 (1.239e-01) */
#define FX_COS_C4 2228783956u  /* Q35 (6.487e-02) */
#define FX_COS_C6 2966274782u  /* Q40 (2.698e-03) */
#define FX_COS_C8 2114891122u  /* Q45 (6.011e-05) */
#define FX_COS_C10 1876463675u /* Q51 (8.333e-07) */
#define FX_COS_C12 2270339908u /* Q58 (7.877e-09) */

/* round(a * b / 2^sh); callers keep a * b below 2^64 - 2^(sh-1) (checked per call site: the
 * largest is s * e2 < 1.81e19 < 2^64 = 1.845e19). 1 <= sh <= 63. */
static inline uint64_t mulr(uint32_t a, uint32_t b, unsigned sh)
{
    return ((uint64_t)a * b + ((uint64_t)1 << (sh - 1u))) >> sh;
}

/* s = u^2 = t^2 / 2^44 in Q33 (rounded), for t in [0, 45 deg] Q16 (t <= 2949120, s <= 0.4944,
 * s_q33 <= 4.247e9 < 2^32). */
static inline uint32_t oct_s(uint32_t t)
{
    return (uint32_t)(((uint64_t)t * t + 1024u) >> 11);
}

/* sin(t) in Q30 for t in [0, 45 deg] Q16. u = t / 2^22 exactly (Q32: t << 10). */
static uint32_t sin_oct(uint32_t t)
{
    uint32_t u = t << 10, s = oct_s(t), p;
    uint64_t v;
    p = FX_SIN_C9 - (uint32_t)mulr(s, FX_SIN_C11, 40); /* Q48 */
    p = FX_SIN_C7 - (uint32_t)mulr(s, p, 38);          /* Q43 */
    p = FX_SIN_C5 - (uint32_t)mulr(s, p, 38);          /* Q38 */
    p = FX_SIN_C3 - (uint32_t)mulr(s, p, 37);          /* Q34 */
    p = FX_SIN_A1 - (uint32_t)mulr(s, p, 32);          /* R, Q35, in [0.0056, 0.117] */
    v = ((uint64_t)u << 8) + mulr(u, p, 27);           /* u (1 + R), Q40 */
    return (uint32_t)((v + (1u << 9)) >> 10);
}

/* cos(t) in Q30 for t in [0, 45 deg] Q16. */
static uint32_t cos_oct(uint32_t t)
{
    uint32_t s = oct_s(t), p;
    uint64_t v;
    p = FX_COS_C10 - (uint32_t)mulr(s, FX_COS_C12, 40); /* Q51 */
    p = FX_COS_C8 - (uint32_t)mulr(s, p, 39);           /* Q45 */
    p = FX_COS_C6 - (uint32_t)mulr(s, p, 38);           /* Q40 */
    p = FX_COS_C4 - (uint32_t)mulr(s, p, 38);           /* Q35 */
    p = (uint32_t)mulr(s, p, 33);                       /* s (c4 - ...), Q35, <= 0.032 */
    v = ((uint64_t)1 << 40) - ((uint64_t)s << 6)        /* 1 - s/2, exact, Q40 */
        - mulr(s, FX_COS_E2, 28) + mulr(s, p, 28);
    return (uint32_t)((v + (1u << 9)) >> 10);
}

/* deg = quadrant * 90 + r (mod 360 deg), r in [0, 90 deg). Exact. */
static unsigned reduce_quadrant(int32_t deg, int32_t *r)
{
    int32_t a = deg % FX_DEG_360; /* C99 truncation: a in (-360, 360) deg */
    unsigned q = 0;
    if (a < 0) a += FX_DEG_360;
    if (a >= FX_DEG_180) {
        a -= FX_DEG_180;
        q = 2u;
    }
    if (a >= FX_DEG_90) {
        a -= FX_DEG_90;
        q += 1u;
    }
    *r = a;
    return q;
}

/* sin(r) and cos(r) for r in [0, 90 deg), as Q30 magnitudes. At r = 45 deg both take sin_oct, so
 * that sin(45) == cos(45) and the symmetries stay exact. */
static uint32_t sin_r(int32_t r)
{
    return r <= FX_DEG_45 ? sin_oct((uint32_t)r) : cos_oct((uint32_t)(FX_DEG_90 - r));
}

static uint32_t cos_r(int32_t r)
{
    return r < FX_DEG_45 ? cos_oct((uint32_t)r) : sin_oct((uint32_t)(FX_DEG_90 - r));
}

/* sin(q * 90 + r). */
static fx_q30_t sin_quadrant(unsigned q, int32_t r)
{
    int32_t m = (int32_t)((q & 1u) ? cos_r(r) : sin_r(r)); /* <= 2^30 */
    return (q & 2u) ? -m : m;
}

fx_q30_t fx_sin_deg(fx_q16_t deg)
{
    int32_t r;
    unsigned q = reduce_quadrant(deg, &r);
    return sin_quadrant(q, r);
}

fx_q30_t fx_cos_deg(fx_q16_t deg)
{
    int32_t r;
    unsigned q = reduce_quadrant(deg, &r);
    return sin_quadrant((q + 1u) & 3u, r); /* cos(x) = sin(x + 90 deg) */
}

void fx_sincos_deg(fx_q16_t deg, fx_q30_t *sin_out, fx_q30_t *cos_out)
{
    int32_t r;
    unsigned q = reduce_quadrant(deg, &r);
    if (sin_out != NULL) *sin_out = sin_quadrant(q, r);
    if (cos_out != NULL) *cos_out = sin_quadrant((q + 1u) & 3u, r);
}
