/*
 * ADIS1636x/1640x pure functions: raw -> physical (Q16.16), offset conversions, sample rate,
 * variant and register tables, DIAG_STAT decoding.
 *
 * The conversions claim exact rounding (nearest, ties away from zero) of the exact rational:
 * each is checked exhaustively over its input range with integer arithmetic only -
 * 2 |q x den - num| <= den, and on a tie the magnitude rounds up - plus exact vectors.
 */
#include "inclino/adis_imu.h"
#include "adis_imu_regs.h" /* white-box: the driver's register map */
#include "inclino/fx.h"
#include "unit.h"

#include <string.h>

/* The fallible conversions, for inputs where they must succeed. */
static int32_t gyro_dps(int32_t c, enum adis_imu_range r)
{
    int32_t v = 0;
    CHECK_OK(adis_imu_gyro_dps_from_counts(c, r, &v));
    return v;
}

static int32_t accel_g(int32_t c, uint32_t lsb_ug)
{
    int32_t v = 0;
    CHECK_OK(adis_imu_accel_g_from_counts(c, lsb_ug, &v));
    return v;
}

static int32_t temp_c(int32_t c, enum adis_imu_family f)
{
    int32_t v = 0;
    CHECK_OK(adis_imu_temp_c_from_counts(c, f, &v));
    return v;
}

static int32_t accel_off_to_g(int32_t c, uint32_t lsb_ug)
{
    int32_t v = 0;
    CHECK_OK(adis_imu_accel_off_g_from_counts(c, lsb_ug, &v));
    return v;
}

static int16_t accel_off_from_g(int32_t g, uint32_t lsb_ug, bool *sat)
{
    int16_t v = 0;
    CHECK_OK(adis_imu_accel_off_counts_from_g(g, lsb_ug, &v, sat));
    return v;
}

/* q is num/den rounded to nearest, ties away from zero (den > 0). */
static bool rounds_exactly(int64_t q, int64_t num, int64_t den)
{
    const int64_t e = q * den - num; /* error x den */
    const int64_t a = e < 0 ? -e : e;
    if (2 * a < den) {
        return true;
    }
    if (2 * a == den) { /* a tie: |q| must be the larger magnitude */
        return (num >= 0 && e > 0) || (num < 0 && e < 0);
    }
    return false;
}

#if UNIT_REDUCED
#define Q_STEP 61
#else
#define Q_STEP 1
#endif

static unsigned bad;
static void expect_round(int64_t q, int64_t num, int64_t den)
{
    if (!rounds_exactly(q, num, den)) {
        if (bad++ < 5u) {
            CHECK(rounds_exactly(q, num, den)); /* print the first few */
        }
    }
}

static void test_gyro_exhaustive(void)
{
    static const enum adis_imu_range r[3] = {ADIS_IMU_RANGE_300, ADIS_IMU_RANGE_150,
                                             ADIS_IMU_RANGE_75};
    static const int64_t den[3] = {10, 20, 40}; /* 0.05 deg/s = 32768/10 Q16.16 counts */
    int32_t c;
    unsigned k;
    bad = 0;
    for (k = 0; k < 3u; k++) {
        for (c = -8192; c <= 8191; c++) {
            expect_round(gyro_dps(c, r[k]), (int64_t)c * 32768, den[k]);
        }
    }
    CHECK_EQ_INT(bad, 0);
    CHECK_EQ_INT(gyro_dps(6000, ADIS_IMU_RANGE_300), 300 * 65536);
    CHECK_EQ_INT(gyro_dps(-6000, ADIS_IMU_RANGE_300), -300 * 65536);
    CHECK_EQ_INT(gyro_dps(6000, ADIS_IMU_RANGE_75), 75 * 65536);
    CHECK_EQ_INT(gyro_dps(-1, ADIS_IMU_RANGE_300), -3277);        /* -3276.8 */
    CHECK_EQ_INT(gyro_dps(1, ADIS_IMU_RANGE_150), 1638);          /* 1638.4 */
    CHECK_EQ_INT(gyro_dps(1, ADIS_IMU_RANGE_75), 819);            /* 819.2 */
    CHECK_EQ_INT(gyro_dps(-8192, ADIS_IMU_RANGE_300), -26843546); /* -409.6 */
    CHECK_EQ_INT(gyro_dps(5, ADIS_IMU_RANGE_300), 16384);         /* 0.25 exactly */
    {
        int32_t v = 7;
        CHECK_ERR(adis_imu_gyro_dps_from_counts(100, (enum adis_imu_range)3, &v), INC_ERR_INVAL);
        CHECK_EQ_INT(v, 0); /* never a plausible value with an error */
        CHECK_ERR(adis_imu_gyro_dps_from_counts(100, ADIS_IMU_RANGE_300, NULL), INC_ERR_NULL);
        v = 7;
        CHECK_ERR(adis_imu_temp_c_from_counts(0, (enum adis_imu_family)2, &v), INC_ERR_INVAL);
        CHECK_EQ_INT(v, 0);
        CHECK_ERR(adis_imu_temp_c_from_counts(0, ADIS_IMU_FAMILY_1636X, NULL), INC_ERR_NULL);
    }
    /* Out-of-range input is clamped, never overflows. */
    CHECK_EQ_INT(gyro_dps(INT32_MAX, ADIS_IMU_RANGE_75), 65535 * 819 + 13107);
    CHECK(gyro_dps(INT32_MIN, ADIS_IMU_RANGE_300) < 0);
}

