/* lf_vcd.c - libFuzzer target: the VCD to trace converter (sim/trace, trace_from_vcd). The
 * first byte chooses mode (0..3), word size (8/16) and the cs pin; the rest is the capture.
 * Property: whatever the converter writes, the trace reader accepts - every record, as many as
 * the converter counted (a cs pin of 70000 once gave a trace the reader refused). */
#include "inclino/sim/trace.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static char out_buf[1 << 20];
static struct trace_record r;

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const unsigned pins[4] = {0u, 3u, 255u, TRACE_PIN_MAX};
    struct trace_vcd_opts o = {"sclk", "mosi", "miso", "cs0", 3, 16, 3};
    char msg[TRACE_MSG_LEN] = "";
    unsigned line = 0;
    FILE *in, *out;
    int n, got, records = 0;
    long written;
    if (size < 1) return 0;
    o.mode = data[0] & 3u;
    o.bits = (data[0] & 4u) ? 8u : 16u;
    o.cs_pin = pins[(data[0] >> 3) & 3u];
    in = fmemopen((void *)(data + 1), size - 1u > 0u ? size - 1u : 1u, "r");
    out = fmemopen(out_buf, sizeof out_buf, "w");
    if (in == NULL || out == NULL) {
        if (in != NULL) fclose(in);
        if (out != NULL) fclose(out);
        return 0;
    }
    n = trace_from_vcd(in, out, &o, msg, sizeof msg);
    written = ftell(out);
    fclose(in);
    fclose(out);
    if (n < 0) {
        if (n != INC_ERR_FORMAT && n != INC_ERR_IO) abort();
        return 0;
    }
    if (written <= 0 || (size_t)written >= sizeof out_buf) return 0; /* full buffer: cut */
    in = fmemopen(out_buf, (size_t)written, "r");
    if (in == NULL) return 0;
    while ((got = trace_parse_next(in, &line, &r, msg, sizeof msg)) == 1) {
        if (r.kind != TRACE_PERIOD || r.pin != o.cs_pin || r.bits != o.bits) abort();
        records++;
    }
    fclose(in);
    if (got != 0 || records != n) abort(); /* the reader refused what the converter wrote */
    return 0;
}
