/*
 * sim/board.h - the standard simulated board: clock, wires, HAL and SPI master in one struct.
 *
 * Pin map (pin-bus indices = hal_pin_t):
 *   0 sclk, 1 mosi, 2 miso (pull-up unless changed: no device reads all ones),
 *   3..6 cs0..cs3 (pull-up), 7..10 dr0..dr3 (data-ready inputs, pull-down),
 *   11..14 rst0..rst3 (pull-up).
 * Device models attach their SPI slave to sclk/mosi/miso and one csN, and drive drN.
 */
#ifndef INCLINO_SIM_BOARD_H
#define INCLINO_SIM_BOARD_H

#include "inclino/hal.h"
#include "inclino/hal_sim.h"
#include "inclino/sim/clock.h"
#include "inclino/sim/pinbus.h"
#include "inclino/sim/violation.h"
#include "inclino/spi_bitbang.h"

#ifdef __cplusplus
extern "C" {
#endif

enum sim_board_pin {
    SIM_BOARD_SCLK = 0,
    SIM_BOARD_MOSI = 1,
    SIM_BOARD_MISO = 2,
    SIM_BOARD_CS0 = 3,
    SIM_BOARD_DR0 = 7,
    SIM_BOARD_RST0 = 11,
    SIM_BOARD_PINS = 15,
};
#define SIM_BOARD_CS(n) ((unsigned)SIM_BOARD_CS0 + (unsigned)(n))
#define SIM_BOARD_DR(n) ((unsigned)SIM_BOARD_DR0 + (unsigned)(n))
#define SIM_BOARD_RST(n) ((unsigned)SIM_BOARD_RST0 + (unsigned)(n))
#define SIM_BOARD_SPI_MASK                                                                        \
    (SIM_PIN_MASK(SIM_BOARD_SCLK) | SIM_PIN_MASK(SIM_BOARD_MOSI) | SIM_PIN_MASK(SIM_BOARD_MISO) | \
     SIM_PIN_MASK(SIM_BOARD_CS0) | SIM_PIN_MASK(SIM_BOARD_CS0 + 1) |                              \
     SIM_PIN_MASK(SIM_BOARD_CS0 + 2) | SIM_PIN_MASK(SIM_BOARD_CS0 + 3))

struct sim_board {
    struct sim_clock clk;
    struct sim_violation_log log; /* contention and every model that reports here */
    struct sim_pinbus bus;
    struct hal_sim port;
    struct hal hal;
    struct spi_bitbang spi; /* the firmware's SPI master; &spi.bus is the spi_bus */
};

/* Set up everything above. Returns 0 or an error from the parts. */
int sim_board_init(struct sim_board *b);

/* Change MISO's pull (models a board without a pull-up, or a pull-down). */
int sim_board_set_miso_pull(struct sim_board *b, enum sim_pull pull);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_SIM_BOARD_H */
