/*
 * The LPSPI engine through its register model on the simulated board: the timing mapping, every
 * mode and frame size with CS held and toggled, bus timing to the ns and against the part's
 * timing checker, two devices of different mode, size and timing on one bus, every error path.
 */
#include "inclino/s32k_mmio.h"
#include "inclino/sim/board.h"
#include "inclino/sim/loopback.h"
#include "inclino/sim/s32k_bus.h"
#include "inclino/sim/s32k_lpspi_rig.h"
#include "inclino/spi.h"
#include "unit.h"

#include <string.h>

static struct sim_board board;
static struct sim_lpspi_rig rig;
static struct sim_loopback part, part2;
static struct spi_dev dev, dev2;

/* Limits of the test part: 2 MHz, 100 ns setup/hold, 1 us stall, 40 ns output delay. */
static const struct sim_spi_timing part_timing = {
    .min_period_ns = 500,
    .min_half_ns = 250,
    .min_cs_setup_ns = 100,
    .min_cs_hold_ns = 100,
    .min_stall_ns = 1000,
    .mosi_setup_ns = 20,
    .miso_delay_ns = 40,
};

static const struct spi_timing master_timing = {
    .sclk_period_ns = 500,
    .cs_setup_ns = 100,
    .cs_hold_ns = 100,
    .stall_ns = 1000,
    .gap_ns = 0,
};

static uint64_t cs_fall[64], cs_rise[64];
static unsigned n_fall, n_rise;
static struct sim_pin_listener cs_listener;

static void on_cs(void *arg, unsigned pin, bool level, uint64_t t)
{
    (void)arg;
    (void)pin;
    if (!level && n_fall < 64u) {
        cs_fall[n_fall++] = t;
    }
    if (level && n_rise < 64u) {
        cs_rise[n_rise++] = t;
    }
}

static int add_part(struct sim_loopback *p, unsigned slot, uint8_t mode, uint8_t bits,
                    const struct sim_spi_timing *t, uint16_t first)
{
    struct sim_loopback_cfg lc;
    memset(&lc, 0, sizeof(lc));
    lc.bus = &board.bus;
    lc.cs = SIM_BOARD_CS(slot);
    lc.sclk = SIM_BOARD_SCLK;
    lc.mosi = SIM_BOARD_MOSI;
    lc.miso = SIM_BOARD_MISO;
    lc.mode = mode;
    lc.bits = bits;
    lc.timing = *t;
    lc.first = first;
    lc.log = &board.log;
    return sim_loopback_init(p, &lc);
}

static int add_dev(struct spi_dev *d, unsigned slot, uint8_t mode, uint8_t bits,
                   const struct spi_timing *t)
{
    struct spi_dev_cfg dc;
    dc.cs = (hal_pin_t)SIM_BOARD_CS(slot);
    dc.mode = mode;
    dc.bits = bits;
    dc.timing = *t;
    return spi_dev_init(d, &rig.engine.bus, &dc);
}

static int setup(uint8_t mode, uint8_t bits, uint16_t first, uint32_t fclk_hz)
{
    int err = sim_board_init(&board);
    if (err) {
        return err;
    }
    err = sim_lpspi_rig_init(&rig, &board, fclk_hz);
    if (err) {
        return err;
    }
    err = add_part(&part, 0, mode, bits, &part_timing, first);
    if (err) {
        return err;
    }
    err = add_dev(&dev, 0, mode, bits, &master_timing);
    if (err) {
        return err;
    }
    n_fall = n_rise = 0;
    cs_listener.fn = on_cs;
    cs_listener.arg = NULL;
    cs_listener.mask = SIM_PIN_MASK(SIM_BOARD_CS(0));
    return sim_pinbus_listen(&board.bus, &cs_listener);
}

static void bus_clean(void)
{
    const struct s32k_bus_stats *st = s32k_bus_stats();
    CHECK_EQ_INT(st->unmapped_reads, 0);
    CHECK_EQ_INT(st->unmapped_writes, 0);
    CHECK_EQ_INT(st->misaligned, 0);
    CHECK_EQ_INT(rig.model.locked_writes, 0);
    CHECK_EQ_INT(rig.model.bad_commands, 0);
    CHECK(!board.clk.overflowed);
}

