/*
 * s32k_mmio.h - how every S32K1 driver of this port touches a peripheral register.
 *
 * Addresses are the absolute 32-bit bus addresses of the reference manual (for example
 * 0x4002C000 for LPSPI0). The drivers never form a pointer themselves; they call these
 * functions, which exist in two builds:
 *
 *   default                   static inline volatile loads and stores: on the MCU each call is
 *                             one ldr/str (ldrb/strb, ldrh/strh for the 8- and 16-bit forms)
 *   INCLINO_S32K_MMIO_SIM     plain functions implemented by the register-level bus model
 *                             (sim/models/s32k1/bus), which dispatches the access to the model
 *                             mapped at that address; the same driver code then runs on the
 *                             host and under QEMU against the simulated peripherals
 *
 * Widths: use the width the reference manual gives the register (FTFC's FSTAT and FCCOB are
 * 8-bit, most others 32-bit). The seam does no checking; the bus model counts an access to an
 * unmapped address, and the tests assert that there are none.
 */
#ifndef INCLINO_S32K_MMIO_H
#define INCLINO_S32K_MMIO_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#if defined(INCLINO_S32K_MMIO_SIM)

uint32_t s32k_mmio_read32(uint32_t addr);
void s32k_mmio_write32(uint32_t addr, uint32_t value);
uint16_t s32k_mmio_read16(uint32_t addr);
void s32k_mmio_write16(uint32_t addr, uint16_t value);
uint8_t s32k_mmio_read8(uint32_t addr);
void s32k_mmio_write8(uint32_t addr, uint8_t value);

#else

static inline uint32_t s32k_mmio_read32(uint32_t addr)
{
    return *(volatile const uint32_t *)(uintptr_t)addr;
}

static inline void s32k_mmio_write32(uint32_t addr, uint32_t value)
{
    *(volatile uint32_t *)(uintptr_t)addr = value;
}

static inline uint16_t s32k_mmio_read16(uint32_t addr)
{
    return *(volatile const uint16_t *)(uintptr_t)addr;
}

static inline void s32k_mmio_write16(uint32_t addr, uint16_t value)
{
    *(volatile uint16_t *)(uintptr_t)addr = value;
}

static inline uint8_t s32k_mmio_read8(uint32_t addr)
{
    return *(volatile const uint8_t *)(uintptr_t)addr;
}

static inline void s32k_mmio_write8(uint32_t addr, uint8_t value)
{
    *(volatile uint8_t *)(uintptr_t)addr = value;
}

#endif

/* Read-modify-write helpers (not atomic: call them with the peripheral's interrupt masked). */
static inline void s32k_mmio_set32(uint32_t addr, uint32_t mask)
{
    s32k_mmio_write32(addr, s32k_mmio_read32(addr) | mask);
}

static inline void s32k_mmio_clear32(uint32_t addr, uint32_t mask)
{
    s32k_mmio_write32(addr, s32k_mmio_read32(addr) & ~mask);
}

/* Replace the bits of mask with value (value outside mask is ignored). */
static inline void s32k_mmio_modify32(uint32_t addr, uint32_t mask, uint32_t value)
{
    s32k_mmio_write32(addr, (s32k_mmio_read32(addr) & ~mask) | (value & mask));
}

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_S32K_MMIO_H */
