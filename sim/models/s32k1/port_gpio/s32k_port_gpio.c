/* s32k_port_gpio.c - see inclino/sim/s32k_port_gpio.h. */
#include "inclino/sim/s32k_port_gpio.h"

#include <stddef.h>
#include <string.h>

#include "inclino/sim/s32k_bus.h"

#define PORT_REGION_BASE 0x40049000u
#define PORT_REGION_SIZE (0x1000u * S32K_PORT_COUNT)
#define GPIO_REGION_BASE 0x400FF000u
#define GPIO_REGION_SIZE (0x40u * S32K_PORT_COUNT)

static bool is_gpio(const struct sim_s32k_port_gpio *m, unsigned port, unsigned bit)
{
    return ((m->pcr[port][bit] & S32K_PORT_PCR_MUX_MASK) >> S32K_PORT_PCR_MUX_SHIFT) ==
           S32K_PORT_PCR_MUX_GPIO;
}

/* Drive or release every connected line of a port from PDOR/PDDR/MUX. */
static void update_outputs(struct sim_s32k_port_gpio *m, unsigned port, uint32_t changed)
{
    unsigned bit;
    for (bit = 0; bit < S32K_PORT_PINS; bit++) {
        const unsigned line = m->line[port][bit];
        if ((changed & (1u << bit)) == 0u || line == SIM_S32K_PIN_NONE) {
            continue;
        }
        if ((m->pddr[port] & (1u << bit)) != 0u && is_gpio(m, port, bit)) {
            sim_pinbus_master_write(m->bus, line, (m->pdor[port] & (1u << bit)) != 0u);
        } else if (m->bus->pin[line].master_drives) {
            sim_pinbus_master_release(m->bus, line);
        }
    }
}

static uint32_t pdir(const struct sim_s32k_port_gpio *m, unsigned port)
{
    uint32_t v = 0u;
    unsigned bit;
    for (bit = 0; bit < S32K_PORT_PINS; bit++) {
        const unsigned line = m->line[port][bit];
        if (line != SIM_S32K_PIN_NONE && is_gpio(m, port, bit) &&
            (m->pidr[port] & (1u << bit)) == 0u && sim_pinbus_read(m->bus, line)) {
            v |= 1u << bit;
        }
    }
    return v;
}

static void on_change(void *arg, unsigned line, bool level, uint64_t t_ns)
{
    struct sim_s32k_port_gpio *m = arg;
    unsigned port, bit, irqc;
    uint32_t *pcr;
    (void)t_ns;
    if (line >= SIM_PINBUS_MAX_PINS || m->mcu_pin[line] == 0xFFu) {
        return;
    }
    port = m->mcu_pin[line] / S32K_PORT_PINS;
    bit = m->mcu_pin[line] % S32K_PORT_PINS;
    pcr = &m->pcr[port][bit];
    irqc = (*pcr & S32K_PORT_PCR_IRQC_MASK) >> S32K_PORT_PCR_IRQC_SHIFT;
    if ((*pcr & S32K_PORT_PCR_ISF) != 0u) {
        return;
    }
    if ((irqc == S32K_PORT_IRQC_RISING && level) || (irqc == S32K_PORT_IRQC_FALLING && !level) ||
        irqc == S32K_PORT_IRQC_EITHER) {
        *pcr |= S32K_PORT_PCR_ISF;
        m->edges_flagged++;
        sim_s32k_core_raise(m->core,
                            m->part == S32K_PART_116 ? S32K116_IRQ_PORT : S32K144_IRQ_PORTA + port);
    }
}

static uint32_t port_read(void *ctx, uint32_t off, unsigned width)
{
    struct sim_s32k_port_gpio *m = ctx;
    const unsigned port = off / 0x1000u;
    const uint32_t r = off % 0x1000u;
    (void)width;
    if (r < 0x80u) {
        return m->pcr[port][r / 4u];
    }
    if (r == 0xA0u) {
        uint32_t v = 0u;
        unsigned bit;
        for (bit = 0; bit < S32K_PORT_PINS; bit++) {
            if ((m->pcr[port][bit] & S32K_PORT_PCR_ISF) != 0u) {
                v |= 1u << bit;
            }
        }
        return v;
    }
    return 0u;
}

