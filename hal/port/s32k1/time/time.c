/* time.c - see inclino/s32k_time.h. */
#include "inclino/s32k_time.h"

#include <stddef.h>

#include "inclino/s32k1_regs.h"
#include "inclino/s32k_cpu.h"
#include "inclino/s32k_mmio.h"
#include "inclino/s32k_scg.h"

/* After M_CEN, the channel registers need a few functional-clock cycles before they accept
 * writes: a handful of dummy reads of MCR covers them at any core/LPIT clock ratio here. */
#define LPIT_MCR_SETTLE_READS 8u

int s32k_time_init(struct s32k_time *t, enum s32k_part part)
{
    uint32_t i;
    int err;
    if (t == NULL) {
        return INC_ERR_NULL;
    }
    err = hal_cyc_init(&t->conv, S32K_TIME_HZ);
    if (err != INC_OK) {
        return err;
    }
    err = s32k_pcc_enable(S32K_PCC_LPIT, S32K_PCC_PCS_FIRCDIV2);
    if (err != INC_OK) {
        return err;
    }
    s32k_mmio_write32(S32K_LPIT_MCR, S32K_LPIT_MCR_M_CEN);
    for (i = 0; i < LPIT_MCR_SETTLE_READS; i++) {
        (void)s32k_mmio_read32(S32K_LPIT_MCR);
    }
    s32k_mmio_write32(S32K_LPIT_TCTRL(0), 0u);
    s32k_mmio_write32(S32K_LPIT_TCTRL(1), 0u);
    s32k_mmio_write32(S32K_LPIT_MSR, S32K_LPIT_TIF(0) | S32K_LPIT_TIF(1));
    s32k_mmio_write32(S32K_LPIT_TVAL(0), 0xFFFFFFFFu);
    s32k_mmio_write32(S32K_LPIT_TCTRL(0), S32K_LPIT_TCTRL_T_EN);
    t->ticks = 0u;
    t->last = 0xFFFFFFFFu;
    t->irq = part == S32K_PART_116 ? S32K116_IRQ_LPIT0 : S32K144_IRQ_LPIT0_CH1;
    s32k_mmio_write32(S32K_NVIC_ISER(t->irq / 32u), 1u << (t->irq % 32u));
    return INC_OK;
}

uint64_t s32k_time_ticks(struct s32k_time *t)
{
    uint32_t key = s32k_cpu_irq_save();
    uint32_t cur = s32k_mmio_read32(S32K_LPIT_CVAL(0));
    uint64_t ticks;
    t->ticks += (uint32_t)(t->last - cur); /* a down-counter: elapsed = last - now mod 2^32 */
    t->last = cur;
    ticks = t->ticks;
    s32k_cpu_irq_restore(key);
    return ticks;
}

uint64_t s32k_time_now_ns(struct s32k_time *t)
{
    return hal_cyc_to_ns(&t->conv, s32k_time_ticks(t));
}

uint64_t s32k_time_ns_to_ticks(const struct s32k_time *t, uint32_t ns)
{
    return hal_ns_to_cyc_ceil(&t->conv, ns);
}

void s32k_time_arm(struct s32k_time *t, uint64_t ticks)
{
    uint32_t tval;
    (void)t;
    if (ticks == 0u) {
        ticks = 1u;
    }
    tval = ticks > 0x100000000ull ? 0xFFFFFFFFu : (uint32_t)(ticks - 1u);
    s32k_mmio_write32(S32K_LPIT_TCTRL(1), 0u);
    s32k_mmio_write32(S32K_LPIT_MSR, S32K_LPIT_TIF(1));
    s32k_mmio_write32(S32K_LPIT_TVAL(1), tval);
    s32k_mmio_set32(S32K_LPIT_MIER, S32K_LPIT_TIF(1));
    s32k_mmio_write32(S32K_LPIT_TCTRL(1), S32K_LPIT_TCTRL_T_EN);
}

void s32k_time_disarm(struct s32k_time *t)
{
    (void)t;
    s32k_mmio_write32(S32K_LPIT_TCTRL(1), 0u);
    s32k_mmio_clear32(S32K_LPIT_MIER, S32K_LPIT_TIF(1));
    s32k_mmio_write32(S32K_LPIT_MSR, S32K_LPIT_TIF(1));
}
