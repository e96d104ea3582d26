/*
 * fx_div64.c - 64-bit integer division of the project's own (see fx.h, "64-bit division"):
 * fx_udivmod64 / fx_divmod64, and on the Cortex-M0+ (INCLINO_FX_AEABI_DIV64) the two run-time
 * entry points gcc calls for every 64-bit `/` and `%`, __aeabi_uldivmod and __aeabi_ldivmod, on
 * top of them instead of libgcc's (__udivmoddi4 408 B, __divdi3 482 B, __gnu_ldivmod_helper).
 *
 * Method: restoring shift-and-subtract over the quotient's bits only (the divisor is first
 * shifted up to the numerator's top bit), with a 32-bit division when both operands fit 32 bits.
 * Exact: the quotient and remainder of C's unsigned division, bit for bit.
 */
#include "inclino/fx.h"

#include <stddef.h>

uint64_t fx_udivmod64(uint64_t n, uint64_t d, uint64_t *rem)
{
    uint64_t q = 0;
    unsigned s = 0;
    if (d == 0u) {
        if (rem != NULL) *rem = n;
        return UINT64_MAX;
    }
    if ((n >> 32) == 0u && (d >> 32) == 0u) {
        const uint32_t q32 = (uint32_t)n / (uint32_t)d;
        if (rem != NULL) *rem = (uint32_t)n - q32 * (uint32_t)d;
        return q32;
    }
    /* d <= n / 2^s: the highest quotient bit is s. */
    while ((d >> 63) == 0u && (d << 1) <= n) {
        d <<= 1;
        s++;
    }
    for (;;) {
        q <<= 1;
        if (n >= d) {
            n -= d;
            q |= 1u;
        }
        if (s == 0u) break;
        s--;
        d >>= 1;
    }
    if (rem != NULL) *rem = n;
    return q;
}

int64_t fx_divmod64(int64_t n, int64_t d, int64_t *rem)
{
    const uint64_t un = n < 0 ? 0u - (uint64_t)n : (uint64_t)n;
    const uint64_t ud = d < 0 ? 0u - (uint64_t)d : (uint64_t)d;
    uint64_t ur = 0;
    uint64_t uq = fx_udivmod64(un, ud, &ur);
    if (d == 0) {
        uq = n < 0 ? (uint64_t)INT64_MIN : (n > 0 ? (uint64_t)INT64_MAX : 0u);
        ur = un; /* the remainder is n */
    } else if ((n < 0) != (d < 0)) {
        uq = 0u - uq;
    }
    if (rem != NULL) *rem = (int64_t)(n < 0 ? 0u - ur : ur);
    return (int64_t)uq;
}

#ifdef INCLINO_FX_AEABI_DIV64
/*
 * The run-time ABI's 64-bit division [ARM IHI 0043, 4.2]: numerator in r0:r1, denominator in
 * r2:r3; quotient returned in r0:r1 and remainder in r2:r3. The C routine returns the quotient
 * and stores the remainder through its fifth word (on the stack), which these load into r2:r3.
 * Frame: 8 B pushed + 16 B (the argument word and the remainder), 8-byte aligned.
 */
void __aeabi_uldivmod(void);
void __aeabi_ldivmod(void);

__attribute__((naked)) void __aeabi_uldivmod(void)
{
    __asm volatile("push {r4, lr}\n\t"
                   "sub sp, sp, #16\n\t"
                   "add r4, sp, #8\n\t"
                   "str r4, [sp]\n\t"
                   "bl fx_udivmod64\n\t"
                   "ldr r2, [sp, #8]\n\t"
                   "ldr r3, [sp, #12]\n\t"
                   "add sp, sp, #16\n\t"
                   "pop {r4, pc}\n\t");
}

__attribute__((naked)) void __aeabi_ldivmod(void)
{
    __asm volatile("push {r4, lr}\n\t"
                   "sub sp, sp, #16\n\t"
                   "add r4, sp, #8\n\t"
                   "str r4, [sp]\n\t"
                   "bl fx_divmod64\n\t"
                   "ldr r2, [sp, #8]\n\t"
                   "ldr r3, [sp, #12]\n\t"
                   "add sp, sp, #16\n\t"
                   "pop {r4, pc}\n\t");
}
#endif
