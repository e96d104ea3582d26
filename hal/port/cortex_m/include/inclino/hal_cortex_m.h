/*
 * hal_cortex_m.h - the generic bare-metal Cortex-M port of the HAL (M0+, M3, M4F).
 *
 * Fills struct hal_ops (inclino/hal.h) from the core's own peripherals, the same on every
 * Cortex-M part, and takes everything MCU-specific from an MCU-family seam:
 *
 *   time        SysTick (every core) or the DWT cycle counter (ARMv7-M: M3/M4F), counting core
 *               clock cycles in 64 bits; converted to ns with hal/cycles (no floating
 *               point, no division after init).
 *   delay_ns    busy-wait on that counter; never shorter than requested.
 *   crit_*      PRIMASK: crit_enter returns the previous PRIMASK, crit_exit restores it, so
 *               sections nest.
 *   irq_*       a small table of pin -> callback; the family's EXTI/PINT interrupt handler calls
 *               hal_cm_irq_dispatch(); irq_wait sleeps with WFI (SysTick mode, deadline more
 *               than one SysTick period away) or polls (near the deadline, DWT mode). irq_wait
 *               inside a critical section would never see an interrupt: INC_ERR_STATE.
 *   pins        the MCU family's GPIO, through struct hal_cm_gpio_ops (the seam below).
 *
 * Porting to an MCU family = one const struct hal_cm_gpio_ops plus the family's pin interrupt
 * handler calling hal_cm_irq_dispatch(); nothing above the HAL changes. See README.md.
 */
#ifndef INCLINO_HAL_CORTEX_M_H
#define INCLINO_HAL_CORTEX_M_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/error.h"
#include "inclino/hal.h"
#include "inclino/hal_cycles.h"

#ifdef __cplusplus
extern "C" {
#endif

/*
 * The MCU-family seam: GPIO of one family (STM32 GPIOx/EXTI, NXP GPIO/PINT, ...). The family
 * port numbers its pins (hal_pin_t, e.g. port * 16 + bit), configures their direction and
 * alternate function at board set-up (before hal_cm_init), and supplies these operations. All
 * three are required. ctx is hal_cm_config.gpio_ctx.
 */
struct hal_cm_gpio_ops {
    /* Drive an output pin high (true) or low (false). Called from thread and interrupt context. */
    void (*write)(void *ctx, hal_pin_t pin, bool level);
    /* Level of a pin (input, or the driven level of an output). */
    bool (*read)(void *ctx, hal_pin_t pin);
    /*
     * enable == true: route the given edge of pin to the family's pin interrupt, whose handler
     * must call hal_cm_irq_dispatch(cm, pin) and clear the request; enable == false: stop it.
     * Returns 0, INC_ERR_INVAL when the pin or edge cannot interrupt, or INC_ERR_UNSUPPORTED.
     */
    int (*irq_enable)(void *ctx, hal_pin_t pin, enum hal_edge edge, bool enable);
};

/*
 * A family seam with no pins, for images built before a family port exists: writes are
 * ignored, reads return false, irq_enable returns INC_ERR_UNSUPPORTED.
 */
extern const struct hal_cm_gpio_ops hal_cm_gpio_none;

enum hal_cm_timebase {
    /*
     * SysTick, free-running over its full 24 bits at the core clock, with an interrupt per wrap
     * (every 2^24 cycles: 0.67 s at 25 MHz, 0.1 s at 168 MHz). The port owns SysTick and
     * defines SysTick_Handler. Works inside critical sections of any length: a reader that finds
     * the wrap interrupt pending accounts for the wrap itself.
     */
    HAL_CM_TIME_SYSTICK = 0,
    /*
     * DWT CYCCNT (ARMv7-M only; INC_ERR_UNSUPPORTED on the M0+ and wherever the counter does
     * not advance, e.g. under QEMU). No interrupt: the 32-bit counter is extended in software,
     * so now_ns/delay_ns/irq_wait must run at least once per 2^32 cycles (25 s at 168 MHz), and
     * irq_wait polls instead of sleeping.
     */
    HAL_CM_TIME_DWT = 1,
};

struct hal_cm_config {
    uint32_t core_hz; /* core clock in Hz, HAL_CYC_HZ_MIN..HAL_CYC_HZ_MAX */
    enum hal_cm_timebase timebase;
    const struct hal_cm_gpio_ops *gpio; /* required; &hal_cm_gpio_none when there are no pins */
    void *gpio_ctx;                     /* passed to every gpio operation */
};

#define HAL_CM_IRQ_SLOTS 4u /* pins with an attached callback at the same time */

struct hal_cm_irq_slot {
    hal_pin_t pin; /* HAL_PIN_NONE when free */
    enum hal_edge edge;
    hal_irq_cb cb;
    void *arg;
};

/* Port state: allocated by the caller (static), initialised by hal_cm_init. Fields private. */
struct hal_cm {
    struct hal_cm_config cfg;
    struct hal_cyc_conv conv;
    uint64_t wraps;        /* SysTick: counter transitions to 0; DWT: CYCCNT overflows */
    uint32_t dwt_last;     /* DWT: last CYCCNT read */
    uint64_t sleep_min_ns; /* irq_wait sleeps (WFI) only when the deadline is further away */
    struct hal_cm_irq_slot irq[HAL_CM_IRQ_SLOTS];
    volatile uint32_t irq_count; /* callbacks run (dispatch increments it) */
    uint32_t irq_seen;           /* irq_count when irq_wait last returned 0 */
};

/*
 * Initialise the port and fill *hal (ops + ctx = cm). Starts the time base; now_ns() counts
 * from here. In SysTick mode this instance takes SysTick over (the last one initialised owns
 * it). Returns 0; INC_ERR_NULL for a NULL argument or gpio operation; INC_ERR_INVAL for a
 * core_hz out of range or an unknown timebase; INC_ERR_UNSUPPORTED for HAL_CM_TIME_DWT where
 * there is no working cycle counter. On error *hal is untouched.
 */
int hal_cm_init(struct hal_cm *cm, const struct hal_cm_config *cfg, struct hal *hal);

/*
 * Called by the MCU family's pin interrupt handler (interrupt context) for a pin whose edge
 * fired: runs the attached callback, if any, and wakes irq_wait.
 */
void hal_cm_irq_dispatch(struct hal_cm *cm, hal_pin_t pin);

/* The SysTick wrap interrupt; defined here, placed in the vector table by the startup. */
void SysTick_Handler(void);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_HAL_CORTEX_M_H */
