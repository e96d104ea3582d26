/* spi_slave.c - pin-level SPI slave decoder (see sim/spi_slave.h). */
#include "inclino/sim/spi_slave.h"

#include <stddef.h>
#include <string.h>

static void on_pin(void *arg, unsigned pin, bool level, uint64_t t);

static void report(struct sim_spi_slave *s, enum sim_violation_kind kind, uint64_t t,
                   uint64_t measured, uint32_t limit)
{
    s->flags |= SIM_SPI_FLAG(kind);
    sim_violation_report(s->cfg.log, kind, s->cfg.name, t,
                         measured > UINT32_MAX ? UINT32_MAX : (uint32_t)measured, limit);
}

static void miso_event(void *arg, uint64_t t)
{
    struct sim_spi_slave *s = arg;
    (void)t;
    if (s->q_len == 0) {
        return;
    }
    sim_pinbus_device_drive(s->cfg.bus, s->dev, s->cfg.miso, s->q[s->q_head].level);
    s->q_head = (s->q_head + 1u) % SIM_SPI_MISO_QUEUE;
    s->q_len--;
}

/* Drive MISO to `level` tDAV from now (at once when tDAV is 0). */
static void drive_miso(struct sim_spi_slave *s, bool level, uint64_t t)
{
    unsigned slot;
    int h;
    if (s->miso_stuck != SIM_SPI_MISO_OK) {
        level = s->miso_stuck == SIM_SPI_MISO_STUCK_HIGH; /* injected fault (sim/part.h) */
    }
    if (s->cfg.timing.miso_delay_ns == 0 || s->cfg.bus->clk == NULL) {
        sim_pinbus_device_drive(s->cfg.bus, s->dev, s->cfg.miso, level);
        return;
    }
    if (s->q_len == SIM_SPI_MISO_QUEUE) {
        /* Edges faster than the output stage: the oldest pending change is lost. */
        report(s, SIM_VIOL_SCLK_FAST, t, 0, 0);
        return;
    }
    h = sim_clock_schedule(s->cfg.bus->clk, t + s->cfg.timing.miso_delay_ns, miso_event, s);
    if (h < 0) {
        sim_pinbus_device_drive(s->cfg.bus, s->dev, s->cfg.miso, level);
        return;
    }
    slot = (s->q_head + s->q_len) % SIM_SPI_MISO_QUEUE;
    s->q[slot].handle = h;
    s->q[slot].level = level;
    s->q_len++;
}

static void flush_miso(struct sim_spi_slave *s)
{
    while (s->q_len > 0) {
        sim_clock_cancel(s->cfg.bus->clk, s->q[s->q_head].handle);
        s->q_head = (s->q_head + 1u) % SIM_SPI_MISO_QUEUE;
        s->q_len--;
    }
}

static void shift_out_next(struct sim_spi_slave *s, uint64_t t)
{
    bool bit = (s->out >> s->out_bit) & 1u;
    drive_miso(s, bit, t);
    if (s->out_bit == 0) {
        s->out_bit = (uint8_t)(s->cfg.bits - 1u);
    } else {
        s->out_bit--;
    }
}

static void cs_fall(struct sim_spi_slave *s, uint64_t t)
{
    bool sclk = sim_pinbus_read(s->cfg.bus, s->cfg.sclk);
    s->selected = true;
    s->flags = 0;
    s->words = 0;
    s->bits_in = 0;
    s->in = 0;
    s->edge_seen = false;
    s->t_cs_fall = t;
    s->frame_min_period_ns = UINT32_MAX;
    if (s->cfg.mode == SIM_SPI_MODE_AUTO_0_3) {
        s->cpol = sclk ? 1u : 0u;
        s->cpha = s->cpol;
    } else {
        s->cpol = (uint8_t)((s->cfg.mode >> 1) & 1u);
        s->cpha = (uint8_t)(s->cfg.mode & 1u);
        if ((sclk ? 1u : 0u) != s->cpol) {
            report(s, SIM_VIOL_SCLK_IDLE, t, 0, 0);
        }
    }
    if (s->ever_selected && t - s->t_cs_rise < s->cfg.timing.min_stall_ns) {
        report(s, SIM_VIOL_STALL, t, t - s->t_cs_rise, s->cfg.timing.min_stall_ns);
    }
    s->ever_selected = true;
    s->frames++;
    s->out = (uint16_t)(s->cfg.ops->frame_begin(s->cfg.model, s->flags, t) ^ s->out_xor);
    s->out_bit = (uint8_t)(s->cfg.bits - 1u);
    /* The part drives its MSB as soon as it is selected; with CPHA = 1 the first leading edge
     * re-drives the same bit, so the pointer only moves on for CPHA = 0. */
    if (s->cpha == 0) {
        shift_out_next(s, t);
    } else {
        drive_miso(s, (s->out >> s->out_bit) & 1u, t);
    }
}

static void cs_rise(struct sim_spi_slave *s, uint64_t t)
{
    if (s->edge_seen && t - s->t_last_edge < s->cfg.timing.min_cs_hold_ns) {
        report(s, SIM_VIOL_CS_HOLD, t, t - s->t_last_edge, s->cfg.timing.min_cs_hold_ns);
    }
    if (s->bits_in != 0) {
        report(s, SIM_VIOL_PARTIAL_WORD, t, s->bits_in, 0);
    }
    s->selected = false;
    s->t_cs_rise = t;
    flush_miso(s);
    sim_pinbus_device_release(s->cfg.bus, s->dev, s->cfg.miso);
    s->cfg.ops->frame_end(s->cfg.model, s->words, s->flags, t);
}

