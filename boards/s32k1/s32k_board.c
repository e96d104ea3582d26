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

/* LPSPI0 on the SPI pins and the PCS-capable chip selects (the rest stay GPIO, parked high). */
static int lpspi_up(struct s32k_board *b)
{
    const struct s32k_board_pins *p = &b->desc->pins;
    const bool spll = b->desc->clock == S32K_CLOCK_SPLL_80;
    struct spi_lpspi_cfg lc;
    unsigned k;
    int err = s32k_pin_mux(p->sclk, p->lpspi_mux, S32K_PULL_NONE);
    if (err == INC_OK) {
        err = s32k_pin_mux(p->mosi, p->lpspi_mux, S32K_PULL_NONE);
    }
    if (err == INC_OK) {
        err = s32k_pin_mux(p->miso, p->lpspi_mux, S32K_PULL_UP);
    }
    if (err == INC_OK && p->cs_imu_pcs < SPI_LPSPI_PCS_COUNT) {
        err = s32k_pin_mux(p->cs_imu, p->lpspi_mux, S32K_PULL_NONE);
    }
    if (err == INC_OK && p->cs_acc_pcs < SPI_LPSPI_PCS_COUNT) {
        err = s32k_pin_mux(p->cs_acc, p->lpspi_mux, S32K_PULL_NONE);
    }
    if (err == INC_OK) {
        err = s32k_pcc_enable(S32K_PCC_LPSPI0,
                              spll ? S32K_PCC_PCS_SPLLDIV2 : S32K_PCC_PCS_FIRCDIV2);
    }
    if (err != INC_OK) {
        return err;
    }
    lc.hal = &b->hal;
    lc.base = LPSPI0_BASE;
    lc.fclk_hz = spll ? S32K_BOARD_LPSPI_SPLL_HZ : S32K_FIRCDIV2_HZ;
    for (k = 0; k < SPI_LPSPI_PCS_COUNT; k++) {
        lc.pcs_pin[k] = HAL_PIN_NONE;
    }
    if (p->cs_imu_pcs < SPI_LPSPI_PCS_COUNT) {
        lc.pcs_pin[p->cs_imu_pcs] = p->cs_imu;
    }
    if (p->cs_acc_pcs < SPI_LPSPI_PCS_COUNT) {
        lc.pcs_pin[p->cs_acc_pcs] = p->cs_acc;
    }
    lc.timeout_ns = 0;
    err = spi_lpspi_init(&b->lp, &lc);
    if (err == INC_OK) {
        b->spi = &b->lp.bus;
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
    if (spi != S32K_BOARD_SPI_BITBANG && spi != S32K_BOARD_SPI_LPSPI) {
        return INC_ERR_INVAL;
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
    if (spi == S32K_BOARD_SPI_LPSPI) {
        return lpspi_up(b);
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