static void port_write(void *ctx, uint32_t off, uint32_t v, unsigned width)
{
    struct sim_s32k_port_gpio *m = ctx;
    const unsigned port = off / 0x1000u;
    const uint32_t r = off % 0x1000u;
    (void)width;
    if (r < 0x80u) {
        const unsigned bit = r / 4u;
        uint32_t *pcr = &m->pcr[port][bit];
        const uint32_t keep_isf = (*pcr & S32K_PORT_PCR_ISF) != 0u && (v & S32K_PORT_PCR_ISF) == 0u
                                      ? S32K_PORT_PCR_ISF
                                      : 0u;
        *pcr = (v & (S32K_PORT_PCR_PS | S32K_PORT_PCR_PE | S32K_PORT_PCR_MUX_MASK |
                     S32K_PORT_PCR_IRQC_MASK)) |
               keep_isf;
        update_outputs(m, port, 1u << bit);
    } else if (r == 0xA0u) {
        unsigned bit;
        for (bit = 0; bit < S32K_PORT_PINS; bit++) {
            if ((v & (1u << bit)) != 0u) {
                m->pcr[port][bit] &= ~S32K_PORT_PCR_ISF;
            }
        }
    }
}

static uint32_t gpio_read(void *ctx, uint32_t off, unsigned width)
{
    struct sim_s32k_port_gpio *m = ctx;
    const unsigned port = off / 0x40u;
    (void)width;
    switch (off % 0x40u) {
    case 0x00u: return m->pdor[port];
    case 0x10u: return pdir(m, port);
    case 0x14u: return m->pddr[port];
    case 0x18u: return m->pidr[port];
    default: return 0u; /* PSOR, PCOR, PTOR read as 0 */
    }
}

static void gpio_write(void *ctx, uint32_t off, uint32_t v, unsigned width)
{
    struct sim_s32k_port_gpio *m = ctx;
    const unsigned port = off / 0x40u;
    const uint32_t old = m->pdor[port];
    const uint32_t old_dir = m->pddr[port];
    (void)width;
    switch (off % 0x40u) {
    case 0x00u: m->pdor[port] = v; break;
    case 0x04u: m->pdor[port] |= v; break;
    case 0x08u: m->pdor[port] &= ~v; break;
    case 0x0Cu: m->pdor[port] ^= v; break;
    case 0x14u: m->pddr[port] = v; break;
    case 0x18u: m->pidr[port] = v; break;
    default: break;
    }
    update_outputs(m, port, (old ^ m->pdor[port]) | (old_dir ^ m->pddr[port]));
}

static const struct s32k_bus_region_ops port_ops = {port_read, port_write};
static const struct s32k_bus_region_ops gpio_ops = {gpio_read, gpio_write};

int sim_s32k_port_gpio_init(struct sim_s32k_port_gpio *m, struct sim_pinbus *bus,
                            struct sim_s32k_core *core, enum s32k_part part)
{
    int err;
    if (m == NULL || bus == NULL || core == NULL) {
        return INC_ERR_NULL;
    }
    memset(m, 0, sizeof(*m));
    memset(m->line, SIM_S32K_PIN_NONE, sizeof(m->line));
    memset(m->mcu_pin, 0xFF, sizeof(m->mcu_pin));
    m->bus = bus;
    m->core = core;
    m->part = part;
    m->listener.fn = on_change;
    m->listener.arg = m;
    m->listener.mask = 0u;
    err = s32k_bus_map(PORT_REGION_BASE, PORT_REGION_SIZE, &port_ops, m);
    if (err == INC_OK) {
        err = s32k_bus_map(GPIO_REGION_BASE, GPIO_REGION_SIZE, &gpio_ops, m);
    }
    if (err == INC_OK) {
        err = sim_pinbus_listen(bus, &m->listener);
    }
    return err;
}

int sim_s32k_port_gpio_connect(struct sim_s32k_port_gpio *m, unsigned mcu_pin, unsigned line)
{
    if (m == NULL) {
        return INC_ERR_NULL;
    }
    if (mcu_pin >= S32K_PORT_COUNT * S32K_PORT_PINS || line >= SIM_PINBUS_MAX_PINS ||
        m->mcu_pin[line] != 0xFFu) {
        return INC_ERR_INVAL;
    }
    m->line[mcu_pin / S32K_PORT_PINS][mcu_pin % S32K_PORT_PINS] = (uint8_t)line;
    m->mcu_pin[line] = (uint8_t)mcu_pin;
    m->listener.mask |= SIM_PIN_MASK(line);
    return INC_OK;
}
