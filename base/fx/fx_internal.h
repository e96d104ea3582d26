/*
 * fx_internal.h - helpers shared by the fx_*.c files; not part of the module interface.
 */
#ifndef INCLINO_FX_INTERNAL_H
#define INCLINO_FX_INTERNAL_H

#include <stdint.h>

/* Index of the highest set bit of x (x != 0). Portable C, no compiler builtin: the same code on
 * every target (Cortex-M0+ has no CLZ instruction; __builtin_clz would be a libgcc call there). */
static inline unsigned fx_msb32(uint32_t x)
{
    unsigned n = 0;
    if (x >= 0x10000u) {
        x >>= 16;
        n += 16u;
    }
    if (x >= 0x100u) {
        x >>= 8;
        n += 8u;
    }
    if (x >= 0x10u) {
        x >>= 4;
        n += 4u;
    }
    if (x >= 0x4u) {
        x >>= 2;
        n += 2u;
    }
    if (x >= 0x2u) {
        n += 1u;
    }
    return n;
}

#endif /* INCLINO_FX_INTERNAL_H */
