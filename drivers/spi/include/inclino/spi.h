/*
 * spi.h - SPI as the sensor drivers see it: devices and frames, never pins.
 *
 * A bus is anything that can move frames: the bit-banged engine (spi_bitbang.h) on a real or
 * simulated board, a trace recorder wrapped around another bus, or a replay of recorded traffic.
 * It is one const ops table plus a context pointer (struct spi_bus), like the HAL.
 *
 * A device is a bus plus the part's settings (struct spi_dev_cfg): chip-select pin, mode,
 * frame size and timing. spi_transfer() moves n frames to and from one device, either inside
 * one chip-select period (SPI_CS_HOLD, e.g. an ADIS burst read) or with chip-select released
 * for the stall time between frames (SPI_CS_TOGGLE, e.g. ADIS register reads). The stall is also
 * kept between transfers to the same device.
 *
 * Frame words are uint16_t, MSB first on the wire; an 8-bit frame uses bits 7..0 and a word with
 * bits set above the frame size is rejected (INC_ERR_INVAL), never truncated.
 */
#ifndef INCLINO_SPI_H
#define INCLINO_SPI_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "inclino/error.h"
#include "inclino/hal.h"

#ifdef __cplusplus
extern "C" {
#endif

/* SPI modes: bit 1 = CPOL (SCLK idle level), bit 0 = CPHA (1: sample on the trailing edge). */
enum spi_mode {
    SPI_MODE_0 = 0,
    SPI_MODE_1 = 1,
    SPI_MODE_2 = 2,
    SPI_MODE_3 = 3,
};

enum spi_cs_policy {
    SPI_CS_HOLD = 0,   /* CS low across every frame of the transfer; gap_ns between frames */
    SPI_CS_TOGGLE = 1, /* CS released after each frame; stall_ns with CS high between frames */
};

/* Upper bound on frames per transfer (a bound on bus time per call, not a buffer size). */
#define SPI_MAX_FRAMES 256u

/*
 * Timing of one device, in ns. Every value is a minimum the engine guarantees (the simulated
 * bus meets it exactly; a real port adds its own overhead).
 */
struct spi_timing {
    uint32_t sclk_period_ns; /* full SCLK period, >= 2; 500 = 2 MHz. Halves: period/2 (high or
                                low after the leading edge) and period - period/2 */
    uint32_t cs_setup_ns;    /* CS falling edge -> first SCLK edge */
    uint32_t cs_hold_ns;     /* last SCLK edge -> CS rising edge */
    uint32_t stall_ns;       /* CS high between two CS periods of this device (tSTALL) */
    uint32_t gap_ns;         /* SPI_CS_HOLD: SCLK idle between frames; at least the half period
                                is always kept */
};

struct spi_dev_cfg {
    hal_pin_t cs; /* chip select, active low */
    uint8_t mode; /* enum spi_mode */
    uint8_t bits; /* 8 or 16 */
    struct spi_timing timing;
};

struct spi_dev;

struct spi_bus_ops {
    /*
     * Move n (1..SPI_MAX_FRAMES) frames with dev's settings. tx NULL sends zeros; rx may be NULL.
     * Arguments are validated by spi_transfer() before this is called.
     */
    int (*transfer)(void *ctx, struct spi_dev *dev, const uint16_t *tx, uint16_t *rx, size_t n,
                    enum spi_cs_policy cs);
    /* Optional (may be NULL): a device joins the bus (the engine parks its CS high). */
    int (*attach)(void *ctx, struct spi_dev *dev);
};

struct spi_bus {
    const struct spi_bus_ops *ops;
    void *ctx;
};

struct spi_dev {
    const struct spi_bus *bus;
    struct spi_dev_cfg cfg;
    uint64_t cs_release_ns; /* when CS last rose (for the stall between transfers) */
    bool released_once;     /* cs_release_ns is meaningful */
    uint32_t transfers;     /* statistics */
};

/* 0 when the timing is usable (period >= 2 ns), INC_ERR_NULL or INC_ERR_INVAL otherwise. */
int spi_timing_check(const struct spi_timing *t);

/* The shortest period for a maximum SCLK frequency: ceil(1e9 / hz). 0 when hz == 0. */
uint32_t spi_period_for_hz(uint32_t hz);

/*
 * Bind dev to bus with cfg (copied). Validates: bus and ops present, cs != HAL_PIN_NONE,
 * mode 0..3, bits 8 or 16, timing. Returns 0, INC_ERR_NULL or INC_ERR_INVAL (dev unusable).
 */
int spi_dev_init(struct spi_dev *dev, const struct spi_bus *bus, const struct spi_dev_cfg *cfg);

/* Replace the timing (e.g. the ADIS 1 MHz burst limit). Same checks as spi_dev_init. */
int spi_dev_set_timing(struct spi_dev *dev, const struct spi_timing *t);

/*
 * Transfer n frames. Returns 0 or an error: INC_ERR_NULL, INC_ERR_INVAL (n == 0 or
 * > SPI_MAX_FRAMES, a tx word wider than the frame), INC_ERR_STATE (dev not initialised), or
 * the bus's own error. On error rx contents are undefined and must not be used.
 */
int spi_transfer(struct spi_dev *dev, const uint16_t *tx, uint16_t *rx, size_t n,
                 enum spi_cs_policy cs);

/* One frame in its own CS period: shorthand for spi_transfer(dev, &tx, rx, 1, SPI_CS_TOGGLE). */
int spi_xfer1(struct spi_dev *dev, uint16_t tx, uint16_t *rx);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_SPI_H */
