/*
 * test_s32k_port.c - the S32K1 port's own code (_sim build) against the register models:
 * PORT/GPIO drive and read the pin bus, the pin interrupt reaches an attached callback through
 * PCR.IRQC/ISF and the simulated NVIC, the LPIT0 time base advances with register accesses,
 * delays are never short, the tick-to-ns and ns-to-tick conversions are exact, irq_wait times out at its deadline, and the watchdog is configured
 * and refreshed without a bite. Runs on the host and under QEMU.
 */
#include <string.h>

#include "inclino/s32k_board.h"
#include "inclino/s32k_gpio.h"
#include "inclino/s32k_wdog.h"
#include "inclino/sim/clock.h"
#include "inclino/sim/pinbus.h"
#include "inclino/sim/s32k_bus.h"
#include "inclino/sim/s32k_core.h"
#include "inclino/sim/s32k_lpit.h"
#include "inclino/sim/s32k_lpspi.h"
#include "inclino/sim/s32k_port_gpio.h"
#include "unit.h"

static struct sim_clock clk;
static struct sim_pinbus bus;
static struct sim_s32k_core core;
static struct sim_s32k_lpit lpit;
static struct sim_s32k_port_gpio gpio;
static struct s32k_board board;
static struct sim_s32k_lpspi lpspi;
static unsigned edges;

enum { L_SCLK, L_MOSI, L_MISO, L_CS, L_DR };

static void on_edge(void *arg)
{
    (void)arg;
    edges++;
}

static void port_isr4(void *arg)
{
    s32k_board_port_isr(arg, 4u);
}

static void lpit_isr(void *arg)
{
    s32k_board_lpit_isr(arg);
}

static void setup(void)
{
    const struct s32k_board_pins *p = &s32k_board_s32k144evb.pins;
    sim_clock_init(&clk);
    sim_pinbus_init(&bus, &clk, NULL);
    CHECK_OK(sim_pinbus_define(&bus, L_SCLK, "sclk", SIM_PULL_KEEPER, true));
    CHECK_OK(sim_pinbus_define(&bus, L_MOSI, "mosi", SIM_PULL_KEEPER, false));
    CHECK_OK(sim_pinbus_define(&bus, L_MISO, "miso", SIM_PULL_UP, true));
    CHECK_OK(sim_pinbus_define(&bus, L_CS, "cs", SIM_PULL_UP, true));
    CHECK_OK(sim_pinbus_define(&bus, L_DR, "dr", SIM_PULL_DOWN, false));
    s32k_bus_reset();
    CHECK_OK(sim_s32k_core_init(&core, &clk));
    CHECK_OK(sim_s32k_lpit_init(&lpit, &clk, &core, S32K_PART_144, S32K_TIME_HZ, 25u));
    CHECK_OK(sim_s32k_port_gpio_init(&gpio, &bus, &core, S32K_PART_144));
    CHECK_OK(sim_s32k_port_gpio_connect(&gpio, p->sclk, L_SCLK));
    CHECK_OK(sim_s32k_port_gpio_connect(&gpio, p->mosi, L_MOSI));
    CHECK_OK(sim_s32k_port_gpio_connect(&gpio, p->miso, L_MISO));
    CHECK_OK(sim_s32k_port_gpio_connect(&gpio, p->cs_imu, L_CS));
    CHECK_OK(sim_s32k_port_gpio_connect(&gpio, p->dr_imu, L_DR));
    sim_s32k_core_set_handler(&core, S32K144_IRQ_PORTA + 4u, port_isr4, &board);
    sim_s32k_core_set_handler(&core, S32K144_IRQ_LPIT0_CH1, lpit_isr, &board);
    CHECK_OK(s32k_wdog_init(true));
    CHECK_OK(s32k_board_init(&board, &s32k_board_s32k144evb, S32K_BOARD_SPI_BITBANG, true));
}

