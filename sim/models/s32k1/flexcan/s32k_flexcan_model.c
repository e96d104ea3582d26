/* s32k_flexcan_model.c - register-level FlexCAN model; see inclino/sim/s32k_flexcan_model.h. */
#include "inclino/sim/s32k_flexcan_model.h"

#include <string.h>

#include "inclino/s32k_flexcan.h"
#include "inclino/sim/s32k_bus.h"

#define MCR_RESET 0xD890000Fu
#define MCR_ACK_BITS (S32K_FLEXCAN_MCR_LPMACK | S32K_FLEXCAN_MCR_FRZACK | S32K_FLEXCAN_MCR_NOTRDY)
#define ESR1_CLEAR_ON_READ 0xFC00u /* STFERR .. BIT1ERR */
#define BIT_NS 2000u               /* 500 kbit/s */

static bool frozen(const struct s32k_flexcan_model *m)
{
    return (m->mcr & S32K_FLEXCAN_MCR_FRZACK) != 0u;
}

static bool disabled(const struct s32k_flexcan_model *m)
{
    return (m->mcr & S32K_FLEXCAN_MCR_MDIS) != 0u;
}

/* the acknowledge bits follow the request bits at once */
static void mcr_update(struct s32k_flexcan_model *m)
{
    uint32_t v = m->mcr & ~MCR_ACK_BITS;
    bool dis = (v & S32K_FLEXCAN_MCR_MDIS) != 0u;
    bool frz = !dis && (v & S32K_FLEXCAN_MCR_FRZ) != 0u && (v & S32K_FLEXCAN_MCR_HALT) != 0u;
    if (dis) {
        v |= S32K_FLEXCAN_MCR_LPMACK;
    }
    if (frz) {
        v |= S32K_FLEXCAN_MCR_FRZACK;
    }
    if (dis || frz) {
        v |= S32K_FLEXCAN_MCR_NOTRDY;
    }
    m->mcr = v;
}

static uint32_t fltconf(const struct s32k_flexcan_model *m)
{
    if (m->bus_off) {
        return 2u;
    }
    return (m->tec >= 128u || m->rec >= 128u) ? 1u : 0u;
}

static void log_frame(struct s32k_flexcan_model *m, uint16_t id, const uint8_t *d, unsigned dlc,
                      uint64_t t_ns)
{
    if (m->log == NULL) {
        return;
    }
    uint64_t us = t_ns / 1000u;
    fprintf(m->log, "(%010llu.%06llu) %s %03X#",
            (unsigned long long)(us / 1000000u + m->log_epoch_s),
            (unsigned long long)(us % 1000000u), m->iface, (unsigned)id);
    for (unsigned i = 0; i < dlc; i++) {
        fprintf(m->log, "%02X", d[i]);
    }
    fputc('\n', m->log);
}

/* Try to send buffer mb (CODE DATA). */
static void try_tx(struct s32k_flexcan_model *m, unsigned mb)
{
    uint32_t *w = &m->ram[mb * 4u];
    if (disabled(m) || frozen(m) || m->bus_off) {
        return;
    }
    if (m->no_ack) {
        m->stats.tx_failed++;
        m->esr1_sticky |= S32K_FLEXCAN_ESR1_ACKERR;
        if (m->tec < 128u) { /* an error-passive transmitter does not count ACK errors */
            m->tec += 8u;
        }
        return;
    }
    unsigned dlc = (w[0] & S32K_FLEXCAN_CS_DLC_MASK) >> S32K_FLEXCAN_CS_DLC_SHIFT;
    if (dlc > 8u) {
        dlc = 8u;
    }
    uint16_t id = (uint16_t)((w[1] & S32K_FLEXCAN_ID_STD_MASK) >> S32K_FLEXCAN_ID_STD_SHIFT);
    uint8_t d[8];
    for (unsigned b = 0; b < 8u; b++) {
        d[b] = (uint8_t)(w[2u + b / 4u] >> (24u - 8u * (b % 4u)));
    }
    uint64_t start = m->now_ns > m->bus_free_ns ? m->now_ns : m->bus_free_ns;
    uint64_t end = start + (uint64_t)(44u + 8u * dlc) * BIT_NS;
    m->bus_free_ns = end + 3u * BIT_NS;
    log_frame(m, id, d, dlc, end);
    if (m->tec > 0u) {
        m->tec--;
    }
    uint32_t ts = (uint32_t)((end / BIT_NS) & 0xFFFFu);
    w[0] = (w[0] & ~(S32K_FLEXCAN_CS_CODE_MASK | 0xFFFFu)) |
           (S32K_FLEXCAN_CODE_TX_INACTIVE << S32K_FLEXCAN_CS_CODE_SHIFT) | ts;
    m->iflag1 |= 1u << mb;
    m->stats.tx_frames++;
}

