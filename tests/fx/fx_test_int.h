/*
 * fx_test_int.h - the integer-only part of the tests/fx helpers: sweep density, a deterministic
 * generator and exact integer references (written independently of base/fx; the rounding
 * division is unit_round_div in unit.h).
 * No libm and no floating point, so the tests that use only this header also run on rv32imac,
 * whose test board has no C library beyond a printf shim.
 */
#ifndef INCLINO_FX_TEST_INT_H
#define INCLINO_FX_TEST_INT_H

#include <stdint.h>
#include <stdio.h>

#include "inclino/fx.h"
#include "unit.h"

/* Sweep density. The host preset runs the full dense sweeps. An emulated MCU (QEMU, soft-float
 * libm) uses the reduced counts so that each test stays well under ~20 s; so does the
 * host-sanitize build (ASan + UBSan are ~5x slower; its job is finding undefined behaviour on
 * the same code paths, the bounds are proven by the dense host run).
 * FX_DENSITY(full, reduced) picks one; docs/fixed-point.md lists both per test. */
#define FX_DENSITY(full, reduced) UNIT_SIZE(full, reduced)

/* A random int32 with a random magnitude (2^0 .. 2^31) and sign, so that every scale is hit;
 * includes INT32_MIN and INT32_MAX. */
static inline int32_t fxt_rand_scaled(uint32_t *state)
{
    uint32_t r = unit_rand32(state);
    unsigned sh = unit_rand32(state) % 32u;
    int32_t m = (int32_t)((r >> 1) >> sh); /* [0, 2^31 - 1] */
    return (r & 1u) ? -m - 1 : m;
}

/* Bit pattern -> int32 (two's complement), defined. */
static inline int32_t fxt_i32(uint32_t u)
{
    return (u & 0x80000000u) ? (int32_t)(u - 0x80000000u) + INT32_MIN : (int32_t)u;
}

static inline int32_t fxt_sat(int64_t v)
{
    return v > INT32_MAX ? INT32_MAX : (v < INT32_MIN ? INT32_MIN : (int32_t)v);
}

#endif /* INCLINO_FX_TEST_INT_H */