/* ------------------------------------------------------------------ the timing mapping */

static void test_clock_mapping(void)
{
    struct spi_lpspi_clock c;
    struct spi_timing t = master_timing;
    /* 48 MHz: 1 us stall needs 48 counts (DBT 46) at prescale 0; 500 ns = 24 counts. */
    CHECK_OK(spi_lpspi_clock_for(48000000u, &t, SPI_CS_TOGGLE, &c));
    CHECK_EQ_INT(c.prescale, 0);
    CHECK_EQ_INT(c.sckdiv, 22);
    CHECK_EQ_INT(c.pcssck, 4); /* 100 ns = 4.8 counts -> 5 */
    CHECK_EQ_INT(c.sckpcs, 4);
    CHECK_EQ_INT(c.dbt, 46);
    /* Held: DBT is the word gap, at least half a period (250 ns = 12 counts, DBT 11). */
    CHECK_OK(spi_lpspi_clock_for(48000000u, &t, SPI_CS_HOLD, &c));
    CHECK_EQ_INT(c.dbt, 11);
    /* The ADIS low-power stall (80 us = 3840 counts) needs prescale 16: 240 counts, DBT 238;
     * 3334 ns at 3 MHz counts -> 11 -> 12 (even halves), SCKDIV 10. */
    t.sclk_period_ns = 3334;
    t.stall_ns = 80000;
    CHECK_OK(spi_lpspi_clock_for(48000000u, &t, SPI_CS_TOGGLE, &c));
    CHECK_EQ_INT(c.prescale, 4);
    CHECK_EQ_INT(c.dbt, 238);
    CHECK_EQ_INT(c.sckdiv, 10);
    CHECK(spi_lpspi_counts_ns(48000000u, 4, 12u) >= 3334u);
    /* An odd period never gets a short half: 3 counts at 8 MHz = 375 ns, but halves of 1 count
     * (125 ns) < 167 ns, so 4 counts. */
    t = master_timing;
    t.sclk_period_ns = 333;
    CHECK_OK(spi_lpspi_clock_for(8000000u, &t, SPI_CS_TOGGLE, &c));
    CHECK_EQ_INT(c.sckdiv, 2);
    /* Longer than 257 x 128 counts: refused, never shortened. */
    t.stall_ns = 5000000u; /* 257 x 128 / 8 MHz = 4.11 ms */
    CHECK_ERR(spi_lpspi_clock_for(8000000u, &t, SPI_CS_TOGGLE, &c), INC_ERR_TIMING);
    CHECK_ERR(spi_lpspi_clock_for(0u, &master_timing, SPI_CS_TOGGLE, &c), INC_ERR_INVAL);
    CHECK_ERR(spi_lpspi_clock_for(48000000u, NULL, SPI_CS_TOGGLE, &c), INC_ERR_NULL);
    CHECK_ERR(spi_lpspi_clock_for(48000000u, &master_timing, SPI_CS_TOGGLE, NULL), INC_ERR_NULL);
}

/* ------------------------------------------------------------------ loopback */

static const uint16_t words16[] = {0xA5C3, 0x0001, 0x8000, 0xFFFF, 0x0000, 0x3E00, 0x7FFE, 0x1234};
static const uint16_t words8[] = {0xA5, 0x01, 0x80, 0xFF, 0x00, 0x3E, 0x7E, 0x12};
#define NWORDS 8u

