/*
 * The simulated ADIS1636x/1640x on its own, driven through the shared ADIS protocol layer (not
 * the driver), so its datasheet behaviour is checked independently of the driver: defaults,
 * ND/EA, DIAG_STAT clear-on-read, flash and reset, the burst limits (also in low-power mode:
 * the shared core keeps the stricter limit during a burst), protocol errors, the optional
 * ADIS16405 burst bug, the physics hook and the sample clock.
 */
#include "inclino/adis.h"
#include "inclino/sim/adis_imu.h"
#include "inclino/sim/bench.h"
#include "unit.h"

#include <string.h>

static struct sim_board board;
static struct sim_adis_imu part;
static struct spi_dev dev;

static const struct spi_timing t_normal = {500, 100, 100, 10000, 0};
static const struct spi_timing t_lp = {3334, 100, 100, 80000, 0};
static const struct spi_timing t_burst = {1000, 100, 100, 10000, 1000};

static void setup_cfg(enum sim_adis_imu_variant v, const struct sim_physics *phys, bool bug)
{
    struct sim_adis_imu_cfg c;
    struct spi_dev_cfg dc = {SIM_BOARD_CS(0), SPI_MODE_3, 16, {500, 100, 100, 10000, 0}};
    sim_board_init(&board);
    sim_bench_adis_imu_cfg(&board, 0, v, &c);
    c.dio2 = SIM_ADIS_IMU_NO_PIN;
    c.power_on_busy = false;
    c.physics = phys;
    c.burst_bug = bug;
    c.seed = 5;
    sim_adis_imu_init(&part, &c);
    spi_dev_init(&dev, &board.spi.bus, &dc);
}

static void setup(enum sim_adis_imu_variant v)
{
    setup_cfg(v, NULL, false);
}

static uint16_t rd(uint8_t addr)
{
    uint16_t v = 0;
    CHECK_OK(adis_read_reg(&dev, addr, &v));
    return v;
}

static void wait_ms(uint32_t ms)
{
    hal_delay_ms(&board.hal, ms);
}

static void test_defaults(void)
{
    static const uint16_t ids[6] = {0x3FE8, 0x3FEA, 0x3FEC, 0x3FED, 0x4010, 0x4015};
    unsigned v;
    for (v = 0; v < 6u; v++) {
        setup((enum sim_adis_imu_variant)v);
        CHECK_EQ_HEX(rd(0x56), ids[v]);
        CHECK_EQ_HEX(rd(0x34), 0x0006);
        CHECK_EQ_HEX(rd(0x36), 0x0001);
        CHECK_EQ_HEX(rd(0x38), 0x0402);
        CHECK_EQ_HEX(rd(0x00), 0x0000);
        CHECK_EQ_HEX(rd(0x1A), 0x0000);
        CHECK_EQ_HEX(rd(0x3C), 0x0000);
        CHECK_EQ_HEX(rd(0x2C), v >= 4u ? 0x0800 : 0x0000); /* XMAGN_SIF / ALM_SMPL2 */
        CHECK_NEAR(sim_adis_imu_rate_sps(&part), 819.2, 1e-9);
        CHECK_EQ_INT(board.log.total, 0);
    }
}

