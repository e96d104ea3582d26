/*
 * s32k_scg.h - clock set-up of the S32K1 family (SCG) and peripheral clock gating (PCC).
 *
 * Two RUN configurations [S32K1XXRM, System Clock Generator; S32K1xx data sheet, clock limits]:
 *
 *   S32K_CLOCK_FIRC_48     FIRC 48 MHz as system clock: core 48 MHz, bus 48 MHz, slow (flash)
 *                          24 MHz. The reset clock of both parts; the S32K116's only RUN mode
 *                          here (its limit is 48 MHz).
 *   S32K_CLOCK_SPLL_80     S32K144 with the 8 MHz crystal of the S32K144EVB on SOSC: SPLL =
 *                          8 MHz / 1 * 40 / 2 = 160 MHz (VCO 320 MHz), core 80 MHz, bus 40 MHz,
 *                          slow 26.67 MHz (the S32K144's 80 MHz RUN limits).
 *
 * Both leave the asynchronous peripheral clocks at: FIRCDIV2 = 24 MHz (the time base, LPIT0),
 * SIRCDIV2 = 8 MHz, and for SPLL also SOSCDIV2 = 8 MHz, SPLLDIV2 = 40 MHz (LPSPI).
 * Every wait for a valid flag or a clock switch is bounded (S32K_SCG_POLL_MAX polls); a source
 * that never becomes valid returns INC_ERR_TIMEOUT and leaves the part on FIRC.
 */
#ifndef INCLINO_S32K_SCG_H
#define INCLINO_S32K_SCG_H

#include <stdint.h>

#include "inclino/error.h"

#ifdef __cplusplus
extern "C" {
#endif

enum s32k_clock {
    S32K_CLOCK_FIRC_48 = 0,
    S32K_CLOCK_SPLL_80 = 1,
};

#define S32K_FIRC_HZ 48000000u
#define S32K_SOSC_EVB_HZ 8000000u /* crystal of the S32K144EVB / S32K116EVB */
#define S32K_FIRCDIV2_HZ 24000000u
#define S32K_SCG_POLL_MAX 100000u

/*
 * Set up the RUN clocks. *core_hz (may be NULL) receives the core clock on success. Returns 0,
 * INC_ERR_INVAL (unknown mode), INC_ERR_TIMEOUT (a source did not become valid, or the
 * switch did not happen).
 */
int s32k_clock_init(enum s32k_clock mode, uint32_t *core_hz);

/* Gate the clock of the peripheral whose PCC register is at pcc_addr on, with functional clock
 * source pcs (S32K_PCC_PCS_*, 0 = none): PCS is written with the gate off, as the manual
 * requires. INC_ERR_UNSUPPORTED when the PCC register says the peripheral is not present. */
int s32k_pcc_enable(uint32_t pcc_addr, uint32_t pcs);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_S32K_SCG_H */