static void check_loopback(uint8_t mode, uint8_t bits, enum spi_cs_policy cs, uint32_t fclk)
{
    const uint16_t *w = bits == 16u ? words16 : words8;
    const uint16_t first = bits == 16u ? 0x5AA5u : 0x5Au;
    uint16_t rx[NWORDS];
    unsigned i;
    REQUIRE(setup(mode, bits, first, fclk) == 0);
    CHECK_OK(spi_transfer(&dev, w, rx, NWORDS, cs));
    CHECK_EQ_HEX(rx[0], first);
    for (i = 1; i < NWORDS; i++) {
        CHECK_EQ_HEX(rx[i], w[i - 1]);
    }
    CHECK_EQ_INT(part.received, NWORDS);
    for (i = 0; i < NWORDS; i++) {
        CHECK_EQ_HEX(part.rx_log[i], w[i]);
    }
    if (board.log.total != 0u) {
        sim_violation_log_print(&board.log, stdout);
    }
    CHECK_EQ_INT(board.log.total, 0);
    CHECK_EQ_INT(n_fall, cs == SPI_CS_TOGGLE ? NWORDS : 1u);
    CHECK_EQ_INT(n_rise, n_fall);
    CHECK_EQ_INT(part.frames_ended, n_fall);
    /* A second transfer keeps the stall from the first one's last CS rise. */
    CHECK_OK(spi_transfer(&dev, w, rx, 2u, cs));
    CHECK_EQ_HEX(rx[0], w[NWORDS - 1u]);
    CHECK_EQ_INT(board.log.total, 0);
    CHECK(rig.engine.stats.max_in_flight <= SIM_LPSPI_FIFO);
    CHECK_EQ_INT(rig.engine.stats.errors, 0);
    bus_clean();
}

static void test_every_mode_and_size(void)
{
    uint8_t mode;
    for (mode = 0; mode < 4u; mode++) {
        check_loopback(mode, 16, SPI_CS_TOGGLE, 0);
        check_loopback(mode, 8, SPI_CS_TOGGLE, 0);
        check_loopback(mode, 16, SPI_CS_HOLD, 0);
        check_loopback(mode, 8, SPI_CS_HOLD, 0);
        /* 8 MHz (SOSCDIV2 / SIRCDIV2): other counts, the same result. */
        check_loopback(mode, 16, SPI_CS_TOGGLE, 8000000u);
        check_loopback(mode, 8, SPI_CS_HOLD, 8000000u);
    }
}

/* ------------------------------------------------------------------ timing */

/* At 48 MHz the test timing is exact in counts: period 24 (500 ns), setup/hold 5 (104.17 ns ->
 * 105), stall 48 (1000 ns). A CS period of b bits: setup + b x period - second half + hold. */
static void test_bus_timing_exact(void)
{
    uint16_t rx[4];
    const uint16_t tx[4] = {1, 2, 3, 4};
    unsigned i;
    REQUIRE(setup(3, 16, 0, 0) == 0);
    CHECK_OK(spi_transfer(&dev, tx, rx, 4u, SPI_CS_TOGGLE));
    REQUIRE(n_fall == 4u && n_rise == 4u);
    for (i = 0; i < 4u; i++) {
        CHECK_EQ_INT(cs_rise[i] - cs_fall[i], 105u + 16u * 500u - 250u + 105u);
    }
    for (i = 1; i < 4u; i++) {
        CHECK_EQ_INT(cs_fall[i] - cs_rise[i - 1], 1000u); /* DBT + 2 = 48 counts */
    }
    CHECK_EQ_INT(board.log.total, 0);
    /* Held: one CS period, words 16 x 500 - 250 apart plus the gap 250 (DBT + 1 = 12 counts). */
    n_fall = n_rise = 0;
    CHECK_OK(spi_transfer(&dev, tx, rx, 4u, SPI_CS_HOLD));
    REQUIRE(n_fall == 1u && n_rise == 1u);
    CHECK_EQ_INT(cs_rise[0] - cs_fall[0], 105u + 4u * (16u * 500u - 250u) + 3u * 250u + 105u);
    CHECK_EQ_INT(board.log.total, 0);
    bus_clean();
}

/* The checker is live: a device whose timing asks for less than the part needs is caught. */
static void test_checker_catches_fast_device(void)
{
    struct spi_timing fast = master_timing;
    uint16_t rx[2];
    const uint16_t tx[2] = {0x1234, 0x5678};
    REQUIRE(setup(3, 16, 0, 0) == 0);
    fast.sclk_period_ns = 250; /* 4 MHz against a 2 MHz part */
    fast.stall_ns = 200;
    CHECK_OK(spi_dev_set_timing(&dev, &fast));
    CHECK_OK(spi_transfer(&dev, tx, rx, 2u, SPI_CS_TOGGLE));
    CHECK(board.log.total > 0u);
}

