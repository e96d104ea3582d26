/*
 * sim/loopback.h - the simplest SPI part: it answers each word with the previous word it
 * received (XOR a pattern), across CS periods. Its first answer after init is `first`.
 *
 * Used to test the SPI engine in every mode and frame size: the words that come back prove both
 * directions, and the log of received words proves what the part actually decoded.
 */
#ifndef INCLINO_SIM_LOOPBACK_H
#define INCLINO_SIM_LOOPBACK_H

#include <stdint.h>

#include "inclino/sim/spi_slave.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SIM_LOOPBACK_LOG 64u

struct sim_loopback_cfg {
    const char *name;
    struct sim_pinbus *bus;
    unsigned cs, sclk, mosi, miso;
    uint8_t mode; /* 0..3 or SIM_SPI_MODE_AUTO_0_3 */
    uint8_t bits; /* 8 or 16 */
    struct sim_spi_timing timing;
    uint16_t first;    /* answer before any word was received */
    uint16_t xor_mask; /* answers are previous ^ xor_mask */
    struct sim_violation_log *log;
};

struct sim_loopback {
    struct sim_spi_slave slave;
    uint16_t next; /* the answer being prepared */
    uint16_t xor_mask;
    unsigned received;                 /* words received in total */
    uint16_t rx_log[SIM_LOOPBACK_LOG]; /* the first SIM_LOOPBACK_LOG words received */
    unsigned frames_ended;
    unsigned last_frame_words;
    unsigned last_frame_flags;
};

int sim_loopback_init(struct sim_loopback *m, const struct sim_loopback_cfg *cfg);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_SIM_LOOPBACK_H */
