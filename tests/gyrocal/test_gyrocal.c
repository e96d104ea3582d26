/*
 * Gyro bias calibration (firmware/services/gyrocal) on the simulated ADIS1636x/1640x: defaults, gating
 * (refuses when moving or not settled, nothing written), each mode's result measured on the part
 * (the achieved bias: error-model bias + the part's offset register + the processor-side
 * correction), the exact command words (GLOB_CMD bit 3 = 0xBE08, never [ADI-IMU-QS]'s 0xBE04),
 * saturation (flagged, INC_ERR_RANGE), and aborts (motion during the manual average, during the
 * autonull fill, during the busy precision autonull; a temperature ramp), each leaving the old
 * offsets in the part.
 *
 * Noise here is white (the [ADI-IMU-QS] density) plus a constant bias per axis, so bounds are exact
 * statistics; the full ADIS noise model (flicker, random walk) is the benchmark's
 * (bench_gyrocal, and its small seeded CTest run gyrocal_bench_small).
 * Under QEMU and in the sanitizer build (UNIT_REDUCED) the averages and the thermal window are
 * shorter (said per constant).
 */
#include "rig.h"
#include "adis_imu_regs.h" /* white-box: the driver's register map */
#include "unit.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#if UNIT_REDUCED
#define MANUAL_N 1638u  /* 2 s instead of 100 s */
#define THERMAL_AVG 82u /* 0.1 s points, 1 s window */
#define THERMAL_SPAN 10u
#define VERIFY_N 819u
#define WARM_TAU_S 10.0 /* the 1 s thermal window needs a faster warm-up to notice it */
#else
#define MANUAL_N GYROCAL_MANUAL_SAMPLES
#define THERMAL_AVG 819u /* the defaults: 1 s points, 30 s window */
#define THERMAL_SPAN 30u
#define VERIFY_N 1638u
#define WARM_TAU_S 60.0
#endif
#define MONITOR_N (3u * 819u + THERMAL_AVG * THERMAL_SPAN)
#define FS 819.2
#define SIGMA (SIM_NOISE_ADIS_GYRO_ARW * 28.62167) /* per-sample sd: N sqrt(819.2) = 0.887 deg/s */

static const double bias3[3] = {0.7, -1.23, 0.031};

static struct sim_noise_cfg white_cfg(const double b[3])
{
    struct sim_noise_cfg c;
    unsigned a;
    memset(&c, 0, sizeof(c));
    for (a = 0; a < 3u; a++) {
        c.ch[SIM_NOISE_GYRO(a)].white = SIM_NOISE_ADIS_GYRO_ARW;
        c.ch[SIM_NOISE_GYRO(a)].bias = b[a];
        c.ch[SIM_NOISE_ACCEL(a)].white = SIM_NOISE_ADIS_ACCEL_WHITE;
    }
    c.seed = 4242;
    return c;
}

static struct gyrocal_cfg test_cfg(enum sim_adis_imu_variant v)
{
    struct gyrocal_cfg c;
    (void)gyrocal_default_cfg(&c, adis_imu_variant_info((enum adis_imu_variant)v),
                              ADIS_IMU_RANGE_300);
    c.manual_samples = MANUAL_N;
    c.thermal.avg_n = THERMAL_AVG;
    c.thermal.span = THERMAL_SPAN;
    c.verify_samples = VERIFY_N;
    return c;
}

static int setup(enum sim_adis_imu_variant v, const double b[3], const struct gyrocal_cfg *gc)
{
    const struct sim_noise_cfg nc = white_cfg(b);
    struct gyrocal_cfg c = gc != NULL ? *gc : test_cfg(v);
    int err = rig_setup(v, &nc, &c);
    if (err == INC_OK) {
        err = gyrocal_monitor(&rig.gc, MONITOR_N);
    }
    return err;
}

static void offsets_now(int32_t off[3])
{
    unsigned i;
    for (i = 0; i < 3u; i++) {
        off[i] = adis_sign_extend(
            sim_adis_imu_peek(&rig.part, (uint8_t)(ADIS_IMU_REG_XGYRO_OFF + 2u * i)), 13);
    }
}

static uint16_t flash_count(void)
{
    return sim_adis_imu_peek(&rig.part, ADIS_IMU_REG_FLASH_CNT);
}

/* ---- configuration ---- */

