/*
 * s32k_gpio.h - PORT pin muxing, GPIO and the pin interrupt of the S32K1 family
 * [S32K1XXRM, Port Control and Interrupts (PORT); General-Purpose Input/Output (GPIO)].
 *
 * Pin numbers (hal_pin_t): port * 32 + bit, port 0 = PORTA/PTA .. 4 = PORTE/PTE; S32K_PIN(2, 14)
 * is PTC14. Writes use PSOR/PCOR (one store, no read-modify-write, so an interrupt handler that
 * writes another pin of the same port cannot be undone); reads use PDIR.
 *
 * Pin interrupt: PCR.IRQC selects the edge (rising 9, falling 10, either 11); the edge sets
 * PCR.ISF, which requests the port's NVIC vector: on the S32K144 one per port (PORTA 59 ..
 * PORTE 63), on the S32K116 one for all ports (PORT, 9). The handler calls s32k_gpio_isr(),
 * which clears the flags it returns (w1c in ISFR) before the callbacks run, so an edge during
 * a callback is not lost.
 */
#ifndef INCLINO_S32K_GPIO_H
#define INCLINO_S32K_GPIO_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/error.h"
#include "inclino/hal.h"
#include "inclino/s32k1_regs.h"
#include "inclino/s32k_mmio.h"

#ifdef __cplusplus
extern "C" {
#endif

#define S32K_PIN(port, bit) ((hal_pin_t)((uint32_t)(port)*32u + (uint32_t)(bit)))
#define S32K_PIN_PORT(pin) ((uint32_t)(pin) >> 5)
#define S32K_PIN_BIT(pin) ((uint32_t)(pin)&31u)
#define S32K_PIN_VALID(pin) ((uint32_t)(pin) < S32K_PORT_COUNT * S32K_PORT_PINS)

enum s32k_pin_pull { S32K_PULL_NONE = 0, S32K_PULL_UP = 1, S32K_PULL_DOWN = 2 };

/* Gate the clock of PORTA..PORTE on (PCC). 0 or an error of s32k_pcc_enable. */
int s32k_gpio_clock_on(void);

/* Mux pin to alternative mux (0..7; S32K_PORT_PCR_MUX_GPIO = 1) with a pull; interrupt off. */
int s32k_pin_mux(hal_pin_t pin, uint32_t mux, enum s32k_pin_pull pull);

/* Pin as GPIO output driving level (the level is set before the direction). */
int s32k_gpio_output(hal_pin_t pin, bool level);

/* Pin as GPIO input with a pull. */
int s32k_gpio_input(hal_pin_t pin, enum s32k_pin_pull pull);

/* Drive an output pin: PSOR or PCOR, one store. No check (the fast path of the bit-banged SPI). */
static inline void s32k_gpio_write(hal_pin_t pin, bool level)
{
    const uint32_t port = S32K_PIN_PORT(pin);
    s32k_mmio_write32(level ? S32K_GPIO_PSOR(port) : S32K_GPIO_PCOR(port), 1u << S32K_PIN_BIT(pin));
}

/* Level of a pin (PDIR). No check. */
static inline bool s32k_gpio_read(hal_pin_t pin)
{
    return ((s32k_mmio_read32(S32K_GPIO_PDIR(S32K_PIN_PORT(pin))) >> S32K_PIN_BIT(pin)) & 1u) != 0u;
}

/*
 * Route the given edge of pin to its port's interrupt (enable) or stop it: PCR.IRQC, the stale
 * flag cleared, the NVIC vector of the part enabled (never disabled: other pins of the port may
 * use it). INC_ERR_INVAL for a bad pin or edge.
 */
int s32k_gpio_irq_enable(enum s32k_part part, hal_pin_t pin, enum hal_edge edge, bool enable);

/* The NVIC interrupt number of a port's pin interrupt on the part. */
uint32_t s32k_gpio_irq_number(enum s32k_part part, uint32_t port);

/* Interrupt handler work for one port: read ISFR, clear those flags (w1c), return them. */
uint32_t s32k_gpio_isr(uint32_t port);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_S32K_GPIO_H */
