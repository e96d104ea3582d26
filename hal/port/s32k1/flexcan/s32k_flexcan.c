/* s32k_flexcan.c - FlexCAN driver of the S32K1 family; see inclino/s32k_flexcan.h. */
#include "inclino/s32k_flexcan.h"

#include "inclino/s32k_mmio.h"

static uint32_t reg(const struct s32k_flexcan *d, uint32_t off)
{
    return d->cfg.base + off;
}

static uint32_t mb_addr(const struct s32k_flexcan *d, unsigned mb, unsigned word)
{
    return d->cfg.base + S32K_FLEXCAN_MB0 + mb * S32K_FLEXCAN_MB_SIZE + word * 4u;
}

void s32k_flexcan_cfg_default(struct s32k_flexcan_cfg *cfg, uint16_t rx_id)
{
    if (cfg == NULL) {
        return;
    }
    cfg->base = S32K_CAN0_BASE;
    cfg->n_mb = 32u;
    cfg->rx_mb = 8u;
    cfg->tx_first = 9u;
    cfg->tx_count = 4u;
    cfg->rx_id = rx_id;
    cfg->clk_hz = S32K_FLEXCAN_CLK_HZ;
    cfg->poll_limit = 100000u;
}

/* Wait until (MCR & mask) == want, at most poll_limit reads. */
static int wait_mcr(const struct s32k_flexcan *d, uint32_t mask, uint32_t want)
{
    for (uint32_t i = 0; i < d->cfg.poll_limit; i++) {
        if ((s32k_mmio_read32(reg(d, S32K_FLEXCAN_MCR)) & mask) == want) {
            return INC_OK;
        }
    }
    return INC_ERR_TIMEOUT;
}

static int cfg_check(const struct s32k_flexcan_cfg *c)
{
    if (c->n_mb < 2u || c->n_mb > 32u || c->rx_mb >= c->n_mb || c->tx_count < 1u ||
        c->tx_count > 8u || (unsigned)c->tx_first + c->tx_count > c->n_mb || c->rx_id > 0x7FFu ||
        c->poll_limit == 0u) {
        return INC_ERR_INVAL;
    }
    if (c->rx_mb >= c->tx_first && c->rx_mb < c->tx_first + c->tx_count) {
        return INC_ERR_INVAL;
    }
    if (c->clk_hz != S32K_FLEXCAN_CLK_HZ) {
        return INC_ERR_UNSUPPORTED;
    }
    return INC_OK;
}

