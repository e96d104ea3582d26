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

_Static_assert((uint64_t)S32K_TIME_HZ *S32K_TIME_NS_NUM == 1000000000ull * S32K_TIME_NS_DEN,
               "S32K_TIME_NS_NUM / S32K_TIME_NS_DEN must be the tick in ns");
_Static_assert(S32K_TIME_NS_DEN == 3u && S32K_TIME_NS_NUM == 125u,
               "advance() divides by 3, ns_to_ticks by 125 (s32k_time_div3, _div125)");
_Static_assert((uint64_t)S32K_TIME_CHUNK *S32K_TIME_NS_NUM + S32K_TIME_NS_DEN - 1u <= 0xFFFFFFFFull,
               "one conversion step must fit 32 bits");

int s32k_time_init(struct s32k_time *t, enum s32k_part part)
{
    uint32_t i;
    int err;
    if (t == NULL) {
        return INC_ERR_NULL;
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
    t->ns = 0u;
    t->rem = 0u;
    t->last = 0xFFFFFFFFu;
    t->irq = part == S32K_PART_116 ? S32K116_IRQ_LPIT0 : S32K144_IRQ_LPIT0_CH1;
    s32k_mmio_write32(S32K_NVIC_ISER(t->irq / 32u), 1u << (t->irq % 32u));
    return INC_OK;
}

/*
 * floor(x / 3) for every 32-bit x without a division (libgcc's on the M0+ is a loop of about
 * 100 instructions): x/3 = x * (1/4 + 1/16 + 1/64 + ...), summed by doubling the terms, leaves a
 * remainder r = x - 3q with 0 <= r < 48; 11 * r / 32 is floor(r / 3) for every such r. Tested
 * against the division in tests/s32k1 (edges and a sweep).
 */
uint32_t s32k_time_div3(uint32_t x)
{
    uint32_t q = (x >> 2) + (x >> 4);
    uint32_t r;
    q += q >> 4;
    q += q >> 8;
    q += q >> 16;
    r = x - q * 3u;
    return q + ((11u * r) >> 5);
}

/* Advance by d ticks: ns += (d * NUM + rem) / DEN in steps that fit 32 bits. */
static void advance(struct s32k_time *t, uint32_t d)
{
    t->ticks += d;
    while (d != 0u) {
        const uint32_t step = d < S32K_TIME_CHUNK ? d : S32K_TIME_CHUNK;
        const uint32_t x = step * S32K_TIME_NS_NUM + t->rem;
        const uint32_t q = s32k_time_div3(x);
        t->rem = x - q * S32K_TIME_NS_DEN;
        t->ns += q;
        d -= step;
    }
}

static void update(struct s32k_time *t)
{
    const uint32_t cur = s32k_mmio_read32(S32K_LPIT_CVAL(0));
    advance(t, t->last - cur); /* a down-counter: elapsed = last - now mod 2^32 */
    t->last = cur;
}

uint64_t s32k_time_ticks(struct s32k_time *t)
{
    const uint32_t key = s32k_cpu_irq_save();
    uint64_t ticks;
    update(t);
    ticks = t->ticks;
    s32k_cpu_irq_restore(key);
    return ticks;
}

uint64_t s32k_time_now_ns(struct s32k_time *t)
{
    const uint32_t key = s32k_cpu_irq_save();
    uint64_t ns;
    update(t);
    ns = t->ns;
    s32k_cpu_irq_restore(key);
    return ns;
}

/* The high 32 bits of a * b from four 16 x 16 products (the M0+ has no 32 x 32 -> 64 multiply). */
static uint32_t mulhi32(uint32_t a, uint32_t b)
{
    const uint32_t al = a & 0xFFFFu;
    const uint32_t ah = a >> 16;
    const uint32_t bl = b & 0xFFFFu;
    const uint32_t bh = b >> 16;
    const uint32_t ll = al * bl;
    const uint32_t lh = al * bh;
    const uint32_t hl = ah * bl;
    /* the middle column: each term < 2^32 - 2^17 + 1, and their sum is kept in two parts */
    const uint32_t mid = (ll >> 16) + (lh & 0xFFFFu) + (hl & 0xFFFFu);
    return ah * bh + (lh >> 16) + (hl >> 16) + (mid >> 16);
}

/*
 * floor(x / 125) = floor(x * M / 2^38) with M = ceil(2^38 / 125) = 2199023256 for every
 * x < 2^32: M * 125 - 2^38 = 56 and 56 * 2^32 < 2^38, so the excess never reaches a whole step.
 */
#define DIV125_M 2199023256u
#define DIV125_SHIFT 6u /* 38 - 32 */

uint32_t s32k_time_div125(uint32_t x)
{
    return mulhi32(x, DIV125_M) >> DIV125_SHIFT;
}

uint64_t s32k_time_ns_to_ticks(const struct s32k_time *t, uint32_t ns)
{
    /* ceil(ns * DEN / NUM) = q * DEN + ceil(r * DEN / NUM) with ns = q * NUM + r, r < NUM:
     * r * DEN < NUM * DEN = 375, so the last term is 0 for r = 0 and otherwise 1, 2 or 3. */
    const uint32_t q = s32k_time_div125(ns);
    const uint32_t r = ns - q * S32K_TIME_NS_NUM;
    const uint32_t rd = r * S32K_TIME_NS_DEN;
    (void)t;
    return (uint64_t)q * S32K_TIME_NS_DEN + (rd == 0u     ? 0u
                                             : rd <= 125u ? 1u
                                             : rd <= 250u ? 2u
                                                          : 3u);
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
