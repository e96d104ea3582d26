/*
 * The generic Cortex-M HAL port under QEMU (mps2-an385 for M0+/M3, mps2-an386 for M4F; both
 * clock the core, SysTick and the CMSDK timers at 25 MHz). QEMU-specific on purpose: QEMU's DWT
 * cycle counter reads 0, so DWT mode must report INC_ERR_UNSUPPORTED here, and TIMER0 (IRQ 8)
 * stands in for an MCU family's pin interrupt. Without -icount, QEMU's clock follows the host's,
 * so only lower bounds on elapsed time are asserted.
 */
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "inclino/hal.h"
#include "inclino/hal_cortex_m.h"
#include "unit.h"

#define QEMU_CORE_HZ 25000000u
#define MS 1000000ull

/* The fake MCU family: pins in RAM, a log of irq_enable calls. */
struct fake_gpio {
    bool level[16];
    int enable_calls;
    hal_pin_t last_pin;
    enum hal_edge last_edge;
    bool last_enable;
};

static void fake_write(void *ctx, hal_pin_t pin, bool level)
{
    struct fake_gpio *g = ctx;
    if (pin < 16u) {
        g->level[pin] = level;
    }
}

static bool fake_read(void *ctx, hal_pin_t pin)
{
    const struct fake_gpio *g = ctx;
    return pin < 16u && g->level[pin];
}

static int fake_irq_enable(void *ctx, hal_pin_t pin, enum hal_edge edge, bool enable)
{
    struct fake_gpio *g = ctx;
    if (pin >= 16u) {
        return INC_ERR_INVAL; /* this "family" can interrupt on pins 0..15 only */
    }
    g->enable_calls++;
    g->last_pin = pin;
    g->last_edge = edge;
    g->last_enable = enable;
    return INC_OK;
}

static const struct hal_cm_gpio_ops fake_ops = {fake_write, fake_read, fake_irq_enable};

static struct hal_cm cm;
static struct fake_gpio gpio;
static struct hal hal;

static int init_systick(void)
{
    struct hal_cm_config cfg = {QEMU_CORE_HZ, HAL_CM_TIME_SYSTICK, &fake_ops, &gpio};
    return hal_cm_init(&cm, &cfg, &hal);
}

static uint32_t primask(void)
{
    uint32_t v;
    __asm volatile("mrs %0, primask" : "=r"(v));
    return v & 1u;
}

static void test_init_errors(void)
{
    struct hal h = {NULL, NULL};
    struct hal_cm_config cfg = {QEMU_CORE_HZ, HAL_CM_TIME_SYSTICK, &fake_ops, &gpio};
    static const struct hal_cm_gpio_ops no_read = {fake_write, NULL, fake_irq_enable};
    CHECK_ERR(hal_cm_init(NULL, &cfg, &h), INC_ERR_NULL);
    CHECK_ERR(hal_cm_init(&cm, NULL, &h), INC_ERR_NULL);
    CHECK_ERR(hal_cm_init(&cm, &cfg, NULL), INC_ERR_NULL);
    cfg.gpio = NULL;
    CHECK_ERR(hal_cm_init(&cm, &cfg, &h), INC_ERR_NULL);
    cfg.gpio = &no_read;
    CHECK_ERR(hal_cm_init(&cm, &cfg, &h), INC_ERR_NULL);
    cfg.gpio = &fake_ops;
    cfg.core_hz = 999999u;
    CHECK_ERR(hal_cm_init(&cm, &cfg, &h), INC_ERR_INVAL);
    cfg.core_hz = 1000000001u;
    CHECK_ERR(hal_cm_init(&cm, &cfg, &h), INC_ERR_INVAL);
    cfg.core_hz = QEMU_CORE_HZ;
    cfg.timebase = (enum hal_cm_timebase)7;
    CHECK_ERR(hal_cm_init(&cm, &cfg, &h), INC_ERR_INVAL);
    CHECK(h.ops == NULL); /* untouched on error */
}

/* QEMU's DWT does not count; the M0+ has none: either way DWT mode must refuse. */
static void test_dwt_unsupported_under_qemu(void)
{
    struct hal h = {NULL, NULL};
    struct hal_cm_config cfg = {QEMU_CORE_HZ, HAL_CM_TIME_DWT, &fake_ops, &gpio};
    CHECK_ERR(hal_cm_init(&cm, &cfg, &h), INC_ERR_UNSUPPORTED);
    CHECK(h.ops == NULL);
}

static void test_systick_init_fills_hal(void)
{
    REQUIRE(init_systick() == 0);
    CHECK_OK(hal_check(&hal));
    CHECK(hal.ctx == &cm);
}

/* Monotonic over more than two SysTick periods (2^24 cycles = 671 ms at 25 MHz). */
static void test_time_is_monotonic_across_wraps(void)
{
    uint64_t start, prev, now;
    uint32_t reads = 0u, backwards = 0u;
    REQUIRE(init_systick() == 0);
    start = prev = hal_now_ns(&hal);
    do {
        now = hal_now_ns(&hal);
        if (now < prev) {
            backwards++;
        }
        prev = now;
        reads++;
    } while (now - start < 1500u * MS);
    CHECK_EQ_INT(backwards, 0);
    CHECK(reads > 1000u);
    CHECK(cm.wraps >= 2u);
}

