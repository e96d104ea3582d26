/* clock.c - virtual clock and event queue (see sim/clock.h). */
#include "inclino/sim/clock.h"

#include <stddef.h>

void sim_clock_init(struct sim_clock *clk)
{
    unsigned i;
    if (clk == NULL) {
        return;
    }
    clk->now_ns = 0;
    clk->next_seq = 0;
    clk->next_id = 1;
    clk->overflowed = false;
    clk->count = 0;
    clk->hi = 0;
    for (i = 0; i < SIM_CLOCK_MAX_EVENTS; i++) {
        clk->ev[i].id = 0;
        clk->ev[i].fn = NULL;
        clk->ev[i].arg = NULL;
        clk->ev[i].t_ns = 0;
        clk->ev[i].seq = 0;
    }
}

int sim_clock_schedule(struct sim_clock *clk, uint64_t t_ns, sim_event_fn fn, void *arg)
{
    unsigned i;
    if (clk == NULL || fn == NULL) {
        return INC_ERR_NULL;
    }
    for (i = 0; i < SIM_CLOCK_MAX_EVENTS; i++) {
        if (clk->ev[i].id == 0) {
            struct sim_event *e = &clk->ev[i];
            e->t_ns = t_ns < clk->now_ns ? clk->now_ns : t_ns;
            e->seq = clk->next_seq++;
            e->id = clk->next_id++;
            if (clk->next_id > (uint32_t)INT32_MAX) {
                clk->next_id = 1;
            }
            e->fn = fn;
            e->arg = arg;
            clk->count++;
            if (i + 1u > clk->hi) {
                clk->hi = i + 1u;
            }
            return (int)e->id;
        }
    }
    clk->overflowed = true;
    return INC_ERR_NO_SPACE;
}

static void release(struct sim_clock *clk, unsigned i)
{
    clk->ev[i].id = 0;
    clk->count--;
    while (clk->hi > 0 && clk->ev[clk->hi - 1u].id == 0) {
        clk->hi--;
    }
}

int sim_clock_cancel(struct sim_clock *clk, int handle)
{
    unsigned i;
    if (clk == NULL) {
        return INC_ERR_NULL;
    }
    if (handle <= 0) {
        return INC_ERR_INVAL;
    }
    for (i = 0; i < clk->hi; i++) {
        if (clk->ev[i].id == (uint32_t)handle) {
            release(clk, i);
            return INC_OK;
        }
    }
    return INC_ERR_INVAL;
}

/* Index of the earliest pending event (time, then scheduling order), or -1. */
static int earliest(const struct sim_clock *clk)
{
    int best = -1;
    unsigned i;
    if (clk->count == 0) {
        return -1;
    }
    for (i = 0; i < clk->hi; i++) {
        const struct sim_event *e = &clk->ev[i];
        if (e->id == 0) {
            continue;
        }
        if (best < 0 || e->t_ns < clk->ev[best].t_ns ||
            (e->t_ns == clk->ev[best].t_ns && (int32_t)(e->seq - clk->ev[best].seq) < 0)) {
            best = (int)i;
        }
    }
    return best;
}

bool sim_clock_next(const struct sim_clock *clk, uint64_t *t_ns)
{
    int i;
    if (clk == NULL) {
        return false;
    }
    i = earliest(clk);
    if (i < 0) {
        return false;
    }
    if (t_ns != NULL) {
        *t_ns = clk->ev[i].t_ns;
    }
    return true;
}

static void fire(struct sim_clock *clk, int i)
{
    struct sim_event e = clk->ev[i];
    release(clk, (unsigned)i); /* free the slot first: the callback may schedule again */
    if (e.t_ns > clk->now_ns) {
        clk->now_ns = e.t_ns;
    }
    e.fn(e.arg, clk->now_ns);
}

void sim_clock_advance_to(struct sim_clock *clk, uint64_t t_ns)
{
    if (clk == NULL) {
        return;
    }
    for (;;) {
        int i = earliest(clk);
        if (i < 0 || clk->ev[i].t_ns > t_ns) {
            break;
        }
        fire(clk, i);
    }
    if (t_ns > clk->now_ns) {
        clk->now_ns = t_ns;
    }
}

bool sim_clock_step(struct sim_clock *clk)
{
    int i;
    if (clk == NULL) {
        return false;
    }
    i = earliest(clk);
    if (i < 0) {
        return false;
    }
    fire(clk, i);
    return true;
}
