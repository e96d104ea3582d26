/*
 * ADIS16255 driver against the ADIS16255 model on the simulated board: init and identity,
 * configuration (rate, SCLK/stall per rate, range, filter, data-ready), exact outputs for given
 * physical inputs, the error-model and physics hooks, every command with its busy handling,
 * self-test pass/fail/timeout, data-ready waiting and a missed data-ready, and the bad-input
 * cases of issue 3: MISO stuck at 0/1 and no device (init and run time), EA -> STATUS decoded,
 * ND clear -> stale, an SPI framing error reported by the part, a command while the part is
 * busy, a driver timing violation made visible. Every normal case ends with zero violations.
 */
#include "fixture.h"

#include "adis16255_regs.h" /* white-box: the driver's register map */

#include "inclino/adis.h"

#include <math.h>
#include <string.h>

#define TS_NS 3906000ull /* 256 SPS in the model: 2 x 1.953 ms */

static int init_default(void)
{
    return adis16255_init(&fx.drv, &fx.cfg);
}

/* ------------------------------------------------------------------ init and configuration */

static void test_init(void)
{
    fx_setup(true);
    CHECK_OK(init_default());
    CHECK(fx.drv.ready);
    CHECK_EQ_INT(fx.drv.id_check, ADIS16255_ID_OK);
    CHECK_EQ_HEX(sim_adis16255_peek(&fx.part, ADIS16255_REG_SMPL_PRD), 0x0001);
    CHECK_EQ_HEX(sim_adis16255_peek(&fx.part, ADIS16255_REG_SENS_AVG), 0x0402);
    CHECK_EQ_HEX(sim_adis16255_peek(&fx.part, ADIS16255_REG_MSC_CTRL), 0x0006);
    /* 256 SPS: the fast SCLK (2 MHz <= 2.5 MHz) and the 30 us stall. */
    CHECK(fx.drv.fast);
    CHECK_EQ_INT(fx.drv.spi.cfg.timing.sclk_period_ns, 500);
    CHECK_EQ_INT(fx.drv.spi.cfg.timing.stall_ns, ADIS16255_STALL_NS);
    CHECK_EQ_INT(fx.drv.spi.cfg.mode, SPI_MODE_3);
    CHECK_EQ_INT(fx.drv.spi.cfg.bits, 16);
    CHECK(fx.drv.dr_attached);
    CHECK_NO_VIOLATIONS();

    /* Slow rate (60.54 ms x 3 = 5.5 SPS), ±80 with 16 taps, data-ready active low on DIO1. */
    fx_setup(true);
    fx.cfg.smpl_prd = 0x82;
    fx.cfg.range = ADIS16255_RANGE_80;
    fx.cfg.filter_m = 4;
    fx.cfg.dr_pin = SIM_BOARD_DR(1);
    fx.cfg.dr_line = 1;
    fx.cfg.dr_active_high = false;
    fx.cfg.reset_at_init = true;
    fx.cfg.self_test_at_init = true;
    CHECK_OK(init_default());
    CHECK(!fx.drv.fast);
    CHECK_EQ_INT(fx.drv.spi.cfg.timing.sclk_period_ns, 1250);
    CHECK_EQ_INT(fx.drv.spi.cfg.timing.stall_ns, ADIS16255_STALL_SLOW_NS);
    CHECK_EQ_HEX(sim_adis16255_peek(&fx.part, ADIS16255_REG_SMPL_PRD), 0x0082);
    CHECK_EQ_HEX(sim_adis16255_peek(&fx.part, ADIS16255_REG_SENS_AVG), 0x0104);
    CHECK_EQ_HEX(sim_adis16255_peek(&fx.part, ADIS16255_REG_MSC_CTRL), 0x0005);
    CHECK_EQ_INT(fx.part.commands, 1);                      /* the reset */
    CHECK(sim_pinbus_read(&fx.board.bus, SIM_BOARD_DR(1))); /* idle high */
    CHECK_EQ_INT(adis16255_dr_timeout_us(&fx.drv), 2u * 181620u + ADIS16255_DR_MARGIN_US);
    CHECK_NO_VIOLATIONS();
}

static void test_config_changes(void)
{
    struct adis16255_sample s;
    fx_setup(true);
    REQUIRE(init_default() == 0);
    /* Fast -> slow -> fast: the SCLK limit and the stall follow the rate at the right frame. */
    CHECK_OK(adis16255_set_sample_period(&fx.drv, 0x0A));
    CHECK(!fx.drv.fast);
    CHECK_EQ_INT(sim_adis16255_period_ns(&fx.part), 11u * 1953000u);
    CHECK_EQ_INT(fx.part.core.slave.cfg.timing.min_period_ns, 1000);
    CHECK_OK(adis16255_wait_sample(&fx.drv, 0, &s));
    CHECK(s.valid);
    CHECK_OK(adis16255_set_sample_period(&fx.drv, 0x07));
    CHECK(fx.drv.fast);
    CHECK_EQ_INT(fx.part.core.slave.cfg.timing.min_period_ns, 400);
    CHECK_OK(adis16255_set_sample_period(&fx.drv, 0x80));
    CHECK(!fx.drv.fast);
    CHECK_OK(adis16255_set_sample_period(&fx.drv, 0x00));
    CHECK(fx.drv.fast);
    /* Range and filter; invalid combinations never reach the part. */
    CHECK_OK(adis16255_set_sens_avg(&fx.drv, ADIS16255_RANGE_160, 3));
    CHECK_EQ_HEX(sim_adis16255_peek(&fx.part, ADIS16255_REG_SENS_AVG), 0x0203);
    CHECK_ERR(adis16255_set_sens_avg(&fx.drv, ADIS16255_RANGE_80, 2), INC_ERR_INVAL);
    CHECK_ERR(adis16255_set_sens_avg(&fx.drv, ADIS16255_RANGE_320, 7), INC_ERR_INVAL);
    CHECK_EQ_HEX(sim_adis16255_peek(&fx.part, ADIS16255_REG_SENS_AVG), 0x0203);
    CHECK_NO_VIOLATIONS();
}

