/* spi_bitbang.c - bit-banged SPI master (see spi_bitbang.h). */
#include "inclino/spi_bitbang.h"

static int bb_attach(void *ctx, struct spi_dev *dev)
{
    struct spi_bitbang *bb = ctx;
    if (dev->cfg.cs == bb->cfg.sclk || dev->cfg.cs == bb->cfg.mosi || dev->cfg.cs == bb->cfg.miso) {
        return INC_ERR_INVAL;
    }
    hal_pin_write(bb->cfg.hal, dev->cfg.cs, true);
    return INC_OK;
}

/* Busy-wait only when there is something to wait for: a call costs time on a real MCU. */
static inline void wait(const struct hal *hal, uint32_t ns)
{
    if (ns != 0u) {
        hal_delay_ns(hal, ns);
    }
}

/* The transfer of both engines: fast_only (a constant in each caller) leaves the per-bit HAL
 * loop out of an engine made by spi_bitbang_init_fast, whose fast path is never NULL. */
static inline int transfer(struct spi_bitbang *bb, struct spi_dev *dev, const uint16_t *tx,
                           uint16_t *rx, size_t n, enum spi_cs_policy cs, bool fast_only)
{
    const struct hal *hal = bb->cfg.hal;
    const struct spi_timing *t = &dev->cfg.timing;
    const hal_pin_t sclk = bb->cfg.sclk, mosi = bb->cfg.mosi, miso = bb->cfg.miso;
    const bool idle = (dev->cfg.mode & 2u) != 0u;
    const bool cpha = (dev->cfg.mode & 1u) != 0u;
    const unsigned bits = dev->cfg.bits;
    const uint32_t h1 = t->sclk_period_ns / 2u;
    const uint32_t h2 = t->sclk_period_ns - h1;
    const uint32_t gap = t->gap_ns > h2 ? t->gap_ns : h2;
    bool mosi_level = bb->mosi_level;
    size_t f;

    if (!bb->pins_known || bb->sclk_level != idle) {
        /* Every CS is high here, so moving SCLK is invisible to the parts; it must settle for a
         * half period before a CS falls, or a part (or a logic analyser) that looks at SCLK on
         * the CS edge sees the move as a clock edge. */
        hal_pin_write(hal, sclk, idle);
        bb->sclk_level = idle;
        if (!bb->pins_known) {
            hal_pin_write(hal, mosi, false);
            mosi_level = false;
            bb->pins_known = true;
        }
        wait(hal, h2);
    }

    for (f = 0; f < n; f++) {
        const uint16_t word = tx != NULL ? tx[f] : 0u;
        uint16_t in = 0;
        uint32_t lead;
        unsigned b;

        if (f == 0u || cs == SPI_CS_TOGGLE) {
            if (dev->released_once) {
                hal_delay_until(hal, dev->cs_release_ns + t->stall_ns);
            } else if (bb->released_any && bb->last_cs == dev->cfg.cs) {
                /* A device bound again to the same CS: the part still needs its stall. */
                hal_delay_until(hal, bb->last_release_ns + t->stall_ns);
            }
            hal_pin_write(hal, dev->cfg.cs, false);
            lead = t->cs_setup_ns;
        } else {
            lead = gap;
        }

        if (fast_only || bb->fast != NULL) {
            struct spi_bitbang_frame fr;
            fr.word = word;
            fr.bits = (uint8_t)bits;
            fr.cpha = cpha;
            fr.idle = idle;
            fr.mosi_level = mosi_level;
            fr.lead_ns = lead;
            fr.h1_ns = h1;
            fr.h2_ns = h2;
            in = bb->fast->frame(bb->fast->ctx, &fr, &mosi_level);
            b = 0u; /* the bit loop below has nothing left to do */
        } else {
            b = bits;
        }
        while (!fast_only && b-- > 0u) {
            const bool out = ((word >> b) & 1u) != 0u;
            const uint32_t before = b == bits - 1u ? lead : h2;
            if (!cpha) {
                if (out != mosi_level) {
                    hal_pin_write(hal, mosi, out);
                    mosi_level = out;
                }
                wait(hal, before);
                in = (uint16_t)((in << 1) | (hal_pin_read(hal, miso) ? 1u : 0u));
                hal_pin_write(hal, sclk, !idle); /* leading edge: both sides sample */
                wait(hal, h1);
                hal_pin_write(hal, sclk, idle); /* trailing edge: the part shifts */
            } else {
                wait(hal, before);
                hal_pin_write(hal, sclk, !idle); /* leading edge: the part shifts */
                if (out != mosi_level) {
                    hal_pin_write(hal, mosi, out);
                    mosi_level = out;
                }
                wait(hal, h1);
                in = (uint16_t)((in << 1) | (hal_pin_read(hal, miso) ? 1u : 0u));
                hal_pin_write(hal, sclk, idle); /* trailing edge: both sides sample */
            }
        }
        if (rx != NULL) {
            rx[f] = in;
        }
        if (cs == SPI_CS_TOGGLE || f + 1u == n) {
            wait(hal, t->cs_hold_ns);
            hal_pin_write(hal, dev->cfg.cs, true);
            dev->cs_release_ns = hal_now_ns(hal);
            dev->released_once = true;
            bb->last_cs = dev->cfg.cs;
            bb->last_release_ns = dev->cs_release_ns;
            bb->released_any = true;
        }
    }
    bb->mosi_level = mosi_level;
    return INC_OK;
}

