/*
 * The driving diagnostics' arithmetic (firmware/signal/xcheck, inclino/xcheck.h): argument
 * checks; the flat-line detector on exact runs, mask and reset; the vehicle-level residual
 * against a double-precision reference over random inputs and at the clamps (the header's
 * error bound: 2 LSB Q16 + 3e-7 x |k|); the monitor's convergence to a constant (within
 * 2^(shift-1) LSB Q24 + 0.5 LSB Q16), its persistence count, and its noise reduction.
 * Host and QEMU (fewer random cases where UNIT_REDUCED).
 */
#include "inclino/xcheck.h"
#include "unit.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static uint32_t lcg = 12345u;
static uint32_t rnd_u32(void)
{
    lcg = lcg * 1664525u + 1013904223u;
    return lcg;
}
static double rnd_uni(double lo, double hi)
{
    return lo + (hi - lo) * (double)(rnd_u32() >> 8) / 16777216.0;
}

static void test_args(void)
{
    struct xcheck_flat f;
    struct xcheck_mon m;
    const fx_q16_t a[3] = {0, 0, 0};
    const int32_t up[3] = {0, 0, 1 << 30};
    fx_q16_t r[3] = {1, 1, 1};
    bool fail = true;
    CHECK_ERR(xcheck_flat_init(NULL, 16u, 0x3Fu), INC_ERR_NULL);
    CHECK_ERR(xcheck_flat_init(&f, 1u, 0x3Fu), INC_ERR_INVAL);
    CHECK_ERR(xcheck_flat_init(&f, 65536u, 0x3Fu), INC_ERR_INVAL);
    CHECK_ERR(xcheck_flat_init(&f, 16u, 0x40u), INC_ERR_INVAL);
    CHECK_OK(xcheck_flat_init(&f, 2u, 0x3Fu));
    {
        const int32_t six[XCHECK_FLAT_CH] = {0};
        CHECK_EQ_INT(xcheck_flat_step(NULL, six), 0);
    }
    CHECK_EQ_INT(xcheck_flat_step(&f, NULL), 0);
    CHECK_ERR(xcheck_mon_init(NULL, 8u, 1u), INC_ERR_NULL);
    CHECK_ERR(xcheck_mon_init(&m, 0u, 1u), INC_ERR_INVAL);
    CHECK_ERR(xcheck_mon_init(&m, 17u, 1u), INC_ERR_INVAL);
    CHECK_ERR(xcheck_mon_init(&m, 8u, 0u), INC_ERR_INVAL);
    CHECK_ERR(xcheck_mon_init(&m, 8u, (1u << 24) + 1u), INC_ERR_INVAL);
    CHECK_OK(xcheck_mon_init(&m, 8u, 1u));
    CHECK_EQ_INT(xcheck_mon_step(NULL, a, 7u, 0, &fail), 0);
    CHECK(!fail);
    CHECK_EQ_INT(xcheck_mon_step(&m, NULL, 7u, 0, NULL), 0);
    CHECK_ERR(xcheck_kin_residual(NULL, up, 0, FX_Q16_INT(800), 0, 0, r), INC_ERR_NULL);
    CHECK(r[0] == 0 && r[1] == 0 && r[2] == 0);
    CHECK_ERR(xcheck_kin_residual(a, NULL, 0, FX_Q16_INT(800), 0, 0, r), INC_ERR_NULL);
    CHECK_ERR(xcheck_kin_residual(a, up, 0, FX_Q16_INT(800), 0, 0, NULL), INC_ERR_NULL);
    CHECK_ERR(xcheck_kin_residual(a, up, 0, FX_Q16_ONE - 1, 0, 0, r), INC_ERR_INVAL);
    CHECK_OK(xcheck_kin_residual(a, up, 0, FX_Q16_INT(800), 0, 0, r));
    CHECK_EQ_INT(r[2], -FX_Q16_ONE);
}