static void test_other_channels_exhaustive(void)
{
    static const uint32_t lsbs[3] = {3333u, 333u, 1000u};
    int32_t c;
    unsigned k;
    bad = 0;
    for (k = 0; k < 3u; k++) {
        for (c = -8192; c <= 8191; c++) {
            expect_round(accel_g(c, lsbs[k]), (int64_t)c * lsbs[k] * 65536, 1000000);
        }
    }
    for (c = -2048; c <= 2047; c++) {
        expect_round(temp_c(c, ADIS_IMU_FAMILY_1636X), (25000 + (int64_t)c * 136) * 65536, 1000);
        expect_round(temp_c(c, ADIS_IMU_FAMILY_1640X), (25000 + (int64_t)c * 140) * 65536, 1000);
    }
    for (c = 0; c <= 16383; c++) {
        expect_round(adis_imu_supply_v_from_counts(c), (int64_t)c * 2418 * 65536, 1000000);
    }
    for (c = -8192; c <= 8191; c++) {
        expect_round(adis_imu_magn_gauss_from_counts(c), (int64_t)c * 65536, 2000);
    }
    for (c = 0; c <= 4095; c++) {
        expect_round(adis_imu_aux_v_from_counts(c), (int64_t)c * 8058 * 65536, 10000000);
    }
    CHECK_EQ_INT(bad, 0);
    /* vectors */
    CHECK_EQ_INT(accel_g(300, 3333), 65529);  /* 0.9999 g = 65529.4 */
    CHECK_EQ_INT(accel_g(1000, 1000), 65536); /* 1 g exactly */
    CHECK_EQ_INT(accel_g(-1, 333), -22);      /* -21.82 */
    {
        int32_t v = 7;
        CHECK_ERR(adis_imu_accel_g_from_counts(1, 0, &v), INC_ERR_INVAL);
        CHECK_EQ_INT(v, 0);
        v = 7;
        CHECK_ERR(adis_imu_accel_g_from_counts(1, 100001u, &v), INC_ERR_INVAL);
        CHECK_EQ_INT(v, 0);
        CHECK_ERR(adis_imu_accel_g_from_counts(1, 1000u, NULL), INC_ERR_NULL);
    }
    CHECK_EQ_INT(temp_c(0, ADIS_IMU_FAMILY_1636X), 25 * 65536);
    CHECK_EQ_INT(temp_c(-2048, ADIS_IMU_FAMILY_1636X), -16615211); /* -253.528 C */
    CHECK_EQ_INT(temp_c(100, ADIS_IMU_FAMILY_1640X), 39 * 65536);  /* 25 + 14 */
    CHECK_EQ_INT(adis_imu_supply_v_from_counts(0x814), 327708);    /* 5.000424 V */
    CHECK_EQ_INT(adis_imu_supply_v_from_counts(1964), 311227);     /* 4.748952 V = 311227.3 */
    CHECK_EQ_INT(adis_imu_magn_gauss_from_counts(2000), 65536);    /* 1 gauss */
    CHECK_EQ_INT(adis_imu_magn_gauss_from_counts(-1), -33);        /* -32.768 */
    CHECK_EQ_INT(adis_imu_aux_v_from_counts(4095), 216252);        /* 3.299751 V = 216252.48 */
}