static void test_default_cfg(void)
{
    struct gyrocal_cfg c;
    CHECK_OK(
        gyrocal_default_cfg(&c, adis_imu_variant_info(ADIS_IMU_ADIS16364), ADIS_IMU_RANGE_300));
    CHECK_EQ_INT(c.still.window, 819);
    CHECK_EQ_INT(c.still.gyro_var_max, 519);  /* (1 deg/s / 0.05)^2 x 1.2967, +1 */
    CHECK_EQ_INT(c.still.accel_var_max, 130); /* (10 mg / 1 mg)^2 x 1.2967, +1 */
    CHECK_EQ_INT(c.still.gyro_mean_max, 100); /* 5 deg/s */
    CHECK_EQ_INT(c.still.accel_one_g, 1000);
    CHECK_EQ_INT(c.still.accel_norm_tol, 100);
    CHECK_EQ_INT(c.still.accel_drift_max, 3);
    CHECK_EQ_INT(c.thermal.avg_n, 819);
    CHECK_EQ_INT(c.thermal.span, 30);
    CHECK_EQ_INT(c.thermal.max_change, 1);
    CHECK_EQ_INT(c.manual_samples, 82000);
    CHECK(c.manual_to_register && c.flash_update);
    CHECK_EQ_INT(c.adev_q16[GYROCAL_AUTONULL], 5243);
    CHECK_EQ_INT(c.adev_q16[GYROCAL_PRECISION], 524);
    CHECK_EQ_INT(c.adev_q16[GYROCAL_MANUAL], 393);
    CHECK_OK(
        gyrocal_default_cfg(&c, adis_imu_variant_info(ADIS_IMU_ADIS16400), ADIS_IMU_RANGE_300));
    CHECK_EQ_INT(c.still.accel_var_max, 12); /* 3.333 mg LSB */
    CHECK_EQ_INT(c.still.accel_one_g, 300);
    CHECK_EQ_INT(c.still.accel_norm_tol, 30);
    CHECK_EQ_INT(c.still.accel_drift_max, 1);
    CHECK_OK(gyrocal_default_cfg(&c, adis_imu_variant_info(ADIS_IMU_ADIS16362), ADIS_IMU_RANGE_75));
    CHECK_EQ_INT(c.still.gyro_var_max, 8299); /* 0.0125 deg/s LSB */
    CHECK_EQ_INT(c.still.gyro_mean_max, 400);
    CHECK_EQ_INT(c.still.accel_one_g, 3003);
    CHECK_EQ_INT(c.still.accel_drift_max, 10);
    CHECK_ERR(
        gyrocal_default_cfg(&c, adis_imu_variant_info(ADIS_IMU_ADIS16362), (enum adis_imu_range)3),
        INC_ERR_INVAL);
    CHECK_ERR(gyrocal_default_cfg(&c, NULL, ADIS_IMU_RANGE_300), INC_ERR_NULL);
}

static void test_init_rejects(void)
{
    struct gyrocal g;
    struct gyrocal_cfg c;
    struct gyrocal_result res;
    struct adis_imu_sample s;
    const struct sim_noise_cfg nc = white_cfg(bias3);
    REQUIRE(rig_setup(SIM_ADIS16364, &nc, NULL) == INC_OK);
    c = rig.gcfg;
    CHECK_ERR(gyrocal_init(&g, NULL, &c), INC_ERR_NULL);
    c.manual_samples = 1;
    CHECK_ERR(gyrocal_init(&g, &rig.imu, &c), INC_ERR_INVAL);
    CHECK_ERR(gyrocal_run(&g, GYROCAL_AUTONULL, &res), INC_ERR_STATE);
    c = rig.gcfg;
    c.manual_samples = (1u << 18) + 1u;
    CHECK_ERR(gyrocal_init(&g, &rig.imu, &c), INC_ERR_INVAL);
    c = rig.gcfg;
    c.adev_q16[GYROCAL_PRECISION] = 0;
    CHECK_ERR(gyrocal_init(&g, &rig.imu, &c), INC_ERR_INVAL);
    c = rig.gcfg;
    c.verify_sigmas = 0;
    CHECK_ERR(gyrocal_init(&g, &rig.imu, &c), INC_ERR_INVAL);
    c = rig.gcfg;
    c.still.window = 1;
    CHECK_ERR(gyrocal_init(&g, &rig.imu, &c), INC_ERR_INVAL);
    c = rig.gcfg;
    c.thermal.span = 99;
    CHECK_ERR(gyrocal_init(&g, &rig.imu, &c), INC_ERR_INVAL);
    CHECK_ERR(gyrocal_run(&rig.gc, (enum gyrocal_mode)7, &res), INC_ERR_INVAL);
    memset(&s, 0, sizeof(s));
    CHECK_ERR(gyrocal_feed(&rig.gc, &s), INC_ERR_STALE); /* no valid channel */
    CHECK(strcmp(gyrocal_reason_text(GYROCAL_REFUSED_MOVING), "refused: the part is moving") == 0);
    CHECK(strcmp(gyrocal_reason_text((enum gyrocal_reason)99), "unknown") == 0);
}

