/*
 * sim/clock.h - the virtual clock of the simulated board.
 *
 * Time is a 64-bit count of nanoseconds that only moves when something asks it to: a HAL delay,
 * a wait for an interrupt, or a test. Nothing sleeps; every run is deterministic. Device models
 * schedule events (a data-ready pulse, the end of a busy period, a delayed MISO change) at
 * absolute times; advancing the clock fires them in time order, ties in the order they were
 * scheduled. An event may schedule further events, including at the current time.
 *
 * The queue has a fixed size (SIM_CLOCK_MAX_EVENTS); scheduling into a full queue fails with
 * INC_ERR_NO_SPACE and sets the sticky `overflowed` flag, which tests check.
 */
#ifndef INCLINO_SIM_CLOCK_H
#define INCLINO_SIM_CLOCK_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/error.h"

#ifdef __cplusplus
extern "C" {
#endif

#ifndef SIM_CLOCK_MAX_EVENTS
#define SIM_CLOCK_MAX_EVENTS 64
#endif

/* Event callback: runs with the clock's now == its scheduled time. */
typedef void (*sim_event_fn)(void *arg, uint64_t now_ns);

struct sim_event {
    uint64_t t_ns;
    uint32_t seq; /* scheduling order, breaks ties */
    uint32_t id;  /* handle returned to the scheduler; 0 = free slot */
    sim_event_fn fn;
    void *arg;
};

struct sim_clock {
    uint64_t now_ns;
    uint32_t next_seq;
    uint32_t next_id;
    bool overflowed; /* a schedule call found the queue full */
    unsigned count;  /* events pending */
    unsigned hi;     /* slots [hi, MAX) are free: bounds the scans */
    struct sim_event ev[SIM_CLOCK_MAX_EVENTS];
};

void sim_clock_init(struct sim_clock *clk);

/*
 * Schedule fn(arg) at absolute time t_ns (a time in the past runs at the next advance, at the
 * current time). Returns a positive handle, or INC_ERR_NULL / INC_ERR_NO_SPACE.
 */
int sim_clock_schedule(struct sim_clock *clk, uint64_t t_ns, sim_event_fn fn, void *arg);

/* Cancel a pending event by handle. Returns 0, or INC_ERR_INVAL when it is not pending. */
int sim_clock_cancel(struct sim_clock *clk, int handle);

/* Time of the earliest pending event; false when none is pending. */
bool sim_clock_next(const struct sim_clock *clk, uint64_t *t_ns);

/*
 * Advance to t_ns (no-op when t_ns <= now), firing every event due at or before t_ns in order;
 * the clock reads each event's time while it runs, then t_ns.
 */
void sim_clock_advance_to(struct sim_clock *clk, uint64_t t_ns);

/* Fire the earliest pending event (advancing to its time). Returns false when none is pending. */
bool sim_clock_step(struct sim_clock *clk);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_SIM_CLOCK_H */