static void test_gyro_offsets(void)
{
    bool sat = true;
    int32_t q, c;
    bad = 0;
    /* to deg/s: exhaustive over the 13-bit register */
    for (c = -4096; c <= 4095; c++) {
        expect_round(adis_imu_gyro_off_dps_from_counts(c), (int64_t)c * 65536, 80);
    }
    /* from deg/s: every Q16.16 value within the register range and beyond it (every 61st under
     * QEMU, where 64-bit divisions are slow) */
    for (q = -3500000; q <= 3500000; q += Q_STEP) {
        const int16_t o = adis_imu_gyro_off_counts_from_dps(q, &sat);
        const int64_t num = (int64_t)q * 80;
        if (o > -4096 && o < 4095) {
            expect_round(o, num, 65536);
            if (sat && bad++ < 5u) {
                CHECK(!sat);
            }
        } else if ((o == 4095 && num > 4095 * 65536 + 32767) ||
                   (o == -4096 && num < -4096 * 65536 - 32768)) {
            if (!sat && bad++ < 5u) {
                CHECK(sat); /* beyond the register: saturated and flagged */
            }
        } else {
            expect_round(o, num, 65536);
        }
    }
    CHECK_EQ_INT(bad, 0);
    CHECK_EQ_INT(adis_imu_gyro_off_counts_from_dps(65536, &sat), 80); /* 1 deg/s x 80 */
    CHECK(!sat);
    CHECK_EQ_INT(adis_imu_gyro_off_counts_from_dps(2048, NULL), 3);   /* 2.5 -> 3 (tie) */
    CHECK_EQ_INT(adis_imu_gyro_off_counts_from_dps(-2048, NULL), -3); /* -2.5 -> -3 */
    CHECK_EQ_INT(adis_imu_gyro_off_counts_from_dps(2047, NULL), 2);
    CHECK_EQ_INT(adis_imu_gyro_off_counts_from_dps(-3355443, &sat), -4096); /* -51.2 deg/s */
    CHECK(!sat);
    CHECK_EQ_INT(adis_imu_gyro_off_counts_from_dps(3355443, &sat), 4095); /* +51.2: clipped */
    CHECK(sat);
    CHECK_EQ_INT(adis_imu_gyro_off_counts_from_dps(INT32_MAX, &sat), 4095);
    CHECK(sat);
    CHECK_EQ_INT(adis_imu_gyro_off_counts_from_dps(INT32_MIN, &sat), -4096);
    CHECK(sat);
    CHECK_EQ_INT(adis_imu_gyro_off_dps_from_counts(80), 65536);
    CHECK_EQ_INT(adis_imu_gyro_off_dps_from_counts(-1), -819);               /* -0.0125 = -819.2 */
    CHECK_EQ_INT(adis_imu_gyro_off_dps_from_counts(9999), 4095 * 8192 / 10); /* saturated first */
}

static void test_accel_offsets(void)
{
    bool sat = true;
    int32_t c;
    bad = 0;
    for (c = -2048; c <= 2047; c++) {
        expect_round(accel_off_to_g(c, 3333), (int64_t)c * 3333 * 65536, 1000000);
        expect_round(accel_off_from_g(accel_off_to_g(c, 333), 333, &sat) - c, 0, 1);
        if (sat && bad++ < 5u) {
            CHECK(!sat);
        }
    }
    CHECK_EQ_INT(bad, 0);
    CHECK_EQ_INT(accel_off_from_g(65536, 1000, &sat), 1000); /* 1 g at 1 mg */
    CHECK(!sat);
    CHECK_EQ_INT(accel_off_from_g(-65536, 3333, &sat), -300); /* -300.03 */
    CHECK_EQ_INT(accel_off_from_g(3 * 65536, 1000, &sat), 2047);
    CHECK(sat);
    CHECK_EQ_INT(accel_off_from_g(-3 * 65536, 1000, &sat), -2048);
    CHECK(sat);
    {
        int16_t o = 7;
        int32_t g = 7;
        CHECK_ERR(adis_imu_accel_off_counts_from_g(65536, 0, &o, &sat), INC_ERR_INVAL);
        CHECK_EQ_INT(o, 0);
        CHECK(!sat);
        CHECK_ERR(adis_imu_accel_off_counts_from_g(65536, 1000, NULL, &sat), INC_ERR_NULL);
        CHECK_EQ_INT(accel_off_to_g(1000, 1000), 65536);
        CHECK_ERR(adis_imu_accel_off_g_from_counts(1, 200000, &g), INC_ERR_INVAL);
        CHECK_EQ_INT(g, 0);
        CHECK_ERR(adis_imu_accel_off_g_from_counts(1, 1000, NULL), INC_ERR_NULL);
    }
}