static void test_correct_q16(void)
{
    struct gyrocal_correction c = {{1, -3, 32767}, true};
    CHECK_EQ_INT(gyrocal_correct_q16(&c, 0, 0), 205);           /* 204.8 */
    CHECK_EQ_INT(gyrocal_correct_q16(&c, 1, 1000), 1000 - 614); /* -614.4 */
    CHECK_EQ_INT(gyrocal_correct_q16(&c, 2, 0), 6710682);       /* 102.4 deg/s - 1/320 */
    CHECK_EQ_INT(gyrocal_correct_q16(&c, 2, INT32_MAX), INT32_MAX);
    CHECK_EQ_INT(gyrocal_correct_q16(&c, 3, 77), 77);
    c.valid = false;
    CHECK_EQ_INT(gyrocal_correct_q16(&c, 0, 77), 77);
}

/* ---- gating ---- */

static void test_refuses_moving(void)
{
    struct gyrocal_result res;
    int32_t before[3], after[3];
    uint16_t fc;
    unsigned m;
    REQUIRE(setup(SIM_ADIS16364, bias3, NULL) == INC_OK);
    CHECK(gyrocal_at_rest(&rig.gc));
    rig.motion.from_ns = rig_now();
    rig.motion.to_ns = UINT64_MAX;
    rig.motion.rate_dps = 10.0; /* steady 10 deg/s about z */
    REQUIRE(gyrocal_monitor(&rig.gc, 2u * 819u) == INC_OK);
    CHECK(!gyrocal_at_rest(&rig.gc));
    CHECK(rig.gc.still.last.why & STILL_WHY_GYRO_MEAN);
    offsets_now(before);
    fc = flash_count();
    for (m = 0; m < (unsigned)GYROCAL_MODES; m++) {
        CHECK_ERR(gyrocal_run(&rig.gc, (enum gyrocal_mode)m, &res), INC_ERR_MOTION);
        CHECK_EQ_INT(res.reason, GYROCAL_REFUSED_MOVING);
        CHECK_EQ_INT(res.new_offset[0], res.old_offset[0]);
    }
    offsets_now(after);
    CHECK(memcmp(before, after, sizeof(before)) == 0);
    CHECK_EQ_INT(flash_count(), fc);
    CHECK_EQ_INT(rig_cmd_seen(0xBE01), 0);
    CHECK_EQ_INT(rig_cmd_seen(0xBE10), 0);
    CHECK_EQ_INT(rig_cmd_seen(0xBE08), 0);
    /* vibration without net rotation is refused too */
    rig.motion.rate_dps = 0.0;
    rig.motion.vib_dps = 3.0;
    REQUIRE(gyrocal_monitor(&rig.gc, 2u * 819u) == INC_OK);
    CHECK_ERR(gyrocal_run(&rig.gc, GYROCAL_AUTONULL, &res), INC_ERR_MOTION);
    CHECK(rig.gc.still.last.why & STILL_WHY_GYRO_VAR);
    CHECK_EQ_INT(rig_violations(), 0);
}

