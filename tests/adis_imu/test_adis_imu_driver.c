/*
 * ADIS1636x/1640x driver against the simulated part (pin-level bus, virtual time).
 *
 * Every normal case asserts zero timing/protocol violations; the cases that break a rule on
 * purpose assert the violation they expect. Expected register counts are worked out here from
 * the datasheet scales (docs/sensor-facts.md §3.3), not taken from the model.
 */
#include "fixture.h"
#include "adis_imu_regs.h" /* white-box: the driver's register map */
#include "unit.h"

#include <stdio.h>
#include <string.h>

/* ---- the standard physical input and what each variant must report ---- */

static void input1(struct sim_inertial_input *in)
{
    sim_inertial_at_rest(in);
    in->rate_dps[0] = 10.0;
    in->rate_dps[1] = -20.5;
    in->rate_dps[2] = 123.45;
    in->accel_g[0] = 0.5;
    in->accel_g[1] = -0.25;
    in->accel_g[2] = 0.98;
    in->temp_c = 40.0;
    in->supply_v = 5.0;
}

/* Accelerometer counts of input1 per variant: g / LSB rounded (3.333, 0.333, 1, 3.333 mg). */
static const int32_t accel1[SIM_ADIS_IMU_VARIANTS][3] = {
    {150, -75, 294},    /* 0.5/0.003333 = 150.015, -75.0075, 294.03 */
    {1502, -751, 2943}, /* 0.5/0.000333 = 1501.50, -750.75, 2942.94 */
    {500, -250, 980},   {150, -75, 294}, {150, -75, 294}, {150, -75, 294},
};
/* Physical accel of those counts in Q16.16 g: round(counts x lsb_ug x 65536 / 1e6). */
static const int32_t accel1_q16[SIM_ADIS_IMU_VARIANTS][3] = {
    {32765, -16382, 64219}, {32779, -16389, 64227}, {32768, -16384, 64225},
    {32765, -16382, 64219}, {32765, -16382, 64219}, {32765, -16382, 64219},
};

static bool is_1640x(enum sim_adis_imu_variant v)
{
    return v == SIM_ADIS16400 || v == SIM_ADIS16405;
}

static uint16_t word14(int32_t c)
{
    return (uint16_t)(0x8000u | ((uint32_t)c & 0x3FFFu)); /* ND set, EA clear */
}

static void setup_input1(enum sim_adis_imu_variant v)
{
    struct sim_inertial_input in;
    fx_setup(v);
    input1(&in);
    sim_adis_imu_set_input(&fx.part, &in);
    sim_adis_imu_set_magn(&fx.part, 0.25, -0.1, 0.5);
    sim_adis_imu_set_aux(&fx.part, 1.5);
    fx_set_input_settled(&in);
}

static void check_sample1(enum sim_adis_imu_variant v, const struct adis_imu_sample *s)
{
    struct adis_imu_phys p;
    const uint16_t all = is_1640x(v)
                             ? (uint16_t)(ADIS_IMU_CH_ALL & ~(ADIS_IMU_CH(ADIS_IMU_CH_TEMP1) |
                                                              ADIS_IMU_CH(ADIS_IMU_CH_TEMP2)))
                             : (uint16_t)(ADIS_IMU_CH_ALL & ~ADIS_IMU_CH_MAGNS);
    unsigned i;
    CHECK_EQ_HEX(s->present, all);
    CHECK_EQ_HEX(s->valid, all);
    CHECK_EQ_HEX(s->stale, 0);
    CHECK_EQ_HEX(s->raw[ADIS_IMU_CH_GYRO_X], word14(200));  /* 10 / 0.05 */
    CHECK_EQ_HEX(s->raw[ADIS_IMU_CH_GYRO_Y], word14(-410)); /* -20.5 / 0.05: 0xBE66 */
    CHECK_EQ_HEX(s->raw[ADIS_IMU_CH_GYRO_Z], word14(2469)); /* 123.45 / 0.05 */
    CHECK_EQ_INT(s->counts[ADIS_IMU_CH_GYRO_Y], -410);
    for (i = 0; i < 3u; i++) {
        CHECK_EQ_INT(s->counts[ADIS_IMU_CH_ACCEL_X + i], accel1[v][i]);
        CHECK_EQ_HEX(s->raw[ADIS_IMU_CH_ACCEL_X + i], word14(accel1[v][i]));
    }
    CHECK_EQ_HEX(s->raw[ADIS_IMU_CH_SUPPLY], 0x8000u | 2068u); /* 5 V / 2.418 mV = 0x814 */
    CHECK_EQ_INT(s->counts[ADIS_IMU_CH_AUX], 1862);            /* 1.5 V / 805.8 uV */
    if (is_1640x(v)) {
        CHECK_EQ_INT(s->counts[ADIS_IMU_CH_TEMP0], 107);  /* 15 C / 0.14 */
        CHECK_EQ_INT(s->counts[ADIS_IMU_CH_MAGN_X], 500); /* 0.25 G / 0.5 mG */
        CHECK_EQ_INT(s->counts[ADIS_IMU_CH_MAGN_Y], -200);
        CHECK_EQ_INT(s->counts[ADIS_IMU_CH_MAGN_Z], 1000);
    } else {
        for (i = 0; i < 3u; i++) {
            CHECK_EQ_INT(s->counts[ADIS_IMU_CH_TEMP0 + i], 110); /* 15 C / 0.136 */
        }
    }
    REQUIRE(adis_imu_to_phys(&fx.imu, s, &p) == 0);
    CHECK_EQ_INT(p.gyro_dps[0], 655360);   /* 10.0 deg/s exactly */
    CHECK_EQ_INT(p.gyro_dps[1], -1343488); /* -20.5 */
    CHECK_EQ_INT(p.gyro_dps[2], 8090419);  /* 123.45 x 65536 = 8090419.2 */
    for (i = 0; i < 3u; i++) {
        CHECK_EQ_INT(p.accel_g[i], accel1_q16[v][i]);
    }
    CHECK_EQ_INT(p.supply_v, 327708); /* 2068 x 2.418 mV = 5.000424 V */
    CHECK_EQ_INT(p.aux_v, 98330);     /* 1862 x 805.8 uV = 1.5003996 V */
    if (is_1640x(v)) {
        CHECK_EQ_INT(p.temp_c[0], 2620129);   /* 25 + 107 x 0.14 = 39.98 C */
        CHECK_EQ_INT(p.magn_gauss[1], -6554); /* -0.1 G */
    } else {
        CHECK_EQ_INT(p.temp_c[2], 2618819); /* 25 + 110 x 0.136 = 39.96 C */
    }
}