int s32k_flexcan_init(struct s32k_flexcan *dev, const struct s32k_flexcan_cfg *cfg)
{
    if (dev == NULL || cfg == NULL) {
        return INC_ERR_NULL;
    }
    dev->ready = false;
    int rc = cfg_check(cfg);
    if (rc != INC_OK) {
        return rc;
    }
    dev->cfg = *cfg;
    dev->last_esr1 = 0;
    dev->sent = dev->received = dev->overruns = 0;

    /* 1. disabled, then the clock source: the oscillator clock */
    s32k_mmio_set32(reg(dev, S32K_FLEXCAN_MCR), S32K_FLEXCAN_MCR_MDIS);
    rc = wait_mcr(dev, S32K_FLEXCAN_MCR_LPMACK, S32K_FLEXCAN_MCR_LPMACK);
    if (rc != INC_OK) {
        return rc;
    }
    s32k_mmio_clear32(reg(dev, S32K_FLEXCAN_CTRL1), S32K_FLEXCAN_CTRL1_CLKSRC);
    /* 2. enabled (it comes up frozen), soft reset */
    s32k_mmio_clear32(reg(dev, S32K_FLEXCAN_MCR), S32K_FLEXCAN_MCR_MDIS);
    rc = wait_mcr(dev, S32K_FLEXCAN_MCR_LPMACK, 0u);
    if (rc != INC_OK) {
        return rc;
    }
    s32k_mmio_set32(reg(dev, S32K_FLEXCAN_MCR), S32K_FLEXCAN_MCR_SOFTRST);
    rc = wait_mcr(dev, S32K_FLEXCAN_MCR_SOFTRST, 0u);
    if (rc != INC_OK) {
        return rc;
    }
    /* 3. freeze */
    s32k_mmio_set32(reg(dev, S32K_FLEXCAN_MCR), S32K_FLEXCAN_MCR_FRZ | S32K_FLEXCAN_MCR_HALT);
    rc = wait_mcr(dev, S32K_FLEXCAN_MCR_FRZACK, S32K_FLEXCAN_MCR_FRZACK);
    if (rc != INC_OK) {
        return rc;
    }
    /* 4. configuration */
    s32k_mmio_modify32(reg(dev, S32K_FLEXCAN_MCR),
                       S32K_FLEXCAN_MCR_MAXMB_MASK | S32K_FLEXCAN_MCR_SRXDIS |
                           S32K_FLEXCAN_MCR_IRMQ | S32K_FLEXCAN_MCR_RFEN,
                       ((uint32_t)(cfg->n_mb - 1u) & S32K_FLEXCAN_MCR_MAXMB_MASK) |
                           S32K_FLEXCAN_MCR_SRXDIS);
    s32k_mmio_write32(reg(dev, S32K_FLEXCAN_CTRL1), S32K_FLEXCAN_CTRL1_500K);
    for (unsigned mb = 0; mb < cfg->n_mb; mb++) {
        for (unsigned w = 0; w < 4u; w++) {
            s32k_mmio_write32(mb_addr(dev, mb, w), 0u);
        }
    }
    for (unsigned i = 0; i < cfg->tx_count; i++) {
        s32k_mmio_write32(mb_addr(dev, cfg->tx_first + i, 0u),
                          S32K_FLEXCAN_CODE_TX_INACTIVE << S32K_FLEXCAN_CS_CODE_SHIFT);
    }
    s32k_mmio_write32(reg(dev, S32K_FLEXCAN_RXMGMASK), S32K_FLEXCAN_ID_STD_MASK);
    s32k_mmio_write32(mb_addr(dev, cfg->rx_mb, 1u),
                      (uint32_t)cfg->rx_id << S32K_FLEXCAN_ID_STD_SHIFT);
    s32k_mmio_write32(mb_addr(dev, cfg->rx_mb, 0u),
                      S32K_FLEXCAN_CODE_RX_EMPTY << S32K_FLEXCAN_CS_CODE_SHIFT);
    s32k_mmio_write32(reg(dev, S32K_FLEXCAN_IMASK1), 0u);
    s32k_mmio_write32(reg(dev, S32K_FLEXCAN_IFLAG1), 0xFFFFFFFFu);
    /* 5. leave freeze */
    s32k_mmio_clear32(reg(dev, S32K_FLEXCAN_MCR), S32K_FLEXCAN_MCR_HALT | S32K_FLEXCAN_MCR_FRZ);
    rc = wait_mcr(dev, S32K_FLEXCAN_MCR_FRZACK, 0u);
    if (rc != INC_OK) {
        return rc;
    }
    rc = wait_mcr(dev, S32K_FLEXCAN_MCR_NOTRDY, 0u);
    if (rc != INC_OK) {
        return rc;
    }
    dev->ready = true;
    return INC_OK;
}

/* The error bits of ESR1 that clear when it is read (STFERR .. BIT1ERR). */
#define ESR1_ERR_BITS 0xFC00u

/* Read ESR1 and keep what it said: its error bits accumulate until error_state reports them. */
static uint32_t read_esr1(struct s32k_flexcan *dev)
{
    uint32_t v = s32k_mmio_read32(reg(dev, S32K_FLEXCAN_ESR1));
    dev->last_esr1 = v | (dev->last_esr1 & ESR1_ERR_BITS);
    return dev->last_esr1;
}

static bool bus_off(uint32_t esr1)
{
    return ((esr1 & S32K_FLEXCAN_ESR1_FLTCONF_MASK) >> S32K_FLEXCAN_ESR1_FLTCONF_SHIFT) >= 2u;
}

int s32k_flexcan_error_state(struct s32k_flexcan *dev)
{
    if (dev == NULL) {
        return INC_ERR_NULL;
    }
    if (!dev->ready) {
        return INC_ERR_STATE;
    }
    uint32_t v = read_esr1(dev);
    dev->last_esr1 &= ~ESR1_ERR_BITS; /* reported now */
    uint32_t fltconf = (v & S32K_FLEXCAN_ESR1_FLTCONF_MASK) >> S32K_FLEXCAN_ESR1_FLTCONF_SHIFT;
    if (fltconf >= 2u) {
        return INC_ERR_BUS;
    }
    if (fltconf == 1u) {
        return INC_ERR_DEVICE;
    }
    if ((v & S32K_FLEXCAN_ESR1_ACKERR) != 0u) {
        return INC_ERR_TIMEOUT;
    }
    return INC_OK;
}