static void test_refuses_thermal(void)
{
    struct gyrocal_result res;
    struct gyrocal_cfg c = test_cfg(SIM_ADIS16405);
    uint64_t t0;
    c.settle_timeout_ms = 3000;
    REQUIRE(setup(SIM_ADIS16405, bias3, &c) == INC_OK);
    /* warming: +8 C with a 60 s (QEMU: 10 s) time constant, from now */
    rig.temp.t0_ns = rig_now();
    rig.temp.rise_c = 8.0;
    rig.temp.tau_s = WARM_TAU_S;
    REQUIRE(gyrocal_monitor(&rig.gc, MONITOR_N) == INC_OK);
    CHECK(gyrocal_at_rest(&rig.gc));
    CHECK(!gyrocal_settled(&rig.gc));
    CHECK_ERR(gyrocal_run(&rig.gc, GYROCAL_AUTONULL, &res), INC_ERR_THERMAL);
    CHECK_EQ_INT(res.reason, GYROCAL_REFUSED_THERMAL);
    CHECK_ERR(gyrocal_run(&rig.gc, GYROCAL_PRECISION, &res), INC_ERR_THERMAL);
    t0 = rig_now();
    CHECK_ERR(gyrocal_run(&rig.gc, GYROCAL_MANUAL, &res), INC_ERR_THERMAL); /* waits 3 s first */
    CHECK(rig_now() - t0 >= 3000000000ull);
    CHECK(rig_now() - t0 < 3200000000ull);
    CHECK_EQ_INT(res.reason, GYROCAL_REFUSED_THERMAL);
    CHECK_EQ_HEX(rig.imu.smpl_prd, 0x0001u);
    CHECK_EQ_INT(rig_cmd_seen(0xBE01) + rig_cmd_seen(0xBE10) + rig_cmd_seen(0xBE08), 0);
#if !UNIT_REDUCED
    /* With the default 15 min it waits the warm-up out and then calibrates. */
    rig.gc.cfg.settle_timeout_ms = 15u * 60u * 1000u;
    t0 = rig_now();
    CHECK_OK(gyrocal_run(&rig.gc, GYROCAL_MANUAL, &res));
    printf("  manual waited %.0f s for settling\n", (double)(res.t_end_ns - t0) * 1e-9 - 100.0);
    CHECK(res.t_end_ns - t0 > 100000000000ull);
#endif
    CHECK_EQ_INT(rig_violations(), 0);
}

/* ---- the three modes ---- */

static void test_autonull(void)
{
    struct gyrocal_result res;
    double b[3];
    uint16_t fc;
    unsigned i;
    /* white noise through the 2 x 64-tap Bartlett: sd sigma sqrt((2N^2+1)/(3N^3)) */
    const double sd = SIGMA * sqrt((2.0 * 64 * 64 + 1.0) / (3.0 * 64 * 64 * 64));
    REQUIRE(setup(SIM_ADIS16364, bias3, NULL) == INC_OK);
    fc = flash_count();
    CHECK_OK(gyrocal_run(&rig.gc, GYROCAL_AUTONULL, &res));
    CHECK_EQ_INT(res.reason, GYROCAL_DONE);
    CHECK_EQ_INT(rig_cmd_seen(0xBE01), 1);
    CHECK_EQ_INT(rig_cmd_seen(0xBE08), 1); /* flash update after the verification */
    CHECK_EQ_INT(flash_count(), fc + 1u);
    CHECK_EQ_HEX(rig.imu.sens_avg, 0x0402u); /* the user's filter is back */
    CHECK_EQ_HEX(rig.imu.smpl_prd, 0x0001u);
    CHECK_EQ_INT(res.residual_q16[0], 5248); /* sqrt(5243^2 + 819^2 / 12) */
    rig_bias_mean(0.15, b);
    for (i = 0; i < 3u; i++) {
        CHECK_NEAR(res.new_offset[i], -80.0 * bias3[i], 80.0 * 4.0 * sd + 0.5);
        CHECK_NEAR(b[i], 0.0, 4.0 * sd + 0.00625);
        CHECK(fabs((double)res.verify_mean_q16[i]) <= (double)res.verify_limit_q16[i]);
    }
    printf("  autonull: achieved %.4f %.4f %.4f deg/s (sd %.3f)\n", b[0], b[1], b[2], sd);
    CHECK_EQ_INT(rig_violations(), 0);
}

static void test_precision(void)
{
    struct gyrocal_result res;
    double b[3];
    unsigned i;
    const double sd = SIGMA / sqrt(30.0 * FS);
    REQUIRE(setup(SIM_ADIS16405, bias3, NULL) == INC_OK);
    CHECK_OK(gyrocal_run(&rig.gc, GYROCAL_PRECISION, &res));
    CHECK_EQ_INT(rig_cmd_seen(0xBE10), 1);
    CHECK_EQ_INT(res.residual_q16[1], 575); /* sqrt(524^2 + 819^2 / 12) */
    CHECK(res.t_end_ns - res.t_start_ns >= 30000000000ull);
    rig_bias_mean(1.0, b);
    for (i = 0; i < 3u; i++) {
        CHECK_NEAR(b[i], 0.0, 4.0 * sd + 0.00625);
    }
    printf("  precision: achieved %.4f %.4f %.4f deg/s (sd %.4f)\n", b[0], b[1], b[2], sd);
    CHECK_EQ_INT(rig_violations(), 0);
}

