/*
 * sim/s32k_lpspi_rig.h - the LPSPI engine (drivers/spi_lpspi, _sim build) and its register model
 * wired to the standard simulated board (sim/board.h), for tests and benches that run the
 * sensor drivers through LPSPI instead of the bit-banged engine.
 *
 * LPSPI0 at its real address; SCK, SOUT, SIN on the board's sclk, mosi, miso; PCS0..3 on
 * cs0..cs3, so a driver's spi_dev_cfg.cs = SIM_BOARD_CS(k) is served by PCSk. The functional
 * clock is SIM_LPSPI_RIG_FCLK_HZ unless changed. Every register access costs
 * SIM_LPSPI_RIG_ACCESS_NS of virtual time (the S32K1 bus hook), so the engine's status polling
 * lets simulated time pass as on the part. One rig per process (the S32K1 bus is global).
 */
#ifndef INCLINO_SIM_S32K_LPSPI_RIG_H
#define INCLINO_SIM_S32K_LPSPI_RIG_H

#include "inclino/sim/board.h"
#include "inclino/sim/s32k_lpspi.h"
#include "inclino/spi_lpspi.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SIM_LPSPI_RIG_FCLK_HZ 48000000u /* FIRCDIV2 = 48 MHz (an S32K1 LPSPI clock choice) */
#define SIM_LPSPI_RIG_ACCESS_NS 25u     /* one peripheral register access, a modelled cost */

struct sim_lpspi_rig {
    struct sim_board *board;
    struct sim_s32k_lpspi model;
    struct spi_lpspi engine; /* &engine.bus is the spi_bus for the drivers */
};

/* Reset the S32K1 bus, map the model, install the access hook, initialise the engine at
 * fclk_hz (0: SIM_LPSPI_RIG_FCLK_HZ). Returns 0 or the model's or engine's error. */
int sim_lpspi_rig_init(struct sim_lpspi_rig *r, struct sim_board *b, uint32_t fclk_hz);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_SIM_S32K_LPSPI_RIG_H */