/* ------------------------------------------------------------------ outputs */

static void test_outputs_exact(void)
{
    /* Physical input -> model (scale, quantisation) -> driver (Q16.16), exact both ways. */
    static const struct {
        enum adis16255_range range;
        uint8_t m;
        double rate, temp;
        uint16_t gyro_data, temp_data;
        int32_t rate_q16, temp_q16;
    } v[] = {
        {ADIS16255_RANGE_320, 2, 100.0, 40.0, 0x0555, 0x067, 6553600, 2619205},
        {ADIS16255_RANGE_320, 2, -200.0, -10.0, 0x3556, 0xF0F, -13107200, -656494},
        {ADIS16255_RANGE_80, 4, 50.0, 75.0, 0x0AAA, 0x158, 3276800, 4914099},
        {ADIS16255_RANGE_160, 2, 0.0, 25.0, 0x0000, 0x000, 0, 1638400},
    };
    struct adis16255_sample s;
    int32_t v_q16 = -1;
    unsigned i;
    for (i = 0; i < sizeof(v) / sizeof(v[0]); i++) {
        fx_setup(true);
        fx.cfg.range = v[i].range;
        fx.cfg.filter_m = v[i].m;
        fx_input(v[i].rate, v[i].temp, 5.0);
        REQUIRE(init_default() == 0);
        CHECK_OK(adis16255_wait_sample(&fx.drv, 0, &s));
        CHECK(s.valid);
        CHECK_EQ_HEX(s.gyro_word, 0x8000u | v[i].gyro_data);
        CHECK_EQ_HEX(s.temp_word, 0x8000u | v[i].temp_data);
        CHECK_EQ_INT(s.rate_dps_q16, v[i].rate_q16);
        CHECK_EQ_INT(s.temp_c_q16, v[i].temp_q16);
        CHECK_EQ_INT(s.flags, ADIS16255_SAMPLE_GYRO_NEW | ADIS16255_SAMPLE_TEMP_NEW);
        CHECK_OK(adis16255_read_supply(&fx.drv, &v_q16));
        CHECK_EQ_INT(v_q16, 327680); /* 5.0 V -> 2730 counts -> 5.0000 V */
        CHECK_NO_VIOLATIONS();
    }
}

static void test_angle(void)
{
    int32_t deg = -1;
    fx_setup(true);
    fx_input(10.0, 25.0, 5.0);
    REQUIRE(init_default() == 0);
    /* 256 samples of 10 °/s x 3.906 ms = 9.99936 ° -> floor(272.98) = 272 counts. The first
     * sample came at t = 0; wait for the 256th. */
    hal_delay_until(&fx.board.hal, 255u * TS_NS + 1000u);
    CHECK_EQ_INT(fx.part.samples, 256);
    CHECK_OK(adis16255_read_angle(&fx.drv, &deg));
    CHECK_EQ_INT(deg, 652959);
    CHECK_ERR(adis16255_read_angle(&fx.drv, &deg), INC_ERR_STALE);
    CHECK_EQ_INT(deg, 0);
    CHECK_NO_VIOLATIONS();
}

/* Error model: a bias of +1.5 °/s and +2 °C on the sensing element, with the sample period. */
struct bias_model {
    unsigned calls;
    double dt;
};
static void bias_apply(void *ctx, const struct sim_inertial_input *in,
                       struct sim_inertial_input *out, uint64_t t, double dt)
{
    struct bias_model *b = ctx;
    (void)t;
    *out = *in;
    out->rate_dps[2] += 1.5;
    out->temp_c += 2.0;
    b->calls++;
    b->dt = dt;
}

/* Physics: the rate steps from 0 to 40 °/s at t = 20 ms. */
static void step_physics(void *ctx, uint64_t t, struct sim_inertial_input *in)
{
    (void)ctx;
    sim_inertial_at_rest(in);
    in->rate_dps[2] = t >= 20000000u ? 40.0 : 0.0;
}

static void test_hooks(void)
{
    struct bias_model bm = {0, 0.0};
    struct sim_error_model em = {bias_apply, &bm};
    struct sim_physics ph = {step_physics, NULL};
    struct adis16255_sample s;
    int32_t q;
    fx_setup(true);
    fx_input(0.0, 25.0, 5.0);
    sim_adis16255_set_error_model(&fx.part, &em);
    REQUIRE(init_default() == 0);
    CHECK_OK(adis16255_wait_sample(&fx.drv, 0, &s));
    /* 1.5 °/s -> round(20.475) = 20 counts; 27 °C -> round(13.76) = 14 counts. */
    CHECK_EQ_HEX(s.gyro_word & 0x3FFFu, 20);
    CHECK_OK(adis16255_gyro_dps_from_word(20, ADIS16255_RANGE_320, &q));
    CHECK_EQ_INT(s.rate_dps_q16, q);
    CHECK_EQ_HEX(s.temp_word & 0x0FFFu, 14);
    CHECK(bm.calls >= 1u);
    CHECK_NEAR(bm.dt, 0.003906, 1e-12);

    fx_setup(true);
    sim_adis16255_set_physics(&fx.part, &ph);
    REQUIRE(init_default() == 0);
    CHECK_OK(adis16255_wait_sample(&fx.drv, 0, &s));
    CHECK_EQ_INT(s.rate_dps_q16, 0);
    hal_delay_until(&fx.board.hal, 40000000u);
    /* 4 taps: 4 samples after the step the average is the full 40 °/s = 546 counts. */
    CHECK_OK(adis16255_wait_sample(&fx.drv, 0, &s));
    CHECK_EQ_HEX(s.gyro_word & 0x3FFFu, 546);
    CHECK_NO_VIOLATIONS();
}

