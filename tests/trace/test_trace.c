/*
 * Register-traffic record and replay: a small "driver" runs against the loopback part while the
 * recorder writes its traffic; the replay then serves that trace to the same driver (same
 * results, no bus), catches every kind of divergence with the frame index and both words, and
 * rejects malformed trace files naming the line. A golden trace in tests/trace/golden is replayed
 * too, so the format itself cannot drift.
 */
#include "inclino/sim/bench.h"
#include "inclino/sim/loopback.h"
#include "inclino/sim/trace.h"
#include "inclino/sim/vcd.h"
#include "unit.h"

#include <stdio.h>
#include <string.h>

#ifndef GOLDEN_DIR
#error "GOLDEN_DIR must be defined"
#endif

static struct sim_board board;
static struct sim_loopback part;
static struct trace_rec rec;
static struct trace_replay rp;
static int dr_dev;

static volatile unsigned dr_seen;
static void on_dr(void *arg)
{
    (void)arg;
    dr_seen++;
}

static void pulse_on(void *arg, uint64_t t)
{
    (void)arg;
    (void)t;
    sim_pinbus_device_drive(&board.bus, (unsigned)dr_dev, SIM_BOARD_DR(0), true);
}
static void pulse_off(void *arg, uint64_t t)
{
    (void)arg;
    (void)t;
    sim_pinbus_device_drive(&board.bus, (unsigned)dr_dev, SIM_BOARD_DR(0), false);
}

static void setup_board(void)
{
    struct sim_loopback_cfg lc;
    sim_board_init(&board);
    sim_bench_loopback_cfg(&board, 1, &lc);
    lc.mode = 3;
    lc.bits = 16;
    lc.timing.min_period_ns = 500;
    lc.first = 0xA5C3;
    sim_loopback_init(&part, &lc);
    dr_dev = sim_pinbus_add_device(&board.bus);
    /* Data-ready pulses at 50 us and 200 us. */
    sim_clock_schedule(&board.clk, 50000, pulse_on, NULL);
    sim_clock_schedule(&board.clk, 50100, pulse_off, NULL);
    sim_clock_schedule(&board.clk, 200000, pulse_on, NULL);
    sim_clock_schedule(&board.clk, 200100, pulse_off, NULL);
}

/*
 * The "driver": attach DR, three toggled frames, wait for data-ready, a held 4-word period,
 * a wait that times out, one more frame. `bad_word` != 0 replaces the 6th word sent.
 * Results go to out[] (9 words) and the wait results to waits[2].
 */
static int driver(const struct spi_bus *bus, const struct hal *hal, uint16_t bad_word,
                  uint16_t *out, int *waits)
{
    struct spi_dev dev;
    struct spi_dev_cfg dc = {SIM_BOARD_CS(1), SPI_MODE_3, 16, {500, 100, 100, 9000, 0}};
    uint16_t tx1[3] = {0x5600, 0x0400, 0x3C00};
    uint16_t tx2[4] = {0x3E00, 0x1111, 0x2222, 0x3333};
    int err;
    dr_seen = 0;
    if (bad_word != 0) {
        tx2[2] = bad_word;
    }
    err = spi_dev_init(&dev, bus, &dc);
    if (err) return err;
    err = hal_irq_attach(hal, SIM_BOARD_DR(0), HAL_EDGE_RISING, on_dr, NULL);
    if (err) return err;
    err = spi_transfer(&dev, tx1, out, 3, SPI_CS_TOGGLE);
    if (err) return err;
    waits[0] = hal_irq_wait(hal, hal_now_ns(hal) + 1000000u);
    err = spi_transfer(&dev, tx2, out + 3, 4, SPI_CS_HOLD);
    if (err) return err;
    waits[1] = hal_irq_wait(hal, hal_now_ns(hal) + 50000u); /* nothing until 200 us: times out */
    err = spi_xfer1(&dev, 0x7000, out + 7);
    if (err) return err;
    hal_delay_ns(hal, 200000u); /* the 200 us pulse comes in here */
    err = spi_xfer1(&dev, 0x7100, out + 8);
    hal_irq_attach(hal, SIM_BOARD_DR(0), HAL_EDGE_RISING, NULL, NULL);
    return err;
}

static uint16_t rec_out[9];
static int rec_waits[2];

