/*
 * sim/trace.h - register-traffic record and replay.
 *
 * Record: struct trace_rec wraps a struct spi_bus (and the HAL) that a driver uses and writes
 * every chip-select period it sees - time, CS pin, frame size, MOSI words, MISO words - and
 * every data-ready interrupt to a text trace (format: docs/traces.md).
 *
 * Replay: struct trace_replay is a bus and a HAL made of a trace. It answers each CS period with
 * the recorded MISO words, checks that the driver sends the recorded MOSI words (and CS pin,
 * frame size, number of words per CS period), fires the recorded interrupts when the driver
 * waits for one, and advances virtual time as the driver delays. At the first divergence it
 * fails - that transfer and every later one return INC_ERR_MISMATCH - and keeps a message with
 * the frame index, the trace line and the expected and actual words.
 *
 * The unit of a trace is one CS period, as a logic analyser sees it: a transfer with CS toggled
 * between n frames is n records of one word; with CS held it is one record of n words.
 */
#ifndef INCLINO_SIM_TRACE_H
#define INCLINO_SIM_TRACE_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

#include "inclino/hal.h"
#include "inclino/spi.h"

#ifdef __cplusplus
extern "C" {
#endif

#define TRACE_MAX_WORDS SPI_MAX_FRAMES /* words in one CS period */
#define TRACE_MAX_IRQS 8u
#define TRACE_MSG_LEN 200u
#define TRACE_LINE_MAX 4095u  /* characters in one line of a trace, before its newline */
#define TRACE_PIN_MAX 0xFFFEu /* largest cs= / pin= a trace holds (0xFFFF is no pin) */

struct trace_rec;

struct trace_rec_irq {
    struct trace_rec *rec;
    hal_pin_t pin;
    hal_irq_cb cb;
    void *arg;
};

struct trace_rec {
    struct spi_bus bus; /* give &rec.bus to spi_dev_init */
    struct hal hal;     /* give &rec.hal to the driver (records interrupts) */
    const struct spi_bus *inner;
    const struct hal *inner_hal;
    FILE *f;
    bool io_error;
    struct trace_rec_irq irq[TRACE_MAX_IRQS];
    uint32_t periods, words, irqs; /* statistics */
};

/*
 * Start recording to path (overwritten) the traffic that passes through rec->bus to inner and
 * the interrupts attached through rec->hal to inner_hal. Returns 0, INC_ERR_NULL or INC_ERR_IO.
 */
int trace_rec_open(struct trace_rec *rec, const char *path, const struct spi_bus *inner,
                   const struct hal *inner_hal);
/* Write a comment line ("# text") into the trace, e.g. what the following traffic is. */
int trace_rec_comment(struct trace_rec *rec, const char *text);
/* Flush and close. Returns 0 or INC_ERR_IO (any write failed). */
int trace_rec_close(struct trace_rec *rec);

/* One record of a trace. */
enum trace_kind {
    TRACE_PERIOD = 1, /* a CS period */
    TRACE_IRQ = 2,    /* an interrupt callback ran */
};

struct trace_record {
    enum trace_kind kind;
    uint64_t t_ns;
    unsigned pin;  /* CS pin (period) or interrupt pin */
    unsigned bits; /* period: 8 or 16 */
    unsigned n;    /* period: words */
    unsigned line; /* line in the file */
    uint16_t mosi[TRACE_MAX_WORDS];
    uint16_t miso[TRACE_MAX_WORDS];
};

/*
 * Read the next record from f (skipping blank and comment lines; *line counts lines).
 * Returns 1 with *r filled, 0 at the end of the file, or INC_ERR_FORMAT with a message in msg
 * (naming the line) for a malformed line: a field that is missing, not separated by blanks, out
 * of range or beyond 64 bits, a word that is not 1..4 hex digits, a NUL byte, more than
 * TRACE_LINE_MAX characters. INC_ERR_IO on a read error.
 */
int trace_parse_next(FILE *f, unsigned *line, struct trace_record *r, char *msg, size_t msg_len);

/* Write one record in the trace format. Returns 0 or INC_ERR_IO. */
int trace_write_record(FILE *f, const struct trace_record *r);

struct trace_replay_irq {
    hal_pin_t pin;
    hal_irq_cb cb;
    void *arg;
};

struct trace_replay {
    struct spi_bus bus; /* give &rp.bus to spi_dev_init */
    struct hal hal;     /* give &rp.hal to the driver */
    FILE *f;
    unsigned line;
    struct trace_record next; /* the record the driver must produce next */
    bool have_next;
    uint64_t now_ns;
    uint32_t crit_depth;
    uint32_t fired;
    uint32_t frame;   /* words consumed so far (the frame index of messages) */
    uint32_t periods; /* records consumed */
    int status;       /* INC_OK, or the first error (sticky) */
    char msg[TRACE_MSG_LEN];
    struct trace_replay_irq irq[TRACE_MAX_IRQS];
};

/* Open a trace for replay. Returns 0, INC_ERR_NULL, INC_ERR_IO or INC_ERR_FORMAT. */
int trace_replay_open(struct trace_replay *rp, const char *path);
/*
 * End the replay: 0 when no divergence happened and every record was consumed; otherwise the
 * sticky error (INC_ERR_MISMATCH, INC_ERR_FORMAT) and the message. Closes the file.
 */
int trace_replay_finish(struct trace_replay *rp);
/* The first divergence or error, "" when none. */
const char *trace_replay_message(const struct trace_replay *rp);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_SIM_TRACE_H */

#ifndef INCLINO_SIM_TRACE_VCD_H
#define INCLINO_SIM_TRACE_VCD_H
#ifdef __cplusplus
extern "C" {
#endif
/*
 * Convert a logic-analyser capture in VCD form (PulseView/sigrok, GTKWave, or sim/vcd.h) into a
 * trace: SPI is decoded from the named wires in the given mode and word size, one F record per
 * CS period (time = the CS falling edge; a timescale other than 1 ns is scaled). A period still
 * open when the capture ends (CS low at the end of the file) is written like any other. Periods
 * ending in a partial word - CS rising, or the capture ending, mid-word - are an error naming the
 * time. Returns the number of records written, or INC_ERR_INVAL (mode, bits, or cs_pin above
 * TRACE_PIN_MAX, which the trace reader would refuse), INC_ERR_FORMAT with a message (VCD
 * structure, missing wire) / INC_ERR_IO (a read or write error).
 */
struct trace_vcd_opts {
    const char *sclk, *mosi, *miso, *cs; /* wire names in the VCD */
    unsigned mode;                       /* 0..3 */
    unsigned bits;                       /* 8 or 16 */
    unsigned cs_pin;                     /* the cs= number to write (the driver's CS pin) */
};
int trace_from_vcd(FILE *vcd, FILE *out, const struct trace_vcd_opts *o, char *msg, size_t msg_len);
#ifdef __cplusplus
}
#endif
#endif
