/*
 * fx.h - the fixed-point math core of Inclino (module inclino_fx, prefix fx_).
 *
 * Freestanding C11, integer only: no float, no libc, no heap. Every result is defined by C11
 * alone (no implementation-defined right shift of negatives, no signed overflow, no out-of-range
 * conversion), so the outputs are bit-identical on the host, Cortex-M0+/M3/M4F and rv32imac.
 * The full description, with error budgets and measured errors, is docs/fixed-point.md.
 *
 * Q FORMATS (the project convention; docs/fixed-point.md is the one place that lists them)
 *   fx_q16_t  int32, Q16.16: value = raw / 2^16. Physical quantities in their base unit:
 *             acceleration g, angular rate deg/s, angle deg, temperature degC, voltage V.
 *             Range [-32768, 32768 - 2^-16], resolution 2^-16 = 1.53e-5.
 *   fx_q30_t  int32, Q2.30: value = raw / 2^30. Unitless ratios: sin, cos, asin input, gains,
 *             Kalman gains. Range [-2, 2 - 2^-30], resolution 2^-30 = 9.31e-10.
 *   int64     accumulators (sums of int32 samples, full products before rounding).
 *   Internal formats of the trig code (Q24 degrees, Q32..Q58 unsigned polynomial terms) are listed
 *   in docs/fixed-point.md; they never cross this interface.
 *
 * ROUNDING: every operation that drops bits rounds to nearest, ties away from zero (like C's
 *   lround), so f(-x) == -f(x) holds exactly for multiply, divide, shifts and the odd trig
 *   functions. Its error is at most 0.5 LSB of the result format.
 *
 * SATURATION: results that do not fit the output format saturate to INT32_MIN / INT32_MAX
 *   (never wrap). Functions that can fail return int (0 or a negative enum inc_err code) and
 *   always write a documented value; total functions (everything else) return the value.
 *
 * ERROR BOUNDS below are against exact math on the exact input value, in LSB of the output
 *   format, and are proven by tests/fx (dense or exhaustive sweeps against double precision).
 */
#ifndef INCLINO_FX_H
#define INCLINO_FX_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/error.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- Formats ------------------------------------------------------------------------------ */

typedef int32_t fx_q16_t; /* Q16.16: physical quantity in its base unit (g, deg/s, deg, degC, V) */
typedef int32_t fx_q30_t; /* Q2.30: unitless ratio, [-2, 2) */

#define FX_Q16_SHIFT 16
#define FX_Q30_SHIFT 30
#define FX_Q16_ONE ((fx_q16_t)0x00010000) /* 1.0 in Q16 */
#define FX_Q30_ONE ((fx_q30_t)0x40000000) /* 1.0 in Q30 */
#define FX_Q16_HALF ((fx_q16_t)0x00008000)
#define FX_Q30_HALF ((fx_q30_t)0x20000000)

/* An integer constant n in Q16 (compile time; n must be in [-32768, 32767]). */
#define FX_Q16_INT(n) ((fx_q16_t)((n)*65536))
/* Angles in Q16 degrees. */
#define FX_DEG_45 FX_Q16_INT(45)
#define FX_DEG_90 FX_Q16_INT(90)
#define FX_DEG_180 FX_Q16_INT(180)
#define FX_DEG_360 ((int32_t)23592960) /* 360 * 2^16 */

/* ---- Defined shifts, saturation, abs (inline: a few instructions each) --------------------- */

/* floor(x / 2^s): arithmetic right shift, defined for negative x. Any s (s >= 31 gives the
 * exact mathematical result, 0 or -1). Exact. */
static inline int32_t fx_asr32(int32_t x, unsigned s)
{
    if (s > 30u) return x < 0 ? -1 : 0;
    /* Only non-negative values are shifted: -1 - x >= 0 for negative x and never overflows, and
     * floor(x / 2^s) = -1 - floor((-1 - x) / 2^s). Compilers emit one ASR for the body. */
    return x >= 0 ? (x >> s) : -1 - ((-1 - x) >> s);
}

