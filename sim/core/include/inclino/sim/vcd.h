/*
 * sim/vcd.h - write the pin waveforms of a run as a Value Change Dump (IEEE 1364 VCD).
 *
 * The file has a 1 ns timescale and one 1-bit wire per selected pin, named after the pin
 * ("sclk", "mosi", "miso", "cs0", ...), so PulseView/sigrok (`sigrok-cli -I vcd`) and GTKWave
 * open it and the SPI decoder can be attached by name. Every resolved-level change of a selected
 * pin is written with its virtual time; the initial levels are dumped at the time the file is
 * opened.
 */
#ifndef INCLINO_SIM_VCD_H
#define INCLINO_SIM_VCD_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

#include "inclino/error.h"
#include "inclino/sim/pinbus.h"

#ifdef __cplusplus
extern "C" {
#endif

struct sim_vcd {
    FILE *f;
    struct sim_pinbus *bus;
    struct sim_pin_listener listener;
    uint32_t mask;
    uint64_t last_t;
    bool time_written;
    bool io_error;
    bool owns_file; /* opened by sim_vcd_open: closed by sim_vcd_close */
    uint64_t changes;
};

/*
 * Open path for writing and start recording the pins in pin_mask (SIM_PIN_MASK bits; undefined
 * pins are skipped). Returns 0, INC_ERR_NULL, INC_ERR_INVAL (empty mask) or INC_ERR_IO.
 */
int sim_vcd_open(struct sim_vcd *v, const char *path, struct sim_pinbus *bus, uint32_t pin_mask);

/* Stop recording, write the final time stamp and close. Returns 0 or INC_ERR_IO (any write, the
 * flush or the close failed). */
int sim_vcd_close(struct sim_vcd *v);

/*
 * The same into a stream the caller owns (a tools/lib/cli safe output): sim_vcd_start writes the
 * header and records; sim_vcd_stop writes the final time stamp and flushes, but does not close
 * the stream. sim_vcd_stop returns 0 or INC_ERR_IO (any write or the flush failed); it is
 * sim_vcd_close for a recording opened with sim_vcd_open.
 */
int sim_vcd_start(struct sim_vcd *v, FILE *f, struct sim_pinbus *bus, uint32_t pin_mask);
int sim_vcd_stop(struct sim_vcd *v);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_SIM_VCD_H */
