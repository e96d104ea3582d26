/*
 * adis.h - the register protocol shared by the Analog Devices iSensor parts Inclino drives
 * (ADIS16250/16255 gyroscope, ADIS1636x/1640x IMUs). Family drivers build on it; it only sees
 * struct spi_dev frames. (Their data-ready edge counting is every driver's: struct sensor_dr,
 * inclino/sensor.h.)
 *
 * Protocol (docs/sensor-facts.md §2.2, §3.1; ADIS16250/55 Rev B p. 11, ADIS1636x/1640x datasheets):
 *   - SPI mode 3, MSB first, 16-bit frames, CS toggled with the part's stall time between frames
 *     (the device's struct spi_timing carries it);
 *   - read: DIN = addr << 8 (bit 15 = 0); the whole 16-bit register comes out on DOUT during the
 *     NEXT frame, so n registers take n + 1 frames (the reads are pipelined);
 *   - write: DIN = 0x8000 | addr << 8 | byte, one byte per frame: the low byte at the even
 *     address, then the high byte at addr + 1.
 * Output registers carry ND (bit 15, new data since the last read) and EA (bit 14, error or
 * alarm: see the part's DIAG_STAT/STATUS); data bits are below.
 */
#ifndef INCLINO_ADIS_H
#define INCLINO_ADIS_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "inclino/error.h"
#include "inclino/hal.h"
#include "inclino/spi.h"

#ifdef __cplusplus
extern "C" {
#endif

#define ADIS_FLAG_ND 0x8000u /* new data since the register was last read */
#define ADIS_FLAG_EA 0x4000u /* error or alarm active */
#define ADIS_WRITE 0x8000u   /* write bit of a command frame */
#define ADIS_ADDR_MAX 0x7Fu  /* 7-bit addresses (the ADIS16255 uses 6 bits) */
/* Registers per adis_read_regs call: the drivers read at most 14 at once (every channel of an
 * ADIS1636x/1640x); the buffers of 17 frames sit on the stack of the small images' deepest path. */
#define ADIS_MAX_PIPELINE 16u

/* Read one 16-bit register (2 frames): the bus traffic, results and errors of
 * adis_read_regs(dev, &addr, value, 1), with a 2-frame buffer (a small stack frame). */
int adis_read_reg(struct spi_dev *dev, uint8_t addr, uint16_t *value);

/*
 * Read n (1..ADIS_MAX_PIPELINE) registers in one pipelined sequence of n + 1 frames: frame k
 * sends the read of addrs[k] and receives addrs[k-1]; the last frame sends a read of
 * register 0x00 (harmless) to clock out addrs[n-1]. values[k] = register addrs[k].
 */
int adis_read_regs(struct spi_dev *dev, const uint8_t *addrs, uint16_t *values, size_t n);

/*
 * adis_read_regs with the trailing frame's command chosen: it reads register tail_addr (its
 * value arrives in the first frame of the next sequence to the part), and *first (may be NULL)
 * receives this sequence's first MISO word: the answer to the previous sequence's trailing
 * command when nothing else went to the part in between. A driver that always ends its sample
 * read with the same register learns from *first, at no bus cost, whether the part still
 * answers that register as expected (a busy part answers garbage, a reset one its defaults).
 * adis_read_regs(dev, addrs, values, n) is adis_read_regs_tail(dev, addrs, values, n, 0, NULL).
 * Errors as adis_read_regs; INC_ERR_INVAL also for tail_addr > ADIS_ADDR_MAX.
 */
int adis_read_regs_tail(struct spi_dev *dev, const uint8_t *addrs, uint16_t *values, size_t n,
                        uint8_t tail_addr, uint16_t *first);

/* Write one byte (1 frame). */
int adis_write_byte(struct spi_dev *dev, uint8_t addr, uint8_t value);

/* Write a 16-bit register: low byte to addr (even), high byte to addr + 1 (2 frames). */
int adis_write_reg(struct spi_dev *dev, uint8_t addr, uint16_t value);

/*
 * The signed value of the low `bits` bits of a register (two's complement), e.g. 14 for a gyro
 * output: adis_sign_extend(0x3FFF, 14) == -1, adis_sign_extend(0x1770, 14) == 6000. The bits
 * above (ND, EA) are ignored. bits in 1..16.
 */
int32_t adis_sign_extend(uint16_t raw, unsigned bits);

/* The unsigned value of the low `bits` bits of a register. bits in 1..16. */
uint16_t adis_field(uint16_t raw, unsigned bits);

/*
 * The count to write to a user-offset register (ADIS16255 GYRO_OFF, ADIS1636x/1640x XGYRO_OFF
 * and XACCL_OFF): round(num / den), ties away from zero, saturated to the register's two's
 * complement range [-2^(bits-1), 2^(bits-1) - 1]. The caller forms num / den exactly: num = the
 * offset in its fixed-point format x the register's LSB per unit (numerator), exact in int64;
 * den = the format's scale x the denominator, e.g. Q16.16 deg/s at 80 LSB per deg/s is
 * (dps_q16 * 80) / 65536. Any num. *saturated (may be NULL) is set when the rounded quotient
 * lies outside the register's range (the result is then the nearest end), cleared otherwise.
 * |error| <= 0.5 LSB when not saturated. den == 0 or bits outside 2..16: 0, *saturated set.
 * Returns the count (the caller masks it to the register's width).
 */
int32_t adis_offset_counts(int64_t num, uint32_t den, unsigned bits, bool *saturated);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_ADIS_H */
