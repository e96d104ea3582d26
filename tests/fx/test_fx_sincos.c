/*
 * test_fx_sincos.c - fx_sin_deg, fx_cos_deg, fx_sincos_deg against libm over every angle.
 *
 * Bound asserted: FX_SINCOS_BOUND_LSB = 0.57 LSB Q30 (0.5 output rounding + 0.065 internal,
 * docs/fixed-point.md); the project aim 2e-9 (2.15 LSB) is asserted as well.
 *
 * Sweeps (full = host preset / reduced = QEMU and host-sanitize):
 *   one turn: every TURN_STEP-th Q16 angle of [0, 360) deg, TURN_STEP = 1 / 193 (the host
 *             covers all 23 592 960 angles of a turn exhaustively, i.e. every angle there is,
 *             because the reduction below is exact);
 *   whole int32 range: every WIDE_STEP-th angle from INT32_MIN to INT32_MAX, WIDE_STEP =
 *             997 / 2^16+1: the result must equal the one of the reduced angle bit for bit,
 *             and match libm on the reduced angle;
 *   exact values at multiples of 30 and 45 deg, odd/even symmetry, sin^2 + cos^2.
 * The reference angle a * pi / (180 * 2^16) is computed in double from the exact integer
 * remainder, so the reference carries only ~1e-16 relative error.
 */
#include "fx_test.h"

#define FX_SINCOS_BOUND_LSB 0.57
#define AIM_LSB (2e-9 * FXT_Q30)

#define TURN_STEP FX_DENSITY(1L, 193L)
#define WIDE_STEP FX_DENSITY(997L, (1L << 16) + 1L)

static double rad_of(int64_t a_q16)
{
    return (double)a_q16 * (FXT_PI / (180.0 * FXT_Q16));
}

static void test_exact_values(void)
{
    int32_t k;
    fx_q30_t s = 1, c = 1;
    /* multiples of 90 deg: exactly 0 / +-1 */
    for (k = -8; k <= 8; k++) {
        int32_t a = k * FX_DEG_90;
        static const int32_t sin_q[4] = {0, FX_Q30_ONE, 0, -FX_Q30_ONE};
        int q = ((k % 4) + 4) % 4;
        CHECK_EQ_INT(fx_sin_deg(a), sin_q[q]);
        CHECK_EQ_INT(fx_cos_deg(a), sin_q[(q + 1) % 4]);
    }
    CHECK_EQ_INT(fx_sin_deg(FX_Q16_INT(30)), FX_Q30_HALF);
    CHECK_EQ_INT(fx_sin_deg(FX_Q16_INT(150)), FX_Q30_HALF);
    CHECK_EQ_INT(fx_sin_deg(FX_Q16_INT(-30)), -FX_Q30_HALF);
    CHECK_EQ_INT(fx_sin_deg(FX_Q16_INT(210)), -FX_Q30_HALF);
    CHECK_EQ_INT(fx_cos_deg(FX_Q16_INT(60)), FX_Q30_HALF);
    CHECK_EQ_INT(fx_cos_deg(FX_Q16_INT(120)), -FX_Q30_HALF);
    CHECK_EQ_INT(fx_cos_deg(FX_Q16_INT(-300)), FX_Q30_HALF);
    /* 45 deg: sqrt(1/2) * 2^30 = 759250124.99 */
    CHECK_EQ_INT(fx_sin_deg(FX_DEG_45), 759250125);
    CHECK_EQ_INT(fx_cos_deg(FX_DEG_45), 759250125);
    CHECK_EQ_INT(fx_sin_deg(-FX_DEG_45 - FX_DEG_90), -759250125);
    /* the extremes of the input range: -32768 deg = -91 turns - 8 deg; 32768 - 2^-16 deg */
    CHECK_EQ_INT(fx_sin_deg(INT32_MIN), fx_sin_deg(FX_Q16_INT(352)));
    CHECK_EQ_INT(fx_cos_deg(INT32_MIN), fx_cos_deg(FX_Q16_INT(-8)));
    CHECK_EQ_INT(fx_sin_deg(INT32_MAX), fx_sin_deg(INT32_MAX - 91 * FX_DEG_360));
    /* the smallest angle: sin(2^-16 deg) = 2.6632e-7 rad -> 285.95 LSB Q30 */
    CHECK_EQ_INT(fx_sin_deg(1), 286);
    CHECK_EQ_INT(fx_cos_deg(1), FX_Q30_ONE);
    fx_sincos_deg(FX_Q16_INT(30), &s, &c);
    CHECK_EQ_INT(s, FX_Q30_HALF);
    CHECK_EQ_INT(c, fx_cos_deg(FX_Q16_INT(30)));
    fx_sincos_deg(FX_Q16_INT(30), NULL, &c);
    fx_sincos_deg(FX_Q16_INT(30), &s, NULL);
    fx_sincos_deg(FX_Q16_INT(30), NULL, NULL);
    CHECK_EQ_INT(s, FX_Q30_HALF);
}

