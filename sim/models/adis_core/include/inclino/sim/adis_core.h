/*
 * sim/adis_core.h - the SPI protocol of the simulated ADIS parts (ADIS16255, ADIS1636x/1640x),
 * shared by their models; each model supplies its register file through the hooks below.
 *
 * Written from the datasheets (ADIS16250/55 Rev B p. 11; ADIS16362/67/407 SPI sections; see
 * docs/sensor-facts.md §2.2, §3.1), not from the drivers:
 *   - 16-bit frames, mode 3. A read command (bit 15 = 0, address in bits 14..8) latches the
 *     register when CS rises; its value is shifted out during the NEXT frame.
 *   - A write command (bit 15 = 1) writes its low byte to the addressed byte register when CS
 *     rises. A frame after a write shifts out an undefined word (here: pseudo-random garbage).
 *   - Commands take effect at CS rise and only from a clean frame: a frame that broke a timing
 *     rule (stall, hold, setup, SCLK speed, partial word) is dropped, and the next frame shifts
 *     out garbage, as the part's state is then unknown.
 *   - While the part is busy (after a reset, autonull, flash update... the model says when) it
 *     answers garbage, ignores commands and each such frame is reported as SIM_VIOL_BUSY.
 *   - Burst (ADIS1636x/1640x): DIN = burst_cmd starts, in the same CS period, a stream of
 *     output words; SCLK must not exceed burst_min_period_ns for the whole frame (checked with
 *     the slave's frame_min_period_ns: a faster burst is reported and returns garbage). A
 *     stricter limit already in force (low-power mode) still applies during the burst.
 */
#ifndef INCLINO_SIM_ADIS_CORE_H
#define INCLINO_SIM_ADIS_CORE_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/sim/inertial.h"
#include "inclino/sim/spi_slave.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SIM_ADIS_BURST_MAX 16u

struct sim_adis_ops {
    /* The 16-bit register at addr (even or odd address: the whole register), latched for the
     * next frame; read side effects (ND clear, DIAG clear-on-read) belong here. */
    uint16_t (*read)(void *model, uint8_t addr, uint64_t t_ns);
    /* Write one byte to byte-address addr. */
    void (*write)(void *model, uint8_t addr, uint8_t value, uint64_t t_ns);
    /* True while the part is busy and ignores the bus. */
    bool (*busy)(void *model, uint64_t t_ns);
    /* Burst read (may be NULL: no burst). Fill up to max words, return the count. */
    unsigned (*burst)(void *model, uint16_t *words, unsigned max, uint64_t t_ns);
};

struct sim_adis_cfg {
    const char *name;
    struct sim_pinbus *bus;
    unsigned cs, sclk, mosi, miso;
    struct sim_spi_timing timing; /* limits in normal mode */
    uint8_t addr_mask;            /* 0x3F (ADIS16255) or 0x7F (ADIS1636x/1640x) */
    uint16_t burst_cmd;           /* 0x3E00 on ADIS1636x/1640x; 0 = no burst */
    uint32_t burst_min_period_ns; /* 1000 (1 MHz) */
    const struct sim_adis_ops *ops;
    void *model;
    struct sim_violation_log *log;
    uint64_t seed; /* garbage generator */
    /* Optional (NULL: none). Called with `model` when a frame is dropped because it broke a
     * timing or framing rule (flags: the frame's SIM_SPI_FLAG bits), not because the part was
     * busy: a part with an "SPI communication failure" status bit sets it here. Also called
     * for a burst clocked faster than burst_min_period_ns (flags 0). A config
     * member rather than an op so that existing positional sim_adis_ops initialisers stay
     * valid under -Wmissing-field-initializers. */
    void (*frame_error)(void *model, unsigned flags, uint64_t t_ns);
};

struct sim_adis_core {
    struct sim_spi_slave slave;
    struct sim_adis_cfg cfg;
    struct sim_rng rng;
    uint16_t next_out; /* word for the next frame */
    bool next_valid;   /* false: next frame shifts out garbage */
    uint16_t cmd;      /* command of the current frame */
    bool bursting;
    uint16_t burst[SIM_ADIS_BURST_MAX];
    unsigned burst_len;
    /* statistics */
    uint32_t reads, writes, dropped, busy_frames, bursts;
};

int sim_adis_core_init(struct sim_adis_core *c, const struct sim_adis_cfg *cfg);

/* Change the SCLK/stall limits (normal <-> low-power mode). */
int sim_adis_core_set_timing(struct sim_adis_core *c, const struct sim_spi_timing *t);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_SIM_ADIS_CORE_H */