static void test_manual(void)
{
    struct gyrocal_result res;
    struct gyrocal_correction c;
    int32_t off[3];
    double b[3];
    uint16_t fc;
    unsigned i;
    const double se = SIGMA / sqrt((double)MANUAL_N);
    REQUIRE(setup(SIM_ADIS16400, bias3, NULL) == INC_OK);
    fc = flash_count();
    CHECK_OK(gyrocal_run(&rig.gc, GYROCAL_MANUAL, &res));
    CHECK_EQ_INT(res.samples, MANUAL_N);
    CHECK_EQ_INT(res.missed, 0);
    CHECK_EQ_INT(rig_cmd_seen(0xBE08), 1); /* GLOB_CMD[3]: bit 3 */
    CHECK_EQ_INT(rig_cmd_seen(0xBE04), 0); /* never [ADI-IMU-QS]'s typo word (AUX DAC latch) */
    CHECK_EQ_INT(flash_count(), fc + 1u);
    c = gyrocal_correction_get(&rig.gc);
    CHECK(c.valid);
    for (i = 0; i < 3u; i++) {
        /* offset = old - round(80 x mean); mean_q16 is that mean */
        CHECK_NEAR(res.new_offset[i], res.old_offset[i] - 80.0 * res.mean_q16[i] / 65536.0, 0.51);
        CHECK_NEAR(res.mean_q16[i] / 65536.0, bias3[i], 4.0 * se + 0.05 / sqrt(12.0 * MANUAL_N));
        CHECK(c.corr[i] >= -2 && c.corr[i] <= 2); /* what the 0.0125 register could not take */
        CHECK_EQ_INT(res.proc_corr[i], c.corr[i]);
    }
    rig_bias_mean(1.0, b); /* register + processor-side correction */
    for (i = 0; i < 3u; i++) {
        CHECK_NEAR(b[i], 0.0, 4.0 * se + 1.0 / 640.0);
    }
    printf("  manual: achieved %.5f %.5f %.5f deg/s (se %.5f), residual estimate %.5f\n", b[0],
           b[1], b[2], se, res.residual_q16[0] / 65536.0);
    /* the flash holds it: a software reset brings the same offsets back */
    CHECK_OK(adis_imu_command(&rig.imu, ADIS_IMU_CMD_SW_RESET));
    for (i = 0; i < 3u; i++) {
        CHECK_OK(adis_imu_get_gyro_offset(&rig.imu, i, &off[i]));
        CHECK_EQ_INT(off[i], res.new_offset[i]);
    }
    CHECK_EQ_INT(rig_violations(), 0);
}

static void test_manual_processor_only(void)
{
    struct gyrocal_result res;
    struct gyrocal_cfg c = test_cfg(SIM_ADIS16364);
    int32_t before[3], after[3];
    double b[3];
    unsigned i;
    const double se = SIGMA / sqrt((double)MANUAL_N);
    c.manual_to_register = false;
    REQUIRE(setup(SIM_ADIS16364, bias3, &c) == INC_OK);
    offsets_now(before);
    CHECK_OK(gyrocal_run(&rig.gc, GYROCAL_MANUAL, &res));
    offsets_now(after);
    CHECK(memcmp(before, after, sizeof(before)) == 0); /* the part is left alone */
    CHECK_EQ_INT(rig_cmd_seen(0xBE08), 0);
    for (i = 0; i < 3u; i++) {
        CHECK_NEAR(res.proc_corr[i], -320.0 * bias3[i], 320.0 * (4.0 * se) + 1.0);
    }
#if !UNIT_REDUCED
    CHECK_EQ_INT(res.residual_q16[0], 397); /* sqrt(393^2 + 205^2 / 12): [ADI-IMU-QS]'s 0.006 */
#endif
    rig_bias_mean(1.0, b);
    for (i = 0; i < 3u; i++) {
        CHECK_NEAR(b[i], 0.0, 4.0 * se + 1.0 / 640.0);
    }
    CHECK_EQ_INT(rig_violations(), 0);
}

