/*
 * adis_imu_tables.c - what the driver knows about the parts, as data: variants, register maps,
 * DIAG_STAT names, and the pure raw -> physical conversions (see adis_imu.h).
 *
 * Sources: docs/sensor-facts.md §3.2 (map), §3.3 (scales), §3.4 (control registers,
 * timings), §3.5 (PROD_ID); [ADI-IMU-QS] (offset register resolution, the x80 rule).
 */
#include "inclino/adis_imu.h"

#include "adis_imu_regs.h"

#include "inclino/fx.h"

/*
 * Per-variant facts. Waits: Linux's sw_reset_ms / self_test_ms (docs/sensor-facts.md §3.4) are the longest
 * figures any source gives for each part (OPTEC's ADIS16405 reset is 100/170 ms, the ADIS16367's
 * 60/130 ms), so the driver takes them. The 16360/16365 use Linux's ADIS16300 table (290 ms).
 */
static const struct adis_imu_variant_info variants[ADIS_IMU_VARIANT_COUNT] = {
    {"ADIS16360", ADIS_IMU_PROD_ID_16360, ADIS_IMU_FAMILY_1636X, 11u, 3333u, 3333u, 12u, 290u,
     290u},
    {"ADIS16362", ADIS_IMU_PROD_ID_16362, ADIS_IMU_FAMILY_1636X, 11u, 333u, 333u, 12u, 130u, 12u},
    {"ADIS16364", ADIS_IMU_PROD_ID_16364, ADIS_IMU_FAMILY_1636X, 11u, 1000u, 1000u, 12u, 130u, 12u},
    {"ADIS16365", ADIS_IMU_PROD_ID_16365, ADIS_IMU_FAMILY_1636X, 11u, 3333u, 3333u, 12u, 290u,
     290u},
    {"ADIS16400", ADIS_IMU_PROD_ID_16400, ADIS_IMU_FAMILY_1640X, 12u, 3333u, 3333u, 14u, 170u, 12u},
    {"ADIS16405", ADIS_IMU_PROD_ID_16405, ADIS_IMU_FAMILY_1640X, 12u, 3333u, 3333u, 14u, 170u, 12u},
};

const struct adis_imu_variant_info *adis_imu_variant_info(enum adis_imu_variant v)
{
    if ((unsigned)v >= (unsigned)ADIS_IMU_VARIANT_COUNT) {
        return NULL;
    }
    return &variants[v];
}

enum adis_imu_variant adis_imu_variant_from_prod_id(uint16_t id)
{
    unsigned i;
    for (i = 0; i < (unsigned)ADIS_IMU_VARIANT_COUNT; i++) {
        if (variants[i].prod_id == id) {
            return (enum adis_imu_variant)i;
        }
    }
    return ADIS_IMU_UNKNOWN;
}

const char *adis_imu_variant_name(enum adis_imu_variant v)
{
    const struct adis_imu_variant_info *vi = adis_imu_variant_info(v);
    return vi != NULL ? vi->name : "unknown";
}

/* Register maps (docs/sensor-facts.md §3.2). Widths: outputs §3.3; offsets §3.4 (13-bit gyro: our
 * choice, listed in docs/unconfirmed-facts.md); control registers by their used bits. */
#define OUT_S(n, a, b)                   \
    {                                    \
        n, a, b, ADIS_IMU_RO, true, true \
    }
#define OUT_U(n, a, b)                    \
    {                                     \
        n, a, b, ADIS_IMU_RO, true, false \
    }
#define RW_S(n, a, b)                     \
    {                                     \
        n, a, b, ADIS_IMU_RW, false, true \
    }
#define RW_U(n, a, b)                      \
    {                                      \
        n, a, b, ADIS_IMU_RW, false, false \
    }
#define RO_U(n, a, b)                      \
    {                                      \
        n, a, b, ADIS_IMU_RO, false, false \
    }