static void sample(struct sim_spi_slave *s, uint64_t t)
{
    bool bit = sim_pinbus_read(s->cfg.bus, s->cfg.mosi);
    if (s->cfg.timing.mosi_setup_ns != 0 && t - s->t_mosi_change < s->cfg.timing.mosi_setup_ns) {
        report(s, SIM_VIOL_MOSI_SETUP, t, t - s->t_mosi_change, s->cfg.timing.mosi_setup_ns);
        bit = s->mosi_prev;
    }
    s->in = (uint16_t)((s->in << 1) | (bit ? 1u : 0u));
    s->bits_in++;
    if (s->bits_in == s->cfg.bits) {
        uint16_t mask = (uint16_t)(s->cfg.bits == 16u ? 0xFFFFu : ((1u << s->cfg.bits) - 1u));
        uint16_t w = (uint16_t)(s->in & mask);
        unsigned idx = s->words++;
        s->total_words++;
        s->bits_in = 0;
        s->in = 0;
        s->out = (uint16_t)(s->cfg.ops->word(s->cfg.model, w, idx, s->flags, t) ^ s->out_xor);
        s->out_bit = (uint8_t)(s->cfg.bits - 1u);
    }
}

static void sclk_edge(struct sim_spi_slave *s, bool level, uint64_t t)
{
    bool leading = (level ? 1u : 0u) != s->cpol;
    bool sampling = s->cpha == 0 ? leading : !leading;
    bool first = !s->edge_seen;

    if (!first && s->cfg.timing.min_half_ns != 0 &&
        t - s->t_last_edge < s->cfg.timing.min_half_ns) {
        report(s, SIM_VIOL_SCLK_FAST, t, t - s->t_last_edge, s->cfg.timing.min_half_ns);
    }
    s->edge_seen = true;
    s->t_last_edge = t;
    if (first && t - s->t_cs_fall < s->cfg.timing.min_cs_setup_ns) {
        /* The part is not ready yet: this edge is lost. */
        report(s, SIM_VIOL_CS_SETUP, t, t - s->t_cs_fall, s->cfg.timing.min_cs_setup_ns);
        return;
    }
    if (sampling) {
        if (s->t_last_sample > s->t_cs_fall && t - s->t_last_sample < s->frame_min_period_ns) {
            s->frame_min_period_ns = (uint32_t)(t - s->t_last_sample);
        }
        if (s->t_last_sample > s->t_cs_fall && t - s->t_last_sample < s->cfg.timing.min_period_ns) {
            /* Faster than the shift register: the bit is lost. */
            report(s, SIM_VIOL_SCLK_FAST, t, t - s->t_last_sample, s->cfg.timing.min_period_ns);
            s->t_last_sample = t;
            return;
        }
        s->t_last_sample = t;
        sample(s, t);
    } else {
        /* Shifting edge. With CPHA = 1 the very first leading edge re-drives the MSB that was
         * put out at CS fall; every shifting edge moves to the next bit. */
        shift_out_next(s, t);
    }
}

static void on_pin(void *arg, unsigned pin, bool level, uint64_t t)
{
    struct sim_spi_slave *s = arg;
    if (pin == s->cfg.cs) {
        if (!level && !s->selected) {
            cs_fall(s, t);
        } else if (level && s->selected) {
            cs_rise(s, t);
        }
    } else if (pin == s->cfg.mosi) {
        s->mosi_prev = !level;
        s->t_mosi_change = t;
    } else if (pin == s->cfg.sclk && s->selected) {
        sclk_edge(s, level, t);
    }
}

int sim_spi_slave_init(struct sim_spi_slave *s, const struct sim_spi_slave_cfg *cfg)
{
    int dev;
    if (s == NULL || cfg == NULL || cfg->bus == NULL || cfg->ops == NULL ||
        cfg->ops->frame_begin == NULL || cfg->ops->word == NULL || cfg->ops->frame_end == NULL) {
        return INC_ERR_NULL;
    }
    if ((cfg->bits != 8u && cfg->bits != 16u) || cfg->mode > SIM_SPI_MODE_AUTO_0_3 ||
        cfg->cs >= SIM_PINBUS_MAX_PINS || cfg->sclk >= SIM_PINBUS_MAX_PINS ||
        cfg->mosi >= SIM_PINBUS_MAX_PINS || cfg->miso >= SIM_PINBUS_MAX_PINS) {
        return INC_ERR_INVAL;
    }
    memset(s, 0, sizeof(*s));
    s->cfg = *cfg;
    if (s->cfg.name == NULL) {
        s->cfg.name = "spi-slave";
    }
    dev = sim_pinbus_add_device(cfg->bus);
    if (dev < 0) {
        return dev;
    }
    s->dev = (unsigned)dev;
    s->listener.fn = on_pin;
    s->listener.arg = s;
    s->listener.mask = SIM_PIN_MASK(cfg->cs) | SIM_PIN_MASK(cfg->sclk) | SIM_PIN_MASK(cfg->mosi);
    s->mosi_prev = sim_pinbus_read(cfg->bus, cfg->mosi);
    return sim_pinbus_listen(cfg->bus, &s->listener);
}

int sim_spi_slave_set_timing(struct sim_spi_slave *s, const struct sim_spi_timing *t)
{
    if (s == NULL || t == NULL) {
        return INC_ERR_NULL;
    }
    s->cfg.timing = *t;
    return INC_OK;
}

void sim_spi_slave_detach(struct sim_spi_slave *s)
{
    if (s == NULL || s->cfg.bus == NULL) {
        return;
    }
    flush_miso(s);
    sim_pinbus_device_release(s->cfg.bus, s->dev, s->cfg.miso);
    sim_pinbus_unlisten(s->cfg.bus, &s->listener);
    s->selected = false;
}
