/*
 * test_kf_adapt.c - the adaptive per-axis filter of [CN110567483] (inclino/kf_adapt.h) on
 * hand-checkable cases: dz over a partial and a sliding window (with rounding ties), Q and R from
 * C, D, A, B, the scalar steps with a gain of exactly 1/2 and one rounded gain, coasting, the
 * six-axis wrapper and bad input. Integer only: host, QEMU Cortex-M and rv32imac.
 */
#include <stdint.h>
#include <stdio.h>

#include "inclino/kf_adapt.h"
#include "unit.h"

#define U ((int64_t)65536) /* 1 raw^2 in P format (raw^2 * 2^16) */

static struct kf_adapt_config cfg(uint32_t window, int64_t c, int64_t d, int64_t a, fx_q16_t b,
                                  int64_t p0)
{
    struct kf_adapt_config k;
    k.window = window;
    k.c = c;
    k.d = d;
    k.a = a;
    k.b = b;
    k.p0 = p0;
    return k;
}

/* dz = (n Z - sum of the n samples in the window) / (n - 1). Window k = 4 (R = 0: K = 1, the
 * estimate is the sample, so only dz matters here):
 *   10            first sample: dz = 0
 *   10, 10        (20 - 20) / 1 = 0
 *   10, 10, 10    0
 *   +14           (56 - 44) / 3 = 4
 *   +14 (slides)  window 10 10 14 14: (56 - 48) / 3 = 2.67 -> 3
 *   +11           window 10 14 14 11: (44 - 49) / 3 = -1.67 -> -2
 */
static void test_dz_window4(void)
{
    const int32_t z[] = {10, 10, 10, 14, 14, 11};
    const int32_t dz[] = {0, 0, 0, 4, 3, -2};
    struct kf_adapt f;
    struct kf_adapt_config c = cfg(4, U, 0, 0, 0, U);
    unsigned i;
    REQUIRE(kf_adapt_init(&f, &c) == INC_OK);
    for (i = 0; i < 6; i++) {
        int32_t est;
        struct kf_adapt_step st;
        CHECK_OK(kf_adapt_process(&f, z[i], &est, &st));
        CHECK_EQ_INT(st.dz, dz[i]);
        CHECK_EQ_INT(est, z[i]); /* R = 0 */
        if (i > 0) {
            CHECK_EQ_INT(st.q, U); /* D = 0: Q = C */
            CHECK_EQ_INT(st.r, 0);
            CHECK_EQ_INT(st.k, FX_Q30_ONE);
        }
    }
}

/* Window 3, ties of (3 Z - S) / 2 round away from zero:
 *   0, 0, 1   (3 - 1) / 2 = 1
 *   +2        window 0 1 2: (6 - 3) / 2 = 1.5 -> 2
 *   +0        window 1 2 0: (0 - 3) / 2 = -1.5 -> -2 */
static void test_dz_ties(void)
{
    const int32_t z[] = {0, 0, 1, 2, 0};
    const int32_t dz[] = {0, 0, 1, 2, -2};
    struct kf_adapt f;
    struct kf_adapt_config c = cfg(3, U, 0, 0, 0, U);
    unsigned i;
    REQUIRE(kf_adapt_init(&f, &c) == INC_OK);
    for (i = 0; i < 5; i++) {
        int32_t est;
        struct kf_adapt_step st;
        CHECK_OK(kf_adapt_process(&f, z[i], &est, &st));
        CHECK_EQ_INT(st.dz, dz[i]);
    }
}

/* C = 1, D = 1, A = 1, B = 1, P0 = 1 (raw units), window 2:
 *   z = 0   first: X = 0, P = 1
 *   z = 2   dz = 2, Q = 1 + 2 = 3, R = |1 + 3| = 4, P- = 4, K = 1/2: X = 1, P = 2
 *   z = 2   dz = 0, Q = 1, R = 2, P- = 3, K = 3/5 -> round(0.6 * 2^30) = 644245094;
 *           X = 1 + K * 1 (internal 2^16 scale: 65536 + round(644245094 * 65536 / 2^30) =
 *           65536 + 39322), P = round((2^30 - K) * 3 U / 2^30) = round(78643.2) = 78643 */
