/* s32k_hal.c - see inclino/s32k_hal.h. */
#include "inclino/s32k_hal.h"

#include <stddef.h>

#include "inclino/s32k_cpu.h"
#include "inclino/s32k_gpio.h"
#include "inclino/s32k_wdog.h"

static void p_pin_write(void *ctx, hal_pin_t pin, bool level)
{
    (void)ctx;
    s32k_gpio_write(pin, level);
}

static bool p_pin_read(void *ctx, hal_pin_t pin)
{
    (void)ctx;
    return s32k_gpio_read(pin);
}

static uint64_t p_now_ns(void *ctx)
{
    struct s32k_hal *p = ctx;
    return s32k_time_now_ns(&p->time);
}

static void poll_until(struct s32k_hal *p, uint64_t end_ticks)
{
    while (s32k_time_ticks(&p->time) < end_ticks) {
    }
}

void s32k_hal_delay_ns(struct s32k_hal *p, uint32_t ns)
{
    uint64_t end;
    uint32_t key;
#if !defined(INCLINO_S32K_MMIO_SIM)
    if (ns <= S32K_HAL_SPIN_MAX_NS) {
        s32k_hal_short_run(p, s32k_hal_short_prep(p, ns));
        return;
    }
#endif
    end = s32k_time_ticks(&p->time) + s32k_time_ns_to_ticks(&p->time, ns) + 1u;
    key = s32k_cpu_irq_save();
    if ((key & 1u) == 0u && ns > S32K_HAL_SPIN_MAX_NS) {
        /* Sleep until S32K_HAL_SPIN_MAX_NS before the end, then poll. */
        const uint64_t tail = s32k_time_ns_to_ticks(&p->time, S32K_HAL_SPIN_MAX_NS);
        for (;;) {
            const uint64_t now = s32k_time_ticks(&p->time);
            if (now + tail >= end) {
                break;
            }
            if (p->cfg.watchdog) {
                s32k_wdog_refresh();
            }
            s32k_time_arm(&p->time, end - tail - now);
            s32k_cpu_wfi();
            s32k_time_disarm(&p->time);
        }
    }
    s32k_cpu_irq_restore(key);
    poll_until(p, end);
}

static void p_delay_ns(void *ctx, uint32_t ns)
{
    s32k_hal_delay_ns(ctx, ns);
}

static uint32_t p_crit_enter(void *ctx)
{
    (void)ctx;
    return s32k_cpu_irq_save();
}

static void p_crit_exit(void *ctx, uint32_t key)
{
    (void)ctx;
    s32k_cpu_irq_restore(key);
}

static int p_irq_attach(void *ctx, hal_pin_t pin, enum hal_edge edge, hal_irq_cb cb, void *arg)
{
    struct s32k_hal *p = ctx;
    struct s32k_hal_irq_slot *slot = NULL;
    uint32_t key;
    size_t i;
    int err;
    if (!S32K_PIN_VALID(pin) ||
        (edge != HAL_EDGE_RISING && edge != HAL_EDGE_FALLING && edge != HAL_EDGE_BOTH)) {
        return INC_ERR_INVAL;
    }
    for (i = 0; i < S32K_HAL_IRQ_SLOTS; i++) {
        if (p->irq[i].pin == pin) {
            slot = &p->irq[i];
            break;
        }
        if (slot == NULL && p->irq[i].pin == HAL_PIN_NONE) {
            slot = &p->irq[i];
        }
    }
    if (cb == NULL) {
        if (slot == NULL || slot->pin != pin) {
            return INC_OK;
        }
        err = s32k_gpio_irq_enable(p->cfg.part, pin, edge, false);
        key = s32k_cpu_irq_save();
        slot->pin = HAL_PIN_NONE;
        slot->cb = NULL;
        slot->arg = NULL;
        s32k_cpu_irq_restore(key);
        return err;
    }
    if (slot == NULL) {
        return INC_ERR_NO_SPACE;
    }
    key = s32k_cpu_irq_save();
    slot->pin = pin;
    slot->cb = cb;
    slot->arg = arg;
    s32k_cpu_irq_restore(key);
    err = s32k_gpio_irq_enable(p->cfg.part, pin, edge, true);
    if (err != INC_OK) {
        key = s32k_cpu_irq_save();
        slot->pin = HAL_PIN_NONE;
        slot->cb = NULL;
        s32k_cpu_irq_restore(key);
    }
    return err;
}