static int bb_transfer(void *ctx, struct spi_dev *dev, const uint16_t *tx, uint16_t *rx, size_t n,
                       enum spi_cs_policy cs)
{
    return transfer(ctx, dev, tx, rx, n, cs, false);
}

static int bb_transfer_fast(void *ctx, struct spi_dev *dev, const uint16_t *tx, uint16_t *rx,
                            size_t n, enum spi_cs_policy cs)
{
    return transfer(ctx, dev, tx, rx, n, cs, true);
}

static const struct spi_bus_ops bb_ops = {
    .transfer = bb_transfer,
    .attach = bb_attach,
};

static const struct spi_bus_ops bb_fast_ops = {
    .transfer = bb_transfer_fast,
    .attach = bb_attach,
};

void spi_bitbang_set_fast(struct spi_bitbang *bb, const struct spi_bitbang_fast *fast)
{
    if (bb != NULL && (fast != NULL || bb->bus.ops != &bb_fast_ops)) {
        bb->fast = fast;
    }
}

static int init(struct spi_bitbang *bb, const struct spi_bitbang_cfg *cfg,
                const struct spi_bus_ops *ops)
{
    int err;
    if (bb == NULL || cfg == NULL) {
        return INC_ERR_NULL;
    }
    err = hal_check(cfg->hal);
    if (err != INC_OK) {
        return err;
    }
    if (cfg->sclk == HAL_PIN_NONE || cfg->mosi == HAL_PIN_NONE || cfg->miso == HAL_PIN_NONE ||
        cfg->sclk == cfg->mosi || cfg->sclk == cfg->miso || cfg->mosi == cfg->miso) {
        return INC_ERR_INVAL;
    }
    bb->cfg = *cfg;
    bb->fast = NULL;
    bb->bus.ops = ops;
    bb->bus.ctx = bb;
    bb->sclk_level = false;
    bb->mosi_level = false;
    bb->pins_known = false;
    bb->released_any = false;
    bb->last_cs = HAL_PIN_NONE;
    bb->last_release_ns = 0;
    return INC_OK;
}

int spi_bitbang_init(struct spi_bitbang *bb, const struct spi_bitbang_cfg *cfg)
{
    return init(bb, cfg, &bb_ops);
}

int spi_bitbang_init_fast(struct spi_bitbang *bb, const struct spi_bitbang_cfg *cfg,
                          const struct spi_bitbang_fast *fast)
{
    int err;
    if (fast == NULL || fast->frame == NULL) {
        return INC_ERR_NULL;
    }
    err = init(bb, cfg, &bb_fast_ops);
    if (err == INC_OK) {
        bb->fast = fast;
    }
    return err;
}
