/* GPS-gap speed blending ([KF-SCA3000]): the factor K against its formula, propagation, blending,
 * gaps and bad input. */
#include "inclino/gpsblend.h"
#include "unit.h"

#include <math.h>
#include <stdio.h>

#if UNIT_REDUCED
#define SWEEP 300
#else
#define SWEEP 30000
#endif

static double q30(int32_t x)
{
    return x / 1073741824.0;
}
static double q16(int32_t x)
{
    return x / 65536.0;
}
static int32_t to_q16(double x)
{
    return (int32_t)lround(x * 65536.0);
}

static double k_exact(double a, double q, unsigned rounds)
{
    double k = fabs(a) / sqrt(a * a + q * q);
    unsigned i;
    for (i = 0; i < rounds; i++)
        k = k + (1.0 - k) * k;
    return k;
}

static void test_factor_values(void)
{
    const int32_t q = to_q16(0.02);
    /* a = Q: K^2 = 1/2. */
    CHECK_NEAR(q30(gpsb_factor(q, q, 0)), sqrt(0.5), 4.0 / 1073741824.0);
    CHECK_NEAR(q30(gpsb_factor(-q, q, 1)), 1.0 - (1.0 - sqrt(0.5)) * (1.0 - sqrt(0.5)),
               9.0 / 1073741824.0);
    /* [KF-SCA3000]'s curve with Q = 20: at A = 30 the one-round K is 0.972; at A = 5 it is small. */
    CHECK_NEAR(q30(gpsb_factor(to_q16(0.030), q, 1)), 0.9718, 0.0001);
    CHECK(q30(gpsb_factor(to_q16(0.005), q, 1)) < 0.5);
    CHECK_EQ_INT(gpsb_factor(0, q, 3), 0);
    CHECK_EQ_INT(gpsb_factor(123, 0, 1), FX_Q30_ONE);
    CHECK_EQ_INT(gpsb_factor(INT32_MIN, 1, 0), FX_Q30_ONE);
    CHECK(gpsb_factor(1, FX_Q16_INT(1), 0) > 0); /* tiny K is not lost */
}

static uint32_t lcg = 99u;
static double urand(void)
{
    lcg = lcg * 1664525u + 1013904223u;
    return (lcg >> 8) / 16777216.0;
}

static void test_factor_sweep(void)
{
    double worst[3] = {0, 0, 0};
    unsigned r;
    int i;
    for (i = 0; i < SWEEP; i++) {
        /* log-uniform magnitudes from 1 LSB to 16 g */
        int32_t a = (int32_t)lround(pow(2.0, urand() * 20.0)) * (urand() < 0.5 ? -1 : 1);
        int32_t q = (int32_t)lround(pow(2.0, urand() * 20.0));
        for (r = 0; r < 3; r++) {
            double e = fabs(q30(gpsb_factor(a, q, r)) - k_exact(a, q, r)) * 1073741824.0;
            if (e > worst[r]) worst[r] = e;
        }
    }
    printf("K error: %.2f / %.2f / %.2f LSB Q30 after 0 / 1 / 2 rounds\n", worst[0], worst[1],
           worst[2]);
    CHECK(worst[0] <= 4.0);
    CHECK(worst[1] <= 8.5);
    CHECK(worst[2] <= 17.5);
}

/* Straight acceleration: K near 1 and the speed follows a * g0 * t. */
static void test_propagation(void)
{
    struct gpsb s;
    struct gpsb_cfg c = gpsb_default_cfg(to_q16(0.0001));
    fx_q16_t v = 0;
    int i;
    double ref;
    CHECK_OK(gpsb_init(&s, &c));
    CHECK_ERR(gpsb_step(&s, FX_Q16_ONE, 13000000, &v), INC_ERR_STATE); /* no fix yet */
    CHECK_OK(gpsb_fix(&s, FX_Q16_INT(10)));
    for (i = 0; i < 77; i++) { /* ~1 s at 13 ms */
        CHECK_OK(gpsb_step(&s, to_q16(0.1), 13000000, &v));
    }
    {
        /* the same recursion in double */
        double vd = 10.0, kd = k_exact(q16(to_q16(0.1)), q16(to_q16(0.0001)), 1);
        for (i = 0; i < 77; i++)
            vd = 10.0 + kd * (vd + q16(to_q16(0.1)) * 9.80665 * 0.013 - 10.0);
        ref = vd;
    }
    CHECK_NEAR(q16(v), ref, 2.0 / 65536);
    CHECK_NEAR(q16(v), 10.0 + 0.1 * 9.80665 * 1.001, 0.001);
    CHECK(gpsb_speed(&s, &v));
    /* A fix resets the speed. */
    CHECK_OK(gpsb_fix(&s, FX_Q16_INT(12)));
    CHECK(gpsb_speed(&s, &v));
    CHECK_EQ_INT(v, FX_Q16_INT(12));
}

