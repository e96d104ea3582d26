/* adis.c - shared ADIS register protocol and offset encoding (see adis.h). */
#include "inclino/adis.h"

#include "inclino/fx.h"

static uint16_t read_cmd(uint8_t addr)
{
    return (uint16_t)((uint16_t)addr << 8);
}

int adis_read_regs(struct spi_dev *dev, const uint8_t *addrs, uint16_t *values, size_t n)
{
    return adis_read_regs_tail(dev, addrs, values, n, 0x00u, NULL);
}

int adis_read_regs_tail(struct spi_dev *dev, const uint8_t *addrs, uint16_t *values, size_t n,
                        uint8_t tail_addr, uint16_t *first)
{
    uint16_t tx[ADIS_MAX_PIPELINE + 1u];
    uint16_t rx[ADIS_MAX_PIPELINE + 1u];
    size_t i;
    int err;
    if (dev == NULL || addrs == NULL || values == NULL) {
        return INC_ERR_NULL;
    }
    if (n == 0u || n > ADIS_MAX_PIPELINE || tail_addr > ADIS_ADDR_MAX) {
        return INC_ERR_INVAL;
    }
    for (i = 0; i < n; i++) {
        if (addrs[i] > ADIS_ADDR_MAX) {
            return INC_ERR_INVAL;
        }
        tx[i] = read_cmd(addrs[i]);
    }
    tx[n] = read_cmd(tail_addr);
    err = spi_transfer(dev, tx, rx, n + 1u, SPI_CS_TOGGLE);
    if (err != INC_OK) {
        return err;
    }
    for (i = 0; i < n; i++) {
        values[i] = rx[i + 1u];
    }
    if (first != NULL) {
        *first = rx[0];
    }
    return INC_OK;
}

/* The same two frames as adis_read_regs(dev, &addr, value, 1), in a frame of its own: a register
 * read inside a sample read (DIAG_STAT) is on the deepest stack path of the small images, and
 * the pipelined read's buffers are sized for 33 frames. */
int adis_read_reg(struct spi_dev *dev, uint8_t addr, uint16_t *value)
{
    uint16_t tx[2], rx[2];
    int err;
    if (dev == NULL || value == NULL) {
        return INC_ERR_NULL;
    }
    if (addr > ADIS_ADDR_MAX) {
        return INC_ERR_INVAL;
    }
    tx[0] = read_cmd(addr);
    tx[1] = read_cmd(0x00u);
    err = spi_transfer(dev, tx, rx, 2u, SPI_CS_TOGGLE);
    if (err == INC_OK) {
        *value = rx[1];
    }
    return err;
}

int adis_write_byte(struct spi_dev *dev, uint8_t addr, uint8_t value)
{
    if (dev == NULL) {
        return INC_ERR_NULL;
    }
    if (addr > ADIS_ADDR_MAX) {
        return INC_ERR_INVAL;
    }
    return spi_xfer1(dev, (uint16_t)(ADIS_WRITE | (uint16_t)addr << 8 | value), NULL);
}

int adis_write_reg(struct spi_dev *dev, uint8_t addr, uint16_t value)
{
    uint16_t tx[2];
    if (dev == NULL) {
        return INC_ERR_NULL;
    }
    if ((addr & 1u) != 0u || addr >= ADIS_ADDR_MAX) {
        return INC_ERR_INVAL;
    }
    tx[0] = (uint16_t)(ADIS_WRITE | (uint16_t)addr << 8 | (value & 0xFFu));
    tx[1] = (uint16_t)(ADIS_WRITE | (uint16_t)(addr + 1u) << 8 | (value >> 8));
    return spi_transfer(dev, tx, NULL, 2u, SPI_CS_TOGGLE);
}

int32_t adis_sign_extend(uint16_t raw, unsigned bits)
{
    uint32_t v, sign;
    if (bits == 0u || bits > 16u) {
        return 0;
    }
    v = (uint32_t)raw & ((1UL << bits) - 1UL);
    sign = 1UL << (bits - 1u);
    /* (v ^ sign) - sign: two's complement without shifting a negative value. */
    return (int32_t)(v ^ sign) - (int32_t)sign;
}

uint16_t adis_field(uint16_t raw, unsigned bits)
{
    if (bits == 0u || bits > 16u) {
        return 0;
    }
    return (uint16_t)((uint32_t)raw & ((1UL << bits) - 1UL));
}

int32_t adis_offset_counts(int64_t num, uint32_t den, unsigned bits, bool *saturated)
{
    int32_t c, lo, hi;
    bool sat;
    if (den == 0u || bits < 2u || bits > 16u) {
        if (saturated != NULL) {
            *saturated = true;
        }
        return 0;
    }
    hi = (int32_t)((1UL << (bits - 1u)) - 1UL);
    lo = -hi - 1;
    c = fx_div64(num, den); /* saturated to int32: still outside [lo, hi] when it was */
    sat = c > hi || c < lo;
    if (saturated != NULL) {
        *saturated = sat;
    }
    return fx_clamp(c, lo, hi);
}