static const struct adis_imu_reg_desc map_1636x[] = {
    RO_U("FLASH_CNT", 0x00, 16),
    OUT_U("SUPPLY_OUT", 0x02, 12),
    OUT_S("XGYRO_OUT", 0x04, 14),
    OUT_S("YGYRO_OUT", 0x06, 14),
    OUT_S("ZGYRO_OUT", 0x08, 14),
    OUT_S("XACCL_OUT", 0x0A, 14),
    OUT_S("YACCL_OUT", 0x0C, 14),
    OUT_S("ZACCL_OUT", 0x0E, 14),
    OUT_S("XTEMP_OUT", 0x10, 12),
    OUT_S("YTEMP_OUT", 0x12, 12),
    OUT_S("ZTEMP_OUT", 0x14, 12),
    OUT_U("AUX_ADC", 0x16, 12),
    RW_S("XGYRO_OFF", 0x1A, 13),
    RW_S("YGYRO_OFF", 0x1C, 13),
    RW_S("ZGYRO_OFF", 0x1E, 13),
    RW_S("XACCL_OFF", 0x20, 12),
    RW_S("YACCL_OFF", 0x22, 12),
    RW_S("ZACCL_OFF", 0x24, 12),
    RW_U("ALM_MAG1", 0x26, 16),
    RW_U("ALM_MAG2", 0x28, 16),
    RW_U("ALM_SMPL1", 0x2A, 8),
    RW_U("ALM_SMPL2", 0x2C, 8),
    RW_U("ALM_CTRL", 0x2E, 16),
    RW_U("AUX_DAC", 0x30, 12),
    RW_U("GPIO_CTRL", 0x32, 16),
    RW_U("MSC_CTRL", 0x34, 12),
    RW_U("SMPL_PRD", 0x36, 8),
    RW_U("SENS_AVG", 0x38, 11),
    RW_U("SLP_CNT", 0x3A, 9),
    RO_U("DIAG_STAT", 0x3C, 16),
    {"GLOB_CMD", 0x3E, 8, ADIS_IMU_WO, false, false},
    RO_U("LOT_ID1", 0x52, 16),
    RO_U("LOT_ID2", 0x54, 16),
    RO_U("PROD_ID", 0x56, 16),
    RO_U("SERIAL_NUM", 0x58, 16),
};

static const struct adis_imu_reg_desc map_1640x[] = {
    RO_U("FLASH_CNT", 0x00, 16),  OUT_U("SUPPLY_OUT", 0x02, 14),
    OUT_S("XGYRO_OUT", 0x04, 14), OUT_S("YGYRO_OUT", 0x06, 14),
    OUT_S("ZGYRO_OUT", 0x08, 14), OUT_S("XACCL_OUT", 0x0A, 14),
    OUT_S("YACCL_OUT", 0x0C, 14), OUT_S("ZACCL_OUT", 0x0E, 14),
    OUT_S("XMAGN_OUT", 0x10, 14), OUT_S("YMAGN_OUT", 0x12, 14),
    OUT_S("ZMAGN_OUT", 0x14, 14), OUT_S("TEMP_OUT", 0x16, 12),
    OUT_U("AUX_ADC", 0x18, 12),   RW_S("XGYRO_OFF", 0x1A, 13),
    RW_S("YGYRO_OFF", 0x1C, 13),  RW_S("ZGYRO_OFF", 0x1E, 13),
    RW_S("XACCL_OFF", 0x20, 12),  RW_S("YACCL_OFF", 0x22, 12),
    RW_S("ZACCL_OFF", 0x24, 12),  RW_S("XMAGN_HIF", 0x26, 14),
    RW_S("YMAGN_HIF", 0x28, 14),  RW_S("ZMAGN_HIF", 0x2A, 14),
    RW_U("XMAGN_SIF", 0x2C, 12),  RW_U("YMAGN_SIF", 0x2E, 12),
    RW_U("ZMAGN_SIF", 0x30, 12),  RW_U("GPIO_CTRL", 0x32, 16),
    RW_U("MSC_CTRL", 0x34, 12),   RW_U("SMPL_PRD", 0x36, 8),
    RW_U("SENS_AVG", 0x38, 11),   RW_U("SLP_CNT", 0x3A, 9),
    RO_U("DIAG_STAT", 0x3C, 16),  {"GLOB_CMD", 0x3E, 8, ADIS_IMU_WO, false, false},
    RW_U("ALM_MAG1", 0x40, 16),   RW_U("ALM_MAG2", 0x42, 16),
    RW_U("ALM_SMPL1", 0x44, 8),   RW_U("ALM_SMPL2", 0x46, 8),
    RW_U("ALM_CTRL", 0x48, 16),   RW_U("AUX_DAC", 0x4A, 12),
    RO_U("PRODUCT_ID", 0x56, 16),
};