static void test_flat(void)
{
    struct xcheck_flat f;
    int32_t v[XCHECK_FLAT_CH] = {1, 2, 3, 4, 5, 6};
    unsigned k;
    CHECK_OK(xcheck_flat_init(&f, 4u, 0x3Fu));
    for (k = 1; k <= 3u; k++)
        CHECK_EQ_INT(xcheck_flat_step(&f, v), 0); /* runs of 1, 2, 3 */
    CHECK_EQ_HEX(xcheck_flat_step(&f, v), 0x3F);  /* the 4th equal sample */
    CHECK_EQ_HEX(xcheck_flat_step(&f, v), 0x3F);  /* stays (saturated count) */
    v[2]++;                                       /* channel 2 moves: its run restarts */
    CHECK_EQ_HEX(xcheck_flat_step(&f, v), 0x3B);
    for (k = 0; k < 2u; k++)
        CHECK_EQ_HEX(xcheck_flat_step(&f, v), 0x3B);
    CHECK_EQ_HEX(xcheck_flat_step(&f, v), 0x3F); /* 4 equal again */
    /* a noisy channel (changes every sample) never flags, the mask hides a channel */
    CHECK_OK(xcheck_flat_init(&f, 4u, 0x2Fu));
    for (k = 0; k < 1000u; k++) {
        v[0] = (int32_t)(k & 1u) - 5; /* alternating */
        v[1] = INT32_MIN;             /* constant: flagged */
        v[4] = INT32_MAX;             /* constant, but masked out */
        v[5] = (int32_t)(k % 3u);     /* never two equal in a row */
        {
            const uint8_t o = xcheck_flat_step(&f, v);
            CHECK((o & 0x31u) == 0u);
            if (k >= 3u) CHECK((o & 0x02u) != 0u);
        }
    }
    xcheck_flat_reset(&f);
    CHECK_EQ_INT(xcheck_flat_step(&f, v), 0); /* the history is gone */
}

/* |error| of one residual component against the double reference */
static double ref_err(fx_q16_t acc, int32_t up, double k_ref, fx_q16_t got)
{
    double a = acc / 65536.0;
    double r;
    if (a > 32.0) a = 32.0;
    if (a < -32.0) a = -32.0;
    if (k_ref > 32.0) k_ref = 32.0;
    if (k_ref < -32.0) k_ref = -32.0;
    r = a - up / 1073741824.0 - k_ref;
    if (r > 64.0) r = 64.0;
    if (r < -64.0) r = -64.0;
    return fabs(got / 65536.0 - r) * 65536.0; /* LSB */
}

static void test_kin_residual(void)
{
    const double g0 = 9.80665, pi = 3.14159265358979323846;
    const unsigned n = UNIT_SIZE(200000u, 5000u);
    double worst = 0.0;
    unsigned i;
    for (i = 0; i < n; i++) {
        fx_q16_t acc[3], r[3];
        int32_t up[3];
        const bool big = (i % 8u) == 0u; /* sometimes beyond the clamps */
        const double rate = rnd_uni(1.0, big ? 32767.0 : 4000.0);
        const double dv = rnd_uni(-1.0, 1.0) * (big ? 300.0 : 0.05);
        const double v = rnd_uni(-1.0, 1.0) * (big ? 300.0 : 60.0);
        const double yaw = rnd_uni(-1.0, 1.0) * (big ? 30000.0 : 300.0);
        unsigned k;
        const fx_q16_t rq = (fx_q16_t)lround(rate * 65536.0);
        const fx_q16_t dvq = (fx_q16_t)lround(dv * 65536.0), vq = (fx_q16_t)lround(v * 65536.0);
        const fx_q16_t yq = (fx_q16_t)lround(yaw * 65536.0);
        double dvc = dvq / 65536.0, vc = vq / 65536.0, kx, ky;
        for (k = 0; k < 3u; k++) {
            acc[k] = (fx_q16_t)lround(rnd_uni(-1.0, 1.0) * (big ? 40.0 : 3.0) * 65536.0);
            up[k] = (int32_t)lround(rnd_uni(-1.0, 1.0) * 1073741823.0);
        }
        CHECK_OK(xcheck_kin_residual(acc, up, dvq, rq, vq, yq, r));
        if (dvc > 256.0) dvc = 256.0;
        if (dvc < -256.0) dvc = -256.0;
        if (vc > 256.0) vc = 256.0;
        if (vc < -256.0) vc = -256.0;
        kx = dvc * (rq / 65536.0);
        if (kx > 400.0) kx = 400.0;
        if (kx < -400.0) kx = -400.0;
        kx /= g0;
        ky = vc * (yq / 65536.0) * pi / 180.0 / g0;
        {
            const double e0 = ref_err(acc[0], up[0], kx, r[0]);
            const double e1 = ref_err(acc[1], up[1], ky, r[1]);
            const double e2 = ref_err(acc[2], up[2], 0.0, r[2]);
            const double l0 = 2.0 + 3e-7 * fabs(kx) * 65536.0;
            const double l1 = 2.0 + 3e-7 * fabs(ky) * 65536.0;
            if (e0 > l0 || e1 > l1 || e2 > 2.0) {
                CHECK(e0 <= l0 && e1 <= l1 && e2 <= 2.0);
                printf("  case %u: dv %g rate %g v %g yaw %g errs %g %g %g\n", i, dv, rate, v, yaw,
                       e0, e1, e2);
                return;
            }
            if (!big) {
                if (e0 > worst) worst = e0;
                if (e1 > worst) worst = e1;
                if (e2 > worst) worst = e2;
            }
        }
    }
    printf("  kin residual: worst |error| %.3f LSB Q16 over %u in-range cases\n", worst, n);
    CHECK(worst <= 2.0);
}

