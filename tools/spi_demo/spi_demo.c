/*
 * spi_demo - the project's main job until the EPB demo exists: one simulated SPI exchange with
 * a loopback part on the simulated board, printed word by word with its bus time, any timing
 * violation the part saw, and optionally the waveforms as a VCD.
 *
 *   spi_demo [--vcd FILE] [--mode 0..3] [--bits 8|16] [--sclk-hz HZ] [--stall-ns NS]
 *            [--hold] [WORD ...]          (hex words; default 3E00 5600 0000 1234 BEEF)
 *
 * Exit status: 0 when the words came back as sent and no violation was seen, 1 otherwise,
 * 2 for bad arguments.
 */
#include "inclino/sim/board.h"
#include "inclino/sim/loopback.h"
#include "inclino/sim/vcd.h"
#include "inclino/spi.h"
#include "inclino/tool_cli.h"
#include "inclino/tool_summary.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_WORDS 64

static int usage(void)
{
    fprintf(stderr, "usage: spi_demo [--vcd FILE] [--mode 0..3] [--bits 8|16] [--sclk-hz HZ]\n"
                    "                [--stall-ns NS] [--hold] [HEXWORD ...]\n");
    return tool_summary_error("usage", 2);
}

/* A decimal option through tools/lib/cli (the whole field, min..max; the message names it). */
static int parse_ul(const char *opt, const char *s, unsigned long min, unsigned long max,
                    unsigned long *out)
{
    uint64_t v;
    if (s == NULL) {
        cli_error("%s needs a value", opt);
        return -1;
    }
    if (cli_parse_u64(opt, s, min, max, &v) != INC_OK) return -1;
    *out = (unsigned long)v;
    return 0;
}

/* A word: 1..4 (16-bit) or 1..2 (8-bit) hex digits and nothing else (no "0x", no sign, no
 * blanks; strtoul took all of those). */
static int parse_word(const char *s, unsigned long bits, unsigned long *out)
{
    const size_t max_digits = bits == 16 ? 4u : 2u;
    unsigned long v = 0;
    size_t k, n = strlen(s);
    int ok = n >= 1u && n <= max_digits;
    for (k = 0; ok && k < n; k++) {
        const char c = s[k];
        if (c >= '0' && c <= '9')
            v = v * 16u + (unsigned)(c - '0');
        else if (c >= 'a' && c <= 'f')
            v = v * 16u + (unsigned)(c - 'a' + 10);
        else if (c >= 'A' && c <= 'F')
            v = v * 16u + (unsigned)(c - 'A' + 10);
        else
            ok = 0;
    }
    if (!ok) {
        cli_error("word '%s' is not 1..%zu hex digits (a %lu-bit frame)", s, max_digits, bits);
        return -1;
    }
    *out = v;
    return 0;
}

