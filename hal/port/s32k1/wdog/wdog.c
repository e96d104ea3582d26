/* wdog.c - see inclino/s32k_wdog.h. */
#include "inclino/s32k_wdog.h"

#include "inclino/s32k1_regs.h"
#include "inclino/s32k_mmio.h"

/* TOVAL in counts of the prescaled LPO: 128 kHz / 256 = 500 Hz, 2 ms per count. */
#define WDOG_TOVAL ((S32K_WDOG_TIMEOUT_MS * (S32K_WDOG_LPO_HZ / 256u)) / 1000u)

static int wait_cs(uint32_t bit)
{
    uint32_t n;
    for (n = 0; n < S32K_WDOG_POLL_MAX; n++) {
        if ((s32k_mmio_read32(S32K_WDOG_CS) & bit) != 0u) {
            return INC_OK;
        }
    }
    return INC_ERR_TIMEOUT;
}

int s32k_wdog_init(bool enable)
{
    uint32_t cs = S32K_WDOG_CS_CMD32EN | S32K_WDOG_CS_UPDATE | S32K_WDOG_CS_CLK_LPO;
    int err;
    s32k_mmio_write32(S32K_WDOG_CNT, S32K_WDOG_UNLOCK_KEY);
    err = wait_cs(S32K_WDOG_CS_ULK);
    if (err != INC_OK) {
        return err;
    }
    if (enable) {
        cs |= S32K_WDOG_CS_EN | S32K_WDOG_CS_PRES;
        s32k_mmio_write32(S32K_WDOG_TOVAL, WDOG_TOVAL);
    } else {
        s32k_mmio_write32(S32K_WDOG_TOVAL, 0xFFFFu);
    }
    s32k_mmio_write32(S32K_WDOG_WIN, 0u);
    s32k_mmio_write32(S32K_WDOG_CS, cs);
    return wait_cs(S32K_WDOG_CS_RCS);
}

void s32k_wdog_refresh(void)
{
    s32k_mmio_write32(S32K_WDOG_CNT, S32K_WDOG_REFRESH_KEY);
}
