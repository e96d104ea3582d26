/* On-device calibration procedures (firmware/signal/cal, cal_proc.c): one-point, +-1 g flip ([ADI-EPB],
 * with the correct gain, and what its misprinted 0.5 would do), six-position, still-interval
 * averaging, gyro offset and turn scale; exact values, error bounds, every refusal. Host and
 * QEMU. */
#include "inclino/cal.h"
#include "cal_test.h"

#include <string.h>

#define G(x) ((fx_q16_t)lround((x)*CALT_Q16))

static void test_flip_exact(void)
{
    fx_q16_t off = 0;
    fx_q30_t gain = 0;
    int32_t corr;
    /* A+ = 1.02 g, A- = -0.98 g: offset 0.02 g, gain 1.0 exactly. */
    CHECK_OK(cal_flip(G(1.02), G(1.02) - 2 * CAL_ONE_G, &off, &gain));
    CHECK_EQ_INT(off, G(1.02) - CAL_ONE_G);
    CHECK_EQ_INT(gain, FX_Q30_ONE);
    /* A+ = 1.03, A- = -0.97 + gain error: offset (A+ + A-)/2, gain (A+ - A-)/2. */
    CHECK_OK(cal_flip(70000, -62000, &off, &gain));
    CHECK_EQ_INT(off, 4000);
    CHECK_EQ_INT(gain, 66000 * 16384);
    /* Corrected value at the two points: exactly +-1 g (a_true = (a_out - offset) / gain). */
    CHECK_OK(fx_div(70000 - off, (int32_t)(gain >> 14), 16, &corr));
    CHECK_EQ_INT(corr, CAL_ONE_G);
    CHECK_OK(fx_div(-62000 - off, (int32_t)(gain >> 14), 16, &corr));
    CHECK_EQ_INT(corr, -CAL_ONE_G);
    /* Odd sums round half away from zero. */
    CHECK_OK(cal_flip(65537, -65536, &off, &gain));
    CHECK_EQ_INT(off, 1);
    CHECK_OK(cal_flip(65536, -65537, &off, &gain));
    CHECK_EQ_INT(off, -1);
}

static void test_printed_flip_gain_is_wrong(void)
{
    /* [ADI-EPB] prints gain = 0.5 * (A+ - A-) / 2. For an ideal part (A+ = +1 g, A- = -1 g) that
     * is 0.5, and a_true = (a_out - offset) / gain would read 2 g on the +1 g face. The module
     * uses (A+ - A-) / 2 = 1.0. */
    const int64_t a_pos = CAL_ONE_G, a_neg = -CAL_ONE_G;
    const int64_t printed_q16 = (a_pos - a_neg) / 2 / 2; /* 0.5 * (A+ - A-) / 2 */
    fx_q16_t off;
    fx_q30_t gain;
    CHECK_EQ_INT(printed_q16, CAL_ONE_G / 2);
    CHECK_EQ_INT((a_pos - 0) * 65536 / printed_q16, 2 * CAL_ONE_G); /* reads 2 g */
    CHECK_OK(cal_flip(CAL_ONE_G, -CAL_ONE_G, &off, &gain));
    CHECK_EQ_INT(gain, FX_Q30_ONE);
    CHECK_EQ_INT(off, 0);
}

