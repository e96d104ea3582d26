/*
 * The ADIS1636x/1640x driver through its ops table (adis_imu_sensor_ops, inclino/sensor.h):
 * init through the table, a sample in physical units with the driver's conversions, per-axis
 * saturation, the missed count across a stale read, the 1636x temperature mean, diagnostics,
 * self-test, identity (with the 1636x serial and lot ids), info from the configured range, and
 * every op's refusal before init.
 */
#include <string.h>

#include "fixture.h"
#include "adis_imu_regs.h" /* white-box: the driver's register map */
#include "inclino/sensor.h"
#include "unit.h"

static struct sensor sen = {&adis_imu_sensor_ops, &fx.imu};

static void input(double gx, double ax, double az)
{
    struct sim_inertial_input in;
    memset(&in, 0, sizeof in);
    in.rate_dps[0] = gx;
    in.accel_g[0] = ax;
    in.accel_g[2] = az;
    in.temp_c = 25.0 + 14.0; /* 100 TEMP_OUT counts on the 1640x */
    in.supply_v = 5.0;
    fx_set_input_settled(&in);
}

static void test_refused_before_init(void)
{
    struct sensor_sample s;
    struct sensor_diag d;
    struct sensor_identity id;
    struct sensor_info info;
    memset(&fx.imu, 0, sizeof fx.imu);
    CHECK_ERR(sensor_wait_ready(&sen, 0u), INC_ERR_STATE);
    CHECK_ERR(sensor_read(&sen, &s), INC_ERR_STATE);
    CHECK_ERR(sensor_read_diag(&sen, &d), INC_ERR_STATE);
    CHECK_ERR(sensor_self_test(&sen, &d), INC_ERR_STATE);
    CHECK_ERR(sensor_get_identity(&sen, &id), INC_ERR_STATE);
    CHECK_EQ_INT(id.family, SENSOR_FAMILY_NONE);
    CHECK_ERR(sensor_get_info(&sen, &info), INC_ERR_STATE);
    CHECK_EQ_INT(info.accel_fs_g, 0);
    CHECK_ERR(adis_imu_sensor_ops.read(NULL, &s), INC_ERR_NULL);
    CHECK_ERR(adis_imu_sensor_ops.wait_ready(NULL, 0u), INC_ERR_NULL);
    CHECK_ERR(adis_imu_sensor_ops.read_diag(&fx.imu, NULL), INC_ERR_NULL);
    CHECK_ERR(adis_imu_sensor_ops.info(&fx.imu, NULL), INC_ERR_NULL);
}

static void test_adis16405_sample(void)
{
    struct sensor_sample s;
    struct sensor_info info;
    struct sensor_identity id;
    struct sensor_diag d;
    int32_t g;
    fx_setup(SIM_ADIS16405);
    REQUIRE(sensor_init(&sen, &fx.cfg) == INC_OK);
    input(10.0, 0.0, 1.0);
    REQUIRE(sensor_next(&sen, 0u, &s) == INC_OK);
    CHECK_EQ_INT(s.flags, SENSOR_S_HAVE_ACCEL | SENSOR_S_HAVE_GYRO | SENSOR_S_HAVE_TEMP);
    /* 1 g = 300 counts of 3.333 mg; 10 deg/s = 200 counts of 0.05 deg/s (the default +-300) */
    REQUIRE(adis_imu_accel_g_from_counts(300, 3333u, &g) == INC_OK);
    CHECK_NEAR_INT(s.accel_g[2], g, 2 * 218); /* +-1 count of noise */
    CHECK_NEAR_INT(s.gyro_dps[0], FX_Q16_INT(10), 2 * 3277);
    CHECK_NEAR_INT(s.temp_c, FX_Q16_INT(39), 65536 / 5);
    CHECK(s.t_ns != 0u);

    CHECK_OK(sensor_get_info(&sen, &info));
    CHECK_EQ_INT(info.gyro_fs_dps, FX_Q16_INT(300));
    CHECK_EQ_INT(info.accel_fs_g, 1789391); /* 8192 x 3.333 mg = 27.303936 g */
    CHECK_EQ_INT(info.rate_mhz, 819200);
    REQUIRE(adis_imu_set_filter(&fx.imu, 4u, ADIS_IMU_RANGE_75) == INC_OK);
    CHECK_OK(sensor_get_info(&sen, &info));
    CHECK_EQ_INT(info.gyro_fs_dps, FX_Q16_INT(75));

    CHECK_OK(sensor_get_identity(&sen, &id));
    CHECK_EQ_INT(id.family, SENSOR_FAMILY_ADIS163XX);
    CHECK_EQ_INT(id.product, 16405);
    CHECK_EQ_INT(id.serial, 0); /* the 1640x has none */

    CHECK_OK(sensor_read_diag(&sen, &d));
    CHECK_EQ_INT(d.flags, 0);
    CHECK_NEAR_INT(d.supply_v, FX_Q16_INT(5), 65536 / 100);
    sim_adis_imu_raise_diag(&fx.part, ADIS_IMU_DIAG_SUPPLY_HIGH | ADIS_IMU_DIAG_ALARM2);
    CHECK_OK(sensor_read_diag(&sen, &d)); /* the read worked: the part reports */
    CHECK_EQ_INT(d.flags, SENSOR_D_SUPPLY | SENSOR_D_ALARM);
    CHECK_EQ_HEX(d.raw, ADIS_IMU_DIAG_SUPPLY_HIGH | ADIS_IMU_DIAG_ALARM2);

    CHECK_OK(sensor_self_test(&sen, &d));
    CHECK_EQ_INT(d.flags, 0);
    sim_adis_imu_set_self_test_fail(&fx.part, ADIS_IMU_DIAG_XACCL_ST);
    CHECK_ERR(sensor_self_test(&sen, &d), INC_ERR_DEVICE);
    CHECK_EQ_INT(d.flags, SENSOR_D_SELF_TEST);
    CHECK_EQ_INT(fx_violations(), 0);
}