static void test_sample_rate(void)
{
    CHECK_EQ_INT(adis_imu_sample_period_ns(0x01), 1220703);     /* 819.2 SPS */
    CHECK_EQ_INT(adis_imu_sample_period_ns(0x00), 610352);      /* 1638.4 SPS */
    CHECK_EQ_INT(adis_imu_sample_period_ns(0x09), 6103516);     /* 163.84 SPS */
    CHECK_EQ_INT(adis_imu_sample_period_ns(0x7F), 78125000);    /* 128 x tB */
    CHECK_EQ_INT(adis_imu_sample_period_ns(0xFF), 2421875000u); /* 128 x 31 x tB */
    CHECK_EQ_INT(adis_imu_sample_rate_msps(0x01), 819200);
    CHECK_EQ_INT(adis_imu_sample_rate_msps(0x0A), 148945); /* 148.945 SPS */
    CHECK_EQ_INT(adis_imu_sample_rate_msps(0x80), 52852);  /* 1638.4/31 = 52.8516 */
    CHECK(!adis_imu_smpl_prd_is_low_power(0x09));
    CHECK(adis_imu_smpl_prd_is_low_power(0x0A));
    CHECK(adis_imu_smpl_prd_is_low_power(0x81));
}

static void test_tables(void)
{
    static const uint16_t ids[6] = {0x3FE8, 0x3FEA, 0x3FEC, 0x3FED, 0x4010, 0x4015};
    static const char *const names[6] = {"ADIS16360", "ADIS16362", "ADIS16364",
                                         "ADIS16365", "ADIS16400", "ADIS16405"};
    const struct adis_imu_reg_desc *d;
    size_t n = 0, i;
    unsigned v, f;
    for (v = 0; v < 6u; v++) {
        const struct adis_imu_variant_info *vi = adis_imu_variant_info((enum adis_imu_variant)v);
        REQUIRE(vi != NULL);
        CHECK_EQ_HEX(vi->prod_id, ids[v]);
        CHECK(strcmp(vi->name, names[v]) == 0);
        CHECK_EQ_INT(adis_imu_variant_from_prod_id(ids[v]), v);
        CHECK_EQ_INT(vi->burst_words, v < 4u ? 11 : 12);
        CHECK_EQ_INT(vi->family, v < 4u ? ADIS_IMU_FAMILY_1636X : ADIS_IMU_FAMILY_1640X);
        CHECK(vi->reset_ms >= 130u && vi->self_test_ms >= 12u);
    }
    CHECK_EQ_INT(adis_imu_variant_info(ADIS_IMU_ADIS16362)->accel_lsb_ug, 333);
    CHECK_EQ_INT(adis_imu_variant_info(ADIS_IMU_ADIS16364)->accel_lsb_ug, 1000);
    CHECK_EQ_INT(adis_imu_variant_info(ADIS_IMU_ADIS16405)->accel_lsb_ug, 3333);
    CHECK_EQ_INT(adis_imu_variant_from_prod_id(0x4105), ADIS_IMU_UNKNOWN); /* OPTEC's typo */
    CHECK(adis_imu_variant_info(ADIS_IMU_ANY) == NULL);
    CHECK(strcmp(adis_imu_variant_name(ADIS_IMU_UNKNOWN), "unknown") == 0);
    for (f = 0; f < 2u; f++) {
        const struct adis_imu_reg_desc *m = adis_imu_reg_map((enum adis_imu_family)f, &n);
        REQUIRE(m != NULL);
        CHECK_EQ_INT(n, f == 0u ? 35 : 39); /* docs/sensor-facts.md §3.2 */
        for (i = 0; i < n; i++) {
            CHECK_EQ_INT(m[i].addr & 1u, 0);
            CHECK(m[i].addr <= 0x7Eu);
            CHECK(m[i].bits >= 8u && m[i].bits <= 16u);
            if (i > 0u) {
                CHECK(m[i].addr > m[i - 1u].addr); /* sorted, unique */
            }
        }
    }
    CHECK(adis_imu_reg_map((enum adis_imu_family)2, &n) == NULL);
    CHECK_EQ_INT(n, 0);
    d = adis_imu_reg_find(ADIS_IMU_FAMILY_1636X, ADIS1636X_REG_XTEMP_OUT);
    REQUIRE(d != NULL);
    CHECK(strcmp(d->name, "XTEMP_OUT") == 0 && d->bits == 12u && d->is_output && d->is_signed);
    d = adis_imu_reg_find(ADIS_IMU_FAMILY_1640X, ADIS1640X_REG_XMAGN_OUT);
    REQUIRE(d != NULL);
    CHECK(strcmp(d->name, "XMAGN_OUT") == 0 && d->bits == 14u);
    d = adis_imu_reg_find(ADIS_IMU_FAMILY_1640X, ADIS_IMU_REG_XGYRO_OFF);
    REQUIRE(d != NULL);
    CHECK(d->bits == 13u && d->access == ADIS_IMU_RW && !d->is_output);
    d = adis_imu_reg_find(ADIS_IMU_FAMILY_1640X, ADIS1640X_REG_AUX_ADC);
    REQUIRE(d != NULL);
    CHECK(strcmp(d->name, "AUX_ADC") == 0 && !d->is_signed);
    d = adis_imu_reg_find(ADIS_IMU_FAMILY_1636X, ADIS_IMU_REG_GLOB_CMD);
    REQUIRE(d != NULL);
    CHECK_EQ_INT(d->access, ADIS_IMU_WO);
    CHECK(adis_imu_reg_find(ADIS_IMU_FAMILY_1640X, ADIS1636X_REG_SERIAL_NUM) == NULL);
    CHECK(adis_imu_reg_find(ADIS_IMU_FAMILY_1636X, ADIS1640X_REG_ALM_CTRL) == NULL);
}