static void test_flip_bound(void)
{
    /* Random valid pairs: offset within 0.5 LSB of the exact (A+ + A-)/2, gain exact. */
    uint32_t s = 99u;
    struct calt_err e = {0.0, 0};
    const unsigned n = CALT_DENSITY(1000000u, 200000u);
    unsigned i;
    for (i = 0; i < n; i++) {
        const int64_t g2 = calt_range(&s, 2 * (int64_t)(CAL_GAIN_MIN >> 14) + 1,
                                      2 * (int64_t)(CAL_GAIN_MAX >> 14) - 1);
        const int64_t o2 = calt_range(&s, -2 * (int64_t)CAL_OFFSET_MAX + 1,
                                      2 * (int64_t)CAL_OFFSET_MAX - 1);
        /* a_pos - a_neg = g2, a_pos + a_neg = o2 (same parity needed for integers) */
        const int64_t sum = o2, diff = g2 + ((g2 ^ o2) & 1);
        const fx_q16_t ap = (fx_q16_t)((sum + diff) / 2), an = (fx_q16_t)((sum - diff) / 2);
        fx_q16_t off;
        fx_q30_t gain;
        const int err = cal_flip(ap, an, &off, &gain);
        const int64_t gq = ((int64_t)ap - an) * 8192;
        if (gq < CAL_GAIN_MIN || gq > CAL_GAIN_MAX) {
            CHECK_ERR(err, INC_ERR_RANGE);
            continue;
        }
        CHECK_OK(err);
        CHECK_EQ_INT(gain, gq);
        calt_err_add(&e, (double)off - ((double)ap + an) / 2.0);
    }
    calt_report("cal_flip offset", &e, 0.5);
    CHECK(e.max <= 0.5);
}

static void test_flip_refusals(void)
{
    fx_q16_t off = 111;
    fx_q30_t gain = 222;
    /* Swapped: the +1 g face reads below the -1 g face. */
    CHECK_ERR(cal_flip(-CAL_ONE_G, CAL_ONE_G, &off, &gain), INC_ERR_DEGENERATE);
    CHECK_ERR(cal_flip(1000, 1000, &off, &gain), INC_ERR_DEGENERATE);
    /* Gain at the limits and one LSB beyond ((A+ - A-) = 1.5 g and 2.5 g). */
    CHECK_OK(cal_flip(G(0.75), G(-0.75), &off, &gain));
    CHECK_EQ_INT(gain, CAL_GAIN_MIN);
    CHECK_ERR(cal_flip(G(0.75) - 1, G(-0.75), &off, &gain), INC_ERR_RANGE);
    CHECK_OK(cal_flip(G(1.25), G(-1.25), &off, &gain));
    CHECK_ERR(cal_flip(G(1.25) + 1, G(-1.25), &off, &gain), INC_ERR_RANGE);
    /* Offset at +-0.5 g and beyond. */
    off = 111;
    CHECK_OK(cal_flip(G(1.5), G(-0.5), &off, &gain));
    CHECK_EQ_INT(off, CAL_OFFSET_MAX);
    off = 111;
    gain = 222;
    CHECK_ERR(cal_flip(G(1.5) + 2, G(-0.5) + 2, &off, &gain), INC_ERR_RANGE);
    CHECK_EQ_INT(off, 111); /* untouched */
    CHECK_EQ_INT(gain, 222);
    CHECK_ERR(cal_flip(INT32_MAX, INT32_MIN, &off, &gain), INC_ERR_RANGE);
    CHECK_ERR(cal_flip(1, 0, NULL, &gain), INC_ERR_NULL);
    CHECK_ERR(cal_flip(1, 0, &off, NULL), INC_ERR_NULL);
}

static void test_one_point(void)
{
    const fx_q16_t mean[3] = {G(0.015), G(-0.02), G(1.03)};
    const fx_q16_t level[3] = {0, 0, CAL_ONE_G};
    fx_q16_t off[3] = {7, 7, 7};
    CHECK_OK(cal_one_point(mean, level, off));
    CHECK_EQ_INT(off[0], G(0.015));
    CHECK_EQ_INT(off[1], G(-0.02));
    CHECK_EQ_INT(off[2], G(1.03) - CAL_ONE_G);
    {
        const fx_q16_t far[3] = {G(0.6), 0, CAL_ONE_G};
        const fx_q16_t bad_expect[3] = {0, 0, 2 * CAL_ONE_G};
        off[0] = 7;
        CHECK_ERR(cal_one_point(far, level, off), INC_ERR_RANGE);
        CHECK_EQ_INT(off[0], 7);
        CHECK_ERR(cal_one_point(mean, bad_expect, off), INC_ERR_RANGE);
        CHECK_ERR(cal_one_point(NULL, level, off), INC_ERR_NULL);
    }
}