static void test_steps_by_hand(void)
{
    struct kf_adapt f;
    struct kf_adapt_config c = cfg(2, U, U, U, FX_Q16_ONE, U);
    struct kf_adapt_step st;
    int32_t est;
    REQUIRE(kf_adapt_init(&f, &c) == INC_OK);
    CHECK_OK(kf_adapt_process(&f, 0, &est, &st));
    CHECK_EQ_INT(est, 0);
    CHECK_EQ_INT(f.p, U);
    CHECK_OK(kf_adapt_process(&f, 2, &est, &st));
    CHECK_EQ_INT(st.dz, 2);
    CHECK_EQ_INT(st.q, 3 * U);
    CHECK_EQ_INT(st.r, 4 * U);
    CHECK_EQ_INT(st.k, FX_Q30_HALF);
    CHECK_EQ_INT(est, 1);
    CHECK_EQ_INT(f.x, 65536);
    CHECK_EQ_INT(f.p, 2 * U);
    CHECK_OK(kf_adapt_process(&f, 2, &est, &st));
    CHECK_EQ_INT(st.dz, 0);
    CHECK_EQ_INT(st.q, U);
    CHECK_EQ_INT(st.r, 2 * U);
    CHECK_EQ_INT(st.k, 644245094);
    CHECK_EQ_INT(f.x, 65536 + 39322);
    CHECK_EQ_INT(est, 2); /* 1.6 rounds to 2 */
    CHECK_EQ_INT(f.p, 78643);
    CHECK_EQ_INT(kf_adapt_estimate(&f), 2);
}

/* R = |A + B Q| with a negative B: A = 2, B = -1, Q = C = 5 -> R = |2 - 5| = 3. */
static void test_r_abs(void)
{
    struct kf_adapt f;
    struct kf_adapt_config c = cfg(2, 5 * U, 0, 2 * U, -FX_Q16_ONE, 0);
    struct kf_adapt_step st;
    int32_t est;
    REQUIRE(kf_adapt_init(&f, &c) == INC_OK);
    CHECK_OK(kf_adapt_process(&f, 7, &est, &st));
    CHECK_OK(kf_adapt_process(&f, 7, &est, &st));
    CHECK_EQ_INT(st.r, 3 * U);
    CHECK_EQ_INT(st.q, 5 * U);
    /* P- = 0 + 5, K = 5/8 exactly */
    CHECK_EQ_INT(st.k, FX_Q30_ONE / 8 * 5);
}

/* The point of the patent's filter: on a step, |dz| raises Q and the gain, so it follows much
 * faster than the same filter without D, while both smooth alike when the input is still. */
static void test_adaptive_follows_step(void)
{
    struct kf_adapt fa, ff;
    struct kf_adapt_config ca = cfg(8, U / 64, U / 4, 64 * U, 0, 64 * U);
    struct kf_adapt_config cf = cfg(8, U / 64, 0, 64 * U, 0, 64 * U);
    int32_t ea = 0, ef = 0;
    unsigned i, na = 0, nf = 0;
    REQUIRE(kf_adapt_init(&fa, &ca) == INC_OK);
    REQUIRE(kf_adapt_init(&ff, &cf) == INC_OK);
    for (i = 0; i < 2000; i++) { /* settle at 0 */
        CHECK_OK(kf_adapt_process(&fa, 0, &ea, NULL));
        CHECK_OK(kf_adapt_process(&ff, 0, &ef, NULL));
    }
    CHECK_EQ_INT(ea, 0);
    for (i = 0; i < 400; i++) { /* step to 1000 raw: samples to reach 900 */
        CHECK_OK(kf_adapt_process(&fa, 1000, &ea, NULL));
        CHECK_OK(kf_adapt_process(&ff, 1000, &ef, NULL));
        if (ea < 900) na++;
        if (ef < 900) nf++;
    }
    printf("samples to 90 %%: adaptive %u, fixed %u\n", na, nf);
    CHECK(na * 4 < nf);
    CHECK_NEAR_INT(ea, 1000, 1);
}

/* Coasting holds the estimate and grows P by C; the window keeps the real samples. */
static void test_coast(void)
{
    struct kf_adapt f;
    struct kf_adapt_config c = cfg(2, U, 0, U, 0, U);
    int32_t est = -1;
    REQUIRE(kf_adapt_init(&f, &c) == INC_OK);
    CHECK_OK(kf_adapt_coast(&f, &est)); /* before the first sample: estimate 0, P untouched */
    CHECK_EQ_INT(est, 0);
    CHECK_EQ_INT(f.p, U);
    CHECK_OK(kf_adapt_process(&f, 40, &est, NULL));
    CHECK_OK(kf_adapt_coast(&f, &est));
    CHECK_EQ_INT(est, 40);
    CHECK_EQ_INT(f.p, 2 * U);
    CHECK_EQ_INT(f.count, 1);
    kf_adapt_restart(&f);
    CHECK_EQ_INT(kf_adapt_estimate(&f), 0);
    CHECK_OK(kf_adapt_process(&f, -5, &est, NULL));
    CHECK_EQ_INT(est, -5);
    /* P saturates at KF_P_MAX when coasting for ever */
    f.p = KF_P_MAX - 1;
    CHECK_OK(kf_adapt_coast(&f, &est));
    CHECK_EQ_INT(f.p, KF_P_MAX);
}

