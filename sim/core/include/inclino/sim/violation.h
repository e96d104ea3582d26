/*
 * sim/violation.h - the record of every timing or protocol rule a simulated part saw broken.
 *
 * Device models and the SPI-slave framework report here; tests read the counts per kind and
 * print the entries. A fixed number of entries is kept (the first SIM_VIOLATION_LOG_MAX); the
 * counters keep counting after that.
 */
#ifndef INCLINO_SIM_VIOLATION_H
#define INCLINO_SIM_VIOLATION_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

enum sim_violation_kind {
    SIM_VIOL_SCLK_FAST = 0, /* SCLK period (or a half period) shorter than the part allows */
    SIM_VIOL_CS_SETUP,      /* first SCLK edge too soon after CS fell */
    SIM_VIOL_CS_HOLD,       /* CS rose too soon after the last SCLK edge */
    SIM_VIOL_STALL,         /* CS fell too soon after it last rose (tSTALL) */
    SIM_VIOL_MOSI_SETUP,    /* MOSI changed too close before a sampling edge */
    SIM_VIOL_SCLK_IDLE,     /* SCLK not at the mode's idle level when CS fell */
    SIM_VIOL_PARTIAL_WORD,  /* CS rose in the middle of a word */
    SIM_VIOL_CONTENTION,    /* two drivers on one pin disagree */
    SIM_VIOL_BUSY,          /* the part was addressed while busy with a command */
    SIM_VIOL_PROTOCOL,      /* model-specific protocol error (bad command, frame length) */
    SIM_VIOL_KIND_COUNT
};

struct sim_violation {
    uint64_t t_ns;
    enum sim_violation_kind kind;
    const char *source;   /* the part or pin that saw it (static string) */
    uint32_t measured_ns; /* what the master did (0 when not a duration) */
    uint32_t limit_ns;    /* what the part requires (0 when not a duration) */
};

#ifndef SIM_VIOLATION_LOG_MAX
#define SIM_VIOLATION_LOG_MAX 32
#endif

struct sim_violation_log {
    unsigned total;
    unsigned per_kind[SIM_VIOL_KIND_COUNT];
    unsigned stored;
    struct sim_violation v[SIM_VIOLATION_LOG_MAX];
};

void sim_violation_log_init(struct sim_violation_log *log);
void sim_violation_report(struct sim_violation_log *log, enum sim_violation_kind kind,
                          const char *source, uint64_t t_ns, uint32_t measured_ns,
                          uint32_t limit_ns);
unsigned sim_violation_count(const struct sim_violation_log *log, enum sim_violation_kind kind);
const char *sim_violation_kind_name(enum sim_violation_kind kind);
/* "t=1234 ns stall: adis16400 measured 3000 ns < required 9000 ns" into buf (snprintf rules). */
int sim_violation_format(const struct sim_violation *v, char *buf, size_t len);
/* Print every stored entry, one per line, and the totals. */
void sim_violation_log_print(const struct sim_violation_log *log, FILE *out);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_SIM_VIOLATION_H */