/* ------------------------------------------------------------------ flags */

static void test_stale(void)
{
    struct adis16255_sample s;
    fx_setup(true);
    fx_input(100.0, 40.0, 5.0);
    REQUIRE(init_default() == 0);
    CHECK_OK(adis16255_wait_sample(&fx.drv, 0, &s));
    CHECK(s.valid);
    /* Read again before the next sample: ND clear -> stale, never valid, values zeroed. */
    CHECK_ERR(adis16255_read_sample(&fx.drv, &s), INC_ERR_STALE);
    CHECK(!s.valid);
    CHECK_EQ_INT(s.rate_dps_q16, 0);
    CHECK_EQ_INT(s.temp_c_q16, 0);
    CHECK_EQ_HEX(s.gyro_word, 0x0555); /* the raw word is kept: ND clear */
    CHECK_EQ_INT(s.flags, 0);

    /* At rest and 25 °C both words are 0x0000 when stale: the driver tells a stale sample from
     * a stuck MISO by a SENS_AVG read-back, and says stale. */
    fx_setup(true);
    REQUIRE(init_default() == 0);
    CHECK_OK(adis16255_wait_sample(&fx.drv, 0, &s));
    CHECK_ERR(adis16255_read_sample(&fx.drv, &s), INC_ERR_STALE);
    CHECK_EQ_HEX(s.gyro_word, 0x0000);
    CHECK_EQ_HEX(s.temp_word, 0x0000);
    CHECK_NO_VIOLATIONS();
}

static void test_ea_status(void)
{
    struct adis16255_sample s;
    struct adis16255_status st;
    fx_setup(true);
    REQUIRE(init_default() == 0);
    /* Supply below 4.75 V: EA on every output, STATUS bit 0. */
    fx_input(10.0, 25.0, 4.6);
    CHECK_ERR(adis16255_wait_sample(&fx.drv, 0, &s), INC_ERR_DEVICE);
    CHECK(!s.valid);
    CHECK(s.flags & ADIS16255_SAMPLE_ALARM);
    CHECK_EQ_HEX(s.status.raw, ADIS16255_STATUS_SUPPLY_LOW);
    CHECK(s.status.supply_low);
    CHECK(fx.drv.status.supply_low);
    CHECK_EQ_INT(s.rate_dps_q16, 0);
    CHECK_OK(adis16255_read_diag(&fx.drv, &st)); /* a live condition: still set */
    CHECK(st.supply_low && !st.supply_high);
    /* Above 5.25 V. */
    fx_input(10.0, 25.0, 5.4);
    CHECK_ERR(adis16255_wait_sample(&fx.drv, 0, &s), INC_ERR_DEVICE);
    CHECK(s.status.supply_high && !s.status.supply_low);
    /* Over range (400 °/s at ±320): latched until STATUS is read. */
    fx_input(400.0, 25.0, 5.0);
    fx_wait_ms(20); /* the 4-tap filter fills */
    CHECK_ERR(adis16255_wait_sample(&fx.drv, 0, &s), INC_ERR_DEVICE);
    CHECK(s.status.overrange);
    CHECK_EQ_HEX(s.gyro_word & 0x3FFFu, 4368); /* clamped at 320 °/s */
    fx_input(100.0, 25.0, 5.0);
    CHECK_ERR(adis16255_wait_sample(&fx.drv, 0, &s), INC_ERR_DEVICE); /* filter still > 320 */
    fx_wait_ms(20);
    CHECK_OK(adis16255_read_diag(&fx.drv, &st));
    CHECK_OK(adis16255_wait_sample(&fx.drv, 0, &s));
    CHECK(s.valid);
    CHECK_EQ_INT(s.rate_dps_q16, 6553600);
    CHECK_NO_VIOLATIONS();
}

static void test_spi_framing_error(void)
{
    struct adis16255_sample s;
    uint16_t v;
    fx_setup(true);
    REQUIRE(init_default() == 0);
    CHECK_OK(adis16255_wait_sample(&fx.drv, 0, &s));
    /* The driver breaks the stall once (5 us < 30 us): the part drops the frame, logs it, and
     * flags an SPI communication failure. */
    fx.drv.spi.cfg.timing.stall_ns = 5000;
    CHECK_OK(adis_read_reg(&fx.drv.spi, ADIS16255_REG_SUPPLY_OUT, &v));
    fx.drv.spi.cfg.timing.stall_ns = ADIS16255_STALL_NS;
    CHECK(sim_violation_count(&fx.board.log, SIM_VIOL_STALL) >= 1u);
    CHECK_EQ_INT(fx.board.log.v[0].kind, SIM_VIOL_STALL);
    CHECK_EQ_INT(fx.board.log.v[0].limit_ns, 30000);
    CHECK(fx.board.log.v[0].measured_ns < 30000u);
    CHECK(fx.part.frame_errors >= 1u);
    /* ... which the driver reports with the next sample. */
    CHECK_ERR(adis16255_wait_sample(&fx.drv, 0, &s), INC_ERR_DEVICE);
    CHECK(s.status.spi_fail);
    CHECK(fx.drv.status.spi_fail);
    /* Latched: reading STATUS cleared it; the next sample is clean. */
    CHECK_OK(adis16255_wait_sample(&fx.drv, 0, &s));
    CHECK(s.valid);
    sim_violation_log_print(&fx.board.log, stdout);
}

