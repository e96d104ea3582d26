/* rig.c - the LPSPI engine and model on the standard board (see s32k_lpspi_rig.h). */
#include "inclino/sim/s32k_lpspi_rig.h"

#include "inclino/sim/s32k_bus.h"

static void charge_access(void *ctx)
{
    struct sim_clock *clk = ctx;
    sim_clock_advance_to(clk, clk->now_ns + SIM_LPSPI_RIG_ACCESS_NS);
}

int sim_lpspi_rig_init(struct sim_lpspi_rig *r, struct sim_board *b, uint32_t fclk_hz)
{
    struct sim_s32k_lpspi_cfg mc;
    struct spi_lpspi_cfg ec;
    unsigned k;
    int err;
    if (r == NULL || b == NULL) {
        return INC_ERR_NULL;
    }
    if (fclk_hz == 0u) {
        fclk_hz = SIM_LPSPI_RIG_FCLK_HZ;
    }
    r->board = b;
    s32k_bus_reset();
    mc.base = LPSPI0_BASE;
    mc.fclk_hz = fclk_hz;
    mc.clk = &b->clk;
    mc.bus = &b->bus;
    mc.sck = SIM_BOARD_SCLK;
    mc.sout = SIM_BOARD_MOSI;
    mc.sin = SIM_BOARD_MISO;
    for (k = 0; k < SIM_LPSPI_PCS; k++) {
        mc.pcs[k] = SIM_BOARD_CS(k);
    }
    mc.core = NULL; /* the standard board's HAL has no NVIC: the engine polls */
    mc.irq = 0u;
    err = sim_s32k_lpspi_init(&r->model, &mc);
    if (err != INC_OK) {
        return err;
    }
    s32k_bus_set_hook(charge_access, &b->clk);
    ec.hal = &b->hal;
    ec.base = LPSPI0_BASE;
    ec.fclk_hz = fclk_hz;
    for (k = 0; k < SPI_LPSPI_PCS_COUNT; k++) {
        ec.pcs_pin[k] = (hal_pin_t)SIM_BOARD_CS(k);
    }
    ec.timeout_ns = 0;
    ec.irq_wait = false;
    return spi_lpspi_init(&r->engine, &ec);
}