/* A short manual average (2 s): the measured standard error exceeds [ADI-IMU-QS]'s 0.006 deg/s and
 * becomes the residual estimate. The part filters with its default SENS_AVG (M = 2), which
 * lowers the per-sample noise but not the noise of the mean; the estimate must not be fooled
 * (it would read 0.41 of the truth). */
static void test_residual_estimate(void)
{
    struct gyrocal_result res;
    struct gyrocal_cfg c = test_cfg(SIM_ADIS16364);
    const double se = SIGMA / sqrt(1638.0);
    const double want = sqrt(se * se + 0.0125 * 0.0125 / 12.0) * 65536.0;
    unsigned i;
    c.manual_samples = 1638;
    REQUIRE(setup(SIM_ADIS16364, bias3, &c) == INC_OK);
    CHECK_EQ_HEX(rig.imu.sens_avg, 0x0402u);
    CHECK_OK(gyrocal_run(&rig.gc, GYROCAL_MANUAL, &res));
    for (i = 0; i < 3u; i++) {
        CHECK_NEAR(res.residual_q16[i], want, 0.08 * want);
    }
    printf("  residual estimate after 2 s: %.4f %.4f %.4f deg/s (expected %.4f)\n",
           res.residual_q16[0] / 65536.0, res.residual_q16[1] / 65536.0,
           res.residual_q16[2] / 65536.0, want / 65536.0);
    CHECK_EQ_INT(rig_violations(), 0);
}

/* A 60 deg/s bias is beyond the 13-bit register (+-51.2 deg/s): saturated, flagged, written; the
 * processor-side correction takes the rest. The steady-rotation test must be off to allow it
 * (from the part alone, 60 deg/s of bias looks like rotation). */
static void test_saturation(void)
{
    static const double big[3] = {60.0, -60.0, 0.2};
    struct gyrocal_result res;
    struct gyrocal_cfg c = test_cfg(SIM_ADIS16364);
    double b[3];
    c.still.gyro_mean_max = 0;
    REQUIRE(setup(SIM_ADIS16364, big, &c) == INC_OK);
    CHECK_ERR(gyrocal_run(&rig.gc, GYROCAL_MANUAL, &res), INC_ERR_RANGE);
    CHECK_EQ_INT(res.reason, GYROCAL_SATURATED);
    CHECK_EQ_INT(res.new_offset[0], -4096);
    CHECK_EQ_INT(res.new_offset[1], 4095);
    CHECK(res.saturated[0] && res.saturated[1] && !res.saturated[2]);
    CHECK(!res.proc_saturated[0]);
    CHECK_NEAR(res.proc_corr[0], -320.0 * (60.0 - 51.2), 20.0);
    rig_bias_mean(1.0, b);
    CHECK_NEAR(b[0], 0.0, 0.05);
    CHECK_NEAR(b[1], 0.0, 0.05);
    /* autonull: the part saturates by itself; the flag comes from the read-back */
    CHECK_ERR(gyrocal_run(&rig.gc, GYROCAL_AUTONULL, &res), INC_ERR_RANGE);
    CHECK(res.saturated[0] && res.saturated[1]);
    CHECK_EQ_INT(rig_violations(), 0);
}

/* ---- aborts ---- */

static void test_motion_during_manual(void)
{
    struct gyrocal_result res;
    int32_t before[3], after[3];
    REQUIRE(setup(SIM_ADIS16364, bias3, NULL) == INC_OK);
    offsets_now(before);
    rig.motion.from_ns = rig_now() + (uint64_t)(MANUAL_N / FS * 0.5e9);
    rig.motion.to_ns = rig.motion.from_ns + 300000000u; /* 0.3 s at 30 deg/s: 9 deg */
    rig.motion.rate_dps = 30.0;
    CHECK_ERR(gyrocal_run(&rig.gc, GYROCAL_MANUAL, &res), INC_ERR_MOTION);
    CHECK_EQ_INT(res.reason, GYROCAL_ABORTED_MOTION);
    CHECK(res.samples < MANUAL_N); /* stopped at the first bad window */
    offsets_now(after);
    CHECK(memcmp(before, after, sizeof(before)) == 0);
    CHECK_EQ_INT(res.new_offset[1], before[1]);
    CHECK_EQ_INT(rig_cmd_seen(0xBE08), 0);
    CHECK(!gyrocal_correction_get(&rig.gc).valid);
    CHECK_EQ_INT(rig_violations(), 0);
}