/* ---- init ---- */

static void test_init_each_variant(void)
{
    unsigned v;
    for (v = 0; v < (unsigned)SIM_ADIS_IMU_VARIANTS; v++) {
        const struct adis_imu_variant_info *vi = adis_imu_variant_info((enum adis_imu_variant)v);
        uint16_t id = 0;
        enum adis_imu_variant found = ADIS_IMU_UNKNOWN;
        fx_setup((enum sim_adis_imu_variant)v);
        CHECK_OK(fx_init());
        CHECK_OK(adis_imu_found(&fx.imu, &id, &found));
        CHECK_EQ_HEX(id, vi->prod_id);
        CHECK_EQ_INT(found, v);
        CHECK(!fx.imu.low_power);
        CHECK_EQ_HEX(fx.imu.smpl_prd, 0x0001u);
        CHECK_EQ_HEX(fx.imu.sens_avg, 0x0402u);
        CHECK_EQ_HEX(fx.imu.msc_ctrl, 0x0006u);
        CHECK_EQ_INT(fx.imu.spi.cfg.timing.sclk_period_ns, 500);
        CHECK_EQ_INT(fx.imu.spi.cfg.timing.stall_ns, ADIS_IMU_STALL_NORMAL_NS);
        CHECK_EQ_INT(fx_violations(), 0);
    }
    /* ANY accepts the part and says which one it is; reset and self-test at init. */
    fx_setup(SIM_ADIS16362);
    fx.cfg.variant = ADIS_IMU_ANY;
    fx.cfg.reset_at_init = true;
    fx.cfg.self_test_at_init = true;
    CHECK_OK(fx_init());
    CHECK_EQ_INT(fx.imu.found_variant, ADIS_IMU_ADIS16362);
    CHECK_EQ_INT(fx.part.commands, 1);
    CHECK_EQ_INT(fx_violations(), 0);
}

static void test_wrong_prod_id(void)
{
    uint16_t id = 0;
    enum adis_imu_variant found = ADIS_IMU_ANY;
    struct adis_imu_sample s;
    fx_setup(SIM_ADIS16405);
    fx.cfg.variant = ADIS_IMU_ADIS16400;
    CHECK_ERR(fx_init(), INC_ERR_ID);
    CHECK_OK(adis_imu_found(&fx.imu, &id, &found));
    CHECK_EQ_HEX(id, 0x4015);
    CHECK_EQ_INT(found, ADIS_IMU_ADIS16405);
    CHECK(strcmp(adis_imu_variant_name(found), "ADIS16405") == 0);
    CHECK_ERR(adis_imu_read_sample(&fx.imu, &s), INC_ERR_STATE); /* no use after a failed init */
    /* A PROD_ID of no known part: reported as found, named "unknown". */
    fx_setup(SIM_ADIS16364);
    fx.part.reg[0x56 >> 1] = 0x3FEF; /* ADIS16367, not supported */
    CHECK_ERR(fx_init(), INC_ERR_ID);
    CHECK_OK(adis_imu_found(&fx.imu, &id, &found));
    CHECK_EQ_HEX(id, 0x3FEF);
    CHECK_EQ_INT(found, ADIS_IMU_UNKNOWN);
    CHECK(strcmp(adis_imu_variant_name(found), "unknown") == 0);
    fx.cfg.variant = ADIS_IMU_ANY;
    CHECK_ERR(fx_init(), INC_ERR_ID);
    CHECK_EQ_INT(fx_violations(), 0);
}

static void test_no_device_at_init(void)
{
    /* Nothing on the bus: MISO's pull-up reads 0xFFFF. */
    fx_setup(SIM_ADIS16400);
    sim_spi_slave_detach(&fx.part.core.slave);
    CHECK_ERR(fx_init(), INC_ERR_BUS);
    CHECK_EQ_HEX(fx.imu.found_id, 0xFFFF);
    /* MISO stuck low (or a pull-down): 0x0000. */
    CHECK_OK(sim_board_set_miso_pull(&fx.board, SIM_PULL_DOWN));
    CHECK_ERR(fx_init(), INC_ERR_BUS);
    CHECK_EQ_HEX(fx.imu.found_id, 0x0000);
    CHECK(!fx.imu.ready);
}

/* The caller skipped the power-on wait: the part is busy and answers garbage. The driver must
 * not accept it, and the log shows what went wrong. */
static void test_init_too_early_shows_violation(void)
{
    int err;
    fx_prepare(SIM_ADIS16405);
    sim_adis_imu_init(&fx.part, &fx.part_cfg);
    err = fx_init();
    CHECK(err == INC_ERR_ID || err == INC_ERR_BUS);
    CHECK(!fx.imu.ready);
    CHECK(sim_violation_count(&fx.board.log, SIM_VIOL_BUSY) >= 1u);
    printf("expected violations:\n");
    CHECK(fx_violations() > 0u);
}

/* ---- reads ---- */

static void test_burst_exact_each_variant(void)
{
    unsigned v;
    for (v = 0; v < (unsigned)SIM_ADIS_IMU_VARIANTS; v++) {
        struct adis_imu_sample s;
        setup_input1((enum sim_adis_imu_variant)v);
        REQUIRE(fx_init() == 0);
        CHECK_OK(adis_imu_wait_ready(&fx.imu, 0, NULL));
        CHECK_OK(adis_imu_read_sample(&fx.imu, &s));
        check_sample1((enum sim_adis_imu_variant)v, &s);
        CHECK_EQ_INT(fx.part.core.bursts, 1);
        /* the device timing is back to normal mode after the burst */
        CHECK_EQ_INT(fx.imu.spi.cfg.timing.sclk_period_ns, 500);
        CHECK_EQ_INT(fx_violations(), 0);
    }
}

