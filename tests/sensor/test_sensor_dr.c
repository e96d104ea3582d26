/*
 * sensor_dr: the data-ready edge counting every driver shares (drivers/sensor). A scripted HAL
 * here: a clock that only irq_wait moves, edges at scripted times delivered through the attached
 * handler, "foreign" wake-ups (another part's interrupt) and a check that every critical section
 * is left. Integer only: it also runs on rv32imac.
 */
#include "inclino/sensor.h"
#include "unit.h"

#define MAX_EV 8

struct fake {
    uint64_t now;
    uint64_t ev_t[MAX_EV]; /* scripted events, ascending */
    bool ev_foreign[MAX_EV];
    unsigned n_ev, next_ev;
    hal_irq_cb cb;
    void *arg;
    int crit_depth, crit_max;
    unsigned waits;
};

static void f_pin_write(void *ctx, hal_pin_t pin, bool level)
{
    (void)ctx;
    (void)pin;
    (void)level;
}

static bool f_pin_read(void *ctx, hal_pin_t pin)
{
    (void)ctx;
    (void)pin;
    return false;
}

static uint64_t f_now(void *ctx)
{
    return ((struct fake *)ctx)->now;
}

static void f_delay(void *ctx, uint32_t ns)
{
    ((struct fake *)ctx)->now += ns;
}

static int f_attach(void *ctx, hal_pin_t pin, enum hal_edge edge, hal_irq_cb cb, void *arg)
{
    struct fake *f = ctx;
    (void)pin;
    (void)edge;
    f->cb = cb;
    f->arg = arg;
    return INC_OK;
}

/* The next scripted event at or before the deadline: an edge runs the handler, a foreign
 * wake-up only returns. None: the clock goes to the deadline. */
static int f_wait(void *ctx, uint64_t deadline)
{
    struct fake *f = ctx;
    f->waits++;
    if (f->next_ev < f->n_ev && f->ev_t[f->next_ev] <= deadline) {
        const unsigned i = f->next_ev++;
        if (f->ev_t[i] > f->now) {
            f->now = f->ev_t[i];
        }
        if (!f->ev_foreign[i] && f->cb != NULL) {
            f->cb(f->arg);
        }
        return INC_OK;
    }
    if (deadline > f->now) {
        f->now = deadline;
    }
    return INC_ERR_TIMEOUT;
}

static uint32_t f_enter(void *ctx)
{
    struct fake *f = ctx;
    f->crit_depth++;
    if (f->crit_depth > f->crit_max) {
        f->crit_max = f->crit_depth;
    }
    return (uint32_t)f->crit_depth;
}

static void f_exit(void *ctx, uint32_t key)
{
    struct fake *f = ctx;
    CHECK_EQ_INT((int)key, f->crit_depth);
    f->crit_depth--;
}

static const struct hal_ops fake_ops = {f_pin_write, f_pin_read, f_now,   f_delay,
                                        f_attach,    f_wait,     f_enter, f_exit};

static struct fake fk;
static struct hal hal = {&fake_ops, &fk};
static struct sensor_dr dr;

static void setup(void)
{
    struct fake zero = {0};
    fk = zero;
    sensor_dr_reset(&dr);
    CHECK_EQ_INT(hal_irq_attach(&hal, 0, HAL_EDGE_FALLING, sensor_dr_isr, &dr), INC_OK);
}

static void script(uint64_t t, bool foreign)
{
    fk.ev_t[fk.n_ev] = t;
    fk.ev_foreign[fk.n_ev] = foreign;
    fk.n_ev++;
}

static void test_timeout(void)
{
    uint32_t pending = 99;
    setup();
    fk.now = 1000;
    CHECK_EQ_INT(sensor_dr_wait(&hal, &dr, 5000, &pending), INC_ERR_TIMEOUT);
    CHECK_EQ_INT(fk.now, 5000u);
    CHECK_EQ_INT(pending, 0u);
    CHECK_EQ_INT(fk.crit_depth, 0);
    /* deadline already past: no sleep at all */
    fk.waits = 0;
    CHECK_EQ_INT(sensor_dr_wait(&hal, &dr, 10, &pending), INC_ERR_TIMEOUT);
    CHECK_EQ_INT(fk.waits, 0u);
    CHECK_EQ_INT(fk.now, 5000u);
}

