/* loopback.c - see sim/loopback.h. */
#include "inclino/sim/loopback.h"

#include <string.h>

static uint16_t lb_begin(void *model, unsigned flags, uint64_t t)
{
    struct sim_loopback *m = model;
    (void)flags;
    (void)t;
    return m->next;
}

static uint16_t lb_word(void *model, uint16_t mosi, unsigned index, unsigned flags, uint64_t t)
{
    struct sim_loopback *m = model;
    (void)index;
    (void)flags;
    (void)t;
    if (m->received < SIM_LOOPBACK_LOG) {
        m->rx_log[m->received] = mosi;
    }
    m->received++;
    m->next = (uint16_t)(mosi ^ m->xor_mask);
    return m->next;
}

static void lb_end(void *model, unsigned words, unsigned flags, uint64_t t)
{
    struct sim_loopback *m = model;
    (void)t;
    m->frames_ended++;
    m->last_frame_words = words;
    m->last_frame_flags = flags;
}

static const struct sim_spi_slave_ops lb_ops = {
    .frame_begin = lb_begin,
    .word = lb_word,
    .frame_end = lb_end,
};

int sim_loopback_init(struct sim_loopback *m, const struct sim_loopback_cfg *cfg)
{
    struct sim_spi_slave_cfg sc;
    if (m == NULL || cfg == NULL) {
        return INC_ERR_NULL;
    }
    memset(m, 0, sizeof(*m));
    m->next = cfg->first;
    m->xor_mask = cfg->xor_mask;
    sc.name = cfg->name != NULL ? cfg->name : "loopback";
    sc.bus = cfg->bus;
    sc.cs = cfg->cs;
    sc.sclk = cfg->sclk;
    sc.mosi = cfg->mosi;
    sc.miso = cfg->miso;
    sc.mode = cfg->mode;
    sc.bits = cfg->bits;
    sc.timing = cfg->timing;
    sc.ops = &lb_ops;
    sc.model = m;
    sc.log = cfg->log;
    return sim_spi_slave_init(&m->slave, &sc);
}
