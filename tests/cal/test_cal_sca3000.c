/*
 * The calibration chain on a device model: the simulated part's errors (sim/calpart.h, part A:
 * [TEMP-LORENTZ]'s temperature curves, [ADI-EPB]'s nonlinearity, misalignment) plugged into the SCA3000
 * register model through its error-model hook, read by the SCA3000 driver over the bit-banged
 * SPI of the simulated board, and corrected by firmware/signal/cal:
 *   1. the counts read over SPI are exactly the error model's output quantised at 0.75 mg;
 *   2. the on-device six-position procedure (driver reads, cal_avg, cal_six_position) gives
 *      the flip offset and gain of those counts;
 *   3. a record made by the calibration station for this part (golden_record_a.h, host tool)
 *      is decoded against the identity the driver reads, and cal_acc_* with the driver's
 *      temperature corrects level and tilted readings over -20..60 degC to within 1.5 mg, where
 *      the uncorrected part is off by more than 10 mg.
 * Host and QEMU.
 */
#include "inclino/cal.h"
#include "inclino/sca3000.h"
#include "inclino/sim/board.h"
#include "inclino/sim/calpart.h"
#include "inclino/sim/sca3000.h"
#include "cal_test.h"
#include "golden_record_a.h"

#include <string.h>

#define SAMPLE_NS 11000000u /* longer than the model's sample period: each read is a new sample */

static struct sim_board board;
static struct sim_sca3000 part;
static struct sim_calpart errs;
static struct sca3000 dev;

static int setup(void)
{
    struct sim_sca3000_cfg pc;
    struct sca3000_cfg cfg;
    struct sim_calpart_params p;
    struct sim_error_model em;
    int err;
    memset(&board, 0, sizeof board);
    err = sim_board_init(&board);
    if (err != 0) return err;
    memset(&pc, 0, sizeof pc);
    pc.bus = &board.bus;
    pc.cs = SIM_BOARD_CS(0);
    pc.sclk = SIM_BOARD_SCLK;
    pc.mosi = SIM_BOARD_MOSI;
    pc.miso = SIM_BOARD_MISO;
    pc.int_pin = SIM_BOARD_DR(0);
    pc.variant = SIM_SCA3000_D01;
    pc.log = &board.log;
    err = sim_sca3000_init(&part, &pc);
    if (err != 0) return err;
    /* Part A without noise, so that the counts can be predicted exactly. */
    sim_calpart_paper(&p);
    p.acc_noise_g = 0.0;
    sim_calpart_init(&errs, &p, 1);
    em = sim_calpart_error_model(&errs);
    sim_sca3000_set_error_model(&part, &em);
    memset(&cfg, 0, sizeof cfg);
    cfg.bus = &board.spi.bus;
    cfg.cs = SIM_BOARD_CS(0);
    cfg.variant = SCA3000_D01;
    cfg.hal = &board.hal;
    cfg.int_pin = SIM_BOARD_DR(0);
    return sca3000_init(&dev, &cfg);
}

static void input(const double f[3], double t)
{
    struct sim_inertial_input in;
    sim_inertial_at_rest(&in);
    in.accel_g[0] = f[0];
    in.accel_g[1] = f[1];
    in.accel_g[2] = f[2];
    in.temp_c = t;
    sim_sca3000_set_input(&part, &in);
}

/* Mean of n readings through the driver, nominal-scaled to g Q16. */
static int read_mean(unsigned n, fx_q16_t mean[3], int16_t last[3])
{
    struct cal_avg a;
    unsigned k, i;
    cal_avg_reset(&a);
    for (k = 0; k < n; k++) {
        int32_t g[3];
        int err;
        sim_clock_advance_to(&board.clk, board.clk.now_ns + SAMPLE_NS);
        err = sca3000_read_accel(&dev, last);
        if (err != INC_OK) return err;
        for (i = 0; i < 3u; i++) {
            err = sca3000_accel_g_from_counts(last[i], SCA3000_D01, &g[i]);
            if (err != INC_OK) return err;
        }
        err = cal_avg_add(&a, g);
        if (err != INC_OK) return err;
    }
    return cal_avg_mean(&a, INT32_MAX, mean);
}

/* The driver's temperature in Q16 degC. */
static int read_temp(fx_q16_t *t)
{
    uint16_t raw = 0;
    int err = sca3000_read_temp(&dev, &raw);
    return err ? err : sca3000_temp_c_from_counts(raw, t);
}

/* Counts the error model must produce for specific force f at temperature t (noise off). */
static void expected_counts(const double f[3], double t, int32_t c[3])
{
    struct sim_inertial_input in, out;
    struct sim_calpart copy = errs; /* same hysteresis state, no side effect on the real one */
    unsigned i;
    sim_inertial_at_rest(&in);
    for (i = 0; i < 3u; i++)
        in.accel_g[i] = f[i];
    in.temp_c = t;
    sim_calpart_apply(&copy, &in, &out, 0, 0.0);
    for (i = 0; i < 3u; i++)
        c[i] = sim_quantise(out.accel_g[i], 0.00075, 13, NULL);
}