const struct adis_imu_reg_desc *adis_imu_reg_map(enum adis_imu_family f, size_t *count)
{
    const struct adis_imu_reg_desc *m;
    size_t n;
    if (f == ADIS_IMU_FAMILY_1636X) {
        m = map_1636x;
        n = sizeof(map_1636x) / sizeof(map_1636x[0]);
    } else if (f == ADIS_IMU_FAMILY_1640X) {
        m = map_1640x;
        n = sizeof(map_1640x) / sizeof(map_1640x[0]);
    } else {
        m = NULL;
        n = 0;
    }
    if (count != NULL) {
        *count = n;
    }
    return m;
}

const struct adis_imu_reg_desc *adis_imu_reg_find(enum adis_imu_family f, uint8_t addr)
{
    size_t n = 0, i;
    const struct adis_imu_reg_desc *m = adis_imu_reg_map(f, &n);
    for (i = 0; i < n; i++) {
        if (m[i].addr == addr) {
            return &m[i];
        }
    }
    return NULL;
}

static const char *const diag_names[16] = {
    "supply < 4.75 V",
    "supply > 5.25 V",
    "flash update failure",
    "SPI communication failure",
    "sensor over range",
    "self-test error",
    "flash checksum",
    "unused",
    "alarm 1",
    "alarm 2",
    "Z gyro self-test failure",
    "Y gyro self-test failure",
    "X gyro self-test failure",
    "X accel self-test failure",
    "Y accel self-test failure",
    "Z accel self-test failure",
};

const char *adis_imu_diag_bit_name(unsigned bit)
{
    return bit < 16u ? diag_names[bit] : "";
}

void adis_imu_diag_decode(uint16_t diag, struct adis_imu_diag *out)
{
    if (out == NULL) {
        return;
    }
    out->supply_low = (diag & ADIS_IMU_DIAG_SUPPLY_LOW) != 0u;
    out->supply_high = (diag & ADIS_IMU_DIAG_SUPPLY_HIGH) != 0u;
    out->flash_update_fail = (diag & ADIS_IMU_DIAG_FLASH_UPDATE) != 0u;
    out->spi_fail = (diag & ADIS_IMU_DIAG_SPI_FAIL) != 0u;
    out->overrange = (diag & ADIS_IMU_DIAG_OVERRANGE) != 0u;
    out->self_test_fail = (diag & ADIS_IMU_DIAG_SELF_TEST) != 0u;
    out->flash_checksum = (diag & ADIS_IMU_DIAG_FLASH_CHECKSUM) != 0u;
    out->alarm1 = (diag & ADIS_IMU_DIAG_ALARM1) != 0u;
    out->alarm2 = (diag & ADIS_IMU_DIAG_ALARM2) != 0u;
    out->gyro_st_fail[0] = (diag & ADIS_IMU_DIAG_XGYRO_ST) != 0u;
    out->gyro_st_fail[1] = (diag & ADIS_IMU_DIAG_YGYRO_ST) != 0u;
    out->gyro_st_fail[2] = (diag & ADIS_IMU_DIAG_ZGYRO_ST) != 0u;
    out->accel_st_fail[0] = (diag & ADIS_IMU_DIAG_XACCL_ST) != 0u;
    out->accel_st_fail[1] = (diag & ADIS_IMU_DIAG_YACCL_ST) != 0u;
    out->accel_st_fail[2] = (diag & ADIS_IMU_DIAG_ZACCL_ST) != 0u;
    out->any = (diag & ADIS_IMU_DIAG_ERRORS) != 0u;
}