/* Over the rated range the model clips and sets DIAG_STAT overrange (EA on every word): the
 * read fails and hands out nothing, so no clipped value reaches the caller as a plain sample. */
static void test_overrange(void)
{
    struct sensor_sample s;
    struct sensor_diag d;
    fx_setup(SIM_ADIS16405);
    REQUIRE(sensor_init(&sen, &fx.cfg) == INC_OK);
    input(-350.0, 0.0, 1.0);
    CHECK_ERR(sensor_next(&sen, 0u, &s), INC_ERR_DEVICE);
    CHECK_EQ_INT(s.flags, 0);
    CHECK_EQ_INT(s.gyro_dps[0], 0);
    input(0.0, 0.0, 1.0);
    CHECK_OK(sensor_read_diag(&sen, &d));
    REQUIRE(sensor_next(&sen, 0u, &s) == INC_OK);
    CHECK_EQ_INT(s.flags & (SENSOR_S_GYRO_SAT | SENSOR_S_ACCEL_SAT), 0);
    CHECK_EQ_INT(fx_violations(), 0);
}

static void test_missed_and_stale(void)
{
    struct sensor_sample s;
    fx_setup(SIM_ADIS16405);
    REQUIRE(sensor_init(&sen, &fx.cfg) == INC_OK);
    input(0.0, 0.0, 1.0);
    REQUIRE(sensor_next(&sen, 0u, &s) == INC_OK);
    /* a read right after a read: ND clear, the sample is stale and counts as missed */
    CHECK_ERR(sensor_read(&sen, &s), INC_ERR_STALE);
    CHECK_EQ_INT(s.flags, 0);
    REQUIRE(sensor_next(&sen, 0u, &s) == INC_OK);
    CHECK_EQ_INT(s.missed, 1);
    /* five periods without a read: four or five edges beyond the one waited for */
    hal_delay_ns(&fx.board.hal, 5u * adis_imu_current_period_ns(&fx.imu));
    REQUIRE(sensor_next(&sen, 0u, &s) == INC_OK);
    CHECK(s.missed >= 4u && s.missed <= 5u);
    REQUIRE(sensor_next(&sen, 0u, &s) == INC_OK);
    CHECK_EQ_INT(s.missed, 0);
    /* without data-ready the wait is refused */
    REQUIRE(adis_imu_dr_config(&fx.imu, false, ADIS_IMU_DR_DIO1, false) == INC_OK);
    CHECK_ERR(sensor_wait_ready(&sen, 0u), INC_ERR_STATE);
    CHECK_EQ_INT(fx_violations(), 0);
}

static void test_adis16364_identity_and_temps(void)
{
    struct sensor_sample s;
    struct sensor_identity id;
    struct sensor_info info;
    fx_setup(SIM_ADIS16364);
    REQUIRE(sensor_init(&sen, &fx.cfg) == INC_OK);
    input(0.0, 0.0, 1.0);
    REQUIRE(sensor_next(&sen, 0u, &s) == INC_OK);
    /* the mean of the three gyro temperatures: 39 degC = 102.9 counts of 0.136 */
    CHECK_NEAR_INT(s.temp_c, FX_Q16_INT(39), 65536 / 5);
    CHECK_OK(sensor_get_identity(&sen, &id));
    CHECK_EQ_INT(id.family, SENSOR_FAMILY_ADIS163XX);
    CHECK_EQ_INT(id.product, 16364);
    CHECK_EQ_INT(id.serial, sim_adis_imu_peek(&fx.part, ADIS1636X_REG_SERIAL_NUM));
    CHECK_EQ_INT(id.lot_id1, sim_adis_imu_peek(&fx.part, ADIS1636X_REG_LOT_ID1));
    CHECK_EQ_INT(id.lot_id2, sim_adis_imu_peek(&fx.part, ADIS1636X_REG_LOT_ID2));
    CHECK_OK(sensor_get_info(&sen, &info));
    CHECK_EQ_INT(info.accel_fs_g, 536871); /* 8192 x 1 mg */
    CHECK_EQ_INT(fx_violations(), 0);
}