/* Faces of a part with offset o, gains g and a small cross-axis coupling, in g. */
static void make_faces(fx_q16_t face[CAL_FACES][3], const double o[3], const double g[3],
                       double cross)
{
    unsigned f, i;
    for (f = 0; f < CAL_FACES; f++) {
        const unsigned axis = f / 2u;
        const double s = (f % 2u) ? -1.0 : 1.0;
        for (i = 0; i < 3u; i++) {
            const double a = (i == axis) ? s : 0.0;
            face[f][i] = G(o[i] + g[i] * a + cross * s * (i != axis));
        }
    }
}

static void test_six_position(void)
{
    static const double o[3] = {0.012, -0.018, 0.025}, g[3] = {1.021, 0.984, 1.008};
    fx_q16_t face[CAL_FACES][3], off[3] = {0, 0, 0};
    fx_q30_t gain[3] = {0, 0, 0};
    unsigned i;
    make_faces(face, o, g, 0.008);
    CHECK_OK(cal_six_position((const fx_q16_t(*)[3])face, off, gain));
    for (i = 0; i < 3u; i++) {
        fx_q16_t fo;
        fx_q30_t fg;
        REQUIRE(cal_flip(face[2 * i][i], face[2 * i + 1][i], &fo, &fg) == INC_OK);
        CHECK_EQ_INT(off[i], fo);
        CHECK_EQ_INT(gain[i], fg);
        CHECK_NEAR(off[i] / CALT_Q16, o[i], 1.0 / CALT_Q16);
        CHECK_NEAR(gain[i] / CALT_Q30, g[i], 1.0 / CALT_Q16);
    }
    /* Faces recorded in the wrong slots: Y+ measured where X+ belongs. */
    {
        fx_q16_t tmp[3];
        memcpy(tmp, face[CAL_FACE_XP], sizeof tmp);
        memcpy(face[CAL_FACE_XP], face[CAL_FACE_YP], sizeof tmp);
        memcpy(face[CAL_FACE_YP], tmp, sizeof tmp);
        off[0] = 5;
        CHECK_ERR(cal_six_position((const fx_q16_t(*)[3])face, off, gain), INC_ERR_DEGENERATE);
        CHECK_EQ_INT(off[0], 5);
    }
    /* Z faces swapped (+1 g and -1 g). */
    make_faces(face, o, g, 0.0);
    {
        fx_q16_t tmp[3];
        memcpy(tmp, face[CAL_FACE_ZP], sizeof tmp);
        memcpy(face[CAL_FACE_ZP], face[CAL_FACE_ZN], sizeof tmp);
        memcpy(face[CAL_FACE_ZN], tmp, sizeof tmp);
        CHECK_ERR(cal_six_position((const fx_q16_t(*)[3])face, off, gain), INC_ERR_DEGENERATE);
    }
    /* A gain out of range on one axis refuses all three. */
    {
        static const double g2[3] = {1.0, 1.3, 1.0};
        make_faces(face, o, g2, 0.0);
        off[0] = 5;
        CHECK_ERR(cal_six_position((const fx_q16_t(*)[3])face, off, gain), INC_ERR_RANGE);
        CHECK_EQ_INT(off[0], 5);
    }
    CHECK_ERR(cal_six_position(NULL, off, gain), INC_ERR_NULL);
}

