/* lf_trace.c - libFuzzer target: the register-trace reader (sim/trace, trace_parse_next).
 * Properties: every record returned is in the format's ranges (bits 8/16, 1..TRACE_MAX_WORDS
 * words for a period, pin <= TRACE_PIN_MAX), and written back with trace_write_record it reads
 * back as the same record. */
#include "inclino/sim/trace.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static struct trace_record r, back;

static void check_round_trip(void)
{
    char buf[16384];
    char msg[TRACE_MSG_LEN];
    unsigned line = 0;
    FILE *f = fmemopen(buf, sizeof buf, "w");
    int got;
    if (f == NULL) return;
    if (trace_write_record(f, &r) != INC_OK) abort();
    fclose(f);
    f = fmemopen(buf, strlen(buf), "r");
    if (f == NULL) return;
    got = trace_parse_next(f, &line, &back, msg, sizeof msg);
    fclose(f);
    if (got != 1 || back.kind != r.kind || back.t_ns != r.t_ns || back.pin != r.pin) abort();
    if (r.kind == TRACE_PERIOD && (back.bits != r.bits || back.n != r.n ||
                                   memcmp(back.mosi, r.mosi, r.n * sizeof r.mosi[0]) != 0 ||
                                   memcmp(back.miso, r.miso, r.n * sizeof r.miso[0]) != 0)) {
        abort();
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char msg[TRACE_MSG_LEN];
    unsigned line = 0;
    FILE *f;
    int got, records = 0;
    if (size == 0) return 0;
    f = fmemopen((void *)data, size, "r");
    if (f == NULL) return 0;
    while ((got = trace_parse_next(f, &line, &r, msg, sizeof msg)) == 1 && records < 10000) {
        if (r.pin > TRACE_PIN_MAX) abort();
        if (r.kind == TRACE_PERIOD &&
            ((r.bits != 8u && r.bits != 16u) || r.n < 1u || r.n > TRACE_MAX_WORDS)) {
            abort();
        }
        if (r.kind != TRACE_PERIOD && r.kind != TRACE_IRQ) abort();
        check_round_trip();
        records++;
    }
    if (got < 0 && msg[0] == '\0') abort(); /* every refusal says why */
    fclose(f);
    return 0;
}
