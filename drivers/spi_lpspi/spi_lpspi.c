/* spi_lpspi.c - the S32K1 LPSPI behind struct spi_bus (see spi_lpspi.h). */
#include "inclino/spi_lpspi.h"

#include "inclino/s32k_mmio.h"

#define NS_PER_S 1000000000u
#define PRESCALE_MAX 7u
#define FCLK_MAX_HZ \
    200000000u /* above any S32K1 LPSPI functional clock; keeps the math in 64 bits */
#define FIFO_MAX_WORDS 16u

static uint32_t rd(const struct spi_lpspi *lp, uint32_t off)
{
    return s32k_mmio_read32(lp->cfg.base + off);
}

static void wr(const struct spi_lpspi *lp, uint32_t off, uint32_t v)
{
    s32k_mmio_write32(lp->cfg.base + off, v);
}

/* Counts of 2^p / f that cover ns: ceil(ns f / (1e9 2^p)). */
static uint32_t counts_for(uint32_t fclk_hz, unsigned p, uint32_t ns)
{
    const uint64_t den = (uint64_t)NS_PER_S << p;
    const uint64_t c = ((uint64_t)ns * fclk_hz + den - 1u) / den;
    return c > UINT32_MAX ? UINT32_MAX : (uint32_t)c;
}

uint32_t spi_lpspi_counts_ns(uint32_t fclk_hz, unsigned prescale, uint32_t counts)
{
    uint64_t ns;
    if (fclk_hz == 0u || prescale > PRESCALE_MAX) {
        return 0u;
    }
    ns = (((uint64_t)counts * ((uint64_t)NS_PER_S << prescale)) + fclk_hz - 1u) / fclk_hz;
    return ns > UINT32_MAX ? UINT32_MAX : (uint32_t)ns;
}

static uint32_t max_u32(uint32_t a, uint32_t b)
{
    return a > b ? a : b;
}

int spi_lpspi_clock_for(uint32_t fclk_hz, const struct spi_timing *t, enum spi_cs_policy cs,
                        struct spi_lpspi_clock *out)
{
    unsigned p;
    int err;
    if (out == NULL) {
        return INC_ERR_NULL;
    }
    err = spi_timing_check(t);
    if (err != INC_OK) {
        return err;
    }
    if (fclk_hz == 0u || fclk_hz > FCLK_MAX_HZ || (cs != SPI_CS_HOLD && cs != SPI_CS_TOGGLE)) {
        return INC_ERR_INVAL;
    }
    for (p = 0; p <= PRESCALE_MAX; p++) {
        const uint32_t half = t->sclk_period_ns - t->sclk_period_ns / 2u; /* ceil(P / 2) */
        const uint32_t period = max_u32(counts_for(fclk_hz, p, t->sclk_period_ns),
                                        2u * counts_for(fclk_hz, p, half));
        const uint32_t setup = max_u32(counts_for(fclk_hz, p, t->cs_setup_ns), 1u);
        const uint32_t hold = max_u32(counts_for(fclk_hz, p, t->cs_hold_ns), 1u);
        uint32_t dbt;
        if (cs == SPI_CS_TOGGLE) {
            dbt = max_u32(counts_for(fclk_hz, p, t->stall_ns), 2u) - 2u;
        } else {
            dbt = max_u32(counts_for(fclk_hz, p, max_u32(t->gap_ns, half)), 1u) - 1u;
        }
        if (max_u32(period, 2u) - 2u <= LPSPI_CCR_FIELD_MAX && setup - 1u <= LPSPI_CCR_FIELD_MAX &&
            hold - 1u <= LPSPI_CCR_FIELD_MAX && dbt <= LPSPI_CCR_FIELD_MAX) {
            out->prescale = (uint8_t)p;
            out->sckdiv = (uint8_t)(max_u32(period, 2u) - 2u);
            out->pcssck = (uint8_t)(setup - 1u);
            out->sckpcs = (uint8_t)(hold - 1u);
            out->dbt = (uint8_t)dbt;
            return INC_OK;
        }
    }
    return INC_ERR_TIMING;
}