static void test_registers_exact_each_variant(void)
{
    unsigned v;
    for (v = 0; v < (unsigned)SIM_ADIS_IMU_VARIANTS; v++) {
        struct adis_imu_sample s;
        setup_input1((enum sim_adis_imu_variant)v);
        REQUIRE(fx_init() == 0);
        CHECK_OK(adis_imu_wait_ready(&fx.imu, 0, NULL));
        CHECK_OK(adis_imu_read_channels(&fx.imu, ADIS_IMU_CH_ALL, &s));
        check_sample1((enum sim_adis_imu_variant)v, &s);
        CHECK_EQ_INT(fx.part.core.bursts, 0);
        /* a subset: only what was asked is present */
        CHECK_OK(adis_imu_wait_ready(&fx.imu, 0, NULL));
        CHECK_OK(adis_imu_read_channels(&fx.imu, ADIS_IMU_CH_GYROS, &s));
        CHECK_EQ_HEX(s.present, ADIS_IMU_CH_GYROS);
        CHECK_EQ_INT(s.counts[ADIS_IMU_CH_GYRO_Z], 2469);
        CHECK_EQ_INT(s.counts[ADIS_IMU_CH_ACCEL_X], 0);
        CHECK_EQ_INT(fx_violations(), 0);
    }
}

static void test_stale(void)
{
    struct adis_imu_sample s;
    struct adis_imu_phys p;
    setup_input1(SIM_ADIS16400);
    REQUIRE(fx_init() == 0);
    CHECK_OK(adis_imu_wait_ready(&fx.imu, 0, NULL));
    CHECK_OK(adis_imu_read_sample(&fx.imu, &s));
    /* Again before the next sample: ND is clear in every word. */
    CHECK_ERR(adis_imu_read_sample(&fx.imu, &s), INC_ERR_STALE);
    CHECK_EQ_HEX(s.valid, 0);
    CHECK_EQ_HEX(s.stale, s.present);
    CHECK_EQ_INT(s.counts[ADIS_IMU_CH_GYRO_X], 200); /* the data is there, but not valid */
    CHECK_OK(adis_imu_to_phys(&fx.imu, &s, &p));
    CHECK_EQ_INT(p.gyro_dps[0], 0); /* ...and never converted */
    /* Non-burst: one stale channel among fresh ones is flagged alone. */
    CHECK_OK(adis_imu_wait_ready(&fx.imu, 0, NULL));
    CHECK_OK(adis_imu_read_channels(&fx.imu, ADIS_IMU_CH(ADIS_IMU_CH_GYRO_X), &s));
    CHECK_ERR(adis_imu_read_channels(&fx.imu, ADIS_IMU_CH_GYROS, &s), INC_ERR_STALE);
    CHECK_EQ_HEX(s.stale, ADIS_IMU_CH(ADIS_IMU_CH_GYRO_X));
    CHECK_EQ_HEX(s.valid, ADIS_IMU_CH(ADIS_IMU_CH_GYRO_Y) | ADIS_IMU_CH(ADIS_IMU_CH_GYRO_Z));
    /* Still gyros read twice at zero rate: equal 0x0000 words, yet a live part -> stale. */
    fx_set_input_settled(&(struct sim_inertial_input){{0, 0, 0}, {0, 0, 1}, 25.0, 5.0});
    CHECK_OK(adis_imu_wait_ready(&fx.imu, 0, NULL));
    CHECK_OK(adis_imu_read_channels(&fx.imu, ADIS_IMU_CH_GYROS, &s));
    CHECK_ERR(adis_imu_read_channels(&fx.imu, ADIS_IMU_CH_GYROS, &s), INC_ERR_STALE);
    CHECK_EQ_HEX(s.raw[ADIS_IMU_CH_GYRO_X], 0x0000);
    CHECK_EQ_INT(fx.imu.stale_reads, 3);
    CHECK_EQ_INT(fx_violations(), 0);
}

static void test_error_flags(void)
{
    struct adis_imu_sample s;
    struct adis_imu_diag d;
    struct sim_inertial_input in;
    setup_input1(SIM_ADIS16364);
    REQUIRE(fx_init() == 0);
    /* An alarm: EA in every word, DIAG_STAT read, decoded, no value valid. */
    sim_adis_imu_raise_diag(&fx.part, 0x0100u);
    CHECK_OK(adis_imu_wait_ready(&fx.imu, 0, NULL));
    CHECK_ERR(adis_imu_read_sample(&fx.imu, &s), INC_ERR_DEVICE);
    CHECK_EQ_HEX(s.diag, 0x0100);
    CHECK_EQ_HEX(s.valid, 0);
    CHECK(s.raw[ADIS_IMU_CH_GYRO_X] & ADIS_FLAG_EA);
    adis_imu_diag_decode(s.diag, &d);
    CHECK(d.alarm1 && d.any && !d.alarm2 && !d.spi_fail);
    /* DIAG_STAT cleared on read: the next sample is clean. */
    CHECK_OK(adis_imu_wait_ready(&fx.imu, 0, NULL));
    CHECK_OK(adis_imu_read_sample(&fx.imu, &s));
    /* Supply below 4.75 V: the condition persists, so does the error. */
    input1(&in);
    in.supply_v = 4.6;
    sim_adis_imu_set_input(&fx.part, &in);
    CHECK_OK(adis_imu_wait_ready(&fx.imu, 0, NULL));
    CHECK_ERR(adis_imu_read_channels(&fx.imu, ADIS_IMU_CH_ALL, &s), INC_ERR_DEVICE);
    CHECK_EQ_HEX(s.diag, 0x0001);
    CHECK_OK(adis_imu_wait_ready(&fx.imu, 0, NULL));
    CHECK_ERR(adis_imu_read_sample(&fx.imu, &s), INC_ERR_DEVICE);
    adis_imu_diag_decode(s.diag, &d);
    CHECK(d.supply_low);
    /* Over range: 400 deg/s clips at 6000 counts and raises DIAG_STAT[4]. */
    input1(&in);
    in.rate_dps[0] = 400.0;
    fx_set_input_settled(&in);
    CHECK_ERR(adis_imu_read_sample(&fx.imu, &s), INC_ERR_DEVICE);
    CHECK_EQ_HEX(s.diag, 0x0010);
    CHECK_EQ_INT(s.counts[ADIS_IMU_CH_GYRO_X], 6000);
    CHECK_EQ_INT(fx.imu.device_errors, 4);
    CHECK_EQ_INT(fx_violations(), 0);
}

/* A frame the part could not decode (here 8 clocks instead of 16) sets DIAG_STAT[3]; the
 * driver's next read reports it. */