static void test_record(void)
{
    FILE *f;
    unsigned line = 0, periods = 0, irqs = 0;
    struct trace_record r;
    char msg[100];
    setup_board();
    REQUIRE(trace_rec_open(&rec, "trace_test.trace", &board.spi.bus, &board.hal) == 0);
    CHECK_OK(trace_rec_comment(&rec, "loopback test driver"));
    CHECK_ERR(trace_rec_comment(&rec, "two\nlines"), INC_ERR_INVAL);
    CHECK_OK(driver(&rec.bus, &rec.hal, 0, rec_out, rec_waits));
    CHECK_OK(trace_rec_close(&rec));
    CHECK_EQ_INT(board.log.total, 0);
    CHECK_EQ_INT(rec_waits[0], 0);
    CHECK_EQ_INT(rec_waits[1], INC_ERR_TIMEOUT);
    CHECK_EQ_INT(dr_seen, 2);
    CHECK_EQ_HEX(rec_out[0], 0xA5C3);
    CHECK_EQ_HEX(rec_out[1], 0x5600);
    CHECK_EQ_HEX(rec_out[3], 0x3C00);
    CHECK_EQ_HEX(rec_out[6], 0x2222);
    CHECK_EQ_HEX(rec_out[8], 0x7000);
    CHECK_EQ_INT(rec.periods, 6);
    CHECK_EQ_INT(rec.words, 9);
    CHECK_EQ_INT(rec.irqs, 2);

    f = fopen("trace_test.trace", "r");
    REQUIRE(f != NULL);
    while (trace_parse_next(f, &line, &r, msg, sizeof(msg)) == 1) {
        if (r.kind == TRACE_PERIOD) {
            if (periods == 3) { /* the held period */
                CHECK_EQ_INT(r.n, 4);
                CHECK_EQ_HEX(r.mosi[0], 0x3E00);
                CHECK_EQ_HEX(r.miso[0], 0x3C00);
            }
            CHECK_EQ_INT(r.pin, SIM_BOARD_CS(1));
            CHECK_EQ_INT(r.bits, 16);
            periods++;
        } else {
            CHECK_EQ_INT(r.pin, SIM_BOARD_DR(0));
            CHECK(irqs == 0 ? r.t_ns == 50000 : r.t_ns == 200000);
            irqs++;
        }
    }
    fclose(f);
    CHECK_EQ_INT(periods, 6);
    CHECK_EQ_INT(irqs, 2);
}

static void test_replay_same_results(void)
{
    uint16_t out[9];
    int waits[2];
    REQUIRE(trace_replay_open(&rp, "trace_test.trace") == 0);
    CHECK_OK(driver(&rp.bus, &rp.hal, 0, out, waits));
    CHECK_OK(trace_replay_finish(&rp));
    CHECK(strcmp(trace_replay_message(&rp), "") == 0);
    CHECK(memcmp(out, rec_out, sizeof(out)) == 0);
    CHECK_EQ_INT(waits[0], rec_waits[0]);
    CHECK_EQ_INT(waits[1], rec_waits[1]);
    CHECK_EQ_INT(dr_seen, 2);
    CHECK_EQ_INT(rp.frame, 9);
}

static void test_replay_divergence(void)
{
    uint16_t out[9];
    int waits[2];
    const char *m;
    REQUIRE(trace_replay_open(&rp, "trace_test.trace") == 0);
    CHECK_ERR(driver(&rp.bus, &rp.hal, 0xBAD0, out, waits), INC_ERR_MISMATCH);
    CHECK_ERR(trace_replay_finish(&rp), INC_ERR_MISMATCH);
    m = trace_replay_message(&rp);
    printf("divergence reported as: %s\n", m);
    CHECK(strstr(m, "frame 5") != NULL);
    CHECK(strstr(m, "expected MOSI 2222") != NULL);
    CHECK(strstr(m, "driver sent BAD0") != NULL);
}

