/*
 * Gyro bias commands of the ADIS1636x/1640x, measured on the simulated part: the error-model
 * hook gives the gyros a bias (and, for precision autonull, seeded white noise); the driver runs
 * the procedures of [ADI-IMU-QS]; the test reads the bias actually achieved from the model
 * (sim_adis_imu_gyro_dps: the output before quantisation) and the offsets from the part.
 *
 * Also the seed's manual calibration over 100 s at 819.2 SPS through the pin-level bus
 * (82 000 reads), which keeps the per-sample cost of the model and the driver in view. Under
 * QEMU it runs 2 s.
 */
#include "fixture.h"
#include "adis_imu_regs.h" /* white-box: the driver's register map */
#include "unit.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* ---- error model: constant bias + seeded white noise; it also sums what the part averaged ---- */

struct bias_model {
    double bias[3];
    double noise_dps; /* white noise rms per sample (0: none) */
    struct sim_rng rng;
    const struct sim_adis_imu *part;
    double prec_sum[3]; /* rates the part saw while precision autonull ran */
    uint32_t prec_n;
    uint32_t calls;
};

static struct bias_model bm;

static void bias_apply(void *ctx, const struct sim_inertial_input *in,
                       struct sim_inertial_input *out, uint64_t t_ns, double dt_s)
{
    struct bias_model *b = ctx;
    unsigned i;
    (void)t_ns;
    (void)dt_s;
    *out = *in;
    for (i = 0; i < 3u; i++) {
        out->rate_dps[i] += b->bias[i];
        if (b->noise_dps > 0.0) {
            out->rate_dps[i] += b->noise_dps * sim_rng_gauss(&b->rng);
        }
    }
    if (b->part != NULL && b->part->prec_active) {
        for (i = 0; i < 3u; i++) {
            b->prec_sum[i] += out->rate_dps[i];
        }
        b->prec_n++;
    }
    b->calls++;
}

static const struct sim_error_model bias_hook = {bias_apply, &bm};

static void setup_biased(enum sim_adis_imu_variant v, double bx, double by, double bz, double noise)
{
    memset(&bm, 0, sizeof(bm));
    bm.bias[0] = bx;
    bm.bias[1] = by;
    bm.bias[2] = bz;
    bm.noise_dps = noise;
    sim_rng_seed(&bm.rng, 2024u);
    fx_prepare(v);
    fx.part_cfg.error = &bias_hook;
    fx_start();
    bm.part = &fx.part;
}

static int32_t round_half_away(double x)
{
    return (int32_t)(x < 0.0 ? -floor(-x + 0.5) : floor(x + 0.5));
}

/* The hook is in the signal path: a constant bias shows in the output registers. */
static void test_error_model_hook(void)
{
    struct adis_imu_sample s;
    setup_biased(SIM_ADIS16405, 0.7, -1.23, 0.031, 0.0);
    REQUIRE(fx_init() == 0);
    fx_wait_ms(200); /* the filter settles on the biased input */
    CHECK_OK(adis_imu_dr_flush(&fx.imu));
    CHECK_OK(adis_imu_wait_ready(&fx.imu, 0, NULL));
    CHECK_OK(adis_imu_read_sample(&fx.imu, &s));
    CHECK_EQ_INT(s.counts[ADIS_IMU_CH_GYRO_X], 14);  /* 0.7 / 0.05 */
    CHECK_EQ_INT(s.counts[ADIS_IMU_CH_GYRO_Y], -25); /* -1.23 / 0.05 = -24.6 */
    CHECK_EQ_INT(s.counts[ADIS_IMU_CH_GYRO_Z], 1);   /* 0.62 */
    CHECK(bm.calls > 300u);
    CHECK_EQ_INT(fx_violations(), 0);
}

/* [ADI-IMU-QS] autonull: SMPL_PRD = 0x01, SENS_AVG = 0x06, 200 ms for the taps to fill, then
 * GLOB_CMD[0]. The part writes -(output) in 0.0125 deg/s LSB: the bias is removed to within half
 * an offset LSB (0.00625 deg/s). */
