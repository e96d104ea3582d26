/*
 * hal_cortex_m.c - see hal_cortex_m.h.
 *
 * Register addresses and bits: ARMv7-M Architecture Reference Manual (DDI 0403E) B3.2 (System
 * Control Space), B3.3 (SysTick), C1.8 (DWT); ARMv6-M ARM (DDI 0419) B3 for the M0+, which has
 * the same SCS and SysTick registers and no DWT cycle counter.
 */
#include "inclino/hal_cortex_m.h"

#include <stddef.h>

#define CM_REG(addr) (*(volatile uint32_t *)(addr))

#define CM_ICSR CM_REG(0xE000ED04u)  /* Interrupt Control and State */
#define CM_ICSR_PENDSTSET (1u << 26) /* SysTick exception pending (read) */
#define CM_ICSR_PENDSTCLR (1u << 25) /* clear it (write) */

#define CM_SYST_CSR CM_REG(0xE000E010u) /* SysTick control and status */
#define CM_SYST_RVR CM_REG(0xE000E014u) /* reload value */
#define CM_SYST_CVR CM_REG(0xE000E018u) /* current value; any write clears it */
#define CM_SYST_CSR_ENABLE (1u << 0)
#define CM_SYST_CSR_TICKINT (1u << 1)
#define CM_SYST_CSR_CLKSOURCE (1u << 2) /* 1 = processor clock */
#define CM_SYST_MAX 0x00FFFFFFu         /* 24-bit counter: period 2^24 cycles */

#define CM_DEMCR CM_REG(0xE000EDFCu) /* Debug Exception and Monitor Control */
#define CM_DEMCR_TRCENA (1u << 24)   /* enables the DWT */
#define CM_DWT_CTRL CM_REG(0xE0001000u)
#define CM_DWT_CTRL_CYCCNTENA (1u << 0)
#define CM_DWT_CTRL_NOCYCCNT (1u << 25) /* the counter is not implemented */
#define CM_DWT_CYCCNT CM_REG(0xE0001004u)

/* The instance whose wraps SysTick_Handler counts (the last one initialised in SysTick mode). */
static struct hal_cm *volatile hal_cm_systick_owner;

static uint32_t cm_irq_save(void)
{
    uint32_t primask;
    __asm volatile("mrs %0, primask\n\tcpsid i" : "=r"(primask) : : "memory");
    return primask;
}

static void cm_irq_restore(uint32_t primask)
{
    /* Re-enable only if interrupts were enabled at the matching save: sections nest. */
    if ((primask & 1u) == 0u) {
        __asm volatile("cpsie i" : : : "memory");
    }
}

/*
 * 64-bit cycle count. SysTick: wraps counts the counter's transitions to 0, the moment its
 * exception becomes pending, so the cycles of the running period are (MAX + 1 - CVR) mod 2^24
 * (CVR == 0 is the first cycle of the next period). Read with interrupts masked: if the wrap
 * is pending, its handler has not counted it - maybe it cannot run because the caller holds a
 * critical section - so count it here and withdraw the request; CVR is read again because the
 * first read may precede the wrap. One read per 2^24 cycles keeps this exact in any critical
 * section.
 */
static uint64_t cm_cycles(struct hal_cm *cm)
{
    uint32_t key = cm_irq_save();
    uint64_t cycles;
    if (cm->cfg.timebase == HAL_CM_TIME_SYSTICK) {
        uint32_t cvr = CM_SYST_CVR;
        if ((CM_ICSR & CM_ICSR_PENDSTSET) != 0u) {
            CM_ICSR = CM_ICSR_PENDSTCLR;
            cm->wraps++;
            cvr = CM_SYST_CVR;
        }
        cycles = (cm->wraps << 24) + ((CM_SYST_MAX + 1u - cvr) & CM_SYST_MAX);
    } else {
        uint32_t c = CM_DWT_CYCCNT;
        if (c < cm->dwt_last) {
            cm->wraps++;
        }
        cm->dwt_last = c;
        cycles = (cm->wraps << 32) | c;
    }
    cm_irq_restore(key);
    return cycles;
}

void SysTick_Handler(void)
{
    /* Masked: a higher-priority handler calling now_ns() must not see half an increment. */
    uint32_t key = cm_irq_save();
    struct hal_cm *cm = hal_cm_systick_owner;
    if (cm != NULL) {
        cm->wraps++;
    }
    cm_irq_restore(key);
}

static void cm_pin_write(void *ctx, hal_pin_t pin, bool level)
{
    struct hal_cm *cm = ctx;
    cm->cfg.gpio->write(cm->cfg.gpio_ctx, pin, level);
}

