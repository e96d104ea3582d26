/*
 * hal_cycles.h - cycle counter <-> nanoseconds for the MCU ports (cortex_m, riscv), integer only.
 *
 * A port counts core clock cycles (SysTick, DWT CYCCNT, mcycle) in 64 bits and converts with
 * precomputed Q32.32 factors: no floating point, no division after init, no overflow for any
 * input in range. The core clock is given in Hz, HAL_CYC_HZ_MIN..HAL_CYC_HZ_MAX.
 */
#ifndef INCLINO_HAL_CYCLES_H
#define INCLINO_HAL_CYCLES_H

#include <stdint.h>

#include "inclino/error.h"

#ifdef __cplusplus
extern "C" {
#endif

#define HAL_CYC_HZ_MIN 1000000u    /* 1 MHz: keeps ns_per_cyc_q32 below 2^42 */
#define HAL_CYC_HZ_MAX 1000000000u /* 1 GHz: keeps cyc_per_ns_q32 at or below 2^32 */

struct hal_cyc_conv {
    uint32_t hz;             /* core clock, Hz */
    uint64_t ns_per_cyc_q32; /* floor(1e9 * 2^32 / hz): ns per cycle, Q32.32 */
    uint64_t cyc_per_ns_q32; /* ceil(hz * 2^32 / 1e9): cycles per ns, Q32.32, <= 2^32 */
};

/*
 * Precompute the factors for a clock of hz Hz. Returns 0, INC_ERR_NULL for conv == NULL, or
 * INC_ERR_INVAL when hz is outside HAL_CYC_HZ_MIN..HAL_CYC_HZ_MAX (conv is then untouched).
 */
int hal_cyc_init(struct hal_cyc_conv *conv, uint32_t hz);

/*
 * ns elapsed in `cycles` cycles, rounded down. With exact = cycles * 1e9 / hz:
 *   exact - 1 - cycles / 2^32  <  result  <=  exact,
 * i.e. at most 1 ns plus 1 ns per 2^32 cycles (25.6 s at 168 MHz; 4e-11 relative, far below
 * any crystal's tolerance) below exact. Monotonic non-decreasing in cycles. Valid while the
 * result fits 64 bits (584 years).
 */
uint64_t hal_cyc_to_ns(const struct hal_cyc_conv *conv, uint64_t cycles);

/*
 * The smallest whole number of cycles lasting at least ns, possibly one more:
 *   ceil(ns * hz / 1e9)  <=  result  <=  ceil(ns * hz / 1e9) + 1.
 * For busy-waits, which must never be short. Any ns (uint32_t) is valid.
 */
uint64_t hal_ns_to_cyc_ceil(const struct hal_cyc_conv *conv, uint32_t ns);

/*
 * floor(a * b / 2^32), exact, with a 128-bit intermediate built from 32x32->64 products. The
 * result wraps modulo 2^64 when it does not fit (the callers above stay in range).
 */
uint64_t hal_cyc_mul_q32(uint64_t a, uint64_t b);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_HAL_CYCLES_H */
