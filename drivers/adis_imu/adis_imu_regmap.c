/*
 * adis_imu_regmap.c - the register maps of both families and the DIAG_STAT bit names, by name
 * (see adis_imu.h). A translation unit of their own, with their strings: an image that never
 * looks a register up by a caller's address (the driver's own reads go to constant addresses,
 * adis_imu_read_known in adis_imu_regs.h) links none of it.
 *
 * Sources: docs/sensor-facts.md §3.2 (map), §3.4 (control registers).
 */
#include "inclino/adis_imu.h"

#include "adis_imu_regs.h"

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
