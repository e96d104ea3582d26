/*
 * The SCA3000 driver through its ops table (sca3000_sensor_ops, inclino/sensor.h): the output-
 * rate pacing of wait_ready (one period after the previous sample, the first one too; periods
 * lost counted as missed; the timeout), accel in g with the driver's conversion, per-axis
 * saturation, temperature on the D01 only, diagnostics, self-test unsupported, identity and
 * info per variant, and every op's refusal before init or in motion-detection mode.
 */
#include <string.h>

#include "fixture.h"
#include "inclino/sensor.h"

static struct sensor sen = {&sca3000_sensor_ops, &fx.dev};

static void test_refused_before_init(void)
{
    struct sensor_sample s;
    struct sensor_diag d;
    struct sensor_identity id;
    struct sensor_info info;
    memset(&fx.dev, 0, sizeof fx.dev);
    CHECK_ERR(sensor_wait_ready(&sen, 0u), INC_ERR_STATE);
    CHECK_ERR(sensor_read(&sen, &s), INC_ERR_STATE);
    CHECK_ERR(sensor_read_diag(&sen, &d), INC_ERR_STATE);
    CHECK_ERR(sensor_self_test(&sen, &d), INC_ERR_UNSUPPORTED);
    CHECK_ERR(sensor_get_identity(&sen, &id), INC_ERR_STATE);
    CHECK_ERR(sensor_get_info(&sen, &info), INC_ERR_STATE);
    CHECK_ERR(sca3000_sensor_ops.read(NULL, &s), INC_ERR_NULL);
    CHECK_ERR(sca3000_sensor_ops.wait_ready(NULL, 0u), INC_ERR_NULL);
    CHECK_ERR(sca3000_sensor_ops.info(&fx.dev, NULL), INC_ERR_NULL);
    CHECK_ERR(sca3000_wait_ready(NULL, 0u, NULL), INC_ERR_NULL);
}

static void test_pacing(void)
{
    struct sensor_sample s;
    uint32_t period, missed = 7;
    uint64_t t0;
    REQUIRE(fx_setup(SIM_SCA3000_E04) == INC_OK);
    fx_input(0.0, 0.0, 1.0, 25.0);
    period = sca3000_period_ns(&fx.dev);
    CHECK_EQ_INT(period, 10000000); /* 100 Hz in normal mode: ceil(1e12 / 100000 mHz) */
    t0 = fx.board.clk.now_ns;
    REQUIRE(sensor_next(&sen, 0u, &s) == INC_OK); /* the first waits one period too */
    CHECK_EQ_INT(s.t_ns, t0 + period);
    CHECK_EQ_INT(s.missed, 0);
    CHECK_EQ_INT(s.flags, SENSOR_S_HAVE_ACCEL); /* no temperature on the E04 */
    CHECK_NEAR_INT(s.accel_g[2], FX_Q16_ONE, FX_Q16_ONE / 200);
    REQUIRE(sensor_next(&sen, 0u, &s) == INC_OK);
    CHECK_EQ_INT(s.t_ns, t0 + 2u * period);
    /* 3.5 periods late: three periods lost */
    fx_wait_ns(4u * (uint64_t)period + period / 2u);
    REQUIRE(sensor_next(&sen, 0u, &s) == INC_OK);
    CHECK_EQ_INT(s.missed, 3);
    t0 = s.t_ns; /* a late wait returns at once: the sample is taken now */
    REQUIRE(sensor_next(&sen, 0u, &s) == INC_OK);
    CHECK_EQ_INT(s.t_ns, t0 + period);
    CHECK_EQ_INT(s.missed, 0);
    /* a timeout shorter than the wait: INC_ERR_TIMEOUT after the timeout, the pacing kept */
    t0 = fx.board.clk.now_ns;
    CHECK_ERR(sca3000_wait_ready(&fx.dev, 1000u, &missed), INC_ERR_TIMEOUT);
    CHECK_EQ_INT(missed, 0);
    CHECK_EQ_INT(fx.board.clk.now_ns, t0 + 1000u);
    CHECK_OK(sca3000_wait_ready(&fx.dev, 0u, &missed));
    CHECK_EQ_INT(missed, 0);
    /* motion detection has no output rate */
    REQUIRE(sca3000_set_mode(&fx.dev, SCA3000_MODE_MOTION) == INC_OK);
    CHECK_EQ_INT(sca3000_period_ns(&fx.dev), 0);
    CHECK_ERR(sensor_wait_ready(&sen, 0u), INC_ERR_STATE);
    CHECK_NO_VIOLATIONS();
}