static uint32_t ccr_of(const struct spi_lpspi_clock *c)
{
    return ((uint32_t)c->sckdiv << LPSPI_CCR_SCKDIV_SHIFT) |
           ((uint32_t)c->dbt << LPSPI_CCR_DBT_SHIFT) |
           ((uint32_t)c->pcssck << LPSPI_CCR_PCSSCK_SHIFT) |
           ((uint32_t)c->sckpcs << LPSPI_CCR_SCKPCS_SHIFT);
}

/* Master, PCS active low, SIN in / SOUT out, stall (never underrun) when the TX FIFO is empty. */
static void setup_module(struct spi_lpspi *lp)
{
    wr(lp, LPSPI_CR, LPSPI_CR_RST);
    wr(lp, LPSPI_CR, 0u);
    wr(lp, LPSPI_IER, 0u);
    wr(lp, LPSPI_DER, 0u);
    wr(lp, LPSPI_CFGR0, 0u);
    wr(lp, LPSPI_CFGR1, LPSPI_CFGR1_MASTER);
    wr(lp, LPSPI_FCR, 0u);
    wr(lp, LPSPI_CR, LPSPI_CR_RTF | LPSPI_CR_RRF);
    wr(lp, LPSPI_SR, LPSPI_SR_W1C_MASK);
    lp->programmed = false;
    lp->cpol_known = false;
}

static int find_pcs(const struct spi_lpspi *lp, hal_pin_t cs)
{
    unsigned k;
    for (k = 0; k < SPI_LPSPI_PCS_COUNT; k++) {
        if (lp->cfg.pcs_pin[k] != HAL_PIN_NONE && lp->cfg.pcs_pin[k] == cs) {
            return (int)k;
        }
    }
    return -1;
}

static int lp_attach(void *ctx, struct spi_dev *dev)
{
    const struct spi_lpspi *lp = ctx;
    return find_pcs(lp, dev->cfg.cs) < 0 ? INC_ERR_INVAL : INC_OK;
}

/* An error leaves the module reset (every PCS negated, FIFOs empty) and re-programmed later. */
static int fail(struct spi_lpspi *lp, int err)
{
    lp->stats.errors++;
    lp->stats.last_sr = rd(lp, LPSPI_SR);
    setup_module(lp);
    wr(lp, LPSPI_CR, LPSPI_CR_MEN);
    return err;
}

struct waiter {
    uint32_t polls;
    uint64_t deadline;
};

static void waiter_arm(const struct spi_lpspi *lp, struct waiter *w, uint64_t budget_ns)
{
    w->polls = 0;
    w->deadline = hal_now_ns(lp->cfg.hal) + budget_ns + lp->cfg.timeout_ns;
}

/* The clock is read every SPI_LPSPI_CLOCK_EVERY polls only (a poll is two register reads, a
 * clock read on the M0+ about 60 instructions): a timeout is seen at most that many polls late. */
static bool waiter_expired(const struct spi_lpspi *lp, struct waiter *w)
{
    ++w->polls;
    return w->polls > SPI_LPSPI_POLL_LIMIT ||
           ((w->polls % SPI_LPSPI_CLOCK_EVERY) == 0u && hal_now_ns(lp->cfg.hal) > w->deadline);
}

static bool same_timing(const struct spi_timing *a, const struct spi_timing *b)
{
    return a->sclk_period_ns == b->sclk_period_ns && a->cs_setup_ns == b->cs_setup_ns &&
           a->cs_hold_ns == b->cs_hold_ns && a->stall_ns == b->stall_ns && a->gap_ns == b->gap_ns;
}

