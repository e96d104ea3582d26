/* The time-only HAL of sim/hal_sim (hal_sim_time): a clock and nothing else. */
#include "inclino/hal_sim.h"
#include "inclino/spi_bitbang.h"
#include "unit.h"

static void never(void *arg)
{
    (void)arg;
    unit_fail(__FILE__, __LINE__, "an interrupt of the time-only HAL fired");
}

static void test_time_and_waits(void)
{
    struct hal_sim_time t;
    struct hal hal;
    uint32_t k1, k2;
    CHECK_ERR(hal_sim_time_init(NULL, &hal), INC_ERR_NULL);
    CHECK_ERR(hal_sim_time_init(&t, NULL), INC_ERR_NULL);
    REQUIRE(hal_sim_time_init(&t, &hal) == INC_OK);
    CHECK_OK(hal_check(&hal));
    CHECK_EQ_INT(hal_now_ns(&hal), 0);
    hal_delay_ns(&hal, 1500);
    hal_delay_ms(&hal, 2);
    CHECK_EQ_INT(hal_now_ns(&hal), 2001500);
    CHECK_OK(hal_irq_attach(&hal, 3, HAL_EDGE_RISING, never, NULL));
    CHECK_ERR(hal_irq_wait(&hal, 5000000), INC_ERR_TIMEOUT);
    CHECK_EQ_INT(hal_now_ns(&hal), 5000000);
    CHECK_ERR(hal_irq_wait(&hal, 10), INC_ERR_TIMEOUT); /* a past deadline: time stays */
    CHECK_EQ_INT(hal_now_ns(&hal), 5000000);
    CHECK(!hal_pin_read(&hal, 2));
    hal_pin_write(&hal, 2, true);
    CHECK(!hal_pin_read(&hal, 2));
    k1 = hal_crit_enter(&hal);
    k2 = hal_crit_enter(&hal);
    CHECK_EQ_INT(t.crit_depth, 2);
    hal_crit_exit(&hal, k2);
    hal_crit_exit(&hal, k1);
    CHECK_EQ_INT(t.crit_depth, 0);
}

/* The SPI engine on it: the transfer takes its time, MISO reads 0 (nothing drives it). */
static void test_spi_engine_costs_time(void)
{
    static const struct spi_dev_cfg dc = {3, SPI_MODE_3, 16, {500, 100, 100, 9000, 0}};
    struct hal_sim_time t;
    struct hal hal;
    struct spi_bitbang bb;
    struct spi_bitbang_cfg bc;
    struct spi_dev dev;
    uint16_t rx = 0xFFFF;
    REQUIRE(hal_sim_time_init(&t, &hal) == INC_OK);
    bc.hal = &hal;
    bc.sclk = 0;
    bc.mosi = 1;
    bc.miso = 2;
    REQUIRE(spi_bitbang_init(&bb, &bc) == INC_OK);
    REQUIRE(spi_dev_init(&dev, &bb.bus, &dc) == INC_OK);
    CHECK_OK(spi_xfer1(&dev, 0x1234, &rx));
    CHECK_EQ_HEX(rx, 0);
    CHECK(hal_now_ns(&hal) >= 16u * 500u);
    CHECK(t.pin_writes > 16u);
}

int main(void)
{
    UNIT_RUN(test_time_and_waits);
    UNIT_RUN(test_spi_engine_costs_time);
    return unit_report();
}
