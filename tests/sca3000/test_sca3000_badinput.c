/*
 * SCA3000 bad input (issue 3), each one a case: wrong REVID (init fails naming the REVID found),
 * no device and MISO stuck low or high - at init and at run time - never read as valid data,
 * a genuine all-zero sample still accepted, the part's SPI frame error reported, EEPROM
 * checksum error, a locked-up part, the driver violating the part's timing (the violation log
 * shows it and the driver does not return data), NULL / invalid configuration and arguments.
 */
#include "fixture.h"

#include <stdio.h>
#include <string.h>

/* A second driver on MISO: a short to ground (contends with the part, reads 0). */
static void short_miso_low(void)
{
    int d = sim_pinbus_add_device(&fx.board.bus);
    REQUIRE(d >= 0);
    sim_pinbus_device_drive(&fx.board.bus, (unsigned)d, SIM_BOARD_MISO, false);
}

static void test_wrong_revid(void)
{
    int16_t xyz[3] = {1, 2, 3};
    REQUIRE(fx_setup_part(SIM_SCA3000_D01, 0x41) == 0);
    CHECK_ERR(sca3000_init(&fx.dev, &fx.cfg), INC_ERR_ID);
    CHECK_EQ_HEX(sca3000_revid(&fx.dev), 0x41); /* the part found is named */
    CHECK(!fx.dev.ready);
    CHECK_ERR(sca3000_read_accel(&fx.dev, xyz), INC_ERR_STATE);
    CHECK_EQ_INT(xyz[0], 1);
    /* Configured for that revision, the same part is accepted (init again only after the
     * part's CS-high time: a new binding does not know when CS last rose). */
    fx.cfg.expected_revid = 0x41;
    fx_wait_ns(SCA3000_STALL_NS);
    CHECK_OK(sca3000_init(&fx.dev, &fx.cfg));
    CHECK_OK(sca3000_read_accel(&fx.dev, xyz));
    CHECK_EQ_INT(xyz[2], 1333);
    CHECK_NO_VIOLATIONS();
}

static void test_no_device_or_stuck_miso_at_init(void)
{
    /* No device; the board's MISO pull-up reads all ones. */
    REQUIRE(fx_setup_part(SIM_SCA3000_E02, 0) == 0);
    sim_sca3000_detach(&fx.part);
    CHECK_ERR(sca3000_init(&fx.dev, &fx.cfg), INC_ERR_BUS);
    CHECK_EQ_HEX(sca3000_revid(&fx.dev), 0xFF);
    CHECK(!fx.dev.ready);
    /* No device, pull-down: all zeros. */
    REQUIRE(sim_board_set_miso_pull(&fx.board, SIM_PULL_DOWN) == 0);
    CHECK_ERR(sca3000_init(&fx.dev, &fx.cfg), INC_ERR_BUS);
    CHECK_EQ_HEX(sca3000_revid(&fx.dev), 0x00);
    CHECK_NO_VIOLATIONS();
    /* Part present but MISO shorted low. */
    REQUIRE(fx_setup_part(SIM_SCA3000_E02, 0) == 0);
    short_miso_low();
    CHECK_ERR(sca3000_init(&fx.dev, &fx.cfg), INC_ERR_BUS);
    CHECK_EQ_HEX(sca3000_revid(&fx.dev), 0x00);
    CHECK(sim_violation_count(&fx.board.log, SIM_VIOL_CONTENTION) > 0u);
}

/* After a good init the part disappears and MISO floats to the pull: every call fails. */
static void check_runtime_loss(enum sim_pull pull)
{
    int16_t xyz[3] = {7, 7, 7};
    int16_t vals[8];
    uint16_t t = 77;
    uint8_t st = 0x5A, v = 0x5A;
    unsigned count = 77;
    size_t n = 77;
    REQUIRE(fx_setup(SIM_SCA3000_D01) == 0);
    CHECK_OK(sca3000_read_accel(&fx.dev, xyz));
    CHECK_OK(sca3000_int_config(&fx.dev, SCA3000_INT_RING_1_2, true));
    sim_sca3000_detach(&fx.part);
    REQUIRE(sim_board_set_miso_pull(&fx.board, pull) == 0);
    xyz[0] = xyz[1] = xyz[2] = 7;
    CHECK_ERR(sca3000_read_accel(&fx.dev, xyz), INC_ERR_BUS);
    CHECK(xyz[0] == 7 && xyz[1] == 7 && xyz[2] == 7);
    CHECK_ERR(sca3000_read_temp(&fx.dev, &t), INC_ERR_BUS);
    CHECK_EQ_INT(t, 77);
    CHECK_ERR(sca3000_read_diag(&fx.dev, &st), INC_ERR_BUS);
    CHECK_ERR(sca3000_ring_count(&fx.dev, &count), INC_ERR_BUS);
    CHECK_EQ_INT(count, 77);
    CHECK_ERR(sca3000_ring_read(&fx.dev, vals, 8, &n), INC_ERR_BUS);
    CHECK_EQ_INT(n, 77);
    CHECK_ERR(sca3000_int_status(&fx.dev, &st), INC_ERR_BUS);
    CHECK_ERR(sca3000_set_mode(&fx.dev, SCA3000_MODE_OPTION1), INC_ERR_BUS);
    CHECK_ERR(sca3000_ind_read(&fx.dev, SCA3000_IND_OUT_CTRL, &v), INC_ERR_BUS);
    CHECK_EQ_HEX(v, 0x5A);
    CHECK(fx.dev.bus_errors >= 8u);
    CHECK_NO_VIOLATIONS();
}