static void test_autonull(void)
{
    static const double b[3] = {0.7, -1.23, 0.031};
    struct adis_imu_sample s;
    int32_t off[3];
    unsigned i;
    setup_biased(SIM_ADIS16364, b[0], b[1], b[2], 0.0);
    REQUIRE(fx_init() == 0);
    CHECK_OK(adis_imu_set_sample_period(&fx.imu, 0x01));
    CHECK_OK(adis_imu_set_filter(&fx.imu, 6, ADIS_IMU_RANGE_300));
    fx_wait_ms(200);
    CHECK_OK(adis_imu_command(&fx.imu, ADIS_IMU_CMD_AUTONULL));
    for (i = 0; i < 3u; i++) {
        CHECK_OK(adis_imu_get_gyro_offset(&fx.imu, i, &off[i]));
        CHECK_EQ_INT(off[i], round_half_away(-b[i] * 80.0)); /* -56, 98, -2 */
        CHECK(fabs(sim_adis_imu_gyro_dps(&fx.part, i)) <= 0.00625 + 1e-12);
    }
    CHECK_EQ_INT(off[1], 98);
    /* The outputs read zero now. */
    CHECK_OK(adis_imu_dr_flush(&fx.imu));
    CHECK_OK(adis_imu_wait_ready(&fx.imu, 0, NULL));
    CHECK_OK(adis_imu_read_sample(&fx.imu, &s));
    for (i = 0; i < 3u; i++) {
        CHECK_EQ_INT(s.counts[ADIS_IMU_CH_GYRO_X + i], 0);
    }
    /* Again, from a wrong offset already in place: the result is the same (new = old - out). */
    CHECK_OK(adis_imu_set_gyro_offset(&fx.imu, 0, 300));
    fx_wait_ms(200);
    CHECK_OK(adis_imu_command(&fx.imu, ADIS_IMU_CMD_AUTONULL));
    CHECK_OK(adis_imu_get_gyro_offset(&fx.imu, 0, &off[0]));
    CHECK_EQ_INT(off[0], -56);
    /* Flash update keeps it over a reset. */
    CHECK_OK(adis_imu_command(&fx.imu, ADIS_IMU_CMD_FLASH_UPDATE));
    CHECK_OK(adis_imu_command(&fx.imu, ADIS_IMU_CMD_SW_RESET));
    CHECK_OK(adis_imu_get_gyro_offset(&fx.imu, 1, &off[1]));
    CHECK_EQ_INT(off[1], 98);
    CHECK_EQ_INT(fx_violations(), 0);
}

/* A bias beyond the 13-bit register (+-51.2 deg/s) saturates the offset. */
static void test_autonull_saturates(void)
{
    int32_t off = 0;
    setup_biased(SIM_ADIS16400, 60.0, -60.0, 0.0, 0.0);
    REQUIRE(fx_init() == 0);
    fx_wait_ms(200);
    CHECK_OK(adis_imu_command(&fx.imu, ADIS_IMU_CMD_AUTONULL));
    CHECK_OK(adis_imu_get_gyro_offset(&fx.imu, 0, &off));
    CHECK_EQ_INT(off, -4096);
    CHECK_OK(adis_imu_get_gyro_offset(&fx.imu, 1, &off));
    CHECK_EQ_INT(off, 4095);
    CHECK_NEAR(sim_adis_imu_gyro_dps(&fx.part, 0), 60.0 - 51.2, 1e-9);
    CHECK_EQ_INT(fx_violations(), 0);
}

/* Precision autonull: GLOB_CMD[4]; the part averages 30 s at 819.2 SPS (its own rate, whatever
 * SMPL_PRD says) and writes -(mean). With 0.5 deg/s rms noise per sample the mean of 24 576
 * samples is within 4 sigma = 0.0128 deg/s of the bias. */