static bool cm_pin_read(void *ctx, hal_pin_t pin)
{
    struct hal_cm *cm = ctx;
    return cm->cfg.gpio->read(cm->cfg.gpio_ctx, pin);
}

static uint64_t cm_now_ns(void *ctx)
{
    struct hal_cm *cm = ctx;
    return hal_cyc_to_ns(&cm->conv, cm_cycles(cm));
}

static void cm_delay_ns(void *ctx, uint32_t ns)
{
    struct hal_cm *cm = ctx;
    /*
     * One cycle more than the ceiling: the start sample may be taken at the very end of a
     * cycle, so a difference of n counts only guarantees more than n - 1 whole cycles.
     */
    uint64_t need = hal_ns_to_cyc_ceil(&cm->conv, ns) + 1u;
    uint64_t start = cm_cycles(cm);
    while (cm_cycles(cm) - start < need) {
    }
}

static uint32_t cm_crit_enter(void *ctx)
{
    (void)ctx;
    return cm_irq_save();
}

static void cm_crit_exit(void *ctx, uint32_t key)
{
    (void)ctx;
    cm_irq_restore(key);
}

static int cm_irq_attach(void *ctx, hal_pin_t pin, enum hal_edge edge, hal_irq_cb cb, void *arg)
{
    struct hal_cm *cm = ctx;
    struct hal_cm_irq_slot *slot = NULL;
    uint32_t key;
    size_t i;
    int err;

    if (pin == HAL_PIN_NONE ||
        (edge != HAL_EDGE_RISING && edge != HAL_EDGE_FALLING && edge != HAL_EDGE_BOTH)) {
        return INC_ERR_INVAL;
    }
    for (i = 0; i < HAL_CM_IRQ_SLOTS; i++) {
        if (cm->irq[i].pin == pin) {
            slot = &cm->irq[i];
            break;
        }
        if (slot == NULL && cm->irq[i].pin == HAL_PIN_NONE) {
            slot = &cm->irq[i];
        }
    }
    if (cb == NULL) {
        /* Detach: stop the interrupt first, then free the slot. */
        if (slot == NULL || slot->pin != pin) {
            return INC_OK;
        }
        err = cm->cfg.gpio->irq_enable(cm->cfg.gpio_ctx, pin, slot->edge, false);
        key = cm_irq_save();
        slot->pin = HAL_PIN_NONE;
        slot->cb = NULL;
        slot->arg = NULL;
        cm_irq_restore(key);
        return err;
    }
    if (slot == NULL) {
        return INC_ERR_NO_SPACE;
    }
    /* Fill the slot before enabling, so an edge that fires at once finds its callback. */
    key = cm_irq_save();
    {
        struct hal_cm_irq_slot old = *slot;
        slot->pin = pin;
        slot->edge = edge;
        slot->cb = cb;
        slot->arg = arg;
        cm_irq_restore(key);
        err = cm->cfg.gpio->irq_enable(cm->cfg.gpio_ctx, pin, edge, true);
        if (err != INC_OK) {
            key = cm_irq_save();
            *slot = old;
            cm_irq_restore(key);
        }
    }
    return err;
}

void hal_cm_irq_dispatch(struct hal_cm *cm, hal_pin_t pin)
{
    size_t i;
    if (cm == NULL) {
        return;
    }
    for (i = 0; i < HAL_CM_IRQ_SLOTS; i++) {
        if (cm->irq[i].pin == pin && cm->irq[i].cb != NULL) {
            cm->irq[i].cb(cm->irq[i].arg);
            cm->irq_count++;
            return;
        }
    }
}

static int cm_irq_wait(void *ctx, uint64_t deadline_ns)
{
    struct hal_cm *cm = ctx;
    for (;;) {
        uint32_t key = cm_irq_save();
        uint64_t now;
        if ((key & 1u) != 0u) {
            /* The caller holds a critical section: no interrupt could ever be taken. */
            return INC_ERR_STATE;
        }
        if (cm->irq_count != cm->irq_seen) {
            cm->irq_seen = cm->irq_count;
            cm_irq_restore(key);
            return INC_OK;
        }
        now = hal_cyc_to_ns(&cm->conv, cm_cycles(cm));
        if (now >= deadline_ns) {
            cm_irq_restore(key);
            return INC_ERR_TIMEOUT;
        }
        /*
         * WFI with PRIMASK set: an interrupt that becomes pending wakes the core but is taken
         * only at cm_irq_restore, after the check above, so none is lost between check and
         * sleep (ARMv7-M ARM B1.5.19). The SysTick wrap wakes it at least once per period; near
         * the deadline, poll instead so the timeout is not a whole period late.
         */
        if (cm->cfg.timebase == HAL_CM_TIME_SYSTICK && deadline_ns - now > cm->sleep_min_ns) {
            __asm volatile("dsb\n\twfi" : : : "memory");
        }
        cm_irq_restore(key);
    }
}