/* floor(x / 2^s) for int64, any s (s >= 63 gives 0 or -1). Exact. */
static inline int64_t fx_asr64(int64_t x, unsigned s)
{
    if (s > 62u) return x < 0 ? -1 : 0;
    return x >= 0 ? (x >> s) : -1 - ((-1 - x) >> s);
}

/* |x| as uint32, exact for every x (|INT32_MIN| = 2^31). */
static inline uint32_t fx_uabs32(int32_t x)
{
    return x < 0 ? 0u - (uint32_t)x : (uint32_t)x;
}

/* |x| as uint64, exact for every x. */
static inline uint64_t fx_uabs64(int64_t x)
{
    return x < 0 ? 0u - (uint64_t)x : (uint64_t)x;
}

/* int64 -> int32, saturating. Exact inside [INT32_MIN, INT32_MAX]. */
static inline int32_t fx_sat32(int64_t x)
{
    return x > INT32_MAX ? INT32_MAX : (x < INT32_MIN ? INT32_MIN : (int32_t)x);
}

/* |x|, saturating: fx_abs(INT32_MIN) = INT32_MAX (error 1 LSB there), exact elsewhere. */
static inline int32_t fx_abs(int32_t x)
{
    return x >= 0 ? x : (x == INT32_MIN ? INT32_MAX : -x);
}

/* -x, saturating: fx_neg(INT32_MIN) = INT32_MAX, exact elsewhere. */
static inline int32_t fx_neg(int32_t x)
{
    return x == INT32_MIN ? INT32_MAX : -x;
}

/* a + b and a - b in one Q format (Q16+Q16, Q30+Q30, ...), saturating; exact when in range. */
static inline int32_t fx_add(int32_t a, int32_t b)
{
    return fx_sat32((int64_t)a + b);
}

static inline int32_t fx_sub(int32_t a, int32_t b)
{
    return fx_sat32((int64_t)a - b);
}

/* min(max(x, lo), hi). Requires lo <= hi; if lo > hi the result is hi. */
static inline int32_t fx_clamp(int32_t x, int32_t lo, int32_t hi)
{
    if (x < lo) x = lo;
    return x > hi ? hi : x;
}

/* x * 2^s, saturating, defined for negative x (C's << of a negative is undefined).
 * Any s is allowed; s >= 32 saturates every non-zero x. Exact when in range. */
static inline int32_t fx_lshift_sat32(int32_t x, unsigned s)
{
    if (s > 32u) s = 32u;
    return fx_sat32((int64_t)x * ((int64_t)1 << s));
}

/* ---- Rounding shifts and conversions ----------------------------------------------------- */

/* round(x / 2^s), ties away from zero; any s (s >= 33 gives 0). |error| <= 0.5 LSB. Never
 * saturates (the result always fits). */
int32_t fx_rshift_round32(int32_t x, unsigned s);

/* round(x / 2^s) for int64, ties away from zero; any s (s >= 65 gives 0). |error| <= 0.5 LSB. */
int64_t fx_rshift_round64(int64_t x, unsigned s);

/* Integer n -> Q16, saturating for |n| > 32767 (INT32_MIN/MAX). Exact in range. */
static inline fx_q16_t fx_q16_from_int(int32_t n)
{
    return fx_lshift_sat32(n, FX_Q16_SHIFT);
}

/* Q16 -> nearest integer, ties away from zero. |error| <= 0.5. */
static inline int32_t fx_q16_round_int(fx_q16_t x)
{
    return fx_rshift_round32(x, FX_Q16_SHIFT);
}

/* Q30 -> Q16, ties away from zero. |error| <= 0.5 LSB Q16. Never saturates. */
static inline fx_q16_t fx_q30_to_q16(fx_q30_t x)
{
    return fx_rshift_round32(x, FX_Q30_SHIFT - FX_Q16_SHIFT);
}

/* Q16 -> Q30, exact for x in [-2, 2); saturates outside. */
static inline fx_q30_t fx_q16_to_q30(fx_q16_t x)
{
    return fx_lshift_sat32(x, FX_Q30_SHIFT - FX_Q16_SHIFT);
}

/* ---- Multiply ------------------------------------------------------------------------------ */