static void test_spi_failure_reported(void)
{
    struct spi_dev bad;
    struct spi_dev_cfg dc = {SIM_BOARD_CS(0), SPI_MODE_3, 8, {500, 100, 100, 10000, 0}};
    struct adis_imu_sample s;
    struct adis_imu_diag d;
    setup_input1(SIM_ADIS16405);
    REQUIRE(fx_init() == 0);
    REQUIRE(spi_dev_init(&bad, &fx.board.spi.bus, &dc) == 0);
    fx_wait_ms(1);
    CHECK_OK(spi_xfer1(&bad, 0x56, NULL));
    CHECK_EQ_INT(sim_violation_count(&fx.board.log, SIM_VIOL_PARTIAL_WORD), 1);
    CHECK_EQ_INT(fx.board.log.total, 1);
    fx_wait_ms(1);
    CHECK_ERR(adis_imu_read_sample(&fx.imu, &s), INC_ERR_DEVICE);
    adis_imu_diag_decode(s.diag, &d);
    CHECK(d.spi_fail);
    CHECK_EQ_HEX(fx.imu.last_diag, ADIS_IMU_DIAG_SPI_FAIL);
    CHECK_EQ_INT(fx.board.log.total, 1); /* nothing else */
}

static void test_bus_stuck_at_run_time(void)
{
    struct adis_imu_sample s;
    setup_input1(SIM_ADIS16400);
    REQUIRE(fx_init() == 0);
    CHECK_OK(adis_imu_wait_ready(&fx.imu, 0, NULL));
    CHECK_OK(adis_imu_read_sample(&fx.imu, &s));
    /* The part drops off the bus: MISO floats high. */
    sim_spi_slave_detach(&fx.part.core.slave);
    CHECK_ERR(adis_imu_read_sample(&fx.imu, &s), INC_ERR_BUS);
    CHECK_EQ_HEX(s.valid, 0);
    CHECK_ERR(adis_imu_read_channels(&fx.imu, ADIS_IMU_CH_GYROS, &s), INC_ERR_BUS);
    CHECK_ERR(adis_imu_read_channels(&fx.imu, ADIS_IMU_CH(ADIS_IMU_CH_GYRO_Z), &s), INC_ERR_BUS);
    /* MISO stuck low. */
    CHECK_OK(sim_board_set_miso_pull(&fx.board, SIM_PULL_DOWN));
    CHECK_ERR(adis_imu_read_sample(&fx.imu, &s), INC_ERR_BUS);
    CHECK_ERR(adis_imu_read_channels(&fx.imu, ADIS_IMU_CH_ALL, &s), INC_ERR_BUS);
    CHECK_ERR(adis_imu_read_channels(&fx.imu, ADIS_IMU_CH(ADIS_IMU_CH_SUPPLY), &s), INC_ERR_BUS);
    CHECK_EQ_HEX(s.valid, 0);
    CHECK_EQ_INT(fx.imu.bus_errors, 6);
}

/* ---- sample rate, SCLK and filter ---- */

static void test_sample_period_and_sclk(void)
{
    struct adis_imu_sample s;
    uint64_t t0, t1;
    setup_input1(SIM_ADIS16405);
    REQUIRE(fx_init() == 0);
    /* 0x0A: 148.9 SPS, low-power mode: 300 kHz and the long stall. */
    CHECK_OK(adis_imu_set_sample_period(&fx.imu, 0x0A));
    CHECK(fx.imu.low_power);
    CHECK(fx.part.low_power);
    CHECK_EQ_INT(fx.imu.spi.cfg.timing.sclk_period_ns, 3334);
    CHECK_EQ_INT(fx.imu.spi.cfg.timing.stall_ns, ADIS_IMU_STALL_LOW_POWER_NS);
    CHECK_EQ_INT(adis_imu_current_period_ns(&fx.imu), 6713867); /* 11 x 610351.5625 */
    CHECK_OK(adis_imu_wait_ready(&fx.imu, 0, NULL));
    t0 = fx.board.clk.now_ns;
    CHECK_OK(adis_imu_read_sample(&fx.imu, &s));
    CHECK_EQ_INT(s.counts[ADIS_IMU_CH_GYRO_X], 200);
    CHECK_OK(adis_imu_wait_ready(&fx.imu, 0, NULL));
    t1 = fx.board.clk.now_ns;
    CHECK_NEAR_INT(t1 - t0, 6713867, 1);
    CHECK_OK(adis_imu_read_channels(&fx.imu, ADIS_IMU_CH_ALL, &s));
    /* Time base bit: still low power. */
    CHECK_OK(adis_imu_set_sample_period(&fx.imu, 0x81));
    CHECK(fx.imu.low_power);
    CHECK_EQ_INT(adis_imu_current_period_ns(&fx.imu), 37841797); /* 62 x tB */
    CHECK_OK(adis_imu_wait_ready(&fx.imu, 0, NULL));
    CHECK_OK(adis_imu_read_sample(&fx.imu, &s));
    /* Back to normal mode at the boundary 0x09 (163.84 SPS). */
    CHECK_OK(adis_imu_set_sample_period(&fx.imu, 0x09));
    CHECK(!fx.imu.low_power);
    CHECK(!fx.part.low_power);
    CHECK_EQ_INT(fx.imu.spi.cfg.timing.sclk_period_ns, 500);
    CHECK_OK(adis_imu_wait_ready(&fx.imu, 0, NULL));
    CHECK_OK(adis_imu_read_channels(&fx.imu, ADIS_IMU_CH_ALL, &s));
    CHECK_NEAR(sim_adis_imu_rate_sps(&fx.part), 163.84, 1e-9);
    CHECK_EQ_INT(fx_violations(), 0);
}

/* The part changes to low-power mode behind the driver's back: the driver's 2 MHz frames and
 * short stall break the part's limits, the log shows it and no value comes out valid. */
static void test_wrong_sclk_shows_violation(void)
{
    struct adis_imu_sample s;
    int err;
    setup_input1(SIM_ADIS16360);
    REQUIRE(fx_init() == 0);
    sim_adis_imu_poke(&fx.part, 0x36, 0x0014);
    err = adis_imu_read_channels(&fx.imu, ADIS_IMU_CH_ALL, &s);
    CHECK(err != INC_OK);
    CHECK_EQ_HEX(s.valid, 0);
    CHECK(sim_violation_count(&fx.board.log, SIM_VIOL_SCLK_FAST) > 0u);
    CHECK(sim_violation_count(&fx.board.log, SIM_VIOL_STALL) > 0u);
    printf("expected violations (err %s):\n", inc_err_name(err));
    CHECK(fx_violations() > 0u);
}