static void test_nd_ea_and_diag(void)
{
    uint16_t w;
    setup(SIM_ADIS16400);
    /* at rest: z = 1 g / 3.333 mg = 300 counts, ND set until read */
    w = rd(0x0E);
    CHECK_EQ_HEX(w, 0x8000u | 300u);
    CHECK_EQ_HEX(rd(0x0E), 300u);            /* ND cleared by the read */
    CHECK_EQ_HEX(rd(0x02), 0x8000u | 2068u); /* other registers keep their ND */
    wait_ms(2);
    CHECK_EQ_HEX(rd(0x0E), 0x8000u | 300u); /* a new sample sets it again */
    /* EA follows DIAG_STAT; DIAG_STAT clears on read */
    sim_adis_imu_raise_diag(&part, 0x0200);
    CHECK_EQ_HEX(rd(0x0E), 0x4000u | 300u);
    CHECK_EQ_HEX(rd(0x3C), 0x0200);
    CHECK_EQ_HEX(rd(0x3C), 0x0000);
    CHECK_EQ_HEX(rd(0x0E), 300u);
    /* a supply out of range persists from sample to sample */
    {
        struct sim_inertial_input in;
        sim_inertial_at_rest(&in);
        in.supply_v = 5.4;
        sim_adis_imu_set_input(&part, &in);
    }
    wait_ms(2);
    CHECK_EQ_HEX(rd(0x3C), 0x0002);
    wait_ms(2);
    CHECK_EQ_HEX(rd(0x3C), 0x0002);
    CHECK_EQ_INT(board.log.total, 0);
}

static void test_flash_reset_and_protocol(void)
{
    setup(SIM_ADIS16362);
    CHECK_OK(adis_write_reg(&dev, 0x1C, 0x1F00)); /* YGYRO_OFF = -256 */
    CHECK_EQ_HEX(rd(0x1C), 0xFF00);               /* read back sign-extended */
    CHECK_OK(adis_write_reg(&dev, 0x22, 0xFFFF)); /* only 12 bits kept */
    CHECK_EQ_HEX(part.reg[0x22 >> 1], 0x0FFF);
    CHECK_OK(adis_write_byte(&dev, 0x3E, 0x08)); /* flash update */
    CHECK(sim_adis_imu_is_busy(&part));
    wait_ms(SIM_ADIS_IMU_FLASH_UPDATE_MS);
    CHECK_EQ_HEX(rd(0x00), 1);
    CHECK_OK(adis_write_reg(&dev, 0x1C, 0x0005));
    CHECK_OK(adis_write_byte(&dev, 0x3E, 0x80)); /* reset: the flash value comes back */
    wait_ms(60);
    CHECK_EQ_HEX(rd(0x1C), 0xFF00);
    CHECK_EQ_HEX(rd(0x22), 0xFFFF);
    CHECK_OK(adis_write_byte(&dev, 0x3E, 0x02)); /* factory restore */
    wait_ms(SIM_ADIS_IMU_FACTORY_RESTORE_MS);
    CHECK_EQ_HEX(rd(0x1C), 0);
    CHECK_EQ_HEX(rd(0x22), 0);
    CHECK_EQ_INT(board.log.total, 0);
    /* Writes the part does not accept: read-only, SENS_AVG M = 7, unknown range code. */
    CHECK_OK(adis_write_byte(&dev, 0x56, 0x12));
    CHECK_OK(adis_write_byte(&dev, 0x38, 0x07));
    CHECK_OK(adis_write_byte(&dev, 0x39, 0x03));
    CHECK_EQ_HEX(rd(0x56), 0x3FEA);
    CHECK_EQ_HEX(rd(0x38), 0x0402);
    CHECK_EQ_INT(sim_violation_count(&board.log, SIM_VIOL_PROTOCOL), 3);
}

static void test_busy_garbage(void)
{
    setup(SIM_ADIS16405);
    CHECK_OK(adis_write_byte(&dev, 0x3E, 0x01)); /* autonull: busy 50 ms */
    CHECK(rd(0x56) != 0x4015 || sim_violation_count(&board.log, SIM_VIOL_BUSY) > 0u);
    CHECK(sim_violation_count(&board.log, SIM_VIOL_BUSY) >= 1u);
    wait_ms(SIM_ADIS_IMU_AUTONULL_MS);
    CHECK_EQ_HEX(rd(0x56), 0x4015);
}