/*
 * A critical section longer than a SysTick period: the wrap handler cannot run, the reader
 * accounts for the wrap itself, and the handler does not count it again afterwards.
 */
static void test_time_inside_long_critical_section(void)
{
    uint64_t t0, t1, t2;
    uint32_t key;
    REQUIRE(init_systick() == 0);
    key = hal_crit_enter(&hal);
    t0 = hal_now_ns(&hal);
    hal_delay_ns(&hal, 800u * 1000u * 1000u);
    t1 = hal_now_ns(&hal);
    hal_crit_exit(&hal, key);
    t2 = hal_now_ns(&hal);
    CHECK(t1 - t0 >= 800u * MS);
    CHECK(t2 >= t1);
    CHECK(t2 - t1 < 300u * MS); /* a wrap counted twice would add 671 ms */
}

static void test_delay_is_never_short(void)
{
    static const uint32_t ns[] = {0u, 1u, 39u, 40u, 41u, 1000u, 12345u, 1000000u, 50000000u};
    size_t i;
    REQUIRE(init_systick() == 0);
    for (i = 0; i < sizeof(ns) / sizeof(ns[0]); i++) {
        uint64_t t0 = hal_now_ns(&hal);
        hal_delay_ns(&hal, ns[i]);
        CHECK(hal_now_ns(&hal) - t0 >= ns[i]);
    }
    {
        uint64_t t0 = hal_now_ns(&hal);
        hal_delay_ms(&hal, 20u);
        CHECK(hal_now_ns(&hal) - t0 >= 20u * MS);
    }
}

static void test_critical_sections_nest(void)
{
    uint32_t k0, k1;
    REQUIRE(init_systick() == 0);
    REQUIRE(primask() == 0u);
    k0 = hal_crit_enter(&hal);
    CHECK_EQ_INT(primask(), 1);
    k1 = hal_crit_enter(&hal);
    CHECK_EQ_INT(primask(), 1);
    hal_crit_exit(&hal, k1);
    CHECK_EQ_INT(primask(), 1); /* inner exit keeps the outer section */
    hal_crit_exit(&hal, k0);
    CHECK_EQ_INT(primask(), 0);
}

static void test_pins_go_through_the_family_seam(void)
{
    REQUIRE(init_systick() == 0);
    hal_pin_write(&hal, 5u, true);
    CHECK(gpio.level[5]);
    CHECK(hal_pin_read(&hal, 5u));
    hal_pin_write(&hal, 5u, false);
    CHECK(!hal_pin_read(&hal, 5u));
}

static volatile int cb_runs;
static void *volatile cb_last_arg;

static void count_cb(void *arg)
{
    cb_runs++;
    cb_last_arg = arg;
}

static void test_irq_attach_and_dispatch(void)
{
    int tag = 0;
    hal_pin_t p;
    REQUIRE(init_systick() == 0);
    gpio.enable_calls = 0;
    cb_runs = 0;
    CHECK_ERR(hal_irq_attach(&hal, 3u, (enum hal_edge)0, count_cb, NULL), INC_ERR_INVAL);
    CHECK_ERR(hal_irq_attach(&hal, HAL_PIN_NONE, HAL_EDGE_RISING, count_cb, NULL), INC_ERR_INVAL);
    CHECK_ERR(hal_irq_attach(&hal, 99u, HAL_EDGE_RISING, count_cb, NULL), INC_ERR_INVAL);
    CHECK_EQ_INT(gpio.enable_calls, 0);

    CHECK_OK(hal_irq_attach(&hal, 3u, HAL_EDGE_FALLING, count_cb, &tag));
    CHECK_EQ_INT(gpio.enable_calls, 1);
    CHECK_EQ_INT(gpio.last_pin, 3);
    CHECK_EQ_INT(gpio.last_edge, HAL_EDGE_FALLING);
    CHECK(gpio.last_enable);

    /* The family's ISR would call this; an unknown pin is ignored. */
    hal_cm_irq_dispatch(&cm, 4u);
    CHECK_EQ_INT(cb_runs, 0);
    hal_cm_irq_dispatch(&cm, 3u);
    CHECK_EQ_INT(cb_runs, 1);
    CHECK(cb_last_arg == &tag);
    /* It ran before the wait: the wait returns at once, the event is not lost. */
    CHECK_OK(hal_irq_wait(&hal, hal_now_ns(&hal) + 1000u * MS));
    {
        uint64_t deadline = hal_now_ns(&hal) + 2u * MS;
        CHECK_ERR(hal_irq_wait(&hal, deadline), INC_ERR_TIMEOUT);
        CHECK(hal_now_ns(&hal) >= deadline);
    }

    /* Slots: 3 is taken; three more fit, the fifth pin does not. */
    for (p = 10u; p < 13u; p++) {
        CHECK_OK(hal_irq_attach(&hal, p, HAL_EDGE_BOTH, count_cb, NULL));
    }
    CHECK_ERR(hal_irq_attach(&hal, 13u, HAL_EDGE_BOTH, count_cb, NULL), INC_ERR_NO_SPACE);
    /* Re-attaching a pin replaces its callback without a new slot. */
    CHECK_OK(hal_irq_attach(&hal, 12u, HAL_EDGE_RISING, count_cb, NULL));
    /* Detach frees a slot and disables the interrupt. */
    CHECK_OK(hal_irq_attach(&hal, 3u, HAL_EDGE_FALLING, NULL, NULL));
    CHECK(!gpio.last_enable);
    CHECK_EQ_INT(gpio.last_pin, 3);
    hal_cm_irq_dispatch(&cm, 3u);
    CHECK_EQ_INT(cb_runs, 1);
    CHECK_OK(hal_irq_attach(&hal, 13u, HAL_EDGE_BOTH, count_cb, NULL));
}

