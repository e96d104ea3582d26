/*
 * Each timing rule of the SPI-slave framework broken once on purpose: the violation is
 * reported with what was measured and what was required, and the master gets what a real part
 * would give it (wrong bits, a flagged frame).
 */
#include "inclino/sim/bench.h"
#include "inclino/sim/loopback.h"
#include "inclino/spi.h"
#include "unit.h"

#include <string.h>

static struct sim_board board;
static struct sim_loopback part;
static struct spi_dev dev;

/* A slow part: 1 MHz, 500 ns setup and hold, 10 us stall, 100 ns MOSI setup, 200 ns tDAV. */
static const struct sim_spi_timing limits = {
    .min_period_ns = 1000,
    .min_half_ns = 0,
    .min_cs_setup_ns = 500,
    .min_cs_hold_ns = 500,
    .min_stall_ns = 10000,
    .mosi_setup_ns = 100,
    .miso_delay_ns = 200,
};

/* A master that meets every limit. */
static const struct spi_timing good = {
    .sclk_period_ns = 1000,
    .cs_setup_ns = 500,
    .cs_hold_ns = 500,
    .stall_ns = 10000,
    .gap_ns = 0,
};

static void setup(uint8_t part_mode, uint8_t part_bits, uint8_t master_mode, uint8_t master_bits,
                  const struct spi_timing *t)
{
    struct sim_loopback_cfg lc;
    struct spi_dev_cfg dc;
    sim_board_init(&board);
    sim_bench_loopback_cfg(&board, 0, &lc);
    lc.name = "slowpart";
    lc.mode = part_mode;
    lc.bits = part_bits;
    lc.timing = limits;
    lc.first = 0x5AA5;
    sim_loopback_init(&part, &lc);
    dc.cs = SIM_BOARD_CS(0);
    dc.mode = master_mode;
    dc.bits = master_bits;
    dc.timing = *t;
    spi_dev_init(&dev, &board.spi.bus, &dc);
}

static void test_no_violation_when_in_spec(void)
{
    uint16_t rx[3];
    const uint16_t tx[3] = {0x1234, 0xABCD, 0x0F0F};
    setup(SPI_MODE_3, 16, SPI_MODE_3, 16, &good);
    CHECK_OK(spi_transfer(&dev, tx, rx, 3, SPI_CS_TOGGLE));
    CHECK_EQ_INT(board.log.total, 0);
    CHECK_EQ_HEX(rx[0], 0x5AA5);
    CHECK_EQ_HEX(rx[1], 0x1234);
    CHECK_EQ_HEX(rx[2], 0xABCD);
}

static void test_sclk_too_fast(void)
{
    struct spi_timing t = good;
    uint16_t rx[2];
    const uint16_t tx[2] = {0x1234, 0xABCD};
    char line[160];
    t.sclk_period_ns = 500; /* 2 MHz into a 1 MHz part */
    setup(SPI_MODE_3, 16, SPI_MODE_3, 16, &t);
    CHECK_OK(spi_transfer(&dev, tx, rx, 2, SPI_CS_TOGGLE));
    /* Per frame: 15 sampling edges after the first come 500 ns apart (< 1000 ns) and are lost. */
    CHECK_EQ_INT(sim_violation_count(&board.log, SIM_VIOL_SCLK_FAST), 30);
    CHECK_EQ_INT(board.log.v[0].measured_ns, 500);
    CHECK_EQ_INT(board.log.v[0].limit_ns, 1000);
    CHECK(sim_violation_format(&board.log.v[0], line, sizeof(line)) > 0);
    CHECK(strstr(line, "sclk-too-fast") != NULL && strstr(line, "slowpart") != NULL);
    /* Wrong bits both ways: the part decoded no whole word, the master read the 250 ns-late MISO. */
    CHECK_EQ_INT(part.received, 0);
    CHECK(sim_violation_count(&board.log, SIM_VIOL_PARTIAL_WORD) == 2);
    CHECK(rx[1] != 0x1234);
}

static void test_cs_setup_too_short(void)
{
    struct spi_timing t = good;
    uint16_t rx;
    t.cs_setup_ns = 100;
    setup(SPI_MODE_3, 16, SPI_MODE_3, 16, &t);
    CHECK_OK(spi_xfer1(&dev, 0x1234, &rx));
    CHECK_EQ_INT(sim_violation_count(&board.log, SIM_VIOL_CS_SETUP), 1);
    CHECK_EQ_INT(board.log.v[0].measured_ns, 100);
    CHECK_EQ_INT(board.log.v[0].limit_ns, 500);
    /* The first (shifting) edge was missed: every bit out comes one bit late. */
    CHECK_EQ_HEX(rx, 0x2D52);             /* 0x5AA5 >> 1: the MSB (0) is repeated */
    CHECK_EQ_HEX(part.rx_log[0], 0x1234); /* sampling edges were all seen */
}

static void test_cs_hold_too_short(void)
{
    struct spi_timing t = good;
    t.cs_hold_ns = 100;
    setup(SPI_MODE_3, 16, SPI_MODE_3, 16, &t);
    CHECK_OK(spi_xfer1(&dev, 0x1234, NULL));
    CHECK_EQ_INT(sim_violation_count(&board.log, SIM_VIOL_CS_HOLD), 1);
    CHECK_EQ_INT(board.log.total, 1);
    CHECK_EQ_INT(board.log.v[0].measured_ns, 100);
    CHECK_EQ_INT(board.log.v[0].limit_ns, 500);
    /* The model learns it with the frame. */
    CHECK(part.last_frame_flags & SIM_SPI_FLAG(SIM_VIOL_CS_HOLD));
}

