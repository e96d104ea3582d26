/*
 * spi_bitbang.h - SPI master made of three GPIO pins and a delay: the only code in Inclino that
 * touches SCLK, MOSI, MISO and chip-select.
 *
 * It serves struct spi_bus (spi.h), so a sensor driver cannot tell it from hardware SPI. All four
 * modes, MSB first, 8- and 16-bit frames, CS held or toggled between frames, per-device timing.
 *
 * Bus time. For one frame of b bits with period P (halves h1 = P/2 after the leading edge and
 * h2 = P - h1 before it), setup S, hold H and stall T, the engine keeps exactly:
 *   CS fall -> first edge S; leading -> trailing h1; trailing -> next leading h2;
 *   last edge -> CS rise H; CS rise -> next CS fall of the same device >= T.
 * So a CS period lasts S + b*P - h2 + H and frame-to-frame b*P - h2 + S + H + T, inside the
 * physical bound b*P + S + H + T (the simulated bus measures it: docs/benchmarks.md). Between
 * frames of one CS period the SCLK idles max(gap, h2).
 *
 * Sampling. CPHA = 0: MOSI is set before the leading edge and MISO read at it. CPHA = 1: MOSI is
 * set at the leading edge and MISO read at the trailing edge, h1 after the part shifted it out,
 * so h1 must cover the part's output delay (the device's timing must say so).
 *
 * The pins' directions are set up by the board (port); CS is parked high when a device
 * attaches. When a transfer needs SCLK at another idle level than it has (the first transfer,
 * or a device with another CPOL), SCLK moves while every CS is high and settles for h2 before
 * CS falls.
 */
#ifndef INCLINO_SPI_BITBANG_H
#define INCLINO_SPI_BITBANG_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/hal.h"
#include "inclino/spi.h"

#ifdef __cplusplus
extern "C" {
#endif

struct spi_bitbang_cfg {
    const struct hal *hal;
    hal_pin_t sclk;
    hal_pin_t mosi;
    hal_pin_t miso;
};

/*
 * A port's fast path for the bits of one frame (optional, spi_bitbang_set_fast). The engine
 * keeps everything around the bits (SCLK idle moves, CS, stall, set-up, hold, gaps); the port
 * clocks the `bits` bits of `word`, MSB first, in exactly the engine's order with the port's
 * pins and delays inlined - for CPHA = 0, per bit: MOSI if it changes, wait (lead_ns for the
 * first bit, h2_ns after), read MISO, SCLK to !idle, wait h1_ns, SCLK to idle; for CPHA = 1:
 * wait (lead/h2), SCLK to !idle, MOSI if it changes, wait h1_ns, read MISO, SCLK to idle - and
 * returns the bits read (MSB first). A wait of 0 ns is skipped, a non-zero one is at least that
 * long. One indirect call per frame instead of five per bit (docs/benchmarks.md).
 */
struct spi_bitbang_frame {
    uint16_t word;
    uint8_t bits;
    bool cpha;
    bool idle;       /* SCLK idle level (CPOL) */
    bool mosi_level; /* MOSI now; the port returns the level it leaves in mosi_out */
    uint32_t lead_ns, h1_ns, h2_ns;
};

struct spi_bitbang_fast {
    uint16_t (*frame)(void *ctx, const struct spi_bitbang_frame *fr, bool *mosi_out);
    void *ctx;
};

struct spi_bitbang {
    struct spi_bitbang_cfg cfg;
    const struct spi_bitbang_fast *fast; /* NULL: every bit through the HAL's pin operations */
    struct spi_bus bus; /* the interface this engine serves; pass &bb.bus to spi_dev_init */
    bool sclk_level;
    bool mosi_level;
    bool pins_known;          /* sclk_level/mosi_level reflect the pins */
    bool released_any;        /* last_cs/last_release_ns are meaningful */
    hal_pin_t last_cs;        /* the CS that rose last, and when: a device initialised again */
    uint64_t last_release_ns; /* on the same CS still gets its stall */
};

/*
 * Initialise the engine on a HAL and three pins (distinct, not HAL_PIN_NONE). Returns 0,
 * INC_ERR_NULL (cfg, hal or a HAL operation missing) or INC_ERR_INVAL (pins).
 */
int spi_bitbang_init(struct spi_bitbang *bb, const struct spi_bitbang_cfg *cfg);

/* Use a port's fast path for the frames' bits (NULL: back to the HAL pin operations). It must
 * drive the same pins as cfg names. On an engine made by spi_bitbang_init_fast a NULL is
 * ignored (that engine has no per-bit path). */
void spi_bitbang_set_fast(struct spi_bitbang *bb, const struct spi_bitbang_fast *fast);

/* spi_bitbang_init with the fast path set for good: the engine's transfer has no per-bit HAL
 * loop, so an image that uses only this initialiser links none (the S32K1 boards: about 300 B of
 * the M0+ image, docs/benchmarks.md). INC_ERR_NULL also for fast or fast->frame NULL. */
int spi_bitbang_init_fast(struct spi_bitbang *bb, const struct spi_bitbang_cfg *cfg,
                          const struct spi_bitbang_fast *fast);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_SPI_BITBANG_H */