static void test_filter_and_range(void)
{
    struct adis_imu_sample s;
    struct adis_imu_phys p;
    struct sim_inertial_input in;
    /* Step response of the default filter (M = 2: two 4-tap averages): 8 deg/s arrives as
     * 8 x {1, 3, 6, 10, 13, 15, 16} / 16 = 0.5, 1.5, 3, 5, 6.5, 7.5, 8 deg/s. */
    static const int32_t step[8] = {10, 30, 60, 100, 130, 150, 160, 160};
    unsigned k;
    fx_setup(SIM_ADIS16400);
    REQUIRE(fx_init() == 0);
    sim_inertial_at_rest(&in);
    fx_set_input_settled(&in);
    CHECK_OK(adis_imu_wait_ready(&fx.imu, 0, NULL));
    in.rate_dps[0] = 8.0;
    sim_adis_imu_set_input(&fx.part, &in);
    for (k = 0; k < 8u; k++) {
        CHECK_OK(adis_imu_wait_ready(&fx.imu, 0, NULL));
        CHECK_OK(adis_imu_read_sample(&fx.imu, &s));
        CHECK_EQ_INT(s.counts[ADIS_IMU_CH_GYRO_X], step[k]);
    }
    /* M = 0: no filter, the step passes in one sample. */
    CHECK_OK(adis_imu_set_filter(&fx.imu, 0, ADIS_IMU_RANGE_300));
    CHECK_EQ_HEX(fx.part.reg[0x38 >> 1], 0x0400);
    in.rate_dps[0] = -3.0;
    CHECK_OK(adis_imu_wait_ready(&fx.imu, 0, NULL));
    sim_adis_imu_set_input(&fx.part, &in);
    CHECK_OK(adis_imu_wait_ready(&fx.imu, 0, NULL));
    CHECK_OK(adis_imu_read_sample(&fx.imu, &s));
    CHECK_EQ_INT(s.counts[ADIS_IMU_CH_GYRO_X], -60);
    /* +-75 deg/s needs M >= 4 [U]: LSB 0.0125, so -3 deg/s is -240 counts. */
    CHECK_ERR(adis_imu_set_filter(&fx.imu, 3, ADIS_IMU_RANGE_75), INC_ERR_INVAL);
    CHECK_OK(adis_imu_set_filter(&fx.imu, 4, ADIS_IMU_RANGE_75));
    CHECK_EQ_HEX(fx.part.reg[0x38 >> 1], 0x0104);
    CHECK_EQ_INT(adis_imu_gyro_range(&fx.imu), ADIS_IMU_RANGE_75);
    fx_set_input_settled(&in);
    CHECK_OK(adis_imu_read_sample(&fx.imu, &s));
    CHECK_EQ_INT(s.counts[ADIS_IMU_CH_GYRO_X], -240);
    CHECK_OK(adis_imu_to_phys(&fx.imu, &s, &p));
    CHECK_EQ_INT(p.gyro_dps[0], -3 * 65536);
    CHECK_EQ_INT(s.gyro_range, ADIS_IMU_RANGE_75);
    /* +-150 with M = 2 (shrinking taps: the range byte goes first, no illegal step). */
    CHECK_OK(adis_imu_set_filter(&fx.imu, 2, ADIS_IMU_RANGE_150));
    CHECK_EQ_HEX(fx.part.reg[0x38 >> 1], 0x0202);
    fx_set_input_settled(&in);
    CHECK_OK(adis_imu_read_sample(&fx.imu, &s));
    CHECK_EQ_INT(s.counts[ADIS_IMU_CH_GYRO_X], -120);
    /* a sample keeps the scale it was read with: converted after another range change */
    CHECK_OK(adis_imu_set_filter(&fx.imu, 4, ADIS_IMU_RANGE_75));
    CHECK_OK(adis_imu_to_phys(&fx.imu, &s, &p));
    CHECK_EQ_INT(p.gyro_dps[0], -3 * 65536);
    CHECK_ERR(adis_imu_set_filter(&fx.imu, 1, ADIS_IMU_RANGE_150), INC_ERR_INVAL);
    CHECK_ERR(adis_imu_set_filter(&fx.imu, 7, ADIS_IMU_RANGE_300), INC_ERR_INVAL);
    CHECK_ERR(adis_imu_set_filter(&fx.imu, 2, (enum adis_imu_range)3), INC_ERR_INVAL);
    CHECK_EQ_INT(fx.part.protocol_errors, 0);
    CHECK_EQ_INT(fx_violations(), 0);
}

/* ---- commands ---- */

static void test_flash_update_restore_reset(void)
{
    uint16_t cnt0 = 0, cnt1 = 0;
    int32_t off = 0;
    fx_setup(SIM_ADIS16405);
    REQUIRE(fx_init() == 0);
    CHECK_OK(adis_imu_read_reg(&fx.imu, ADIS_IMU_REG_FLASH_CNT, &cnt0));
    /* Flash update: FLASH_CNT counts it. */
    CHECK_OK(adis_imu_set_gyro_offset(&fx.imu, 1, -123));
    CHECK_OK(adis_imu_set_sample_period(&fx.imu, 0x0A));
    CHECK_OK(adis_imu_command(&fx.imu, ADIS_IMU_CMD_FLASH_UPDATE));
    CHECK_OK(adis_imu_read_reg(&fx.imu, ADIS_IMU_REG_FLASH_CNT, &cnt1));
    CHECK_EQ_INT(cnt1, cnt0 + 1u);
    /* Not stored: normal mode and another offset. */
    CHECK_OK(adis_imu_set_sample_period(&fx.imu, 0x01));
    CHECK_OK(adis_imu_set_gyro_offset(&fx.imu, 1, 77));
    /* Reset: the flash values come back; the driver re-reads them and re-times the bus. */
    CHECK_OK(adis_imu_command(&fx.imu, ADIS_IMU_CMD_SW_RESET));
    CHECK(fx.imu.low_power);
    CHECK_EQ_HEX(fx.imu.smpl_prd, 0x0A);
    CHECK_OK(adis_imu_get_gyro_offset(&fx.imu, 1, &off));
    CHECK_EQ_INT(off, -123);
    /* Data-ready is put back as configured (here it was stored enabled anyway). */
    CHECK_OK(adis_imu_wait_ready(&fx.imu, 0, NULL));
    /* Factory restore: offsets to zero. */
    CHECK_OK(adis_imu_command(&fx.imu, ADIS_IMU_CMD_FACTORY_RESTORE));
    CHECK_OK(adis_imu_get_gyro_offset(&fx.imu, 1, &off));
    CHECK_EQ_INT(off, 0);
    CHECK_EQ_INT(fx.part.flash_writes, 1);
    /* AUX DAC latch takes no time. */
    CHECK_EQ_INT(adis_imu_command_ms(&fx.imu, ADIS_IMU_CMD_AUX_DAC_LATCH), 0);
    CHECK_OK(adis_imu_command(&fx.imu, ADIS_IMU_CMD_AUX_DAC_LATCH));
    CHECK(!adis_imu_busy(&fx.imu));
    CHECK_EQ_INT(fx.part.commands, 4);
    CHECK_EQ_INT(adis_imu_command_ms(&fx.imu, ADIS_IMU_CMD_SW_RESET), 170);
    CHECK_EQ_INT(adis_imu_command_ms(&fx.imu, ADIS_IMU_CMD_PRECISION_AUTONULL), 30000);
    CHECK_EQ_INT(fx_violations(), 0);
}

