/*
 * bench_kf_cm.c - instructions per update of the filters on Cortex-M under QEMU (not a test).
 *
 * The method of benches/fx/bench_fx_cm.c: with -icount shift=S,align=off QEMU advances its virtual
 * time 2^S ns per executed instruction, and the mps2 SysTick (25 MHz processor clock) then counts
 * instructions * 2^S / 40. Each filter update runs BENCH_N times on prepared, noisy inputs after a
 * warm-up (the filters are in their steady state); the same loop around an empty noinline
 * function is subtracted. Instructions, not cycles. Run with benches/kf/bench_kf_cm.sh <dir>.
 */
#include <stdbool.h>
#include <stdio.h>

#include "inclino/avg.h"
#include "inclino/fx128.h"
#include "inclino/kf.h"
#include "inclino/kf_adapt.h"
#include "inclino/tilt.h"
#include "unit.h"

#define BENCH_N 32
#define WARM 200
#define SYST_CSR (*(volatile uint32_t *)0xE000E010u)
#define SYST_RVR (*(volatile uint32_t *)0xE000E014u)
#define SYST_CVR (*(volatile uint32_t *)0xE000E018u)

static int32_t in_z[BENCH_N + WARM];
static volatile int32_t sink;

static AVG_MOVING_DEFINE(ma, 82);
static struct kf f1, f2;
static struct kf_adapt fa;
static struct tilt tl;
static const fx_q30_t one = FX_Q30_ONE;
static const int64_t q1 = KF_P_ONE_Q16 / 1000000;
static const struct kf_model m1 = {1, 0, &one, 0, &q1};
static const fx_q30_t a2[4] = {FX_Q30_ONE, -1310720, 0, FX_Q30_ONE}, b2[2] = {1310720, 0};
static const fx_q30_t h2[2] = {FX_Q30_ONE, 0};
static const int64_t q2[4] = {KF_P_ONE_Q16 / 800000, 0, 0, KF_P_ONE_Q16 / 4000000};
static const struct kf_model m2 = {2, 1, a2, b2, q2};

__attribute__((noinline)) static int32_t empty(int32_t z)
{
    __asm__ volatile("" ::: "memory");
    return z;
}

__attribute__((noinline)) static int32_t up_ma(int32_t z)
{
    int32_t y;
    bool full;
    (void)avg_moving_push(&ma, z, &y, &full);
    return y;
}

__attribute__((noinline)) static int32_t up_kf1(int32_t z)
{
    (void)kf_predict(&f1, &m1, 0);
    (void)kf_update_row(&f1, &one, KF_P_ONE_Q16 / 1000, z);
    return kf_x(&f1, 0);
}

__attribute__((noinline)) static int32_t up_kf2(int32_t z)
{
    int32_t u = z * 8;
    (void)kf_predict(&f2, &m2, &u);
    (void)kf_update_row(&f2, h2, KF_P_ONE_Q16 / 4, z);
    return kf_x(&f2, 0);
}

__attribute__((noinline)) static int32_t up_adapt(int32_t z)
{
    int32_t y;
    (void)kf_adapt_process(&fa, z, &y, 0);
    return y;
}

__attribute__((noinline)) static int32_t up_tilt(int32_t z)
{
    struct tilt_input in;
    struct tilt_output o;
    in.accel_g[0] = -3277 + z;
    in.accel_g[1] = 1311 - z;
    in.accel_g[2] = 65400 + z / 2;
    in.gyro_dps[0] = 32768 + 30 * z;
    in.gyro_dps[1] = -13107 - 30 * z;
    in.gyro_dps[2] = 0;
    in.flags = 0;
    (void)tilt_step(&tl, &in, 1220703u, &o);
    return o.angle_deg[0];
}

/* The 128-bit helpers the filters are built from, on covariance-sized operands (each figure
 * includes forming the operands: one or two 64-bit multiplies of its own). */
__attribute__((noinline)) static int32_t up_mul64(int32_t z)
{
    fx_i128_t p = fx_i128_mul((int64_t)z * 1234567891, (int64_t)z * 987654321 + 12345);
    return (int32_t)p.hi;
}
__attribute__((noinline)) static int32_t up_mul32(int32_t z)
{
    fx_i128_t p = fx_i128_mul((int64_t)z * 1234567891, 1310720);
    return (int32_t)p.hi;
}
__attribute__((noinline)) static int32_t up_div(int32_t z)
{
    int64_t q;
    /* a Kalman gain: v * 2^30 / s with v ~ 2^40, s ~ 2^42 */
    (void)fx_i128_div_i64(fx_i128_mul(((int64_t)1 << 40) + z, (int64_t)1 << 30),
                          ((int64_t)1 << 42) + 3 * (int64_t)z, &q);
    return (int32_t)q;
}

static void ticks_reset(void)
{
    SYST_CSR = 0;
    SYST_RVR = 0x00FFFFFFu;
    SYST_CVR = 0;
    SYST_CSR = 5u;
}

static void measure(const char *name, int32_t (*fn)(int32_t))
{
    uint32_t t0, t1, t2, t3;
    int i;
    for (i = 0; i < WARM; i++)
        sink += fn(in_z[i]);
    ticks_reset();
    t0 = SYST_CVR;
    for (i = 0; i < BENCH_N; i++)
        sink += fn(in_z[WARM + i]);
    t1 = SYST_CVR;
    t2 = SYST_CVR;
    for (i = 0; i < BENCH_N; i++)
        sink += empty(in_z[WARM + i]);
    t3 = SYST_CVR;
    printf("BENCH %s %lu %lu\n", name, (unsigned long)((t0 - t1) & 0xFFFFFFu),
           (unsigned long)((t2 - t3) & 0xFFFFFFu));
}

int main(void)
{
    uint32_t s = 0x1234567u;
    int i;
    struct kf_adapt_config ac = {32u,
                                 KF_P_ONE_Q16 / 100000000,
                                 41000,
                                 KF_P_ONE_Q16 / 5000,
                                 -FX_Q16_INT(238),
                                 KF_P_ONE_Q16 / 5000};
    static struct tilt_config tc;
    const int64_t p1 = KF_P_ONE_Q16, p2[4] = {KF_P_ONE_Q16, 0, 0, KF_P_ONE_Q16};
    for (i = 0; i < BENCH_N + WARM; i++) {
        in_z[i] = (int32_t)(unit_rand32(&s) % 1311u) - 655; /* +-0.01 g / deg of noise */
    }
    (void)avg_moving_init(&ma, ma_line, 82u, 82u);
    (void)kf_init(&f1, 1u, 0, &p1);
    (void)kf_init(&f2, 2u, 0, p2);
    (void)kf_adapt_init(&fa, &ac);
    printf("BENCH_N %d\n", BENCH_N);
    measure("fx_i128_mul_64x64", up_mul64);
    measure("fx_i128_mul_64x32", up_mul32);
    measure("fx_i128_mul_64x32+div_i64", up_div);
    measure("moving_average_N82", up_ma);
    measure("kf_n1_predict+update", up_kf1);
    measure("kf_n2_predict+update", up_kf2);
    measure("kf_adapt_process", up_adapt);
    for (i = 0; i < 3; i++) {
        static const char *const names[3] = {"tilt_step_feedback", "tilt_step_printed",
                                             "tilt_step_kf2"};
        (void)tilt_config_default(&tc, 1220703u);
        tc.mode = (uint32_t)i;
        (void)tilt_init(&tl, &tc);
        measure(names[i], up_tilt);
    }
    return 0;
}