static void test_replay_wrong_shape_and_length(void)
{
    struct spi_dev dev;
    struct spi_dev_cfg dc = {SIM_BOARD_CS(2), SPI_MODE_3, 16, {500, 100, 100, 9000, 0}};
    uint16_t w = 0x5600, rx;
    /* Wrong chip select. */
    REQUIRE(trace_replay_open(&rp, "trace_test.trace") == 0);
    REQUIRE(spi_dev_init(&dev, &rp.bus, &dc) == 0);
    CHECK_ERR(spi_xfer1(&dev, w, &rx), INC_ERR_MISMATCH);
    CHECK(strstr(trace_replay_message(&rp), "cs=4") != NULL);
    CHECK_ERR(spi_xfer1(&dev, w, &rx), INC_ERR_MISMATCH); /* sticky */
    trace_replay_finish(&rp);
    /* The driver stops early. */
    dc.cs = SIM_BOARD_CS(1);
    REQUIRE(trace_replay_open(&rp, "trace_test.trace") == 0);
    REQUIRE(spi_dev_init(&dev, &rp.bus, &dc) == 0);
    CHECK_OK(spi_xfer1(&dev, w, &rx));
    CHECK_EQ_HEX(rx, 0xA5C3);
    CHECK_ERR(trace_replay_finish(&rp), INC_ERR_MISMATCH);
    CHECK(strstr(trace_replay_message(&rp), "stopped") != NULL);
}

static int write_file(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    if (f == NULL) return -1;
    fputs(text, f);
    return fclose(f);
}

static void expect_format_error(const char *body, const char *needle)
{
    char text[512];
    struct spi_dev dev;
    struct spi_dev_cfg dc = {SIM_BOARD_CS(1), SPI_MODE_3, 16, {500, 100, 100, 9000, 0}};
    uint16_t rx;
    snprintf(text, sizeof(text), "# inclino-trace 1\n# comment\n\n%s", body);
    REQUIRE(write_file("trace_bad.trace", text) == 0);
    if (trace_replay_open(&rp, "trace_bad.trace") == INC_OK) {
        REQUIRE(spi_dev_init(&dev, &rp.bus, &dc) == 0);
        CHECK(spi_xfer1(&dev, 0x5600, &rx) != INC_OK);
    }
    CHECK_ERR(trace_replay_finish(&rp), INC_ERR_FORMAT);
    if (strstr(trace_replay_message(&rp), needle) == NULL) {
        printf("message was: %s\n", trace_replay_message(&rp));
    }
    CHECK(strstr(trace_replay_message(&rp), needle) != NULL);
}

static void test_malformed_traces(void)
{
    expect_format_error("X t=1\n", "line 4: record must start");
    expect_format_error("F t=1 cs=4 bits=12 mosi=0 miso=0\n", "line 4: bits=");
    expect_format_error("F t=1 cs=4 bits=16 mosi=5600 miso=0,0\n", "line 4: mosi= and miso=");
    expect_format_error("F t=1 cs=4 bits=16 mosi=5600,ZZ miso=0\n", "line 4: bad mosi=");
    expect_format_error("F t=1 cs=4 bits=8 mosi=100 miso=0\n", "line 4: bad mosi=");
    expect_format_error("F cs=4 bits=16 mosi=5600 miso=0\n", "line 4: bad or missing t=");
    expect_format_error("F t=1 cs=4 bits=16 mosi=5600 miso=0 extra\n", "line 4: unexpected text");
    expect_format_error("I t=5\n", "line 4: bad or missing pin=");
    REQUIRE(write_file("trace_bad.trace", "inclino trace?\n") == 0);
    CHECK_ERR(trace_replay_open(&rp, "trace_bad.trace"), INC_ERR_FORMAT);
    CHECK(strstr(trace_replay_message(&rp), "not an inclino trace") != NULL);
    trace_replay_finish(&rp);
    CHECK_ERR(trace_replay_open(&rp, "no/such/file.trace"), INC_ERR_IO);
    trace_replay_finish(&rp);
    CHECK_ERR(trace_replay_open(NULL, "x"), INC_ERR_NULL);
    CHECK_ERR(trace_rec_open(&rec, "x.trace", NULL, &board.hal), INC_ERR_NULL);
    remove("trace_bad.trace");
}

/* The golden trace: the same driver against the loopback, recorded once and committed. */
static void test_golden(void)
{
    uint16_t out[9];
    int waits[2];
    REQUIRE(trace_replay_open(&rp, GOLDEN_DIR "/loopback_driver.trace") == 0);
    CHECK_OK(driver(&rp.bus, &rp.hal, 0, out, waits));
    CHECK_OK(trace_replay_finish(&rp));
    printf("golden: %s\n", trace_replay_message(&rp));
    CHECK(memcmp(out, rec_out, sizeof(out)) == 0);
}


