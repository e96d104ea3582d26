/* calstore_ftfc.c - calstore_flash_ops on the FTFC D-flash driver (see calstore_ftfc.h). */
#include "inclino/calstore_ftfc.h"

static int op_read(void *ctx, uint32_t addr, uint8_t *buf, uint32_t len)
{
    return s32k_ftfc_read(ctx, addr, buf, len);
}

static int op_program(void *ctx, uint32_t addr, const uint8_t *buf, uint32_t len)
{
    return s32k_ftfc_program(ctx, addr, buf, len);
}

static int op_erase(void *ctx, uint32_t addr)
{
    return s32k_ftfc_erase_sector(ctx, addr);
}

const struct calstore_flash_ops calstore_ftfc_ops = {
    .read = op_read,
    .program = op_program,
    .erase = op_erase,
};

int calstore_ftfc_config(struct s32k_ftfc *f, uint32_t first_sector, struct calstore_config *out)
{
    const uint32_t sectors = f != NULL ? f->dflash_size / S32K_DFLASH_SECTOR : 0u;
    if (f == NULL || out == NULL) {
        return INC_ERR_NULL;
    }
    if (!f->ready) {
        return INC_ERR_STATE;
    }
    if (first_sector >= sectors || sectors - first_sector < 2u ||
        calstore_slot_min_size(S32K_FTFC_PHRASE, S32K_DFLASH_SECTOR) > S32K_DFLASH_SECTOR) {
        return INC_ERR_NO_SPACE;
    }
    out->ops = &calstore_ftfc_ops;
    out->ctx = f;
    out->page_size = S32K_DFLASH_SECTOR;
    out->prog_size = S32K_FTFC_PHRASE;
    out->erased_value = CALSTORE_ERASED;
    out->slot_addr[0] = first_sector * S32K_DFLASH_SECTOR;
    out->slot_addr[1] = (first_sector + 1u) * S32K_DFLASH_SECTOR;
    out->slot_size = S32K_DFLASH_SECTOR;
    return INC_OK;
}
