/* ftfc.c - FTFC command sequence on the FlexNVM data flash (see s32k_ftfc.h). */
#include "inclino/s32k_ftfc.h"

#include "inclino/s32k_mmio.h"

#define RESERVED 0xFFFFFFFFu

/* D-flash bytes per DEPART code ([S32K1XXRM] FlexNVM partition code tables). */
static const uint32_t depart_s32k144[16] = {
    0x10000u, RESERVED, RESERVED, 0x8000u, 0u,       RESERVED, RESERVED, RESERVED,
    0u,       RESERVED, 0x4000u,  0x8000u, 0x10000u, RESERVED, RESERVED, 0x10000u,
};
static const uint32_t depart_s32k116[16] = {
    0x8000u, RESERVED, RESERVED, 0u,      RESERVED, RESERVED, RESERVED, RESERVED,
    0u,      0x2000u,  RESERVED, 0x8000u, RESERVED, RESERVED, RESERVED, 0x8000u,
};

uint32_t s32k_ftfc_dflash_size(enum s32k_ftfc_part part, uint8_t depart)
{
    uint32_t v;
    if (depart > 15u) {
        return 0u;
    }
    if (part == S32K_FTFC_S32K144) {
        v = depart_s32k144[depart];
    } else if (part == S32K_FTFC_S32K116) {
        v = depart_s32k116[depart];
    } else {
        return 0u;
    }
    return v == RESERVED ? 0u : v;
}

static uint8_t fstat(const struct s32k_ftfc *f)
{
    return s32k_mmio_read8(f->cfg.ftfc_base + S32K_FTFC_FSTAT);
}

static void fccob(const struct s32k_ftfc *f, unsigned n, uint8_t v)
{
    s32k_mmio_write8(f->cfg.ftfc_base + S32K_FTFC_FCCOB(n), v);
}

static bool wait_ccif(const struct s32k_ftfc *f)
{
    uint32_t polls;
    for (polls = 0; polls < f->cfg.poll_limit; polls++) {
        if ((fstat(f) & S32K_FTFC_FSTAT_CCIF) != 0u) {
            return true;
        }
    }
    return false;
}

/* FCCOB0 = cmd, FCCOB1..3 = D-flash command address of off, FCCOB4.. = data (n bytes: byte k
 * of the phrase in FCCOB(4 + (k ^ 3)), which is register offset 8 + k). */
static int command(struct s32k_ftfc *f, uint8_t cmd, uint32_t off, const uint8_t *data, unsigned n)
{
    const uint32_t addr = S32K_FTFC_DFLASH_CMD_ADDR + off;
    uint8_t st;
    unsigned k;
    if (!wait_ccif(f)) {
        f->stats.timeouts++;
        return INC_ERR_BUSY;
    }
    s32k_mmio_write8(f->cfg.ftfc_base + S32K_FTFC_FSTAT,
                     S32K_FTFC_FSTAT_ACCERR | S32K_FTFC_FSTAT_FPVIOL);
    fccob(f, 0, cmd);
    fccob(f, 1, (uint8_t)(addr >> 16));
    fccob(f, 2, (uint8_t)(addr >> 8));
    fccob(f, 3, (uint8_t)addr);
    for (k = 0; k < n; k++) {
        fccob(f, 4u + (k ^ 3u), data[k]);
    }
    f->stats.commands++;
    s32k_mmio_write8(f->cfg.ftfc_base + S32K_FTFC_FSTAT, S32K_FTFC_FSTAT_CCIF); /* launch */
    if (!wait_ccif(f)) {
        f->stats.timeouts++;
        return INC_ERR_TIMEOUT;
    }
    st = fstat(f);
    if ((st & (S32K_FTFC_FSTAT_ACCERR | S32K_FTFC_FSTAT_FPVIOL | S32K_FTFC_FSTAT_MGSTAT0)) == 0u) {
        return INC_OK;
    }
    f->stats.last_fstat = st;
    if ((st & S32K_FTFC_FSTAT_ACCERR) != 0u) {
        f->stats.accerr++;
        return INC_ERR_INVAL;
    }
    if ((st & S32K_FTFC_FSTAT_FPVIOL) != 0u) {
        f->stats.fpviol++;
        return INC_ERR_STATE;
    }
    f->stats.mgstat0++;
    return INC_ERR_IO;
}