static void test_mon(void)
{
    struct xcheck_mon m;
    unsigned sh, k;
    bool fail;
    /* convergence to a constant: within 2^(sh-1) LSB Q24 + 0.5 LSB Q16 */
    for (sh = 1; sh <= UNIT_SIZE(16u, 12u); sh++) {
        const fx_q16_t d[3] = {FX_Q16_INT(1) / 20, -FX_Q16_INT(3), 12345};
        const fx_q16_t z[3] = {0, 0, 0};
        fx_q16_t lev = 0;
        CHECK_OK(xcheck_mon_init(&m, (uint8_t)sh, 1u));
        (void)xcheck_mon_step(&m, z, 7u, INT32_MAX, NULL);
        for (k = 0; k < 32u * (1u << sh) + 64u; k++)
            lev = xcheck_mon_step(&m, d, 1u, INT32_MAX, NULL);
        CHECK(fabs(m.lp[0] - d[0] * 256.0) <= (double)(1u << sh));
        CHECK(fabs(lev - (double)d[0]) <= (double)(1u << sh) / 256.0 + 0.5);
        CHECK(fabs(m.lp[2] - d[2] * 256.0) <= (double)(1u << sh));
        CHECK(fabs(m.lp[1] / 16777216.0 + 3.0) * 16777216.0 <= (double)(1u << sh));
        lev = xcheck_mon_step(&m, d, 7u, INT32_MAX, NULL);
        CHECK(abs(lev - FX_Q16_INT(3)) <= (int)(1u << sh) / 256 + 1);
    }
    /* the start from 0, the clamp at 32 g, the persistence count (shift 1: lp halves the gap) */
    {
        const fx_q16_t d[3] = {FX_Q16_INT(100), -FX_Q16_INT(100), 1 << 10};
        CHECK_OK(xcheck_mon_init(&m, 1u, 3u));
        /* stage 1: 1/2, 3/4, 7/8, 15/16; stage 2: 1/4, 1/2, 11/16, 13/16 of the input */
        CHECK_EQ_INT(xcheck_mon_step(&m, d, 7u, 0, &fail), FX_Q16_INT(8)); /* 32 g / 4 */
        CHECK(!fail);
        CHECK_EQ_INT(xcheck_mon_step(&m, d, 4u, 0, &fail), 512);
        CHECK(!fail);
        CHECK_EQ_INT(xcheck_mon_step(&m, d, 4u, 703, &fail), 704); /* the 3rd over */
        CHECK(fail);
        CHECK_EQ_INT(xcheck_mon_step(&m, d, 4u, 832, &fail), 832); /* not above: restarts */
        CHECK(!fail);
        (void)xcheck_mon_step(&m, d, 4u, 0, &fail);
        CHECK(!fail);
        xcheck_mon_reset(&m);
        CHECK(m.over_n == 0u && m.lp[0] == 0 && m.lp1[2] == 0);
    }
    /* noise: the output's sigma is sigma sqrt(g (2 - 2g + g^2) / (2 - g)^3) (g = 2^-8: 0.031) */
    {
        const unsigned n = UNIT_SIZE(400000u, 40000u);
        double s2 = 0.0, s1 = 0.0;
        CHECK_OK(xcheck_mon_init(&m, 8u, 1u));
        for (k = 0; k < n; k++) {
            fx_q16_t d[3];
            double u = 0.0;
            unsigned j;
            for (j = 0; j < 12u; j++)
                u += rnd_uni(0.0, 1.0);
            d[0] = (fx_q16_t)lround((u - 6.0) * 0.01 * 65536.0); /* N(0, 10 mg) */
            d[1] = d[2] = 0;
            (void)xcheck_mon_step(&m, d, 1u, INT32_MAX, NULL);
            if (k >= 4096u) {
                const double x = m.lp[0] / 16777216.0;
                s1 += x;
                s2 += x * x;
            }
        }
        {
            const double cnt = (double)(n - 4096u), mean = s1 / cnt;
            const double sd = sqrt(s2 / cnt - mean * mean);
            const double g = 1.0 / 256.0;
            const double want = 0.01 * sqrt(g * (2.0 - 2.0 * g + g * g) / pow(2.0 - g, 3.0));
            printf("  monitor: low-pass sigma %.3g g (expected %.3g)\n", sd, want);
            CHECK(fabs(sd / want - 1.0) < (UNIT_REDUCED ? 0.25 : 0.1));
        }
    }
}