/* ---- sample rate (docs/sensor-facts.md §3.4 SMPL_PRD) ---- */

/* tB = 1/1638.4 s = 610351.5625 ns = 9765625/16 ns exactly, so periods are exact in 1/16 ns. */
#define TB_SIXTEENTHS_NS 9765625ull
#define TB_SLOW_FACTOR 31u /* 52.851 SPS base = 1638.4 / 31 (Linux constants) */

static uint32_t tb_units(uint8_t smpl_prd)
{
    uint32_t n = (uint32_t)(smpl_prd & ADIS_IMU_SMPL_PRD_NS_MASK) + 1u;
    return (smpl_prd & ADIS_IMU_SMPL_PRD_TIMEBASE) != 0u ? n * TB_SLOW_FACTOR : n;
}

uint32_t adis_imu_sample_period_ns(uint8_t smpl_prd)
{
    return (uint32_t)(((uint64_t)tb_units(smpl_prd) * TB_SIXTEENTHS_NS + 8u) / 16u);
}

uint32_t adis_imu_sample_rate_msps(uint8_t smpl_prd)
{
    const uint32_t d = tb_units(smpl_prd);
    return (1638400u + d / 2u) / d;
}

bool adis_imu_smpl_prd_is_low_power(uint8_t smpl_prd)
{
    return smpl_prd > ADIS_IMU_SMPL_PRD_NORMAL_MAX;
}

/* ---- conversions ---- */

/*
 * Each conversion forms the exact rational as an int64 numerator over a uint32 denominator and
 * lets fx_muldiv round it (ties away from zero) and saturate it to int32: the same result as
 * fx_div64 of the full product, with 32-bit divisions for the register widths (the M0+ reads
 * seven conversions per sample).
 * Inputs beyond any register width are clamped so the products below cannot overflow int64.
 */
static int64_t clamp_counts(int32_t c)
{
    if (c > 65535) {
        return 65535;
    }
    if (c < -65536) {
        return -65536;
    }
    return c;
}

static bool lsb_ok(uint32_t lsb_ug)
{
    return lsb_ug != 0u && lsb_ug <= 100000u;
}

int adis_imu_gyro_dps_from_counts(int32_t counts, enum adis_imu_range range, int32_t *dps_q16)
{
    /* 0.05 deg/s x 65536 = 32768 / 10; the LSB halves with each smaller range
     * (docs/sensor-facts.md §3.3 [D]). */
    uint32_t den;
    if (dps_q16 == NULL) {
        return INC_ERR_NULL;
    }
    switch (range) {
    case ADIS_IMU_RANGE_300: den = 10u; break;
    case ADIS_IMU_RANGE_150: den = 20u; break;
    case ADIS_IMU_RANGE_75: den = 40u; break;
    default: *dps_q16 = 0; return INC_ERR_INVAL;
    }
    *dps_q16 = fx_muldiv(clamp_counts(counts), 32768u, den);
    return INC_OK;
}

int adis_imu_accel_g_from_counts(int32_t counts, uint32_t lsb_ug, int32_t *g_q16)
{
    if (g_q16 == NULL) {
        return INC_ERR_NULL;
    }
    if (!lsb_ok(lsb_ug)) {
        *g_q16 = 0;
        return INC_ERR_INVAL;
    }
    *g_q16 = fx_muldiv(clamp_counts(counts) * (int64_t)lsb_ug, 1024u, 15625u); /* 65536 / 1e6 */
    return INC_OK;
}

