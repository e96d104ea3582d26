/*
 * adis_imu_tables.c - what the driver knows about the parts, as data: variants, DIAG_STAT
 * decoding, and the pure raw -> physical conversions (see adis_imu.h; the register maps and the
 * DIAG_STAT bit names are in adis_imu_regmap.c).
 *
 * Sources: docs/sensor-facts.md §3.3 (scales), §3.4 (control registers,
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
