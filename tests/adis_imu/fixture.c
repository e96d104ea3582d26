/* fixture.c - see fixture.h. */
#include "fixture.h"

#include "inclino/sim/bench.h"

#include <stdio.h>
#include <string.h>

struct fx fx;

void fx_prepare(enum sim_adis_imu_variant v)
{
    memset(&fx, 0, sizeof(fx));
    sim_board_init(&fx.board);
    sim_bench_adis_imu_cfg(&fx.board, 0, v, &fx.part_cfg);
    fx.cfg.hal = &fx.board.hal;
    fx.cfg.bus = &fx.board.spi.bus;
    fx.cfg.cs = SIM_BOARD_CS(0);
    fx.cfg.variant = (uint8_t)v; /* same order in both enums */
    fx.cfg.dr_pin = SIM_BOARD_DR(0);
    fx.cfg.dr_line = ADIS_IMU_DR_DIO1;
    fx.cfg.dr_active_low = false;
}

void fx_start(void)
{
    sim_adis_imu_init(&fx.part, &fx.part_cfg);
    /* The driver does not wait for power-on: its caller does (adis_imu.h). */
    hal_delay_ms(&fx.board.hal, ADIS_IMU_STARTUP_MS);
}

void fx_setup(enum sim_adis_imu_variant v)
{
    fx_prepare(v);
    fx_start();
}

int fx_init(void)
{
    return adis_imu_init(&fx.imu, &fx.cfg);
}

unsigned fx_violations(void)
{
    if (fx.board.log.total != 0u) {
        sim_violation_log_print(&fx.board.log, stdout);
    }
    return fx.board.log.total;
}

void fx_wait_ms(uint32_t ms)
{
    hal_delay_ms(&fx.board.hal, ms);
}

void fx_set_input_settled(const struct sim_inertial_input *in)
{
    sim_adis_imu_set_input(&fx.part, in);
    /* 128 samples at the current rate: every Bartlett setting (2N - 1 <= 127) has settled. */
    hal_delay_until(&fx.board.hal, fx.board.clk.now_ns +
                                       (uint64_t)(128.0 * 1e9 / sim_adis_imu_rate_sps(&fx.part)) +
                                       1u);
}