static void test_one_turn(void)
{
    struct fxt_err es = {0}, ec = {0}, pyth = {0};
    unsigned long sym_bad = 0, pair_bad = 0;
    int32_t a;
    for (a = 0; a < FX_DEG_360; a += TURN_STEP) {
        fx_q30_t s, c;
        double x = rad_of(a);
        fx_sincos_deg(a, &s, &c);
        fxt_err_add(&es, (double)s - ldexp(sin(x), 30), a, s);
        fxt_err_add(&ec, (double)c - ldexp(cos(x), 30), a, c);
        /* |s^2 + c^2 - 1| in Q30 LSB: <= 2 (|s| + |c|) 0.57 <= 2 sqrt(2) 0.57 = 1.62 */
        fxt_err_add(&pyth, ((double)s * s + (double)c * c) / FXT_Q30 - FXT_Q30, a, 0);
        if (s != fx_sin_deg(a) || c != fx_cos_deg(a)) pair_bad++;
        if (fx_sin_deg(-a) != -s || fx_cos_deg(-a) != c) sym_bad++;
    }
    fxt_report("fx_sin_deg one turn", &es, 1.0 / FXT_Q30, "");
    fxt_report("fx_cos_deg one turn", &ec, 1.0 / FXT_Q30, "");
    fxt_report("sin^2 + cos^2 - 1", &pyth, 1.0 / FXT_Q30, "");
    FXT_CHECK_ERR(es, FX_SINCOS_BOUND_LSB);
    FXT_CHECK_ERR(ec, FX_SINCOS_BOUND_LSB);
    FXT_CHECK_ERR(es, AIM_LSB);
    FXT_CHECK_ERR(ec, AIM_LSB);
    FXT_CHECK_ERR(pyth, 2.0 * 1.41422 * FX_SINCOS_BOUND_LSB);
    CHECK_EQ_INT(pair_bad, 0);
    CHECK_EQ_INT(sym_bad, 0);
}

static void test_whole_range(void)
{
    struct fxt_err es = {0}, ec = {0};
    unsigned long red_bad = 0;
    int64_t a;
    for (a = INT32_MIN; a <= INT32_MAX; a += WIDE_STEP) {
        int64_t r = a % FX_DEG_360;
        fx_q30_t s = fx_sin_deg((int32_t)a), c = fx_cos_deg((int32_t)a);
        if (r < 0) r += FX_DEG_360;
        if (s != fx_sin_deg((int32_t)r) || c != fx_cos_deg((int32_t)r)) red_bad++;
        fxt_err_add(&es, (double)s - ldexp(sin(rad_of(r)), 30), (double)a, s);
        fxt_err_add(&ec, (double)c - ldexp(cos(rad_of(r)), 30), (double)a, c);
    }
    fxt_report("fx_sin_deg whole int32 range", &es, 1.0 / FXT_Q30, "");
    fxt_report("fx_cos_deg whole int32 range", &ec, 1.0 / FXT_Q30, "");
    FXT_CHECK_ERR(es, FX_SINCOS_BOUND_LSB);
    FXT_CHECK_ERR(ec, FX_SINCOS_BOUND_LSB);
    CHECK_EQ_INT(red_bad, 0);
}

int main(void)
{
    UNIT_RUN(test_exact_values);
    UNIT_RUN(test_one_turn);
    UNIT_RUN(test_whole_range);
    return unit_report();
}
