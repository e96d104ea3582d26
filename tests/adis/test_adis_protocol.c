/*
 * The shared ADIS register protocol: driver side (drivers/adis) against the simulated protocol
 * core (sim/models/adis_core) with a plain register file behind it.
 */
#include "inclino/adis.h"
#include "inclino/sim/adis_core.h"
#include "inclino/sim/board.h"
#include "unit.h"

#include <string.h>

struct regfile {
    uint16_t reg[64];
    uint64_t busy_until;
    unsigned reads;
};

static uint16_t rf_read(void *m, uint8_t addr, uint64_t t)
{
    struct regfile *r = m;
    (void)t;
    r->reads++;
    return r->reg[(addr & 0x7Fu) >> 1];
}

static void rf_write(void *m, uint8_t addr, uint8_t v, uint64_t t)
{
    struct regfile *r = m;
    uint16_t *w = &r->reg[(addr & 0x7Fu) >> 1];
    (void)t;
    *w = (addr & 1u) ? (uint16_t)((*w & 0x00FFu) | (uint16_t)v << 8)
                     : (uint16_t)((*w & 0xFF00u) | v);
}

static bool rf_busy(void *m, uint64_t t)
{
    const struct regfile *r = m;
    return t < r->busy_until;
}

static unsigned rf_burst(void *m, uint16_t *w, unsigned max, uint64_t t)
{
    struct regfile *r = m;
    unsigned i;
    (void)t;
    for (i = 0; i < 4u && i < max; i++) {
        w[i] = r->reg[1u + i];
    }
    return i;
}

static const struct sim_adis_ops rf_ops = {rf_read, rf_write, rf_busy, rf_burst};

static struct sim_board board;
static struct sim_adis_core core;
static struct regfile rf;
static struct spi_dev dev;

static const struct spi_timing normal = {500, 100, 100, 9000, 0};    /* 2 MHz, 9 us stall */
static const struct spi_timing burst = {1000, 100, 100, 9000, 1000}; /* 1 MHz */

static void setup(void)
{
    struct sim_adis_cfg ac;
    struct spi_dev_cfg dc;
    unsigned i;
    memset(&rf, 0, sizeof(rf));
    for (i = 0; i < 64u; i++) {
        rf.reg[i] = (uint16_t)(0x1000u + i);
    }
    sim_board_init(&board);
    memset(&ac, 0, sizeof(ac));
    ac.name = "adis-test";
    ac.bus = &board.bus;
    ac.cs = SIM_BOARD_CS(0);
    ac.sclk = SIM_BOARD_SCLK;
    ac.mosi = SIM_BOARD_MOSI;
    ac.miso = SIM_BOARD_MISO;
    ac.timing.min_period_ns = 500;
    ac.timing.min_cs_setup_ns = 50;
    ac.timing.min_cs_hold_ns = 50;
    ac.timing.min_stall_ns = 9000;
    ac.timing.miso_delay_ns = 100;
    ac.addr_mask = 0x7F;
    ac.burst_cmd = 0x3E00;
    ac.burst_min_period_ns = 1000;
    ac.ops = &rf_ops;
    ac.model = &rf;
    ac.log = &board.log;
    ac.seed = 7;
    sim_adis_core_init(&core, &ac);
    dc.cs = SIM_BOARD_CS(0);
    dc.mode = SPI_MODE_3;
    dc.bits = 16;
    dc.timing = normal;
    spi_dev_init(&dev, &board.spi.bus, &dc);
}

static void test_read_write(void)
{
    uint16_t v = 0, vals[3];
    const uint8_t addrs[3] = {0x04, 0x56, 0x3C};
    setup();
    CHECK_OK(adis_read_reg(&dev, 0x56, &v));
    CHECK_EQ_HEX(v, 0x1000u + 0x2Bu);
    CHECK_OK(adis_read_regs(&dev, addrs, vals, 3));
    CHECK_EQ_HEX(vals[0], 0x1002);
    CHECK_EQ_HEX(vals[1], 0x102B);
    CHECK_EQ_HEX(vals[2], 0x101E);
    CHECK_EQ_INT(core.reads, 2u + 4u); /* the final frames read register 0x00 */
    CHECK_OK(adis_write_reg(&dev, 0x1A, 0xBEEF));
    CHECK_EQ_HEX(rf.reg[0x1A >> 1], 0xBEEF);
    CHECK_OK(adis_write_byte(&dev, 0x1B, 0x12));
    CHECK_EQ_HEX(rf.reg[0x1A >> 1], 0x12EF);
    CHECK_OK(adis_read_reg(&dev, 0x1A, &v));
    CHECK_EQ_HEX(v, 0x12EF);
    CHECK_EQ_INT(board.log.total, 0);
}

static void test_busy_and_broken_frames(void)
{
    uint16_t v = 0;
    setup();
    /* Busy: garbage back, the write is ignored and reported. */
    rf.busy_until = board.clk.now_ns + 1000000u;
    CHECK_OK(adis_write_reg(&dev, 0x20, 0x5555));
    CHECK(rf.reg[0x20 >> 1] != 0x5555);
    CHECK_EQ_INT(sim_violation_count(&board.log, SIM_VIOL_BUSY), 2);
    hal_delay_ns(&board.hal, 1000000u);
    CHECK_OK(adis_read_reg(&dev, 0x20, &v));
    CHECK_EQ_HEX(v, 0x1010);
    /* A frame sent without the stall is dropped: the write does not happen. */
    dev.cfg.timing.stall_ns = 1000;
    CHECK_OK(adis_write_reg(&dev, 0x22, 0xAAAA));
    CHECK(sim_violation_count(&board.log, SIM_VIOL_STALL) >= 1);
    CHECK(rf.reg[0x22 >> 1] != 0xAAAA);
}

