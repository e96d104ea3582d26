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

static int run(enum epb_rig_board board, struct app_result *res)
{
    struct app_cfg cfg;
    struct epb_rig_vehicle v;
    int err = epb_rig_init(&rig, EPB_RIG_ADIS16405, NULL, 1u);
    if (err == INC_OK) {
        err = epb_rig_set_board(&rig, board);
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

int main(void)
{
    UNIT_RUN(test_same_result);
    return unit_report();
}