static void test_pins(void)
{
    const struct s32k_board_pins *p = &s32k_board_s32k144evb.pins;
    setup();
    CHECK(sim_pinbus_read(&bus, L_CS));   /* parked high by the bring-up */
    CHECK(sim_pinbus_read(&bus, L_SCLK)); /* mode 3 idle */
    hal_pin_write(&board.hal, p->cs_imu, false);
    CHECK(!sim_pinbus_read(&bus, L_CS));
    hal_pin_write(&board.hal, p->cs_imu, true);
    CHECK(sim_pinbus_read(&bus, L_CS));
    CHECK(hal_pin_read(&board.hal, p->miso)); /* pull-up of the line */
    sim_pinbus_device_drive(&bus, (unsigned)sim_pinbus_add_device(&bus), L_MISO, false);
    CHECK(!hal_pin_read(&board.hal, p->miso));
    /* LPSPI: without the LPSPI0 model nothing answers PARAM (unsupported); with it the engine
     * serves the board's bus, the ADIS CS on PCS1 (PTB5 ALT3) and parked high. */
    {
        struct sim_s32k_lpspi_cfg lc;
        unsigned k;
        memset(&lc, 0, sizeof(lc));
        lc.base = LPSPI0_BASE;
        lc.fclk_hz = S32K_BOARD_LPSPI_SPLL_HZ;
        lc.clk = &clk;
        lc.bus = &bus;
        lc.sck = L_SCLK;
        lc.sout = L_MOSI;
        lc.sin = L_MISO;
        for (k = 0; k < SIM_LPSPI_PCS; k++) {
            lc.pcs[k] = SIM_LPSPI_NO_PIN;
        }
        lc.pcs[p->cs_imu_pcs] = L_CS;
        CHECK_OK(sim_s32k_lpspi_init(&lpspi, &lc));
        CHECK_OK(s32k_board_init(&board, &s32k_board_s32k144evb, S32K_BOARD_SPI_LPSPI, true));
        CHECK(board.spi == &board.lp.bus);
        CHECK(board.lp.cfg.irq_wait); /* sleeps on its interrupt */
        CHECK((core.enabled[S32K1_IRQ_LPSPI0 / 32u] & (1u << (S32K1_IRQ_LPSPI0 % 32u))) != 0u);
        CHECK_EQ_INT(board.lp.fifo_words, 4);
        CHECK_EQ_INT(lpspi.locked_writes, 0);
        CHECK(sim_pinbus_read(&bus, L_CS));
    }
    CHECK_EQ_INT(s32k_board_init(&board, &s32k_board_s32k144evb, (enum s32k_board_spi)7, true),
                 INC_ERR_INVAL);
    /* The two-step bring-up of the board images: one engine, only after the core. */
    CHECK_EQ_INT(s32k_board_init_core(NULL, &s32k_board_s32k144evb, true), INC_ERR_NULL);
    CHECK_EQ_INT(s32k_board_spi_bitbang(NULL), INC_ERR_NULL);
    CHECK_EQ_INT(s32k_board_spi_lpspi(NULL), INC_ERR_NULL);
    CHECK_OK(s32k_board_init_core(&board, &s32k_board_s32k144evb, true));
    CHECK(board.spi == NULL);
    CHECK_OK(s32k_board_spi_bitbang(&board));
    CHECK(board.spi == &board.bb.bus);
    CHECK_EQ_INT(s32k_board_spi_bitbang(&board), INC_ERR_STATE);
    CHECK_EQ_INT(s32k_board_spi_lpspi(&board), INC_ERR_STATE);
    CHECK_EQ_INT((int)s32k_bus_stats()->unmapped_reads, 0);
    CHECK_EQ_INT((int)s32k_bus_stats()->unmapped_writes, 0);
}

static void test_irq(void)
{
    const struct s32k_board_pins *p = &s32k_board_s32k144evb.pins;
    int dev;
    uint32_t key;
    setup();
    dev = sim_pinbus_add_device(&bus);
    edges = 0;
    CHECK_OK(hal_irq_attach(&board.hal, p->dr_imu, HAL_EDGE_RISING, on_edge, NULL));
    sim_pinbus_device_drive(&bus, (unsigned)dev, L_DR, true);
    CHECK_EQ_INT((int)edges, 1);
    sim_pinbus_device_drive(&bus, (unsigned)dev, L_DR, false); /* falling: ignored */
    CHECK_EQ_INT((int)edges, 1);
    CHECK_OK(hal_irq_wait(&board.hal, hal_now_ns(&board.hal) + 1000000u));
    /* inside a critical section the edge is held and runs at the exit */
    key = hal_crit_enter(&board.hal);
    sim_pinbus_device_drive(&bus, (unsigned)dev, L_DR, true);
    CHECK_EQ_INT((int)edges, 1);
    hal_crit_exit(&board.hal, key);
    CHECK_EQ_INT((int)edges, 2);
    CHECK_EQ_INT((int)(s32k_mmio_read32(S32K_PORT_ISFR(4)) & (1u << 2)), 0); /* cleared */
}