/* Two devices on one bus, as the SCA3000 (8-bit, 2 us period, 10 us stall) and an ADIS part
 * (mode 3, 16-bit, 500 ns period, its stall): alternated, each met exactly by its own timing. */
static void test_two_devices_reconfigured(void)
{
    static const struct sim_spi_timing sca_part = {
        .min_period_ns = 2000,
        .min_half_ns = 1000,
        .min_cs_setup_ns = 1000,
        .min_cs_hold_ns = 1000,
        .min_stall_ns = 10000,
        .mosi_setup_ns = 20,
        .miso_delay_ns = 100,
    };
    static const struct spi_timing sca_dev = {2000, 1000, 1000, 10000, 0};
    uint16_t rx[3];
    const uint16_t a[3] = {0x1111, 0x2222, 0x3333};
    const uint16_t s[3] = {0x11, 0x22, 0x33};
    unsigned round;
    REQUIRE(setup(3, 16, 0xAAAA, 0) == 0);
    REQUIRE(add_part(&part2, 1, 0, 8, &sca_part, 0x55) == 0);
    REQUIRE(add_dev(&dev2, 1, 0, 8, &sca_dev) == 0);
    for (round = 0; round < 3u; round++) {
        CHECK_OK(spi_transfer(&dev, a, rx, 3u, SPI_CS_TOGGLE));
        CHECK_OK(spi_transfer(&dev2, s, rx, 3u, SPI_CS_HOLD));
        CHECK_EQ_HEX(rx[1], 0x11);
        CHECK_EQ_HEX(rx[2], 0x22);
    }
    CHECK_EQ_INT(part.received, 9);
    CHECK_EQ_INT(part2.received, 9);
    if (board.log.total != 0u) {
        sim_violation_log_print(&board.log, stdout);
    }
    CHECK_EQ_INT(board.log.total, 0);
    CHECK_EQ_INT(rig.engine.stats.reconfigs, 6); /* every device change rewrites CCR */
    bus_clean();
}

/* ------------------------------------------------------------------ errors */

