/*
 * sensor_dr.c - data-ready edge counting, the one helper of every driver (inclino/sensor.h).
 */
#include "inclino/sensor.h"

void sensor_dr_reset(struct sensor_dr *dr)
{
    if (dr != NULL) {
        dr->count = 0;
        dr->taken = 0;
    }
}

void sensor_dr_isr(void *arg)
{
    struct sensor_dr *dr = arg;
    if (dr != NULL) {
        dr->count = dr->count + 1u;
    }
}

/* Edges not yet consumed; consumes them. */
static uint32_t take(const struct hal *hal, struct sensor_dr *dr)
{
    const uint32_t key = hal_crit_enter(hal);
    const uint32_t n = dr->count - dr->taken;
    dr->taken = dr->taken + n;
    hal_crit_exit(hal, key);
    return n;
}

void sensor_dr_sync(const struct hal *hal, struct sensor_dr *dr)
{
    if (hal != NULL && dr != NULL) {
        (void)take(hal, dr);
    }
}

int sensor_dr_wait(const struct hal *hal, struct sensor_dr *dr, uint64_t deadline_ns,
                   uint32_t *pending)
{
    uint32_t n = 0;
    int err = INC_OK;
    if (hal == NULL || dr == NULL) {
        err = INC_ERR_NULL;
    } else {
        for (;;) {
            n = take(hal, dr);
            if (n != 0u) {
                break;
            }
            if (hal_now_ns(hal) >= deadline_ns) {
                err = INC_ERR_TIMEOUT;
                break;
            }
            (void)hal_irq_wait(hal, deadline_ns);
        }
    }
    if (pending != NULL) {
        *pending = n;
    }
    return err;
}