static void test_runtime_loss_pull_up(void)
{
    check_runtime_loss(SIM_PULL_UP);
}

static void test_runtime_loss_pull_down(void)
{
    check_runtime_loss(SIM_PULL_DOWN);
}

static void test_runtime_short_low(void)
{
    int16_t xyz[3] = {7, 7, 7};
    REQUIRE(fx_setup(SIM_SCA3000_E05) == 0);
    fx_input(0.3, 0.2, 1.0, 25.0);
    fx_wait_ns(6000000);
    CHECK_OK(sca3000_read_accel(&fx.dev, xyz));
    CHECK_EQ_INT(xyz[0], 48);
    short_miso_low();
    xyz[0] = 7;
    CHECK_ERR(sca3000_read_accel(&fx.dev, xyz), INC_ERR_BUS);
    CHECK_EQ_INT(xyz[0], 7);
}

/* Zero g on all axes (free fall) reads as all-zero bytes: confirmed by REVID, then accepted. */
static void test_genuine_zero_accepted(void)
{
    int16_t xyz[3] = {7, 7, 7};
    REQUIRE(fx_setup(SIM_SCA3000_E04) == 0);
    fx_input(0.0, 0.0, 0.0, 25.0);
    fx_wait_ns(11000000);
    CHECK_OK(sca3000_read_accel(&fx.dev, xyz));
    CHECK(xyz[0] == 0 && xyz[1] == 0 && xyz[2] == 0);
    CHECK_EQ_INT(fx.dev.revid_confirms, 1);
    CHECK_EQ_INT(fx.dev.bus_errors, 0);
    CHECK_NO_VIOLATIONS();
}

/* A corrupt CS period on the wire (a glitch: CS low for three clocks), as EMI would make it. */
static void glitch(void)
{
    const struct hal *h = &fx.board.hal;
    int i;
    hal_delay_ns(h, 20000);
    hal_pin_write(h, FX_CS, false);
    hal_delay_ns(h, 2000);
    for (i = 0; i < 3; i++) {
        hal_pin_write(h, SIM_BOARD_SCLK, false);
        hal_delay_ns(h, 2000);
        hal_pin_write(h, SIM_BOARD_SCLK, true);
        hal_delay_ns(h, 2000);
    }
    hal_delay_ns(h, 2000);
    hal_pin_write(h, FX_CS, true);
    hal_delay_ns(h, 20000);
}

static void test_frame_error_reported(void)
{
    int16_t xyz[3] = {7, 7, 7};
    REQUIRE(fx_setup(SIM_SCA3000_D01) == 0);
    glitch();
    CHECK(fx.part.frame_error);
    CHECK_ERR(sca3000_read_accel(&fx.dev, xyz), INC_ERR_DEVICE);
    CHECK_EQ_HEX(sca3000_last_status(&fx.dev) & SCA3000_STATUS_FRAME, SCA3000_STATUS_FRAME);
    CHECK_EQ_INT(fx.dev.frame_errors, 1);
    CHECK_EQ_INT(xyz[0], 7);                    /* no data from a call that failed */
    CHECK_OK(sca3000_read_accel(&fx.dev, xyz)); /* reported once, then cleared */
    CHECK_EQ_INT(xyz[2], 1333);
    /* The glitch is in the log as what it was, and nothing else is. */
    CHECK_EQ_INT(sim_violation_count(&fx.board.log, SIM_VIOL_PARTIAL_WORD), 1);
    CHECK_EQ_INT(fx.board.log.total, 1);
    /* A frame error left over from before init is cleared by init, not fatal. */
    REQUIRE(fx_setup_part(SIM_SCA3000_D01, 0) == 0);
    glitch();
    CHECK_OK(sca3000_init(&fx.dev, &fx.cfg));
    CHECK(!fx.part.frame_error);
}