static void tx_pending(struct s32k_flexcan_model *m)
{
    for (unsigned mb = 0; mb < m->n_mb; mb++) {
        uint32_t code = (m->ram[mb * 4u] & S32K_FLEXCAN_CS_CODE_MASK) >> S32K_FLEXCAN_CS_CODE_SHIFT;
        if (code == S32K_FLEXCAN_CODE_TX_DATA) {
            try_tx(m, mb);
        }
    }
}

static uint32_t model_read(void *ctx, uint32_t off, unsigned width)
{
    struct s32k_flexcan_model *m = ctx;
    (void)width;
    if (off >= S32K_FLEXCAN_MB0 && off < S32K_FLEXCAN_MB0 + m->n_mb * S32K_FLEXCAN_MB_SIZE) {
        return m->ram[(off - S32K_FLEXCAN_MB0) / 4u];
    }
    switch (off) {
    case S32K_FLEXCAN_MCR: return m->mcr;
    case S32K_FLEXCAN_CTRL1: return m->ctrl1;
    case S32K_FLEXCAN_TIMER: return (uint32_t)((m->now_ns / BIT_NS) & 0xFFFFu);
    case S32K_FLEXCAN_RXMGMASK: return m->rxmgmask;
    case S32K_FLEXCAN_ECR: return (m->tec & 0xFFu) | ((m->rec & 0xFFu) << 8);
    case S32K_FLEXCAN_ESR1: {
        uint32_t v = (fltconf(m) << S32K_FLEXCAN_ESR1_FLTCONF_SHIFT) | m->esr1_sticky;
        m->esr1_sticky &= ~ESR1_CLEAR_ON_READ;
        return v;
    }
    case S32K_FLEXCAN_IMASK1: return m->imask1;
    case S32K_FLEXCAN_IFLAG1: return m->iflag1;
    default: return 0u;
    }
}

static void model_write(void *ctx, uint32_t off, uint32_t v, unsigned width)
{
    struct s32k_flexcan_model *m = ctx;
    (void)width;
    bool config_ok = frozen(m) || disabled(m);
    if (off >= S32K_FLEXCAN_MB0 && off < S32K_FLEXCAN_MB0 + m->n_mb * S32K_FLEXCAN_MB_SIZE) {
        unsigned idx = (off - S32K_FLEXCAN_MB0) / 4u;
        m->ram[idx] = v;
        uint32_t code = (v & S32K_FLEXCAN_CS_CODE_MASK) >> S32K_FLEXCAN_CS_CODE_SHIFT;
        if (idx % 4u == 0u && code == S32K_FLEXCAN_CODE_TX_DATA) {
            try_tx(m, idx / 4u);
        }
        return;
    }
    switch (off) {
    case S32K_FLEXCAN_MCR: {
        bool was_frozen = frozen(m);
        if ((v & S32K_FLEXCAN_MCR_SOFTRST) != 0u) {
            m->mcr = (MCR_RESET & ~S32K_FLEXCAN_MCR_MDIS) | (m->mcr & S32K_FLEXCAN_MCR_MDIS);
            m->imask1 = 0;
            m->iflag1 = 0;
            m->esr1_sticky = 0;
            m->tec = m->rec = 0;
        } else {
            uint32_t keep_cfg = config_ok ? 0u
                                          : (S32K_FLEXCAN_MCR_MAXMB_MASK | S32K_FLEXCAN_MCR_SRXDIS |
                                             S32K_FLEXCAN_MCR_IRMQ);
            if (!config_ok && ((v ^ m->mcr) & keep_cfg) != 0u) {
                m->stats.config_violations++;
            }
            m->mcr = (v & ~keep_cfg) | (m->mcr & keep_cfg);
        }
        mcr_update(m);
        if (was_frozen && !frozen(m)) {
            tx_pending(m);
        }
        break;
    }
    case S32K_FLEXCAN_CTRL1:
        if (!config_ok) {
            m->stats.config_violations++;
            break;
        }
        if (!disabled(m) && ((v ^ m->ctrl1) & S32K_FLEXCAN_CTRL1_CLKSRC) != 0u) {
            m->stats.config_violations++; /* CLKSRC only while disabled */
            v = (v & ~S32K_FLEXCAN_CTRL1_CLKSRC) | (m->ctrl1 & S32K_FLEXCAN_CTRL1_CLKSRC);
        }
        m->ctrl1 = v;
        break;
    case S32K_FLEXCAN_RXMGMASK:
        if (!config_ok) {
            m->stats.config_violations++;
            break;
        }
        m->rxmgmask = v;
        break;
    case S32K_FLEXCAN_IMASK1: m->imask1 = v; break;
    case S32K_FLEXCAN_IFLAG1: m->iflag1 &= ~v; break;
    case S32K_FLEXCAN_ESR1:
        m->esr1_sticky &= ~(v & (S32K_FLEXCAN_ESR1_ERRINT | S32K_FLEXCAN_ESR1_BOFFINT));
        break;
    default: break;
    }
}

