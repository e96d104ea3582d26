/* fixture.c - see fixture.h. */
#include "fixture.h"

#include "inclino/sim/bench.h"

#include <string.h>

struct fx fx;

void fx_default_cfg(struct adis16255_cfg *cfg)
{
    memset(cfg, 0, sizeof(*cfg));
    cfg->bus = &fx.board.spi.bus;
    cfg->hal = &fx.board.hal;
    cfg->cs = SIM_BOARD_CS(0);
    cfg->dr_pin = SIM_BOARD_DR(0);
    cfg->smpl_prd = 0x01;
    cfg->range = ADIS16255_RANGE_320;
    cfg->filter_m = 2;
    cfg->dr_enable = true;
    cfg->dr_active_high = true;
    cfg->dr_line = 0;
}

void fx_setup_times(bool with_part, const struct sim_adis16255_times *times)
{
    struct sim_adis16255_cfg mc;
    memset(&fx, 0, sizeof(fx));
    sim_board_init(&fx.board);
    fx.has_part = with_part;
    if (with_part) {
        sim_bench_adis16255_cfg(&fx.board, 0, &mc);
        if (times != NULL) {
            mc.times = *times;
        }
        sim_adis16255_init(&fx.part, &mc);
    }
    fx_default_cfg(&fx.cfg);
}

void fx_setup(bool with_part)
{
    fx_setup_times(with_part, NULL);
}

void fx_input(double rate_dps, double temp_c, double supply_v)
{
    struct sim_inertial_input in;
    sim_inertial_at_rest(&in);
    in.rate_dps[2] = rate_dps;
    in.temp_c = temp_c;
    in.supply_v = supply_v;
    sim_adis16255_set_input(&fx.part, &in);
}

void fx_wait_ms(uint32_t ms)
{
    hal_delay_ms(&fx.board.hal, ms);
}