static void test_burst(void)
{
    uint16_t tx[5] = {0x3E00, 0, 0, 0, 0}, rx[5];
    setup();
    CHECK_OK(spi_dev_set_timing(&dev, &burst));
    CHECK_OK(spi_transfer(&dev, tx, rx, 5, SPI_CS_HOLD));
    CHECK_EQ_HEX(rx[1], 0x1001);
    CHECK_EQ_HEX(rx[4], 0x1004);
    CHECK_EQ_INT(board.log.total, 0);
    /* The same burst at 2 MHz: reported, garbage. */
    CHECK_OK(spi_dev_set_timing(&dev, &normal));
    CHECK_OK(spi_transfer(&dev, tx, rx, 5, SPI_CS_HOLD));
    CHECK(sim_violation_count(&board.log, SIM_VIOL_SCLK_FAST) >= 1);
    CHECK(rx[1] != 0x1001 || rx[2] != 0x1002);
}

static void test_helpers_and_errors(void)
{
    uint16_t v;
    uint8_t a = 0x80;
    setup();
    CHECK_EQ_INT(adis_sign_extend(0x3FFF, 14), -1);
    CHECK_EQ_INT(adis_sign_extend(0xBFFF, 14), -1); /* ND/EA ignored */
    CHECK_EQ_INT(adis_sign_extend(0x1770, 14), 6000);
    CHECK_EQ_INT(adis_sign_extend(0x2890, 14), -6000);
    CHECK_EQ_INT(adis_sign_extend(0x2000, 14), -8192);
    CHECK_EQ_INT(adis_sign_extend(0x0800, 12), -2048);
    CHECK_EQ_INT(adis_sign_extend(0x8000, 16), -32768);
    CHECK_EQ_INT(adis_sign_extend(0x1234, 0), 0);
    CHECK_EQ_HEX(adis_field(0xC814, 12), 0x814);
    CHECK_ERR(adis_read_reg(NULL, 0, &v), INC_ERR_NULL);
    CHECK_ERR(adis_read_reg(&dev, 0, NULL), INC_ERR_NULL);
    CHECK_ERR(adis_read_reg(&dev, 0x80, &v), INC_ERR_INVAL);
    CHECK_ERR(adis_read_regs(&dev, &a, &v, 1), INC_ERR_INVAL);
    CHECK_ERR(adis_read_regs(&dev, &a, &v, 0), INC_ERR_INVAL);
    CHECK_ERR(adis_read_regs(&dev, &a, &v, ADIS_MAX_PIPELINE + 1u), INC_ERR_INVAL);
    CHECK_ERR(adis_write_reg(&dev, 0x21, 0), INC_ERR_INVAL); /* odd address */
    CHECK_ERR(adis_write_byte(&dev, 0x80, 0), INC_ERR_INVAL);
    CHECK_ERR(adis_write_byte(NULL, 0x10, 0), INC_ERR_NULL);
    CHECK_EQ_INT(core.reads + core.writes, 0); /* nothing reached the part */
    {
        uint8_t many[ADIS_MAX_PIPELINE];
        uint16_t vals[ADIS_MAX_PIPELINE];
        unsigned k;
        for (k = 0; k < ADIS_MAX_PIPELINE; k++) {
            many[k] = (uint8_t)(2u * k);
        }
        CHECK_OK(adis_read_regs(&dev, many, vals, ADIS_MAX_PIPELINE)); /* the largest read */
        for (k = 0; k < ADIS_MAX_PIPELINE; k++) {
            CHECK_EQ_HEX(vals[k], 0x1000u + k);
        }
    }
}

/* adis_read_reg has its own 2-frame path: the same reads and values as adis_read_regs with
 * n = 1 (the frames themselves: the golden traces of tests/golden). */
static void test_read_reg_as_regs(void)
{
    uint16_t v1 = 0, v2 = 0;
    uint8_t a;
    setup();
    for (a = 0x00; a < 0x40; a = (uint8_t)(a + 0x0E)) {
        const unsigned r0 = core.reads;
        CHECK_OK(adis_read_reg(&dev, a, &v1));
        CHECK_EQ_INT(core.reads - r0, 2u);
        CHECK_OK(adis_read_regs(&dev, &a, &v2, 1u));
        CHECK_EQ_INT(core.reads - r0, 4u);
        CHECK_EQ_HEX(v1, v2);
        CHECK_EQ_HEX(v1, 0x1000u + (a >> 1));
    }
    CHECK_EQ_INT(board.log.total, 0);
}

int main(void)
{
    UNIT_RUN(test_read_reg_as_regs);
    UNIT_RUN(test_read_write);
    UNIT_RUN(test_busy_and_broken_frames);
    UNIT_RUN(test_burst);
    UNIT_RUN(test_helpers_and_errors);
    return unit_report();
}
