/*
 * fx128.h - 128-bit signed integers for int64 covariance arithmetic (module inclino_fx,
 * prefix fx_i128_).
 *
 * Why: the Kalman filters keep covariances in int64 with 48 fractional bits (docs/kalman.md);
 * a product of two such numbers, or of one and a Q30 coefficient, needs up to 126 bits before it
 * is rounded back. C11 has no 128-bit type on 32-bit targets, so this is a two-word struct in
 * portable C: the same bits on the host, Cortex-M0+/M3/M4F and rv32imac. Only what the filters
 * need: exact multiply, saturating add/subtract, a rounding right shift back to int64 and a
 * rounding division by an int64.
 *
 * FORMAT: fx_i128_t holds a two's complement value v = hi * 2^64 + lo with hi read as signed
 *   (bit 127 is the sign). Range [-2^127, 2^127 - 1]. The binary point is the caller's: these
 *   are integer operations, a product of Qa and Qb operands is Q(a+b).
 * ROUNDING: to nearest, ties away from zero, like the rest of fx (f(-x) == -f(x) exactly).
 * SATURATION: never wraps. fx_i128_add/sub/mac saturate to [-2^127, 2^127 - 1]; the conversions
 *   to int64 saturate to [INT64_MIN, INT64_MAX] and report it.
 * ERRORS against exact math: multiply, add, subtract are exact in range; the shift and the
 *   division are within 0.5 LSB of the result when not saturated. tests/fx/test_fx128.c proves
 *   every function against an independent reference (the compiler's __int128 on the host, exact
 *   vectors from Python on every target).
 */
#ifndef INCLINO_FX128_H
#define INCLINO_FX128_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/error.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    uint64_t lo; /* bits 0..63 */
    uint64_t hi; /* bits 64..127, two's complement: bit 63 of hi is the sign of the value */
} fx_i128_t;

/* x as a 128-bit value. Exact. */
static inline fx_i128_t fx_i128_from_i64(int64_t x)
{
    fx_i128_t r;
    r.lo = (uint64_t)x;
    r.hi = x < 0 ? UINT64_MAX : 0u;
    return r;
}

/* true when x < 0. */
static inline bool fx_i128_is_neg(fx_i128_t x)
{
    return (x.hi >> 63) != 0u;
}

/* a * b, exact for every int64 pair (|a * b| <= 2^126). */
fx_i128_t fx_i128_mul(int64_t a, int64_t b);

/* a + b and a - b, exact when the result is in [-2^127, 2^127 - 1], else saturated to that range. */
fx_i128_t fx_i128_add(fx_i128_t a, fx_i128_t b);
fx_i128_t fx_i128_sub(fx_i128_t a, fx_i128_t b);

/* acc + a * b (fx_i128_add of the exact product): exact in range, saturating otherwise. */
fx_i128_t fx_i128_mac(fx_i128_t acc, int64_t a, int64_t b);

/* -1, 0 or +1 as a < b, a == b, a > b. Exact. */
int fx_i128_cmp(fx_i128_t a, fx_i128_t b);

/* round(x / 2^s), ties away from zero, saturated to [INT64_MIN, INT64_MAX]. Any s: s == 0 is
 * a plain saturating conversion, s >= 129 gives 0 (s == 128 gives round(x / 2^128), which is -1
 * only for x = -2^127). |error| <= 0.5 LSB when not saturated. When the result saturates and
 * sat != NULL, *sat is set to true; otherwise *sat is left as it was (so one flag can collect
 * the saturations of a whole computation). */
int64_t fx_i128_rshift_round(fx_i128_t x, unsigned s, bool *sat);

/* *quot = round(num / den), ties away from zero. Returns 0 with |error| <= 0.5 LSB; or
 *   INC_ERR_NULL   quot is NULL;
 *   INC_ERR_INVAL  den == 0: *quot = INT64_MAX if num > 0, INT64_MIN if num < 0, 0 if num == 0;
 *   INC_ERR_RANGE  the rounded quotient does not fit int64: *quot saturated to INT64_MIN/MAX.
 * Cost: one native 64/64 division when |num| < 2^64, else one shift-subtract step per quotient
 * bit (bit length of |num| minus that of |den|, plus one; at most 64). */
int fx_i128_div_i64(fx_i128_t num, int64_t den, int64_t *quot);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_FX128_H */
