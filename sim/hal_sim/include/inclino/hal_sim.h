/*
 * hal_sim.h - the HAL port of the simulated board (host and QEMU).
 *
 * Pins are pin-bus indices; writing one makes the master drive it. Time is the virtual clock:
 * delay_ns advances it (firing the device models' events on the way) and never sleeps.
 * irq_wait advances the clock event by event until an attached callback has run or the deadline
 * is reached. Interrupt callbacks run at the virtual instant of their edge, also in the middle
 * of a delay (as an ISR pre-empts a busy-wait), except inside a critical section: then they are
 * held pending and run when the outermost section ends.
 */
#ifndef INCLINO_HAL_SIM_H
#define INCLINO_HAL_SIM_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/hal.h"
#include "inclino/sim/clock.h"
#include "inclino/sim/pinbus.h"

#ifdef __cplusplus
extern "C" {
#endif

#define HAL_SIM_MAX_IRQS 8u

struct hal_sim;

struct hal_sim_irq {
    struct hal_sim *port;
    struct sim_pin_listener listener;
    hal_pin_t pin;
    enum hal_edge edge;
    hal_irq_cb cb;
    void *arg;
    bool pending; /* edge seen inside a critical section */
};

struct hal_sim {
    struct sim_clock *clk;
    struct sim_pinbus *bus;
    uint32_t crit_depth;
    uint32_t fired; /* callbacks run since the last irq_wait returned */
    struct hal_sim_irq irq[HAL_SIM_MAX_IRQS];
    /* statistics for benchmarks */
    uint64_t pin_writes, pin_reads, delays;
};

/* Bind the port to a clock and a pin bus and fill *out. Returns 0 or INC_ERR_NULL. */
int hal_sim_init(struct hal_sim *port, struct sim_clock *clk, struct sim_pinbus *bus,
                 struct hal *out);

/*
 * The time-only HAL: a clock and nothing else, for code under test that needs time and delays
 * but no board (pure driver logic, benchmarks of the SPI engine's own cost). Pins read low and
 * writes are ignored; attaching an interrupt succeeds and it never fires; irq_wait moves the
 * clock to its deadline and returns INC_ERR_TIMEOUT; critical sections nest and are counted.
 * now_ns starts at 0 (set it to start elsewhere).
 */
struct hal_sim_time {
    uint64_t now_ns;
    uint32_t crit_depth;
    uint64_t delays, waits, pin_writes; /* statistics */
};

/* Zero *t and fill *out. Returns 0 or INC_ERR_NULL. */
int hal_sim_time_init(struct hal_sim_time *t, struct hal *out);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_HAL_SIM_H */
