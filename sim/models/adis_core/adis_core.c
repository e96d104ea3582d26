/* adis_core.c - SPI protocol of the simulated ADIS parts (see sim/adis_core.h). */
#include "inclino/sim/adis_core.h"

#include <string.h>

/* Violations that make the part drop a frame. */
#define FRAME_BROKEN                                                        \
    (SIM_SPI_FLAG(SIM_VIOL_SCLK_FAST) | SIM_SPI_FLAG(SIM_VIOL_CS_SETUP) |   \
     SIM_SPI_FLAG(SIM_VIOL_CS_HOLD) | SIM_SPI_FLAG(SIM_VIOL_STALL) |        \
     SIM_SPI_FLAG(SIM_VIOL_MOSI_SETUP) | SIM_SPI_FLAG(SIM_VIOL_SCLK_IDLE) | \
     SIM_SPI_FLAG(SIM_VIOL_PARTIAL_WORD))

static uint16_t garbage(struct sim_adis_core *c)
{
    return (uint16_t)sim_rng_u32(&c->rng);
}

static uint16_t on_begin(void *model, unsigned flags, uint64_t t)
{
    struct sim_adis_core *c = model;
    c->bursting = false;
    c->cmd = 0;
    if (c->cfg.ops->busy != NULL && c->cfg.ops->busy(c->cfg.model, t)) {
        c->busy_frames++;
        sim_violation_report(c->cfg.log, SIM_VIOL_BUSY, c->cfg.name, t, 0, 0);
        c->next_valid = false;
        return garbage(c);
    }
    if (flags & FRAME_BROKEN) {
        c->next_valid = false;
    }
    return c->next_valid ? c->next_out : garbage(c);
}

static uint16_t on_word(void *model, uint16_t mosi, unsigned index, unsigned flags, uint64_t t)
{
    struct sim_adis_core *c = model;
    (void)flags;
    if (index == 0) {
        c->cmd = mosi;
        if (c->cfg.burst_cmd != 0 && mosi == c->cfg.burst_cmd && c->cfg.ops->burst != NULL &&
            !(c->cfg.ops->busy != NULL && c->cfg.ops->busy(c->cfg.model, t))) {
            struct sim_spi_timing bt = c->slave.cfg.timing;
            c->bursting = true;
            c->bursts++;
            c->burst_len = c->cfg.ops->burst(c->cfg.model, c->burst, SIM_ADIS_BURST_MAX, t);
            if (c->slave.frame_min_period_ns < c->cfg.burst_min_period_ns) {
                sim_violation_report(c->cfg.log, SIM_VIOL_SCLK_FAST, c->cfg.name, t,
                                     c->slave.frame_min_period_ns, c->cfg.burst_min_period_ns);
                c->burst_len = 0; /* the part cannot keep up: garbage */
                if (c->cfg.frame_error != NULL) {
                    c->cfg.frame_error(c->cfg.model, 0, t);
                }
            }
            /* The rest of the burst is held to the burst clock limit, or to the mode's own
             * limit when that is stricter (low-power mode). */
            if (bt.min_period_ns < c->cfg.burst_min_period_ns) {
                bt.min_period_ns = c->cfg.burst_min_period_ns;
            }
            sim_spi_slave_set_timing(&c->slave, &bt);
        }
    }
    if (c->bursting) {
        return index < c->burst_len ? c->burst[index] : garbage(c);
    }
    return garbage(c);
}

static void on_end(void *model, unsigned words, unsigned flags, uint64_t t)
{
    struct sim_adis_core *c = model;
    const uint16_t cmd = c->cmd;
    const uint8_t addr = (uint8_t)((cmd >> 8) & c->cfg.addr_mask);
    if (c->bursting) {
        sim_spi_slave_set_timing(&c->slave, &c->cfg.timing);
        c->bursting = false;
        c->next_valid = false;
        if ((flags & FRAME_BROKEN) && c->cfg.frame_error != NULL) {
            c->cfg.frame_error(c->cfg.model, flags, t);
        }
        return;
    }
    if (words == 0 || (flags & (FRAME_BROKEN | SIM_SPI_FLAG(SIM_VIOL_BUSY))) ||
        (c->cfg.ops->busy != NULL && c->cfg.ops->busy(c->cfg.model, t))) {
        const bool busy = c->cfg.ops->busy != NULL && c->cfg.ops->busy(c->cfg.model, t);
        if (words != 0) {
            c->dropped++;
        }
        if ((flags & FRAME_BROKEN) && !busy && c->cfg.frame_error != NULL) {
            c->cfg.frame_error(c->cfg.model, flags, t);
        }
        c->next_valid = false;
        return;
    }
    if (cmd & 0x8000u) {
        c->writes++;
        c->cfg.ops->write(c->cfg.model, addr, (uint8_t)(cmd & 0xFFu), t);
        c->next_valid = false; /* DOUT after a write is undefined */
    } else {
        c->reads++;
        c->next_out = c->cfg.ops->read(c->cfg.model, addr, t);
        c->next_valid = true;
    }
}

static const struct sim_spi_slave_ops adis_slave_ops = {
    .frame_begin = on_begin,
    .word = on_word,
    .frame_end = on_end,
};

int sim_adis_core_init(struct sim_adis_core *c, const struct sim_adis_cfg *cfg)
{
    struct sim_spi_slave_cfg sc;
    if (c == NULL || cfg == NULL || cfg->ops == NULL || cfg->ops->read == NULL ||
        cfg->ops->write == NULL) {
        return INC_ERR_NULL;
    }
    memset(c, 0, sizeof(*c));
    c->cfg = *cfg;
    if (c->cfg.name == NULL) {
        c->cfg.name = "adis";
    }
    sim_rng_seed(&c->rng, cfg->seed);
    sc.name = c->cfg.name;
    sc.bus = cfg->bus;
    sc.cs = cfg->cs;
    sc.sclk = cfg->sclk;
    sc.mosi = cfg->mosi;
    sc.miso = cfg->miso;
    sc.mode = 3;
    sc.bits = 16;
    sc.timing = cfg->timing;
    sc.ops = &adis_slave_ops;
    sc.model = c;
    sc.log = cfg->log;
    return sim_spi_slave_init(&c->slave, &sc);
}

int sim_adis_core_set_timing(struct sim_adis_core *c, const struct sim_spi_timing *t)
{
    if (c == NULL || t == NULL) {
        return INC_ERR_NULL;
    }
    c->cfg.timing = *t;
    return sim_spi_slave_set_timing(&c->slave, t);
}
