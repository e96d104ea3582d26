/*
 * hal.h - the hardware abstraction the firmware runs on.
 *
 * The whole hardware dependency of Inclino is one caller-owned `struct hal`: a pointer to a const
 * table of operations plus an opaque context pointer that is passed back to every operation.
 * Nothing in firmware/ or drivers/ touches hardware any other way. Why an ops table and not
 * link-time ports: the host tests link the simulated port and, in one binary, several simulated
 * boards (one per test case, or a replay next to a live model); a run-time table makes that
 * possible, and on the MCU its cost (one indirect call per pin toggle) is measured in
 * docs/benchmarks.md. See docs/hal.md.
 *
 * Ports (hal/port/<name>/) fill the table:
 *   sim       - the simulated board of sim/: virtual clock, pin bus, device models (host, QEMU)
 *   cortex_m  - generic bare-metal Cortex-M: SysTick or DWT time base, PRIMASK critical
 *               sections; GPIO comes from an MCU-family seam (struct hal_cm_gpio_ops)
 *
 * Contract common to every port:
 *   - pins are numbered by the port (hal_pin_t); the port configures their direction at board
 *     set-up, so the HAL only writes and reads levels;
 *   - now_ns() is monotonic and never wraps in the life of the device (64-bit ns);
 *   - delay_ns(ns) returns no earlier than ns after it was called (it may return later);
 *   - an attached interrupt callback runs in interrupt context: it must be short and may only
 *     touch state that the main line reads inside a critical section or atomically;
 *   - irq_wait() sleeps until at least one attached callback has run since the previous
 *     irq_wait() returned, or until the deadline; in the simulation it advances the virtual clock
 *     to the next scheduled event instead of sleeping.
 */
#ifndef INCLINO_HAL_H
#define INCLINO_HAL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "inclino/error.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A pin number; its meaning belongs to the port (sim: pin-bus index; MCU: port*16 + bit...). */
typedef uint16_t hal_pin_t;
#define HAL_PIN_NONE ((hal_pin_t)0xFFFFu)

enum hal_edge {
    HAL_EDGE_RISING = 1,
    HAL_EDGE_FALLING = 2,
    HAL_EDGE_BOTH = 3,
};

/* Interrupt callback: runs in interrupt context with the argument given to irq_attach. */
typedef void (*hal_irq_cb)(void *arg);

struct hal_ops {
    /* Drive an output pin high (true) or low (false). */
    void (*pin_write)(void *ctx, hal_pin_t pin, bool level);
    /* Read the level of a pin (input, or the driven level of an output). */
    bool (*pin_read)(void *ctx, hal_pin_t pin);
    /* Monotonic time in ns since the port started. */
    uint64_t (*now_ns)(void *ctx);
    /* Busy-wait at least ns nanoseconds. */
    void (*delay_ns)(void *ctx, uint32_t ns);
    /*
     * Call cb(arg) from interrupt context on the given edge of pin. One callback per pin;
     * attaching again replaces it, cb == NULL detaches. Returns 0, INC_ERR_INVAL for a pin the
     * port cannot interrupt on, or INC_ERR_NO_SPACE when the port's table is full.
     */
    int (*irq_attach)(void *ctx, hal_pin_t pin, enum hal_edge edge, hal_irq_cb cb, void *arg);
    /*
     * Sleep until an attached callback has run (returns 0) or now_ns() >= deadline_ns (returns
     * INC_ERR_TIMEOUT). A callback that ran since the previous irq_wait() returned counts, so an
     * interrupt between a check and the wait is never lost.
     */
    int (*irq_wait)(void *ctx, uint64_t deadline_ns);
    /* Enter a critical section (interrupt callbacks deferred); returns the key for exit. Nests. */
    uint32_t (*crit_enter)(void *ctx);
    /* Leave the critical section entered with the matching key. */
    void (*crit_exit)(void *ctx, uint32_t key);
};

struct hal {
    const struct hal_ops *ops;
    void *ctx;
};

/* 0 when hal, its ops and every operation are present; INC_ERR_NULL otherwise. */
int hal_check(const struct hal *hal);

/* Thin inline wrappers. They do not check pointers: validate once with hal_check() at init. */
static inline void hal_pin_write(const struct hal *hal, hal_pin_t pin, bool level)
{
    hal->ops->pin_write(hal->ctx, pin, level);
}

static inline bool hal_pin_read(const struct hal *hal, hal_pin_t pin)
{
    return hal->ops->pin_read(hal->ctx, pin);
}

static inline uint64_t hal_now_ns(const struct hal *hal)
{
    return hal->ops->now_ns(hal->ctx);
}

static inline void hal_delay_ns(const struct hal *hal, uint32_t ns)
{
    hal->ops->delay_ns(hal->ctx, ns);
}

static inline int hal_irq_attach(const struct hal *hal, hal_pin_t pin, enum hal_edge edge,
                                 hal_irq_cb cb, void *arg)
{
    return hal->ops->irq_attach(hal->ctx, pin, edge, cb, arg);
}

static inline int hal_irq_wait(const struct hal *hal, uint64_t deadline_ns)
{
    return hal->ops->irq_wait(hal->ctx, deadline_ns);
}

static inline uint32_t hal_crit_enter(const struct hal *hal)
{
    return hal->ops->crit_enter(hal->ctx);
}

static inline void hal_crit_exit(const struct hal *hal, uint32_t key)
{
    hal->ops->crit_exit(hal->ctx, key);
}

/* Busy-wait at least ms milliseconds (any length; delay_ns is called in pieces of <= 1 s). */
void hal_delay_ms(const struct hal *hal, uint32_t ms);

/* Wait until now_ns() >= t_ns (returns at once when t_ns is in the past). */
void hal_delay_until(const struct hal *hal, uint64_t t_ns);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_HAL_H */