/* Cruising: acceleration within the noise keeps the speed near GPS. */
static void test_cruise_stays_on_gps(void)
{
    struct gpsb s;
    struct gpsb_cfg c = gpsb_default_cfg(to_q16(0.02));
    fx_q16_t v = 0;
    int i;
    CHECK_OK(gpsb_init(&s, &c));
    CHECK_OK(gpsb_fix(&s, FX_Q16_INT(20)));
    for (i = 0; i < 77; i++) {
        /* noise-like +-5 mg alternating */
        CHECK_OK(gpsb_step(&s, to_q16(i & 1 ? 0.005 : -0.005), 13000000, &v));
    }
    CHECK_NEAR(q16(v), 20.0, 0.002);
    CHECK(s.last_k < FX_Q30_HALF);
}

static void test_gap_and_errors(void)
{
    struct gpsb s;
    struct gpsb_cfg c = gpsb_default_cfg(to_q16(0.02)), bad;
    fx_q16_t v = 1;
    int i, err = 0;
    CHECK_OK(gpsb_init(&s, &c));
    CHECK_OK(gpsb_fix(&s, FX_Q16_INT(5)));
    CHECK_ERR(gpsb_step(&s, 0, 0, &v), INC_ERR_RANGE);
    CHECK_ERR(gpsb_step(&s, 0, c.max_step_ns + 1u, &v), INC_ERR_RANGE);
    CHECK_EQ_INT(v, FX_Q16_INT(5)); /* unchanged */
    for (i = 0; i < 40; i++) {      /* 4 s without a fix */
        err = gpsb_step(&s, 0, 100000000, &v);
    }
    CHECK_ERR(err, INC_ERR_TIMEOUT);
    CHECK(!gpsb_speed(&s, &v));
    CHECK_OK(gpsb_fix(&s, FX_Q16_INT(5)));
    CHECK(gpsb_speed(&s, &v));
    CHECK_ERR(gpsb_init(NULL, &c), INC_ERR_NULL);
    CHECK_ERR(gpsb_init(&s, NULL), INC_ERR_NULL);
    bad = c;
    bad.q_noise_g = 0;
    CHECK_ERR(gpsb_init(&s, &bad), INC_ERR_INVAL);
    CHECK_ERR(gpsb_fix(&s, 0), INC_ERR_STATE); /* a failed init leaves it unusable */
    bad = c;
    bad.rounds = GPSB_MAX_ROUNDS + 1;
    CHECK_ERR(gpsb_init(&s, &bad), INC_ERR_INVAL);
    bad = c;
    bad.max_step_ns = 2000000000u;
    CHECK_ERR(gpsb_init(&s, &bad), INC_ERR_INVAL);
    bad = c;
    bad.max_gap_ns = 0;
    CHECK_ERR(gpsb_init(&s, &bad), INC_ERR_INVAL);
    CHECK_ERR(gpsb_step(NULL, 0, 1, &v), INC_ERR_NULL);
    CHECK_ERR(gpsb_fix(NULL, 0), INC_ERR_NULL);
    CHECK(!gpsb_speed(NULL, &v));
    /* Extreme inputs do not overflow: 16 g clamp, 1 s steps. */
    CHECK_OK(gpsb_init(&s, &c));
    c.max_step_ns = 1000000000u;
    CHECK_OK(gpsb_init(&s, &c));
    CHECK_OK(gpsb_fix(&s, FX_Q16_INT(100)));
    CHECK_OK(gpsb_step(&s, INT32_MAX, 1000000000u, &v));
    CHECK_NEAR(q16(v), 100.0 + 16.0 * 9.80665, 0.001);
    CHECK_OK(gpsb_step(&s, INT32_MIN, 1000000000u, &v));
    CHECK_NEAR(q16(v), 100.0, 0.001);
}

int main(void)
{
    UNIT_RUN(test_factor_values);
    UNIT_RUN(test_factor_sweep);
    UNIT_RUN(test_propagation);
    UNIT_RUN(test_cruise_stays_on_gps);
    UNIT_RUN(test_gap_and_errors);
    return unit_report();
}