static const struct hal_ops hal_cm_ops = {
    cm_pin_write,  cm_pin_read, cm_now_ns,     cm_delay_ns,
    cm_irq_attach, cm_irq_wait, cm_crit_enter, cm_crit_exit,
};

static void none_write(void *ctx, hal_pin_t pin, bool level)
{
    (void)ctx;
    (void)pin;
    (void)level;
}

static bool none_read(void *ctx, hal_pin_t pin)
{
    (void)ctx;
    (void)pin;
    return false;
}

static int none_irq_enable(void *ctx, hal_pin_t pin, enum hal_edge edge, bool enable)
{
    (void)ctx;
    (void)pin;
    (void)edge;
    (void)enable;
    return INC_ERR_UNSUPPORTED;
}

const struct hal_cm_gpio_ops hal_cm_gpio_none = {none_write, none_read, none_irq_enable};

#if !defined(__ARM_ARCH_6M__)
/* Start DWT CYCCNT; INC_ERR_UNSUPPORTED when absent or not counting (QEMU reads it as 0). */
static int cm_dwt_start(void)
{
    volatile uint32_t spin;
    uint32_t c0;
    CM_DEMCR |= CM_DEMCR_TRCENA;
    if ((CM_DWT_CTRL & CM_DWT_CTRL_NOCYCCNT) != 0u) {
        return INC_ERR_UNSUPPORTED;
    }
    CM_DWT_CYCCNT = 0u;
    CM_DWT_CTRL |= CM_DWT_CTRL_CYCCNTENA;
    c0 = CM_DWT_CYCCNT;
    for (spin = 0u; spin < 64u; spin++) {
    }
    if (CM_DWT_CYCCNT == c0) {
        CM_DWT_CTRL &= ~CM_DWT_CTRL_CYCCNTENA;
        return INC_ERR_UNSUPPORTED;
    }
    return INC_OK;
}
#endif

int hal_cm_init(struct hal_cm *cm, const struct hal_cm_config *cfg, struct hal *hal)
{
    struct hal_cyc_conv conv;
    size_t i;
    int err;

    if (cm == NULL || cfg == NULL || hal == NULL || cfg->gpio == NULL || cfg->gpio->write == NULL ||
        cfg->gpio->read == NULL || cfg->gpio->irq_enable == NULL) {
        return INC_ERR_NULL;
    }
    if (cfg->timebase != HAL_CM_TIME_SYSTICK && cfg->timebase != HAL_CM_TIME_DWT) {
        return INC_ERR_INVAL;
    }
    err = hal_cyc_init(&conv, cfg->core_hz);
    if (err != INC_OK) {
        return err;
    }
    if (cfg->timebase == HAL_CM_TIME_DWT) {
#if defined(__ARM_ARCH_6M__)
        return INC_ERR_UNSUPPORTED; /* ARMv6-M has no cycle counter */
#else
        err = cm_dwt_start();
        if (err != INC_OK) {
            return err;
        }
#endif
    }

    if (hal_cm_systick_owner == cm) {
        hal_cm_systick_owner = NULL; /* re-initialising: no wrap counting while we set up */
    }
    cm->cfg = *cfg;
    cm->conv = conv;
    cm->wraps = 0u;
    cm->dwt_last = 0u;
    cm->sleep_min_ns = hal_cyc_to_ns(&conv, (uint64_t)CM_SYST_MAX + 1u);
    for (i = 0; i < HAL_CM_IRQ_SLOTS; i++) {
        cm->irq[i].pin = HAL_PIN_NONE;
        cm->irq[i].edge = HAL_EDGE_RISING;
        cm->irq[i].cb = NULL;
        cm->irq[i].arg = NULL;
    }
    cm->irq_count = 0u;
    cm->irq_seen = 0u;

    if (cfg->timebase == HAL_CM_TIME_SYSTICK) {
        uint32_t key = cm_irq_save();
        CM_SYST_CSR = 0u;
        CM_SYST_RVR = CM_SYST_MAX;
        CM_SYST_CVR = 0u; /* clears the counter and COUNTFLAG */
        CM_ICSR = CM_ICSR_PENDSTCLR;
        hal_cm_systick_owner = cm;
        CM_SYST_CSR = CM_SYST_CSR_CLKSOURCE | CM_SYST_CSR_TICKINT | CM_SYST_CSR_ENABLE;
        cm_irq_restore(key);
    }

    hal->ops = &hal_cm_ops;
    hal->ctx = cm;
    return INC_OK;
}
