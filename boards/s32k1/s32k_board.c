/* s32k_board.c - see inclino/s32k_board.h. */
#include "inclino/s32k_board.h"

#include <stddef.h>

#include "inclino/s32k_gpio.h"

static int pins_up(const struct s32k_board_pins *p)
{
    int err = s32k_gpio_clock_on();
    /* SPI mode 3 idles SCLK high; chip selects and RST inactive high. */
    if (err == INC_OK) {
        err = s32k_gpio_output(p->sclk, true);
    }
    if (err == INC_OK) {
        err = s32k_gpio_output(p->mosi, true);
    }
    if (err == INC_OK) {
        err = s32k_gpio_input(p->miso, S32K_PULL_UP);
    }
    if (err == INC_OK) {
        err = s32k_gpio_output(p->cs_imu, true);
    }
    if (err == INC_OK) {
        err = s32k_gpio_output(p->cs_acc, true);
    }
    if (err == INC_OK) {
        err = s32k_gpio_output(p->rst_imu, true);
    }
    if (err == INC_OK) {
        err = s32k_gpio_input(p->dr_imu, S32K_PULL_NONE);
    }
    if (err == INC_OK) {
        err = s32k_gpio_input(p->dr_acc, S32K_PULL_NONE);
    }
    if (err == INC_OK) {
        err = s32k_pin_mux(p->can_tx, p->can_mux, S32K_PULL_NONE);
    }
    if (err == INC_OK) {
        err = s32k_pin_mux(p->can_rx, p->can_mux, S32K_PULL_NONE);
    }
    return err;
}

int s32k_board_init(struct s32k_board *b, const struct s32k_board_desc *desc,
                    enum s32k_board_spi spi, bool watchdog)
{
    struct s32k_hal_config hc;
    struct spi_bitbang_cfg sc;
    int err;
    if (b == NULL || desc == NULL) {
        return INC_ERR_NULL;
    }
    if (spi != S32K_BOARD_SPI_BITBANG) {
        /* The LPSPI engine (drivers/spi_lpspi) is not wired in yet: see docs/boards.md. */
        return spi == S32K_BOARD_SPI_LPSPI ? INC_ERR_UNSUPPORTED : INC_ERR_INVAL;
    }
    b->desc = desc;
    b->spi = NULL;
    err = s32k_clock_init(desc->clock, &b->core_hz);
    if (err == INC_OK) {
        err = pins_up(&desc->pins);
    }
    if (err != INC_OK) {
        return err;
    }
    hc.part = desc->part;
    hc.core_hz = b->core_hz;
    hc.watchdog = watchdog;
    err = s32k_hal_init(&b->port, &hc, &b->hal);
    if (err != INC_OK) {
        return err;
    }
    sc.hal = &b->hal;
    sc.sclk = desc->pins.sclk;
    sc.mosi = desc->pins.mosi;
    sc.miso = desc->pins.miso;
    err = spi_bitbang_init(&b->bb, &sc);
    if (err == INC_OK) {
        b->spi = &b->bb.bus;
    }
    return err;
}

void s32k_board_port_isr(struct s32k_board *b, uint32_t port)
{
    if (b != NULL) {
        s32k_hal_port_isr(&b->port, port);
    }
}

void s32k_board_lpit_isr(struct s32k_board *b)
{
    if (b != NULL) {
        s32k_hal_lpit_isr(&b->port);
    }
}
