/*
 * sim/s32k_port_gpio.h - register-level model of PORTA..PORTE and PTA..PTE of the S32K1,
 * connected to the simulated pin bus (inclino/sim/pinbus.h).
 *
 * Wiring: sim_s32k_port_gpio_connect(m, pin, line) joins MCU pin `pin` (port * 32 + bit, as in
 * inclino/s32k_gpio.h) to pin-bus line `line`. For a connected pin:
 *   - output (PDDR bit set, PCR.MUX = GPIO): the master drives the line with PDOR's bit; PSOR,
 *     PCOR, PTOR and PDOR writes change it; clearing PDDR releases the line;
 *   - PDIR reads the resolved line level (0 when PIDR disables the input or MUX is not GPIO,
 *     as on the part); unconnected pins read 0;
 *   - PCR.IRQC 9/10/11: an edge of the line (whoever drives it) sets PCR.ISF and raises the
 *     port's NVIC interrupt in the simulated core (S32K144 59 + port, S32K116 9); ISF and ISFR
 *     are write-1-to-clear; while ISF is set a further edge changes nothing.
 * PCR.PE/PS are stored, not applied: the pin bus's pulls are the board's (resistors).
 */
#ifndef INCLINO_SIM_S32K_PORT_GPIO_H
#define INCLINO_SIM_S32K_PORT_GPIO_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/error.h"
#include "inclino/s32k1_regs.h"
#include "inclino/sim/pinbus.h"
#include "inclino/sim/s32k_core.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SIM_S32K_PIN_NONE 0xFFu

struct sim_s32k_port_gpio {
    struct sim_pinbus *bus;
    struct sim_s32k_core *core;
    enum s32k_part part;
    uint32_t pcr[S32K_PORT_COUNT][S32K_PORT_PINS];
    uint32_t pdor[S32K_PORT_COUNT], pddr[S32K_PORT_COUNT], pidr[S32K_PORT_COUNT];
    uint8_t line[S32K_PORT_COUNT][S32K_PORT_PINS]; /* pin-bus line, SIM_S32K_PIN_NONE */
    uint8_t mcu_pin[SIM_PINBUS_MAX_PINS];          /* line -> MCU pin, 0xFF none */
    struct sim_pin_listener listener;
    uint64_t edges_flagged; /* ISF set by an edge */
};

/* Map the PORT and GPIO regions; nothing connected yet. 0 or an error. */
int sim_s32k_port_gpio_init(struct sim_s32k_port_gpio *m, struct sim_pinbus *bus,
                            struct sim_s32k_core *core, enum s32k_part part);

/* Connect MCU pin (port * 32 + bit) to a pin-bus line. INC_ERR_INVAL for a bad pin/line or a
 * line already connected. */
int sim_s32k_port_gpio_connect(struct sim_s32k_port_gpio *m, unsigned mcu_pin, unsigned line);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_SIM_S32K_PORT_GPIO_H */
