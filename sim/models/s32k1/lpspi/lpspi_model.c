/* lpspi_model.c - register-level LPSPI model on the simulated pin bus (see s32k_lpspi.h). */
#include "inclino/sim/s32k_lpspi.h"

#include <string.h>

#include "inclino/sim/s32k_bus.h"
#include "inclino/spi_lpspi_regs.h"

#define NO_PCS SIM_LPSPI_PCS

static void kick(struct sim_s32k_lpspi *m);

/* ns of c counts of the prescaled clock, rounded up. */
static uint64_t counts_ns(const struct sim_s32k_lpspi *m, uint32_t c)
{
    const unsigned p = (m->tcr & LPSPI_TCR_PRESCALE_MASK) >> LPSPI_TCR_PRESCALE_SHIFT;
    const uint64_t num = (uint64_t)c * (1000000000ull << p);
    return (num + m->cfg.fclk_hz - 1u) / m->cfg.fclk_hz;
}

static uint32_t field(uint32_t ccr, unsigned shift)
{
    return (ccr >> shift) & 0xFFu;
}

static uint32_t sck_counts(const struct sim_s32k_lpspi *m)
{
    return field(m->ccr, LPSPI_CCR_SCKDIV_SHIFT) + 2u;
}

static bool cpol(const struct sim_s32k_lpspi *m)
{
    return (m->tcr & LPSPI_TCR_CPOL) != 0u;
}

static bool cpha(const struct sim_s32k_lpspi *m)
{
    return (m->tcr & LPSPI_TCR_CPHA) != 0u;
}

static void pin(struct sim_s32k_lpspi *m, unsigned p, bool level)
{
    if (p != SIM_LPSPI_NO_PIN) {
        sim_pinbus_master_write(m->cfg.bus, p, level);
    }
}

static void drive_bit(struct sim_s32k_lpspi *m)
{
    pin(m, m->cfg.sout, ((m->out >> (m->bit - 1u)) & 1u) != 0u);
}

static void sample(struct sim_s32k_lpspi *m)
{
    m->in = (uint16_t)((m->in << 1) | (sim_pinbus_read(m->cfg.bus, m->cfg.sin) ? 1u : 0u));
}

static void on_event(void *arg, uint64_t now);
static void irq_update(struct sim_s32k_lpspi *m);

static void at(struct sim_s32k_lpspi *m, enum sim_lpspi_phase ph, uint64_t t)
{
    int h;
    m->phase = ph;
    h = sim_clock_schedule(m->cfg.clk, t, on_event, m);
    m->event = h > 0 ? h : 0;
}

static void push_rx(struct sim_s32k_lpspi *m, uint32_t v)
{
    if (m->force_ref || m->rx_len >= SIM_LPSPI_FIFO) {
        m->sr_w1c |= LPSPI_SR_REF;
        m->force_ref = false;
        return;
    }
    m->rxf[(m->rx_head + m->rx_len) % SIM_LPSPI_FIFO] = v;
    m->rx_len++;
}

static void word_done(struct sim_s32k_lpspi *m, uint64_t now)
{
    m->words++;
    m->t_last_edge = now;
    m->sr_w1c |= LPSPI_SR_WCF;
    if ((m->tcr & LPSPI_TCR_RXMSK) == 0u) {
        push_rx(m, m->in);
    }
    if (m->force_tef) {
        m->sr_w1c |= LPSPI_SR_TEF;
        m->force_tef = false;
    }
    if ((m->tcr & LPSPI_TCR_CONT) != 0u) {
        m->phase = SIM_LPSPI_HOLDING;
        m->event = 0;
        kick(m);
    } else {
        at(m, SIM_LPSPI_NEGATE, now + counts_ns(m, field(m->ccr, LPSPI_CCR_SCKPCS_SHIFT) + 1u));
    }
}