static void test_avg(void)
{
    struct cal_avg a;
    int32_t m[3] = {9, 9, 9};
    const int32_t s1[3] = {10, -10, 3}, s2[3] = {11, -11, 4};
    cal_avg_reset(&a);
    CHECK_ERR(cal_avg_mean(&a, 100, m), INC_ERR_STATE);
    CHECK_OK(cal_avg_add(&a, s1));
    CHECK_OK(cal_avg_add(&a, s2));
    CHECK_OK(cal_avg_mean(&a, 1, m));
    CHECK_EQ_INT(m[0], 11); /* 10.5 -> 11 (ties away from zero) */
    CHECK_EQ_INT(m[1], -11);
    CHECK_EQ_INT(m[2], 4);
    /* Span 1 is still; a third sample that moves 5 LSB is motion for max_span 4. */
    {
        const int32_t s3[3] = {15, -10, 3};
        CHECK_OK(cal_avg_add(&a, s3));
        m[0] = 9;
        CHECK_ERR(cal_avg_mean(&a, 4, m), INC_ERR_MOTION);
        CHECK_EQ_INT(m[0], 9);
        CHECK_OK(cal_avg_mean(&a, 5, m));
        CHECK_ERR(cal_avg_mean(&a, -1, m), INC_ERR_INVAL);
    }
    /* The span of the extreme values does not overflow. */
    {
        const int32_t lo[3] = {INT32_MIN, 0, 0}, hi[3] = {INT32_MAX, 0, 0};
        cal_avg_reset(&a);
        CHECK_OK(cal_avg_add(&a, lo));
        CHECK_OK(cal_avg_add(&a, hi));
        CHECK_ERR(cal_avg_mean(&a, INT32_MAX, m), INC_ERR_MOTION);
    }
    /* Full accumulator refuses the sample. */
    a.sum[0].count = FX_SUM_MAX_COUNT;
    CHECK_ERR(cal_avg_add(&a, s1), INC_ERR_OVERFLOW);
    CHECK_ERR(cal_avg_add(NULL, s1), INC_ERR_NULL);
}

static void test_gyro_offset(void)
{
    struct cal_avg a;
    fx_q16_t off[3] = {1, 1, 1};
    uint32_t s = 5u;
    unsigned k;
    /* 0.42, -0.77, 0.15 deg/s with +-0.05 deg/s of noise. */
    cal_avg_reset(&a);
    for (k = 0; k < 2000u; k++) {
        int32_t v[3];
        v[0] = G(0.42) + (int32_t)calt_range(&s, -3277, 3277);
        v[1] = G(-0.77) + (int32_t)calt_range(&s, -3277, 3277);
        v[2] = G(0.15) + (int32_t)calt_range(&s, -3277, 3277);
        CHECK_OK(cal_avg_add(&a, v));
    }
    CHECK_OK(cal_gyro_offset(&a, G(0.2), off));
    CHECK_NEAR(off[0] / CALT_Q16, 0.42, 0.003);
    CHECK_NEAR(off[1] / CALT_Q16, -0.77, 0.003);
    CHECK_ERR(cal_gyro_offset(&a, G(0.05), off), INC_ERR_MOTION); /* someone touched the table */
    cal_avg_reset(&a);
    {
        const int32_t v[3] = {G(31.0), 0, 0};
        CHECK_OK(cal_avg_add(&a, v));
        CHECK_ERR(cal_gyro_offset(&a, 0, off), INC_ERR_RANGE);
    }
    CHECK_ERR(cal_gyro_offset(NULL, 0, off), INC_ERR_NULL);
}

/* One turn about `axis`: n samples of rate (deg/s) through cal_turn_add; returns the exact
 * integral A of (sample - offset) * dt in degrees. */
static double run_turn(struct cal_turn *t, unsigned axis, double rate, double scale, double bias,
                       long n, fx_q30_t dt, const fx_q16_t off[3], uint32_t *s)
{
    double exact = 0.0;
    long k;
    CHECK_OK(cal_turn_start(t, off, dt));
    for (k = 0; k < n; k++) {
        fx_q16_t r[3];
        unsigned i;
        for (i = 0; i < 3u; i++) {
            const double w = (i == axis) ? rate : 0.0;
            r[i] = G(bias + scale * w) + (int32_t)calt_range(s, -3000, 3000);
        }
        CHECK_OK(cal_turn_add(t, r));
        exact += ((double)r[axis] - off[axis]) / CALT_Q16 * (dt / CALT_Q30);
    }
    return exact;
}

