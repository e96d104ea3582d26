/* s32k_board.c - see inclino/s32k_board.h. */
#include "inclino/s32k_board.h"

#include <stddef.h>

#include "inclino/compiler.h"
#include "inclino/s32k_gpio.h"
#include "inclino/s32k_mmio.h"

/* INC_NOINLINE: out of line also under link-time optimisation (the board images, boards/s32k1/CMakeLists.txt):
 * the bring-up steps keep their own frames instead of adding theirs to the caller's, and the
 * vectors' handlers (placed before the flash configuration field, s32k1-sections.ld, where space
 * is short) stay one call each instead of a copy of the port's interrupt code per vector. */

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
    lc.irq_wait = true; /* sleep while the FIFO drains (the vector calls s32k_board_lpspi_isr) */
    err = spi_lpspi_init(&b->lp, &lc);
    if (err == INC_OK) {
        s32k_mmio_write32(S32K_NVIC_ICPR(S32K1_IRQ_LPSPI0 / 32u), 1u << (S32K1_IRQ_LPSPI0 % 32u));
        s32k_mmio_write32(S32K_NVIC_ISER(S32K1_IRQ_LPSPI0 / 32u), 1u << (S32K1_IRQ_LPSPI0 % 32u));
        b->spi = &b->lp.bus;
    }
    return err;
}

INC_NOINLINE void s32k_board_lpspi_isr(struct s32k_board *b)
{
    if (b != NULL && b->spi == &b->lp.bus) { /* the engines share memory (s32k_board.h) */
        spi_lpspi_isr(&b->lp);
        s32k_hal_wake(&b->port);
    }
}

INC_NOINLINE int s32k_board_init_core(struct s32k_board *b, const struct s32k_board_desc *desc,
                                      bool watchdog)
{
    struct s32k_hal_config hc;
    int err;
    if (b == NULL || desc == NULL) {
        return INC_ERR_NULL;
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
    return s32k_hal_init(&b->port, &hc, &b->hal);
}

INC_NOINLINE int s32k_board_spi_bitbang(struct s32k_board *b)
{
    struct spi_bitbang_cfg sc;
    int err;
    if (b == NULL) {
        return INC_ERR_NULL;
    }
    if (b->desc == NULL || b->spi != NULL) {
        return INC_ERR_STATE;
    }
    sc.hal = &b->hal;
    sc.sclk = b->desc->pins.sclk;
    sc.mosi = b->desc->pins.mosi;
    sc.miso = b->desc->pins.miso;
    b->fast.frame = s32k_board_bb_frame;
    b->fast.ctx = b;
    err = spi_bitbang_init_fast(&b->bb, &sc, &b->fast);
    if (err == INC_OK) {
        b->spi = &b->bb.bus;
    }
    return err;
}

int s32k_board_spi_lpspi(struct s32k_board *b)
{
    if (b == NULL) {
        return INC_ERR_NULL;
    }
    if (b->desc == NULL || b->spi != NULL) {
        return INC_ERR_STATE;
    }
    return lpspi_up(b);
}

int s32k_board_init(struct s32k_board *b, const struct s32k_board_desc *desc,
                    enum s32k_board_spi spi, bool watchdog)
{
    int err;
    if (b == NULL || desc == NULL) {
        return INC_ERR_NULL;
    }
    if (spi != S32K_BOARD_SPI_BITBANG && spi != S32K_BOARD_SPI_LPSPI) {
        return INC_ERR_INVAL;
    }
    err = s32k_board_init_core(b, desc, watchdog);
    if (err != INC_OK) {
        return err;
    }
    return spi == S32K_BOARD_SPI_LPSPI ? s32k_board_spi_lpspi(b) : s32k_board_spi_bitbang(b);
}

uint16_t s32k_board_bb_frame(void *ctx, const struct spi_bitbang_frame *fr, bool *mosi_out)
{
    struct s32k_board *b = ctx;
    const struct s32k_board_pins *pins = &b->desc->pins;
    const uint32_t sclk_mask = 1u << S32K_PIN_BIT(pins->sclk);
    const uint32_t mosi_mask = 1u << S32K_PIN_BIT(pins->mosi);
    const uint32_t miso_bit = S32K_PIN_BIT(pins->miso);
    /* SCLK's leading and trailing edges: the register each writes (PSOR sets, PCOR clears). */
    const uint32_t lead_reg = fr->idle ? S32K_GPIO_PCOR(S32K_PIN_PORT(pins->sclk))
                                       : S32K_GPIO_PSOR(S32K_PIN_PORT(pins->sclk));
    const uint32_t trail_reg = fr->idle ? S32K_GPIO_PSOR(S32K_PIN_PORT(pins->sclk))
                                        : S32K_GPIO_PCOR(S32K_PIN_PORT(pins->sclk));
    const uint32_t mosi_set = S32K_GPIO_PSOR(S32K_PIN_PORT(pins->mosi));
    const uint32_t mosi_clr = S32K_GPIO_PCOR(S32K_PIN_PORT(pins->mosi));
    const uint32_t miso_in = S32K_GPIO_PDIR(S32K_PIN_PORT(pins->miso));
    const uint32_t d_h1 = s32k_hal_short_prep(&b->port, fr->h1_ns);
    const uint32_t d_h2 = s32k_hal_short_prep(&b->port, fr->h2_ns);
    uint32_t before = s32k_hal_short_prep(&b->port, fr->lead_ns); /* first bit: the lead */
    /* the frame's bits left-aligned in 32 bits: bit 31 is the next one out */
    uint32_t w = fr->bits >= 1u && fr->bits <= 16u ? (uint32_t)fr->word << (32u - fr->bits) : 0u;
    uint32_t mosi = fr->mosi_level ? 1u : 0u;
    uint32_t in = 0u;
    unsigned n = fr->bits <= 16u ? fr->bits : 0u;
    if (!fr->cpha) {
        for (; n != 0u; n--, w <<= 1) {
            const uint32_t out = w >> 31;
            if (out != mosi) {
                s32k_mmio_write32(out != 0u ? mosi_set : mosi_clr, mosi_mask);
                mosi = out;
            }
            s32k_hal_short_run(&b->port, before);
            in = (in << 1) | ((s32k_mmio_read32(miso_in) >> miso_bit) & 1u);
            s32k_mmio_write32(lead_reg, sclk_mask);
            s32k_hal_short_run(&b->port, d_h1);
            s32k_mmio_write32(trail_reg, sclk_mask);
            before = d_h2;
        }
    } else {
        for (; n != 0u; n--, w <<= 1) {
            const uint32_t out = w >> 31;
            s32k_hal_short_run(&b->port, before);
            s32k_mmio_write32(lead_reg, sclk_mask);
            if (out != mosi) {
                s32k_mmio_write32(out != 0u ? mosi_set : mosi_clr, mosi_mask);
                mosi = out;
            }
            s32k_hal_short_run(&b->port, d_h1);
            in = (in << 1) | ((s32k_mmio_read32(miso_in) >> miso_bit) & 1u);
            s32k_mmio_write32(trail_reg, sclk_mask);
            before = d_h2;
        }
    }
    *mosi_out = mosi != 0u;
    return (uint16_t)in;
}

INC_NOINLINE void s32k_board_port_isr(struct s32k_board *b, uint32_t port)
{
    if (b != NULL) {
        s32k_hal_port_isr(&b->port, port);
    }
}

INC_NOINLINE void s32k_board_lpit_isr(struct s32k_board *b)
{
    if (b != NULL) {
        s32k_hal_lpit_isr(&b->port);
    }
}
