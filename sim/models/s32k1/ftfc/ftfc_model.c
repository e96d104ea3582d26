/* ftfc_model.c - FTFC register model with a NOR FlexNVM array (see sim/s32k_ftfc.h). */
#include "inclino/sim/s32k_ftfc.h"

#include <string.h>

#include "inclino/sim/s32k_bus.h"

#define ERR_FLAGS (S32K_FTFC_FSTAT_ACCERR | S32K_FTFC_FSTAT_FPVIOL)

static uint32_t rnd(struct sim_s32k_ftfc *m)
{
    m->rng = m->rng * 1664525u + 1013904223u;
    return m->rng >> 8;
}

static void reset_regs(struct sim_s32k_ftfc *m)
{
    m->fstat = S32K_FTFC_FSTAT_CCIF;
    m->fcnfg = 0;
    m->fdprot = 0xFFu; /* unprotected */
    memset(m->fccob, 0, sizeof(m->fccob));
    m->event = 0;
}

static void do_erase(struct sim_s32k_ftfc *m, bool torn)
{
    uint32_t i;
    for (i = 0; i < S32K_DFLASH_SECTOR; i++) {
        uint8_t *b = &m->mem[m->off + i];
        if (!torn) {
            *b = 0xFFu;
            continue;
        }
        switch (rnd(m) % 4u) {
        case 0: *b = 0xFFu; break;                  /* erased */
        case 1: *b = (uint8_t)(*b | rnd(m)); break; /* partly erased */
        case 2: *b = (uint8_t)rnd(m); break;        /* garbage */
        default: break;                             /* untouched */
        }
    }
}

static void do_program(struct sim_s32k_ftfc *m, bool torn)
{
    unsigned k;
    for (k = 0; k < S32K_FTFC_PHRASE; k++) {
        uint8_t clear = (uint8_t)~m->data[k];
        if (torn) {
            clear &= (uint8_t)rnd(m);
        }
        m->mem[m->off + k] &= (uint8_t)~clear;
    }
}

static bool phrase_erased(const struct sim_s32k_ftfc *m)
{
    unsigned k;
    for (k = 0; k < S32K_FTFC_PHRASE; k++) {
        if (m->mem[m->off + k] != 0xFFu) {
            return false;
        }
    }
    return true;
}

static void complete(void *arg, uint64_t now)
{
    struct sim_s32k_ftfc *m = arg;
    (void)now;
    m->event = 0;
    if (!m->powered) {
        m->fstat |= S32K_FTFC_FSTAT_MGSTAT0;
    } else {
        bool cut;
        m->steps++;
        cut = m->cut_at != 0u && m->steps == m->cut_at;
        if (m->cmd == S32K_FTFC_CMD_ERASE_SECTOR) {
            if (!cut || m->cut_mode == SIMFLASH_CUT_AFTER) {
                do_erase(m, false);
            } else if (m->cut_mode == SIMFLASH_CUT_TORN) {
                do_erase(m, true);
            }
            if (!cut) {
                m->stats.erases++;
            }
        } else if (!phrase_erased(m)) {
            m->stats.reprograms++;
            m->fstat |= S32K_FTFC_FSTAT_MGSTAT0;
        } else {
            if (!cut || m->cut_mode == SIMFLASH_CUT_AFTER) {
                do_program(m, false);
            } else if (m->cut_mode == SIMFLASH_CUT_TORN) {
                do_program(m, true);
            }
            if (!cut) {
                m->stats.phrases++;
            }
        }
        if (cut) {
            m->powered = false;
            m->cut_at = 0;
            m->fstat |= S32K_FTFC_FSTAT_MGSTAT0;
        }
    }
    m->fstat |= S32K_FTFC_FSTAT_CCIF;
}

static bool protected_range(const struct sim_s32k_ftfc *m, uint32_t off, uint32_t len)
{
    const uint32_t region = m->dflash_size / 8u;
    uint32_t r;
    if (region == 0u) {
        return false;
    }
    for (r = off / region; r <= (off + len - 1u) / region && r < 8u; r++) {
        if ((m->fdprot & (1u << r)) == 0u) {
            return true;
        }
    }
    return false;
}