/* round(a * b / 2^shift), ties away from zero, saturating to int32. The product is exact in
 * int64 (|a*b| <= 2^62); any shift is allowed (large shifts give the rounded math result, 0 or
 * +-1). |error| <= 0.5 LSB when not saturated. */
int32_t fx_mul_shift(int32_t a, int32_t b, unsigned shift);

/* Q16 * Q16 -> Q16, round(a*b / 2^16), ties away from zero. Saturates when |a*b| >= 32768.
 * |error| <= 0.5 LSB (7.6e-6) when not saturated. */
fx_q16_t fx_mul_q16(fx_q16_t a, fx_q16_t b);

/* Q30 * Q30 -> Q30, round(a*b / 2^30), ties away from zero. Saturates when the product is
 * outside [-2, 2) (e.g. 1.5 * 1.5). |error| <= 0.5 LSB (4.7e-10) when not saturated. */
fx_q30_t fx_mul_q30(fx_q30_t a, fx_q30_t b);

/* Q16 * Q30 -> Q16: scale a physical quantity by a gain/ratio. Same arithmetic as fx_mul_q30
 * (round(a*g / 2^30), ties away from zero); saturates to INT32_MIN/MAX when |a*g| >= 32768.
 * |error| <= 0.5 LSB Q16 when not saturated. */
static inline fx_q16_t fx_mul_q16_q30(fx_q16_t a, fx_q30_t g)
{
    return fx_mul_q30(a, g);
}

/* ---- Divide and reciprocal --------------------------------------------------------------- */

/* *quot = round(num * 2^frac_bits / den), ties away from zero; frac_bits in [0, 31].
 * Operands in any one format; the quotient has frac_bits fractional bits more than num has
 * relative to den (Q16/Q16 with 16 -> Q16; Q16/Q16 with 30 -> Q30 ratio; Q30/Q30 with 30 -> Q30).
 * Returns 0 with |error| <= 0.5 LSB; or
 *   INC_ERR_NULL   quot is NULL;
 *   INC_ERR_INVAL  den == 0 or frac_bits > 31: *quot = INT32_MAX if num > 0, INT32_MIN if
 *                  num < 0, 0 if num == 0 (den == 0), 0 (frac_bits > 31);
 *   INC_ERR_RANGE  the quotient does not fit int32: *quot saturated to INT32_MIN/MAX. */
int fx_div(int32_t num, int32_t den, unsigned frac_bits, int32_t *quot);

/* Q16 / Q16 -> Q16 (fx_div with 16 fractional bits). Saturates (INC_ERR_RANGE) when
 * |num/den| >= 32768. */
static inline int fx_div_q16(fx_q16_t num, fx_q16_t den, fx_q16_t *quot)
{
    return fx_div(num, den, FX_Q16_SHIFT, quot);
}

/* Q30 / Q30 -> Q30 (fx_div with 30 fractional bits). Saturates (INC_ERR_RANGE) when
 * num/den is outside [-2, 2). Also Q16/Q16 -> Q30 ratio. */
static inline int fx_div_q30(fx_q30_t num, fx_q30_t den, fx_q30_t *quot)
{
    return fx_div(num, den, FX_Q30_SHIFT, quot);
}

/* 1/x, Q16 -> Q16: round(2^32 / x). In range (|error| <= 0.5 LSB) for x < -2^-15 or x > 2^-15
 * (raw |x| > 2; raw x = -2 gives -32768 exactly); x == 0 -> INC_ERR_INVAL, other tiny x ->
 * INC_ERR_RANGE, both saturated as fx_div. */
static inline int fx_recip_q16(fx_q16_t x, fx_q16_t *r)
{
    return fx_div(FX_Q16_ONE, x, FX_Q16_SHIFT, r);
}

/* 1/x, Q30 -> Q30: round(2^60 / x). In range (|error| <= 0.5 LSB) for |x| > 0.5 and x = -0.5;
 * otherwise saturated as fx_div (INC_ERR_RANGE, or INC_ERR_INVAL for x == 0). */
static inline int fx_recip_q30(fx_q30_t x, fx_q30_t *r)
{
    return fx_div(FX_Q30_ONE, x, FX_Q30_SHIFT, r);
}

