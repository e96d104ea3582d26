/* The simulated HAL port: virtual time, delays, interrupts, critical sections. */
#include "inclino/hal.h"
#include "inclino/hal_sim.h"
#include "inclino/sim/board.h"
#include "unit.h"

#include <string.h>

static struct sim_board b;
static unsigned irq_count;
static uint64_t irq_time;

static void on_irq(void *arg)
{
    (void)arg;
    irq_count++;
    irq_time = b.clk.now_ns;
}

/* A pulse on dr0 from t to t + 100 ns, driven by a "device". */
static int dev_id;
static void pulse_on(void *arg, uint64_t now)
{
    (void)arg;
    (void)now;
    sim_pinbus_device_drive(&b.bus, (unsigned)dev_id, SIM_BOARD_DR(0), true);
}

static void pulse_off(void *arg, uint64_t now)
{
    (void)arg;
    (void)now;
    sim_pinbus_device_drive(&b.bus, (unsigned)dev_id, SIM_BOARD_DR(0), false);
}

static void schedule_pulse(uint64_t t)
{
    sim_clock_schedule(&b.clk, t, pulse_on, NULL);
    sim_clock_schedule(&b.clk, t + 100u, pulse_off, NULL);
}

static void test_time_and_delay(void)
{
    REQUIRE(sim_board_init(&b) == 0);
    CHECK_OK(hal_check(&b.hal));
    CHECK_EQ_INT(hal_now_ns(&b.hal), 0);
    hal_delay_ns(&b.hal, 1234);
    CHECK_EQ_INT(hal_now_ns(&b.hal), 1234);
    hal_delay_ms(&b.hal, 2500); /* in pieces of 1 s */
    CHECK_EQ_INT(hal_now_ns(&b.hal), 1234u + 2500000000ull);
    hal_delay_until(&b.hal, 5000000000ull);
    CHECK_EQ_INT(hal_now_ns(&b.hal), 5000000000ull);
    hal_delay_until(&b.hal, 1); /* past: no wait */
    CHECK_EQ_INT(hal_now_ns(&b.hal), 5000000000ull);
    hal_pin_write(&b.hal, SIM_BOARD_CS(0), false);
    CHECK(!hal_pin_read(&b.hal, SIM_BOARD_CS(0)));
    CHECK(hal_pin_read(&b.hal, SIM_BOARD_MISO)); /* pull-up */
}

static void test_irq_wait(void)
{
    REQUIRE(sim_board_init(&b) == 0);
    dev_id = sim_pinbus_add_device(&b.bus);
    irq_count = 0;
    CHECK_OK(hal_irq_attach(&b.hal, SIM_BOARD_DR(0), HAL_EDGE_RISING, on_irq, NULL));
    schedule_pulse(10000);
    schedule_pulse(30000);
    /* The wait advances virtual time straight to the first edge. */
    CHECK_OK(hal_irq_wait(&b.hal, 1000000));
    CHECK_EQ_INT(irq_count, 1);
    CHECK_EQ_INT(irq_time, 10000);
    CHECK_EQ_INT(hal_now_ns(&b.hal), 10000);
    CHECK_OK(hal_irq_wait(&b.hal, 1000000));
    CHECK_EQ_INT(irq_time, 30000);
    /* Nothing more scheduled: the deadline passes. */
    CHECK_ERR(hal_irq_wait(&b.hal, 50000), INC_ERR_TIMEOUT);
    CHECK_EQ_INT(hal_now_ns(&b.hal), 50000);
    /* An interrupt during a delay is not lost: the next wait returns at once. */
    schedule_pulse(60000);
    hal_delay_ns(&b.hal, 20000);
    CHECK_EQ_INT(irq_time, 60000);
    CHECK_OK(hal_irq_wait(&b.hal, 1000000));
    CHECK_EQ_INT(hal_now_ns(&b.hal), 70000);
    /* Falling edge only. */
    CHECK_OK(hal_irq_attach(&b.hal, SIM_BOARD_DR(0), HAL_EDGE_FALLING, on_irq, NULL));
    schedule_pulse(100000);
    CHECK_OK(hal_irq_wait(&b.hal, 1000000));
    CHECK_EQ_INT(irq_time, 100100);
    /* Detach. */
    CHECK_OK(hal_irq_attach(&b.hal, SIM_BOARD_DR(0), HAL_EDGE_RISING, NULL, NULL));
    schedule_pulse(200000);
    CHECK_ERR(hal_irq_wait(&b.hal, 300000), INC_ERR_TIMEOUT);
    CHECK_EQ_INT(irq_count, 4);
    /* Errors */
    CHECK_ERR(hal_irq_attach(&b.hal, 31, HAL_EDGE_RISING, on_irq, NULL), INC_ERR_INVAL);
    CHECK_ERR(hal_irq_attach(&b.hal, 200, HAL_EDGE_RISING, on_irq, NULL), INC_ERR_INVAL);
    CHECK_ERR(hal_irq_attach(&b.hal, SIM_BOARD_DR(1), (enum hal_edge)0, on_irq, NULL),
              INC_ERR_INVAL);
}

static void test_critical_section_defers(void)
{
    uint32_t k1, k2;
    REQUIRE(sim_board_init(&b) == 0);
    dev_id = sim_pinbus_add_device(&b.bus);
    irq_count = 0;
    CHECK_OK(hal_irq_attach(&b.hal, SIM_BOARD_DR(0), HAL_EDGE_RISING, on_irq, NULL));
    schedule_pulse(1000);
    k1 = hal_crit_enter(&b.hal);
    k2 = hal_crit_enter(&b.hal);
    hal_delay_ns(&b.hal, 5000);
    CHECK_EQ_INT(irq_count, 0);
    hal_crit_exit(&b.hal, k2);
    CHECK_EQ_INT(irq_count, 0); /* still inside the outer section */
    hal_crit_exit(&b.hal, k1);
    CHECK_EQ_INT(irq_count, 1);
    CHECK_EQ_INT(irq_time, 5000); /* ran when the section ended */
}

static void test_hal_check(void)
{
    struct hal h;
    struct hal_ops ops;
    REQUIRE(sim_board_init(&b) == 0);
    CHECK_ERR(hal_check(NULL), INC_ERR_NULL);
    h.ops = NULL;
    h.ctx = NULL;
    CHECK_ERR(hal_check(&h), INC_ERR_NULL);
    ops = *b.hal.ops;
    ops.irq_wait = NULL;
    h.ops = &ops;
    CHECK_ERR(hal_check(&h), INC_ERR_NULL);
    CHECK_ERR(hal_sim_init(NULL, &b.clk, &b.bus, &h), INC_ERR_NULL);
    CHECK_ERR(hal_sim_init(&b.port, NULL, &b.bus, &h), INC_ERR_NULL);
}

int main(void)
{
    UNIT_RUN(test_time_and_delay);
    UNIT_RUN(test_irq_wait);
    UNIT_RUN(test_critical_section_defers);
    UNIT_RUN(test_hal_check);
    return unit_report();
}
