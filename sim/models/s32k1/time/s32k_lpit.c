/* s32k_lpit.c - see inclino/sim/s32k_lpit.h. */
#include "inclino/sim/s32k_lpit.h"

#include <stddef.h>
#include <string.h>

#include "inclino/sim/s32k_bus.h"

static uint64_t ticks_in(const struct sim_s32k_lpit *m, uint64_t dt_ns)
{
    return (dt_ns / 1000000000ull) * m->hz + ((dt_ns % 1000000000ull) * m->hz) / 1000000000ull;
}

/* First ns at which `ticks` ticks have elapsed (rounded up). */
static uint64_t ns_of(const struct sim_s32k_lpit *m, uint64_t ticks)
{
    return (ticks / m->hz) * 1000000000ull + ((ticks % m->hz) * 1000000000ull + m->hz - 1u) / m->hz;
}

static bool running(const struct sim_s32k_lpit *m, unsigned ch)
{
    return (m->mcr & S32K_LPIT_MCR_M_CEN) != 0u && (m->tctrl[ch] & S32K_LPIT_TCTRL_T_EN) != 0u;
}

static unsigned irq_of(const struct sim_s32k_lpit *m, unsigned ch)
{
    return m->part == S32K_PART_116 ? S32K116_IRQ_LPIT0 : 48u + ch;
}

static void expire(void *arg, uint64_t now_ns);

static void schedule(struct sim_s32k_lpit *m, unsigned ch)
{
    if (m->event[ch] > 0) {
        (void)sim_clock_cancel(m->clk, m->event[ch]);
        m->event[ch] = 0;
    }
    if (running(m, ch)) {
        /* the event's argument is &tval[ch]: expire() recovers the channel from it */
        const int h = sim_clock_schedule(
            m->clk, m->start_ns[ch] + ns_of(m, (uint64_t)m->tval[ch] + 1u), expire, &m->tval[ch]);
        m->event[ch] = h > 0 ? h : 0;
    }
}

static struct sim_s32k_lpit *the_lpit;

static void expire(void *arg, uint64_t now_ns)
{
    struct sim_s32k_lpit *m = the_lpit;
    const unsigned ch = (unsigned)((const uint32_t *)arg - m->tval);
    m->event[ch] = 0;
    m->msr |= S32K_LPIT_TIF(ch);
    m->start_ns[ch] = now_ns;
    schedule(m, ch);
    if ((m->mier & S32K_LPIT_TIF(ch)) != 0u) {
        sim_s32k_core_raise(m->core, irq_of(m, ch));
    }
}

static uint32_t cval(const struct sim_s32k_lpit *m, unsigned ch)
{
    uint64_t t;
    if (!running(m, ch)) {
        return 0u;
    }
    t = ticks_in(m, m->clk->now_ns - m->start_ns[ch]) % ((uint64_t)m->tval[ch] + 1u);
    return m->tval[ch] - (uint32_t)t;
}

static uint32_t lpit_read(void *ctx, uint32_t off, unsigned width)
{
    struct sim_s32k_lpit *m = ctx;
    (void)width;
    if (off == 0x08u) {
        return m->mcr;
    }
    if (off == 0x0Cu) {
        return m->msr;
    }
    if (off == 0x10u) {
        return m->mier;
    }
    if (off >= 0x20u && off < 0x60u) {
        const unsigned ch = (off - 0x20u) / 0x10u;
        switch ((off - 0x20u) % 0x10u) {
        case 0x0u: return m->tval[ch];
        case 0x4u: return cval(m, ch);
        case 0x8u: return m->tctrl[ch];
        default: return 0u;
        }
    }
    return 0u;
}

static void lpit_write(void *ctx, uint32_t off, uint32_t v, unsigned width)
{
    struct sim_s32k_lpit *m = ctx;
    unsigned ch;
    (void)width;
    if (off == 0x08u) {
        m->mcr = v & (S32K_LPIT_MCR_M_CEN | S32K_LPIT_MCR_DBG_EN);
        for (ch = 0; ch < SIM_S32K_LPIT_CHANNELS; ch++) {
            m->start_ns[ch] = m->clk->now_ns;
            schedule(m, ch);
        }
    } else if (off == 0x0Cu) {
        m->msr &= ~v;
    } else if (off == 0x10u) {
        m->mier = v & 0xFu;
    } else if (off >= 0x20u && off < 0x60u) {
        ch = (off - 0x20u) / 0x10u;
        switch ((off - 0x20u) % 0x10u) {
        case 0x0u:
            m->tval[ch] = v; /* takes effect at the next start or reload */
            break;
        case 0x8u: {
            const bool was = running(m, ch);
            m->tctrl[ch] = v & S32K_LPIT_TCTRL_T_EN;
            if (!was && running(m, ch)) {
                m->start_ns[ch] = m->clk->now_ns;
            }
            schedule(m, ch);
            break;
        }
        default: break;
        }
    }
}

static const struct s32k_bus_region_ops lpit_ops = {lpit_read, lpit_write};

static void access_hook(void *ctx)
{
    struct sim_s32k_lpit *m = ctx;
    if (m->core != NULL && m->core->isr_depth != 0u) {
        return;
    }
    m->accesses++;
    sim_clock_advance_to(m->clk, m->clk->now_ns + m->access_ns);
}

int sim_s32k_lpit_init(struct sim_s32k_lpit *m, struct sim_clock *clk, struct sim_s32k_core *core,
                       enum s32k_part part, uint32_t hz, uint32_t access_ns)
{
    int err;
    if (m == NULL || clk == NULL || core == NULL) {
        return INC_ERR_NULL;
    }
    if (hz == 0u) {
        return INC_ERR_INVAL;
    }
    memset(m, 0, sizeof(*m));
    m->clk = clk;
    m->core = core;
    m->part = part;
    m->hz = hz;
    m->access_ns = access_ns;
    err = s32k_bus_map(S32K_LPIT_BASE, 0x100u, &lpit_ops, m);
    if (err != INC_OK) {
        return err;
    }
    the_lpit = m;
    s32k_bus_set_hook(access_hook, m);
    return INC_OK;
}