int s32k_ftfc_init(struct s32k_ftfc *f, const struct s32k_ftfc_cfg *cfg)
{
    uint32_t size;
    if (f == NULL || cfg == NULL) {
        return INC_ERR_NULL;
    }
    f->ready = false;
    if (cfg->part != S32K_FTFC_S32K144 && cfg->part != S32K_FTFC_S32K116) {
        return INC_ERR_INVAL;
    }
    f->cfg = *cfg;
    if (f->cfg.poll_limit == 0u) {
        f->cfg.poll_limit = S32K_FTFC_POLL_DEFAULT;
    }
    f->stats = (struct s32k_ftfc_stats){0};
    f->depart = (uint8_t)S32K_SIM_FCFG1_DEPART(s32k_mmio_read32(cfg->fcfg1_addr));
    if (f->depart == S32K_DEPART_UNPARTITIONED) {
        return INC_ERR_STATE; /* never partitioned: refused, never programmed blindly */
    }
    size = s32k_ftfc_dflash_size(cfg->part, f->depart);
    if (size == 0u) {
        return INC_ERR_UNSUPPORTED;
    }
    f->dflash_size = size;
    f->ready = true;
    return INC_OK;
}

static int check(const struct s32k_ftfc *f, uint32_t off, uint32_t len, uint32_t align)
{
    if (!f->ready) {
        return INC_ERR_STATE;
    }
    if (off % align != 0u || len % align != 0u || off > f->dflash_size ||
        len > f->dflash_size - off) {
        return INC_ERR_INVAL;
    }
    return INC_OK;
}

int s32k_ftfc_erase_sector(struct s32k_ftfc *f, uint32_t off)
{
    int err;
    if (f == NULL) {
        return INC_ERR_NULL;
    }
    err = check(f, off, S32K_DFLASH_SECTOR, S32K_DFLASH_SECTOR);
    if (err != INC_OK) {
        return err;
    }
    err = command(f, S32K_FTFC_CMD_ERASE_SECTOR, off, NULL, 0u);
    if (err == INC_OK) {
        f->stats.erases++;
    }
    return err;
}

int s32k_ftfc_program(struct s32k_ftfc *f, uint32_t off, const uint8_t *buf, uint32_t len)
{
    uint32_t i;
    int err;
    if (f == NULL || (buf == NULL && len != 0u)) {
        return INC_ERR_NULL;
    }
    err = check(f, off, len, S32K_FTFC_PHRASE);
    if (err != INC_OK) {
        return err;
    }
    for (i = 0; i < len; i += S32K_FTFC_PHRASE) {
        err = command(f, S32K_FTFC_CMD_PROGRAM_PHRASE, off + i, &buf[i], S32K_FTFC_PHRASE);
        if (err != INC_OK) {
            return err;
        }
        f->stats.phrases++;
    }
    return INC_OK;
}

int s32k_ftfc_read(struct s32k_ftfc *f, uint32_t off, uint8_t *buf, uint32_t len)
{
    uint32_t i;
    int err;
    if (f == NULL || (buf == NULL && len != 0u)) {
        return INC_ERR_NULL;
    }
    err = check(f, off, len, 1u);
    if (err != INC_OK) {
        return err;
    }
    if (!wait_ccif(f)) { /* no read while a command runs on the block (RDCOLERR) */
        f->stats.timeouts++;
        return INC_ERR_BUSY;
    }
    for (i = 0; i < len; i++) {
        buf[i] = s32k_mmio_read8(f->cfg.dflash_base + off + i);
    }
    return INC_OK;
}