void s32k_hal_port_isr(struct s32k_hal *p, uint32_t port)
{
    uint32_t flags;
    size_t i;
    if (p == NULL) {
        return;
    }
    flags = s32k_gpio_isr(port);
    for (i = 0; i < S32K_HAL_IRQ_SLOTS && flags != 0u; i++) {
        const hal_pin_t pin = p->irq[i].pin;
        if (pin != HAL_PIN_NONE && S32K_PIN_PORT(pin) == port && p->irq[i].cb != NULL &&
            (flags & (1u << S32K_PIN_BIT(pin))) != 0u) {
            p->irq[i].cb(p->irq[i].arg);
            p->irq_count++;
        }
    }
}

void s32k_hal_lpit_isr(struct s32k_hal *p)
{
    if (p != NULL) {
        s32k_time_disarm(&p->time);
    }
}

void s32k_hal_wake(struct s32k_hal *p)
{
    if (p != NULL) {
        p->irq_count++;
    }
}

static int p_irq_wait(void *ctx, uint64_t deadline_ns)
{
    struct s32k_hal *p = ctx;
    for (;;) {
        const uint32_t key = s32k_cpu_irq_save();
        uint64_t now;
        if ((key & 1u) != 0u) {
            return INC_ERR_STATE; /* inside a critical section no interrupt can be taken */
        }
        if (p->cfg.watchdog) {
            s32k_wdog_refresh();
        }
        if (p->irq_count != p->irq_seen) {
            p->irq_seen = p->irq_count;
            s32k_cpu_irq_restore(key);
            return INC_OK;
        }
        now = s32k_time_now_ns(&p->time);
        if (now >= deadline_ns) {
            s32k_cpu_irq_restore(key);
            return INC_ERR_TIMEOUT;
        }
        if (deadline_ns - now > S32K_HAL_SPIN_MAX_NS) {
            /* WFI with PRIMASK set: a pending edge wakes the core and is taken at the restore
             * below, after the check above; LPIT0 channel 1 wakes it before the deadline. */
            const uint64_t rem = deadline_ns - now - S32K_HAL_SPIN_MAX_NS;
            const uint32_t rem32 = rem > 0xFFFFFFFFull ? 0xFFFFFFFFu : (uint32_t)rem;
            s32k_time_arm(&p->time, s32k_time_ns_to_ticks(&p->time, rem32));
            s32k_cpu_wfi();
            s32k_time_disarm(&p->time);
        }
        s32k_cpu_irq_restore(key);
    }
}

static const struct hal_ops s32k_hal_ops = {
    p_pin_write,  p_pin_read, p_now_ns,     p_delay_ns,
    p_irq_attach, p_irq_wait, p_crit_enter, p_crit_exit,
};

uint32_t s32k_hal_loop_q16(uint32_t core_hz)
{
    return (uint32_t)((((uint64_t)core_hz << 16) / 1000000000u + 1u) / S32K_HAL_LOOP_CYCLES) + 1u;
}

int s32k_hal_init(struct s32k_hal *p, const struct s32k_hal_config *cfg, struct hal *hal)
{
    size_t i;
    int err;
    if (p == NULL || cfg == NULL || hal == NULL) {
        return INC_ERR_NULL;
    }
    if ((cfg->part != S32K_PART_144 && cfg->part != S32K_PART_116) ||
        cfg->core_hz < S32K_HAL_CORE_HZ_MIN || cfg->core_hz > S32K_HAL_CORE_HZ_MAX) {
        return INC_ERR_INVAL;
    }
    p->cfg = *cfg;
    /* core cycles per ns in Q16.16, divided by the cycles of one loop turn */
    p->loop_q16 = s32k_hal_loop_q16(cfg->core_hz);
    for (i = 0; i < S32K_HAL_IRQ_SLOTS; i++) {
        p->irq[i].pin = HAL_PIN_NONE;
        p->irq[i].cb = NULL;
        p->irq[i].arg = NULL;
    }
    p->irq_count = 0u;
    p->irq_seen = 0u;
    err = s32k_time_init(&p->time, cfg->part);
    if (err != INC_OK) {
        return err;
    }
    hal->ops = &s32k_hal_ops;
    hal->ctx = p;
    return INC_OK;
}
