/*
 * hal_cycles.c - see hal_cycles.h.
 *
 * Why Q32.32 factors: a cycle count reaches 2^64 in principle, so cycles * 1e9 overflows any
 * 64-bit intermediate, and a 64-bit division per now_ns() costs a libgcc call of several
 * hundred cycles on an M0+. One 64x64->128 multiply (four 32x32->64 products; UMULL on
 * ARMv7-M) keeps the conversion exact up to the documented rounding and cheap. The two 64-bit
 * divisions happen once, in hal_cyc_init.
 */
#include "inclino/hal_cycles.h"

#include <stddef.h>

#define HAL_CYC_NS_PER_S 1000000000ull

int hal_cyc_init(struct hal_cyc_conv *conv, uint32_t hz)
{
    if (conv == NULL) {
        return INC_ERR_NULL;
    }
    if (hz < HAL_CYC_HZ_MIN || hz > HAL_CYC_HZ_MAX) {
        return INC_ERR_INVAL;
    }
    conv->hz = hz;
    /* 1e9 * 2^32 < 2^62 and hz * 2^32 <= 1e9 * 2^32: both fit 64 bits. */
    conv->ns_per_cyc_q32 = (HAL_CYC_NS_PER_S << 32) / hz;
    conv->cyc_per_ns_q32 = (((uint64_t)hz << 32) + HAL_CYC_NS_PER_S - 1u) / HAL_CYC_NS_PER_S;
    return INC_OK;
}

uint64_t hal_cyc_mul_q32(uint64_t a, uint64_t b)
{
    uint64_t a0 = (uint32_t)a;
    uint64_t a1 = a >> 32;
    uint64_t b0 = (uint32_t)b;
    uint64_t b1 = b >> 32;
    uint64_t p00 = a0 * b0;
    uint64_t p01 = a0 * b1;
    uint64_t p10 = a1 * b0;
    uint64_t p11 = a1 * b1;
    /*
     * a * b = p11 * 2^64 + (p01 + p10) * 2^32 + p00, so floor(a * b / 2^32) is
     * p11 * 2^32 + p01 + p10 + floor(p00 / 2^32): every term is whole, nothing is lost.
     */
    return (p11 << 32) + p01 + p10 + (p00 >> 32);
}

uint64_t hal_cyc_to_ns(const struct hal_cyc_conv *conv, uint64_t cycles)
{
    return hal_cyc_mul_q32(cycles, conv->ns_per_cyc_q32);
}

uint64_t hal_ns_to_cyc_ceil(const struct hal_cyc_conv *conv, uint32_t ns)
{
    /* ns < 2^32 and the factor <= 2^32: the product fits 64 bits. Round the Q32.32 up. */
    uint64_t q = (uint64_t)ns * conv->cyc_per_ns_q32;
    return (q >> 32) + ((q & 0xFFFFFFFFu) != 0u ? 1u : 0u);
}