/* ------------------------------------------------------------------ commands */

static void test_commands(void)
{
    struct bias_model bm = {0, 0.0};
    struct sim_error_model em = {bias_apply, &bm};
    struct adis16255_sample s;
    int32_t off = 0;
    bool sat = true;
    uint16_t endurance;
    fx_setup(true);
    fx_input(0.0, 25.0, 5.0);
    sim_adis16255_set_error_model(&fx.part, &em); /* +1.5 °/s bias */
    REQUIRE(init_default() == 0);
    CHECK_OK(adis16255_wait_sample(&fx.drv, 0, &s));
    CHECK_EQ_HEX(s.gyro_word & 0x3FFFu, 20);

    /* Autonull: GYRO_OFF = -mean over the filter window = -1.5 / 0.018315 = -81.9 -> -82. */
    CHECK_OK(adis16255_autonull(&fx.drv));
    CHECK_EQ_HEX(sim_adis16255_peek(&fx.part, ADIS16255_REG_GYRO_OFF), 0xFAE); /* -82 */
    CHECK_OK(adis16255_get_gyro_offset(&fx.drv, &off));
    CHECK_EQ_INT(off, adis16255_gyro_off_dps_from_word(0xFAE));
    CHECK(fabs(fx.part.rate_out_dps) <= 0.5 * SIM_ADIS16255_OFF_LSB); /* achieved bias */
    CHECK_OK(adis16255_wait_sample(&fx.drv, 0, &s));
    CHECK(s.valid);
    CHECK_EQ_INT(s.rate_dps_q16, 0);

    /* Flash update: ENDURANCE + 1 and the offset in the flash copy. */
    endurance = sim_adis16255_peek(&fx.part, ADIS16255_REG_ENDURANCE);
    CHECK_OK(adis16255_flash_update(&fx.drv));
    CHECK_EQ_HEX(sim_adis16255_peek(&fx.part, ADIS16255_REG_ENDURANCE), endurance + 1u);
    CHECK_EQ_HEX(sim_adis16255_flash(&fx.part, ADIS16255_REG_GYRO_OFF), 0xFAE);

    /* Factory restore: offset 0 and scale 1.0 in the registers. */
    CHECK_OK(adis16255_set_gyro_offset(&fx.drv, 65536, &sat)); /* 1 °/s */
    CHECK(!sat);
    CHECK_EQ_HEX(sim_adis16255_peek(&fx.part, ADIS16255_REG_GYRO_OFF), 0x037);
    sim_adis16255_poke(&fx.part, ADIS16255_REG_GYRO_SCALE, 0x0900);
    CHECK_OK(adis16255_factory_restore(&fx.drv));
    CHECK_EQ_HEX(sim_adis16255_peek(&fx.part, ADIS16255_REG_GYRO_OFF), 0x000);
    CHECK_EQ_HEX(sim_adis16255_peek(&fx.part, ADIS16255_REG_GYRO_SCALE), 0x0800);

    /* Reset: the part reloads its flash (offset -82, rate 256 SPS); the driver writes its own
     * configuration again. */
    CHECK_OK(adis16255_set_sens_avg(&fx.drv, ADIS16255_RANGE_160, 2));
    CHECK_OK(adis16255_reset(&fx.drv));
    CHECK_EQ_HEX(sim_adis16255_peek(&fx.part, ADIS16255_REG_GYRO_OFF), 0xFAE);
    CHECK_EQ_HEX(sim_adis16255_peek(&fx.part, ADIS16255_REG_SENS_AVG), 0x0202);
    CHECK_EQ_INT(fx.part.commands, 4);
    CHECK_OK(adis16255_wait_sample(&fx.drv, 0, &s));
    CHECK(s.valid);

    /* Saturation of the offset is flagged and the register holds the limit. */
    CHECK_OK(adis16255_set_gyro_offset(&fx.drv, -50 * 65536, &sat));
    CHECK(sat);
    CHECK_EQ_HEX(sim_adis16255_peek(&fx.part, ADIS16255_REG_GYRO_OFF), 0x800);
    CHECK_EQ_INT(fx.part.frame_errors, 0);
    CHECK_NO_VIOLATIONS();
}

/* The chained SENS_AVG word: every register read ends with a SENS_AVG command, and a sample
 * read refuses its words when the first one (the answer to that command) is not the SENS_AVG
 * the driver wrote. A busy part's garbage, a part that lost its configuration (a reset: its
 * range is no longer the one the conversion assumes) are never taken for a sample. */