/* A command issued while the part executes another one is not lost: the driver waits. */
static void test_busy_not_lost(void)
{
    uint16_t cnt = 0;
    int32_t off = 0;
    uint64_t t0;
    fx_setup(SIM_ADIS16364);
    REQUIRE(fx_init() == 0);
    CHECK_OK(adis_imu_set_gyro_offset(&fx.imu, 0, 500));
    t0 = fx.board.clk.now_ns;
    CHECK_OK(adis_imu_command_start(&fx.imu, ADIS_IMU_CMD_FLASH_UPDATE));
    CHECK(adis_imu_busy(&fx.imu));
    CHECK(sim_adis_imu_is_busy(&fx.part));
    CHECK_OK(adis_imu_command_start(&fx.imu, ADIS_IMU_CMD_FACTORY_RESTORE));
    CHECK(fx.board.clk.now_ns - t0 >= (uint64_t)ADIS_IMU_FLASH_UPDATE_MS * 1000000u);
    CHECK_OK(adis_imu_read_reg(&fx.imu, ADIS_IMU_REG_FLASH_CNT, &cnt)); /* waits again */
    CHECK_EQ_INT(cnt, 1);
    CHECK_OK(adis_imu_get_gyro_offset(&fx.imu, 0, &off));
    CHECK_EQ_INT(off, 0);
    CHECK_EQ_INT(fx.part.commands, 2);
    CHECK(!adis_imu_busy(&fx.imu));
    CHECK_EQ_INT(fx_violations(), 0);
    /* A driver that ignored the busy time: the part drops the command and the log shows it. */
    CHECK_OK(adis_imu_command_start(&fx.imu, ADIS_IMU_CMD_FLASH_UPDATE));
    fx.imu.busy_until_ns = 0;
    CHECK_OK(adis_imu_command_start(&fx.imu, ADIS_IMU_CMD_FLASH_UPDATE));
    CHECK_EQ_INT(fx.part.commands, 3);
    CHECK_EQ_INT(sim_violation_count(&fx.board.log, SIM_VIOL_BUSY), 1);
    printf("expected violation:\n");
    CHECK_EQ_INT(fx_violations(), 1);
}

static void test_offsets(void)
{
    struct adis_imu_sample s;
    struct sim_inertial_input in;
    int32_t c = 0;
    fx_setup(SIM_ADIS16364);
    REQUIRE(fx_init() == 0);
    sim_inertial_at_rest(&in);
    fx_set_input_settled(&in);
    /* Full 13-bit range, read back sign-extended; beyond it nothing is written. */
    CHECK_OK(adis_imu_set_gyro_offset(&fx.imu, 2, 4095));
    CHECK_OK(adis_imu_get_gyro_offset(&fx.imu, 2, &c));
    CHECK_EQ_INT(c, 4095);
    CHECK_OK(adis_imu_set_gyro_offset(&fx.imu, 2, -4096));
    CHECK_OK(adis_imu_get_gyro_offset(&fx.imu, 2, &c));
    CHECK_EQ_INT(c, -4096);
    CHECK_EQ_HEX(fx.part.reg[0x1E >> 1], 0x1000);
    CHECK_ERR(adis_imu_set_gyro_offset(&fx.imu, 2, 4096), INC_ERR_RANGE);
    CHECK_ERR(adis_imu_set_gyro_offset(&fx.imu, 2, -4097), INC_ERR_RANGE);
    CHECK_ERR(adis_imu_set_gyro_offset(&fx.imu, 3, 0), INC_ERR_INVAL);
    CHECK_OK(adis_imu_get_gyro_offset(&fx.imu, 2, &c));
    CHECK_EQ_INT(c, -4096);
    /* Effect on the output (offset adds [U]): +80 LSB = +1 deg/s = +20 output counts. */
    CHECK_OK(adis_imu_set_gyro_offset(&fx.imu, 0, 80));
    CHECK_OK(
        adis_imu_set_gyro_offset(&fx.imu, 1, adis_imu_gyro_off_counts_from_dps(-65536 / 2, NULL)));
    CHECK_OK(adis_imu_dr_flush(&fx.imu)); /* a sample taken with the new offsets */
    CHECK_OK(adis_imu_wait_ready(&fx.imu, 0, NULL));
    CHECK_OK(adis_imu_read_sample(&fx.imu, &s));
    CHECK_EQ_INT(s.counts[ADIS_IMU_CH_GYRO_X], 20);
    CHECK_EQ_INT(s.counts[ADIS_IMU_CH_GYRO_Y], -10);
    CHECK_EQ_INT(s.counts[ADIS_IMU_CH_GYRO_Z], -4096 / 4); /* -51.2 deg/s */
    /* Accelerometer offset: 12-bit, at the output LSB [U] (1 mg on the ADIS16364). */
    CHECK_OK(adis_imu_set_accel_offset(&fx.imu, 0, -2048));
    CHECK_OK(adis_imu_get_accel_offset(&fx.imu, 0, &c));
    CHECK_EQ_INT(c, -2048);
    CHECK_ERR(adis_imu_set_accel_offset(&fx.imu, 0, 2048), INC_ERR_RANGE);
    CHECK_OK(adis_imu_set_accel_offset(&fx.imu, 2, 25));
    CHECK_OK(adis_imu_dr_flush(&fx.imu));
    CHECK_OK(adis_imu_wait_ready(&fx.imu, 0, NULL));
    CHECK_OK(adis_imu_read_sample(&fx.imu, &s));
    CHECK_EQ_INT(s.counts[ADIS_IMU_CH_ACCEL_X], -2048);
    CHECK_EQ_INT(s.counts[ADIS_IMU_CH_ACCEL_Z], 1025);
    CHECK_EQ_INT(fx_violations(), 0);
}