static void launch(struct sim_s32k_ftfc *m)
{
    const uint8_t cmd = m->fccob[0];
    const uint32_t addr = ((uint32_t)m->fccob[1] << 16) | ((uint32_t)m->fccob[2] << 8) |
                          m->fccob[3];
    const uint32_t off = addr - S32K_FTFC_DFLASH_CMD_ADDR;
    uint32_t len, dur;
    unsigned k;
    int h;
    m->stats.launches++;
    if (cmd == S32K_FTFC_CMD_ERASE_SECTOR) {
        len = S32K_DFLASH_SECTOR;
        dur = m->cfg.erase_ns;
    } else if (cmd == S32K_FTFC_CMD_PROGRAM_PHRASE) {
        len = S32K_FTFC_PHRASE;
        dur = m->cfg.program_ns;
    } else {
        m->fstat |= S32K_FTFC_FSTAT_ACCERR;
        m->stats.accerr++;
        return;
    }
    if ((addr & S32K_FTFC_DFLASH_CMD_ADDR) == 0u || off % len != 0u || off >= m->dflash_size ||
        len > m->dflash_size - off) {
        m->fstat |= S32K_FTFC_FSTAT_ACCERR;
        m->stats.accerr++;
        return;
    }
    if (protected_range(m, off, len)) {
        m->fstat |= S32K_FTFC_FSTAT_FPVIOL;
        m->stats.fpviol++;
        return;
    }
    m->cmd = cmd;
    m->off = off;
    for (k = 0; k < S32K_FTFC_PHRASE; k++) {
        m->data[k] = m->fccob[4u + (k ^ 3u)];
    }
    m->fstat &= (uint8_t) ~(S32K_FTFC_FSTAT_CCIF | S32K_FTFC_FSTAT_MGSTAT0);
    h = sim_clock_schedule(m->cfg.clk, m->cfg.clk->now_ns + dur, complete, m);
    m->event = h > 0 ? h : 0;
    if (h <= 0) {
        complete(m, m->cfg.clk->now_ns); /* queue full: never leave CCIF stuck */
    }
}

/* FCCOB register offset -> FCCOB index, or -1. */
static int fccob_index(uint32_t off)
{
    unsigned n;
    for (n = 0; n < 12u; n++) {
        if (S32K_FTFC_FCCOB(n) == off) {
            return (int)n;
        }
    }
    return -1;
}

static uint32_t reg_read1(struct sim_s32k_ftfc *m, uint32_t off)
{
    int n;
    if (off == S32K_FTFC_FSTAT) {
        return m->fstat;
    }
    if (off == S32K_FTFC_FCNFG) {
        return m->fcnfg;
    }
    if (off == S32K_FTFC_FDPROT) {
        return m->fdprot;
    }
    if (off == 0x02u) {
        return 0xFEu; /* FSEC: unsecured */
    }
    n = fccob_index(off);
    return n >= 0 ? m->fccob[n] : 0u;
}

static uint32_t regs_read(void *ctx, uint32_t off, unsigned width)
{
    struct sim_s32k_ftfc *m = ctx;
    uint32_t v = 0;
    unsigned i;
    for (i = 0; i < width; i++) {
        v |= reg_read1(m, off + i) << (8u * i);
    }
    return v;
}

static void reg_write1(struct sim_s32k_ftfc *m, uint32_t off, uint8_t v)
{
    int n;
    if (off == S32K_FTFC_FSTAT) {
        const bool idle = (m->fstat & S32K_FTFC_FSTAT_CCIF) != 0u;
        m->fstat &= (uint8_t) ~(v & (ERR_FLAGS | S32K_FTFC_FSTAT_RDCOLERR));
        if ((v & S32K_FTFC_FSTAT_CCIF) != 0u && idle && (m->fstat & ERR_FLAGS) == 0u) {
            launch(m);
        }
        return;
    }
    if (off == S32K_FTFC_FDPROT) {
        m->fdprot &= v; /* protection can only be added until reset */
        return;
    }
    if (off == S32K_FTFC_FCNFG) {
        m->fcnfg = v & 0xC0u;
        return;
    }
    n = fccob_index(off);
    if (n >= 0) {
        if ((m->fstat & S32K_FTFC_FSTAT_CCIF) == 0u) {
            m->stats.locked_writes++;
        } else {
            m->fccob[n] = v;
        }
    }
}

