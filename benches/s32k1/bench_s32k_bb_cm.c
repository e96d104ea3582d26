/*
 * bench_s32k_bb_cm.c - instructions per 16-bit frame of the S32K1 port's bit-banged fast path
 * (s32k_board_bb_frame, direct build) and of the engine's generic path through the HAL ops
 * table is not measurable here (the port's time base needs LPIT0); not a test.
 *
 * Cases: SPI mode 3, word 0xA5A5; "no delays" (h1 = h2 = lead = 0: the code alone) and
 * "1 MHz" (h1 = h2 = 500 ns at the S32K116's 48 MHz: the counted delay loops included). With
 * -icount shift=6 SysTick counts instructions x 2^6 / 40 (docs/benchmarks.md, "Cortex-M"); the
 * same loop around an empty function is subtracted. Instructions, not cycles.
 */
#include <stdio.h>
#include <string.h>

#include "inclino/s32k_board.h"
#include "unit.h"

#define BENCH_N 256u
#define SYST_CSR (*(volatile uint32_t *)0xE000E010u)
#define SYST_RVR (*(volatile uint32_t *)0xE000E014u)
#define SYST_CVR (*(volatile uint32_t *)0xE000E018u)

static struct s32k_board board;
static volatile uint32_t sink;

static void ticks_reset(void)
{
    SYST_CSR = 0;
    SYST_RVR = 0x00FFFFFFu;
    SYST_CVR = 0;
    SYST_CSR = 5u;
}

static uint32_t ticks(void)
{
    return 0x00FFFFFFu - SYST_CVR;
}

/* The signature of struct spi_bitbang_fast's frame (ctx stays non-const). */
/* cppcheck-suppress constParameter */
__attribute__((noinline)) static uint16_t empty(void *ctx, const struct spi_bitbang_frame *fr,
                                                bool *mosi_out)
{
    __asm__ volatile("" ::: "memory");
    *mosi_out = ctx != NULL;
    return fr->word;
}

static uint32_t run(uint16_t (*fn)(void *, const struct spi_bitbang_frame *, bool *),
                    const struct spi_bitbang_frame *fr)
{
    uint32_t t0, i;
    bool m = false;
    ticks_reset();
    t0 = ticks();
    for (i = 0; i < BENCH_N; i++) {
        sink += fn(&board, fr, &m);
    }
    return ticks() - t0;
}

int main(void)
{
    struct spi_bitbang_frame fr;
    memset(&fr, 0, sizeof(fr));
    board.desc = &s32k_board_s32k116evb;
    board.port.cfg.core_hz = 48000000u;
    board.port.loop_q16 = s32k_hal_loop_q16(48000000u);
    fr.word = 0xA5A5u;
    fr.bits = 16u;
    fr.cpha = true;
    fr.idle = true;
    printf("BENCH_N %u\n", (unsigned)BENCH_N);
    printf("BENCH bb_frame 16-bit mode 3 no delays %lu %lu\n",
           (unsigned long)run(s32k_board_bb_frame, &fr), (unsigned long)run(empty, &fr));
    fr.lead_ns = 500u;
    fr.h1_ns = 500u;
    fr.h2_ns = 500u;
    printf("BENCH bb_frame 16-bit mode 3 1 MHz at 48 MHz %lu %lu\n",
           (unsigned long)run(s32k_board_bb_frame, &fr), (unsigned long)run(empty, &fr));
    return 0;
}
