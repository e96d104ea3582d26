/* gpio.c - see inclino/s32k_gpio.h. */
#include "inclino/s32k_gpio.h"

#include "inclino/s32k_scg.h"

int s32k_gpio_clock_on(void)
{
    uint32_t p;
    for (p = 0; p < S32K_PORT_COUNT; p++) {
        int err = s32k_pcc_enable(S32K_PCC_PORT(p), 0u);
        if (err != INC_OK) {
            return err;
        }
    }
    return INC_OK;
}

static uint32_t pull_bits(enum s32k_pin_pull pull)
{
    if (pull == S32K_PULL_UP) {
        return S32K_PORT_PCR_PE | S32K_PORT_PCR_PS;
    }
    if (pull == S32K_PULL_DOWN) {
        return S32K_PORT_PCR_PE;
    }
    return 0u;
}

int s32k_pin_mux(hal_pin_t pin, uint32_t mux, enum s32k_pin_pull pull)
{
    if (!S32K_PIN_VALID(pin) || mux > 7u || pull > S32K_PULL_DOWN) {
        return INC_ERR_INVAL;
    }
    /* ISF written as 1 clears a stale flag; IRQC = 0. */
    s32k_mmio_write32(S32K_PORT_PCR(S32K_PIN_PORT(pin), S32K_PIN_BIT(pin)),
                      (mux << S32K_PORT_PCR_MUX_SHIFT) | pull_bits(pull) | S32K_PORT_PCR_ISF);
    return INC_OK;
}

int s32k_gpio_output(hal_pin_t pin, bool level)
{
    int err = s32k_pin_mux(pin, S32K_PORT_PCR_MUX_GPIO, S32K_PULL_NONE);
    if (err != INC_OK) {
        return err;
    }
    s32k_gpio_write(pin, level);
    s32k_mmio_set32(S32K_GPIO_PDDR(S32K_PIN_PORT(pin)), 1u << S32K_PIN_BIT(pin));
    return INC_OK;
}

int s32k_gpio_input(hal_pin_t pin, enum s32k_pin_pull pull)
{
    int err = s32k_pin_mux(pin, S32K_PORT_PCR_MUX_GPIO, pull);
    if (err != INC_OK) {
        return err;
    }
    s32k_mmio_clear32(S32K_GPIO_PDDR(S32K_PIN_PORT(pin)), 1u << S32K_PIN_BIT(pin));
    s32k_mmio_clear32(S32K_GPIO_PIDR(S32K_PIN_PORT(pin)), 1u << S32K_PIN_BIT(pin));
    return INC_OK;
}

uint32_t s32k_gpio_irq_number(enum s32k_part part, uint32_t port)
{
    return part == S32K_PART_116 ? S32K116_IRQ_PORT : S32K144_IRQ_PORTA + port;
}

int s32k_gpio_irq_enable(enum s32k_part part, hal_pin_t pin, enum hal_edge edge, bool enable)
{
    uint32_t irqc;
    uint32_t port;
    if (!S32K_PIN_VALID(pin) || (part != S32K_PART_144 && part != S32K_PART_116)) {
        return INC_ERR_INVAL;
    }
    if (edge == HAL_EDGE_RISING) {
        irqc = S32K_PORT_IRQC_RISING;
    } else if (edge == HAL_EDGE_FALLING) {
        irqc = S32K_PORT_IRQC_FALLING;
    } else if (edge == HAL_EDGE_BOTH) {
        irqc = S32K_PORT_IRQC_EITHER;
    } else {
        return INC_ERR_INVAL;
    }
    if (!enable) {
        irqc = S32K_PORT_IRQC_OFF;
    }
    port = S32K_PIN_PORT(pin);
    /* IRQC replaced; ISF (w1c) written as 1 so an edge from before does not fire at once. */
    s32k_mmio_modify32(S32K_PORT_PCR(port, S32K_PIN_BIT(pin)),
                       S32K_PORT_PCR_IRQC_MASK | S32K_PORT_PCR_ISF,
                       (irqc << S32K_PORT_PCR_IRQC_SHIFT) | S32K_PORT_PCR_ISF);
    if (enable) {
        const uint32_t irq = s32k_gpio_irq_number(part, port);
        s32k_mmio_write32(S32K_NVIC_ICPR(irq / 32u), 1u << (irq % 32u));
        s32k_mmio_write32(S32K_NVIC_ISER(irq / 32u), 1u << (irq % 32u));
    }
    return INC_OK;
}

uint32_t s32k_gpio_isr(uint32_t port)
{
    uint32_t flags;
    if (port >= S32K_PORT_COUNT) {
        return 0u;
    }
    flags = s32k_mmio_read32(S32K_PORT_ISFR(port));
    if (flags != 0u) {
        s32k_mmio_write32(S32K_PORT_ISFR(port), flags);
    }
    return flags;
}
