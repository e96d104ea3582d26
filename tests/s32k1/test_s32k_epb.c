/*
 * test_s32k_epb.c - the EPB application end to end through the S32K144EVB port (the port's own
 * code, _sim build, against the register models) and through the generic simulated board, on
 * the same rig (part, errors, seed, parked car on 10 %): the first estimate of each must be
 * hold the truth inside its bound, and the two must agree: slope to 0.001 deg, bound to 0.005 deg
 * (its noise term comes from the block's own scatter), the same flags (the port's
 * register-access time may move the first sample of a block by one). Uncalibrated (no end of
 * line): short enough for QEMU, where this test also runs.
 */
#include <math.h>
#include <string.h>

#include "inclino/sim/epb_rig_state.h"
#include "inclino/sim/s32k_bus.h"
#include "unit.h"

static struct epb_rig rig;

static double q16(fx_q16_t v)
{
    return (double)v / 65536.0;
}

static int run_spi(enum epb_rig_board board, bool lpspi, struct app_result *res)
{
    struct app_cfg cfg;
    struct epb_rig_vehicle v;
    int err = epb_rig_init(&rig, EPB_RIG_ADIS16405, NULL, 1u);
    if (err == INC_OK) {
        err = epb_rig_set_board_spi(&rig, board, lpspi);
    }
    if (err == INC_OK) {
        err = app_cfg_default(&cfg, epb_rig_rate_mhz(&rig));
    }
    if (err == INC_OK) {
        err = epb_rig_power_up(&rig, &cfg);
    }
    if (err != INC_OK) {
        return err;
    }
    epb_rig_vehicle_default(&v);
    v.bump_rate_hz = 0.0;
    epb_rig_park(&rig, &v);
    return app_measure(&rig.app, res);
}

static int run(enum epb_rig_board board, struct app_result *res)
{
    return run_spi(board, false, res);
}

static void test_same_result(void)
{
    struct app_result gen, port;
    double truth;
    CHECK_OK(run(EPB_RIG_BOARD_SIM, &gen));
    CHECK_EQ_INT((int)epb_rig_violations(&rig), 0);
    CHECK_OK(run(EPB_RIG_BOARD_S32K144, &port));
    CHECK_EQ_INT((int)epb_rig_violations(&rig), 0);
    CHECK_EQ_INT((int)rig.s32k_core.wdog_bites, 0);
    CHECK_EQ_INT((int)s32k_bus_stats()->unmapped_reads, 0);
    CHECK_EQ_INT((int)s32k_bus_stats()->unmapped_writes, 0);
    CHECK(rig.s32k_gpio.edges_flagged > 1000u); /* data ready came through PORTE's IRQC */
    truth = atan(0.10) * 180.0 / 3.14159265358979323846;
    /* uncalibrated: the bound (about 5.5 deg) is too wide to be valid, in both runs alike */
    CHECK_EQ_INT((int)port.valid, (int)gen.valid);
    CHECK(fabs(q16(port.slope.slope_deg) - truth) <= q16(port.slope.bound_deg));
    CHECK_NEAR(q16(port.slope.slope_deg), q16(gen.slope.slope_deg), 0.001);
    CHECK_NEAR(q16(port.slope.bound_deg), q16(gen.slope.bound_deg), 0.005);
    CHECK_EQ_INT((int)port.flags, (int)gen.flags);
}

/* LPSPI with the engine sleeping on LPSPI0's interrupt (spi_lpspi.h, irq_wait): the same
 * estimate as the bit-banged port, every burst read in 4 sleeps (13 words through a 4-word
 * FIFO: the engine refills after each), no error; a shifter that stops makes the read fail with
 * a timeout instead of sleeping for ever. */
static void test_lpspi_sleeps(void)
{
    struct app_result bb, lp;
    struct sensor_sample smp;
    uint32_t sleeps, errors;
    CHECK_OK(run_spi(EPB_RIG_BOARD_S32K144, false, &bb));
    CHECK_OK(run_spi(EPB_RIG_BOARD_S32K144, true, &lp));
    CHECK_EQ_INT((int)epb_rig_violations(&rig), 0);
    CHECK(rig.s32k.lp.cfg.irq_wait);
    CHECK_EQ_INT((int)rig.s32k.lp.stats.errors, 0);
    /* the estimate's 2048 bursts and the power-up's reads: 4 sleeps per burst */
    CHECK(rig.s32k.lp.stats.sleeps >= 4u * 2048u);
    CHECK(rig.s32k.lp.stats.sleeps <= 4u * 2048u + 400u);
    /* every sleep ended by LPSPI0's interrupt (not by the wait's deadline timer) */
    CHECK(rig.s32k_lpspi.irqs >= rig.s32k.lp.stats.sleeps);
    CHECK(rig.s32k_core.delivered >= rig.s32k.lp.stats.sleeps + 2048u); /* + data ready */
    CHECK_NEAR(q16(lp.slope.slope_deg), q16(bb.slope.slope_deg), 0.001);
    CHECK_EQ_INT((int)lp.flags, (int)bb.flags);
    sleeps = rig.s32k.lp.stats.sleeps;
    errors = rig.s32k.lp.stats.errors;
    rig.s32k_lpspi.stall_engine = true;
    CHECK(sensor_next(epb_rig_sensor(&rig), 0u, &smp) != INC_OK);
    CHECK(rig.s32k.lp.stats.errors > errors);
    CHECK(rig.s32k.lp.stats.sleeps > sleeps);
    rig.s32k_lpspi.stall_engine = false;
}

int main(void)
{
    UNIT_RUN(test_same_result);
    UNIT_RUN(test_lpspi_sleeps);
    return unit_report();
}
