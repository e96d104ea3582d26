/* scg.c - see inclino/s32k_scg.h. */
#include "inclino/s32k_scg.h"

#include <stdbool.h>
#include <stddef.h>

#include "inclino/s32k1_regs.h"
#include "inclino/s32k_mmio.h"

static bool poll_set(uint32_t addr, uint32_t mask, uint32_t want)
{
    uint32_t n;
    for (n = 0; n < S32K_SCG_POLL_MAX; n++) {
        if ((s32k_mmio_read32(addr) & mask) == want) {
            return true;
        }
    }
    return false;
}

static int switch_to(uint32_t rccr)
{
    s32k_mmio_write32(S32K_SCG_RCCR, rccr);
    return poll_set(S32K_SCG_CSR, S32K_SCG_SCS_MASK, rccr & S32K_SCG_SCS_MASK) ? INC_OK
                                                                               : INC_ERR_TIMEOUT;
}

static int firc_48(void)
{
    /* FIRC runs from reset; make sure it is valid and selected, core/bus 48, slow 24 MHz. */
    if (!poll_set(S32K_SCG_FIRCCSR, S32K_SCG_XCSR_VLD, S32K_SCG_XCSR_VLD)) {
        return INC_ERR_TIMEOUT;
    }
    s32k_mmio_write32(S32K_SCG_FIRCDIV, (S32K_SCG_DIV_1 << S32K_SCG_DIV1_SHIFT) |
                                            (S32K_SCG_DIV_2 << S32K_SCG_DIV2_SHIFT));
    s32k_mmio_write32(S32K_SCG_SIRCDIV, (S32K_SCG_DIV_1 << S32K_SCG_DIV1_SHIFT) |
                                            (S32K_SCG_DIV_1 << S32K_SCG_DIV2_SHIFT));
    return switch_to(S32K_SCG_CCR(S32K_SCG_SCS_FIRC, 1u, 1u, 2u));
}

static int spll_80(void)
{
    int err = firc_48(); /* known state first: FIRC selected */
    if (err != INC_OK) {
        return err;
    }
    /* SOSC: 8 MHz crystal (EREFS), medium range 1..8 MHz, low gain; DIV1 = DIV2 = /1. */
    s32k_mmio_write32(S32K_SCG_SOSCCSR, 0u); /* off (and unlocked) while configuring */
    s32k_mmio_write32(S32K_SCG_SOSCDIV, (S32K_SCG_DIV_1 << S32K_SCG_DIV1_SHIFT) |
                                            (S32K_SCG_DIV_1 << S32K_SCG_DIV2_SHIFT));
    s32k_mmio_write32(S32K_SCG_SOSCCFG, S32K_SCG_SOSCCFG_RANGE_MED | S32K_SCG_SOSCCFG_EREFS);
    s32k_mmio_write32(S32K_SCG_SOSCCSR, S32K_SCG_XCSR_EN);
    if (!poll_set(S32K_SCG_SOSCCSR, S32K_SCG_XCSR_VLD, S32K_SCG_XCSR_VLD)) {
        return INC_ERR_TIMEOUT;
    }
    /* SPLL: PREDIV /1, MULT x40 -> VCO 320 MHz, SPLL_CLK 160 MHz; DIV1 /2 (80), DIV2 /4 (40). */
    s32k_mmio_write32(S32K_SCG_SPLLCSR, 0u);
    s32k_mmio_write32(S32K_SCG_SPLLDIV, (2u << S32K_SCG_DIV1_SHIFT) | (3u << S32K_SCG_DIV2_SHIFT));
    /* PREDIV = 0 (/1): only the MULT field is non-zero */
    s32k_mmio_write32(S32K_SCG_SPLLCFG, (40u - 16u) << S32K_SCG_SPLLCFG_MULT_SHIFT);
    s32k_mmio_write32(S32K_SCG_SPLLCSR, S32K_SCG_XCSR_EN);
    if (!poll_set(S32K_SCG_SPLLCSR, S32K_SCG_XCSR_VLD, S32K_SCG_XCSR_VLD)) {
        return INC_ERR_TIMEOUT;
    }
    /* RUN from SPLL: core 160/2 = 80; bus and slow divide the core clock: 80/2 = 40,
     * 80/3 = 26.67 MHz. */
    return switch_to(S32K_SCG_CCR(S32K_SCG_SCS_SPLL, 2u, 2u, 3u));
}

int s32k_clock_init(enum s32k_clock mode, uint32_t *core_hz)
{
    int err;
    uint32_t hz;
    if (mode == S32K_CLOCK_FIRC_48) {
        err = firc_48();
        hz = S32K_FIRC_HZ;
    } else if (mode == S32K_CLOCK_SPLL_80) {
        err = spll_80();
        hz = 80000000u;
        if (err != INC_OK) {
            (void)switch_to(S32K_SCG_CCR(S32K_SCG_SCS_FIRC, 1u, 1u, 2u));
        }
    } else {
        return INC_ERR_INVAL;
    }
    if (err == INC_OK && core_hz != NULL) {
        *core_hz = hz;
    }
    return err;
}

int s32k_pcc_enable(uint32_t pcc_addr, uint32_t pcs)
{
    if ((s32k_mmio_read32(pcc_addr) & S32K_PCC_PR) == 0u) {
        return INC_ERR_UNSUPPORTED;
    }
    s32k_mmio_write32(pcc_addr, 0u); /* gate off: PCS may only change with CGC = 0 */
    s32k_mmio_write32(pcc_addr, (pcs << S32K_PCC_PCS_SHIFT) & S32K_PCC_PCS_MASK);
    s32k_mmio_write32(pcc_addr, ((pcs << S32K_PCC_PCS_SHIFT) & S32K_PCC_PCS_MASK) | S32K_PCC_CGC);
    return INC_OK;
}