/* ---- data-ready and self-test ---- */

static void test_data_ready(void)
{
    struct adis_imu_sample s;
    uint32_t missed = 99;
    uint64_t t0;
    unsigned k;
    setup_input1(SIM_ADIS16362);
    /* DR on DIO2, active low, wired to dr1. */
    fx.cfg.dr_pin = SIM_BOARD_DR(1);
    fx.cfg.dr_line = ADIS_IMU_DR_DIO2;
    fx.cfg.dr_active_low = true;
    REQUIRE(fx_init() == 0);
    CHECK_EQ_HEX(fx.part.reg[0x34 >> 1], 0x0005);
    CHECK_OK(adis_imu_wait_ready(&fx.imu, 0, &missed));
    t0 = fx.board.clk.now_ns;
    for (k = 0; k < 10u; k++) {
        CHECK_OK(adis_imu_wait_ready(&fx.imu, 0, &missed));
        CHECK_EQ_INT(missed, 0);
        /* one edge per sample period (1220703.125 ns) */
        CHECK_NEAR_INT(fx.board.clk.now_ns - t0, 1220703, 1);
        t0 = fx.board.clk.now_ns;
        CHECK_OK(adis_imu_read_sample(&fx.imu, &s));
    }
    /* Samples not read are counted. */
    fx_wait_ms(5);
    CHECK_OK(adis_imu_wait_ready(&fx.imu, 0, &missed));
    CHECK_EQ_INT(missed, 3); /* 5 ms = 4 samples: one consumed, three missed */
    /* DR wired to the wrong line: the edge never comes -> timeout, not a stale read. */
    fx_setup(SIM_ADIS16362);
    fx.cfg.dr_pin = SIM_BOARD_DR(1); /* but the part drives DIO1 = dr0 */
    REQUIRE(fx_init() == 0);
    CHECK_ERR(adis_imu_wait_ready(&fx.imu, 0, NULL), INC_ERR_TIMEOUT);
    CHECK_ERR(adis_imu_wait_ready(&fx.imu, 10000000u, NULL), INC_ERR_TIMEOUT);
    CHECK_EQ_INT(fx.imu.timeouts, 2);
    /* The part stops data-ready (MSC_CTRL[2] cleared elsewhere): missed data-ready. */
    fx_setup(SIM_ADIS16362);
    REQUIRE(fx_init() == 0);
    CHECK_OK(adis_imu_wait_ready(&fx.imu, 0, NULL));
    sim_adis_imu_poke(&fx.part, 0x34, 0x0002);
    CHECK_ERR(adis_imu_wait_ready(&fx.imu, 0, NULL), INC_ERR_TIMEOUT);
    /* Disabled in the driver: waiting is refused. */
    CHECK_OK(adis_imu_dr_config(&fx.imu, false, ADIS_IMU_DR_DIO1, false));
    CHECK_EQ_HEX(fx.part.reg[0x34 >> 1], 0x0000);
    CHECK_ERR(adis_imu_wait_ready(&fx.imu, 0, NULL), INC_ERR_STATE);
    CHECK_EQ_INT(fx_violations(), 0);
}

static void test_self_test(void)
{
    uint16_t diag = 0xFFFF;
    struct adis_imu_diag d;
    fx_setup(SIM_ADIS16400);
    REQUIRE(fx_init() == 0);
    CHECK_OK(adis_imu_self_test(&fx.imu, &diag));
    CHECK_EQ_HEX(diag, 0);
    CHECK_EQ_HEX(fx.part.reg[0x34 >> 1] & 0x0400u, 0); /* cleared itself */
    sim_adis_imu_set_self_test_fail(&fx.part, ADIS_IMU_DIAG_XGYRO_ST | ADIS_IMU_DIAG_ZACCL_ST);
    CHECK_ERR(adis_imu_self_test(&fx.imu, &diag), INC_ERR_DEVICE);
    CHECK_EQ_HEX(diag, 0x9020);
    adis_imu_diag_decode(diag, &d);
    CHECK(d.self_test_fail && d.gyro_st_fail[0] && d.accel_st_fail[2] && !d.gyro_st_fail[1]);
    /* At init: a failing part fails init. */
    fx_setup(SIM_ADIS16360);
    sim_adis_imu_set_self_test_fail(&fx.part, ADIS_IMU_DIAG_YACCL_ST);
    fx.cfg.self_test_at_init = true;
    CHECK_ERR(fx_init(), INC_ERR_DEVICE);
    CHECK_EQ_HEX(fx.imu.last_diag, 0x4020);
    CHECK(!fx.imu.ready);
    CHECK_EQ_INT(fx_violations(), 0);
}

/* ---- register access and bad arguments ---- */