static void test_chained_sens_avg(void)
{
    struct adis16255_sample s;
    unsigned i, ok = 0, busy = 0;
    uint16_t sa;
    fx_setup(true);
    fx_input(100.0, 40.0, 5.0);
    REQUIRE(init_default() == 0);
    CHECK_OK(adis16255_wait_sample(&fx.drv, 0, &s));
    CHECK_OK(adis16255_wait_sample(&fx.drv, 0, &s));
    CHECK_EQ_INT((int)fx.drv.tail_fails, 0);
    /* Busy for 50 ms (a reason the driver did not cause): the part shifts garbage out and its
     * data-ready keeps coming; every read is refused, none delivers a value. */
    sim_adis16255_force_busy(&fx.part, 50000000u);
    for (i = 0; i < 20u; i++) {
        fx_wait_ms(2);
        const int err = adis16255_read_sample(&fx.drv, &s);
        ok += err == INC_OK ? 1u : 0u;
        busy += err == INC_ERR_BUSY ? 1u : 0u;
    }
    CHECK_EQ_INT((int)ok, 0);
    CHECK(busy >= 19u); /* the first read after the onset may still be chained to a good word */
    CHECK(fx.drv.tail_fails >= 19u);
    /* Free again: the next read re-establishes the chain, then samples flow (the first
     * waits may find the outputs stale: the part restarts sampling). */
    fx_wait_ms(20);
    for (i = 0; i < 5u && adis16255_wait_sample(&fx.drv, 0, &s) != INC_OK; i++) {
    }
    CHECK(i < 5u);
    CHECK(s.valid);
    /* The part's SENS_AVG changed behind the driver's back (a reset to the ±80 deg/s range):
     * refused at the next read. */
    sa = sim_adis16255_peek(&fx.part, ADIS16255_REG_SENS_AVG);
    sim_adis16255_poke(&fx.part, ADIS16255_REG_SENS_AVG, (uint16_t)((sa & 0x00FFu) | 0x0100u));
    fx_wait_ms(5);
    (void)adis16255_read_sample(&fx.drv, &s); /* answers the last good read's command */
    fx_wait_ms(5);
    CHECK_ERR(adis16255_read_sample(&fx.drv, &s), INC_ERR_BUSY);
    CHECK(!s.valid);
}

static void test_command_while_busy(void)
{
    uint16_t e0;
    struct sim_adis16255_times slow;
    fx_setup(true);
    REQUIRE(init_default() == 0);
    e0 = sim_adis16255_peek(&fx.part, ADIS16255_REG_ENDURANCE);
    /* The part is busy for a reason the driver did not cause (200 ms): the driver finds it
     * answering garbage, waits, then sends the flash update, which happens exactly once. */
    sim_adis16255_force_busy(&fx.part, 200000000u);
    CHECK_OK(adis16255_flash_update(&fx.drv));
    CHECK_EQ_HEX(sim_adis16255_peek(&fx.part, ADIS16255_REG_ENDURANCE), e0 + 1u);
    /* Its polls hit the busy part (reported), nothing else broke, and no frame error. */
    CHECK(sim_violation_count(&fx.board.log, SIM_VIOL_BUSY) >= 1u);
    CHECK_EQ_INT(fx.board.log.total, sim_violation_count(&fx.board.log, SIM_VIOL_BUSY));
    CHECK_EQ_INT(fx.part.frame_errors, 0);
    CHECK_EQ_INT(fx.part.commands, 1);

    /* Busy longer than the driver will wait: INC_ERR_BUSY, the command was not sent (nothing
     * lost in silence); once the part is free the retry goes through, once. */
    sim_adis16255_force_busy(&fx.part, 3000000000ull);
    CHECK_ERR(adis16255_flash_update(&fx.drv), INC_ERR_BUSY);
    CHECK_EQ_HEX(sim_adis16255_peek(&fx.part, ADIS16255_REG_ENDURANCE), e0 + 1u);
    CHECK_EQ_INT(fx.part.commands, 1);
    fx_wait_ms(2100);
    CHECK_OK(adis16255_flash_update(&fx.drv));
    CHECK_EQ_HEX(sim_adis16255_peek(&fx.part, ADIS16255_REG_ENDURANCE), e0 + 2u);

    /* A part slower than the driver's [U] wait (flash update 350 ms > 200 ms): the driver
     * polls until it answers; the next command is not lost. */
    memset(&slow, 0, sizeof(slow));
    slow.flash_update_ns = 350000000u;
    fx_setup_times(true, &slow);
    REQUIRE(init_default() == 0);
    e0 = sim_adis16255_peek(&fx.part, ADIS16255_REG_ENDURANCE);
    CHECK_OK(adis16255_flash_update(&fx.drv));
    CHECK_OK(adis16255_autonull(&fx.drv));
    CHECK_EQ_HEX(sim_adis16255_peek(&fx.part, ADIS16255_REG_ENDURANCE), e0 + 1u);
    CHECK_EQ_INT(fx.part.commands, 2);
    CHECK_EQ_INT(fx.board.log.total, sim_violation_count(&fx.board.log, SIM_VIOL_BUSY));
}

