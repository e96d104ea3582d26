/*
 * sim/spi_slave.h - pin-level SPI slave, the front end of every simulated part.
 *
 * The framework watches CS, SCLK and MOSI on the pin bus and drives MISO, exactly as a part's
 * shift register does; a device model above it only sees whole words. It decodes the four SPI
 * modes (or senses mode 0/3 from SCLK's level when CS falls, as parts that accept both do),
 * MSB first, 8- or 16-bit words, any number of words per CS frame.
 *
 * Timing rules are checked on every edge against the part's limits (struct sim_spi_timing);
 * each break is written to the violation log and has the consequence it has on silicon:
 *   - MISO changes miso_delay_ns after the shifting edge (tDAV): a master that samples earlier,
 *     e.g. with SCLK too fast, reads the previous bit;
 *   - a sampling edge closer than min_period_ns to the previous one is missed by the shift
 *     register (the bit is lost, the word misaligns);
 *   - the first SCLK edge sooner than min_cs_setup_ns after CS fell is missed;
 *   - MOSI that changed less than mosi_setup_ns before a sampling edge is sampled at its old
 *     level;
 *   - CS falling sooner than min_stall_ns after it rose, or rising sooner than min_cs_hold_ns
 *     after the last edge, or mid-word: the frame is flagged and the model decides (an ADIS part
 *     answers garbage and drops the command).
 * The model learns every violation of the current frame through the `flags` arguments
 * (bit SIM_SPI_FLAG(kind)).
 */
#ifndef INCLINO_SIM_SPI_SLAVE_H
#define INCLINO_SIM_SPI_SLAVE_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/error.h"
#include "inclino/sim/clock.h"
#include "inclino/sim/pinbus.h"
#include "inclino/sim/violation.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SIM_SPI_MODE_AUTO_0_3 4u /* sense CPOL at CS fall; CPHA = CPOL (modes 0 and 3) */
#define SIM_SPI_FLAG(kind) (1u << (unsigned)(kind))

struct sim_spi_timing {
    uint32_t min_period_ns;   /* between consecutive sampling edges: 1e9 / max SCLK */
    uint32_t min_half_ns;     /* shortest SCLK high or low time (0: not checked) */
    uint32_t min_cs_setup_ns; /* CS fall -> first SCLK edge */
    uint32_t min_cs_hold_ns;  /* last SCLK edge -> CS rise */
    uint32_t min_stall_ns;    /* CS rise -> next CS fall */
    uint32_t mosi_setup_ns;   /* MOSI stable before a sampling edge (0: not checked) */
    uint32_t miso_delay_ns;   /* MISO valid after the shifting edge or CS fall (tDAV) */
};

struct sim_spi_slave_ops {
    /* CS fell. Return the first word to shift out. flags: violations seen at CS fall. */
    uint16_t (*frame_begin)(void *model, unsigned flags, uint64_t t_ns);
    /*
     * A whole word arrived (index = its position in the CS frame). Return the next word to shift
     * out in the same CS frame. flags: violations seen in this frame so far.
     */
    uint16_t (*word)(void *model, uint16_t mosi, unsigned index, unsigned flags, uint64_t t_ns);
    /* CS rose after `words` whole words. flags: every violation seen in the frame. */
    void (*frame_end)(void *model, unsigned words, unsigned flags, uint64_t t_ns);
};

struct sim_spi_slave_cfg {
    const char *name; /* part name for violation reports */
    struct sim_pinbus *bus;
    unsigned cs, sclk, mosi, miso; /* pin numbers on the bus */
    uint8_t mode;                  /* 0..3 or SIM_SPI_MODE_AUTO_0_3 */
    uint8_t bits;                  /* 8 or 16 */
    struct sim_spi_timing timing;
    const struct sim_spi_slave_ops *ops;
    void *model;
    struct sim_violation_log *log; /* where violations go (may be NULL) */
};

#define SIM_SPI_MISO_QUEUE 8u

/* Wire faults (sim/part.h); zero (the state after init) is a healthy slave. */
enum sim_spi_miso_fault {
    SIM_SPI_MISO_OK = 0,
    SIM_SPI_MISO_STUCK_LOW = 1,  /* MISO driven low whenever the part drives it */
    SIM_SPI_MISO_STUCK_HIGH = 2, /* MISO driven high whenever the part drives it */
};

struct sim_spi_slave {
    struct sim_spi_slave_cfg cfg;
    struct sim_pin_listener listener;
    unsigned dev; /* device id on the pin bus */
    bool selected;
    bool ever_selected;
    uint8_t cpol, cpha; /* mode of the current frame */
    uint8_t bits_in;    /* bits received of the current word */
    uint8_t out_bit;    /* next bit index of `out` to drive */
    uint16_t in;        /* shift-in register */
    uint16_t out;       /* word being shifted out */
    unsigned words;     /* whole words this frame */
    unsigned flags;     /* violations this frame */
    bool edge_seen;     /* an SCLK edge occurred in this frame */
    bool mosi_prev;     /* MOSI level before its last change */
    uint64_t t_cs_fall, t_cs_rise, t_last_edge, t_last_sample, t_mosi_change;
    uint32_t frame_min_period_ns; /* shortest sampling-edge interval seen in this CS frame
                                     (UINT32_MAX before the second sampling edge); lets a model
                                     check a limit that depends on the command, e.g. burst */
    /* MISO changes waiting for their tDAV, in order. */
    struct {
        int handle;
        bool level;
    } q[SIM_SPI_MISO_QUEUE];
    unsigned q_head, q_len;
    /* injected faults: MISO stuck (enum sim_spi_miso_fault), XOR of every word shifted out */
    uint8_t miso_stuck;
    uint16_t out_xor;
    /* statistics */
    uint32_t frames, total_words;
};

int sim_spi_slave_init(struct sim_spi_slave *s, const struct sim_spi_slave_cfg *cfg);
/* Change the limits (a part's maximum SCLK depends on its mode: normal, burst, low power). */
int sim_spi_slave_set_timing(struct sim_spi_slave *s, const struct sim_spi_timing *t);
/* Disconnect from the bus (listener removed, MISO released). */
void sim_spi_slave_detach(struct sim_spi_slave *s);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_SIM_SPI_SLAVE_H */
