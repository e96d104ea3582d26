/*
 * sca3000_regs.h - the SCA3000 register addresses, command bit, MODE bits and protected-bit masks
 * the driver uses (private to drivers/sca3000: callers see inclino/sca3000.h; the white-box tests
 * of tests/sca3000 include it too). docs/drivers-sca3000.md, "Registers used".
 */
#ifndef INCLINO_SCA3000_REGS_H
#define INCLINO_SCA3000_REGS_H

/* ---- direct registers (docs/sensor-facts.md §1.3) ------------------------------------------ */

#define SCA3000_REG_REVID 0x00u
#define SCA3000_REG_STATUS 0x02u
#define SCA3000_REG_X_LSB 0x04u
#define SCA3000_REG_X_MSB 0x05u
#define SCA3000_REG_Y_LSB 0x06u
#define SCA3000_REG_Y_MSB 0x07u
#define SCA3000_REG_Z_LSB 0x08u
#define SCA3000_REG_Z_MSB 0x09u
#define SCA3000_REG_BUF_DATA 0x0Fu
#define SCA3000_REG_TEMP_LSB 0x12u
#define SCA3000_REG_TEMP_MSB 0x13u
#define SCA3000_REG_MODE 0x14u
#define SCA3000_REG_BUF_COUNT 0x15u
#define SCA3000_REG_INT_STATUS 0x16u
#define SCA3000_REG_CTRL_SEL 0x18u
#define SCA3000_REG_UNLOCK 0x1Eu
#define SCA3000_REG_INT_MASK 0x21u
#define SCA3000_REG_CTRL_DATA 0x22u

#define SCA3000_CMD_WRITE 0x02u

#define SCA3000_MODE_BUF_EN 0x80u
#define SCA3000_MODE_BUF_8BIT 0x40u
#define SCA3000_MODE_FFD_EN 0x10u
#define SCA3000_MODE_PROTECT 0x28u /* reserved: kept as read */
#define SCA3000_MODE_MEAS_MASK 0x03u

#define SCA3000_INT_MASK_PROTECT 0x1Cu
#define SCA3000_INT_MASK_ACTIVE_HIGH 0x01u

#define SCA3000_MD_CTRL_PROTECT 0xC0u
#define SCA3000_OUT_CTRL_PROTECT 0xE0u /* must stay set ("the device will not function") */

#endif /* INCLINO_SCA3000_REGS_H */
