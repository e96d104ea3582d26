/*
 * adis_imu_regs.h - the ADIS1636x/1640x register addresses and control bits the driver uses
 * (private to drivers/adis_imu: callers see inclino/adis_imu.h; the white-box tests of
 * tests/adis_imu, tests/gyrocal and tests/app include it too). docs/drivers-adis-imu.md §1.3.
 */
#ifndef INCLINO_ADIS_IMU_REGS_H
#define INCLINO_ADIS_IMU_REGS_H

/* ---------------------------------------------------------------------------------------------
 * Register map (docs/sensor-facts.md §3.2). Addresses are the even (low-byte) address of each
 * 16-bit register; the high byte is at address + 1. ADIS_IMU_REG_* exist on both families,
 * ADIS1636X_REG_* / ADIS1640X_REG_* only on that family.
 * ------------------------------------------------------------------------------------------- */
#define ADIS_IMU_REG_FLASH_CNT 0x00u  /* 16-bit flash write counter, read-only */
#define ADIS_IMU_REG_SUPPLY_OUT 0x02u /* 12-bit (1636x) / 14-bit (1640x [U]) unsigned, 2.418 mV */
#define ADIS_IMU_REG_XGYRO_OUT 0x04u  /* 14-bit two's complement, 0.05 deg/s at +-300 deg/s */
#define ADIS_IMU_REG_YGYRO_OUT 0x06u
#define ADIS_IMU_REG_ZGYRO_OUT 0x08u
#define ADIS_IMU_REG_XACCL_OUT 0x0Au /* 14-bit two's complement, LSB per variant */
#define ADIS_IMU_REG_YACCL_OUT 0x0Cu
#define ADIS_IMU_REG_ZACCL_OUT 0x0Eu
#define ADIS1636X_REG_XTEMP_OUT 0x10u /* 12-bit two's complement, 0.136 C, 0 = 25 C */
#define ADIS1636X_REG_YTEMP_OUT 0x12u
#define ADIS1636X_REG_ZTEMP_OUT 0x14u
#define ADIS1636X_REG_AUX_ADC 0x16u   /* 12-bit unsigned, 805.8 uV */
#define ADIS1640X_REG_XMAGN_OUT 0x10u /* 14-bit two's complement, 0.5 mgauss */
#define ADIS1640X_REG_YMAGN_OUT 0x12u
#define ADIS1640X_REG_ZMAGN_OUT 0x14u
#define ADIS1640X_REG_TEMP_OUT 0x16u /* 12-bit two's complement, 0.14 C, 0 = 25 C */
#define ADIS1640X_REG_AUX_ADC 0x18u  /* 12-bit unsigned, 805.8 uV */
#define ADIS_IMU_REG_XGYRO_OFF 0x1Au /* 13-bit two's complement, 0.0125 deg/s [U width] */
#define ADIS_IMU_REG_YGYRO_OFF 0x1Cu
#define ADIS_IMU_REG_ZGYRO_OFF 0x1Eu
#define ADIS_IMU_REG_XACCL_OFF 0x20u /* 12-bit two's complement, LSB [U] */
#define ADIS_IMU_REG_YACCL_OFF 0x22u
#define ADIS_IMU_REG_ZACCL_OFF 0x24u
#define ADIS1636X_REG_ALM_MAG1 0x26u
#define ADIS1636X_REG_ALM_MAG2 0x28u
#define ADIS1636X_REG_ALM_SMPL1 0x2Au
#define ADIS1636X_REG_ALM_SMPL2 0x2Cu
#define ADIS1636X_REG_ALM_CTRL 0x2Eu
#define ADIS1636X_REG_AUX_DAC 0x30u
#define ADIS1640X_REG_XMAGN_HIF 0x26u /* magnetometer hard-iron correction */
#define ADIS1640X_REG_YMAGN_HIF 0x28u
#define ADIS1640X_REG_ZMAGN_HIF 0x2Au
#define ADIS1640X_REG_XMAGN_SIF 0x2Cu /* magnetometer soft-iron correction, default 0x0800 */
#define ADIS1640X_REG_YMAGN_SIF 0x2Eu
#define ADIS1640X_REG_ZMAGN_SIF 0x30u
#define ADIS_IMU_REG_GPIO_CTRL 0x32u
#define ADIS_IMU_REG_MSC_CTRL 0x34u /* default 0x0006 */
#define ADIS_IMU_REG_SMPL_PRD 0x36u /* default 0x0001 (819.2 SPS) */
#define ADIS_IMU_REG_SENS_AVG 0x38u /* default 0x0402 */
#define ADIS_IMU_REG_SLP_CNT 0x3Au
#define ADIS_IMU_REG_DIAG_STAT 0x3Cu
#define ADIS_IMU_REG_GLOB_CMD 0x3Eu /* write-only commands; 0x3E00 as a read = burst */
#define ADIS1640X_REG_ALM_MAG1 0x40u
#define ADIS1640X_REG_ALM_MAG2 0x42u
#define ADIS1640X_REG_ALM_SMPL1 0x44u
#define ADIS1640X_REG_ALM_SMPL2 0x46u
#define ADIS1640X_REG_ALM_CTRL 0x48u
#define ADIS1640X_REG_AUX_DAC 0x4Au
#define ADIS1636X_REG_LOT_ID1 0x52u
#define ADIS1636X_REG_LOT_ID2 0x54u
#define ADIS_IMU_REG_PROD_ID 0x56u /* "PRODUCT_ID" on the 1640x */
#define ADIS1636X_REG_SERIAL_NUM 0x58u

#define ADIS_IMU_BURST_CMD 0x3E00u /* DIN that starts a burst read */

/* MSC_CTRL bits (docs/sensor-facts.md §3.4). */
#define ADIS_IMU_MSC_DR_LINE_DIO2 0x0001u /* 1 = DIO2, 0 = DIO1 */
#define ADIS_IMU_MSC_DR_POL_HIGH 0x0002u  /* 1 = active high */
#define ADIS_IMU_MSC_DR_EN 0x0004u
#define ADIS_IMU_MSC_ACCEL_ORIGIN 0x0040u
#define ADIS_IMU_MSC_GYRO_G_COMP 0x0080u
#define ADIS_IMU_MSC_ST_MANUAL_POS 0x0100u
#define ADIS_IMU_MSC_ST_MANUAL_NEG 0x0200u
#define ADIS_IMU_MSC_SELF_TEST 0x0400u /* internal self-test; clears itself when done */
#define ADIS_IMU_MSC_MEM_TEST 0x0800u
#define ADIS_IMU_MSC_DEFAULT 0x0006u

/* ---------------------------------------------------------------------------------------------
 * Reads the driver makes at constant addresses (the serial number and lot ids of the 1636x,
 * SUPPLY_OUT): adis_imu_read_reg without the look-up in the register map, which for each of them
 * always finds a readable register of the part's family (tests/adis_imu checks every one against
 * adis_imu_reg_find). So an image that never reads a register by a caller's address links no
 * register map (adis_imu_regmap.c). Not for DIAG_STAT (adis_imu_read_diag). 0, INC_ERR_NULL,
 * INC_ERR_STATE (not initialised), a bus error.
 * ------------------------------------------------------------------------------------------- */
#include <stdint.h>
struct adis_imu;
int adis_imu_read_known(struct adis_imu *dev, uint8_t addr, uint16_t *value);

#endif /* INCLINO_ADIS_IMU_REGS_H */
