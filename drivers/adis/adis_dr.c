/*
 * adis_dr.c - data-ready edge counting shared by the ADIS drivers (adis.h).
 */
#include "inclino/adis.h"

void adis_dr_reset(struct adis_dr *dr)
{
    if (dr != NULL) {
        dr->count = 0;
        dr->taken = 0;
    }
}

void adis_dr_isr(void *arg)
{
    struct adis_dr *dr = arg;
    if (dr != NULL) {
        dr->count = dr->count + 1u;
    }
}

/* Edges not yet consumed; consumes them. */
static uint32_t take(const struct hal *hal, struct adis_dr *dr)
{
    const uint32_t key = hal_crit_enter(hal);
    const uint32_t n = dr->count - dr->taken;
    dr->taken = dr->taken + n;
    hal_crit_exit(hal, key);
    return n;
}

void adis_dr_sync(const struct hal *hal, struct adis_dr *dr)
{
    if (hal != NULL && dr != NULL) {
        (void)take(hal, dr);
    }
}

int adis_dr_wait(const struct hal *hal, struct adis_dr *dr, uint64_t deadline_ns, uint32_t *pending)
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