static void test_irq_wait_refuses_inside_critical_section(void)
{
    uint32_t key;
    REQUIRE(init_systick() == 0);
    key = hal_crit_enter(&hal);
    CHECK_ERR(hal_irq_wait(&hal, hal_now_ns(&hal) + MS), INC_ERR_STATE);
    hal_crit_exit(&hal, key);
}

/* A real interrupt wakes irq_wait from WFI: CMSDK TIMER0 (IRQ 8) plays the pin interrupt. */
#define TIMER0_CTRL (*(volatile uint32_t *)0x40000000u)
#define TIMER0_VALUE (*(volatile uint32_t *)0x40000004u)
#define TIMER0_RELOAD (*(volatile uint32_t *)0x40000008u)
#define TIMER0_INTCLEAR (*(volatile uint32_t *)0x4000000Cu)
#define NVIC_ISER0 (*(volatile uint32_t *)0xE000E100u)
#define NVIC_ICER0 (*(volatile uint32_t *)0xE000E180u)
#define TIMER0_IRQ 8u
#define TIMER_PIN 7u

void IRQ8_Handler(void);
void IRQ8_Handler(void)
{
    TIMER0_INTCLEAR = 1u;
    TIMER0_CTRL = 0u; /* one shot */
    hal_cm_irq_dispatch(&cm, TIMER_PIN);
}

static void test_irq_wait_sleeps_until_interrupt(void)
{
    uint64_t t0, t1;
    REQUIRE(init_systick() == 0);
    cb_runs = 0;
    REQUIRE(hal_irq_attach(&hal, TIMER_PIN, HAL_EDGE_RISING, count_cb, NULL) == 0);
    TIMER0_CTRL = 0u;
    TIMER0_RELOAD = QEMU_CORE_HZ / 200u; /* 5 ms */
    TIMER0_VALUE = QEMU_CORE_HZ / 200u;
    TIMER0_INTCLEAR = 1u;
    NVIC_ISER0 = 1u << TIMER0_IRQ;
    t0 = hal_now_ns(&hal);
    TIMER0_CTRL = (1u << 3) | 1u; /* interrupt enable, enable */
    CHECK_OK(hal_irq_wait(&hal, t0 + 2000u * MS));
    t1 = hal_now_ns(&hal);
    NVIC_ICER0 = 1u << TIMER0_IRQ;
    CHECK_EQ_INT(cb_runs, 1);
    CHECK(t1 - t0 >= 4u * MS);
    CHECK(t1 - t0 < 1000u * MS);
}

static void test_gpio_none(void)
{
    struct hal_cm_config cfg = {QEMU_CORE_HZ, HAL_CM_TIME_SYSTICK, &hal_cm_gpio_none, NULL};
    REQUIRE(hal_cm_init(&cm, &cfg, &hal) == 0);
    hal_pin_write(&hal, 1u, true);
    CHECK(!hal_pin_read(&hal, 1u));
    CHECK_ERR(hal_irq_attach(&hal, 1u, HAL_EDGE_RISING, count_cb, NULL), INC_ERR_UNSUPPORTED);
}

int main(void)
{
    UNIT_RUN(test_init_errors);
    UNIT_RUN(test_dwt_unsupported_under_qemu);
    UNIT_RUN(test_systick_init_fills_hal);
    UNIT_RUN(test_time_is_monotonic_across_wraps);
    UNIT_RUN(test_time_inside_long_critical_section);
    UNIT_RUN(test_delay_is_never_short);
    UNIT_RUN(test_critical_sections_nest);
    UNIT_RUN(test_pins_go_through_the_family_seam);
    UNIT_RUN(test_irq_attach_and_dispatch);
    UNIT_RUN(test_irq_wait_refuses_inside_critical_section);
    UNIT_RUN(test_irq_wait_sleeps_until_interrupt);
    UNIT_RUN(test_gpio_none);
    return unit_report();
}