/* A logic-analyser capture of the same traffic (our VCD) converts to the same trace records. */
static void test_vcd_conversion(void)
{
    static struct sim_vcd vcd;
    static struct trace_record a, b;
    struct spi_dev dev;
    struct spi_dev_cfg dc = {SIM_BOARD_CS(1), SPI_MODE_3, 16, {500, 100, 100, 9000, 0}};
    const uint16_t tx1[3] = {0x5600, 0x0400, 0x3C00}, tx2[4] = {0x3E00, 0x1111, 0x2222, 0x3333};
    const struct trace_vcd_opts o = {"sclk", "mosi", "miso", "cs1", 3, 16, SIM_BOARD_CS(1)};
    char msg[100] = "";
    unsigned la = 0, lb = 0, n = 0;
    FILE *fv, *ft, *fr;
    setup_board();
    REQUIRE(sim_vcd_open(&vcd, "trace_cap.vcd", &board.bus, SIM_BOARD_SPI_MASK) == 0);
    REQUIRE(trace_rec_open(&rec, "trace_rec.trace", &board.spi.bus, &board.hal) == 0);
    REQUIRE(spi_dev_init(&dev, &rec.bus, &dc) == 0);
    CHECK_OK(spi_transfer(&dev, tx1, NULL, 3, SPI_CS_TOGGLE));
    CHECK_OK(spi_transfer(&dev, tx2, NULL, 4, SPI_CS_HOLD));
    CHECK_OK(trace_rec_close(&rec));
    CHECK_OK(sim_vcd_close(&vcd));
    fv = fopen("trace_cap.vcd", "r");
    ft = fopen("trace_conv.trace", "w");
    REQUIRE(fv != NULL && ft != NULL);
    CHECK_EQ_INT(trace_from_vcd(fv, ft, &o, msg, sizeof(msg)), 4);
    fclose(fv);
    fclose(ft);
    fr = fopen("trace_rec.trace", "r");
    ft = fopen("trace_conv.trace", "r");
    REQUIRE(fr != NULL && ft != NULL);
    while (trace_parse_next(fr, &la, &a, msg, sizeof(msg)) == 1) {
        REQUIRE(trace_parse_next(ft, &lb, &b, msg, sizeof(msg)) == 1);
        CHECK_EQ_INT(a.pin, b.pin);
        CHECK_EQ_INT(a.n, b.n);
        CHECK(memcmp(a.mosi, b.mosi, a.n * sizeof(uint16_t)) == 0);
        CHECK(memcmp(a.miso, b.miso, a.n * sizeof(uint16_t)) == 0);
        CHECK(a.t_ns <= b.t_ns); /* recorded when the master began; captured at the CS edge */
        n++;
    }
    CHECK_EQ_INT(n, 4);
    CHECK_EQ_INT(trace_parse_next(ft, &lb, &b, msg, sizeof(msg)), 0);
    fclose(fr);
    fclose(ft);
    /* A capture that cuts a word short is an error naming the time. */
    fv = fopen("trace_cap.vcd", "w");
    REQUIRE(fv != NULL);
    fputs("$timescale 1 us $end\n$var wire 1 ! sclk $end\n$var wire 1 \" mosi $end\n"
          "$var wire 1 # miso $end\n$var wire 1 $ cs1 $end\n$enddefinitions $end\n"
          "#0\n1!\n1$\n#1\n0$\n#2\n0!\n#3\n1!\n#4\n1$\n",
          fv);
    fclose(fv);
    fv = fopen("trace_cap.vcd", "r");
    ft = fopen("trace_conv.trace", "w");
    REQUIRE(fv != NULL && ft != NULL);
    CHECK_ERR(trace_from_vcd(fv, ft, &o, msg, sizeof(msg)), INC_ERR_FORMAT);
    CHECK(strstr(msg, "mid-word at t=4000 ns") != NULL);
    fclose(fv);
    fclose(ft);
    remove("trace_cap.vcd");
    remove("trace_conv.trace");
    remove("trace_rec.trace");
}

int main(int argc, char **argv)
{
    UNIT_RUN(test_record);
    if (argc > 1 && strcmp(argv[1], "--regenerate") == 0) {
        /* Refresh the golden trace from a live run (review the diff before committing). */
        return rename("trace_test.trace", GOLDEN_DIR "/loopback_driver.trace") == 0 ? unit_report()
                                                                                    : 1;
    }
    UNIT_RUN(test_replay_same_results);
    UNIT_RUN(test_replay_divergence);
    UNIT_RUN(test_replay_wrong_shape_and_length);
    UNIT_RUN(test_malformed_traces);
    UNIT_RUN(test_golden);
    UNIT_RUN(test_vcd_conversion);
    remove("trace_test.trace");
    return unit_report();
}
