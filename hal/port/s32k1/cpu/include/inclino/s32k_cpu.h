/*
 * s32k_cpu.h - the core operations of the S32K1 port that are not registers: masking
 * interrupts (PRIMASK) and sleeping until an interrupt is pending (WFI).
 *
 *   default                 inline assembly (cpsid/cpsie, mrs primask, dsb + wfi): identical on
 *                           the Cortex-M4F (S32K144) and the Cortex-M0+ (S32K116)
 *   INCLINO_S32K_MMIO_SIM   plain functions of the simulated core (sim/models/s32k1/core):
 *                           PRIMASK is a flag of the simulated NVIC, and wfi advances the
 *                           simulated clock event by event until an enabled interrupt is
 *                           pending, exactly the condition that wakes a real core (pending
 *                           counts even while PRIMASK is set, ARMv7-M ARM B1.5.19).
 */
#ifndef INCLINO_S32K_CPU_H
#define INCLINO_S32K_CPU_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#if defined(INCLINO_S32K_MMIO_SIM)

/* Mask interrupts; returns the previous PRIMASK (bit 0 set = they were masked). */
uint32_t s32k_cpu_irq_save(void);
/* Unmask them if they were unmasked at the matching save (pending handlers run here). */
void s32k_cpu_irq_restore(uint32_t primask);
/* Sleep until an enabled interrupt is pending. */
void s32k_cpu_wfi(void);

#else

static inline uint32_t s32k_cpu_irq_save(void)
{
    uint32_t primask;
    __asm volatile("mrs %0, primask\n\tcpsid i" : "=r"(primask) : : "memory");
    return primask;
}

static inline void s32k_cpu_irq_restore(uint32_t primask)
{
    if ((primask & 1u) == 0u) {
        __asm volatile("cpsie i" : : : "memory");
    }
}

static inline void s32k_cpu_wfi(void)
{
    __asm volatile("dsb\n\twfi" : : : "memory");
}

#endif

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_S32K_CPU_H */