static void test_self_test(void)
{
    struct sim_adis16255_times slow;
    uint16_t v;
    fx_setup(true);
    REQUIRE(init_default() == 0);
    CHECK_OK(adis16255_self_test(&fx.drv));
    CHECK_EQ_HEX(fx.drv.status.raw, 0);
    CHECK_EQ_HEX(sim_adis16255_peek(&fx.part, ADIS16255_REG_MSC_CTRL), 0x0006); /* bit 10 clear */
    CHECK_NO_VIOLATIONS();

    /* Failing part: INC_ERR_DEVICE, STATUS decoded; it stays until a passing self-test. */
    sim_adis16255_fail_self_test(&fx.part, true);
    CHECK_ERR(adis16255_self_test(&fx.drv), INC_ERR_DEVICE);
    CHECK(fx.drv.status.self_test_fail);
    CHECK_EQ_HEX(fx.drv.status.raw, ADIS16255_STATUS_SELF_TEST);
    sim_adis16255_fail_self_test(&fx.part, false);
    CHECK_OK(adis16255_self_test(&fx.drv));
    CHECK(!fx.drv.status.self_test_fail);

    /* The self-test moves the output (+25 °/s in the model) while it runs. */
    CHECK_OK(adis_write_byte(&fx.drv.spi, ADIS16255_REG_MSC_CTRL + 1u, 0x04));
    fx_wait_ms(25);
    CHECK_OK(adis_read_reg(&fx.drv.spi, ADIS16255_REG_GYRO_OUT, &v));
    CHECK_EQ_HEX(v & 0x3FFFu, 341); /* 25 / 0.07326 = 341.25 */
    CHECK(sim_adis16255_peek(&fx.part, ADIS16255_REG_MSC_CTRL) & ADIS16255_MSC_ST_INT);
    fx_wait_ms(10);
    CHECK_EQ_HEX(sim_adis16255_peek(&fx.part, ADIS16255_REG_MSC_CTRL), 0x0006);
    CHECK_NO_VIOLATIONS();

    /* Init with a failing self-test fails. */
    fx_setup(true);
    sim_adis16255_fail_self_test(&fx.part, true);
    fx.cfg.self_test_at_init = true;
    CHECK_ERR(init_default(), INC_ERR_DEVICE);
    CHECK(!fx.drv.ready);
    CHECK(fx.drv.status.self_test_fail);

    /* A self-test that never finishes: timeout after ADIS16255_SELF_TEST_TIMEOUT_MS. */
    memset(&slow, 0, sizeof(slow));
    slow.self_test_ns = 500000000u;
    fx_setup_times(true, &slow);
    REQUIRE(init_default() == 0);
    {
        const uint64_t t0 = fx.board.clk.now_ns;
        CHECK_ERR(adis16255_self_test(&fx.drv), INC_ERR_TIMEOUT);
        CHECK(fx.board.clk.now_ns - t0 >= (uint64_t)ADIS16255_SELF_TEST_TIMEOUT_MS * 1000000u);
        CHECK(fx.board.clk.now_ns - t0 < 300000000u);
    }
    CHECK_NO_VIOLATIONS();
}

/* ------------------------------------------------------------------ data-ready */

static void test_data_ready(void)
{
    struct adis16255_sample s;
    uint64_t t1, t0;
    unsigned i;
    fx_setup(true);
    fx_input(100.0, 25.0, 5.0);
    REQUIRE(init_default() == 0);
    CHECK_OK(adis16255_wait_sample(&fx.drv, 0, &s));
    t0 = s.t_ns;
    for (i = 0; i < 10u; i++) {
        CHECK_OK(adis16255_wait_sample(&fx.drv, 0, &s));
        CHECK(s.valid);
        CHECK_EQ_INT(s.flags, ADIS16255_SAMPLE_GYRO_NEW | ADIS16255_SAMPLE_TEMP_NEW);
    }
    t1 = s.t_ns;
    CHECK_EQ_INT(t1 - t0, 10u * TS_NS); /* one sample per period, none skipped */
    CHECK_EQ_INT(fx.part.dr_pulses, fx.part.samples);

    /* Edges pile up while the caller is away: the wait returns at once and says so. */
    fx_wait_ms(12);
    CHECK_OK(adis16255_wait_sample(&fx.drv, 0, &s));
    CHECK(s.flags & ADIS16255_SAMPLE_OVERRUN);
    CHECK(s.valid);

    /* Missed data-ready: timeout after 2 periods + margin, nothing made up. */
    sim_adis16255_suppress_dr(&fx.part, true);
    t0 = fx.board.clk.now_ns;
    CHECK_ERR(adis16255_wait_sample(&fx.drv, 0, &s), INC_ERR_TIMEOUT);
    CHECK(!s.valid);
    CHECK_EQ_INT(s.rate_dps_q16, 0);
    CHECK_EQ_INT(fx.board.clk.now_ns - t0, (2u * 3906u + ADIS16255_DR_MARGIN_US) * 1000u);
    CHECK_ERR(adis16255_wait_sample(&fx.drv, 500, &s), INC_ERR_TIMEOUT);
    sim_adis16255_suppress_dr(&fx.part, false);
    CHECK_OK(adis16255_wait_sample(&fx.drv, 0, &s));
    CHECK(s.valid);

    /* Active low on DIO1, slow rate. */
    fx_setup(true);
    fx.cfg.dr_pin = SIM_BOARD_DR(1);
    fx.cfg.dr_line = 1;
    fx.cfg.dr_active_high = false;
    fx.cfg.smpl_prd = 0x80;
    REQUIRE(init_default() == 0);
    CHECK_OK(adis16255_wait_sample(&fx.drv, 0, &s));
    t0 = s.t_ns;
    CHECK_OK(adis16255_wait_sample(&fx.drv, 0, &s));
    CHECK_EQ_INT(s.t_ns - t0, 60540000u);
    CHECK(s.valid);

    /* No data-ready pin configured: waiting is not possible. */
    fx_setup(true);
    fx.cfg.dr_pin = HAL_PIN_NONE;
    REQUIRE(init_default() == 0);
    CHECK_ERR(adis16255_wait_sample(&fx.drv, 0, &s), INC_ERR_STATE);
    CHECK_NO_VIOLATIONS();
}

