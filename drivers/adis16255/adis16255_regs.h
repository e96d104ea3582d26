/*
 * adis16255_regs.h - the ADIS16250/16255 register addresses, MSC_CTRL and COMMAND bits the
 * driver uses (private to drivers/adis16255: callers see inclino/adis16255.h; the white-box tests
 * of tests/adis16255 include it too). docs/drivers-adis16255.md, "Registers".
 */
#ifndef INCLINO_ADIS16255_REGS_H
#define INCLINO_ADIS16255_REGS_H

/* ---- register map (docs/sensor-facts.md §2.3) ---------------------------------------------- */
/* Lower (even) byte addresses; the upper byte is addr + 1. 6-bit addresses. */
#define ADIS16255_REG_ENDURANCE 0x00u  /* flash write counter, 16-bit, no ND/EA */
#define ADIS16255_REG_SUPPLY_OUT 0x02u /* 12-bit binary, 1.8315 mV/LSB */
#define ADIS16255_REG_GYRO_OUT 0x04u   /* 14-bit two's complement */
#define ADIS16255_REG_AUX_ADC 0x0Au    /* 12-bit binary, 0.6105 mV/LSB */
#define ADIS16255_REG_TEMP_OUT 0x0Cu   /* 12-bit two's complement, 0.1453 °C/LSB, 0 = 25 °C */
#define ADIS16255_REG_ANGL_OUT 0x0Eu   /* 14-bit angle [U] format and scale */
#define ADIS16255_REG_GYRO_OFF 0x14u   /* 12-bit two's complement offset [U] LSB */
#define ADIS16255_REG_GYRO_SCALE 0x16u /* 12-bit unsigned, 0x0800 = x1.0 */
#define ADIS16255_REG_ALM_MAG1 0x20u
#define ADIS16255_REG_ALM_MAG2 0x22u
#define ADIS16255_REG_ALM_SMPL1 0x24u
#define ADIS16255_REG_ALM_SMPL2 0x26u
#define ADIS16255_REG_ALM_CTRL 0x28u
#define ADIS16255_REG_AUX_DAC 0x30u
#define ADIS16255_REG_GPIO_CTRL 0x32u
#define ADIS16255_REG_MSC_CTRL 0x34u
#define ADIS16255_REG_SMPL_PRD 0x36u /* bit 7 time base, bits 6..0 NS; 8-bit register */
#define ADIS16255_REG_SENS_AVG 0x38u /* range and filter, [U] layout (below) */
#define ADIS16255_REG_SLP_CNT 0x3Au
#define ADIS16255_REG_STATUS 0x3Cu
#define ADIS16255_REG_COMMAND 0x3Eu /* 8-bit register, write only */

/* MSC_CTRL (docs/sensor-facts.md §2.3). */
#define ADIS16255_MSC_DR_LINE 0x0001u     /* data-ready line: 0 = DIO0, 1 = DIO1 [U] */
#define ADIS16255_MSC_DR_POL_HIGH 0x0002u /* data-ready active high */
#define ADIS16255_MSC_DR_EN 0x0004u       /* data-ready enable */
#define ADIS16255_MSC_ST_POS 0x0100u      /* manual self-test, positive */
#define ADIS16255_MSC_ST_NEG 0x0200u      /* manual self-test, negative */
#define ADIS16255_MSC_ST_INT 0x0400u      /* internal self-test; clears itself when done */
#define ADIS16255_MSC_DEFINED 0x0707u     /* bits the driver knows; the rest read 0 */

/* COMMAND (docs/sensor-facts.md §2.3). */
#define ADIS16255_CMD_AUTONULL 0x01u
#define ADIS16255_CMD_FACTORY_RESTORE 0x02u
#define ADIS16255_CMD_DAC_LATCH 0x04u
#define ADIS16255_CMD_FLASH_UPDATE 0x08u
#define ADIS16255_CMD_RESET 0x80u


#endif /* INCLINO_ADIS16255_REGS_H */