/* DIAG_STAT -> SENSOR_D_*, one bit at a time and all error bits at once. */
static uint32_t expected_flags(uint16_t d)
{
    uint32_t f = 0u;
    if ((d & (ADIS_IMU_DIAG_SUPPLY_LOW | ADIS_IMU_DIAG_SUPPLY_HIGH)) != 0u) f |= SENSOR_D_SUPPLY;
    if ((d & ADIS_IMU_DIAG_SELF_TEST_BITS) != 0u) f |= SENSOR_D_SELF_TEST;
    if ((d & ADIS_IMU_DIAG_OVERRANGE) != 0u) f |= SENSOR_D_OVERRANGE;
    if ((d & ADIS_IMU_DIAG_SPI_FAIL) != 0u) f |= SENSOR_D_BUS;
    if ((d & (ADIS_IMU_DIAG_FLASH_UPDATE | ADIS_IMU_DIAG_FLASH_CHECKSUM)) != 0u) {
        f |= SENSOR_D_MEMORY;
    }
    if ((d & (ADIS_IMU_DIAG_ALARM1 | ADIS_IMU_DIAG_ALARM2)) != 0u) f |= SENSOR_D_ALARM;
    return f;
}

static void test_diag_bits(void)
{
    struct sensor_diag d;
    unsigned b;
    fx_setup(SIM_ADIS16405);
    REQUIRE(sensor_init(&sen, &fx.cfg) == INC_OK);
    input(0.0, 0.0, 1.0);
    CHECK_OK(sensor_read_diag(&sen, &d)); /* the power-up flags, once */
    for (b = 0; b <= 16u; b++) {
        const uint16_t bits = b == 16u ? (uint16_t)ADIS_IMU_DIAG_ERRORS : (uint16_t)(1u << b);
        if (b == 7u) {
            continue; /* never set by a live part (a bus fault) */
        }
        sim_adis_imu_raise_diag(&fx.part, bits);
        CHECK_OK(sensor_read_diag(&sen, &d));
        CHECK_EQ_HEX(d.raw, bits);
        CHECK_EQ_HEX(d.flags, expected_flags(bits));
    }
    CHECK_EQ_INT(fx_violations(), 0);
}

/* The gyro full scale of every range; the temperature exactly that of the part's counts (the
 * 1636x mean of three equal die temperatures, the 1640x TEMP_OUT). */
static void test_info_ranges_and_temp(void)
{
    static const struct {
        enum sim_adis_imu_variant v;
        uint8_t temp_addr;
        enum adis_imu_family f;
    } parts[] = {
        {SIM_ADIS16364, ADIS1636X_REG_XTEMP_OUT, ADIS_IMU_FAMILY_1636X},
        {SIM_ADIS16405, ADIS1640X_REG_TEMP_OUT, ADIS_IMU_FAMILY_1640X},
    };
    size_t k;
    for (k = 0; k < sizeof parts / sizeof parts[0]; k++) {
        struct sensor_sample s;
        struct sensor_info info;
        int32_t want = 0;
        fx_setup(parts[k].v);
        REQUIRE(sensor_init(&sen, &fx.cfg) == INC_OK);
        input(0.0, 0.0, 1.0);
        REQUIRE(sensor_next(&sen, 0u, &s) == INC_OK);
        REQUIRE(adis_imu_temp_c_from_counts(
                    adis_sign_extend(sim_adis_imu_peek(&fx.part, parts[k].temp_addr), 12u),
                    parts[k].f, &want) == INC_OK);
        CHECK_EQ_INT(s.temp_c, want);
        REQUIRE(adis_imu_set_filter(&fx.imu, 2u, ADIS_IMU_RANGE_150) == INC_OK);
        CHECK_OK(sensor_get_info(&sen, &info));
        CHECK_EQ_INT(info.gyro_fs_dps, FX_Q16_INT(150));
        REQUIRE(adis_imu_set_filter(&fx.imu, 4u, ADIS_IMU_RANGE_75) == INC_OK);
        CHECK_OK(sensor_get_info(&sen, &info));
        CHECK_EQ_INT(info.gyro_fs_dps, FX_Q16_INT(75));
        REQUIRE(adis_imu_set_filter(&fx.imu, 0u, ADIS_IMU_RANGE_300) == INC_OK);
        CHECK_OK(sensor_get_info(&sen, &info));
        CHECK_EQ_INT(info.gyro_fs_dps, FX_Q16_INT(300));
        CHECK_EQ_INT(fx_violations(), 0);
    }
}

int main(void)
{
    UNIT_RUN(test_refused_before_init);
    UNIT_RUN(test_adis16405_sample);
    UNIT_RUN(test_overrange);
    UNIT_RUN(test_missed_and_stale);
    UNIT_RUN(test_adis16364_identity_and_temps);
    UNIT_RUN(test_diag_bits);
    UNIT_RUN(test_info_ranges_and_temp);
    return unit_report();
}