/* adis_imu_read_known (adis_imu_regs.h) skips the map look-up of adis_imu_read_reg: each
 * constant address the driver reads with it must be a readable register of the family it is
 * read on, so that the two give the same result. */
static void test_read_known_addresses(void)
{
    static const uint8_t r1636x[] = {ADIS1636X_REG_SERIAL_NUM, ADIS1636X_REG_LOT_ID1,
                                     ADIS1636X_REG_LOT_ID2, ADIS_IMU_REG_SUPPLY_OUT};
    const struct adis_imu_reg_desc *d;
    unsigned i;
    for (i = 0; i < sizeof(r1636x); i++) {
        d = adis_imu_reg_find(ADIS_IMU_FAMILY_1636X, r1636x[i]);
        CHECK(d != NULL && (d->access & ADIS_IMU_RO) != 0u && r1636x[i] != ADIS_IMU_REG_DIAG_STAT);
    }
    d = adis_imu_reg_find(ADIS_IMU_FAMILY_1640X, ADIS_IMU_REG_SUPPLY_OUT);
    CHECK(d != NULL && (d->access & ADIS_IMU_RO) != 0u);
}

static void test_diag(void)
{
    struct adis_imu_diag d;
    unsigned b;
    adis_imu_diag_decode(0, &d);
    CHECK(!d.any && !d.supply_low && !d.gyro_st_fail[0]);
    adis_imu_diag_decode(0x0080, &d); /* the unused bit is not an error */
    CHECK(!d.any);
    adis_imu_diag_decode(0xFFFF, &d);
    CHECK(d.any && d.supply_low && d.supply_high && d.flash_update_fail && d.spi_fail &&
          d.overrange && d.self_test_fail && d.flash_checksum && d.alarm1 && d.alarm2);
    CHECK(d.gyro_st_fail[0] && d.gyro_st_fail[1] && d.gyro_st_fail[2]);
    CHECK(d.accel_st_fail[0] && d.accel_st_fail[1] && d.accel_st_fail[2]);
    adis_imu_diag_decode(0x0800, &d);
    CHECK(d.gyro_st_fail[1] && !d.gyro_st_fail[0] && !d.gyro_st_fail[2] && d.any);
    adis_imu_diag_decode(0x2000, &d);
    CHECK(d.accel_st_fail[0] && !d.accel_st_fail[1]);
    adis_imu_diag_decode(0x0008, NULL); /* no crash */
    for (b = 0; b < 16u; b++) {
        CHECK(strlen(adis_imu_diag_bit_name(b)) > 0u);
    }
    CHECK(strcmp(adis_imu_diag_bit_name(3), "SPI communication failure") == 0);
    CHECK(strcmp(adis_imu_diag_bit_name(16), "") == 0);
    CHECK_EQ_HEX(ADIS_IMU_DIAG_ERRORS | ADIS_IMU_DIAG_UNUSED, 0xFFFF);
}