static void regs_write(void *ctx, uint32_t off, uint32_t value, unsigned width)
{
    unsigned i;
    for (i = 0; i < width; i++) {
        reg_write1(ctx, off + i, (uint8_t)(value >> (8u * i)));
    }
}

static uint32_t array_read(void *ctx, uint32_t off, unsigned width)
{
    struct sim_s32k_ftfc *m = ctx;
    uint32_t v = 0;
    unsigned i;
    if ((m->fstat & S32K_FTFC_FSTAT_CCIF) == 0u) {
        m->fstat |= S32K_FTFC_FSTAT_RDCOLERR;
        m->stats.read_collisions++;
    }
    for (i = 0; i < width; i++) {
        const uint32_t a = off + i;
        v |= (uint32_t)(a < m->dflash_size ? m->mem[a] : 0xFFu) << (8u * i);
    }
    return v;
}

static void array_write(void *ctx, uint32_t off, uint32_t value, unsigned width)
{
    struct sim_s32k_ftfc *m = ctx;
    (void)off;
    (void)value;
    (void)width;
    m->stats.array_writes++;
}

static uint32_t fcfg1_read(void *ctx, uint32_t off, unsigned width)
{
    const struct sim_s32k_ftfc *m = ctx;
    const uint32_t v = ((uint32_t)m->cfg.depart & 0xFu) << 12;
    (void)width;
    return v >> (8u * (off & 3u));
}

static void fcfg1_write(void *ctx, uint32_t off, uint32_t value, unsigned width)
{
    (void)ctx;
    (void)off;
    (void)value;
    (void)width; /* read-only */
}

static const struct s32k_bus_region_ops regs_ops = {regs_read, regs_write};
static const struct s32k_bus_region_ops array_ops = {array_read, array_write};
static const struct s32k_bus_region_ops fcfg1_ops = {fcfg1_read, fcfg1_write};

int sim_s32k_ftfc_init(struct sim_s32k_ftfc *m, const struct sim_s32k_ftfc_cfg *cfg)
{
    int err;
    if (m == NULL || cfg == NULL || cfg->clk == NULL) {
        return INC_ERR_NULL;
    }
    if (cfg->part != S32K_FTFC_S32K144 && cfg->part != S32K_FTFC_S32K116) {
        return INC_ERR_INVAL;
    }
    memset(m, 0, sizeof(*m));
    m->cfg = *cfg;
    if (m->cfg.erase_ns == 0u) {
        m->cfg.erase_ns = SIM_FTFC_ERASE_NS_DEFAULT;
    }
    if (m->cfg.program_ns == 0u) {
        m->cfg.program_ns = SIM_FTFC_PROGRAM_NS_DEFAULT;
    }
    m->flexnvm_size = cfg->part == S32K_FTFC_S32K144 ? S32K144_FLEXNVM_SIZE : S32K116_FLEXNVM_SIZE;
    m->dflash_size = s32k_ftfc_dflash_size(cfg->part, cfg->depart);
    memset(m->mem, 0xFF, sizeof(m->mem));
    m->powered = true;
    reset_regs(m);
    err = s32k_bus_map(S32K_FTFC_BASE, S32K_FTFC_REGION_SIZE, &regs_ops, m);
    if (err == INC_OK) {
        err = s32k_bus_map(S32K_DFLASH_BASE, m->flexnvm_size, &array_ops, m);
    }
    if (err == INC_OK && cfg->map_fcfg1) {
        err = s32k_bus_map(S32K_SIM_FCFG1, 4u, &fcfg1_ops, m);
    }
    return err;
}

void sim_s32k_ftfc_cut_power_at(struct sim_s32k_ftfc *m, uint32_t n, enum simflash_cut_mode mode,
                                uint32_t seed)
{
    m->cut_at = n == 0u ? 0u : m->steps + n;
    m->cut_mode = mode;
    m->rng = seed * 2654435761u + 1u;
}

void sim_s32k_ftfc_power_on(struct sim_s32k_ftfc *m)
{
    if (m->event > 0) {
        (void)sim_clock_cancel(m->cfg.clk, m->event);
    }
    reset_regs(m);
    m->powered = true;
    m->cut_at = 0;
}

bool sim_s32k_ftfc_powered(const struct sim_s32k_ftfc *m)
{
    return m->powered;
}

uint32_t sim_s32k_ftfc_steps(const struct sim_s32k_ftfc *m)
{
    return m->steps;
}