static void test_no_hal(void)
{
    REQUIRE(fx_setup_part(SIM_SCA3000_E02, 0) == INC_OK);
    fx.cfg.hal = NULL;
    fx.cfg.int_pin = HAL_PIN_NONE;
    REQUIRE(sensor_init(&sen, &fx.cfg) == INC_OK);
    CHECK_ERR(sensor_wait_ready(&sen, 0u), INC_ERR_STATE); /* pacing needs the HAL's clock */
    CHECK_NO_VIOLATIONS();
}

static void test_d01_temperature_saturation(void)
{
    struct sensor_sample s;
    int32_t c;
    REQUIRE(fx_setup(SIM_SCA3000_D01) == INC_OK);
    fx_input(0.0, 0.0, 1.0, 30.0);
    REQUIRE(sensor_next(&sen, 0u, &s) == INC_OK);
    CHECK_EQ_INT(s.flags, SENSOR_S_HAVE_ACCEL | SENSOR_S_HAVE_TEMP);
    CHECK_NEAR_INT(s.temp_c, FX_Q16_INT(30), FX_Q16_ONE);
    /* the D01 is 0.75 mg: 1 g is 1333 counts */
    REQUIRE(sca3000_accel_g_from_counts(1333, SCA3000_D01, &c) == INC_OK);
    CHECK_EQ_INT(s.accel_g[2], c);
    /* beyond the 13-bit range on y (3.07 g): the end count, flagged on that axis only */
    fx_input(0.0, -5.0, 1.0, 30.0);
    REQUIRE(sensor_next(&sen, 0u, &s) == INC_OK);
    CHECK_EQ_INT(s.flags & SENSOR_S_ACCEL_SAT, SENSOR_S_ACCEL_SAT_X << 1);
    CHECK_NO_VIOLATIONS();
}

static void test_diag_identity_info(void)
{
    static const uint32_t product[4] = {SCA3000_PRODUCT_D01, SCA3000_PRODUCT_E02,
                                        SCA3000_PRODUCT_E04, SCA3000_PRODUCT_E05};
    static const int32_t fs[4] = {201327, 268435, 536871, 1677722}; /* 3.072 .. 25.6 g */
    static const uint32_t rate[4] = {250000u, 125000u, 100000u, 200000u};
    struct sensor_diag d;
    struct sensor_identity id;
    struct sensor_info info;
    unsigned v;
    for (v = 0; v < 4u; v++) {
        REQUIRE(fx_setup((enum sim_sca3000_variant)v) == INC_OK);
        CHECK_OK(sensor_get_identity(&sen, &id));
        CHECK_EQ_INT(id.family, SENSOR_FAMILY_SCA3000);
        CHECK_EQ_HEX(id.product, product[v]);
        CHECK_EQ_HEX(id.revision, SCA3000_REVID_DEFAULT);
        CHECK_EQ_INT(id.serial | id.lot_id1 | id.lot_id2, 0);
        CHECK_OK(sensor_get_info(&sen, &info));
        CHECK_EQ_INT(info.accel_fs_g, fs[v]);
        CHECK_EQ_INT(info.gyro_fs_dps, 0);
        CHECK_EQ_INT(info.rate_mhz, rate[v]);
        CHECK_EQ_INT(info.rate_mhz, sca3000_odr_mhz(&fx.dev));
    }
    CHECK_OK(sensor_read_diag(&sen, &d));
    CHECK_EQ_INT(d.flags, 0);
    CHECK_EQ_INT(d.supply_v, 0);
    sim_sca3000_set_faults(&fx.part, SIM_SCA3000_FAULT_EEPROM);
    CHECK_OK(sensor_read_diag(&sen, &d)); /* the part reports; the read worked */
    CHECK_EQ_INT(d.flags, SENSOR_D_MEMORY);
    CHECK((d.raw & SCA3000_STATUS_EEPROM) != 0u);
    CHECK_ERR(sensor_self_test(&sen, &d), INC_ERR_UNSUPPORTED);
    CHECK_NO_VIOLATIONS();
}

int main(void)
{
    UNIT_RUN(test_refused_before_init);
    UNIT_RUN(test_pacing);
    UNIT_RUN(test_no_hal);
    UNIT_RUN(test_d01_temperature_saturation);
    UNIT_RUN(test_diag_identity_info);
    return unit_report();
}