static void test_errors(void)
{
    struct spi_timing slow = master_timing;
    struct spi_dev stray;
    struct spi_dev_cfg dc;
    uint16_t rx[2];
    const uint16_t tx[2] = {0x0102, 0x0304};
    uint64_t changes;

    /* A CS that no PCS drives. */
    REQUIRE(setup(3, 16, 0, 0) == 0);
    dc.cs = (hal_pin_t)SIM_BOARD_DR(0);
    dc.mode = 3;
    dc.bits = 16;
    dc.timing = master_timing;
    CHECK_ERR(spi_dev_init(&stray, &rig.engine.bus, &dc), INC_ERR_INVAL);

    /* A timing the counters cannot hold: refused before anything moves on the bus. */
    slow.stall_ns = 1000000u; /* 1 ms > 257 x 128 / 48 MHz = 685 us */
    CHECK_OK(spi_dev_set_timing(&dev, &slow));
    changes = board.bus.changes;
    CHECK_ERR(spi_transfer(&dev, tx, rx, 2u, SPI_CS_TOGGLE), INC_ERR_TIMING);
    CHECK_EQ_INT(board.bus.changes, changes);
    CHECK_EQ_INT(part.received, 0);
    CHECK_OK(spi_dev_set_timing(&dev, &master_timing));

    /* TEF and REF: the transfer fails and the next one works again. */
    rig.model.force_tef = true;
    CHECK_ERR(spi_transfer(&dev, tx, rx, 2u, SPI_CS_TOGGLE), INC_ERR_BUS);
    CHECK((rig.engine.stats.last_sr & LPSPI_SR_TEF) != 0u || rig.engine.stats.errors == 1u);
    CHECK_OK(spi_transfer(&dev, tx, rx, 2u, SPI_CS_TOGGLE));
    rig.model.force_ref = true;
    CHECK_ERR(spi_transfer(&dev, tx, rx, 2u, SPI_CS_HOLD), INC_ERR_BUS);
    CHECK_OK(spi_transfer(&dev, tx, rx, 2u, SPI_CS_HOLD));
    /* After a reset mid-frame no PCS is left asserted. */
    CHECK(sim_pinbus_read(&board.bus, SIM_BOARD_CS(0)));

    /* The shifter stops: a timeout, within the bound of expected time + timeout_ns. */
    rig.model.stall_engine = true;
    {
        const uint64_t t0 = board.clk.now_ns;
        CHECK_ERR(spi_transfer(&dev, tx, rx, 2u, SPI_CS_TOGGLE), INC_ERR_TIMEOUT);
        CHECK(board.clk.now_ns - t0 < 1000000u);
    }
    rig.model.stall_engine = false;
    CHECK_OK(spi_transfer(&dev, tx, rx, 2u, SPI_CS_TOGGLE));

    /* Busy before the transfer: someone left a continuous frame open on PCS0. */
    s32k_mmio_write32(LPSPI0_BASE + LPSPI_TCR,
                      LPSPI_TCR_CPOL | LPSPI_TCR_CPHA | LPSPI_TCR_CONT | 15u);
    s32k_mmio_write32(LPSPI0_BASE + LPSPI_TDR, 0x0000u);
    hal_delay_ns(&board.hal, 20000u);
    CHECK((s32k_mmio_read32(LPSPI0_BASE + LPSPI_SR) & LPSPI_SR_MBF) != 0u);
    CHECK_ERR(spi_transfer(&dev, tx, rx, 2u, SPI_CS_TOGGLE), INC_ERR_BUSY);
    CHECK(sim_pinbus_read(&board.bus, SIM_BOARD_CS(0))); /* the reset released it */
    CHECK_OK(spi_transfer(&dev, tx, rx, 2u, SPI_CS_TOGGLE));
    CHECK_EQ_INT(rig.engine.stats.errors, 4);
    bus_clean();
}

static void test_init_errors(void)
{
    struct spi_lpspi lp;
    struct spi_lpspi_cfg c;
    unsigned k;
    REQUIRE(sim_board_init(&board) == 0);
    REQUIRE(sim_lpspi_rig_init(&rig, &board, 0) == 0);
    c = rig.engine.cfg;
    CHECK_ERR(spi_lpspi_init(NULL, &c), INC_ERR_NULL);
    CHECK_ERR(spi_lpspi_init(&lp, NULL), INC_ERR_NULL);
    c.fclk_hz = 0;
    CHECK_ERR(spi_lpspi_init(&lp, &c), INC_ERR_INVAL);
    c = rig.engine.cfg;
    c.pcs_pin[1] = c.pcs_pin[0];
    CHECK_ERR(spi_lpspi_init(&lp, &c), INC_ERR_INVAL);
    for (k = 0; k < SPI_LPSPI_PCS_COUNT; k++) {
        c.pcs_pin[k] = HAL_PIN_NONE;
    }
    CHECK_ERR(spi_lpspi_init(&lp, &c), INC_ERR_INVAL);
    c = rig.engine.cfg;
    c.hal = NULL;
    CHECK_ERR(spi_lpspi_init(&lp, &c), INC_ERR_NULL);
    /* No LPSPI at that address: PARAM reads 0 -> 1-word FIFOs, PCSNUM 0: unsupported. */
    c = rig.engine.cfg;
    c.base = 0x4002F000u;
    CHECK_ERR(spi_lpspi_init(&lp, &c), INC_ERR_UNSUPPORTED);
}

int main(void)
{
    UNIT_RUN(test_clock_mapping);
    UNIT_RUN(test_every_mode_and_size);
    UNIT_RUN(test_bus_timing_exact);
    UNIT_RUN(test_checker_catches_fast_device);
    UNIT_RUN(test_two_devices_reconfigured);
    UNIT_RUN(test_errors);
    UNIT_RUN(test_init_errors);
    return unit_report();
}
