/*
 * s32k_bus.h - the simulated S32K1 peripheral bus.
 *
 * The S32K1 port's drivers reach registers only through inclino/s32k_mmio.h. In the _sim build
 * of a driver those calls land here: the bus finds the region that holds the address and calls
 * that region's model with the offset into the region and the access width (1, 2 or 4 bytes).
 * A model is any code that fills struct s32k_bus_region_ops: PORT/GPIO, LPSPI, FTFC, FlexCAN,
 * the time base.
 *
 * There is one bus per process (the register addresses are absolute, like on the chip).
 * s32k_bus_reset() unmaps every region and clears the statistics; a test calls it before it
 * builds a board. An access to an address no region holds reads 0, writes nothing, and is
 * counted (struct s32k_bus_stats); tests assert the counts are zero.
 *
 * An optional access hook runs after every access (mapped or not). The time-base model uses it
 * to charge the simulated time a real bus access takes, so that a driver's busy-wait on a
 * status register terminates in simulated time.
 */
#ifndef INCLINO_SIM_S32K_BUS_H
#define INCLINO_SIM_S32K_BUS_H

#include <stdint.h>

#include "inclino/error.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Most regions one bus holds. */
#define S32K_BUS_MAX_REGIONS 16u

struct s32k_bus_region_ops {
    /* Value of the register at offset (bytes from the region base), width 1, 2 or 4. */
    uint32_t (*read)(void *ctx, uint32_t offset, unsigned width);
    /* Write value (already truncated to width) to the register at offset. */
    void (*write)(void *ctx, uint32_t offset, uint32_t value, unsigned width);
};

struct s32k_bus_stats {
    uint64_t reads;          /* mapped and unmapped */
    uint64_t writes;         /* mapped and unmapped */
    uint32_t unmapped_reads; /* accesses no region holds */
    uint32_t unmapped_writes;
    uint32_t last_unmapped; /* address of the latest unmapped access */
    uint32_t misaligned;    /* accesses whose address is not a multiple of their width */
};

/* Unmap every region, drop the hook, clear the statistics. */
void s32k_bus_reset(void);

/*
 * Map [base, base + size) to ops/ctx. Returns 0, INC_ERR_NULL (ops or ops->read/write NULL),
 * INC_ERR_INVAL (size 0, the range wraps past 2^32 or overlaps a mapped region) or
 * INC_ERR_NO_SPACE (S32K_BUS_MAX_REGIONS already mapped).
 */
int s32k_bus_map(uint32_t base, uint32_t size, const struct s32k_bus_region_ops *ops, void *ctx);

/* Call hook(ctx) after every access; NULL removes it. */
void s32k_bus_set_hook(void (*hook)(void *ctx), void *ctx);

/*
 * The meter, for benchmarks that count the firmware's own instructions under QEMU
 * (benches/s32k1/bench_s32k_cpu_cm.c): enter() is called first thing in every s32k_mmio_*
 * access and in the simulated PRIMASK/WFI seam (sim/models/s32k1/core), leave() last; the core
 * calls leave() before and enter() after a firmware interrupt handler it runs from inside a
 * model, so the handler counts as firmware. The calls nest (the benchmark keeps the depth).
 * NULL: no meter (the default, and after s32k_bus_reset).
 */
struct s32k_bus_meter {
    void (*enter)(void);
    void (*leave)(void);
};
void s32k_bus_set_meter(const struct s32k_bus_meter *m);
void s32k_bus_meter_enter(void);
void s32k_bus_meter_leave(void);

/* The statistics since the last reset. */
const struct s32k_bus_stats *s32k_bus_stats(void);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_SIM_S32K_BUS_H */
