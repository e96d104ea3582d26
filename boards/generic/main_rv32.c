/*
 * main_rv32.c - main() of the EPB image on rv32imac.
 *
 * There is no RISC-V HAL port yet (docs/build.md). So that the image links and measures the
 * real application, main gives it a placeholder HAL: no pins (writes ignored, reads low), time
 * counted by the delays themselves (now_ns advances only through delay_ns and irq_wait, which
 * returns at its deadline), no interrupts, and critical sections that do nothing (no interrupt
 * is ever enabled). A RISC-V port (mcycle/mtime time base, PLIC/CLIC pin interrupts, the family's
 * GPIO) replaces it, as hal/port/cortex_m does on Cortex-M.
 */
#include <stdbool.h>
#include <stdint.h>

#include "epb_image.h"

static uint64_t rv_now;

static void rv_pin_write(void *ctx, hal_pin_t pin, bool level)
{
    (void)ctx;
    (void)pin;
    (void)level;
}

static bool rv_pin_read(void *ctx, hal_pin_t pin)
{
    (void)ctx;
    (void)pin;
    return false;
}

static uint64_t rv_now_ns(void *ctx)
{
    (void)ctx;
    return rv_now;
}

static void rv_delay_ns(void *ctx, uint32_t ns)
{
    (void)ctx;
    rv_now += ns;
}

static int rv_irq_attach(void *ctx, hal_pin_t pin, enum hal_edge edge, hal_irq_cb cb, void *arg)
{
    (void)ctx;
    (void)pin;
    (void)edge;
    (void)cb;
    (void)arg;
    return INC_ERR_UNSUPPORTED;
}

static int rv_irq_wait(void *ctx, uint64_t deadline_ns)
{
    (void)ctx;
    if (rv_now < deadline_ns) {
        rv_now = deadline_ns;
    }
    __asm volatile("wfi");
    return INC_ERR_TIMEOUT;
}

static uint32_t rv_crit_enter(void *ctx)
{
    (void)ctx;
    return 0u;
}

static void rv_crit_exit(void *ctx, uint32_t key)
{
    (void)ctx;
    (void)key;
}

static const struct hal_ops rv_ops = {rv_pin_write,  rv_pin_read, rv_now_ns,     rv_delay_ns,
                                      rv_irq_attach, rv_irq_wait, rv_crit_enter, rv_crit_exit};

int main(void)
{
    static const struct hal rv_hal = {&rv_ops, 0};
    epb_image_run(&rv_hal);
    return 0;
}
