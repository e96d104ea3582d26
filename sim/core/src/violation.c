/* violation.c - see sim/violation.h. */
#include "inclino/sim/violation.h"

#include <string.h>

void sim_violation_log_init(struct sim_violation_log *log)
{
    if (log != NULL) {
        memset(log, 0, sizeof(*log));
    }
}

void sim_violation_report(struct sim_violation_log *log, enum sim_violation_kind kind,
                          const char *source, uint64_t t_ns, uint32_t measured_ns,
                          uint32_t limit_ns)
{
    if (log == NULL || (unsigned)kind >= SIM_VIOL_KIND_COUNT) {
        return;
    }
    log->total++;
    log->per_kind[kind]++;
    if (log->stored < SIM_VIOLATION_LOG_MAX) {
        struct sim_violation *v = &log->v[log->stored++];
        v->t_ns = t_ns;
        v->kind = kind;
        v->source = source != NULL ? source : "?";
        v->measured_ns = measured_ns;
        v->limit_ns = limit_ns;
    }
}

unsigned sim_violation_count(const struct sim_violation_log *log, enum sim_violation_kind kind)
{
    if (log == NULL || (unsigned)kind >= SIM_VIOL_KIND_COUNT) {
        return 0;
    }
    return log->per_kind[kind];
}

const char *sim_violation_kind_name(enum sim_violation_kind kind)
{
    static const char *const names[SIM_VIOL_KIND_COUNT] = {
        "sclk-too-fast",   "cs-setup",     "cs-hold",    "stall", "mosi-setup",
        "sclk-idle-level", "partial-word", "contention", "busy",  "protocol",
    };
    return (unsigned)kind < SIM_VIOL_KIND_COUNT ? names[kind] : "unknown";
}

int sim_violation_format(const struct sim_violation *v, char *buf, size_t len)
{
    if (v == NULL || buf == NULL) {
        return -1;
    }
    if (v->limit_ns != 0 || v->measured_ns != 0) {
        return snprintf(buf, len, "t=%llu ns %s: %s measured %lu ns, required %lu ns",
                        (unsigned long long)v->t_ns, sim_violation_kind_name(v->kind), v->source,
                        (unsigned long)v->measured_ns, (unsigned long)v->limit_ns);
    }
    return snprintf(buf, len, "t=%llu ns %s: %s", (unsigned long long)v->t_ns,
                    sim_violation_kind_name(v->kind), v->source);
}

void sim_violation_log_print(const struct sim_violation_log *log, FILE *out)
{
    unsigned i;
    char line[160];
    if (log == NULL || out == NULL) {
        return;
    }
    for (i = 0; i < log->stored; i++) {
        sim_violation_format(&log->v[i], line, sizeof(line));
        fprintf(out, "violation: %s\n", line);
    }
    if (log->total > log->stored) {
        fprintf(out, "violation: ... %u more not stored\n", log->total - log->stored);
    }
}