static int lp_transfer(void *ctx, struct spi_dev *dev, const uint16_t *tx, uint16_t *rx, size_t n,
                       enum spi_cs_policy cs)
{
    struct spi_lpspi *lp = ctx;
    const struct hal *hal = lp->cfg.hal;
    const struct spi_timing *t = &dev->cfg.timing;
    const unsigned bits = dev->cfg.bits;
    const uint16_t mask = (uint16_t)(bits >= 16u ? 0xFFFFu : (1u << bits) - 1u);
    const bool cpol = (dev->cfg.mode & 2u) != 0u;
    const int pcs = find_pcs(lp, dev->cfg.cs);
    struct spi_lpspi_clock c;
    struct waiter w;
    uint32_t ccr, tcr, word_ns, n_counts;
    size_t sent = 0, got = 0;
    bool end_pending = cs == SPI_CS_HOLD;
    bool slept_out = false;

    if (pcs < 0) {
        return INC_ERR_INVAL;
    }
    /* The register fields of this timing: computed once per timing (64-bit divisions), kept
     * while the same device timing and CS policy come again. */
    if (!lp->ck_valid || lp->ck_cs != (uint8_t)cs || !same_timing(&lp->ck_t, t)) {
        const int err = spi_lpspi_clock_for(lp->cfg.fclk_hz, t, cs, &c);
        if (err != INC_OK) {
            return err; /* nothing reached the bus */
        }
        /* One word on the wire, generously: setup, bits, hold and the gap or stall after it. */
        n_counts = (uint32_t)c.pcssck + 1u + bits * ((uint32_t)c.sckdiv + 2u) + (uint32_t)c.sckpcs +
                   1u + (uint32_t)c.dbt + 2u;
        lp->ck = c;
        lp->ck_t = *t;
        lp->ck_cs = (uint8_t)cs;
        lp->ck_bits = (uint8_t)bits;
        lp->ck_word_ns = spi_lpspi_counts_ns(lp->cfg.fclk_hz, c.prescale, n_counts);
        lp->ck_hold_ns = spi_lpspi_counts_ns(lp->cfg.fclk_hz, c.prescale, (uint32_t)c.sckpcs + 1u);
        lp->ck_settle_ns = spi_lpspi_counts_ns(lp->cfg.fclk_hz, c.prescale,
                                               ((uint32_t)c.sckdiv + 3u) / 2u);
        lp->ck_valid = true;
    } else if (lp->ck_bits != (uint8_t)bits) {
        n_counts = (uint32_t)lp->ck.pcssck + 1u + bits * ((uint32_t)lp->ck.sckdiv + 2u) +
                   (uint32_t)lp->ck.sckpcs + 1u + (uint32_t)lp->ck.dbt + 2u;
        lp->ck_word_ns = spi_lpspi_counts_ns(lp->cfg.fclk_hz, lp->ck.prescale, n_counts);
        lp->ck_bits = (uint8_t)bits;
    }
    c = lp->ck;
    word_ns = lp->ck_word_ns;
    ccr = ccr_of(&c);
    if ((rd(lp, LPSPI_SR) & LPSPI_SR_MBF) != 0u) {
        return fail(lp, INC_ERR_BUSY);
    }
    if (!lp->programmed || ccr != lp->ccr) {
        wr(lp, LPSPI_CR, 0u); /* CCR only while disabled */
        wr(lp, LPSPI_CCR, ccr);
        wr(lp, LPSPI_CR, LPSPI_CR_MEN);
        lp->ccr = ccr;
        lp->programmed = true;
        lp->stats.reconfigs++;
    }

    if (dev->released_once) {
        hal_delay_until(hal, dev->cs_release_ns + t->stall_ns);
    } else if (lp->released_any && lp->last_cs == dev->cfg.cs) {
        hal_delay_until(hal, lp->last_release_ns + t->stall_ns);
    }

