/* fixture.c - see fixture.h. */
#include "fixture.h"

#include "inclino/sim/bench.h"

#include <stdio.h>
#include <string.h>

struct fx fx;

enum sca3000_variant fx_driver_variant(enum sim_sca3000_variant v)
{
    switch (v) {
    case SIM_SCA3000_D01: return SCA3000_D01;
    case SIM_SCA3000_E02: return SCA3000_E02;
    case SIM_SCA3000_E04: return SCA3000_E04;
    default: return SCA3000_E05;
    }
}

int fx_setup_part(enum sim_sca3000_variant v, uint8_t revid)
{
    struct sim_sca3000_cfg pc;
    int err;
    memset(&fx, 0, sizeof(fx));
    err = sim_board_init(&fx.board);
    if (err != 0) {
        return err;
    }
    sim_bench_sca3000_cfg(&fx.board, 0, v, &pc); /* cs0 = FX_CS, INT on dr0 = FX_INT */
    pc.revid = revid;
    err = sim_sca3000_init(&fx.part, &pc);
    if (err != 0) {
        return err;
    }
    fx.cfg.bus = &fx.board.spi.bus;
    fx.cfg.cs = FX_CS;
    fx.cfg.spi_mode0 = false;
    fx.cfg.variant = fx_driver_variant(v);
    fx.cfg.expected_revid = 0;
    fx.cfg.hal = &fx.board.hal;
    fx.cfg.int_pin = FX_INT;
    return 0;
}

int fx_setup(enum sim_sca3000_variant v)
{
    int err = fx_setup_part(v, 0);
    if (err != 0) {
        return err;
    }
    return sca3000_init(&fx.dev, &fx.cfg);
}

void fx_wait_ns(uint64_t ns)
{
    sim_clock_advance_to(&fx.board.clk, fx.board.clk.now_ns + ns);
}

bool fx_log_clean(void)
{
    if (fx.board.log.total == 0u) {
        return true;
    }
    printf("violation log (%u entries):\n", fx.board.log.total);
    sim_violation_log_print(&fx.board.log, stdout);
    if (fx.part.last_protocol != NULL) {
        printf("last model protocol error: %s\n", fx.part.last_protocol);
    }
    return false;
}

void fx_input(double ax, double ay, double az, double temp_c)
{
    struct sim_inertial_input in;
    sim_inertial_at_rest(&in);
    in.accel_g[0] = ax;
    in.accel_g[1] = ay;
    in.accel_g[2] = az;
    in.temp_c = temp_c;
    sim_sca3000_set_input(&fx.part, &in);
}
