/*
 * sim/s32k_core.h - the simulated S32K1 core: NVIC, PRIMASK/WFI, and register models of SCG,
 * PCC and WDOG, mapped into the simulated bus (inclino/sim/s32k_bus.h).
 *
 *   NVIC    ISER/ICER/ISPR/ICPR of IRQ 0..127. sim_s32k_core_raise(irq) makes an interrupt
 *           pending; it is delivered at once (the handler runs, pre-empting the main line at
 *           that simulated instant) when it is enabled, PRIMASK is clear and no handler runs;
 *           otherwise when that changes (s32k_cpu_irq_restore, the end of a handler). One
 *           priority level: handlers do not nest. Handler code is charged no simulated time.
 *   cpu     s32k_cpu_irq_save/restore: PRIMASK; s32k_cpu_wfi: fire clock events one by one
 *           until an enabled interrupt is pending (or none is scheduled).
 *   SCG     enable bits become valid at once; RCCR is copied to CSR (the switch is immediate).
 *   PCC     CGC/PCS stored; PR reads 1 for every register.
 *   WDOG    the unlock and refresh keys, ULK and RCS, TOVAL with the LPO/256 clock; a refresh
 *           later than the timeout after the previous one (simulated time) counts a bite.
 *
 * One core per process (the seam's functions are global); sim_s32k_core_init maps its regions,
 * after s32k_bus_reset().
 */
#ifndef INCLINO_SIM_S32K_CORE_H
#define INCLINO_SIM_S32K_CORE_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/error.h"
#include "inclino/sim/clock.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SIM_S32K_IRQS 128u

typedef void (*sim_s32k_isr)(void *arg);

struct sim_s32k_core {
    struct sim_clock *clk;
    bool primask;
    unsigned isr_depth; /* > 0 while a handler runs */
    uint32_t enabled[SIM_S32K_IRQS / 32u];
    uint32_t pending[SIM_S32K_IRQS / 32u];
    sim_s32k_isr isr[SIM_S32K_IRQS];
    void *isr_arg[SIM_S32K_IRQS];
    uint64_t delivered; /* handlers run */
    /* SCG */
    uint32_t scg[0x1000u / 4u];
    /* PCC */
    uint32_t pcc[0x1000u / 4u];
    /* WDOG */
    uint32_t wdog_cs, wdog_toval, wdog_win;
    bool wdog_unlocked;
    uint64_t wdog_last_ns;
    uint32_t wdog_refreshes, wdog_bites, wdog_configs;
};

/* Map the regions and make this the process's core. 0 or an error of s32k_bus_map. */
int sim_s32k_core_init(struct sim_s32k_core *c, struct sim_clock *clk);

/* The handler of an IRQ (the board's vector table entry). */
void sim_s32k_core_set_handler(struct sim_s32k_core *c, unsigned irq, sim_s32k_isr fn, void *arg);

/* A peripheral requests irq. */
void sim_s32k_core_raise(struct sim_s32k_core *c, unsigned irq);

/* The process's core (NULL before init). */
struct sim_s32k_core *sim_s32k_core_get(void);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_SIM_S32K_CORE_H */