    wr(lp, LPSPI_SR, LPSPI_SR_W1C_MASK);
    tcr = (cpol ? LPSPI_TCR_CPOL : 0u) | ((dev->cfg.mode & 1u) != 0u ? LPSPI_TCR_CPHA : 0u) |
          ((uint32_t)c.prescale << LPSPI_TCR_PRESCALE_SHIFT) |
          ((uint32_t)pcs << LPSPI_TCR_PCS_SHIFT) | (cs == SPI_CS_HOLD ? LPSPI_TCR_CONT : 0u) |
          ((bits - 1u) & LPSPI_TCR_FRAMESZ_MASK);
    wr(lp, LPSPI_TCR, tcr);
    if (!lp->cpol_known || lp->cpol != cpol) {
        /* SCK moves to its new idle level with every PCS negated: let it settle. */
        hal_delay_ns(hal, lp->ck_settle_ns);
        lp->cpol = cpol;
        lp->cpol_known = true;
    }

    /* One deadline for all the words (twice their bus time + cfg.timeout_ns): the clock is read
     * when nothing moved, not after every word. */
    waiter_arm(lp, &w, 2u * (uint64_t)(n + 1u) * word_ns);
    while (got < n) {
        const uint32_t sr = rd(lp, LPSPI_SR);
        uint32_t fsr;
        unsigned txc, rxc;
        bool progress = false;
        if ((sr & (LPSPI_SR_TEF | LPSPI_SR_REF)) != 0u) {
            return fail(lp, INC_ERR_BUS);
        }
        fsr = rd(lp, LPSPI_FSR);
        txc = LPSPI_FSR_TXCOUNT(fsr);
        rxc = LPSPI_FSR_RXCOUNT(fsr);
        for (; rxc > 0u && got < n; rxc--) {
            const uint16_t word = (uint16_t)(rd(lp, LPSPI_RDR) & mask);
            if (rx != NULL) {
                rx[got] = word;
            }
            got++;
            progress = true;
        }
        for (; sent < n && txc < lp->fifo_words && sent - got < lp->fifo_words; txc++) {
            wr(lp, LPSPI_TDR, tx != NULL ? tx[sent] : 0u);
            sent++;
            progress = true;
        }
        if (sent == n && end_pending && txc < lp->fifo_words) {
            /* The command that ends the continuous transfer, queued behind the last word: PCS
             * negates the SCK->PCS delay after that word's last edge. */
            wr(lp, LPSPI_TCR, tcr & ~LPSPI_TCR_CONT);
            end_pending = false;
        }
        if (sent - got > lp->stats.max_in_flight) {
            lp->stats.max_in_flight = (uint32_t)(sent - got);
        }
        if (progress) {
            w.polls = 0;
        } else if (lp->cfg.irq_wait && sent > got && !slept_out) {
            /* RDF once every word in flight is in; TEF/REF wake it too. */
            int r;
            wr(lp, LPSPI_FCR, (uint32_t)(sent - got - 1u) << LPSPI_FCR_RXWATER_SHIFT);
            wr(lp, LPSPI_IER, LPSPI_IER_RDIE | LPSPI_IER_TEIE | LPSPI_IER_REIE);
            lp->stats.sleeps++;
            r = hal_irq_wait(hal, w.deadline);
            wr(lp, LPSPI_IER, 0u);
            /* INC_ERR_TIMEOUT: one more look, then the deadline decides; INC_ERR_STATE
             * (interrupts masked by the caller): it returned at once, the loop polls. */
            slept_out = r == INC_ERR_TIMEOUT || r == INC_ERR_STATE;
            if (++w.polls > SPI_LPSPI_POLL_LIMIT) {
                return fail(lp, INC_ERR_TIMEOUT);
            }
        } else if (waiter_expired(lp, &w)) {
            return fail(lp, INC_ERR_TIMEOUT);
        }
    }

