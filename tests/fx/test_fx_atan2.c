/*
 * test_fx_atan2.c - fx_atan2_deg against libm atan2 over the whole int32 x int32 domain.
 *
 * Bound asserted: FX_ATAN2_BOUND_LSB = 0.81 LSB Q16 (the error budget in fx_trig.c), far inside
 * the requirement 0.001 deg = 65.5 LSB, which is asserted separately.
 *
 * Sweeps (full = host preset / reduced = QEMU and host-sanitize):
 *   angular: N_ANG = 2^19 / 2^13 angles over (-180, 180] on each of 14 radii from 1 to 2^31-1
 *            (so tiny and huge magnitudes in every octant; y, x rounded to integers and the
 *            reference computed from those integers);
 *   random:  N_RAND = 2^21 / 2^15 pairs with random magnitudes 2^0..2^31 and signs;
 *   small:   every (y, x) in [-SMALL, SMALL]^2, SMALL = 64 / 40;
 *   extremes: every pair from {INT32_MIN, INT32_MIN+1, -2^30, -2, -1, 0, 1, 2, 2^30, INT32_MAX-1,
 *            INT32_MAX} and their neighbours on the axes and diagonals (exact values asserted).
 */
#include "fx_test.h"

#define FX_ATAN2_BOUND_LSB 0.81
#define REQUIREMENT_LSB (0.001 * FXT_Q16) /* 0.001 deg */

#define N_ANG FX_DENSITY(1L << 19, 1L << 13)
#define N_RAND FX_DENSITY(1L << 21, 1L << 15)
#define SMALL FX_DENSITY(64, 40)

static double ref_atan2(int32_t y, int32_t x)
{
    return atan2((double)y, (double)x) * FXT_RAD_TO_Q16DEG;
}

static unsigned long odd_bad;

static void one(struct fxt_err *e, int32_t y, int32_t x)
{
    fx_q16_t r = fx_atan2_deg(y, x);
    fxt_err_add(e, (double)r - ref_atan2(y, x), y, x);
    /* exact odd symmetry in y (the negative x axis is +180 on both sides) */
    if (y != 0 && y != INT32_MIN && fx_atan2_deg(-y, x) != -r) odd_bad++;
}

static void test_exact_values(void)
{
    static const int32_t v[] = {INT32_MIN, INT32_MIN + 1, -1073741824,   -2,       -1, 1,
                                2,         1073741824,    INT32_MAX - 1, INT32_MAX};
    size_t i;
    CHECK_EQ_INT(fx_atan2_deg(0, 0), 0);
    for (i = 0; i < sizeof v / sizeof v[0]; i++) {
        int32_t a = v[i];
        uint32_t m = fx_uabs32(a);
        CHECK_EQ_INT(fx_atan2_deg(0, a), a > 0 ? 0 : FX_DEG_180);
        CHECK_EQ_INT(fx_atan2_deg(a, 0), a > 0 ? FX_DEG_90 : -FX_DEG_90);
        /* diagonals, including |INT32_MIN| = 2^31 against 2^31 */
        if (m == 0x80000000u) {
            CHECK_EQ_INT(fx_atan2_deg(a, a), -FX_DEG_90 - FX_DEG_45);
        } else {
            CHECK_EQ_INT(fx_atan2_deg(a, a), a > 0 ? FX_DEG_45 : -FX_DEG_90 - FX_DEG_45);
            CHECK_EQ_INT(fx_atan2_deg(-a, a), a > 0 ? -FX_DEG_45 : FX_DEG_90 + FX_DEG_45);
        }
    }
    CHECK_EQ_INT(fx_atan2_deg(INT32_MIN, INT32_MIN), -FX_DEG_90 - FX_DEG_45);
    CHECK_EQ_INT(fx_atan2_deg(INT32_MIN, INT32_MAX), -FX_DEG_45); /* 45.0000000134 deg */
    CHECK_EQ_INT(fx_atan2_deg(INT32_MAX, INT32_MIN), FX_DEG_90 + FX_DEG_45);
    CHECK_EQ_INT(fx_atan2_deg(1, INT32_MAX), 0);            /* 2.7e-8 deg */
    CHECK_EQ_INT(fx_atan2_deg(-1, INT32_MIN), -FX_DEG_180); /* -180 + 2.7e-8 deg */
    /* The range is [-180, 180]: below the negative x axis, |y/x| < ~1.3e-7 rounds to -180. */
    CHECK_EQ_INT(fx_atan2_deg(-1, -1073741824), -FX_DEG_180); /* -180 + 5.3e-8 deg */
    CHECK_EQ_INT(fx_atan2_deg(1, -1073741824), FX_DEG_180);
    CHECK_EQ_INT(fx_atan2_deg(-1, -8388608), -FX_DEG_180);     /* 0.45 LSB from -180 */
    CHECK_EQ_INT(fx_atan2_deg(-1, -4194304), -FX_DEG_180 + 1); /* 0.90 LSB from -180 */
    CHECK_EQ_INT(fx_atan2_deg(INT32_MAX, 1), FX_DEG_90);
    CHECK_EQ_INT(fx_atan2_deg(1, 1), FX_DEG_45);
    CHECK_EQ_INT(fx_atan2_deg(3, 4), 2416306); /* 36.8699 deg = 2416305.61 LSB */
}