/* XCHECK_MON_XY_NORM: the level is the larger of the masked axes' |lp| and the x-y norm,
 * rounded up to Q16: never below the exact norm of the Q24 values, at most 1 LSB above; random
 * inputs (shift 1: lp moves fast) up to the 32 g clamp, and the persistence on the norm. */
static void test_mon_norm(void)
{
    struct xcheck_mon m;
    unsigned k;
    bool fail;
    double worst = 0.0;
    CHECK_OK(xcheck_mon_init(&m, 1u, 2u));
    for (k = 0; k < UNIT_SIZE(200000u, 20000u); k++) {
        const int sc = (int)(k % 5u) * 6;
        fx_q16_t d[3];
        fx_q16_t lev, lz;
        double nx;
        unsigned i;
        for (i = 0; i < 3u; i++)
            d[i] = (fx_q16_t)((int32_t)rnd_u32() >> sc);
        lev = xcheck_mon_step(&m, d, 4u | XCHECK_MON_XY_NORM, INT32_MAX, NULL);
        nx = sqrt((double)m.lp[0] * m.lp[0] + (double)m.lp[1] * m.lp[1]) / 256.0;
        lz = (fx_q16_t)((abs(m.lp[2]) + 128) >> 8);
        if (lz > nx + 1.0) {
            CHECK_EQ_INT(lev, lz);
        } else {
            CHECK(lev >= nx - 1e-9 || lev == lz);
            CHECK(lev <= (nx > lz ? nx : lz) + 1.0);
            if (nx > lz && lev - nx > worst) worst = lev - nx;
        }
    }
    printf("  mon x-y norm: at most %.3f LSB Q16 above the exact norm\n", worst);
    CHECK(worst <= 1.0);
    /* (0.6, 0.6) g passes a 0.7 g per-axis check but not the norm (0.85 g) */
    {
        const fx_q16_t d[3] = {FX_Q16_INT(6) / 10, FX_Q16_INT(6) / 10, 0};
        const fx_q16_t thr = FX_Q16_INT(7) / 10;
        fx_q16_t lev = 0;
        CHECK_OK(xcheck_mon_init(&m, 1u, 2u));
        for (k = 0; k < 60u; k++)
            (void)xcheck_mon_step(&m, d, 3u, thr, &fail);
        CHECK(!fail);
        for (k = 0; k < 60u; k++)
            lev = xcheck_mon_step(&m, d, XCHECK_MON_XY_NORM, thr, &fail);
        CHECK(fail);
        CHECK(fabs(lev / 65536.0 - 0.6 * sqrt(2.0)) < 2e-5);
    }
}

int main(void)
{
    UNIT_RUN(test_args);
    UNIT_RUN(test_flat);
    UNIT_RUN(test_kin_residual);
    UNIT_RUN(test_mon);
    UNIT_RUN(test_mon_norm);
    return unit_report();
}
