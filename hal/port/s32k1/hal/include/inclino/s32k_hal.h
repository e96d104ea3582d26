/*
 * s32k_hal.h - the HAL port of the S32K1 family (S32K144, S32K116): fills struct hal_ops
 * (inclino/hal.h) from the family's own peripherals, every register through inclino/s32k_mmio.h,
 * so the same code runs on the part (direct build) and against the register-level models (the
 * _sim build, sim/models/s32k1).
 *
 *   pins        GPIO: PSOR/PCOR to write, PDIR to read (inclino/s32k_gpio.h); pins are
 *               port * 32 + bit and are muxed and given a direction by the board before init.
 *   time        LPIT0 channel 0, 24 MHz, 64-bit ns (inclino/s32k_time.h).
 *   delay_ns    up to S32K_HAL_SPIN_MAX_NS: a spin. On the part a counted loop of
 *               S32K_HAL_LOOP_CYCLES core cycles per turn (no timer read: a few cycles per call,
 *               never shorter than asked, longer by flash wait states); in the _sim build a
 *               poll of the time base (each register access costs simulated time). Longer:
 *               sleep (WFI) until LPIT0 channel 1 fires, then poll to the end; inside a
 *               critical section always a poll.
 *   irq_*       a table of pin -> callback; the board's PORT vector calls s32k_hal_port_isr(),
 *               LPIT0's vector s32k_hal_lpit_isr(). irq_wait sleeps with WFI (PRIMASK set, so no
 *               edge between the check and the sleep is lost) until a callback ran or the
 *               deadline; the last S32K_HAL_SPIN_MAX_NS before the deadline it polls.
 *   crit_*      PRIMASK, nesting (inclino/s32k_cpu.h).
 *   watchdog    refreshed in every irq_wait and sleeping delay (inclino/s32k_wdog.h: why).
 */
#ifndef INCLINO_S32K_HAL_H
#define INCLINO_S32K_HAL_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/error.h"
#include "inclino/hal.h"
#include "inclino/s32k1_regs.h"
#include "inclino/s32k_time.h"

#ifdef __cplusplus
extern "C" {
#endif

#define S32K_HAL_IRQ_SLOTS 4u
#define S32K_HAL_SPIN_MAX_NS 20000u /* delays and wait tails up to this spin */
#define S32K_HAL_LOOP_CYCLES 3u     /* lower bound of one subs/bne turn on the M0+ and the M4 */
/* Core clocks s32k_hal_init accepts: the family's range (S32K14x HSRUN 112 MHz at most). */
#define S32K_HAL_CORE_HZ_MIN 1000000u
#define S32K_HAL_CORE_HZ_MAX 112000000u

struct s32k_hal_irq_slot {
    hal_pin_t pin; /* HAL_PIN_NONE when free */
    hal_irq_cb cb;
    void *arg;
};

struct s32k_hal_config {
    enum s32k_part part;
    uint32_t core_hz; /* from s32k_clock_init */
    bool watchdog;    /* refresh the watchdog (it was enabled by the startup) */
};

/* Port state (static, caller-owned); fields private. */
struct s32k_hal {
    struct s32k_hal_config cfg;
    struct s32k_time time;
    uint32_t loop_q16; /* core cycles per ns in Q16.16 / S32K_HAL_LOOP_CYCLES */
    struct s32k_hal_irq_slot irq[S32K_HAL_IRQ_SLOTS];
    volatile uint32_t irq_count; /* callbacks run */
    uint32_t irq_seen;           /* irq_count when irq_wait last returned 0 */
};

/*
 * Start the time base and fill *hal (ops, ctx = p). The clocks (s32k_clock_init) and the pins
 * (s32k_gpio_output/input, s32k_gpio_clock_on) are set up by the board before. Returns 0,
 * INC_ERR_NULL, INC_ERR_INVAL (part or core_hz), or an error of the time base.
 */
int s32k_hal_init(struct s32k_hal *p, const struct s32k_hal_config *cfg, struct hal *hal);

/* Core cycles per ns in Q16.16 over S32K_HAL_LOOP_CYCLES, rounded up (s32k_hal.loop_q16). */
uint32_t s32k_hal_loop_q16(uint32_t core_hz);

/* The port's delay_ns (also for callers that hold the struct, not the HAL). */
void s32k_hal_delay_ns(struct s32k_hal *p, uint32_t ns);

/*
 * Short delays for inner loops (the bit-banged SPI's half periods): prepared once per frame,
 * run per bit without a call or a multiply. On the part a prepared delay up to
 * S32K_HAL_SPIN_MAX_NS is the counted loop inlined at the caller; anything longer, and every
 * delay in the _sim build, goes to s32k_hal_delay_ns. A prepared 0 runs no delay.
 */
#define S32K_HAL_SHORT_CALL 0x80000000u
static inline uint32_t s32k_hal_short_prep(const struct s32k_hal *p, uint32_t ns)
{
#if defined(INCLINO_S32K_MMIO_SIM)
    (void)p;
    return ns == 0u ? 0u : (S32K_HAL_SHORT_CALL | (ns & ~S32K_HAL_SHORT_CALL));
#else
    if (ns == 0u) {
        return 0u;
    }
    if (ns > S32K_HAL_SPIN_MAX_NS) {
        return S32K_HAL_SHORT_CALL | ns;
    }
    /* turns = ceil(ns * cycles per ns / LOOP_CYCLES) + 1 (the +1: a call may start mid-cycle) */
    return (uint32_t)(((uint64_t)ns * p->loop_q16 + 0xFFFFu) >> 16) + 1u;
#endif
}

static inline __attribute__((always_inline)) void s32k_hal_short_run(struct s32k_hal *p, uint32_t v)
{
    if (v == 0u) {
        return;
    }
    if ((v & S32K_HAL_SHORT_CALL) != 0u) {
        s32k_hal_delay_ns(p, v & ~S32K_HAL_SHORT_CALL);
        return;
    }
#if !defined(INCLINO_S32K_MMIO_SIM)
#if defined(__ARM_ARCH_6M__)
    /* gcc passes Thumb-1 inline assembly in divided syntax: there `sub` sets the flags */
    __asm volatile("1: sub %0, #1\n\tbne 1b" : "+l"(v) : : "cc");
#else
    __asm volatile("1: subs %0, %0, #1\n\tbne 1b" : "+l"(v) : : "cc");
#endif
#endif
}

/* Body of a PORT interrupt vector: port 0..4 (S32K116: call it for every port, 0..4). */
void s32k_hal_port_isr(struct s32k_hal *p, uint32_t port);

/* Body of the LPIT0 vector (channel 1 wake-up). */
void s32k_hal_lpit_isr(struct s32k_hal *p);

/* For another peripheral's interrupt handler whose event a driver sleeps on in hal_irq_wait
 * (the LPSPI engine with irq_wait): counts as a callback run, so irq_wait returns 0. Interrupt
 * context. NULL: nothing. */
void s32k_hal_wake(struct s32k_hal *p);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_S32K_HAL_H */
