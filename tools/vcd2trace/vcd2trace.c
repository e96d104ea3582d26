/*
 * vcd2trace - turn a logic-analyser capture (VCD, as PulseView/sigrok or GTKWave export it) of a
 * real board's SPI bus into an Inclino register trace that the replay HAL serves to a driver.
 *
 *   vcd2trace [--sclk NAME] [--mosi NAME] [--miso NAME] [--cs NAME] [--mode 0..3]
 *             [--bits 8|16] [--cs-pin N] IN.vcd OUT.trace
 *
 * Numbers are decimal and range-checked (tools/lib/cli): --cs-pin 0..65534, the trace format's
 * range. OUT is written to a temporary file and renamed at the end; it may not be IN (same file),
 * a FIFO, a symlink or a device; "-" writes the trace to stdout (before the summary line).
 *
 * Defaults: wires sclk/mosi/miso/cs0, mode 3, 16-bit, cs pin 3 (the simulated board's cs0).
 * See docs/traces.md. Exit status 0, 1 on a conversion error (message on stderr), 2 on usage.
 * The last line on stdout is the summary (docs/tool-summary.md): frames=<CS periods> or
 * error=<inc_err name | usage>.
 */
#include "inclino/sim/trace.h"
#include "inclino/tool_cli.h"
#include "inclino/tool_summary.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int main(int argc, char **argv)
{
    struct trace_vcd_opts o = {"sclk", "mosi", "miso", "cs0", 3, 16, 3};
    const char *in = NULL, *outp = NULL;
    const char *inputs[1];
    char msg[200] = "";
    struct cli_out out;
    FILE *fi;
    int a, n, rc = INC_OK;
    tool_summary_begin("vcd2trace");
    cli_set_program("vcd2trace");
    for (a = 1; a < argc && rc == INC_OK; a++) {
        const char *opt = argv[a];
        if (strcmp(opt, "--sclk") == 0 || strcmp(opt, "--mosi") == 0 ||
            strcmp(opt, "--miso") == 0 || strcmp(opt, "--cs") == 0 || strcmp(opt, "--mode") == 0 ||
            strcmp(opt, "--bits") == 0 || strcmp(opt, "--cs-pin") == 0) {
            const char *v = cli_value(argc, argv, &a);
            if (v == NULL) {
                rc = INC_ERR_INVAL;
            } else if (strcmp(opt, "--sclk") == 0) {
                o.sclk = v;
            } else if (strcmp(opt, "--mosi") == 0) {
                o.mosi = v;
            } else if (strcmp(opt, "--miso") == 0) {
                o.miso = v;
            } else if (strcmp(opt, "--cs") == 0) {
                o.cs = v;
            } else if (strcmp(opt, "--mode") == 0) {
                rc = cli_parse_u32(opt, v, 0, 3, &o.mode);
            } else if (strcmp(opt, "--bits") == 0) {
                rc = cli_parse_u32(opt, v, 8, 16, &o.bits);
                if (rc == INC_OK && o.bits != 8u && o.bits != 16u) {
                    cli_error("--bits: '%s' is out of range (accepted: 8 or 16)", v);
                    rc = INC_ERR_RANGE;
                }
            } else {
                rc = cli_parse_u32(opt, v, 0, TRACE_PIN_MAX, &o.cs_pin);
            }
        } else if (opt[0] == '-' && opt[1] != '\0') {
            cli_error("unknown option %s", opt);
            rc = INC_ERR_INVAL;
        } else if (in == NULL) {
            in = opt;
        } else if (outp == NULL) {
            outp = opt;
        } else {
            cli_error("too many arguments (%s)", opt);
            rc = INC_ERR_INVAL;
        }
    }
    if (rc != INC_OK || in == NULL || outp == NULL) {
        fprintf(stderr,
                "usage: vcd2trace [--sclk N] [--mosi N] [--miso N] [--cs N] [--mode 0..3] "
                "[--bits 8|16] [--cs-pin 0..%u] IN.vcd OUT.trace|-\n",
                TRACE_PIN_MAX);
        return tool_summary_error("usage", 2);
    }
    fi = strcmp(in, "-") == 0 ? stdin : fopen(in, "r");
    if (fi == NULL) {
        fprintf(stderr, "vcd2trace: cannot read %s\n", in);
        return tool_summary_error(inc_err_name(INC_ERR_IO), 1);
    }
    inputs[0] = in;
    /* The output never replaces the input, a FIFO, a symlink or a device (tools/lib/cli). */
    if (cli_out_open(&out, "OUT", outp, inputs, 1) != INC_OK) {
        if (fi != stdin) fclose(fi);
        return tool_summary_error(inc_err_name(INC_ERR_IO), 1);
    }
    n = trace_from_vcd(fi, out.f, &o, msg, sizeof(msg));
    if (fi != stdin) fclose(fi);
    if (n < 0) {
        cli_out_discard(&out);
        fprintf(stderr, "vcd2trace: %s (%s)\n", msg[0] ? msg : "conversion failed",
                inc_err_name(n));
        return tool_summary_error(inc_err_name(n), 1);
    }
    if (cli_out_close(&out) != INC_OK) {
        return tool_summary_error(inc_err_name(INC_ERR_IO), 1);
    }
    if (strcmp(outp, "-") != 0) printf("%d CS periods written to %s\n", n, outp);
    tool_summary_add("frames", "%d", n);
    tool_summary_add("mode", "%u", o.mode);
    tool_summary_add("bits", "%u", o.bits);
    return tool_summary_end("ok", 0);
}