static void on_event(void *arg, uint64_t now)
{
    struct sim_s32k_lpspi *m = arg;
    const uint32_t n = sck_counts(m);
    m->event = 0;
    if (m->stall_engine) {
        return;
    }
    switch (m->phase) {
    case SIM_LPSPI_ASSERT:
        m->pcs_on = (m->tcr & LPSPI_TCR_PCS_MASK) >> LPSPI_TCR_PCS_SHIFT;
        pin(m, m->cfg.pcs[m->pcs_on], false);
        if (m->frames == 0u && !m->negated_once) {
            m->t_first_assert = now;
        }
        if (!cpha(m)) {
            drive_bit(m);
        }
        at(m, SIM_LPSPI_LEAD, now + counts_ns(m, field(m->ccr, LPSPI_CCR_PCSSCK_SHIFT) + 1u));
        break;
    case SIM_LPSPI_LEAD:
        if (!cpha(m)) {
            sample(m);
        }
        pin(m, m->cfg.sck, !cpol(m));
        if (cpha(m)) {
            drive_bit(m);
        }
        at(m, SIM_LPSPI_TRAIL, now + counts_ns(m, n / 2u));
        break;
    case SIM_LPSPI_TRAIL:
        if (cpha(m)) {
            sample(m);
        }
        pin(m, m->cfg.sck, cpol(m));
        m->bit--;
        if (m->bit > 0u) {
            if (!cpha(m)) {
                drive_bit(m);
            }
            at(m, SIM_LPSPI_LEAD, now + counts_ns(m, n - n / 2u));
        } else {
            word_done(m, now);
        }
        break;
    case SIM_LPSPI_NEGATE:
        if (m->pcs_on < NO_PCS) {
            pin(m, m->cfg.pcs[m->pcs_on], true);
        }
        m->pcs_on = NO_PCS;
        m->t_negate = now;
        m->t_last_negate = now;
        m->negated_once = true;
        m->frames++;
        m->sr_w1c |= LPSPI_SR_FCF;
        if (m->tx_len == 0u) {
            m->sr_w1c |= LPSPI_SR_TCF;
        }
        pin(m, m->cfg.sck, cpol(m)); /* a command loaded meanwhile may have a new CPOL */
        m->phase = SIM_LPSPI_IDLE;
        kick(m);
        break;
    case SIM_LPSPI_IDLE:
    case SIM_LPSPI_HOLDING:
    default: break;
    }
    irq_update(m);
}

static bool running(const struct sim_s32k_lpspi *m)
{
    return (m->cr & LPSPI_CR_MEN) != 0u && (m->cr & LPSPI_CR_RST) == 0u &&
           (m->cfgr1 & LPSPI_CFGR1_MASTER) != 0u && !m->stall_engine;
}

static void kick(struct sim_s32k_lpspi *m)
{
    const uint64_t now = m->cfg.clk->now_ns;
    while (running(m) && m->tx_len > 0u &&
           (m->phase == SIM_LPSPI_IDLE || m->phase == SIM_LPSPI_HOLDING)) {
        const uint32_t v = m->txf[m->tx_head].v;
        const bool cmd = m->txf[m->tx_head].cmd;
        m->tx_head = (m->tx_head + 1u) % SIM_LPSPI_FIFO;
        m->tx_len--;
        if (cmd) {
            if (m->phase == SIM_LPSPI_HOLDING) {
                /* A new command ends the continuous transfer (CONTC is not modelled). */
                uint64_t t = m->t_last_edge +
                             counts_ns(m, field(m->ccr, LPSPI_CCR_SCKPCS_SHIFT) + 1u);
                m->tcr = v;
                at(m, SIM_LPSPI_NEGATE, t > now ? t : now);
                return;
            }
            m->tcr = v;
            pin(m, m->cfg.sck, cpol(m)); /* every PCS is negated here */
            continue;
        }
        m->bits = (m->tcr & LPSPI_TCR_FRAMESZ_MASK) + 1u;
        if (m->bits > 16u || (m->tcr & LPSPI_TCR_WIDTH_MASK) != 0u ||
            (m->tcr & LPSPI_TCR_LSBF) != 0u) {
            m->bad_commands++;
            continue;
        }
        m->out = (uint16_t)(v & ((1u << m->bits) - 1u));
        m->in = 0;
        m->bit = m->bits;
        if (m->phase == SIM_LPSPI_IDLE) {
            uint64_t t = now;
            if (m->negated_once) {
                const uint64_t e = m->t_negate +
                                   counts_ns(m, field(m->ccr, LPSPI_CCR_DBT_SHIFT) + 2u);
                t = e > t ? e : t;
            }
            at(m, SIM_LPSPI_ASSERT, t);
        } else {
            uint64_t t = m->t_last_edge + counts_ns(m, field(m->ccr, LPSPI_CCR_DBT_SHIFT) + 1u);
            if (!cpha(m)) {
                drive_bit(m);
            }
            at(m, SIM_LPSPI_LEAD, t > now ? t : now);
        }
        return;
    }
}