static void test_burst_limits(void)
{
    uint16_t tx[13] = {0x3E00}, rx[13];
    setup(SIM_ADIS16400);
    wait_ms(1);
    CHECK_OK(spi_dev_set_timing(&dev, &t_burst));
    CHECK_OK(spi_transfer(&dev, tx, rx, 13, SPI_CS_HOLD));
    CHECK_EQ_HEX(rx[1], 0x8000u | 2068u); /* SUPPLY first */
    CHECK_EQ_HEX(rx[6], 0x8000u);         /* YACCL: 0 g, ND */
    CHECK_EQ_HEX(rx[7], 0x8000u | 300u);  /* ZACCL 1 g */
    CHECK_EQ_INT(board.log.total, 0);
    /* At 2 MHz: reported, garbage, SPI failure flagged. */
    CHECK_OK(spi_dev_set_timing(&dev, &t_normal));
    CHECK_OK(spi_transfer(&dev, tx, rx, 13, SPI_CS_HOLD));
    CHECK(sim_violation_count(&board.log, SIM_VIOL_SCLK_FAST) >= 1u);
    CHECK_EQ_HEX(part.diag & 0x0008u, 0x0008);
    /* Low-power mode: a 1 MHz burst breaks the 300 kHz limit (the core keeps it). */
    setup(SIM_ADIS16400);
    wait_ms(1);
    CHECK_OK(adis_write_byte(&dev, 0x36, 0x0A));
    CHECK(part.low_power);
    CHECK_OK(spi_dev_set_timing(&dev, &t_lp));
    wait_ms(1);
    CHECK_OK(spi_dev_set_timing(&dev, &t_burst));
    dev.cfg.timing.stall_ns = 80000;
    CHECK_OK(spi_transfer(&dev, tx, rx, 13, SPI_CS_HOLD));
    CHECK(sim_violation_count(&board.log, SIM_VIOL_SCLK_FAST) >= 1u);
    /* ...and at 300 kHz it is clean. */
    sim_violation_log_init(&board.log);
    wait_ms(1);
    CHECK_OK(spi_dev_set_timing(&dev, &t_lp));
    dev.cfg.timing.gap_ns = 3334;
    CHECK_OK(spi_transfer(&dev, tx, rx, 13, SPI_CS_HOLD));
    CHECK_EQ_INT(board.log.total, 0);
    CHECK_EQ_HEX(rx[7] & 0x3FFFu, 300u);
}

/* Mode 3 by hand on the board's pins: one word at the given SCLK period (CS already low). */
static void bang_word(uint16_t w, uint32_t period)
{
    int b;
    for (b = 15; b >= 0; b--) {
        hal_pin_write(&board.hal, SIM_BOARD_SCLK, false); /* leading edge: the part shifts */
        hal_pin_write(&board.hal, SIM_BOARD_MOSI, ((w >> b) & 1u) != 0u);
        hal_delay_ns(&board.hal, period / 2u);
        hal_pin_write(&board.hal, SIM_BOARD_SCLK, true); /* trailing edge: the part samples */
        hal_delay_ns(&board.hal, period - period / 2u);
    }
}

/* In low-power mode the burst command at 300 kHz followed by words at 1 MHz: the shared core
 * must keep the 300 kHz limit for the words (it used to relax it to the 1 MHz burst limit). */
static void test_burst_keeps_low_power_limit(void)
{
    unsigned k;
    setup(SIM_ADIS16405);
    wait_ms(1);
    CHECK_OK(adis_write_byte(&dev, 0x36, 0x0A));
    REQUIRE(part.low_power);
    wait_ms(1);
    hal_pin_write(&board.hal, SIM_BOARD_CS(0), false);
    hal_delay_ns(&board.hal, 100);
    bang_word(0x3E00, 3334);
    CHECK_EQ_INT(part.core.bursts, 1);
    CHECK_EQ_INT(board.log.total, 0);
    for (k = 0; k < 12u; k++) {
        bang_word(0x0000, 1000);
    }
    hal_delay_ns(&board.hal, 100);
    hal_pin_write(&board.hal, SIM_BOARD_CS(0), true);
    CHECK(sim_violation_count(&board.log, SIM_VIOL_SCLK_FAST) > 0u);
    CHECK_EQ_HEX(part.diag & 0x0008u, 0x0008); /* the part flags the broken frame */
}