/* ------------------------------------------------------------------ bad input */

static void test_no_device_init(void)
{
    /* No part, MISO pulled up: every word 0xFFFF. */
    fx_setup(false);
    CHECK_ERR(init_default(), INC_ERR_BUS);
    CHECK_EQ_INT(fx.drv.id_check, ADIS16255_ID_STUCK_HIGH);
    CHECK(!fx.drv.ready);
    /* No part, MISO pulled down (stuck at 0). */
    fx_setup(false);
    sim_board_set_miso_pull(&fx.board, SIM_PULL_DOWN);
    CHECK_ERR(init_default(), INC_ERR_BUS);
    CHECK_EQ_INT(fx.drv.id_check, ADIS16255_ID_STUCK_LOW);
    /* The part there but its MISO line stuck (cut): same verdicts. */
    fx_setup(true);
    sim_adis16255_disconnect(&fx.part);
    CHECK_ERR(init_default(), INC_ERR_BUS);
    CHECK_EQ_INT(fx.drv.id_check, ADIS16255_ID_STUCK_HIGH);
    /* With reset at init: the reset is harmless, the verdict the same. */
    fx_setup(false);
    fx.cfg.reset_at_init = true;
    CHECK_ERR(init_default(), INC_ERR_BUS);
}

static void test_implausible_part(void)
{
    static const struct {
        uint8_t addr;
        uint16_t value;
        enum adis16255_id_check why;
    } v[] = {
        {ADIS16255_REG_GYRO_SCALE, 0xF800, ADIS16255_ID_RESERVED_BITS},
        {ADIS16255_REG_SMPL_PRD, 0x0101, ADIS16255_ID_RESERVED_BITS},
        {ADIS16255_REG_MSC_CTRL, 0x0016, ADIS16255_ID_RESERVED_BITS},
        {ADIS16255_REG_SENS_AVG, 0x0302, ADIS16255_ID_SENS_AVG},
        {ADIS16255_REG_SENS_AVG, 0x0002, ADIS16255_ID_SENS_AVG},
        {ADIS16255_REG_SENS_AVG, 0x1402, ADIS16255_ID_SENS_AVG},
    };
    unsigned i;
    for (i = 0; i < sizeof(v) / sizeof(v[0]); i++) {
        fx_setup(true);
        sim_adis16255_poke(&fx.part, v[i].addr, v[i].value);
        CHECK_ERR(init_default(), INC_ERR_ID);
        CHECK_EQ_INT(fx.drv.id_check, v[i].why);
    }
    /* Supply reading outside 4..6 V: not believable (a 3.0 V reading). */
    fx_setup(true);
    fx_input(0.0, 25.0, 3.0);
    fx_wait_ms(5);
    CHECK_ERR(init_default(), INC_ERR_ID);
    CHECK_EQ_INT(fx.drv.id_check, ADIS16255_ID_SUPPLY);
    /* Supply in the plausible window but out of spec (4.5 V): the part is there but reports
     * an error; init fails with the STATUS decoded. */
    fx_setup(true);
    fx_input(0.0, 25.0, 4.5);
    fx_wait_ms(5);
    CHECK_ERR(init_default(), INC_ERR_DEVICE);
    CHECK(fx.drv.status.supply_low);
}

static void test_bus_fault_runtime(void)
{
    struct adis16255_sample s;
    int32_t q = 1;
    fx_setup(true);
    fx_input(100.0, 40.0, 5.0);
    REQUIRE(init_default() == 0);
    CHECK_OK(adis16255_wait_sample(&fx.drv, 0, &s));
    /* The part drops off the bus: MISO floats to the pull-up -> 0xFFFF words. They look like
     * ND|EA|data, the STATUS read that EA asks for is 0xFFFF too: not a STATUS word. */
    sim_adis16255_disconnect(&fx.part);
    fx_wait_ms(5);
    CHECK_ERR(adis16255_read_sample(&fx.drv, &s), INC_ERR_BUS);
    CHECK(!s.valid);
    CHECK_EQ_HEX(s.gyro_word, 0xFFFF);
    CHECK_EQ_INT(s.rate_dps_q16, 0);
    CHECK_ERR(adis16255_read_supply(&fx.drv, &q), INC_ERR_BUS);
    CHECK_EQ_INT(q, 0);
    /* Stuck at 0: ND clear, all zero; SENS_AVG does not read back -> bus fault, not stale. */
    sim_board_set_miso_pull(&fx.board, SIM_PULL_DOWN);
    CHECK_ERR(adis16255_read_sample(&fx.drv, &s), INC_ERR_BUS);
    CHECK_EQ_HEX(s.gyro_word, 0x0000);
    CHECK(!s.valid);
    CHECK_ERR(adis16255_get_gyro_offset(&fx.drv, &q), INC_OK); /* 0x0000 is a valid offset ... */
    sim_board_set_miso_pull(&fx.board, SIM_PULL_UP);
    CHECK_ERR(adis16255_get_gyro_offset(&fx.drv, &q), INC_ERR_BUS); /* ... 0xFFFF is not */
    /* Commands find no part: after polling, a bus fault (uniform words), nothing sent. */
    CHECK_ERR(adis16255_flash_update(&fx.drv), INC_ERR_BUS);
    CHECK_NO_VIOLATIONS();
}

