/*
 * bench_can_cm.c - instructions per call of the CAN frame code on Cortex-M under QEMU (not a
 * test; benches/can/bench_can_cm.sh runs it). Method as benches/avg/bench_avg_cm.c: SysTick
 * ticks of BENCH_N calls, minus the same loop around an empty noinline function.
 */
#include <stdio.h>
#include <string.h>

#include "inclino/can_frames.h"
#include "inclino/e2e.h"
#include "unit.h"

#define BENCH_N 256u
#define SYST_CSR (*(volatile uint32_t *)0xE000E010u)
#define SYST_RVR (*(volatile uint32_t *)0xE000E014u)
#define SYST_CVR (*(volatile uint32_t *)0xE000E018u)

static struct can_frame speed[BENCH_N];
static struct can_frame out[2];
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

__attribute__((noinline)) static int empty3(const void *a, const void *b, const void *c)
{
    __asm__ volatile("" ::: "memory");
    return a != b && c != NULL;
}

__attribute__((noinline)) static int empty_out(const void *a, const void *b, bool c, const void *d,
                                               size_t *n)
{
    __asm__ volatile("" ::: "memory");
    *n = 2;
    return a != b && c && d != NULL;
}

int main(void)
{
    struct can_tx tx;
    struct can_speed_rx rx;
    struct e2e_p01_protect_state vtx = {0};
    struct app_esc_output o;
    struct app_vehicle v;
    size_t n = 0;
    uint32_t i, t, base;
    memset(&o, 0, sizeof o);
    o.mode = APP_MODE_DRIVING;
    o.valid = true;
    o.roll_deg = 123456;
    o.pitch_deg = -654321;
    o.bound_deg = 70000;
    for (i = 0; i < BENCH_N; i++) {
        (void)can_pack_speed(&vtx, true, (fx_q16_t)(i * 4000u), true, 1000, &speed[i]);
    }
    printf("BENCH_N %u\n", (unsigned)BENCH_N);

    ticks_reset();
    for (i = 0; i < BENCH_N; i++) {
        sink += (uint32_t)empty_out(&tx, &o, true, out, &n);
    }
    base = ticks();
    (void)can_tx_init(&tx);
    ticks_reset();
    for (i = 0; i < BENCH_N; i++) {
        sink += (uint32_t)can_pack_output(&tx, &o, true, out, &n);
    }
    t = ticks();
    printf("BENCH can_pack_output(DRIVING: INC_Attitude + INC_Status) %lu %lu\n", (unsigned long)t,
           (unsigned long)base);
    o.mode = APP_MODE_PARKED;
    o.epb.slope.slope_deg = 200000;
    o.epb.slope.grade_pct = 300000;
    o.epb.slope.bound_deg = 9000;
    ticks_reset();
    for (i = 0; i < BENCH_N; i++) {
        sink += (uint32_t)can_pack_output(&tx, &o, true, out, &n);
    }
    t = ticks();
    printf("BENCH can_pack_output(PARKED: INC_Slope + INC_Status) %lu %lu\n", (unsigned long)t,
           (unsigned long)base);

    ticks_reset();
    for (i = 0; i < BENCH_N; i++) {
        sink += (uint32_t)empty3(&rx, &speed[i], &v);
    }
    base = ticks();
    (void)can_speed_rx_init(&rx, 5u);
    ticks_reset();
    for (i = 0; i < BENCH_N; i++) {
        sink += (uint32_t)can_speed_rx_cycle(&rx, &speed[i], &v);
    }
    t = ticks();
    printf("BENCH can_speed_rx_cycle(one VEH_Speed frame, E2E check included) %lu %lu\n",
           (unsigned long)t, (unsigned long)base);
    {
        const struct e2e_p01_cfg *c = can_e2e_cfg(CAN_ID_SPEED);
        ticks_reset();
        for (i = 0; i < BENCH_N; i++) {
            sink += (uint32_t)empty3((void *)c, speed[i].data, &v);
        }
        base = ticks();
        ticks_reset();
        for (i = 0; i < BENCH_N; i++) {
            sink += e2e_p01_crc(c, speed[i].data);
        }
        t = ticks();
        printf("BENCH e2e_p01_crc(8-byte frame, bitwise CRC-8) %lu %lu\n", (unsigned long)t,
               (unsigned long)base);
    }
    return 0;
}