static const struct s32k_bus_region_ops model_ops = {model_read, model_write};

int s32k_flexcan_model_init(struct s32k_flexcan_model *m, uint32_t base, unsigned n_mb, FILE *log,
                            const char *iface)
{
    if (m == NULL || iface == NULL) {
        return INC_ERR_NULL;
    }
    if (n_mb < 1u || n_mb > S32K_FLEXCAN_MODEL_MAX_MB || strlen(iface) >= sizeof m->iface) {
        return INC_ERR_INVAL;
    }
    memset(m, 0, sizeof *m);
    m->base = base;
    m->n_mb = n_mb;
    m->mcr = MCR_RESET;
    m->rxmgmask = 0xFFFFFFFFu;
    m->log = log;
    strcpy(m->iface, iface);
    mcr_update(m);
    return s32k_bus_map(base, S32K_FLEXCAN_REGION, &model_ops, m);
}

void s32k_flexcan_model_set_time_ns(struct s32k_flexcan_model *m, uint64_t t_ns)
{
    if (m == NULL) {
        return;
    }
    if (t_ns > m->now_ns) {
        m->now_ns = t_ns;
    }
    tx_pending(m);
}

int s32k_flexcan_model_inject(struct s32k_flexcan_model *m, uint16_t id, const uint8_t *data,
                              uint8_t dlc)
{
    if (m == NULL || (data == NULL && dlc != 0u)) {
        return INC_ERR_NULL;
    }
    if (id > 0x7FFu || dlc > 8u) {
        return INC_ERR_INVAL;
    }
    if (m->bus_off || disabled(m) || frozen(m)) {
        m->stats.rx_dropped++;
        return INC_ERR_BUS;
    }
    /* the frame is on the bus (and in the log) whether a buffer takes it or not */
    uint64_t end = (m->now_ns > m->bus_free_ns ? m->now_ns : m->bus_free_ns) +
                   (uint64_t)(44u + 8u * dlc) * BIT_NS;
    m->bus_free_ns = end + 3u * BIT_NS;
    log_frame(m, id, data, dlc, end);
    uint32_t idw = (uint32_t)id << S32K_FLEXCAN_ID_STD_SHIFT;
    for (unsigned mb = 0; mb < m->n_mb; mb++) {
        uint32_t *w = &m->ram[mb * 4u];
        uint32_t code = (w[0] & S32K_FLEXCAN_CS_CODE_MASK) >> S32K_FLEXCAN_CS_CODE_SHIFT;
        bool rx = code == S32K_FLEXCAN_CODE_RX_EMPTY || code == S32K_FLEXCAN_CODE_RX_FULL ||
                  code == S32K_FLEXCAN_CODE_RX_OVERRUN;
        if (!rx || (w[0] & S32K_FLEXCAN_CS_IDE) != 0u ||
            ((w[1] ^ idw) & m->rxmgmask & S32K_FLEXCAN_ID_STD_MASK) != 0u) {
            continue;
        }
        uint32_t newcode = code == S32K_FLEXCAN_CODE_RX_EMPTY ? S32K_FLEXCAN_CODE_RX_FULL
                                                              : S32K_FLEXCAN_CODE_RX_OVERRUN;
        if (newcode == S32K_FLEXCAN_CODE_RX_OVERRUN) {
            m->stats.rx_overruns++;
        }
        w[1] = idw;
        w[2] = w[3] = 0u;
        for (unsigned b = 0; b < dlc; b++) {
            w[2u + b / 4u] |= (uint32_t)data[b] << (24u - 8u * (b % 4u));
        }
        w[0] = (newcode << S32K_FLEXCAN_CS_CODE_SHIFT) |
               ((uint32_t)dlc << S32K_FLEXCAN_CS_DLC_SHIFT) | (uint32_t)((end / BIT_NS) & 0xFFFFu);
        m->iflag1 |= 1u << mb;
        m->stats.rx_frames++;
        return INC_OK;
    }
    m->stats.rx_dropped++;
    return INC_ERR_BUSY;
}

void s32k_flexcan_model_set_no_ack(struct s32k_flexcan_model *m, bool on)
{
    if (m != NULL) {
        m->no_ack = on;
    }
}

void s32k_flexcan_model_set_bus_off(struct s32k_flexcan_model *m, bool on)
{
    if (m == NULL) {
        return;
    }
    m->bus_off = on;
    if (on) {
        m->esr1_sticky |= S32K_FLEXCAN_ESR1_BOFFINT;
    } else {
        m->tec = m->rec = 0;
    }
}