static void test_eeprom_checksum(void)
{
    int16_t xyz[3] = {7, 7, 7};
    REQUIRE(fx_setup_part(SIM_SCA3000_E02, 0) == 0);
    sim_sca3000_set_faults(&fx.part, SIM_SCA3000_FAULT_EEPROM);
    CHECK_ERR(sca3000_init(&fx.dev, &fx.cfg), INC_ERR_DEVICE);
    CHECK_EQ_HEX(sca3000_last_status(&fx.dev) & SCA3000_STATUS_EEPROM, SCA3000_STATUS_EEPROM);
    CHECK(!fx.dev.ready);
    REQUIRE(fx_setup(SIM_SCA3000_E02) == 0);
    sim_sca3000_set_faults(&fx.part, SIM_SCA3000_FAULT_EEPROM);
    CHECK_ERR(sca3000_read_accel(&fx.dev, xyz), INC_ERR_DEVICE);
    CHECK_EQ_INT(xyz[0], 7);
    CHECK_NO_VIOLATIONS();
}

/* A part locked up by a reserved-register write (not by this driver) answers zeros: BUS. */
static void test_locked_up_part(void)
{
    struct spi_dev other;
    struct spi_dev_cfg dc;
    const uint16_t tx[2] = {(0x01u << 2) | 2u, 0x00};
    int16_t xyz[3] = {7, 7, 7};
    REQUIRE(fx_setup(SIM_SCA3000_D01) == 0);
    dc = fx.dev.spi.cfg;
    REQUIRE(spi_dev_init(&other, &fx.board.spi.bus, &dc) == 0);
    fx_wait_ns(SCA3000_STALL_NS);
    CHECK_OK(spi_transfer(&other, tx, NULL, 2, SPI_CS_HOLD));
    fx_wait_ns(SCA3000_STALL_NS);
    CHECK(fx.part.locked_up);
    CHECK_ERR(sca3000_read_accel(&fx.dev, xyz), INC_ERR_BUS);
    CHECK_EQ_INT(xyz[0], 7);
}

/* The driver configured faster than the part allows: the log shows it, no data comes back. */
static void check_too_fast(uint32_t period, uint32_t setup, uint32_t stall,
                           enum sim_violation_kind k)
{
    int16_t xyz[3] = {7, 7, 7};
    int err;
    REQUIRE(fx_setup_part(SIM_SCA3000_D01, 0) == 0);
    err = sca3000_init(&fx.dev, &fx.cfg);
    REQUIRE(err == INC_OK);
    /* the bug: the driver's own timing broken after init */
    fx.dev.spi.cfg.timing.sclk_period_ns = period;
    fx.dev.spi.cfg.timing.cs_setup_ns = setup;
    fx.dev.spi.cfg.timing.stall_ns = stall;
    err = sca3000_read_accel(&fx.dev, xyz);
    CHECK(err != INC_OK);
    CHECK(xyz[0] == 7 && xyz[1] == 7 && xyz[2] == 7);
    CHECK(sim_violation_count(&fx.board.log, k) > 0u);
    printf("driver too fast (period %u ns, setup %u ns, stall %u ns): %s; violation log:\n",
           (unsigned)period, (unsigned)setup, (unsigned)stall, inc_err_name(err));
    sim_violation_log_print(&fx.board.log, stdout);
}

static void test_driver_violating_timing(void)
{
    check_too_fast(1000, 1000, 10000, SIM_VIOL_SCLK_FAST);
    check_too_fast(2000, 100, 10000, SIM_VIOL_CS_SETUP);
    check_too_fast(2000, 1000, 2000, SIM_VIOL_STALL);
}

