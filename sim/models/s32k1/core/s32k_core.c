/* s32k_core.c - see inclino/sim/s32k_core.h. */
#include "inclino/sim/s32k_core.h"

#include <stddef.h>
#include <string.h>

#include "inclino/s32k1_regs.h"
#include "inclino/s32k_cpu.h"
#include "inclino/sim/s32k_bus.h"

static struct sim_s32k_core *the_core;

struct sim_s32k_core *sim_s32k_core_get(void)
{
    return the_core;
}

static bool deliverable(const struct sim_s32k_core *c, unsigned *irq)
{
    unsigned w;
    for (w = 0; w < SIM_S32K_IRQS / 32u; w++) {
        const uint32_t m = c->pending[w] & c->enabled[w];
        if (m != 0u) {
            unsigned b = 0;
            while ((m & (1u << b)) == 0u) {
                b++;
            }
            *irq = w * 32u + b;
            return true;
        }
    }
    return false;
}

static void deliver(struct sim_s32k_core *c)
{
    unsigned irq;
    while (!c->primask && c->isr_depth == 0u && deliverable(c, &irq)) {
        c->pending[irq / 32u] &= ~(1u << (irq % 32u));
        if (c->isr[irq] != NULL) {
            c->isr_depth++;
            s32k_bus_meter_leave(); /* the handler is firmware */
            c->isr[irq](c->isr_arg[irq]);
            s32k_bus_meter_enter();
            c->isr_depth--;
            c->delivered++;
        }
    }
}

void sim_s32k_core_set_handler(struct sim_s32k_core *c, unsigned irq, sim_s32k_isr fn, void *arg)
{
    if (c != NULL && irq < SIM_S32K_IRQS) {
        c->isr[irq] = fn;
        c->isr_arg[irq] = arg;
    }
}

void sim_s32k_core_raise(struct sim_s32k_core *c, unsigned irq)
{
    if (c == NULL || irq >= SIM_S32K_IRQS) {
        return;
    }
    c->pending[irq / 32u] |= 1u << (irq % 32u);
    deliver(c);
}

/* ---- the cpu seam ---- */

uint32_t s32k_cpu_irq_save(void)
{
    struct sim_s32k_core *c = the_core;
    uint32_t old;
    if (c == NULL) {
        return 1u;
    }
    s32k_bus_meter_enter();
    old = c->primask ? 1u : 0u;
    c->primask = true;
    s32k_bus_meter_leave();
    return old;
}

void s32k_cpu_irq_restore(uint32_t primask)
{
    struct sim_s32k_core *c = the_core;
    s32k_bus_meter_enter();
    if (c != NULL && (primask & 1u) == 0u) {
        c->primask = false;
        deliver(c);
    }
    s32k_bus_meter_leave();
}

void s32k_cpu_wfi(void)
{
    struct sim_s32k_core *c = the_core;
    unsigned irq;
    if (c == NULL) {
        return;
    }
    s32k_bus_meter_enter(); /* asleep: no firmware instruction runs */
    while (!deliverable(c, &irq)) {
        if (!sim_clock_step(c->clk)) {
            break;
        }
    }
    s32k_bus_meter_leave();
}

/* ---- NVIC registers (0xE000E100 .. 0xE000E2FF) ---- */

#define NVIC_BASE 0xE000E100u

static uint32_t nvic_read(void *ctx, uint32_t off, unsigned width)
{
    struct sim_s32k_core *c = ctx;
    const unsigned n = (off & 0x7Fu) / 4u;
    (void)width;
    if (n >= SIM_S32K_IRQS / 32u) {
        return 0u;
    }
    switch (off & ~0x7Fu) {
    case 0x000u: /* ISER */
    case 0x080u: /* ICER */ return c->enabled[n];
    case 0x100u: /* ISPR */
    case 0x180u: /* ICPR */ return c->pending[n];
    default: return 0u;
    }
}

static void nvic_write(void *ctx, uint32_t off, uint32_t v, unsigned width)
{
    struct sim_s32k_core *c = ctx;
    const unsigned n = (off & 0x7Fu) / 4u;
    (void)width;
    if (n >= SIM_S32K_IRQS / 32u) {
        return;
    }
    switch (off & ~0x7Fu) {
    case 0x000u: c->enabled[n] |= v; break;
    case 0x080u: c->enabled[n] &= ~v; break;
    case 0x100u: c->pending[n] |= v; break;
    case 0x180u: c->pending[n] &= ~v; break;
    default: break;
    }
    deliver(c);
}

static const struct s32k_bus_region_ops nvic_ops = {nvic_read, nvic_write};

/* ---- SCG ---- */

static uint32_t scg_read(void *ctx, uint32_t off, unsigned width)
{
    struct sim_s32k_core *c = ctx;
    (void)width;
    return c->scg[(off & 0xFFFu) / 4u];
}

static void scg_write(void *ctx, uint32_t off, uint32_t v, unsigned width)
{
    struct sim_s32k_core *c = ctx;
    const uint32_t i = (off & 0xFFFu) / 4u;
    (void)width;
    if (off == (S32K_SCG_CSR - S32K_SCG_BASE)) {
        return; /* read only */
    }
    if (off == (S32K_SCG_SOSCCSR - S32K_SCG_BASE) || off == (S32K_SCG_SPLLCSR - S32K_SCG_BASE) ||
        off == (S32K_SCG_FIRCCSR - S32K_SCG_BASE) || off == (S32K_SCG_SIRCCSR - S32K_SCG_BASE)) {
        /* enable -> valid at once; keep the selected bit the CSR switch maintains */
        const uint32_t sel = c->scg[i] & S32K_SCG_XCSR_SEL;
        c->scg[i] = (v & (S32K_SCG_XCSR_EN | S32K_SCG_XCSR_LK)) | sel |
                    ((v & S32K_SCG_XCSR_EN) != 0u ? S32K_SCG_XCSR_VLD : 0u);
        return;
    }
    c->scg[i] = v;
    if (off == (S32K_SCG_RCCR - S32K_SCG_BASE)) {
        c->scg[(S32K_SCG_CSR - S32K_SCG_BASE) / 4u] = v;
    }
}

