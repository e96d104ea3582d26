/*
 * spi_bench - figures of the bit-banged SPI engine for docs/benchmarks.md.
 *
 *   spi_bench bus      bus time per frame on the simulated board, every mode and frame size,
 *                      CS toggled (ADIS register reads) and held (bursts), against the physical
 *                      bound bits x period + setup + hold + stall
 *   spi_bench cost N   N 16-bit mode-3 frames through a HAL whose pin and delay operations do
 *                      nothing: run it under callgrind, counting only spi_transfer, to get the
 *                      engine's own instructions per frame (the HAL's are the port's)
 */
#include "inclino/tool_cli.h"
#include "inclino/tool_summary.h"
#include "inclino/sim/board.h"
#include "inclino/sim/loopback.h"
#include "inclino/spi.h"
#include "inclino/spi_bitbang.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define FRAMES 64u
/* Frames of `cost` at most: 10^9 (minutes under callgrind), never a wrapped 2^64 - 1. */
#define COST_MAX 1000000000u

static int bus_table(void)
{
    static struct sim_board board;
    static struct sim_loopback part;
    const struct spi_timing t = {500, 100, 100, 9000, 0}; /* 2 MHz, ADIS-like stall */
    unsigned mode, bits, pol;
    int worst_ok = 1;
    double worst_ratio = 0.0;
    unsigned violations = 0, rows = 0;
    printf("| mode | bits | CS | SCLK | ns per frame (measured) | bound b*P+S+H(+T) | ratio |\n");
    printf("|---|---|---|---|---|---|---|\n");
    for (pol = 0; pol < 2; pol++) {
        for (mode = 0; mode < 4; mode++) {
            for (bits = 8; bits <= 16; bits += 8) {
                struct sim_loopback_cfg lc;
                struct spi_dev dev;
                struct spi_dev_cfg dc;
                uint16_t tx[FRAMES];
                uint64_t t0, t1, bound;
                double per, ratio;
                unsigned i;
                memset(&lc, 0, sizeof(lc));
                sim_board_init(&board);
                lc.bus = &board.bus;
                lc.cs = SIM_BOARD_CS(0);
                lc.sclk = SIM_BOARD_SCLK;
                lc.mosi = SIM_BOARD_MOSI;
                lc.miso = SIM_BOARD_MISO;
                lc.mode = (uint8_t)mode;
                lc.bits = (uint8_t)bits;
                lc.timing.min_period_ns = 500;
                lc.timing.min_stall_ns = 9000;
                lc.log = &board.log;
                sim_loopback_init(&part, &lc);
                dc.cs = SIM_BOARD_CS(0);
                dc.mode = (uint8_t)mode;
                dc.bits = (uint8_t)bits;
                dc.timing = t;
                spi_dev_init(&dev, &board.spi.bus, &dc);
                for (i = 0; i < FRAMES; i++) {
                    tx[i] = (uint16_t)((0x9A5Cu * (i + 1u)) & (bits == 16 ? 0xFFFFu : 0xFFu));
                }
                /* Warm up (SCLK idle level), then measure from one CS fall to the next run's. */
                spi_xfer1(&dev, 0, NULL);
                t0 = hal_now_ns(&board.hal);
                spi_transfer(&dev, tx, NULL, FRAMES, pol ? SPI_CS_HOLD : SPI_CS_TOGGLE);
                t1 = dev.cs_release_ns;
                /* From the previous CS release to the last one: the stall, CS periods, frames. */
                per = (double)(t1 - t0) / FRAMES;
                if (pol) {
                    bound = bits * t.sclk_period_ns +
                            (t.cs_setup_ns + t.cs_hold_ns + t.stall_ns + FRAMES / 2u) / FRAMES;
                } else {
                    bound = bits * t.sclk_period_ns + t.cs_setup_ns + t.cs_hold_ns + t.stall_ns;
                }
                ratio = per / (double)bound;
                if (ratio > 1.05 || board.log.total != 0) worst_ok = 0;
                if (ratio > worst_ratio) worst_ratio = ratio;
                violations += board.log.total;
                rows++;
                printf("| %u | %u | %s | 2 MHz | %.1f | %llu | %.3f |\n", mode, bits,
                       pol ? "held" : "toggled", per, (unsigned long long)bound, ratio);
            }
        }
    }
    printf("\nall within 1.05 x bound and no timing violation: %s\n", worst_ok ? "yes" : "NO");
    tool_summary_add("rows", "%u", rows);
    tool_summary_add("worst_ratio", "%.3f", worst_ratio);
    tool_summary_add("violations", "%u", violations);
    tool_summary_add("within_bound", "%d", worst_ok);
    return worst_ok ? 0 : 1;
}