static void abort_shift(struct sim_s32k_lpspi *m)
{
    if (m->event > 0) {
        (void)sim_clock_cancel(m->cfg.clk, m->event);
        m->event = 0;
    }
    if (m->pcs_on < NO_PCS) {
        pin(m, m->cfg.pcs[m->pcs_on], true);
        m->t_negate = m->cfg.clk->now_ns;
        m->negated_once = true;
    }
    m->pcs_on = NO_PCS;
    m->phase = SIM_LPSPI_IDLE;
}

static void reset_regs(struct sim_s32k_lpspi *m)
{
    abort_shift(m);
    m->sr_w1c = 0;
    m->ier = m->der = m->cfgr0 = m->cfgr1 = m->ccr = m->fcr = m->dmr0 = m->dmr1 = 0;
    m->tcr = 0x1Fu; /* reset value: 32-bit frames, mode 0, PCS0 */
    m->tx_head = m->tx_len = 0;
    m->rx_head = m->rx_len = 0;
}

uint32_t sim_s32k_lpspi_param(void)
{
    return 2u | (2u << 8) | ((uint32_t)SIM_LPSPI_PCS << 16); /* 2^2 = 4 words each */
}

static uint32_t status(const struct sim_s32k_lpspi *m)
{
    uint32_t sr = m->sr_w1c;
    if (m->tx_len <= (m->fcr & 0xFu)) {
        sr |= LPSPI_SR_TDF;
    }
    if (m->rx_len > ((m->fcr >> LPSPI_FCR_RXWATER_SHIFT) & 0xFu)) {
        sr |= LPSPI_SR_RDF;
    }
    if (m->phase != SIM_LPSPI_IDLE) {
        sr |= LPSPI_SR_MBF;
    }
    return sr;
}

/* The interrupt line: an enabled flag is set. */
static void irq_update(struct sim_s32k_lpspi *m)
{
    if (m->cfg.core != NULL && (status(m) & m->ier) != 0u) {
        m->irqs++;
        sim_s32k_core_raise(m->cfg.core, m->cfg.irq);
    }
}

static uint32_t reg_read(void *ctx, uint32_t off, unsigned width)
{
    struct sim_s32k_lpspi *m = ctx;
    uint32_t v = 0;
    (void)width;
    switch (off) {
    case LPSPI_VERID: v = 0x01000004u; break;
    case LPSPI_PARAM: v = sim_s32k_lpspi_param(); break;
    case LPSPI_CR:
        v = m->cr & (LPSPI_CR_MEN | LPSPI_CR_RST | LPSPI_CR_DOZEN | LPSPI_CR_DBGEN);
        break;
    case LPSPI_SR: v = status(m); break;
    case LPSPI_IER: v = m->ier; break;
    case LPSPI_DER: v = m->der; break;
    case LPSPI_CFGR0: v = m->cfgr0; break;
    case LPSPI_CFGR1: v = m->cfgr1; break;
    case LPSPI_DMR0: v = m->dmr0; break;
    case LPSPI_DMR1: v = m->dmr1; break;
    case LPSPI_CCR: v = m->ccr; break;
    case LPSPI_FCR: v = m->fcr; break;
    case LPSPI_FSR: v = m->tx_len | ((uint32_t)m->rx_len << 16); break;
    case LPSPI_TCR: v = m->tcr; break;
    case LPSPI_RSR: v = m->rx_len == 0u ? LPSPI_RSR_RXEMPTY : 0u; break;
    case LPSPI_RDR:
        if (m->rx_len > 0u) {
            v = m->rxf[m->rx_head];
            m->rx_head = (m->rx_head + 1u) % SIM_LPSPI_FIFO;
            m->rx_len--;
        }
        break;
    default: break;
    }
    return v;
}

