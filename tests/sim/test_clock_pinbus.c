/* Virtual clock (ordering, ties, cancel, full queue) and pin bus (drivers, pulls, listeners). */
#include "inclino/sim/clock.h"
#include "inclino/sim/pinbus.h"
#include "unit.h"

#include <string.h>

static struct sim_clock clk;
static char order[32];
static unsigned n_order;
static uint64_t fired_at[32];

static void ev(void *arg, uint64_t now)
{
    const char *tag = arg;
    if (n_order < 31u) {
        fired_at[n_order] = now;
        order[n_order++] = tag[0];
        order[n_order] = 0;
    }
}

static void ev_reschedule(void *arg, uint64_t now)
{
    (void)arg;
    ev("R", now);
    /* An event may schedule another one at the current time: it runs in the same advance. */
    sim_clock_schedule(&clk, now, ev, "N");
}

static void test_clock_order_and_ties(void)
{
    uint64_t t;
    sim_clock_init(&clk);
    n_order = 0;
    order[0] = 0;
    CHECK(!sim_clock_next(&clk, &t));
    CHECK(sim_clock_schedule(&clk, 300, ev, "c") > 0);
    CHECK(sim_clock_schedule(&clk, 100, ev, "a") > 0);
    CHECK(sim_clock_schedule(&clk, 200, ev, "b") > 0);
    CHECK(sim_clock_schedule(&clk, 200, ev, "B") > 0); /* tie: after "b" */
    CHECK(sim_clock_next(&clk, &t));
    CHECK_EQ_INT(t, 100);
    sim_clock_advance_to(&clk, 250);
    CHECK(strcmp(order, "abB") == 0);
    CHECK_EQ_INT(fired_at[0], 100);
    CHECK_EQ_INT(fired_at[2], 200);
    CHECK_EQ_INT(clk.now_ns, 250);
    sim_clock_advance_to(&clk, 100); /* never backwards */
    CHECK_EQ_INT(clk.now_ns, 250);
    CHECK(sim_clock_step(&clk));
    CHECK_EQ_INT(clk.now_ns, 300);
    CHECK(strcmp(order, "abBc") == 0);
    CHECK(!sim_clock_step(&clk));
    /* Past times run at the current time. */
    CHECK(sim_clock_schedule(&clk, 5, ev, "p") > 0);
    sim_clock_advance_to(&clk, 300);
    CHECK_EQ_INT(fired_at[4], 300);
    CHECK(sim_clock_schedule(&clk, 400, ev_reschedule, NULL) > 0);
    sim_clock_advance_to(&clk, 400);
    CHECK(strcmp(order, "abBcpRN") == 0);
    CHECK_EQ_INT(clk.count, 0);
}

static void test_clock_cancel_and_full(void)
{
    int h, i, last = 0;
    sim_clock_init(&clk);
    n_order = 0;
    order[0] = 0;
    h = sim_clock_schedule(&clk, 10, ev, "x");
    CHECK(h > 0);
    CHECK_OK(sim_clock_cancel(&clk, h));
    CHECK_ERR(sim_clock_cancel(&clk, h), INC_ERR_INVAL);
    CHECK_ERR(sim_clock_cancel(&clk, 0), INC_ERR_INVAL);
    sim_clock_advance_to(&clk, 20);
    CHECK_EQ_INT(n_order, 0);
    for (i = 0; i < (int)SIM_CLOCK_MAX_EVENTS; i++) {
        last = sim_clock_schedule(&clk, 100u + (unsigned)i, ev, "f");
    }
    CHECK(last > 0);
    CHECK(!clk.overflowed);
    CHECK_ERR(sim_clock_schedule(&clk, 1000, ev, "g"), INC_ERR_NO_SPACE);
    CHECK(clk.overflowed);
    CHECK_ERR(sim_clock_schedule(NULL, 1, ev, "g"), INC_ERR_NULL);
    CHECK_ERR(sim_clock_schedule(&clk, 1, NULL, NULL), INC_ERR_NULL);
    sim_clock_advance_to(&clk, 1000);
    CHECK_EQ_INT(n_order, 31); /* recorder keeps 31; all ran: */
    CHECK_EQ_INT(clk.count, 0);
    CHECK_EQ_INT(clk.hi, 0);
}

/* --- pin bus --- */
static struct sim_pinbus bus;
static struct sim_violation_log log_;
static unsigned changes[4];
static bool last_level[4];
static uint64_t last_t;

static void on_change(void *arg, unsigned pin, bool level, uint64_t t)
{
    (void)arg;
    if (pin < 4u) {
        changes[pin]++;
        last_level[pin] = level;
    }
    last_t = t;
}