int adis_imu_temp_c_from_counts(int32_t counts, enum adis_imu_family f, int32_t *c_q16)
{
    /* In milli-deg C: 25000 + counts x 136 (1636x) or x 140 (1640x); 0 counts = 25 C. */
    int64_t mc_per_lsb;
    if (c_q16 == NULL) {
        return INC_ERR_NULL;
    }
    switch (f) {
    case ADIS_IMU_FAMILY_1636X: mc_per_lsb = 136; break;
    case ADIS_IMU_FAMILY_1640X: mc_per_lsb = 140; break;
    default: *c_q16 = 0; return INC_ERR_INVAL;
    }
    *c_q16 = fx_muldiv(25000 + clamp_counts(counts) * mc_per_lsb, 8192u, 125u); /* 65536 / 1000 */
    return INC_OK;
}

int32_t adis_imu_supply_v_from_counts(int32_t counts)
{
    return fx_muldiv(clamp_counts(counts) * 2418, 1024u, 15625u); /* 2.418 mV: 65536 / 1e6 */
}

int32_t adis_imu_magn_gauss_from_counts(int32_t counts)
{
    return fx_muldiv(clamp_counts(counts), 65536u, 2000u); /* 0.5 mgauss */
}

int32_t adis_imu_aux_v_from_counts(int32_t counts)
{
    return fx_muldiv(clamp_counts(counts) * 8058, 4096u, 625000u); /* 805.8 uV: 65536 / 1e7 */
}

int16_t adis_imu_gyro_off_counts_from_dps(int32_t dps_q16, bool *saturated)
{
    /* x80 ([ADI-IMU-QS]: "multiply by 80, round"), from Q16.16. */
    return (int16_t)adis_offset_counts((int64_t)dps_q16 * ADIS_IMU_GYRO_OFF_PER_DPS, 65536u,
                                       ADIS_IMU_GYRO_OFF_BITS, saturated);
}

int32_t adis_imu_gyro_off_dps_from_counts(int32_t counts)
{
    const int32_t c = fx_clamp(counts, ADIS_IMU_GYRO_OFF_MIN, ADIS_IMU_GYRO_OFF_MAX);
    return fx_div64((int64_t)c * 65536, (uint32_t)ADIS_IMU_GYRO_OFF_PER_DPS);
}

int adis_imu_accel_off_counts_from_g(int32_t g_q16, uint32_t lsb_ug, int16_t *counts,
                                     bool *saturated)
{
    if (counts == NULL) {
        return INC_ERR_NULL;
    }
    if (!lsb_ok(lsb_ug)) {
        *counts = 0;
        if (saturated != NULL) {
            *saturated = false;
        }
        return INC_ERR_INVAL;
    }
    /* g / (lsb_ug x 1e-6) = g_q16 x 1e6 / (lsb_ug x 65536) = g_q16 x 15625 / (lsb_ug x 1024):
     * the same quotient, with a divisor that fits 32 bits. */
    *counts = (int16_t)adis_offset_counts((int64_t)g_q16 * 15625, lsb_ug * 1024u,
                                          ADIS_IMU_ACCEL_OFF_BITS, saturated);
    return INC_OK;
}

int adis_imu_accel_off_g_from_counts(int32_t counts, uint32_t lsb_ug, int32_t *g_q16)
{
    const int32_t c = fx_clamp(counts, ADIS_IMU_ACCEL_OFF_MIN, ADIS_IMU_ACCEL_OFF_MAX);
    if (g_q16 == NULL) {
        return INC_ERR_NULL;
    }
    if (!lsb_ok(lsb_ug)) {
        *g_q16 = 0;
        return INC_ERR_INVAL;
    }
    *g_q16 = fx_div64((int64_t)c * (int64_t)lsb_ug * 65536, 1000000u);
    return INC_OK;
}