/* round(num / den) of an int64 by a uint32, ties away from zero, saturated to int32: scaling an
 * exact int64 product by a rational constant (raw counts x LSB -> Q16, and back). Any num; den
 * == 0 gives INT32_MAX for num > 0, INT32_MIN for num < 0 and 0 for 0 (as fx_div). |error| <= 0.5
 * LSB when not saturated. The same division as fx_sum_mean. */
int32_t fx_div64(int64_t num, uint32_t den);

/*
 * 64-bit division (base/fx/fx_div64.c), exact integers, no Q format: C's quotient and
 * remainder, bit for bit (tests/fx test_fx_div64: against the compiler's own division on the
 * host, edge cases and a million random pairs of every magnitude). fx_udivmod64: n / d, *rem =
 * n % d (rem may be NULL); d == 0 gives UINT64_MAX and *rem = n. fx_divmod64: truncated toward
 * zero, the remainder takes n's sign, |rem| < |d|; d == 0 gives INT64_MAX for n > 0, INT64_MIN
 * for n < 0, 0 for 0, and *rem = n; INT64_MIN / -1 gives INT64_MIN, remainder 0 (C leaves both
 * undefined). No rounding, no saturation otherwise, error 0. Cost: a
 * 32-bit division when both operands fit 32 bits, else one shift-subtract step per quotient bit
 * (at most 64). On the Cortex-M0+ they are also gcc's __aeabi_uldivmod / __aeabi_ldivmod.
 */
uint64_t fx_udivmod64(uint64_t n, uint64_t d, uint64_t *rem);
int64_t fx_divmod64(int64_t n, int64_t d, int64_t *rem);

/* round(x * m / d), ties away from zero, saturated to int32: fx_div64(x * m, d), bit for bit, for
 * |x| < 2^32 and m < 2^31 (so x * m fits int64); d == 0 as fx_div64. |error| <= 0.5 LSB when not
 * saturated. When |x| < 2^32 and (d - 1) * m < 2^32 it needs only 32-bit divisions (two), so a
 * counts-to-Q16 scaling costs tens of instructions on the M0+ instead of a 64-bit division;
 * otherwise it is fx_div64. */
int32_t fx_muldiv(int64_t x, uint32_t m, uint32_t d);

/* ---- Accumulation ------------------------------------------------------------------------- */

/* Running sum of int32 samples (any one Q format) in int64. Up to FX_SUM_MAX_COUNT samples can
 * never overflow: 2^31 * 2^31 = 2^62 < 2^63. Caller-owned; zero-initialise or fx_sum_reset. */
struct fx_sum {
    int64_t sum;
    uint32_t count;
};

#define FX_SUM_MAX_COUNT 0x80000000u /* 2^31 samples */

void fx_sum_reset(struct fx_sum *acc);

/* Add one sample. INC_ERR_NULL for acc == NULL; INC_ERR_OVERFLOW when count is already
 * FX_SUM_MAX_COUNT (the sample is not added, the sum stays valid). Exact. */
int fx_sum_add(struct fx_sum *acc, int32_t x);

/* *mean = round(sum / count), ties away from zero, same Q format as the samples; |error| <= 0.5
 * LSB, never saturates. INC_ERR_NULL for a NULL pointer; INC_ERR_STATE when count == 0 (mean
 * untouched). */
int fx_sum_mean(const struct fx_sum *acc, int32_t *mean);

/* Mean of n samples x[0..n-1] with the same rounding. INC_ERR_NULL (x or mean NULL),
 * INC_ERR_INVAL when n == 0 or n > FX_SUM_MAX_COUNT (mean untouched). */
int fx_mean_i32(const int32_t *x, uint32_t n, int32_t *mean);

/* ---- Square roots --------------------------------------------------------------------------- */

/* floor(sqrt(n)), exact for every uint32 n (result <= 65535). */
uint32_t fx_isqrt32(uint32_t n);

/* floor(sqrt(n)), exact for every uint64 n (result <= 2^32 - 1). */
uint32_t fx_isqrt64(uint64_t n);