static void test_time(void)
{
    uint64_t t0, t1, deadline, off0, off1;
    setup();
    t0 = hal_now_ns(&board.hal);
    hal_delay_ns(&board.hal, 500u);
    t1 = hal_now_ns(&board.hal);
    CHECK(t1 - t0 >= 500u);
    CHECK(t1 - t0 < 2000u);
    t0 = hal_now_ns(&board.hal);
    off0 = clk.now_ns - t0;
    hal_delay_ms(&board.hal, 100u); /* sleeps on LPIT0 channel 1 */
    t1 = hal_now_ns(&board.hal);
    off1 = clk.now_ns - t1;
    CHECK(t1 - t0 >= 100000000u);
    CHECK(t1 - t0 < 100100000u);
    /* the LPIT clock runs with the simulated clock (it started later: a constant offset) */
    CHECK(off1 >= off0 ? off1 - off0 < 100u : off0 - off1 < 100u);
    deadline = hal_now_ns(&board.hal) + 5000000u;
    CHECK_EQ_INT(hal_irq_wait(&board.hal, deadline), INC_ERR_TIMEOUT);
    CHECK(hal_now_ns(&board.hal) >= deadline);
    CHECK(hal_now_ns(&board.hal) < deadline + 100000u);
    CHECK(core.wdog_refreshes > 0u);
    CHECK_EQ_INT((int)core.wdog_bites, 0);
    CHECK((core.wdog_cs & S32K_WDOG_CS_EN) != 0u);
}

/* ceil(ns * 3 / 125), the ticks of at least ns at 24 MHz, with a 64-bit intermediate. */
static uint64_t ticks_ref(uint32_t ns)
{
    return ((uint64_t)ns * 3u + 124u) / 125u;
}

static void check_conv(uint32_t x, unsigned long *bad)
{
    if (s32k_time_div3(x) != x / 3u || s32k_time_div125(x) != x / 125u ||
        s32k_time_ns_to_ticks(NULL, x) != ticks_ref(x)) {
        (*bad)++;
    }
}

/* The division-free conversions of the time base are the divisions, for every input class. */
static void test_time_conversions(void)
{
    unsigned long bad = 0;
    uint32_t st = 0x71CCu, i;
    uint64_t ns;
    for (i = 0; i < 4096u; i++) { /* both ends of the range */
        check_conv(i, &bad);
        check_conv(0xFFFFFFFFu - i, &bad);
    }
    for (i = 0; i < 32u; i++) { /* around the powers of two, where a reciprocal errs first */
        const uint32_t p = 1u << i;
        uint32_t k;
        for (k = 0; k < 8u; k++) {
            check_conv(p + k, &bad);
            check_conv(p - k, &bad);
        }
    }
    for (i = 0; i < 300000u; i++) {
        const uint32_t x = unit_rand32(&st) >> (unit_rand32(&st) % 32u);
        check_conv(x, &bad);
    }
    CHECK_EQ_INT((long)bad, 0);
    CHECK_EQ_INT((long)s32k_time_ns_to_ticks(NULL, 0u), 0);
    CHECK_EQ_INT((long)s32k_time_ns_to_ticks(NULL, 1u), 1);
    CHECK_EQ_INT((long)s32k_time_ns_to_ticks(NULL, 125u), 3);
    CHECK_EQ_INT((long)s32k_time_ns_to_ticks(NULL, 126u), 4);

    /* The running sum stays exactly floor(ticks * 125 / 3): short reads, then one gap longer
     * than three conversion steps (a step is 2^25 ticks = 1.4 s) and one of nearly 2^32 ticks. */
    setup();
    for (i = 0; i < 100u; i++) {
        uint64_t ticks;
        hal_delay_ns(&board.hal, 1000u + 37u * i);
        ticks = s32k_time_ticks(&board.port.time);
        ns = s32k_time_now_ns(&board.port.time);
        CHECK(ns == board.port.time.ticks * 125u / 3u);
        CHECK(ticks <= board.port.time.ticks);
    }
    /* A gap of 3 steps and a bit without a read (white box: `last` moved back by that much). */
    board.port.time.last += 3u * S32K_TIME_CHUNK + 12345u;
    ns = s32k_time_now_ns(&board.port.time);
    CHECK(ns == board.port.time.ticks * 125u / 3u);
    CHECK_EQ_INT((long)board.port.time.rem, (long)(board.port.time.ticks * 125u % 3u));
    board.port.time.last += 0xFFFF0000u; /* nearly a whole wrap (179 s) unread */
    ns = s32k_time_now_ns(&board.port.time);
    CHECK(ns == board.port.time.ticks * 125u / 3u);
    CHECK(board.port.time.ticks > 3u * S32K_TIME_CHUNK);
}

int main(void)
{
    UNIT_RUN(test_pins);
    UNIT_RUN(test_irq);
    UNIT_RUN(test_time);
    UNIT_RUN(test_time_conversions);
    return unit_report();
}
