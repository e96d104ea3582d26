/*
 * s32k_flexcan_model.h - register-level model of one S32K1 FlexCAN instance on the simulated bus
 * (module inclino_sim_s32k1_flexcan, prefix s32k_flexcan_model_). docs/can.md.
 *
 * What it models (what the driver hal/port/s32k1/flexcan uses, as the reference manual
 * describes it):
 *   - MCR: MDIS -> LPMACK; FRZ and HALT -> FRZACK (only while enabled); NOTRDY while disabled or
 *     frozen; SOFTRST clears itself and resets MCR's configuration fields (MDIS kept); the reset
 *     value 0xD890000F (disabled, frozen, MAXMB 15);
 *   - CTRL1 (only written while frozen or disabled, CLKSRC only while disabled: other writes are
 *     refused and counted in stats.config_violations), RXMGMASK, IMASK1, IFLAG1 (write 1 to
 *     clear), TIMER (the bit-time counter at 500 kbit/s, 16 bits), ECR (TEC 7:0, REC 15:8), ESR1
 *     (FLTCONF from the error counters, ACKERR and the other error bits clear when read);
 *   - message buffers (n_mb x 16 bytes from 0x80): a C/S write with CODE DATA while running
 *     transmits the buffer: one line of the candump log, CODE back to INACTIVE, the IFLAG bit
 *     set. A buffer activated while frozen is sent when the freeze ends. Rx buffers (CODE EMPTY)
 *     take injected frames whose ID matches under RXMGMASK: FULL, or OVERRUN when still FULL.
 * Time: the model has a simulated clock (set_time_ns, set by the harness). A frame takes its
 * length in bits at 500 kbit/s (44 + 8 * DLC bits of a standard data frame plus 3 of interframe
 * space, no stuff bits); frames are serialised on the bus, and the log's timestamp is the end of
 * the frame.
 * Errors injected: no acknowledge (every transmission attempt fails: ACKERR, TEC + 8 per attempt,
 * error passive at TEC >= 128 as in ISO 11898-1; the buffer stays pending), bus off (FLTCONF 1x,
 * nothing is sent or received until cleared).
 *
 * The log: one line per frame on the bus (transmitted by the driver, or injected: the bus carries
 * it whether a buffer takes it or not), `(SSSSSSSSSS.UUUUUU) IFACE III#DDDDDDDDDDDDDDDD`
 * (candump -l), ID in 3 hex digits, data in 2 hex digits per byte (uppercase).
 */
#ifndef INCLINO_SIM_S32K_FLEXCAN_MODEL_H
#define INCLINO_SIM_S32K_FLEXCAN_MODEL_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

#include "inclino/error.h"

#ifdef __cplusplus
extern "C" {
#endif

#define S32K_FLEXCAN_MODEL_MAX_MB 32u

struct s32k_flexcan_model_stats {
    uint32_t tx_frames;         /* frames that left (and were logged) */
    uint32_t tx_failed;         /* transmission attempts without acknowledge */
    uint32_t rx_frames;         /* injected frames that a buffer took */
    uint32_t rx_dropped;        /* injected frames no buffer took (or bus off) */
    uint32_t rx_overruns;       /* frames that overwrote an unread one */
    uint32_t config_violations; /* writes the hardware would refuse (see above) */
};

struct s32k_flexcan_model {
    uint32_t base;
    unsigned n_mb;
    uint32_t mcr, ctrl1, rxmgmask, imask1, iflag1, esr1_sticky;
    uint32_t ram[S32K_FLEXCAN_MODEL_MAX_MB * 4u];
    uint32_t tec, rec;
    bool no_ack, bus_off;
    uint64_t now_ns, bus_free_ns;
    FILE *log;
    uint64_t log_epoch_s; /* added to the log's seconds (0 after init; a harness sets a fixed
                             wall-clock epoch, as candump writes, so that tools like log2asc
                             that treat second 0 as "no time yet" read the log) */
    char iface[16];
    struct s32k_flexcan_model_stats stats;
};

/*
 * Reset the model (registers at their reset values) and map it at base (n_mb buffers, 1..32)
 * on the simulated bus. log may be NULL (no log); iface is the interface name written in the
 * log ("can0"). 0, INC_ERR_NULL, INC_ERR_INVAL, or s32k_bus_map's error.
 */
int s32k_flexcan_model_init(struct s32k_flexcan_model *m, uint32_t base, unsigned n_mb, FILE *log,
                            const char *iface);

/* The simulated time; pending buffers whose frame would have ended by then are sent. */
void s32k_flexcan_model_set_time_ns(struct s32k_flexcan_model *m, uint64_t t_ns);

/* A frame from another node (id <= 0x7FF, dlc <= 8). 0: taken by an Rx buffer; INC_ERR_BUSY: no
 * buffer took it (dropped, counted); INC_ERR_BUS: the node is bus off; INC_ERR_NULL,
 * INC_ERR_INVAL. */
int s32k_flexcan_model_inject(struct s32k_flexcan_model *m, uint16_t id, const uint8_t *data,
                              uint8_t dlc);

/* Error injection: no node acknowledges (true) / acknowledges again (false). */
void s32k_flexcan_model_set_no_ack(struct s32k_flexcan_model *m, bool on);
/* Bus off (true: FLTCONF 1x); false: recovered, error counters 0. */
void s32k_flexcan_model_set_bus_off(struct s32k_flexcan_model *m, bool on);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_SIM_S32K_FLEXCAN_MODEL_H */
