/*
 * vcd2trace - turn a logic-analyser capture (VCD, as PulseView/sigrok or GTKWave export it) of a
 * real board's SPI bus into an Inclino register trace that the replay HAL serves to a driver.
 *
 *   vcd2trace [--sclk NAME] [--mosi NAME] [--miso NAME] [--cs NAME] [--mode 0..3]
 *             [--bits 8|16] [--cs-pin N] IN.vcd OUT.trace
 *
 * Defaults: wires sclk/mosi/miso/cs0, mode 3, 16-bit, cs pin 3 (the simulated board's cs0).
 * See docs/traces.md. Exit status 0, 1 on a conversion error (message on stderr), 2 on usage.
 * The last line on stdout is the summary (docs/tool-summary.md): frames=<CS periods> or
 * error=<inc_err name | usage>.
 */
#include "inclino/sim/trace.h"
#include "inclino/tool_summary.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int main(int argc, char **argv)
{
    struct trace_vcd_opts o = {"sclk", "mosi", "miso", "cs0", 3, 16, 3};
    const char *in = NULL, *outp = NULL;
    char msg[200] = "";
    FILE *fi, *fo;
    int a, n;
    tool_summary_begin("vcd2trace");
    for (a = 1; a < argc; a++) {
        const char *v = a + 1 < argc ? argv[a + 1] : NULL;
        if (strcmp(argv[a], "--sclk") == 0 && v) {
            o.sclk = v;
            a++;
        } else if (strcmp(argv[a], "--mosi") == 0 && v) {
            o.mosi = v;
            a++;
        } else if (strcmp(argv[a], "--miso") == 0 && v) {
            o.miso = v;
            a++;
        } else if (strcmp(argv[a], "--cs") == 0 && v) {
            o.cs = v;
            a++;
        } else if (strcmp(argv[a], "--mode") == 0 && v) {
            o.mode = (unsigned)atoi(v);
            a++;
        } else if (strcmp(argv[a], "--bits") == 0 && v) {
            o.bits = (unsigned)atoi(v);
            a++;
        } else if (strcmp(argv[a], "--cs-pin") == 0 && v) {
            o.cs_pin = (unsigned)atoi(v);
            a++;
        } else if (argv[a][0] == '-') {
            in = NULL;
            break;
        } else if (in == NULL)
            in = argv[a];
        else if (outp == NULL)
            outp = argv[a];
        else {
            in = NULL;
            break;
        }
    }
    if (in == NULL || outp == NULL) {
        fprintf(stderr, "usage: vcd2trace [--sclk N] [--mosi N] [--miso N] [--cs N] [--mode 0..3] "
                        "[--bits 8|16] [--cs-pin N] IN.vcd OUT.trace\n");
        return tool_summary_error("usage", 2);
    }
    fi = fopen(in, "r");
    if (fi == NULL) {
        fprintf(stderr, "vcd2trace: cannot read %s\n", in);
        return tool_summary_error(inc_err_name(INC_ERR_IO), 1);
    }
    fo = fopen(outp, "w");
    if (fo == NULL) {
        fclose(fi);
        fprintf(stderr, "vcd2trace: cannot write %s\n", outp);
        return tool_summary_error(inc_err_name(INC_ERR_IO), 1);
    }
    n = trace_from_vcd(fi, fo, &o, msg, sizeof(msg));
    fclose(fi);
    if (fclose(fo) != 0 && n >= 0) {
        n = INC_ERR_IO;
    }
    if (n < 0) {
        fprintf(stderr, "vcd2trace: %s (%s)\n", msg[0] ? msg : "conversion failed",
                inc_err_name(n));
        return tool_summary_error(inc_err_name(n), 1);
    }
    printf("%d CS periods written to %s\n", n, outp);
    tool_summary_add("frames", "%d", n);
    tool_summary_add("mode", "%u", o.mode);
    tool_summary_add("bits", "%u", o.bits);
    return tool_summary_end("ok", 0);
}