static void test_args(void)
{
    struct adis16255_sample s;
    struct adis16255_status st;
    struct adis16255_cfg c;
    int32_t q;
    bool sat;
    fx_setup(true);
    CHECK_ERR(adis16255_init(NULL, &fx.cfg), INC_ERR_NULL);
    CHECK_ERR(adis16255_init(&fx.drv, NULL), INC_ERR_NULL);
    c = fx.cfg;
    c.bus = NULL;
    CHECK_ERR(adis16255_init(&fx.drv, &c), INC_ERR_NULL);
    c = fx.cfg;
    c.hal = NULL;
    CHECK_ERR(adis16255_init(&fx.drv, &c), INC_ERR_NULL);
    c = fx.cfg;
    c.cs = HAL_PIN_NONE;
    CHECK_ERR(adis16255_init(&fx.drv, &c), INC_ERR_INVAL);
    c = fx.cfg;
    c.range = (enum adis16255_range)3;
    CHECK_ERR(adis16255_init(&fx.drv, &c), INC_ERR_INVAL);
    c = fx.cfg;
    c.filter_m = 7;
    CHECK_ERR(adis16255_init(&fx.drv, &c), INC_ERR_INVAL);
    c = fx.cfg;
    c.range = ADIS16255_RANGE_80;
    c.filter_m = 3;
    CHECK_ERR(adis16255_init(&fx.drv, &c), INC_ERR_INVAL);
    c = fx.cfg;
    c.dr_line = 2;
    CHECK_ERR(adis16255_init(&fx.drv, &c), INC_ERR_INVAL);
    c = fx.cfg;
    c.dr_enable = false; /* a DR pin but the output off */
    CHECK_ERR(adis16255_init(&fx.drv, &c), INC_ERR_INVAL);
    c = fx.cfg;
    c.cs = SIM_BOARD_SCLK; /* the engine refuses a CS on its own pins */
    CHECK_ERR(adis16255_init(&fx.drv, &c), INC_ERR_INVAL);
    CHECK_EQ_INT(fx.part.core.reads + fx.part.core.writes, 0); /* nothing reached the part */
    /* Not initialised: every call says so and leaves outputs safe. */
    CHECK_ERR(adis16255_read_sample(&fx.drv, &s), INC_ERR_STATE);
    CHECK(!s.valid);
    CHECK_ERR(adis16255_wait_sample(&fx.drv, 0, &s), INC_ERR_STATE);
    CHECK_ERR(adis16255_read_supply(&fx.drv, &q), INC_ERR_STATE);
    CHECK_ERR(adis16255_read_angle(&fx.drv, &q), INC_ERR_STATE);
    CHECK_ERR(adis16255_read_diag(&fx.drv, &st), INC_ERR_STATE);
    CHECK_ERR(adis16255_autonull(&fx.drv), INC_ERR_STATE);
    CHECK_ERR(adis16255_flash_update(&fx.drv), INC_ERR_STATE);
    CHECK_ERR(adis16255_factory_restore(&fx.drv), INC_ERR_STATE);
    CHECK_ERR(adis16255_reset(&fx.drv), INC_ERR_STATE);
    CHECK_ERR(adis16255_self_test(&fx.drv), INC_ERR_STATE);
    CHECK_ERR(adis16255_set_sample_period(&fx.drv, 1), INC_ERR_STATE);
    CHECK_ERR(adis16255_set_sens_avg(&fx.drv, ADIS16255_RANGE_320, 2), INC_ERR_STATE);
    CHECK_ERR(adis16255_set_gyro_offset(&fx.drv, 0, &sat), INC_ERR_STATE);
    CHECK_ERR(adis16255_get_gyro_offset(&fx.drv, &q), INC_ERR_STATE);
    /* NULL state / outputs. */
    CHECK_ERR(adis16255_read_sample(NULL, &s), INC_ERR_NULL);
    CHECK_ERR(adis16255_read_sample(&fx.drv, NULL), INC_ERR_NULL);
    CHECK_ERR(adis16255_wait_sample(&fx.drv, 0, NULL), INC_ERR_NULL);
    CHECK_ERR(adis16255_read_supply(&fx.drv, NULL), INC_ERR_NULL);
    CHECK_ERR(adis16255_read_angle(&fx.drv, NULL), INC_ERR_NULL);
    CHECK_ERR(adis16255_read_diag(&fx.drv, NULL), INC_ERR_NULL);
    CHECK_ERR(adis16255_get_gyro_offset(&fx.drv, NULL), INC_ERR_NULL);
    CHECK_ERR(adis16255_autonull(NULL), INC_ERR_NULL);
    CHECK_ERR(adis16255_self_test(NULL), INC_ERR_NULL);
    CHECK_EQ_INT(adis16255_dr_timeout_us(NULL), 0);
    CHECK_EQ_INT(fx.part.core.reads + fx.part.core.writes, 0);
    CHECK_NO_VIOLATIONS();
}

int main(void)
{
    UNIT_RUN(test_init);
    UNIT_RUN(test_config_changes);
    UNIT_RUN(test_outputs_exact);
    UNIT_RUN(test_angle);
    UNIT_RUN(test_hooks);
    UNIT_RUN(test_stale);
    UNIT_RUN(test_ea_status);
    UNIT_RUN(test_spi_framing_error);
    UNIT_RUN(test_commands);
    UNIT_RUN(test_chained_sens_avg);
    UNIT_RUN(test_command_while_busy);
    UNIT_RUN(test_self_test);
    UNIT_RUN(test_data_ready);
    UNIT_RUN(test_no_device_init);
    UNIT_RUN(test_implausible_part);
    UNIT_RUN(test_bus_fault_runtime);
    UNIT_RUN(test_args);
    return unit_report();
}
