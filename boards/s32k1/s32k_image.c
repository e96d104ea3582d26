/* s32k_image.c - see s32k_image.h. */
#include "s32k_image.h"

#include <stddef.h>

#include "epb_image.h"
#include "inclino/calstore_ftfc.h"
#include "inclino/s32k_ftfc.h"
#include "inclino/s32k_wdog.h"

struct s32k_board s32k_image_board;

static struct s32k_ftfc ftfc;
static struct calstore_config store_cfg;

S32K1_EARLY(s32k_image_store)
S32K1_STEP const struct calstore_config *s32k_image_store(const struct s32k_board_desc *desc)
{
    struct s32k_ftfc_cfg fc;
    fc.part = desc->part == S32K_PART_116 ? S32K_FTFC_S32K116 : S32K_FTFC_S32K144;
    fc.ftfc_base = S32K_FTFC_BASE;
    fc.fcfg1_addr = S32K_SIM_FCFG1;
    fc.dflash_base = S32K_DFLASH_BASE;
    fc.poll_limit = 0u;
    if (s32k_ftfc_init(&ftfc, &fc) != INC_OK ||
        calstore_ftfc_config(&ftfc, CALSTORE_FTFC_IMAGE_SECTOR, &store_cfg) != INC_OK) {
        return epb_image_no_flash();
    }
    return &store_cfg;
}

S32K1_EARLY(s32k_image_bringup)
S32K1_STEP void s32k_image_bringup(const struct s32k_board_desc *desc)
{
    struct s32k_board *b = &s32k_image_board;
    int err = desc != NULL ? s32k_board_init_core(b, desc, true) : INC_ERR_NULL;
    if (err == INC_OK) {
#if S32K_IMAGE_LPSPI
        err = s32k_board_spi_lpspi(b);
#else
        err = s32k_board_spi_bitbang(b);
#endif
    }
    if (err != INC_OK) {
        for (;;) {
            /* no refresh: the watchdog resets the part and the bring-up is tried again */
        }
    }
}

S32K1_STEP void s32k_epb_main(const struct s32k_board_desc *desc)
{
    const struct s32k_board *b = &s32k_image_board;
    struct epb_image_board eb;
    s32k_image_bringup(desc);
    eb.hal = &b->hal;
    eb.spi = b->spi;
    eb.cs = desc->pins.cs_imu;
    eb.dr = desc->pins.dr_imu;
    eb.per_result = s32k_wdog_refresh;
    eb.store = s32k_image_store(desc);
    epb_image_run_on(&eb);
}