static void test_sweeps(void)
{
    static const double radius[] = {1.0,         2.0,          3.0,   7.0,         30.0,
                                    1000.0,      65536.0,      1.0e6, 16777216.0,  1.0e8,
                                    268435456.0, 1073741824.0, 2.0e9, 2147483647.0};
    static const int32_t ext[] = {
        INT32_MIN, INT32_MIN + 1, INT32_MIN + 2, -1073741825,   -1073741824,   -2,       -1, 0, 1,
        2,         1073741824,    1073741825,    INT32_MAX - 2, INT32_MAX - 1, INT32_MAX};
    struct fxt_err all = {0}, ang = {0}, rnd = {0}, sml = {0}, xtr = {0};
    uint32_t st = 0x5EED1u;
    size_t ri, i, j;
    long k;
    int32_t y, x;

    odd_bad = 0;
    for (ri = 0; ri < sizeof radius / sizeof radius[0]; ri++) {
        for (k = 0; k < N_ANG; k++) {
            double th = -FXT_PI + 2.0 * FXT_PI * ((double)k + 0.5) / (double)N_ANG;
            double fy = radius[ri] * sin(th), fx = radius[ri] * cos(th);
            y = (int32_t)(fy < 0 ? fy - 0.5 : fy + 0.5);
            x = (int32_t)(fx < 0 ? fx - 0.5 : fx + 0.5);
            one(&ang, y, x);
        }
    }
    for (k = 0; k < N_RAND; k++)
        one(&rnd, fxt_rand_scaled(&st), fxt_rand_scaled(&st));
    for (y = -SMALL; y <= SMALL; y++)
        for (x = -SMALL; x <= SMALL; x++)
            one(&sml, y, x);
    for (i = 0; i < sizeof ext / sizeof ext[0]; i++)
        for (j = 0; j < sizeof ext / sizeof ext[0]; j++)
            one(&xtr, ext[i], ext[j]);

    fxt_report("fx_atan2_deg angular sweep", &ang, 1.0 / FXT_Q16, "deg");
    fxt_report("fx_atan2_deg random pairs", &rnd, 1.0 / FXT_Q16, "deg");
    fxt_report("fx_atan2_deg small grid", &sml, 1.0 / FXT_Q16, "deg");
    fxt_report("fx_atan2_deg extremes", &xtr, 1.0 / FXT_Q16, "deg");
    FXT_CHECK_ERR(ang, FX_ATAN2_BOUND_LSB);
    FXT_CHECK_ERR(rnd, FX_ATAN2_BOUND_LSB);
    FXT_CHECK_ERR(sml, FX_ATAN2_BOUND_LSB);
    FXT_CHECK_ERR(xtr, FX_ATAN2_BOUND_LSB);
    all = ang.max > rnd.max ? ang : rnd;
    if (sml.max > all.max) all = sml;
    if (xtr.max > all.max) all = xtr;
    all.count = ang.count + rnd.count + sml.count + xtr.count;
    fxt_report("fx_atan2_deg (all)", &all, 1.0 / FXT_Q16, "deg");
    FXT_CHECK_ERR(all, REQUIREMENT_LSB);
    CHECK_EQ_INT(odd_bad, 0);
}

int main(void)
{
    UNIT_RUN(test_exact_values);
    UNIT_RUN(test_sweeps);
    return unit_report();
}