static void test_pinbus_resolution(void)
{
    struct sim_pin_listener l = {on_change, NULL,
                                 SIM_PIN_MASK(0) | SIM_PIN_MASK(1) | SIM_PIN_MASK(2), NULL};
    int d0, d1;
    sim_clock_init(&clk);
    sim_violation_log_init(&log_);
    sim_pinbus_init(&bus, &clk, &log_);
    memset(changes, 0, sizeof(changes));
    CHECK_OK(sim_pinbus_define(&bus, 0, "up", SIM_PULL_UP, false));
    CHECK_OK(sim_pinbus_define(&bus, 1, "down", SIM_PULL_DOWN, true));
    CHECK_OK(sim_pinbus_define(&bus, 2, "keep", SIM_PULL_KEEPER, true));
    CHECK_ERR(sim_pinbus_define(&bus, SIM_PINBUS_MAX_PINS, "x", SIM_PULL_UP, false), INC_ERR_INVAL);
    CHECK_ERR(sim_pinbus_define(&bus, 3, NULL, SIM_PULL_UP, false), INC_ERR_NULL);
    CHECK_OK(sim_pinbus_listen(&bus, &l));
    CHECK_ERR(sim_pinbus_listen(&bus, &l), INC_ERR_STATE);
    CHECK(sim_pinbus_read(&bus, 0));
    CHECK(!sim_pinbus_read(&bus, 1));
    CHECK(sim_pinbus_read(&bus, 2));
    CHECK(!sim_pinbus_read(&bus, 3)); /* undefined */
    CHECK_EQ_INT(sim_pinbus_find(&bus, "keep"), 2);
    CHECK_EQ_INT(sim_pinbus_find(&bus, "nope"), -1);

    d0 = sim_pinbus_add_device(&bus);
    d1 = sim_pinbus_add_device(&bus);
    CHECK_EQ_INT(d0, 0);
    CHECK_EQ_INT(d1, 1);
    clk.now_ns = 77;
    sim_pinbus_device_drive(&bus, (unsigned)d0, 0, false);
    CHECK(!sim_pinbus_read(&bus, 0));
    CHECK_EQ_INT(changes[0], 1);
    CHECK_EQ_INT(last_t, 77);
    sim_pinbus_device_drive(&bus, (unsigned)d0, 0, false); /* same level: no event */
    CHECK_EQ_INT(changes[0], 1);
    sim_pinbus_device_release(&bus, (unsigned)d0, 0); /* pull-up again */
    CHECK(sim_pinbus_read(&bus, 0));
    CHECK_EQ_INT(changes[0], 2);
    /* Keeper holds the last driven level. */
    sim_pinbus_device_drive(&bus, (unsigned)d1, 2, false);
    sim_pinbus_device_release(&bus, (unsigned)d1, 2);
    CHECK(!sim_pinbus_read(&bus, 2));
    /* Two devices disagreeing: contention, reads 0. */
    CHECK_EQ_INT(log_.total, 0);
    sim_pinbus_device_drive(&bus, (unsigned)d0, 1, true);
    CHECK(sim_pinbus_read(&bus, 1));
    sim_pinbus_device_drive(&bus, (unsigned)d1, 1, false);
    CHECK(!sim_pinbus_read(&bus, 1));
    CHECK_EQ_INT(sim_violation_count(&log_, SIM_VIOL_CONTENTION), 1);
    /* Master overrides, and is reported when a device disagrees. */
    sim_pinbus_device_release(&bus, (unsigned)d0, 1);
    sim_pinbus_device_release(&bus, (unsigned)d1, 1);
    sim_pinbus_master_write(&bus, 1, true);
    CHECK(sim_pinbus_read(&bus, 1));
    CHECK_EQ_INT(sim_violation_count(&log_, SIM_VIOL_CONTENTION), 1);
    sim_pinbus_master_release(&bus, 1);
    CHECK(!sim_pinbus_read(&bus, 1));
    CHECK_OK(sim_pinbus_unlisten(&bus, &l));
    CHECK_ERR(sim_pinbus_unlisten(&bus, &l), INC_ERR_INVAL);
    sim_pinbus_master_write(&bus, 1, true);
    CHECK_EQ_INT(changes[1], 4); /* the last change was not heard */
    while (sim_pinbus_add_device(&bus) >= 0) {
    }
    CHECK_EQ_INT(bus.devices, SIM_PINBUS_MAX_DEVICES);
}

int main(void)
{
    UNIT_RUN(test_clock_order_and_ties);
    UNIT_RUN(test_clock_cancel_and_full);
    UNIT_RUN(test_pinbus_resolution);
    return unit_report();
}