static void test_stall_too_short(void)
{
    struct spi_timing t = good;
    t.stall_ns = 2000;
    setup(SPI_MODE_3, 16, SPI_MODE_3, 16, &t);
    CHECK_OK(spi_xfer1(&dev, 0x1234, NULL));
    CHECK_EQ_INT(board.log.total, 0);
    CHECK_OK(spi_xfer1(&dev, 0x5678, NULL));
    CHECK_EQ_INT(sim_violation_count(&board.log, SIM_VIOL_STALL), 1);
    CHECK_EQ_INT(board.log.total, 1);
    CHECK_EQ_INT(board.log.v[0].measured_ns, 2000);
    CHECK_EQ_INT(board.log.v[0].limit_ns, 10000);
    CHECK(part.last_frame_flags & SIM_SPI_FLAG(SIM_VIOL_STALL));
}

static void test_mosi_setup_too_short(void)
{
    /* In mode 1 the master sets MOSI at the leading edge and the part samples it h1 = 500 ns
     * later; a part that needs 600 ns of MOSI setup misses every bit where MOSI changes. */
    struct sim_spi_timing lim = limits;
    struct spi_timing t = good;
    uint16_t rx;
    setup(SPI_MODE_1, 16, SPI_MODE_1, 16, &t);
    lim.mosi_setup_ns = 600; /* > h1 = 500 */
    sim_spi_slave_set_timing(&part.slave, &lim);
    CHECK_OK(spi_xfer1(&dev, 0x00FF, &rx));
    /* MOSI starts low, so 0x00FF changes it once, at bit 7. */
    CHECK_EQ_INT(sim_violation_count(&board.log, SIM_VIOL_MOSI_SETUP), 1);
    CHECK_EQ_INT(board.log.v[0].measured_ns, 500);
    CHECK_EQ_INT(board.log.v[0].limit_ns, 600);
    /* The part sampled the old level at that bit: 0x007F instead of 0x00FF. */
    CHECK_EQ_HEX(part.rx_log[0], 0x007F);
}

static void test_wrong_sclk_idle_level(void)
{
    uint16_t rx;
    setup(SPI_MODE_3, 16, SPI_MODE_0, 16, &good);
    CHECK_OK(spi_xfer1(&dev, 0x1234, &rx));
    CHECK_EQ_INT(sim_violation_count(&board.log, SIM_VIOL_SCLK_IDLE), 1);
}

static void test_partial_word(void)
{
    setup(SPI_MODE_3, 16, SPI_MODE_3, 8, &good);
    CHECK_OK(spi_xfer1(&dev, 0x12, NULL));
    CHECK_EQ_INT(sim_violation_count(&board.log, SIM_VIOL_PARTIAL_WORD), 1);
    CHECK_EQ_INT(board.log.v[0].measured_ns, 8); /* bits received */
    CHECK_EQ_INT(part.received, 0);
}

static void test_contention(void)
{
    setup(SPI_MODE_3, 16, SPI_MODE_3, 16, &good);
    sim_pinbus_device_drive(&board.bus, part.slave.dev, SIM_BOARD_MISO, false);
    sim_pinbus_master_write(&board.bus, SIM_BOARD_MISO, true);
    CHECK_EQ_INT(sim_violation_count(&board.log, SIM_VIOL_CONTENTION), 1);
    CHECK(strcmp(board.log.v[0].source, "miso") == 0);
}

static void test_log_keeps_counting_when_full(void)
{
    struct sim_violation_log log;
    unsigned i;
    sim_violation_log_init(&log);
    for (i = 0; i < SIM_VIOLATION_LOG_MAX + 5u; i++) {
        sim_violation_report(&log, SIM_VIOL_BUSY, "x", i, 0, 0);
    }
    sim_violation_report(&log, SIM_VIOL_KIND_COUNT, "x", 0, 0, 0); /* ignored */
    CHECK_EQ_INT(log.total, SIM_VIOLATION_LOG_MAX + 5u);
    CHECK_EQ_INT(log.stored, SIM_VIOLATION_LOG_MAX);
    CHECK_EQ_INT(sim_violation_count(&log, SIM_VIOL_BUSY), SIM_VIOLATION_LOG_MAX + 5u);
    CHECK_EQ_INT(sim_violation_count(&log, SIM_VIOL_KIND_COUNT), 0);
    CHECK(strcmp(sim_violation_kind_name(SIM_VIOL_STALL), "stall") == 0);
}

int main(void)
{
    UNIT_RUN(test_no_violation_when_in_spec);
    UNIT_RUN(test_sclk_too_fast);
    UNIT_RUN(test_cs_setup_too_short);
    UNIT_RUN(test_cs_hold_too_short);
    UNIT_RUN(test_stall_too_short);
    UNIT_RUN(test_mosi_setup_too_short);
    UNIT_RUN(test_wrong_sclk_idle_level);
    UNIT_RUN(test_partial_word);
    UNIT_RUN(test_contention);
    UNIT_RUN(test_log_keeps_counting_when_full);
    return unit_report();
}