/* round(sqrt(n)) to nearest (no ties exist), |error| <= 0.5 LSB, for n <= 2^64 - 2^32; above
 * that the rounded root would be 2^32 and saturates to 2^32 - 1 (|error| < 1 LSB). */
uint32_t fx_isqrt64_round(uint64_t n);

/* sqrt(x), Q16 -> Q16, rounded to nearest (no ties exist): |error| <= 0.5 LSB (7.6e-6).
 * x < 0 is clamped to 0 (result 0). Output <= 181.02 (raw < 2^23.5), never saturates. */
fx_q16_t fx_sqrt_q16(fx_q16_t x);

/* sqrt(x), Q30 -> Q30, rounded to nearest: |error| <= 0.5 LSB (4.7e-10). x < 0 is clamped to 0.
 * Output < 1.4143 (raw < 2^30.5), never saturates. */
fx_q30_t fx_sqrt_q30(fx_q30_t x);

/* ---- Trigonometry (angles in Q16 degrees, ratios in Q30) ------------------------------------ */

/* atan2(y, x) in Q16 degrees, range [-180, 180] (both ends reachable). y and x are any int32 in
 * one common format (only their ratio and signs matter), including INT32_MIN. Exact on the axes
 * and diagonals:
 *   atan2(0, 0) = 0; atan2(0, x>0) = 0; atan2(0, x<0) = +180 deg; atan2(y>0, 0) = +90;
 *   atan2(y<0, 0) = -90; |y| == |x| -> +-45 / +-135.
 * The result is rounded to the nearest LSB, so just below the negative x axis (y < 0, x < 0,
 * |y/x| below about 1.3e-7 rad, half an LSB) it is exactly -180 deg, e.g. atan2(-1, -2^30) =
 * -180; just above it, +180. A caller that needs (-180, 180] maps -180 to +180 itself.
 * Odd in y: atan2(-y, x) == -atan2(y, x) exactly (except the +180 of the negative x axis).
 * |error| <= 0.81 LSB Q16 (1.24e-5 deg) everywhere (error budget in fx_trig.c; measured max
 * 0.57 LSB); the requirement is 0.001 deg = 65.5 LSB.
 * Method: 28-step CORDIC vectoring in the first octant (docs/fixed-point.md). */
fx_q16_t fx_atan2_deg(int32_t y, int32_t x);

/* asin(x) in Q16 degrees, x in Q30. Inputs outside [-1, 1] are clamped to +-1 (result +-90 deg):
 * a ratio A/g that exceeds 1 through noise or vibration reads as the end of the range.
 * Computed as atan2(x, sqrt((1 - x)(1 + x))) with the product exact in 64 bits, so the steep
 * slope near +-1 costs no accuracy. Exact at 0 and +-1; odd: asin(-x) == -asin(x).
 * |error| <= 0.81 LSB Q16 (1.24e-5 deg) for every representable input (atan2's budget plus
 * < 0.002 LSB from the cosine leg; measured max 0.55 LSB); the requirement is 0.001 deg. */
fx_q16_t fx_asin_deg(fx_q30_t x);

/* sin and cos of an angle in Q16 degrees (any int32: the reduction modulo 360 deg is exact
 * integer arithmetic), result Q30 in [-1, 1]. Exact at multiples of 90 deg (0, +-1) and
 * 30/60 deg (0.5); sin is odd and cos is even exactly.
 * |error| <= 0.57 LSB Q30 (5.3e-10): 0.5 output rounding + < 0.065 LSB polynomial truncation
 * and internal rounding (docs/fixed-point.md); measured max 0.545 LSB over every angle.
 * Method: octant reduction, then Taylor polynomials of degree 11 (sin) / 12 (cos) evaluated in
 * unsigned 32x32->64-bit Horner steps with per-coefficient scaling. */
fx_q30_t fx_sin_deg(fx_q16_t deg);
fx_q30_t fx_cos_deg(fx_q16_t deg);

/* Both at once (one reduction); sin_out or cos_out may be NULL. Same values and bounds as
 * fx_sin_deg / fx_cos_deg. */
void fx_sincos_deg(fx_q16_t deg, fx_q30_t *sin_out, fx_q30_t *cos_out);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_FX_H */
