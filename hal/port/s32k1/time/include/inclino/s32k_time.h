/*
 * s32k_time.h - the 64-bit nanosecond time base of the S32K1 port [S32K1XXRM, Low Power
 * Interrupt Timer (LPIT)].
 *
 * Choice: LPIT0, not SysTick. Channel 0 counts down over its full 32 bits (TVAL = 0xFFFFFFFF,
 * 32-bit periodic mode) from FIRCDIV2 = 24 MHz, the same clock on both parts whatever the core
 * runs at: a 41.7 ns tick, one wrap every 179 s, so the software extension to 64 bits needs one
 * read per 179 s (every wait and delay of the port reads it; the watchdog resets a main line
 * that stops for 256 ms long before that). SysTick would wrap every 0.21 s at 80 MHz (24 bits)
 * and needs its own wrap interrupt. Channel 1 is a one-shot wake-up: s32k_time_arm() lets it
 * count the ticks to a deadline and request LPIT0's interrupt (S32K144: channel 1 vector 49;
 * S32K116: the shared LPIT0 vector 20), which wakes the core from WFI.
 *
 * Ticks -> ns: 1 tick = 1e9 / 24e6 = 125/3 ns exactly. Every read converts only the ticks
 * since the previous read (at most 2^25 of them at a time, 1.4 s: d * 125 fits 32 bits) and
 * carries the remainder of the division by 3, so the running sum is exactly
 * floor(ticks * 125 / 3) (no rounding error at any age) with one 32-bit multiply and one
 * division by a constant per read: about 60 instructions on the M0+ instead of the 300 of a
 * general 64-bit conversion, which every wait and timestamp paid (docs/benchmarks.md, "CPU per
 * sample on the S32K1 port"). ns -> ticks rounds up (a wait is never shorter than asked).
 */
#ifndef INCLINO_S32K_TIME_H
#define INCLINO_S32K_TIME_H

#include <stdint.h>

#include "inclino/error.h"
#include "inclino/s32k1_regs.h"

#ifdef __cplusplus
extern "C" {
#endif

#define S32K_TIME_HZ 24000000u /* FIRCDIV2 (inclino/s32k_scg.h) */
/* ns per tick as a fraction: S32K_TIME_NS_NUM / S32K_TIME_NS_DEN = 1e9 / S32K_TIME_HZ. */
#define S32K_TIME_NS_NUM 125u
#define S32K_TIME_NS_DEN 3u
/* Ticks converted in one step: CHUNK * NUM + (DEN - 1) < 2^32. */
#define S32K_TIME_CHUNK 0x02000000u

struct s32k_time {
    uint64_t ticks; /* ticks counted up to `last` */
    uint64_t ns;    /* floor(ticks * NUM / DEN) */
    uint32_t rem;   /* (ticks * NUM) mod DEN */
    uint32_t last;  /* CVAL0 at the last read */
    uint32_t irq;   /* NVIC number of the channel 1 interrupt */
};

/* Clock LPIT0 from FIRCDIV2 (PCC), start channel 0. now counts from here. 0 or an error. */
int s32k_time_init(struct s32k_time *t, enum s32k_part part);

/* Ticks since init (64 bits). Masks interrupts for the read-and-extend. */
uint64_t s32k_time_ticks(struct s32k_time *t);

/* Nanoseconds since init: floor(ticks * 125 / 3), exact. Masks interrupts like the ticks. */
uint64_t s32k_time_now_ns(struct s32k_time *t);

/* Ticks for at least ns nanoseconds: ceil(ns * 3 / 125), exact for every ns < 2^32. */
uint64_t s32k_time_ns_to_ticks(const struct s32k_time *t, uint32_t ns);

/* floor(x / 3) for every x, without a division (the conversion's; exported for its test). */
uint32_t s32k_time_div3(uint32_t x);
/* floor(x / 125) for every x, without a division (ns -> ticks; exported for its test). */
uint32_t s32k_time_div125(uint32_t x);

/* Request the channel 1 interrupt after `ticks` ticks (1..2^32), replacing any armed one. */
void s32k_time_arm(struct s32k_time *t, uint64_t ticks);

/* Stop channel 1 and clear its flag (also the handler's work: call it from LPIT0's vector). */
void s32k_time_disarm(struct s32k_time *t);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_S32K_TIME_H */
