/*
 * main_cortex_m.c - main() of the EPB image on the Cortex-M targets.
 *
 * Brings up the generic Cortex-M HAL port and the application, then sleeps between interrupts.
 * Until an MCU-family port exists the GPIO seam is hal_cm_gpio_none and the core clock is a
 * placeholder (APP_CORE_HZ); a family port supplies both.
 */
#include <stdint.h>

#include "inclino/app.h"
#include "inclino/hal_cortex_m.h"

/* Core clock in Hz: a placeholder until a board port sets the real one (SysTick counts it). */
#define APP_CORE_HZ 48000000u

static struct hal_cm app_cm;
static struct hal app_hal;

int main(void)
{
    static const struct hal_cm_config cfg = {APP_CORE_HZ, HAL_CM_TIME_SYSTICK, &hal_cm_gpio_none,
                                             NULL};
    if (hal_cm_init(&app_cm, &cfg, &app_hal) != 0 || app_init(&app_hal) != 0) {
        for (;;) {
        }
    }
    for (;;) {
        (void)hal_irq_wait(&app_hal, UINT64_MAX);
    }
}