/* Every range, family and LSB code: valid ones convert (and only those), the others fail with
 * INC_ERR_INVAL and 0; the NULL check comes first. Against the rationals written out here,
 * counts clamped to [-65536, 65535]. Codes up to 255: with the ARM EABI's short enums (the
 * cross builds) a cast of 256 and above wraps to a valid code. */
static void test_conversion_codes(void)
{
    static const int32_t counts[] = {0, 1, -1, 5, -8192, 8191, 65535, -65536, 70000, -70000};
    int code;
    size_t i;
    for (code = -3; code <= 255; code++) {
        const bool range_ok = code == 1 || code == 2 || code == 4;
        const bool family_ok = code == 0 || code == 1;
        for (i = 0; i < sizeof counts / sizeof counts[0]; i++) {
            const int64_t c = counts[i] > 65535 ? 65535 : (counts[i] < -65536 ? -65536 : counts[i]);
            int32_t v = 7;
            CHECK_ERR(adis_imu_gyro_dps_from_counts(counts[i], (enum adis_imu_range)code, &v),
                      range_ok ? INC_OK : INC_ERR_INVAL);
            CHECK_EQ_INT(v, range_ok ? fx_div64(c * 32768, 40u / (uint32_t)code) : 0);
            v = 7;
            CHECK_ERR(adis_imu_temp_c_from_counts(counts[i], (enum adis_imu_family)code, &v),
                      family_ok ? INC_OK : INC_ERR_INVAL);
            CHECK_EQ_INT(v, family_ok ? fx_div64((25000 + c * (code == 0 ? 136 : 140)) * 8192, 125u)
                                      : 0);
        }
        CHECK_ERR(adis_imu_gyro_dps_from_counts(0, (enum adis_imu_range)code, NULL), INC_ERR_NULL);
        CHECK_ERR(adis_imu_temp_c_from_counts(0, (enum adis_imu_family)code, NULL), INC_ERR_NULL);
    }
    {
        static const uint32_t lsbs[] = {0u, 1u, 333u, 3333u, 100000u, 100001u, UINT32_MAX};
        size_t k;
        for (k = 0; k < sizeof lsbs / sizeof lsbs[0]; k++) {
            const bool ok = lsbs[k] >= 1u && lsbs[k] <= 100000u;
            for (i = 0; i < sizeof counts / sizeof counts[0]; i++) {
                const int64_t c = counts[i] > 65535 ? 65535
                                                    : (counts[i] < -65536 ? -65536 : counts[i]);
                int32_t v = 7;
                CHECK_ERR(adis_imu_accel_g_from_counts(counts[i], lsbs[k], &v),
                          ok ? INC_OK : INC_ERR_INVAL);
                CHECK_EQ_INT(v, ok ? fx_div64(c * (int64_t)lsbs[k] * 1024, 15625u) : 0);
            }
            CHECK_ERR(adis_imu_accel_g_from_counts(0, lsbs[k], NULL), INC_ERR_NULL);
        }
    }
    for (i = 0; i < sizeof counts / sizeof counts[0]; i++) {
        const int64_t c = counts[i] > 65535 ? 65535 : (counts[i] < -65536 ? -65536 : counts[i]);
        CHECK_EQ_INT(adis_imu_supply_v_from_counts(counts[i]), fx_div64(c * 2418 * 1024, 15625u));
        CHECK_EQ_INT(adis_imu_magn_gauss_from_counts(counts[i]), fx_div64(c * 65536, 2000u));
        CHECK_EQ_INT(adis_imu_aux_v_from_counts(counts[i]), fx_div64(c * 8058 * 4096, 625000u));
    }
}

int main(void)
{
    UNIT_RUN(test_gyro_exhaustive);
    UNIT_RUN(test_other_channels_exhaustive);
    UNIT_RUN(test_gyro_offsets);
    UNIT_RUN(test_accel_offsets);
    UNIT_RUN(test_sample_rate);
    UNIT_RUN(test_tables);
    UNIT_RUN(test_read_known_addresses);
    UNIT_RUN(test_diag);
    UNIT_RUN(test_conversion_codes);
    return unit_report();
}