static const struct s32k_bus_region_ops scg_ops = {scg_read, scg_write};

/* ---- PCC ---- */

static uint32_t pcc_read(void *ctx, uint32_t off, unsigned width)
{
    struct sim_s32k_core *c = ctx;
    (void)width;
    return c->pcc[(off & 0xFFFu) / 4u] | S32K_PCC_PR;
}

static void pcc_write(void *ctx, uint32_t off, uint32_t v, unsigned width)
{
    struct sim_s32k_core *c = ctx;
    (void)width;
    c->pcc[(off & 0xFFFu) / 4u] = v & ~S32K_PCC_PR;
}

static const struct s32k_bus_region_ops pcc_ops = {pcc_read, pcc_write};

/* ---- WDOG ---- */

static uint64_t wdog_timeout_ns(const struct sim_s32k_core *c)
{
    const uint64_t hz = (c->wdog_cs & S32K_WDOG_CS_PRES) != 0u ? S32K_WDOG_LPO_HZ / 256u
                                                               : S32K_WDOG_LPO_HZ;
    return (uint64_t)c->wdog_toval * 1000000000ull / hz;
}

static uint32_t wdog_read(void *ctx, uint32_t off, unsigned width)
{
    struct sim_s32k_core *c = ctx;
    (void)width;
    if (off == 0u) {
        return c->wdog_cs | (c->wdog_unlocked ? S32K_WDOG_CS_ULK : 0u);
    }
    if (off == 8u) {
        return c->wdog_toval;
    }
    if (off == 12u) {
        return c->wdog_win;
    }
    return 0u;
}

static void wdog_write(void *ctx, uint32_t off, uint32_t v, unsigned width)
{
    struct sim_s32k_core *c = ctx;
    (void)width;
    if (off == 4u) {
        if (v == S32K_WDOG_UNLOCK_KEY) {
            c->wdog_unlocked = true;
        } else if (v == S32K_WDOG_REFRESH_KEY) {
            const uint64_t now = c->clk->now_ns;
            if ((c->wdog_cs & S32K_WDOG_CS_EN) != 0u &&
                now - c->wdog_last_ns > wdog_timeout_ns(c)) {
                c->wdog_bites++;
            }
            c->wdog_last_ns = now;
            c->wdog_refreshes++;
        }
        return;
    }
    if (!c->wdog_unlocked) {
        return; /* locked: the write is ignored (on the part: a reset) */
    }
    if (off == 0u) {
        c->wdog_cs = (v & ~(S32K_WDOG_CS_ULK | S32K_WDOG_CS_FLG)) | S32K_WDOG_CS_RCS;
        c->wdog_unlocked = false;
        c->wdog_configs++;
        c->wdog_last_ns = c->clk->now_ns;
    } else if (off == 8u) {
        c->wdog_toval = v & 0xFFFFu;
    } else if (off == 12u) {
        c->wdog_win = v & 0xFFFFu;
    }
}

static const struct s32k_bus_region_ops wdog_ops = {wdog_read, wdog_write};

int sim_s32k_core_init(struct sim_s32k_core *c, struct sim_clock *clk)
{
    int err;
    if (c == NULL || clk == NULL) {
        return INC_ERR_NULL;
    }
    memset(c, 0, sizeof(*c));
    c->clk = clk;
    /* Reset state: FIRC on, valid and selected (CSR.SCS = FIRC). */
    c->scg[(S32K_SCG_FIRCCSR - S32K_SCG_BASE) / 4u] = S32K_SCG_XCSR_EN | S32K_SCG_XCSR_VLD |
                                                      S32K_SCG_XCSR_SEL;
    c->scg[(S32K_SCG_CSR - S32K_SCG_BASE) / 4u] = S32K_SCG_CCR(S32K_SCG_SCS_FIRC, 1u, 1u, 2u);
    c->scg[(S32K_SCG_RCCR - S32K_SCG_BASE) / 4u] = S32K_SCG_CCR(S32K_SCG_SCS_FIRC, 1u, 1u, 2u);
    c->wdog_cs = S32K_WDOG_CS_EN | S32K_WDOG_CS_CLK_LPO | S32K_WDOG_CS_CMD32EN |
                 S32K_WDOG_CS_UPDATE;
    c->wdog_toval = 0x0500u;
    err = s32k_bus_map(NVIC_BASE, 0x200u, &nvic_ops, c);
    if (err == INC_OK) {
        err = s32k_bus_map(S32K_SCG_BASE, 0x1000u, &scg_ops, c);
    }
    if (err == INC_OK) {
        err = s32k_bus_map(S32K_PCC_BASE, 0x1000u, &pcc_ops, c);
    }
    if (err == INC_OK) {
        err = s32k_bus_map(S32K_WDOG_BASE, 0x10u, &wdog_ops, c);
    }
    if (err == INC_OK) {
        the_core = c;
    }
    return err;
}
