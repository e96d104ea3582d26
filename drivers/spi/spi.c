/* spi.c - device binding and argument checks shared by every bus (see spi.h). */
#include "inclino/spi.h"

int spi_timing_check(const struct spi_timing *t)
{
    if (t == NULL) {
        return INC_ERR_NULL;
    }
    if (t->sclk_period_ns < 2u) {
        return INC_ERR_INVAL;
    }
    return INC_OK;
}

uint32_t spi_period_for_hz(uint32_t hz)
{
    if (hz == 0u) {
        return 0u;
    }
    return (uint32_t)((1000000000u + (uint64_t)hz - 1u) / hz);
}

static int check_cfg(const struct spi_dev_cfg *cfg)
{
    if (cfg->cs == HAL_PIN_NONE || cfg->mode > SPI_MODE_3 ||
        (cfg->bits != 8u && cfg->bits != 16u)) {
        return INC_ERR_INVAL;
    }
    return spi_timing_check(&cfg->timing);
}

int spi_dev_init(struct spi_dev *dev, const struct spi_bus *bus, const struct spi_dev_cfg *cfg)
{
    int err;
    if (dev == NULL || bus == NULL || cfg == NULL) {
        return INC_ERR_NULL;
    }
    dev->bus = NULL; /* unusable until every check passed */
    if (bus->ops == NULL || bus->ops->transfer == NULL) {
        return INC_ERR_NULL;
    }
    err = check_cfg(cfg);
    if (err != INC_OK) {
        return err;
    }
    dev->cfg = *cfg;
    dev->cs_release_ns = 0;
    dev->released_once = false;
    dev->transfers = 0;
    if (bus->ops->attach != NULL) {
        err = bus->ops->attach(bus->ctx, dev);
        if (err != INC_OK) {
            return err;
        }
    }
    dev->bus = bus;
    return INC_OK;
}

int spi_dev_set_timing(struct spi_dev *dev, const struct spi_timing *t)
{
    int err;
    if (dev == NULL) {
        return INC_ERR_NULL;
    }
    err = spi_timing_check(t);
    if (err != INC_OK) {
        return err;
    }
    dev->cfg.timing = *t;
    return INC_OK;
}

int spi_transfer(struct spi_dev *dev, const uint16_t *tx, uint16_t *rx, size_t n,
                 enum spi_cs_policy cs)
{
    if (dev == NULL) {
        return INC_ERR_NULL;
    }
    if (dev->bus == NULL) {
        return INC_ERR_STATE;
    }
    if (n == 0u || n > SPI_MAX_FRAMES || (cs != SPI_CS_HOLD && cs != SPI_CS_TOGGLE)) {
        return INC_ERR_INVAL;
    }
    if (tx != NULL && dev->cfg.bits < 16u) {
        uint16_t over = (uint16_t) ~((1u << dev->cfg.bits) - 1u);
        size_t i;
        for (i = 0; i < n; i++) {
            if (tx[i] & over) {
                return INC_ERR_INVAL;
            }
        }
    }
    dev->transfers++;
    return dev->bus->ops->transfer(dev->bus->ctx, dev, tx, rx, n, cs);
}

int spi_xfer1(struct spi_dev *dev, uint16_t tx, uint16_t *rx)
{
    return spi_transfer(dev, &tx, rx, 1u, SPI_CS_TOGGLE);
}