static void test_registers_and_arguments(void)
{
    struct adis_imu s0;
    struct adis_imu_cfg c;
    struct adis_imu_sample smp;
    uint16_t v = 0;
    fx_setup(SIM_ADIS16405);
    /* config checks */
    CHECK_ERR(adis_imu_init(NULL, &fx.cfg), INC_ERR_NULL);
    CHECK_ERR(adis_imu_init(&s0, NULL), INC_ERR_NULL);
    c = fx.cfg;
    c.hal = NULL;
    CHECK_ERR(adis_imu_init(&s0, &c), INC_ERR_NULL);
    c = fx.cfg;
    c.bus = NULL;
    CHECK_ERR(adis_imu_init(&s0, &c), INC_ERR_NULL);
    c = fx.cfg;
    c.variant = 6;
    CHECK_ERR(adis_imu_init(&s0, &c), INC_ERR_INVAL);
    c = fx.cfg;
    c.cs = HAL_PIN_NONE;
    CHECK_ERR(adis_imu_init(&s0, &c), INC_ERR_INVAL);
    c = fx.cfg;
    c.dr_line = 2;
    CHECK_ERR(adis_imu_init(&s0, &c), INC_ERR_INVAL);
    CHECK_ERR(adis_imu_found(&s0, &v, NULL), INC_ERR_STATE);
    CHECK_EQ_INT(fx.part.core.reads + fx.part.core.writes, 0); /* nothing reached the part */
    /* calls on an uninitialised state */
    CHECK_ERR(adis_imu_read_sample(&s0, &smp), INC_ERR_STATE);
    CHECK_ERR(adis_imu_read_channels(&s0, ADIS_IMU_CH_ALL, &smp), INC_ERR_STATE);
    CHECK_ERR(adis_imu_command(&s0, ADIS_IMU_CMD_AUTONULL), INC_ERR_STATE);
    CHECK_ERR(adis_imu_read_sample(NULL, &smp), INC_ERR_NULL);
    CHECK_ERR(adis_imu_set_gyro_offset(NULL, 0, 0), INC_ERR_NULL);
    CHECK(!adis_imu_busy(NULL));
    /* initialised: argument checks */
    REQUIRE(fx_init() == 0);
    CHECK_ERR(adis_imu_read_sample(&fx.imu, NULL), INC_ERR_NULL);
    CHECK_ERR(adis_imu_read_channels(&fx.imu, 0, &smp), INC_ERR_INVAL);
    CHECK_ERR(adis_imu_read_channels(&fx.imu, ADIS_IMU_CH(ADIS_IMU_CH_TEMP2), &smp), INC_ERR_INVAL);
    CHECK_ERR(adis_imu_command(&fx.imu, (enum adis_imu_cmd)0x03), INC_ERR_INVAL);
    CHECK_ERR(adis_imu_command(&fx.imu, (enum adis_imu_cmd)0x20), INC_ERR_INVAL);
    CHECK_ERR(adis_imu_read_reg(&fx.imu, 0x3E, &v), INC_ERR_INVAL); /* write-only */
    CHECK_ERR(adis_imu_read_reg(&fx.imu, 0x52, &v), INC_ERR_INVAL); /* not on the 1640x */
    CHECK_ERR(adis_imu_read_reg(&fx.imu, 0x57, &v), INC_ERR_INVAL); /* odd */
    CHECK_ERR(adis_imu_write_reg(&fx.imu, 0x56, 1), INC_ERR_INVAL); /* read-only */
    CHECK_ERR(adis_imu_write_reg(&fx.imu, 0x36, 1), INC_ERR_INVAL); /* has its own function */
    CHECK_ERR(adis_imu_write_reg(&fx.imu, 0x3E, 1), INC_ERR_INVAL);
    CHECK_ERR(adis_imu_dr_config(&fx.imu, true, (enum adis_imu_dr_line)2, false), INC_ERR_INVAL);
    /* plain register access */
    CHECK_OK(adis_imu_read_reg(&fx.imu, ADIS_IMU_REG_PROD_ID, &v));
    CHECK_EQ_HEX(v, 0x4015);
    CHECK_OK(adis_imu_read_reg(&fx.imu, ADIS1640X_REG_XMAGN_SIF, &v));
    CHECK_EQ_HEX(v, 0x0800);
    CHECK_OK(adis_imu_write_reg(&fx.imu, ADIS1640X_REG_ALM_MAG1, 0xBEEF));
    CHECK_OK(adis_imu_read_reg(&fx.imu, ADIS1640X_REG_ALM_MAG1, &v));
    CHECK_EQ_HEX(v, 0xBEEF);
    CHECK_OK(adis_imu_read_diag(&fx.imu, &v));
    CHECK_EQ_HEX(v, 0);
    CHECK_EQ_INT(fx.part.protocol_errors, 0);
    CHECK_EQ_INT(fx_violations(), 0);
    /* A 1636x has LOT_ID1. */
    fx_setup(SIM_ADIS16365);
    REQUIRE(fx_init() == 0);
    CHECK_OK(adis_imu_read_reg(&fx.imu, ADIS1636X_REG_LOT_ID1, &v));
    CHECK_EQ_HEX(v, 0x1234);
    CHECK_EQ_INT(fx_violations(), 0);
}

/* A reset restores MSC_CTRL from flash; the driver writes the data-ready bits back as configured
 * when they differ (here: active low, not in flash), and leaves them when they agree. */
static void test_reset_restores_dr(void)
{
    fx_setup(SIM_ADIS16405);
    REQUIRE(fx_init() == INC_OK);
    REQUIRE(adis_imu_dr_config(&fx.imu, true, ADIS_IMU_DR_DIO1, true) == INC_OK);
    CHECK_EQ_HEX(sim_adis_imu_peek(&fx.part, ADIS_IMU_REG_MSC_CTRL) & 0x7u, ADIS_IMU_MSC_DR_EN);
    CHECK_OK(adis_imu_command(&fx.imu, ADIS_IMU_CMD_SW_RESET));
    CHECK_EQ_HEX(sim_adis_imu_peek(&fx.part, ADIS_IMU_REG_MSC_CTRL) & 0x7u, ADIS_IMU_MSC_DR_EN);
    CHECK_EQ_HEX(fx.imu.msc_ctrl & 0x7u, ADIS_IMU_MSC_DR_EN);
    REQUIRE(adis_imu_dr_config(&fx.imu, true, ADIS_IMU_DR_DIO1, false) == INC_OK);
    CHECK_OK(adis_imu_command(&fx.imu, ADIS_IMU_CMD_SW_RESET));
    CHECK_EQ_HEX(sim_adis_imu_peek(&fx.part, ADIS_IMU_REG_MSC_CTRL), ADIS_IMU_MSC_DEFAULT);
    CHECK_EQ_HEX(fx.imu.msc_ctrl, ADIS_IMU_MSC_DEFAULT);
    CHECK_OK(adis_imu_wait_ready(&fx.imu, 0, NULL));
    CHECK_EQ_INT(fx_violations(), 0);
}

int main(void)
{
    UNIT_RUN(test_init_each_variant);
    UNIT_RUN(test_wrong_prod_id);
    UNIT_RUN(test_no_device_at_init);
    UNIT_RUN(test_init_too_early_shows_violation);
    UNIT_RUN(test_burst_exact_each_variant);
    UNIT_RUN(test_registers_exact_each_variant);
    UNIT_RUN(test_stale);
    UNIT_RUN(test_error_flags);
    UNIT_RUN(test_spi_failure_reported);
    UNIT_RUN(test_bus_stuck_at_run_time);
    UNIT_RUN(test_sample_period_and_sclk);
    UNIT_RUN(test_wrong_sclk_shows_violation);
    UNIT_RUN(test_filter_and_range);
    UNIT_RUN(test_flash_update_restore_reset);
    UNIT_RUN(test_busy_not_lost);
    UNIT_RUN(test_offsets);
    UNIT_RUN(test_data_ready);
    UNIT_RUN(test_self_test);
    UNIT_RUN(test_registers_and_arguments);
    UNIT_RUN(test_reset_restores_dr);
    return unit_report();
}