    /* The end of the transfer keeps the words' deadline (it is past their bus time by at least
     * one word's time + cfg.timeout_ns when the words came late): no clock read here. */
    w.polls = 0;
    if (end_pending) {
        while (LPSPI_FSR_TXCOUNT(rd(lp, LPSPI_FSR)) >= lp->fifo_words) {
            if (waiter_expired(lp, &w)) {
                return fail(lp, INC_ERR_TIMEOUT);
            }
        }
        wr(lp, LPSPI_TCR, tcr & ~LPSPI_TCR_CONT);
    }
    for (;;) {
        const uint32_t sr = rd(lp, LPSPI_SR);
        if ((sr & (LPSPI_SR_TEF | LPSPI_SR_REF)) != 0u) {
            return fail(lp, INC_ERR_BUS);
        }
        if ((sr & LPSPI_SR_MBF) == 0u && LPSPI_FSR_TXCOUNT(rd(lp, LPSPI_FSR)) == 0u) {
            break;
        }
        if (waiter_expired(lp, &w)) {
            return fail(lp, INC_ERR_TIMEOUT);
        }
    }
    /* The stall counts from the PCS rise; if MBF dropped before the SCK->PCS delay ended
     * (docs/unconfirmed-facts.md), counting from now + that delay is still safe. */
    dev->cs_release_ns = hal_now_ns(hal) + lp->ck_hold_ns;
    dev->released_once = true;
    lp->released_any = true;
    lp->last_cs = dev->cfg.cs;
    lp->last_release_ns = dev->cs_release_ns;
    return INC_OK;
}

void spi_lpspi_isr(struct spi_lpspi *lp)
{
    if (lp != NULL) {
        wr(lp, LPSPI_IER, 0u);
    }
}

static const struct spi_bus_ops lp_ops = {
    .transfer = lp_transfer,
    .attach = lp_attach,
};

int spi_lpspi_init(struct spi_lpspi *lp, const struct spi_lpspi_cfg *cfg)
{
    uint32_t param, txf, rxf;
    unsigned k, j, used = 0;
    int err;
    if (lp == NULL || cfg == NULL) {
        return INC_ERR_NULL;
    }
    err = hal_check(cfg->hal);
    if (err != INC_OK) {
        return err;
    }
    if (cfg->fclk_hz == 0u || cfg->fclk_hz > FCLK_MAX_HZ) {
        return INC_ERR_INVAL;
    }
    for (k = 0; k < SPI_LPSPI_PCS_COUNT; k++) {
        if (cfg->pcs_pin[k] == HAL_PIN_NONE) {
            continue;
        }
        used++;
        for (j = k + 1u; j < SPI_LPSPI_PCS_COUNT; j++) {
            if (cfg->pcs_pin[j] == cfg->pcs_pin[k]) {
                return INC_ERR_INVAL;
            }
        }
    }
    if (used == 0u) {
        return INC_ERR_INVAL;
    }
    lp->cfg = *cfg;
    if (lp->cfg.timeout_ns == 0u) {
        lp->cfg.timeout_ns = SPI_LPSPI_TIMEOUT_DEFAULT_NS;
    }
    param = rd(lp, LPSPI_PARAM);
    txf = LPSPI_PARAM_TXFIFO(param);
    rxf = LPSPI_PARAM_RXFIFO(param);
    if (txf > 4u || rxf > 4u) {
        return INC_ERR_UNSUPPORTED;
    }
    for (k = 0; k < SPI_LPSPI_PCS_COUNT; k++) {
        if (cfg->pcs_pin[k] != HAL_PIN_NONE && k >= LPSPI_PARAM_PCSNUM(param)) {
            return INC_ERR_UNSUPPORTED;
        }
    }
    lp->fifo_words = 1u << (txf < rxf ? txf : rxf);
    if (lp->fifo_words > FIFO_MAX_WORDS) {
        return INC_ERR_UNSUPPORTED;
    }
    lp->bus.ops = &lp_ops;
    lp->bus.ctx = lp;
    lp->released_any = false;
    lp->last_cs = HAL_PIN_NONE;
    lp->last_release_ns = 0;
    lp->stats.reconfigs = 0;
    lp->stats.errors = 0;
    lp->stats.last_sr = 0;
    lp->stats.max_in_flight = 0;
    lp->stats.sleeps = 0;
    lp->ck_valid = false;
    setup_module(lp);
    wr(lp, LPSPI_CR, LPSPI_CR_MEN);
    return INC_OK;
}