static void test_turn(void)
{
    /* [ADI-IMU-QS]'s ADIS rate: 819.2 SPS, dt = 1.220703125 ms = 2^30 / 819.2 in Q30 (rounded). */
    const fx_q30_t dt = (fx_q30_t)lround(CALT_Q30 / 819.2);
    const fx_q16_t off[3] = {G(0.42), G(-0.77), G(0.15)};
    const long n = 3277; /* 4 s at 90 deg/s: 360 deg */
    const double rate = 360.0 / (n * (dt / CALT_Q30));
    struct cal_turn t;
    uint32_t s = 77u;
    fx_q30_t sc = 0;
    double a, bound;
    /* +360 deg about x with scale 1.012. */
    a = run_turn(&t, 0, rate, 1.012, 0.42, n, dt, off, &s);
    CHECK_OK(cal_turn_scale(&t, 0, FX_Q16_INT(360), &sc));
    bound = 0.5 + (1.0 / 131072.0 + n / 8589934592.0) / 360.0 * CALT_Q30;
    CHECK_NEAR(sc, a / 360.0 * CALT_Q30, bound);
    CHECK_NEAR(sc / CALT_Q30, 1.012, 2e-4);
    /* -360 deg about y (scale 0.991): known -360, scale positive. */
    a = run_turn(&t, 1, -rate, 0.991, -0.77, n, dt, off, &s);
    CHECK_OK(cal_turn_scale(&t, 1, FX_Q16_INT(-360), &sc));
    CHECK_NEAR(sc, a / -360.0 * CALT_Q30, bound);
    CHECK_NEAR(sc / CALT_Q30, 0.991, 2e-4);
    /* The wrong direction (known +360 for a -360 turn): degenerate. */
    CHECK_ERR(cal_turn_scale(&t, 1, FX_Q16_INT(360), &sc), INC_ERR_DEGENERATE);
    /* Known angle too small, bad axis, no samples, scale out of range. */
    CHECK_ERR(cal_turn_scale(&t, 1, FX_Q16_INT(45), &sc), INC_ERR_INVAL);
    CHECK_ERR(cal_turn_scale(&t, 3, FX_Q16_INT(360), &sc), INC_ERR_INVAL);
    CHECK_ERR(cal_turn_scale(&t, 1, FX_Q16_INT(-180), &sc), INC_ERR_RANGE); /* 2x */
    CHECK_OK(cal_turn_start(&t, off, dt));
    CHECK_ERR(cal_turn_scale(&t, 0, FX_Q16_INT(360), &sc), INC_ERR_STATE);
    /* Refusals of start and add. */
    CHECK_ERR(cal_turn_start(&t, off, 0), INC_ERR_INVAL);
    CHECK_ERR(cal_turn_start(&t, off, FX_Q30_ONE + 1), INC_ERR_INVAL);
    {
        const fx_q16_t fast[3] = {FX_Q16_INT(2001), 0, 0};
        CHECK_ERR(cal_turn_add(&t, fast), INC_ERR_RANGE);
        CHECK_EQ_INT(t.n, 0);
    }
    /* The accumulator refuses to pass 2^30 degrees (1 s samples at 2000 deg/s). */
    {
        const fx_q16_t fast[3] = {FX_Q16_INT(2000), 0, 0}, zero[3] = {0, 0, 0};
        long k;
        int err = INC_OK;
        CHECK_OK(cal_turn_start(&t, zero, FX_Q30_ONE));
        for (k = 0; k < 600000L && err == INC_OK; k++) {
            err = cal_turn_add(&t, fast);
        }
        CHECK_ERR(err, INC_ERR_OVERFLOW);
        CHECK(t.angle_q32[0] <= ((int64_t)1 << 62));
        CHECK_ERR(cal_turn_scale(&t, 0, FX_Q16_INT(360), &sc), INC_ERR_RANGE);
    }
    CHECK_ERR(cal_turn_add(NULL, off), INC_ERR_NULL);
    CHECK_ERR(cal_turn_scale(NULL, 0, FX_Q16_INT(360), &sc), INC_ERR_NULL);
}

int main(void)
{
    UNIT_RUN(test_flip_exact);
    UNIT_RUN(test_printed_flip_gain_is_wrong);
    UNIT_RUN(test_flip_bound);
    UNIT_RUN(test_flip_refusals);
    UNIT_RUN(test_one_point);
    UNIT_RUN(test_six_position);
    UNIT_RUN(test_avg);
    UNIT_RUN(test_gyro_offset);
    UNIT_RUN(test_turn);
    return unit_report();
}