static void test_precision_autonull(void)
{
    static const double b[3] = {-0.4321, 0.25, 2.0};
    int32_t off[3];
    uint64_t t0;
    unsigned i;
    setup_biased(SIM_ADIS16405, b[0], b[1], b[2], 0.5);
    REQUIRE(fx_init() == 0);
    CHECK_OK(adis_imu_set_sample_period(&fx.imu, 0x20)); /* low power: the part ignores it */
    t0 = fx.board.clk.now_ns;
    CHECK_OK(adis_imu_command_start(&fx.imu, ADIS_IMU_CMD_PRECISION_AUTONULL));
    CHECK(adis_imu_busy(&fx.imu));
    CHECK_NEAR(sim_adis_imu_rate_sps(&fx.part), 819.2, 1e-9);
    /* The next request waits the 30 s out; nothing touches the busy part. */
    CHECK_OK(adis_imu_get_gyro_offset(&fx.imu, 0, &off[0]));
    CHECK(fx.board.clk.now_ns - t0 >= 30000000000ull);
    CHECK(bm.prec_n >= 24575u && bm.prec_n <= 24577u);
    for (i = 0; i < 3u; i++) {
        const double mean = bm.prec_sum[i] / (double)bm.prec_n;
        CHECK_OK(adis_imu_get_gyro_offset(&fx.imu, i, &off[i]));
        CHECK_EQ_INT(off[i], round_half_away(-mean * 80.0)); /* exactly what the part averaged */
        CHECK(fabs(b[i] + off[i] * 0.0125) <= 0.00625 + 4.0 * 0.5 / sqrt(24576.0));
    }
    CHECK_EQ_INT(off[2], -160);
    /* The part is back at its own SMPL_PRD. */
    CHECK_NEAR(sim_adis_imu_rate_sps(&fx.part), 1638.4 / 33.0, 1e-9);
    CHECK_OK(adis_imu_wait_ready(&fx.imu, 0, NULL));
    CHECK_EQ_INT(fx_violations(), 0);
}

/*
 * [ADI-IMU-QS] manual calibration: average 82 000 samples at 819.2 SPS (100 s), x80, round, write,
 * GLOB_CMD[3]. Three gyro registers (4 frames) per data-ready, through the pin-level bus.
 */
static void test_manual_calibration_100s(void)
{
#if UNIT_REDUCED
    const uint32_t n = 1640u; /* 2 s under QEMU */
#else
    const uint32_t n = 82000u;
#endif
    static const double b[3] = {0.1234, -0.0567, 0.0071};
    int64_t sum[3] = {0, 0, 0};
    struct adis_imu_sample s;
    uint32_t k, missed = 0, missed_total = 0;
    uint16_t cnt = 0;
    unsigned i;
    setup_biased(SIM_ADIS16400, b[0], b[1], b[2], 0.5);
    REQUIRE(fx_init() == 0);
    CHECK_OK(adis_imu_set_filter(&fx.imu, 0, ADIS_IMU_RANGE_300));
    for (k = 0; k < n; k++) {
        if (adis_imu_wait_ready(&fx.imu, 0, &missed) != INC_OK ||
            adis_imu_read_channels(&fx.imu, ADIS_IMU_CH_GYROS, &s) != INC_OK) {
            break;
        }
        missed_total += missed;
        for (i = 0; i < 3u; i++) {
            sum[i] += s.counts[ADIS_IMU_CH_GYRO_X + i];
        }
    }
    CHECK_EQ_INT(k, n);
    CHECK_EQ_INT(missed_total, 0);
    CHECK_EQ_INT(fx.imu.reg_reads, n);
    for (i = 0; i < 3u; i++) {
        /* mean deg/s = sum x 0.05 / n; offset = -round(mean x 80) = -round(sum x 4 / n) */
        const double mean = (double)sum[i] * 0.05 / (double)n;
        const int32_t o = round_half_away(-(double)sum[i] * 4.0 / (double)n);
        CHECK(fabs(mean - b[i]) <= 4.0 * sqrt(0.5 * 0.5 + 0.05 * 0.05 / 12.0) / sqrt((double)n));
        CHECK_OK(adis_imu_set_gyro_offset(&fx.imu, i, o));
        CHECK(fabs(sim_adis_imu_gyro_offset_dps(&fx.part, i) + mean) <= 0.00625 + 1e-12);
    }
    CHECK_OK(adis_imu_command(&fx.imu, ADIS_IMU_CMD_FLASH_UPDATE));
    CHECK_OK(adis_imu_read_reg(&fx.imu, ADIS_IMU_REG_FLASH_CNT, &cnt));
    CHECK_EQ_INT(cnt, 1);
    printf("manual calibration: %u samples, %.3f s virtual\n", (unsigned)n,
           (double)fx.board.clk.now_ns * 1e-9);
    CHECK_EQ_INT(fx_violations(), 0);
}

int main(void)
{
    UNIT_RUN(test_error_model_hook);
    UNIT_RUN(test_autonull);
    UNIT_RUN(test_autonull_saturates);
    UNIT_RUN(test_precision_autonull);
    UNIT_RUN(test_manual_calibration_100s);
    return unit_report();
}