static void test_motion_during_autonull(void)
{
    struct gyrocal_result res;
    int32_t before[3], after[3];
    REQUIRE(setup(SIM_ADIS16364, bias3, NULL) == INC_OK);
    offsets_now(before);
    rig.motion.from_ns = rig_now() + 50000000u; /* in the 200 ms fill */
    rig.motion.to_ns = rig.motion.from_ns + 100000000u;
    rig.motion.rate_dps = 20.0;
    CHECK_ERR(gyrocal_run(&rig.gc, GYROCAL_AUTONULL, &res), INC_ERR_MOTION);
    CHECK_EQ_INT(res.reason, GYROCAL_ABORTED_MOTION);
    offsets_now(after);
    CHECK(memcmp(before, after, sizeof(before)) == 0);
    CHECK_EQ_HEX(rig.imu.sens_avg, 0x0402u);
    CHECK_EQ_INT(rig_cmd_seen(0xBE08), 0);
    CHECK_EQ_INT(rig_violations(), 0);
}

/* The part is busy for the 30 s of precision autonull: a turn then is invisible to the
 * detectors, but it biases the part's average (3 deg/s for 28 s: 2.8 deg/s); the verification
 * of the corrected output catches it and the old offsets go back. */
static void test_motion_during_precision(void)
{
    struct gyrocal_result res;
    int32_t before[3], after[3];
    REQUIRE(setup(SIM_ADIS16405, bias3, NULL) == INC_OK);
    offsets_now(before);
    rig.motion.from_ns = rig_now() + 1000000000u;
    rig.motion.to_ns = rig.motion.from_ns + 28000000000ull;
    rig.motion.rate_dps = 3.0;
    CHECK_ERR(gyrocal_run(&rig.gc, GYROCAL_PRECISION, &res), INC_ERR_ABORTED);
    CHECK_EQ_INT(res.reason, GYROCAL_ABORTED_VERIFY);
    CHECK(fabs(res.verify_mean_q16[2] / 65536.0 + 2.8) < 0.2);
    CHECK(fabs((double)res.verify_mean_q16[2]) > (double)res.verify_limit_q16[2]);
    offsets_now(after);
    CHECK(memcmp(before, after, sizeof(before)) == 0);
    CHECK_EQ_INT(rig_cmd_seen(0xBE10), 1);
    CHECK_EQ_INT(rig_cmd_seen(0xBE08), 0);
    CHECK_EQ_INT(rig_violations(), 0);
}

static void test_thermal_during_manual(void)
{
    struct gyrocal_result res;
    int32_t before[3], after[3];
    REQUIRE(setup(SIM_ADIS16364, bias3, NULL) == INC_OK);
    offsets_now(before);
    rig.temp.ramp_from_ns = rig_now() + (uint64_t)(MANUAL_N / FS * 0.3e9);
    rig.temp.ramp_c_per_s = 0.5; /* 0.5 C/s: 4 LSB per second */
    CHECK_ERR(gyrocal_run(&rig.gc, GYROCAL_MANUAL, &res), INC_ERR_THERMAL);
    CHECK_EQ_INT(res.reason, GYROCAL_ABORTED_THERMAL);
    offsets_now(after);
    CHECK(memcmp(before, after, sizeof(before)) == 0);
    CHECK_EQ_INT(rig_cmd_seen(0xBE08), 0);
    CHECK_EQ_INT(rig_violations(), 0);
}

int main(void)
{
    UNIT_RUN(test_default_cfg);
    UNIT_RUN(test_init_rejects);
    UNIT_RUN(test_correct_q16);
    UNIT_RUN(test_refuses_moving);
    UNIT_RUN(test_refuses_thermal);
    UNIT_RUN(test_autonull);
    UNIT_RUN(test_precision);
    UNIT_RUN(test_manual);
    UNIT_RUN(test_manual_processor_only);
    UNIT_RUN(test_residual_estimate);
    UNIT_RUN(test_saturation);
    UNIT_RUN(test_motion_during_manual);
    UNIT_RUN(test_motion_during_autonull);
    UNIT_RUN(test_motion_during_precision);
    UNIT_RUN(test_thermal_during_manual);
    return unit_report();
}
