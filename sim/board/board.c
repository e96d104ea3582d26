/* board.c - see sim/board.h. */
#include "inclino/sim/board.h"

#include <string.h>

static const char *const cs_names[4] = {"cs0", "cs1", "cs2", "cs3"};
static const char *const dr_names[4] = {"dr0", "dr1", "dr2", "dr3"};
static const char *const rst_names[4] = {"rst0", "rst1", "rst2", "rst3"};

int sim_board_init(struct sim_board *b)
{
    struct spi_bitbang_cfg spi;
    unsigned i;
    int err;
    if (b == NULL) {
        return INC_ERR_NULL;
    }
    memset(b, 0, sizeof(*b));
    sim_clock_init(&b->clk);
    sim_violation_log_init(&b->log);
    sim_pinbus_init(&b->bus, &b->clk, &b->log);
    err = sim_pinbus_define(&b->bus, SIM_BOARD_SCLK, "sclk", SIM_PULL_KEEPER, true);
    if (err == INC_OK)
        err = sim_pinbus_define(&b->bus, SIM_BOARD_MOSI, "mosi", SIM_PULL_KEEPER, false);
    if (err == INC_OK) err = sim_pinbus_define(&b->bus, SIM_BOARD_MISO, "miso", SIM_PULL_UP, true);
    for (i = 0; i < 4u && err == INC_OK; i++) {
        err = sim_pinbus_define(&b->bus, SIM_BOARD_CS(i), cs_names[i], SIM_PULL_UP, true);
        if (err == INC_OK)
            err = sim_pinbus_define(&b->bus, SIM_BOARD_DR(i), dr_names[i], SIM_PULL_DOWN, false);
        if (err == INC_OK)
            err = sim_pinbus_define(&b->bus, SIM_BOARD_RST(i), rst_names[i], SIM_PULL_UP, true);
    }
    if (err != INC_OK) {
        return err;
    }
    err = hal_sim_init(&b->port, &b->clk, &b->bus, &b->hal);
    if (err != INC_OK) {
        return err;
    }
    spi.hal = &b->hal;
    spi.sclk = SIM_BOARD_SCLK;
    spi.mosi = SIM_BOARD_MOSI;
    spi.miso = SIM_BOARD_MISO;
    return spi_bitbang_init(&b->spi, &spi);
}

int sim_board_set_miso_pull(struct sim_board *b, enum sim_pull pull)
{
    if (b == NULL) {
        return INC_ERR_NULL;
    }
    if (pull > SIM_PULL_DOWN) {
        return INC_ERR_INVAL;
    }
    b->bus.pin[SIM_BOARD_MISO].pull = pull;
    /* Re-resolve by a no-op release: undriven pins take the new pull's level. */
    sim_pinbus_master_release(&b->bus, SIM_BOARD_MISO);
    return INC_OK;
}
