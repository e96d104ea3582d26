/*
 * s32k_wdog.h - the S32K1 watchdog (WDOG) [S32K1XXRM, Watchdog Timer].
 *
 * Decision: the watchdog stays ENABLED. It runs from the 128 kHz LPO with the fixed /256
 * prescaler (2 ms per count) and a timeout of S32K_WDOG_TIMEOUT_MS; the HAL port refreshes it
 * where the main line waits (every irq_wait and every sleeping delay: once per sensor sample,
 * 1.22 ms at 819.2 SPS), and the board's main loop refreshes it once per result. A main line
 * that stops waiting for samples - a hang, a fault loop, a runaway - resets the part within
 * the timeout, and the EPB/ESC output goes invalid through the reset instead of freezing at a
 * stale value. DBG = 0: it stops while a debugger halts the core.
 *
 * Rules of the manual this code follows:
 *   - unlock: one 32-bit write of 0xD928C520 to CNT (CMD32EN = 1, the reset value), then wait
 *     for CS.ULK; the new TOVAL, WIN and CS must all be written within the unlock window
 *     (128 bus clocks), CS last, each as one 32-bit write; then wait for CS.RCS (the new
 *     configuration took effect);
 *   - reconfiguration after the first one is possible only while CS.UPDATE = 1, so it stays set;
 *   - refresh: one 32-bit write of 0xB480A602 to CNT; no window (WIN = 0), so any time is right;
 *   - the reset configuration (enabled, LPO, short timeout) must be replaced early: the startup
 *     calls s32k_wdog_init before .data and .bss are initialised.
 * The unlock and the writes run with interrupts masked by the caller (startup: they are).
 */
#ifndef INCLINO_S32K_WDOG_H
#define INCLINO_S32K_WDOG_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/error.h"

#ifdef __cplusplus
extern "C" {
#endif

#define S32K_WDOG_TIMEOUT_MS 256u
#define S32K_WDOG_POLL_MAX 10000u

/* Configure: enabled (enable == true) with the timeout above, or disabled (for a debug build
 * or a bench). Returns 0 or INC_ERR_TIMEOUT (ULK or RCS never came). */
int s32k_wdog_init(bool enable);

/* Refresh (service) the watchdog. */
void s32k_wdog_refresh(void);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_S32K_WDOG_H */