int s32k_flexcan_send(struct s32k_flexcan *dev, uint16_t id, const uint8_t *data, uint8_t dlc)
{
    if (dev == NULL || (data == NULL && dlc != 0u)) {
        return INC_ERR_NULL;
    }
    if (!dev->ready) {
        return INC_ERR_STATE;
    }
    if (id > 0x7FFu || dlc > 8u) {
        return INC_ERR_INVAL;
    }
    if (bus_off(read_esr1(dev))) {
        return INC_ERR_BUS;
    }
    uint32_t iflag = s32k_mmio_read32(reg(dev, S32K_FLEXCAN_IFLAG1));
    for (unsigned i = 0; i < dev->cfg.tx_count; i++) {
        unsigned mb = dev->cfg.tx_first + i;
        uint32_t bit = 1u << (mb & 31u);
        uint32_t cs = s32k_mmio_read32(mb_addr(dev, mb, 0u));
        uint32_t code = (cs & S32K_FLEXCAN_CS_CODE_MASK) >> S32K_FLEXCAN_CS_CODE_SHIFT;
        bool done = mb < 32u && (iflag & bit) != 0u;
        if (code == S32K_FLEXCAN_CODE_TX_DATA && !done) {
            continue; /* still pending */
        }
        if (mb < 32u) {
            s32k_mmio_write32(reg(dev, S32K_FLEXCAN_IFLAG1), bit); /* write 1 to clear */
        }
        s32k_mmio_write32(mb_addr(dev, mb, 0u),
                          S32K_FLEXCAN_CODE_TX_INACTIVE << S32K_FLEXCAN_CS_CODE_SHIFT);
        s32k_mmio_write32(mb_addr(dev, mb, 1u), (uint32_t)id << S32K_FLEXCAN_ID_STD_SHIFT);
        uint32_t w[2] = {0u, 0u};
        for (unsigned b = 0; b < dlc; b++) {
            w[b / 4u] |= (uint32_t)data[b] << (24u - 8u * (b % 4u));
        }
        s32k_mmio_write32(mb_addr(dev, mb, 2u), w[0]);
        s32k_mmio_write32(mb_addr(dev, mb, 3u), w[1]);
        s32k_mmio_write32(mb_addr(dev, mb, 0u),
                          (S32K_FLEXCAN_CODE_TX_DATA << S32K_FLEXCAN_CS_CODE_SHIFT) |
                              ((uint32_t)dlc << S32K_FLEXCAN_CS_DLC_SHIFT));
        dev->sent++;
        return INC_OK;
    }
    return INC_ERR_BUSY;
}

int s32k_flexcan_receive(struct s32k_flexcan *dev, uint16_t *id, uint8_t data[8], uint8_t *dlc,
                         bool *overrun)
{
    if (dev == NULL || id == NULL || data == NULL || dlc == NULL) {
        return INC_ERR_NULL;
    }
    if (!dev->ready) {
        return INC_ERR_STATE;
    }
    if (bus_off(read_esr1(dev))) {
        return INC_ERR_BUS;
    }
    unsigned mb = dev->cfg.rx_mb;
    uint32_t bit = 1u << (mb & 31u);
    if (mb < 32u && (s32k_mmio_read32(reg(dev, S32K_FLEXCAN_IFLAG1)) & bit) == 0u) {
        return INC_ERR_STALE;
    }
    uint32_t cs = s32k_mmio_read32(mb_addr(dev, mb, 0u)); /* locks the buffer */
    uint32_t code = (cs & S32K_FLEXCAN_CS_CODE_MASK) >> S32K_FLEXCAN_CS_CODE_SHIFT;
    int rc = INC_ERR_STALE;
    if (code == S32K_FLEXCAN_CODE_RX_FULL || code == S32K_FLEXCAN_CODE_RX_OVERRUN) {
        uint32_t idw = s32k_mmio_read32(mb_addr(dev, mb, 1u));
        const uint32_t w[2] = {s32k_mmio_read32(mb_addr(dev, mb, 2u)),
                               s32k_mmio_read32(mb_addr(dev, mb, 3u))};
        uint8_t n = (uint8_t)((cs & S32K_FLEXCAN_CS_DLC_MASK) >> S32K_FLEXCAN_CS_DLC_SHIFT);
        if (n > 8u) {
            n = 8u; /* classic CAN: a DLC of 9..15 carries 8 bytes */
        }
        *id = (uint16_t)((idw & S32K_FLEXCAN_ID_STD_MASK) >> S32K_FLEXCAN_ID_STD_SHIFT);
        *dlc = n;
        for (unsigned b = 0; b < 8u; b++) {
            data[b] = b < n ? (uint8_t)(w[b / 4u] >> (24u - 8u * (b % 4u))) : 0u;
        }
        if (overrun != NULL) {
            *overrun = code == S32K_FLEXCAN_CODE_RX_OVERRUN;
        }
        if (code == S32K_FLEXCAN_CODE_RX_OVERRUN) {
            dev->overruns++;
        }
        dev->received++;
        rc = INC_OK;
    }
    (void)s32k_mmio_read32(reg(dev, S32K_FLEXCAN_TIMER)); /* unlocks the buffer */
    if (mb < 32u) {
        s32k_mmio_write32(reg(dev, S32K_FLEXCAN_IFLAG1), bit);
    }
    s32k_mmio_write32(mb_addr(dev, mb, 0u),
                      S32K_FLEXCAN_CODE_RX_EMPTY << S32K_FLEXCAN_CS_CODE_SHIFT);
    return rc;
}
