/*
 * fx_sqrt.c - integer and fixed-point square roots (see inclino/fx.h).
 *
 * Method: the binary digit-by-digit ("restoring") square root. Each step decides one bit of the
 * root from an exact remainder, so floor(sqrt(n)) is exact by construction (no seed, no Newton
 * iteration to converge or overshoot) and the final remainder n - root^2 gives the rounding
 * decision for free: sqrt(n) >= root + 1/2  <=>  n >= root^2 + root + 1/4  <=>  rem > root
 * (integers), and a tie cannot happen because (root + 1/2)^2 is never an integer.
 * Cost is one iteration per result bit; the loop starts at the highest set bit pair of n, so
 * small arguments are cheap. Only shifts, adds and compares: the same on M0+ and M3.
 */
#include "inclino/fx.h"

#include "fx_internal.h"

/* floor(sqrt(n)) and the remainder n - root^2, n != 0. */
static uint32_t isqrt32_rem(uint32_t n, uint32_t *rem_out)
{
    uint32_t rem = n, root = 0;
    uint32_t bit = 1u << (fx_msb32(n) & ~1u); /* highest power of 4 <= n */
    while (bit != 0u) {
        if (rem >= root + bit) {
            rem -= root + bit;
            root = (root >> 1) + bit;
        } else {
            root >>= 1;
        }
        bit >>= 2;
    }
    *rem_out = rem;
    return root;
}

static uint32_t isqrt64_rem(uint64_t n, uint64_t *rem_out)
{
    uint64_t rem, root, bit;
    unsigned top;
    if ((n >> 32) == 0u) {
        uint32_t r32 = 0, root32 = 0;
        if (n != 0u) root32 = isqrt32_rem((uint32_t)n, &r32);
        *rem_out = r32;
        return root32;
    }
    top = 32u + fx_msb32((uint32_t)(n >> 32));
    rem = n;
    root = 0;
    bit = (uint64_t)1 << (top & ~1u);
    while (bit != 0u) {
        if (rem >= root + bit) {
            rem -= root + bit;
            root = (root >> 1) + bit;
        } else {
            root >>= 1;
        }
        bit >>= 2;
    }
    *rem_out = rem;
    return (uint32_t)root; /* < 2^32 because n < 2^64 */
}

uint32_t fx_isqrt32(uint32_t n)
{
    uint32_t rem;
    if (n == 0u) return 0;
    return isqrt32_rem(n, &rem);
}

uint32_t fx_isqrt64(uint64_t n)
{
    uint64_t rem;
    return isqrt64_rem(n, &rem);
}

uint32_t fx_isqrt64_round(uint64_t n)
{
    uint64_t rem;
    uint32_t root = isqrt64_rem(n, &rem);
    if (rem > root && root != UINT32_MAX) root++;
    return root;
}

fx_q16_t fx_sqrt_q16(fx_q16_t x)
{
    /* sqrt(x / 2^16) * 2^16 = sqrt(x * 2^16); x * 2^16 < 2^47, result < 2^23.5. */
    if (x <= 0) return 0;
    return (fx_q16_t)fx_isqrt64_round((uint64_t)x << FX_Q16_SHIFT);
}

fx_q30_t fx_sqrt_q30(fx_q30_t x)
{
    /* sqrt(x * 2^30); x * 2^30 < 2^61, result < 2^30.5. */
    if (x <= 0) return 0;
    return (fx_q30_t)fx_isqrt64_round((uint64_t)x << FX_Q30_SHIFT);
}