static void push_tx(struct sim_s32k_lpspi *m, uint32_t v, bool cmd)
{
    if (m->tx_len >= SIM_LPSPI_FIFO) {
        m->sr_w1c |= LPSPI_SR_TEF;
        return;
    }
    m->txf[(m->tx_head + m->tx_len) % SIM_LPSPI_FIFO].v = v;
    m->txf[(m->tx_head + m->tx_len) % SIM_LPSPI_FIFO].cmd = cmd;
    m->tx_len++;
    kick(m);
}

static void park_pins(struct sim_s32k_lpspi *m)
{
    unsigned k;
    for (k = 0; k < SIM_LPSPI_PCS; k++) {
        if (k != m->pcs_on) {
            pin(m, m->cfg.pcs[k], true);
        }
    }
    pin(m, m->cfg.sck, cpol(m));
}

static void reg_write(void *ctx, uint32_t off, uint32_t v, unsigned width)
{
    struct sim_s32k_lpspi *m = ctx;
    const bool men = (m->cr & LPSPI_CR_MEN) != 0u;
    (void)width;
    switch (off) {
    case LPSPI_CR:
        if ((v & LPSPI_CR_RST) != 0u) {
            reset_regs(m);
        }
        if ((v & LPSPI_CR_RTF) != 0u) {
            m->tx_head = m->tx_len = 0;
        }
        if ((v & LPSPI_CR_RRF) != 0u) {
            m->rx_head = m->rx_len = 0;
        }
        m->cr = v & (LPSPI_CR_MEN | LPSPI_CR_RST | LPSPI_CR_DOZEN | LPSPI_CR_DBGEN);
        if ((m->cr & LPSPI_CR_MEN) == 0u) {
            abort_shift(m);
        } else if (!men && (m->cfgr1 & LPSPI_CFGR1_MASTER) != 0u) {
            park_pins(m);
        }
        kick(m);
        break;
    case LPSPI_SR: m->sr_w1c &= ~(v & LPSPI_SR_W1C_MASK); break;
    case LPSPI_IER: m->ier = v & 0x3F03u; break;
    case LPSPI_DER: m->der = v & 3u; break;
    case LPSPI_CFGR0: m->cfgr0 = v & 0x307u; break;
    case LPSPI_CFGR1:
        if (men) {
            m->locked_writes++;
        } else {
            m->cfgr1 = v & 0x0F070F0Fu;
        }
        break;
    case LPSPI_DMR0: m->dmr0 = v; break;
    case LPSPI_DMR1: m->dmr1 = v; break;
    case LPSPI_CCR:
        if (men) {
            m->locked_writes++;
        } else {
            m->ccr = v;
        }
        break;
    case LPSPI_FCR: m->fcr = v & 0x000F000Fu; break;
    case LPSPI_TCR: push_tx(m, v, true); break;
    case LPSPI_TDR: push_tx(m, v, false); break;
    default: break;
    }
    irq_update(m);
}

static const struct s32k_bus_region_ops lpspi_ops = {reg_read, reg_write};

int sim_s32k_lpspi_init(struct sim_s32k_lpspi *m, const struct sim_s32k_lpspi_cfg *cfg)
{
    if (m == NULL || cfg == NULL || cfg->clk == NULL || cfg->bus == NULL) {
        return INC_ERR_NULL;
    }
    if (cfg->fclk_hz == 0u) {
        return INC_ERR_INVAL;
    }
    memset(m, 0, sizeof(*m));
    m->cfg = *cfg;
    m->pcs_on = NO_PCS;
    reset_regs(m);
    return s32k_bus_map(cfg->base, LPSPI_REGION_SIZE, &lpspi_ops, m);
}
