/*
 * The ADIS16255 driver through its ops table (adis16255_sensor_ops, inclino/sensor.h): a single-
 * axis gyro on z with temperature and no accelerometer, the missed count, diagnostics with the
 * supply, self-test pass and fail, identity, info from the configured range and rate, and every
 * op's refusal before init.
 */
#include <string.h>

#include "fixture.h"
#include "inclino/sensor.h"

static struct sensor sen = {&adis16255_sensor_ops, &fx.drv};

static void test_refused_before_init(void)
{
    struct sensor_sample s;
    struct sensor_diag d;
    struct sensor_identity id;
    struct sensor_info info;
    memset(&fx.drv, 0, sizeof fx.drv);
    CHECK_ERR(sensor_wait_ready(&sen, 0u), INC_ERR_STATE);
    CHECK_ERR(sensor_read(&sen, &s), INC_ERR_STATE);
    CHECK_ERR(sensor_read_diag(&sen, &d), INC_ERR_STATE);
    CHECK_ERR(sensor_self_test(&sen, &d), INC_ERR_STATE);
    CHECK_ERR(sensor_get_identity(&sen, &id), INC_ERR_STATE);
    CHECK_ERR(sensor_get_info(&sen, &info), INC_ERR_STATE);
    CHECK_ERR(adis16255_sensor_ops.read(NULL, &s), INC_ERR_NULL);
    CHECK_ERR(adis16255_sensor_ops.wait_ready(NULL, 0u), INC_ERR_NULL);
    CHECK_ERR(adis16255_sensor_ops.identity(&fx.drv, NULL), INC_ERR_NULL);
    CHECK_ERR(adis16255_sensor_ops.self_test(&fx.drv, NULL), INC_ERR_NULL);
}

static void test_sample_on_z(void)
{
    struct sensor_sample s;
    int32_t want;
    fx_setup(true);
    fx_input(100.0, 40.0, 5.0);
    REQUIRE(sensor_init(&sen, &fx.cfg) == INC_OK);
    REQUIRE(sensor_next(&sen, 0u, &s) == INC_OK);
    CHECK_EQ_INT(s.flags, SENSOR_S_HAVE_GYRO | SENSOR_S_HAVE_TEMP);
    CHECK_EQ_INT(s.gyro_dps[0], 0);
    CHECK_EQ_INT(s.gyro_dps[1], 0);
    CHECK_NEAR_INT(s.gyro_dps[2], FX_Q16_INT(100), FX_Q16_ONE / 5);
    CHECK_EQ_INT(s.accel_g[0] | s.accel_g[1] | s.accel_g[2], 0);
    CHECK_NEAR_INT(s.temp_c, FX_Q16_INT(40), FX_Q16_ONE / 5);
    CHECK_EQ_INT(s.missed, 0);
    /* the same value as the driver's own sample */
    {
        struct adis16255_sample d;
        REQUIRE(adis16255_wait_sample(&fx.drv, 0u, &d) == INC_OK);
        REQUIRE(adis16255_gyro_dps_from_word(d.gyro_word, ADIS16255_RANGE_320, &want) == INC_OK);
        CHECK_EQ_INT(d.rate_dps_q16, want);
    }
    /* a read right after a read is stale and counts as missed */
    CHECK_ERR(sensor_read(&sen, &s), INC_ERR_STALE);
    REQUIRE(sensor_next(&sen, 0u, &s) == INC_OK);
    CHECK_EQ_INT(s.missed, 1);
    /* three sample periods (3.9 ms at 256 SPS) without a read */
    fx_wait_ms(3u * 3906u / 1000u + 1u);
    REQUIRE(sensor_next(&sen, 0u, &s) == INC_OK);
    CHECK(s.missed >= 2u && s.missed <= 3u);
    CHECK_NO_VIOLATIONS();
}

static void test_diag_identity_info(void)
{
    struct sensor_diag d;
    struct sensor_identity id;
    struct sensor_info info;
    fx_setup(true);
    fx_input(0.0, 25.0, 5.0);
    REQUIRE(sensor_init(&sen, &fx.cfg) == INC_OK);
    /* init read SUPPLY_OUT: until the next sample it is stale and no supply is reported */
    CHECK_OK(sensor_read_diag(&sen, &d));
    CHECK_EQ_INT(d.supply_v, 0);
    fx_wait_ms(5u);
    CHECK_OK(sensor_read_diag(&sen, &d));
    CHECK_EQ_INT(d.flags, 0);
    CHECK_NEAR_INT(d.supply_v, FX_Q16_INT(5), FX_Q16_ONE / 100);
    CHECK_OK(sensor_get_identity(&sen, &id));
    CHECK_EQ_INT(id.family, SENSOR_FAMILY_ADIS1625X);
    CHECK_EQ_INT(id.product, 16255);
    CHECK_EQ_INT(id.revision | id.serial | id.lot_id1 | id.lot_id2, 0);
    CHECK_OK(sensor_get_info(&sen, &info));
    CHECK_EQ_INT(info.gyro_fs_dps, FX_Q16_INT(320));
    CHECK_EQ_INT(info.accel_fs_g, 0);
    CHECK_EQ_INT(info.rate_mhz, 256016); /* 1 / 3.906 ms */
    CHECK_OK(sensor_self_test(&sen, &d));
    CHECK_EQ_INT(d.flags, 0);
    sim_adis16255_fail_self_test(&fx.part, true);
    CHECK_ERR(sensor_self_test(&sen, &d), INC_ERR_DEVICE);
    CHECK((d.flags & SENSOR_D_SELF_TEST) != 0u);
    CHECK((d.raw & ADIS16255_STATUS_SELF_TEST) != 0u);
    CHECK_NO_VIOLATIONS();

    /* the +-80 range: full scale from the configuration */
    fx_setup(true);
    fx_input(0.0, 25.0, 5.0);
    fx.cfg.range = ADIS16255_RANGE_80;
    fx.cfg.filter_m = 4;
    REQUIRE(sensor_init(&sen, &fx.cfg) == INC_OK);
    CHECK_OK(sensor_get_info(&sen, &info));
    CHECK_EQ_INT(info.gyro_fs_dps, FX_Q16_INT(80));
    CHECK_NO_VIOLATIONS();
}

int main(void)
{
    UNIT_RUN(test_refused_before_init);
    UNIT_RUN(test_sample_on_z);
    UNIT_RUN(test_diag_identity_info);
    return unit_report();
}