static void test_hook_and_six_position(void)
{
    static const double faces[CAL_FACES][3] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                               {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
    fx_q16_t mean[CAL_FACES][3], off[3], exp_q16[CAL_FACES][3];
    fx_q30_t gain[3];
    unsigned f, i;
    REQUIRE(setup() == INC_OK);
    for (f = 0; f < CAL_FACES; f++) {
        int16_t last[3];
        int32_t c[3];
        input(faces[f], 25.0);
        REQUIRE(read_mean(8, mean[f], last) == INC_OK);
        expected_counts(faces[f], 25.0, c);
        for (i = 0; i < 3u; i++) {
            CHECK_EQ_INT(last[i], c[i]); /* the error model's output, exactly, over SPI */
            REQUIRE(sca3000_accel_g_from_counts(c[i], SCA3000_D01, &exp_q16[f][i]) == INC_OK);
            CHECK_EQ_INT(mean[f][i], exp_q16[f][i]);
        }
    }
    CHECK_OK(cal_six_position((const fx_q16_t(*)[3])mean, off, gain));
    for (i = 0; i < 3u; i++) {
        fx_q16_t o;
        fx_q30_t g;
        REQUIRE(cal_flip(exp_q16[2 * i][i], exp_q16[2 * i + 1][i], &o, &g) == INC_OK);
        CHECK_EQ_INT(off[i], o);
        CHECK_EQ_INT(gain[i], g);
        /* Against the part: the flip offset is the bias plus the even nonlinearity (nl2 * K),
         * the gain the scale factor times (1 + nl3) ([ADI-EPB]'s flip sees both), within the
         * 0.75 mg quantisation. */
        CHECK_NEAR(off[i] / CALT_Q16,
                   sim_calpart_tcurve_eval(&errs.p.acc_bias[i], 25.0, errs.m) +
                       errs.p.acc_nl2[i] *
                           sim_calpart_tcurve_eval(&errs.p.acc_scale[i], 25.0, errs.m),
                   0.0004);
    }
    CHECK(board.log.total == 0u);
}

static void test_station_record_on_the_part(void)
{
    static const double temps[] = {-20.0, -5.0, 25.0, 42.0, 60.0};
    static const double tilts_deg[] = {0.0, 20.0, -30.0};
    struct calrec_binding id;
    struct calrec rec;
    struct cal_acc st;
    double worst_cal = 0.0, worst_raw = 0.0;
    unsigned k, j, i;
    REQUIRE(setup() == INC_OK);
    /* The binding the application builds from what the driver read (calrec.h table). */
    memset(&id, 0, sizeof id);
    id.family = CALREC_FAMILY_SCA3000;
    id.product = CALREC_SCA3000_D01;
    id.revision = dev.revid;
    REQUIRE(calrec_decode(golden_record_a, sizeof golden_record_a, &id, &rec, NULL) == INC_OK);
    CHECK(rec.valid);
    CHECK_EQ_INT(rec.acc_tbias[0].kind, CALREC_TM_LORENTZ_CUBIC);
    REQUIRE(cal_acc_init(&st, &rec, FX_Q16_INT(25)) == INC_OK);
    for (k = 0; k < sizeof temps / sizeof temps[0]; k++) {
        fx_q16_t t;
        for (j = 0; j < sizeof tilts_deg / sizeof tilts_deg[0]; j++) {
            const double th = tilts_deg[j] * 3.14159265358979323846 / 180.0;
            const double f[3] = {sin(th), 0.0, cos(th)};
            fx_q16_t raw[3], out[3];
            int16_t last[3];
            input(f, temps[k]);
            sim_clock_advance_to(&board.clk, board.clk.now_ns + SAMPLE_NS);
            REQUIRE(read_temp(&t) == INC_OK);
            CHECK_NEAR(t / CALT_Q16, temps[k], 0.3); /* 0.556 degC LSB */
            CHECK_OK(cal_acc_set_temp(&st, t));
            REQUIRE(read_mean(4, raw, last) == INC_OK);
            CHECK_OK(cal_acc_apply(&st, raw, out));
            for (i = 0; i < 3u; i++) {
                const double ec = fabs(out[i] / CALT_Q16 - f[i]),
                             er = fabs(raw[i] / CALT_Q16 - f[i]);
                worst_cal = ec > worst_cal ? ec : worst_cal;
                worst_raw = er > worst_raw ? er : worst_raw;
                CHECK(ec < 0.0015);
            }
        }
    }
    printf(
        "MEASURED SCA3000 + part A, -20..60 degC, tilts 0/+20/-30 deg: worst error %lld ug calibrated, "
        "%lld ug uncalibrated\n",
        (long long)(worst_cal * 1e6), (long long)(worst_raw * 1e6));
    CHECK(worst_raw > 0.010);
    /* A record for another part is refused by the binding (calstore would run uncalibrated). */
    id.revision ^= 1u;
    CHECK_ERR(calrec_decode(golden_record_a, sizeof golden_record_a, &id, &rec, NULL),
              INC_ERR_MISMATCH);
    CHECK_ERR(cal_acc_init(&st, &rec, FX_Q16_INT(25)), INC_ERR_NOT_CALIBRATED);
    CHECK(board.log.total == 0u);
}

int main(void)
{
    UNIT_RUN(test_hook_and_six_position);
    UNIT_RUN(test_station_record_on_the_part);
    return unit_report();
}
