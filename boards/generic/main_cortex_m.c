/*
 * main_cortex_m.c - main() of the EPB image on the Cortex-M targets.
 *
 * Brings up the generic Cortex-M HAL port and runs the EPB application (epb_image.c) on it.
 * Until an MCU-family port exists the GPIO seam is hal_cm_gpio_none (so the sensor is not found
 * and the bring-up is retried) and the core clock is a placeholder (APP_CORE_HZ); a family port
 * supplies both. The image still links the whole application, so its size and stack reports
 * are the application's.
 */
#include <stddef.h>
#include <stdint.h>

#include "epb_image.h"
#include "inclino/hal_cortex_m.h"

/* Core clock in Hz: a placeholder until a board port sets the real one (SysTick counts it). */
#define APP_CORE_HZ 48000000u

static struct hal_cm app_cm;
static struct hal app_hal;

int main(void)
{
    static const struct hal_cm_config cfg = {APP_CORE_HZ, HAL_CM_TIME_SYSTICK, &hal_cm_gpio_none,
                                             NULL};
    if (hal_cm_init(&app_cm, &cfg, &app_hal) != 0) {
        for (;;) {
        }
    }
    epb_image_run(&app_hal);
    return 0;
}
