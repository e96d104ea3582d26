/*
 * startup_s32k1.c - reset entry and flash configuration field of the S32K1 boards' images.
 *
 * Reset_Handler, in this order: the watchdog (enabled at reset with a short timeout, so it is
 * configured before anything slow; inclino/s32k_wdog.h), the FPU on the M4F (CPACR CP10/CP11
 * full access, ARMv7-M ARM B3.2.20), .data copied from flash, .bss zeroed, main(). The stack
 * pointer is the vector table's entry 0, loaded by the core.
 *
 * Flash configuration field (FCF) at 0x400..0x40F, read by the flash controller at reset
 * [S32K1XXRM, Flash Memory Module (FTFC), "Flash configuration field description"]:
 *   0x400..0x407  backdoor comparison key   0xFF x 8 (backdoor access disabled: KEYEN != 10b)
 *   0x408..0x40B  FPROT3..0                 0xFF (no P-flash region protected)
 *   0x40C         FSEC                      0xFE: SEC = 10b unsecured, FSLACC = 11b, MEEN = 11b,
 *                                           KEYEN = 11b. Any other SEC value SECURES the part
 *                                           (debug access lost until a mass erase)
 *   0x40D         FOPT                      0xFF (erased value; reserved bits untouched)
 *   0x40E         FEPROT                    0xFF (EEPROM unprotected)
 *   0x40F         FDPROT                    0xFF (D-flash unprotected)
 * The image test image_fcf_<image> (boards/s32k1/check_fcf.py) reads these bytes from the built
 * .bin and fails on anything else.
 */
#include <stdint.h>

#include "inclino/s32k_wdog.h"
#include "s32k1_startup.h"

#define S32K1_FSEC_UNSECURED 0xFEu
#define S32K1_FCF_ERASED 0xFFu

__attribute__((used, section(".flash_config"))) const uint8_t s32k1_flash_config[16] = {
    S32K1_FCF_ERASED,     S32K1_FCF_ERASED, S32K1_FCF_ERASED,
    S32K1_FCF_ERASED, /* key 0..3 */
    S32K1_FCF_ERASED,     S32K1_FCF_ERASED, S32K1_FCF_ERASED,
    S32K1_FCF_ERASED, /* key 4..7 */
    S32K1_FCF_ERASED,     S32K1_FCF_ERASED, S32K1_FCF_ERASED,
    S32K1_FCF_ERASED, /* FPROT */
    S32K1_FSEC_UNSECURED, S32K1_FCF_ERASED, S32K1_FCF_ERASED,
    S32K1_FCF_ERASED, /* FSEC FOPT
                                                                                   FEPROT FDPROT */
};

S32K1_EARLY(Reset_Handler) void Reset_Handler(void)
{
    const uint32_t *src = __data_load__;
    uint32_t *dst;

    (void)s32k_wdog_init(true); /* on failure the reset configuration stays: it resets us */
#if defined(__ARM_FP)
    *(volatile uint32_t *)0xE000ED88u |= (0xFu << 20);
    __asm volatile("dsb\n\tisb" ::: "memory");
#endif
    for (dst = __data_start__; dst != __data_end__; dst++, src++) {
        *dst = *src;
    }
    for (dst = __bss_start__; dst != __bss_end__; dst++) {
        *dst = 0u;
    }
    (void)main();
    for (;;) {
    }
}