static void test_edges(void)
{
    uint32_t pending = 0;
    setup();
    /* an edge during the wait: taken at its time */
    script(700, false);
    CHECK_EQ_INT(sensor_dr_wait(&hal, &dr, 2000, &pending), INC_OK);
    CHECK_EQ_INT(pending, 1u);
    CHECK_EQ_INT(fk.now, 700u);
    /* three edges while nobody waited: all consumed at once, no sleep, reported as 3 */
    sensor_dr_isr(&dr);
    sensor_dr_isr(&dr);
    sensor_dr_isr(&dr);
    fk.waits = 0;
    CHECK_EQ_INT(sensor_dr_wait(&hal, &dr, 2000, &pending), INC_OK);
    CHECK_EQ_INT(pending, 3u);
    CHECK_EQ_INT(fk.waits, 0u);
    /* consumed: the next wait times out */
    CHECK_EQ_INT(sensor_dr_wait(&hal, &dr, 2000, &pending), INC_ERR_TIMEOUT);
    CHECK_EQ_INT(pending, 0u);
    /* an edge exactly at the deadline is taken */
    script(3000, false);
    CHECK_EQ_INT(sensor_dr_wait(&hal, &dr, 3000, &pending), INC_OK);
    CHECK_EQ_INT(pending, 1u);
    /* just after the deadline: not taken by this wait, taken by the next */
    script(4001, false);
    CHECK_EQ_INT(sensor_dr_wait(&hal, &dr, 4000, &pending), INC_ERR_TIMEOUT);
    CHECK_EQ_INT(sensor_dr_wait(&hal, &dr, 5000, &pending), INC_OK);
    CHECK_EQ_INT(pending, 1u);
    CHECK_EQ_INT(fk.now, 4001u);
    CHECK_EQ_INT(fk.crit_depth, 0);
    CHECK_EQ_INT(fk.crit_max, 1);
}

static void test_foreign_wakeups(void)
{
    uint32_t pending = 0;
    setup();
    /* two wake-ups by another part's interrupt, then ours: the wait sleeps again each time */
    script(100, true);
    script(200, true);
    script(300, false);
    CHECK_EQ_INT(sensor_dr_wait(&hal, &dr, 1000, &pending), INC_OK);
    CHECK_EQ_INT(pending, 1u);
    CHECK_EQ_INT(fk.now, 300u);
    CHECK_EQ_INT(fk.waits, 3u);
    /* only foreign wake-ups: a timeout at the deadline */
    script(400, true);
    CHECK_EQ_INT(sensor_dr_wait(&hal, &dr, 1000, &pending), INC_ERR_TIMEOUT);
    CHECK_EQ_INT(fk.now, 1000u);
}

static void test_sync_and_wrap(void)
{
    uint32_t pending = 0;
    setup();
    sensor_dr_isr(&dr);
    sensor_dr_isr(&dr);
    sensor_dr_sync(&hal, &dr);
    CHECK_EQ_INT(sensor_dr_wait(&hal, &dr, 10, &pending), INC_ERR_TIMEOUT);
    CHECK_EQ_INT(dr.count, 2u);
    CHECK_EQ_INT(dr.taken, 2u);
    /* the counter wraps: count - taken still counts the edges */
    dr.count = 0xFFFFFFFEu;
    dr.taken = 0xFFFFFFFEu;
    sensor_dr_isr(&dr);
    sensor_dr_isr(&dr);
    sensor_dr_isr(&dr);
    CHECK_EQ_INT(dr.count, 1u);
    CHECK_EQ_INT(sensor_dr_wait(&hal, &dr, 10, &pending), INC_OK);
    CHECK_EQ_INT(pending, 3u);
    CHECK_EQ_INT(dr.taken, 1u);
}

static void test_bad_args(void)
{
    uint32_t pending = 7;
    setup();
    CHECK_EQ_INT(sensor_dr_wait(NULL, &dr, 10, &pending), INC_ERR_NULL);
    CHECK_EQ_INT(pending, 0u);
    CHECK_EQ_INT(sensor_dr_wait(&hal, NULL, 10, &pending), INC_ERR_NULL);
    CHECK_EQ_INT(sensor_dr_wait(&hal, &dr, 10, NULL), INC_ERR_TIMEOUT); /* pending may be NULL */
    sensor_dr_isr(NULL);                                                /* no effect, no crash */
    sensor_dr_sync(NULL, &dr);
    sensor_dr_sync(&hal, NULL);
    sensor_dr_reset(NULL);
    CHECK_EQ_INT(fk.crit_depth, 0);
}

int main(void)
{
    UNIT_RUN(test_timeout);
    UNIT_RUN(test_edges);
    UNIT_RUN(test_foreign_wakeups);
    UNIT_RUN(test_sync_and_wrap);
    UNIT_RUN(test_bad_args);
    return unit_report();
}
