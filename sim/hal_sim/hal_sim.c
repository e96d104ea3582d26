/* hal_sim.c - HAL port on the simulated board (see hal_sim.h). */
#include "inclino/hal_sim.h"

#include <string.h>

static void pin_write(void *ctx, hal_pin_t pin, bool level)
{
    struct hal_sim *p = ctx;
    p->pin_writes++;
    sim_pinbus_master_write(p->bus, pin, level);
}

static bool pin_read(void *ctx, hal_pin_t pin)
{
    struct hal_sim *p = ctx;
    p->pin_reads++;
    return sim_pinbus_read(p->bus, pin);
}

static uint64_t now_ns(void *ctx)
{
    const struct hal_sim *p = ctx;
    return p->clk->now_ns;
}

static void delay_ns(void *ctx, uint32_t ns)
{
    struct hal_sim *p = ctx;
    p->delays++;
    if (ns != 0) {
        sim_clock_advance_to(p->clk, p->clk->now_ns + ns);
    }
}

static void run_irq(struct hal_sim_irq *q)
{
    q->pending = false;
    q->port->fired++;
    q->cb(q->arg);
}

static void on_edge(void *arg, unsigned pin, bool level, uint64_t t)
{
    struct hal_sim_irq *q = arg;
    (void)pin;
    (void)t;
    if (q->cb == NULL) {
        return;
    }
    if (!(q->edge & (level ? HAL_EDGE_RISING : HAL_EDGE_FALLING))) {
        return;
    }
    if (q->port->crit_depth > 0) {
        q->pending = true;
    } else {
        run_irq(q);
    }
}

static int irq_attach(void *ctx, hal_pin_t pin, enum hal_edge edge, hal_irq_cb cb, void *arg)
{
    struct hal_sim *p = ctx;
    struct hal_sim_irq *free_slot = NULL;
    unsigned i;
    if (pin >= SIM_PINBUS_MAX_PINS || p->bus->pin[pin].name == NULL ||
        (cb != NULL && (edge < HAL_EDGE_RISING || edge > HAL_EDGE_BOTH))) {
        return INC_ERR_INVAL;
    }
    for (i = 0; i < HAL_SIM_MAX_IRQS; i++) {
        struct hal_sim_irq *q = &p->irq[i];
        if (q->cb != NULL && q->pin == pin) {
            if (cb == NULL) {
                sim_pinbus_unlisten(p->bus, &q->listener);
                q->cb = NULL;
                q->pending = false;
            } else {
                q->edge = edge;
                q->cb = cb;
                q->arg = arg;
            }
            return INC_OK;
        }
        if (q->cb == NULL && free_slot == NULL) {
            free_slot = q;
        }
    }
    if (cb == NULL) {
        return INC_OK;
    }
    if (free_slot == NULL) {
        return INC_ERR_NO_SPACE;
    }
    free_slot->port = p;
    free_slot->pin = pin;
    free_slot->edge = edge;
    free_slot->cb = cb;
    free_slot->arg = arg;
    free_slot->pending = false;
    free_slot->listener.fn = on_edge;
    free_slot->listener.arg = free_slot;
    free_slot->listener.mask = SIM_PIN_MASK(pin);
    return sim_pinbus_listen(p->bus, &free_slot->listener);
}

static int irq_wait(void *ctx, uint64_t deadline_ns)
{
    struct hal_sim *p = ctx;
    for (;;) {
        uint64_t t;
        if (p->fired > 0) {
            p->fired = 0;
            return INC_OK;
        }
        if (p->clk->now_ns >= deadline_ns) {
            return INC_ERR_TIMEOUT;
        }
        if (!sim_clock_next(p->clk, &t) || t > deadline_ns) {
            sim_clock_advance_to(p->clk, deadline_ns);
        } else {
            sim_clock_step(p->clk);
        }
    }
}

static uint32_t crit_enter(void *ctx)
{
    struct hal_sim *p = ctx;
    return p->crit_depth++;
}

static void crit_exit(void *ctx, uint32_t key)
{
    struct hal_sim *p = ctx;
    unsigned i;
    p->crit_depth = key;
    if (p->crit_depth != 0) {
        return;
    }
    for (i = 0; i < HAL_SIM_MAX_IRQS; i++) {
        if (p->irq[i].cb != NULL && p->irq[i].pending) {
            run_irq(&p->irq[i]);
        }
    }
}

static const struct hal_ops hal_sim_ops = {
    .pin_write = pin_write,
    .pin_read = pin_read,
    .now_ns = now_ns,
    .delay_ns = delay_ns,
    .irq_attach = irq_attach,
    .irq_wait = irq_wait,
    .crit_enter = crit_enter,
    .crit_exit = crit_exit,
};

int hal_sim_init(struct hal_sim *port, struct sim_clock *clk, struct sim_pinbus *bus,
                 struct hal *out)
{
    if (port == NULL || clk == NULL || bus == NULL || out == NULL) {
        return INC_ERR_NULL;
    }
    memset(port, 0, sizeof(*port));
    port->clk = clk;
    port->bus = bus;
    out->ops = &hal_sim_ops;
    out->ctx = port;
    return INC_OK;
}

/* ---- the time-only HAL ---- */

static void t_pin_write(void *ctx, hal_pin_t pin, bool level)
{
    struct hal_sim_time *t = ctx;
    (void)pin;
    (void)level;
    t->pin_writes++;
}

static bool t_pin_read(void *ctx, hal_pin_t pin)
{
    (void)ctx;
    (void)pin;
    return false;
}

static uint64_t t_now(void *ctx)
{
    return ((struct hal_sim_time *)ctx)->now_ns;
}

static void t_delay(void *ctx, uint32_t ns)
{
    struct hal_sim_time *t = ctx;
    t->now_ns += ns;
    t->delays++;
}

static int t_attach(void *ctx, hal_pin_t pin, enum hal_edge edge, hal_irq_cb cb, void *arg)
{
    (void)ctx;
    (void)pin;
    (void)edge;
    (void)cb;
    (void)arg;
    return INC_OK;
}

static int t_wait(void *ctx, uint64_t deadline_ns)
{
    struct hal_sim_time *t = ctx;
    t->waits++;
    if (deadline_ns > t->now_ns) {
        t->now_ns = deadline_ns;
    }
    return INC_ERR_TIMEOUT;
}

static uint32_t t_enter(void *ctx)
{
    struct hal_sim_time *t = ctx;
    return t->crit_depth++;
}

static void t_exit(void *ctx, uint32_t key)
{
    struct hal_sim_time *t = ctx;
    t->crit_depth = key;
}

static const struct hal_ops hal_sim_time_ops = {
    .pin_write = t_pin_write,
    .pin_read = t_pin_read,
    .now_ns = t_now,
    .delay_ns = t_delay,
    .irq_attach = t_attach,
    .irq_wait = t_wait,
    .crit_enter = t_enter,
    .crit_exit = t_exit,
};

int hal_sim_time_init(struct hal_sim_time *t, struct hal *out)
{
    if (t == NULL || out == NULL) {
        return INC_ERR_NULL;
    }
    memset(t, 0, sizeof(*t));
    out->ops = &hal_sim_time_ops;
    out->ctx = t;
    return INC_OK;
}