static void test_six_axes(void)
{
    struct kf_adapt6 f;
    struct kf_adapt_config c[KF_ADAPT_AXES];
    int32_t z[KF_ADAPT_AXES] = {1, 2, 3, 4, 5, 6}, est[KF_ADAPT_AXES];
    unsigned i;
    for (i = 0; i < KF_ADAPT_AXES; i++)
        c[i] = cfg(2 + i, U, U, U, 0, U);
    REQUIRE(kf_adapt6_init(&f, c) == INC_OK);
    CHECK_OK(kf_adapt6_process(&f, z, 0x3Fu, est));
    for (i = 0; i < KF_ADAPT_AXES; i++)
        CHECK_EQ_INT(est[i], z[i]);
    for (i = 0; i < KF_ADAPT_AXES; i++)
        z[i] += 100;
    CHECK_OK(kf_adapt6_process(&f, z, 0x3Fu & ~(1u << 2), est)); /* axis 2 coasts */
    CHECK_EQ_INT(est[2], 3);
    CHECK(est[0] > 1 && est[0] <= 101);
    CHECK_EQ_INT(f.axis[3].cfg.window, 5);
    /* one bad axis: init fails, and no axis is usable */
    c[4].window = 1;
    CHECK_ERR(kf_adapt6_init(&f, c), INC_ERR_INVAL);
    CHECK_ERR(kf_adapt6_process(&f, z, 0x3Fu, est), INC_ERR_STATE);
    CHECK_ERR(kf_adapt6_init(NULL, c), INC_ERR_NULL);
    CHECK_ERR(kf_adapt6_init(&f, NULL), INC_ERR_NULL);
    CHECK_ERR(kf_adapt6_process(&f, NULL, 0, est), INC_ERR_NULL);
}

static void test_bad_input(void)
{
    struct kf_adapt f;
    struct kf_adapt_config c = cfg(4, U, U, U, 0, U), bad;
    int32_t est;
    CHECK_ERR(kf_adapt_init(NULL, &c), INC_ERR_NULL);
    CHECK_ERR(kf_adapt_init(&f, NULL), INC_ERR_NULL);
    CHECK_ERR(kf_adapt_process(&f, 0, &est, NULL), INC_ERR_STATE);
    bad = c;
    bad.window = 1;
    CHECK_ERR(kf_adapt_init(&f, &bad), INC_ERR_INVAL);
    bad.window = KF_ADAPT_WIN_MAX + 1;
    CHECK_ERR(kf_adapt_init(&f, &bad), INC_ERR_INVAL);
    bad = c;
    bad.c = 0;
    CHECK_ERR(kf_adapt_config_check(&bad), INC_ERR_INVAL);
    bad.c = KF_P_MAX + 1;
    CHECK_ERR(kf_adapt_config_check(&bad), INC_ERR_INVAL);
    bad = c;
    bad.d = -1;
    CHECK_ERR(kf_adapt_config_check(&bad), INC_ERR_INVAL);
    bad = c;
    bad.a = -KF_P_MAX - 1;
    CHECK_ERR(kf_adapt_config_check(&bad), INC_ERR_INVAL);
    bad = c;
    bad.p0 = -1;
    CHECK_ERR(kf_adapt_config_check(&bad), INC_ERR_INVAL);
    CHECK_ERR(kf_adapt_config_check(NULL), INC_ERR_NULL);
    CHECK_ERR(kf_adapt_coast(&f, &est), INC_ERR_STATE); /* the refused init left it unusable */
    REQUIRE(kf_adapt_init(&f, &c) == INC_OK);
    CHECK_ERR(kf_adapt_process(&f, 0, NULL, NULL), INC_ERR_NULL);
    CHECK_ERR(kf_adapt_process(NULL, 0, &est, NULL), INC_ERR_NULL);
    CHECK_ERR(kf_adapt_coast(NULL, &est), INC_ERR_NULL);
    CHECK_EQ_INT(kf_adapt_estimate(NULL), 0);
    kf_adapt_restart(NULL);
    /* extreme samples: no overflow, the estimate stays between the samples */
    CHECK_OK(kf_adapt_process(&f, INT32_MAX, &est, NULL));
    CHECK_OK(kf_adapt_process(&f, INT32_MIN, &est, NULL));
    CHECK(est >= INT32_MIN && est <= INT32_MAX);
    CHECK_OK(kf_adapt_process(&f, INT32_MAX, &est, NULL));
    CHECK(f.p >= 0 && f.p <= KF_P_MAX);
}

int main(void)
{
    UNIT_RUN(test_dz_window4);
    UNIT_RUN(test_dz_ties);
    UNIT_RUN(test_steps_by_hand);
    UNIT_RUN(test_r_abs);
    UNIT_RUN(test_adaptive_follows_step);
    UNIT_RUN(test_coast);
    UNIT_RUN(test_six_axes);
    UNIT_RUN(test_bad_input);
    return unit_report();
}