static void test_invalid_config_and_arguments(void)
{
    struct sca3000_cfg c;
    int16_t xyz[3];
    uint8_t b[2];
    size_t n;
    REQUIRE(fx_setup_part(SIM_SCA3000_D01, 0) == 0);
    CHECK_ERR(sca3000_init(NULL, &fx.cfg), INC_ERR_NULL);
    CHECK_ERR(sca3000_init(&fx.dev, NULL), INC_ERR_NULL);
    c = fx.cfg;
    c.bus = NULL;
    CHECK_ERR(sca3000_init(&fx.dev, &c), INC_ERR_NULL);
    c = fx.cfg;
    c.variant = SCA3000_E01;
    CHECK_ERR(sca3000_init(&fx.dev, &c), INC_ERR_UNSUPPORTED);
    c.variant = (enum sca3000_variant)7;
    CHECK_ERR(sca3000_init(&fx.dev, &c), INC_ERR_INVAL);
    c = fx.cfg;
    c.expected_revid = 0xFF;
    CHECK_ERR(sca3000_init(&fx.dev, &c), INC_ERR_INVAL);
    c = fx.cfg;
    c.hal = NULL;
    CHECK_ERR(sca3000_init(&fx.dev, &c), INC_ERR_NULL);
    c = fx.cfg;
    c.cs = HAL_PIN_NONE;
    CHECK_ERR(sca3000_init(&fx.dev, &c), INC_ERR_INVAL);
    CHECK_EQ_INT(fx.part.frames, 0); /* nothing reached the part */

    /* Not initialised (the last init failed). */
    CHECK_ERR(sca3000_read_accel(&fx.dev, xyz), INC_ERR_STATE);
    CHECK_ERR(sca3000_set_mode(&fx.dev, SCA3000_MODE_NORMAL), INC_ERR_STATE);
    CHECK_ERR(sca3000_ring_read(&fx.dev, xyz, 3, &n), INC_ERR_STATE);
    CHECK_ERR(sca3000_read_diag(&fx.dev, NULL), INC_ERR_STATE);
    CHECK_ERR(sca3000_read_accel(NULL, xyz), INC_ERR_NULL);

    /* A usable mode-0 configuration (the part senses it) and the argument checks. */
    c = fx.cfg;
    c.spi_mode0 = true;
    c.int_pin = HAL_PIN_NONE;
    c.hal = NULL;
    REQUIRE(sca3000_init(&fx.dev, &c) == 0);
    CHECK_OK(sca3000_read_accel(&fx.dev, xyz));
    CHECK_EQ_INT(xyz[2], 1333);
    CHECK_ERR(sca3000_read_accel(&fx.dev, NULL), INC_ERR_NULL);
    CHECK_ERR(sca3000_read_temp(&fx.dev, NULL), INC_ERR_NULL);
    CHECK_ERR(sca3000_read_sample(&fx.dev, NULL), INC_ERR_NULL);
    CHECK_ERR(sca3000_read_burst(&fx.dev, SCA3000_REG_X_MSB, b, 0), INC_ERR_INVAL);
    CHECK_ERR(sca3000_read_burst(&fx.dev, SCA3000_REG_X_MSB, b, SCA3000_MAX_BURST + 1u),
              INC_ERR_INVAL);
    CHECK_ERR(sca3000_read_burst(&fx.dev, 0x01, b, 1), INC_ERR_INVAL); /* reserved */
    CHECK_ERR(sca3000_read_burst(&fx.dev, SCA3000_REG_UNLOCK, b, 1), INC_ERR_INVAL);
    CHECK_ERR(sca3000_read_burst(&fx.dev, SCA3000_REG_X_MSB, NULL, 1), INC_ERR_NULL);
    CHECK_ERR(sca3000_ring_config(&fx.dev, 0, 1), INC_ERR_INVAL);
    CHECK_ERR(sca3000_ring_config(&fx.dev, 0x01, 1), INC_ERR_INVAL);
    CHECK_ERR(sca3000_ring_config(&fx.dev, SCA3000_OUT_CTRL_X, 3), INC_ERR_INVAL);
    CHECK_ERR(sca3000_ring_read(&fx.dev, NULL, 3, &n), INC_ERR_NULL);
    CHECK_ERR(sca3000_ring_read(&fx.dev, xyz, 3, NULL), INC_ERR_NULL);
    CHECK_ERR(sca3000_ring_count(&fx.dev, NULL), INC_ERR_NULL);
    CHECK_ERR(sca3000_int_config(&fx.dev, SCA3000_INT_MOTION_X, true), INC_ERR_INVAL);
    CHECK_ERR(sca3000_int_status(&fx.dev, NULL), INC_ERR_NULL);
    CHECK_ERR(sca3000_wait_int(&fx.dev, 1000), INC_ERR_STATE); /* no INT pin */
    CHECK_ERR(sca3000_ind_read(&fx.dev, SCA3000_IND_OUT_CTRL, NULL), INC_ERR_NULL);
    CHECK_NO_VIOLATIONS();
}

int main(void)
{
    UNIT_RUN(test_wrong_revid);
    UNIT_RUN(test_no_device_or_stuck_miso_at_init);
    UNIT_RUN(test_runtime_loss_pull_up);
    UNIT_RUN(test_runtime_loss_pull_down);
    UNIT_RUN(test_runtime_short_low);
    UNIT_RUN(test_genuine_zero_accepted);
    UNIT_RUN(test_frame_error_reported);
    UNIT_RUN(test_eeprom_checksum);
    UNIT_RUN(test_locked_up_part);
    UNIT_RUN(test_driver_violating_timing);
    UNIT_RUN(test_invalid_config_and_arguments);
    return unit_report();
}