/* A HAL that does almost nothing (time is a counter the delays move): the engine's own cost. */
static unsigned null_level;
static uint64_t null_time;
static void n_write(void *c, hal_pin_t p, bool l)
{
    (void)c;
    (void)p;
    null_level ^= l;
}
static bool n_read(void *c, hal_pin_t p)
{
    (void)c;
    return (p & 1u) != 0;
}
static uint64_t n_now(void *c)
{
    (void)c;
    return null_time;
}
static void n_delay(void *c, uint32_t ns)
{
    (void)c;
    null_time += ns;
}
static int n_attach(void *c, hal_pin_t p, enum hal_edge e, hal_irq_cb cb, void *a)
{
    (void)c;
    (void)p;
    (void)e;
    (void)cb;
    (void)a;
    return 0;
}
static int n_wait(void *c, uint64_t d)
{
    (void)c;
    (void)d;
    return 0;
}
static uint32_t n_enter(void *c)
{
    (void)c;
    return 0;
}
static void n_exit(void *c, uint32_t k)
{
    (void)c;
    (void)k;
}
static const struct hal_ops null_ops = {n_write,  n_read, n_now,   n_delay,
                                        n_attach, n_wait, n_enter, n_exit};

static int cost(unsigned long n)
{
    struct hal hal = {&null_ops, NULL};
    struct spi_bitbang bb;
    struct spi_bitbang_cfg bc = {&hal, 0, 1, 2};
    struct spi_dev dev;
    struct spi_dev_cfg dc = {3, SPI_MODE_3, 16, {500, 100, 100, 9000, 0}};
    uint16_t rx;
    unsigned long i;
    if (spi_bitbang_init(&bb, &bc) != 0 || spi_dev_init(&dev, &bb.bus, &dc) != 0) {
        tool_summary_add("error", "setup");
        return 1;
    }
    spi_xfer1(&dev, 0, &rx); /* first transfer moves SCLK: keep it out of the count's average */
    for (i = 0; i < n; i++) {
        uint16_t w = (uint16_t)(0x3E00u ^ (i * 0x1357u));
        spi_transfer(&dev, &w, &rx, 1, SPI_CS_TOGGLE);
    }
    printf("%lu frames, last rx %04X\n", n, rx);
    tool_summary_add("frames", "%lu", n);
    tool_summary_add("last_rx", "%04X", rx);
    return 0;
}

/* The last line on stdout is the summary (docs/tool-summary.md). */
int main(int argc, char **argv)
{
    int st;
    tool_summary_begin("spi_bench");
    cli_set_program("spi_bench");
    if (argc == 2 && strcmp(argv[1], "bus") == 0) {
        tool_summary_add("command", "bus");
        st = bus_table();
        return tool_summary_end(st == 0 ? "ok" : "fail", st);
    }
    if (argc == 3 && strcmp(argv[1], "cost") == 0) {
        uint64_t n;
        tool_summary_add("command", "cost");
        if (cli_parse_u64("N", argv[2], 1, COST_MAX, &n) != 0)
            return tool_summary_error("usage", 2);
        st = cost((unsigned long)n);
        return tool_summary_end(st == 0 ? "ok" : "error", st);
    }
    fprintf(stderr, "usage: spi_bench bus | spi_bench cost N (1..%u)\n", COST_MAX);
    return tool_summary_error("usage", 2);
}