int main(int argc, char **argv)
{
    static struct sim_board board;
    static struct sim_loopback part;
    static struct sim_vcd vcd;
    struct sim_loopback_cfg lc;
    struct spi_dev dev;
    struct spi_dev_cfg dc;
    uint16_t tx[MAX_WORDS], rx[MAX_WORDS];
    const char *words[MAX_WORDS];
    static struct cli_out vcd_out;
    size_t n = 0, i;
    const char *vcd_path = NULL;
    unsigned long mode = 3, bits = 16, hz = 2000000, stall = 9000, v;
    enum spi_cs_policy cs = SPI_CS_TOGGLE;
    uint64_t t0, t1;
    int a, err, bad = 0;
    tool_summary_begin("spi_demo");
    cli_set_program("spi_demo");

    for (a = 1; a < argc; a++) {
        const char *arg = argv[a];
        const char *val = a + 1 < argc ? argv[a + 1] : NULL;
        if (strcmp(arg, "--vcd") == 0 && val != NULL) {
            vcd_path = val;
            a++;
        } else if (strcmp(arg, "--mode") == 0) {
            if (parse_ul(arg, val, 0, 3, &mode) != 0) return usage();
            a++;
        } else if (strcmp(arg, "--bits") == 0) {
            if (parse_ul(arg, val, 8, 16, &bits) != 0) return usage();
            if (bits != 8 && bits != 16) {
                cli_error("--bits: '%s' is out of range (accepted: 8 or 16)", val);
                return usage();
            }
            a++;
        } else if (strcmp(arg, "--sclk-hz") == 0) {
            if (parse_ul(arg, val, 1, 500000000ul, &hz) != 0) return usage();
            a++;
        } else if (strcmp(arg, "--stall-ns") == 0) {
            if (parse_ul(arg, val, 0, 100000000ul, &stall) != 0) return usage();
            a++;
        } else if (strcmp(arg, "--hold") == 0) {
            cs = SPI_CS_HOLD;
        } else if (arg[0] == '-') {
            cli_error("unknown option %s", arg);
            return usage();
        } else {
            if (n == MAX_WORDS) {
                cli_error("more than %d words", MAX_WORDS);
                return usage();
            }
            words[n++] = arg;
        }
    }
    for (i = 0; i < n; i++) { /* after the loop: --bits may come after the words */
        if (parse_word(words[i], bits, &v) != 0) return usage();
        tx[i] = (uint16_t)v;
    }
    if (n == 0) {
        static const uint16_t def[] = {0x3E00, 0x5600, 0x0000, 0x1234, 0xBEEF};
        for (i = 0; i < sizeof(def) / sizeof(def[0]); i++) {
            tx[n++] = (uint16_t)(bits == 16 ? def[i] : def[i] >> 8);
        }
    }

    if (sim_board_init(&board) != 0) {
        fprintf(stderr, "board init failed\n");
        return tool_summary_error("board-init", 1);
    }
    memset(&lc, 0, sizeof(lc));
    lc.name = "loopback";
    lc.bus = &board.bus;
    lc.cs = SIM_BOARD_CS(0);
    lc.sclk = SIM_BOARD_SCLK;
    lc.mosi = SIM_BOARD_MOSI;
    lc.miso = SIM_BOARD_MISO;
    lc.mode = (uint8_t)mode;
    lc.bits = (uint8_t)bits;
    /* The part's limits: an ADIS-like 2 MHz part with a 9 us stall. */
    lc.timing.min_period_ns = 500;
    lc.timing.min_half_ns = 200;
    lc.timing.min_cs_setup_ns = 100;
    lc.timing.min_cs_hold_ns = 100;
    lc.timing.min_stall_ns = 9000;
    lc.timing.mosi_setup_ns = 25;
    lc.timing.miso_delay_ns = 100;
    lc.first = (uint16_t)(bits == 16 ? 0xA5C3 : 0xA5);
    lc.log = &board.log;
    err = sim_loopback_init(&part, &lc);
    if (err == 0) {
        dc.cs = SIM_BOARD_CS(0);
        dc.mode = (uint8_t)mode;
        dc.bits = (uint8_t)bits;
        dc.timing.sclk_period_ns = spi_period_for_hz((uint32_t)hz);
        dc.timing.cs_setup_ns = 100;
        dc.timing.cs_hold_ns = 100;
        dc.timing.stall_ns = (uint32_t)stall;
        dc.timing.gap_ns = 0;
        err = spi_dev_init(&dev, &board.spi.bus, &dc);
    }
    if (err != 0) {
        fprintf(stderr, "setup failed: %s\n", inc_err_name(err));
        return tool_summary_error(inc_err_name(err), 1);
    }
    if (vcd_path != NULL) { /* the safe writer: never a FIFO, symlink or device (tools/lib/cli) */
        if (cli_out_open(&vcd_out, "--vcd", vcd_path, NULL, 0) != INC_OK) {
            return tool_summary_error(inc_err_name(INC_ERR_IO), 1);
        }
        if (sim_vcd_start(&vcd, vcd_out.f, &board.bus, SIM_BOARD_SPI_MASK) != 0) {
            cli_out_discard(&vcd_out);
            fprintf(stderr, "cannot record %s\n", vcd_path);
            return tool_summary_error(inc_err_name(INC_ERR_IO), 1);
        }
    }
    hal_delay_ns(&board.hal, 1000); /* a quiet start in the waveform */
    t0 = hal_now_ns(&board.hal);
    err = spi_transfer(&dev, tx, rx, n, cs);
    t1 = hal_now_ns(&board.hal);
    hal_delay_ns(&board.hal, 1000);
    if (vcd_path != NULL) {
        if (sim_vcd_stop(&vcd) != 0) {
            cli_error("write error on '%s'", vcd_path);
            cli_out_discard(&vcd_out);
            return tool_summary_error(inc_err_name(INC_ERR_IO), 1);
        }
        if (cli_out_close(&vcd_out) != INC_OK)
            return tool_summary_error(inc_err_name(INC_ERR_IO), 1);
    }
    if (err != 0) {
        fprintf(stderr, "transfer failed: %s\n", inc_err_name(err));
        return tool_summary_error(inc_err_name(err), 1);
    }

    printf("Inclino simulated SPI transfer: mode %lu, %lu-bit frames, SCLK %lu Hz (period %lu ns), "
           "CS %s, stall %lu ns\n",
           mode, bits, hz, (unsigned long)dc.timing.sclk_period_ns,
           cs == SPI_CS_HOLD ? "held" : "toggled", stall);
    printf("frame  MOSI   MISO   (the part answers each word with the previous one)\n");
    for (i = 0; i < n; i++) {
        uint16_t expect = i == 0 ? lc.first : tx[i - 1];
        int ok = rx[i] == expect;
        if (!ok) bad = 1;
        printf("%5zu  %0*X  %0*X  %s\n", i, (int)bits / 4, tx[i], (int)bits / 4, rx[i],
               ok ? "ok" : "WRONG");
    }
    printf("bus time: %llu ns for %zu frames (%.1f ns per frame; physical bound %lu ns)\n",
           (unsigned long long)(t1 - t0), n, (double)(t1 - t0) / (double)n,
           (unsigned long)(bits * dc.timing.sclk_period_ns + dc.timing.cs_setup_ns +
                           dc.timing.cs_hold_ns + (cs == SPI_CS_TOGGLE ? stall : 0)));
    printf("timing violations seen by the part: %u\n", board.log.total);
    sim_violation_log_print(&board.log, stdout);
    if (board.log.total != 0) bad = 1;
    if (vcd_path != NULL) {
        printf("waveforms: %s (%llu changes; open in PulseView or GTKWave, decode as SPI "
               "clk=sclk mosi=mosi miso=miso cs=cs0 cpol=%lu cpha=%lu)\n",
               vcd_path, (unsigned long long)vcd.changes, mode >> 1, mode & 1);
    }
    {
        size_t wrong = 0;
        for (i = 0; i < n; i++) {
            if (rx[i] != (i == 0 ? lc.first : tx[i - 1])) wrong++;
        }
        tool_summary_add("mode", "%lu", mode);
        tool_summary_add("bits", "%lu", bits);
        tool_summary_add("sclk_hz", "%lu", hz);
        tool_summary_add("cs", "%s", cs == SPI_CS_HOLD ? "held" : "toggled");
        tool_summary_add("frames", "%zu", n);
        tool_summary_add("wrong", "%zu", wrong);
        tool_summary_add("bus_ns", "%llu", (unsigned long long)(t1 - t0));
        tool_summary_add("violations", "%u", board.log.total);
        if (vcd_path != NULL)
            tool_summary_add("vcd_changes", "%llu", (unsigned long long)vcd.changes);
    }
    return tool_summary_end(bad ? "fail" : "ok", bad);
}
