/*
 * s32k_board.h - the S32K1 evaluation boards as the firmware sees them: which part, which clock,
 * which PORT pins carry the sensors' SPI, chip selects, data-ready and the CAN transceiver
 * (docs/boards.md has the wiring), and the bring-up that turns that into a struct hal and a
 * struct spi_bus.
 *
 * The SPI engine is a choice of the board (enum s32k_board_spi): the bit-banged engine
 * (drivers/spi, over the GPIO pins) or LPSPI, the hardware SPI (drivers/spi_lpspi, on the same
 * pins in their LPSPI mux). Both serve struct spi_bus, so the drivers cannot tell them apart.
 * With LPSPI, SCK/SOUT/SIN and every chip select that is an LPSPI0 PCS pin (cs_imu_pcs,
 * cs_acc_pcs) are muxed to LPSPI0, clocked from SPLLDIV2 (40 MHz) or FIRCDIV2 (24 MHz) by the
 * board's clock, and the engine sleeps on LPSPI0's interrupt (IRQ 26, enabled in the NVIC here;
 * the image's LPSPI0_IRQHandler calls s32k_board_lpspi_isr) while its FIFO drains; a chip
 * select without a PCS stays a GPIO held high, and a device on it is
 * refused by the engine (INC_ERR_INVAL at spi_dev_init) (docs/boards.md, "SPI engine").
 */
#ifndef INCLINO_S32K_BOARD_H
#define INCLINO_S32K_BOARD_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/error.h"
#include "inclino/hal.h"
#include "inclino/s32k1_regs.h"
#include "inclino/s32k_hal.h"
#include "inclino/s32k_scg.h"
#include "inclino/spi.h"
#include "inclino/spi_bitbang.h"
#include "inclino/spi_lpspi.h"

#ifdef __cplusplus
extern "C" {
#endif

enum s32k_board_spi {
    S32K_BOARD_SPI_BITBANG = 0,
    S32K_BOARD_SPI_LPSPI = 1,
};

/* Pins: S32K_PIN(port, bit) of inclino/s32k_gpio.h. */
struct s32k_board_pins {
    hal_pin_t sclk, mosi, miso; /* LPSPI0 SCK/SOUT/SIN when muxed to it */
    hal_pin_t cs_imu;           /* ADIS1636x/1640x chip select */
    hal_pin_t cs_acc;           /* SCA3000 chip select */
    hal_pin_t dr_imu;           /* ADIS DIO1 data ready */
    hal_pin_t dr_acc;           /* SCA3000 INT */
    hal_pin_t rst_imu;          /* ADIS RST (active low) */
    hal_pin_t can_tx, can_rx;   /* CAN0 to the board's transceiver */
    uint8_t lpspi_mux;          /* PCR.MUX of sclk/mosi/miso for LPSPI0 */
    uint8_t can_mux;            /* PCR.MUX of can_tx/can_rx for CAN0 */
    uint8_t cs_imu_pcs;         /* LPSPI0 PCS index of cs_imu in lpspi_mux, or S32K_BOARD_NO_PCS */
    uint8_t cs_acc_pcs;         /* LPSPI0 PCS index of cs_acc in lpspi_mux, or S32K_BOARD_NO_PCS */
};

#define S32K_BOARD_NO_PCS 0xFFu
#define S32K_BOARD_LPSPI_SPLL_HZ 40000000u /* SPLLDIV2 of S32K_CLOCK_SPLL_80 (s32k_scg.h) */

struct s32k_board_desc {
    const char *name; /* "s32k144evb", "s32k116evb" */
    enum s32k_part part;
    enum s32k_clock clock;
    struct s32k_board_pins pins;
};

extern const struct s32k_board_desc s32k_board_s32k144evb;
extern const struct s32k_board_desc s32k_board_s32k116evb;

struct s32k_board {
    const struct s32k_board_desc *desc;
    uint32_t core_hz;
    struct s32k_hal port;
    struct hal hal;
    /* The two SPI engines share their memory: a board runs exactly one (spi says which; the
     * other member is not valid). */
    union {
        struct spi_bitbang bb;
        struct spi_lpspi lp;
    };
    struct spi_bitbang_fast fast; /* the port's inlined bit loop for bb (s32k_board_bb_frame) */
    const struct spi_bus *spi;    /* the engine chosen: &bb.bus or &lp.bus (NULL before) */
};

/*
 * Bring the board up: clocks (desc->clock), PORT clocks, pins (SPI and CS outputs idle high,
 * RST high, data-ready inputs, CAN pins muxed), the HAL port (refreshing the watchdog when
 * `watchdog`: the startup enabled it) and the SPI engine. The watchdog itself is configured by
 * the startup (s32k_wdog_init), before this. Returns 0, INC_ERR_NULL, INC_ERR_INVAL (spi) or
 * the first error of the parts (the LPSPI engine's included).
 */
int s32k_board_init(struct s32k_board *b, const struct s32k_board_desc *desc,
                    enum s32k_board_spi spi, bool watchdog);

/*
 * The same in two steps, so an image links only the engine it uses (the LPSPI driver is about
 * 2 KB of an M0+ image): s32k_board_init_core (clocks, pins, the HAL port; b->spi = NULL), then
 * exactly one of s32k_board_spi_bitbang / s32k_board_spi_lpspi. s32k_board_init is
 * init_core + the engine `spi` names. Each returns 0, INC_ERR_NULL, INC_ERR_STATE (the engine
 * before init_core, or a second engine) or the first error of the parts.
 */
int s32k_board_init_core(struct s32k_board *b, const struct s32k_board_desc *desc, bool watchdog);
int s32k_board_spi_bitbang(struct s32k_board *b);
int s32k_board_spi_lpspi(struct s32k_board *b);

/* The bit-banged engine's fast path on this board (struct spi_bitbang_fast; ctx = the board):
 * PSOR/PCOR/PDIR and the port's inlined short delays, no call per bit. */
uint16_t s32k_board_bb_frame(void *ctx, const struct spi_bitbang_frame *fr, bool *mosi_out);

/* The board's vector entries call these (PORT pin interrupt, LPIT0, LPSPI0: the LPSPI engine
 * sleeps on its interrupt while the FIFO drains, spi_lpspi.h). */
void s32k_board_port_isr(struct s32k_board *b, uint32_t port);
void s32k_board_lpit_isr(struct s32k_board *b);
void s32k_board_lpspi_isr(struct s32k_board *b);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_S32K_BOARD_H */