static void test_burst_bug_switch(void)
{
    uint16_t tx[13] = {0x3E00}, rx[13];
    struct sim_inertial_input in;
    unsigned k;
    for (k = 0; k < 2u; k++) {
        setup_cfg(SIM_ADIS16405, NULL, k == 1u);
        sim_inertial_at_rest(&in);
        in.rate_dps[0] = -0.4; /* 0x3FF8: bit 13 set */
        sim_adis_imu_set_input(&part, &in);
        wait_ms(200);
        CHECK_OK(adis_write_reg(&dev, 0x1A, 0x1FFF)); /* XGYRO_OFF = -1 LSB: -0.0125 */
        CHECK_OK(spi_dev_set_timing(&dev, &t_burst));
        wait_ms(2);
        CHECK_OK(spi_transfer(&dev, tx, rx, 13, SPI_CS_HOLD));
        CHECK_EQ_HEX(rx[2], 0xBFF8u); /* -8: -0.4125 rounds to -8 counts; EA clear: 0x8000|0x3FF8 */
        wait_ms(2);
        CHECK_OK(spi_transfer(&dev, tx, rx, 13, SPI_CS_HOLD));
        CHECK_EQ_HEX(rx[2], k == 1u ? 0x9FF8u : 0xBFF8u); /* the forum's 0x9FF8 vs 0xBFF8 */
        CHECK_OK(spi_dev_set_timing(&dev, &t_normal));
        CHECK_EQ_INT(board.log.total, 0);
    }
}

/* The physics hook feeds the part; samples come at (NS + 1) x 610351.5625 ns. */
static uint32_t phys_calls;
static void phys_sample(void *ctx, uint64_t t, struct sim_inertial_input *in)
{
    (void)ctx;
    sim_inertial_at_rest(in);
    in->rate_dps[2] = (double)(t / 1000000u) * 0.05; /* 1 count per ms of virtual time */
    phys_calls++;
}

static void test_physics_and_clock(void)
{
    static const struct sim_physics phys = {phys_sample, NULL};
    uint64_t n0;
    uint16_t w;
    phys_calls = 0;
    setup_cfg(SIM_ADIS16364, &phys, false);
    CHECK_OK(adis_write_byte(&dev, 0x38, 0x00)); /* no filter */
    n0 = part.samples;
    wait_ms(1000);
    CHECK(part.samples - n0 == 819u || part.samples - n0 == 820u); /* 1 s at 819.2 SPS */
    CHECK(phys_calls >= 819u);
    w = rd(0x08);
    /* the last sample before now (t ~ 1000 ms, at most one period earlier) */
    CHECK(adis_sign_extend(w, 14) >= 998 && adis_sign_extend(w, 14) <= 1000);
    CHECK_OK(adis_write_byte(&dev, 0x36, 0x81)); /* 62 x tB: 26.4 SPS, low power */
    CHECK(part.low_power);
    n0 = part.samples;
    hal_delay_ms(&board.hal, 1000);
    CHECK(part.samples - n0 == 26u || part.samples - n0 == 27u);
    CHECK_NEAR(sim_adis_imu_rate_sps(&part), 1638.4 / 62.0, 1e-9);
    CHECK_EQ_INT(board.log.total, 0);
}

int main(void)
{
    UNIT_RUN(test_defaults);
    UNIT_RUN(test_nd_ea_and_diag);
    UNIT_RUN(test_flash_reset_and_protocol);
    UNIT_RUN(test_busy_garbage);
    UNIT_RUN(test_burst_limits);
    UNIT_RUN(test_burst_keeps_low_power_limit);
    UNIT_RUN(test_burst_bug_switch);
    UNIT_RUN(test_physics_and_clock);
    return unit_report();
}
