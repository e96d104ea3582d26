/* hal.c - port-independent helpers of the HAL (see hal.h). */
#include "inclino/hal.h"

int hal_check(const struct hal *hal)
{
    const struct hal_ops *o;
    if (hal == NULL || hal->ops == NULL) {
        return INC_ERR_NULL;
    }
    o = hal->ops;
    if (o->pin_write == NULL || o->pin_read == NULL || o->now_ns == NULL || o->delay_ns == NULL ||
        o->irq_attach == NULL || o->irq_wait == NULL || o->crit_enter == NULL ||
        o->crit_exit == NULL) {
        return INC_ERR_NULL;
    }
    return INC_OK;
}

void hal_delay_ms(const struct hal *hal, uint32_t ms)
{
    /* delay_ns takes at most ~4.29 s; wait in 1 s pieces. */
    while (ms >= 1000u) {
        hal_delay_ns(hal, 1000000000u);
        ms -= 1000u;
    }
    if (ms > 0u) {
        hal_delay_ns(hal, ms * 1000000u);
    }
}

void hal_delay_until(const struct hal *hal, uint64_t t_ns)
{
    uint64_t now = hal_now_ns(hal);
    while (now < t_ns) {
        uint64_t left = t_ns - now;
        hal_delay_ns(hal, left > 1000000000u ? 1000000000u : (uint32_t)left);
        now = hal_now_ns(hal);
    }
}
