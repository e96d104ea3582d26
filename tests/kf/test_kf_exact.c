/*
 * test_kf_exact.c - proves the rounding contracts of inclino/kf.h and inclino/kf_adapt.h.
 *
 * Host only (needs the compiler's __int128). For random filters of every size:
 *  1. an independent model of the documented arithmetic (each stored quantity = its exact
 *     formula on the stored operands, rounded once to nearest, ties away from zero) is written
 *     here with __int128 and must match the firmware bit for bit, every step;
 *  2. the per-operation error bounds of the headers are checked against exact math:
 *     A P A' + Q within 0.5 (1 + sum_k |a_jk|) LSB (computed exactly in __int128 at 2^-60),
 *     the Joseph P+ against the exact Joseph expression with the exact gain v / s, relative
 *     to the 2^-30 gain resolution.
 */
#include <stdint.h>
#include <math.h>
#include <stdio.h>

#include "inclino/kf.h"
#include "inclino/kf_adapt.h"
#include "unit.h"

typedef __int128 i128;

static uint64_t rs = 0x9E3779B97F4A7C15u;
static uint64_t rnd64(void)
{
    rs ^= rs << 13;
    rs ^= rs >> 7;
    rs ^= rs << 17;
    return rs;
}
static int64_t rnd_range(int64_t lo, int64_t hi) /* [lo, hi] */
{
    return lo + (int64_t)(rnd64() % (uint64_t)(hi - lo + 1));
}

/* round(v / 2^s) ties away from zero, v any i128 with |v| < 2^126. */
static i128 rsh(i128 v, unsigned s)
{
    unsigned __int128 m = v < 0 ? -(unsigned __int128)v : (unsigned __int128)v;
    if (s == 0) return v;
    m = (m + ((unsigned __int128)1 << (s - 1))) >> s;
    return v < 0 ? -(i128)m : (i128)m;
}
static i128 rdiv(i128 n, i128 d)
{
    int neg = (n < 0) != (d < 0);
    unsigned __int128 un = n < 0 ? -(unsigned __int128)n : (unsigned __int128)n;
    unsigned __int128 ud = d < 0 ? -(unsigned __int128)d : (unsigned __int128)d;
    unsigned __int128 q = un / ud, r = un % ud;
    if (r >= ud - r) q++;
    return neg ? -(i128)q : (i128)q;
}
static int64_t sat64(i128 v)
{
    return v > INT64_MAX ? INT64_MAX : (v < INT64_MIN ? INT64_MIN : (int64_t)v);
}
static int64_t clampp(int64_t v)
{
    return v > KF_P_MAX ? KF_P_MAX : (v < -KF_P_MAX ? -KF_P_MAX : v);
}
static int64_t clampx(int64_t v)
{
    return v > KF_X_LIMIT ? KF_X_LIMIT : (v < -KF_X_LIMIT ? -KF_X_LIMIT : v);
}

/* The model's state. */
struct mdl {
    unsigned n;
    int64_t x[4], p[4][4];
};

static void model_predict(struct mdl *s, const fx_q30_t *a, const fx_q30_t *b, unsigned nu,
                          const int32_t *u, const int64_t *q)
{
    unsigned n = s->n, i, j, k;
    int64_t xn[4], am[4][4];
    for (i = 0; i < n; i++) {
        i128 acc = 0;
        for (j = 0; j < n; j++)
            acc += (i128)a[i * n + j] * s->x[j];
        for (j = 0; j < nu; j++)
            acc += (i128)b[i * nu + j] * ((i128)u[j] * 65536);
        xn[i] = clampx(sat64(rsh(acc, 30)));
    }
    for (i = 0; i < n; i++)
        for (j = 0; j < n; j++) {
            i128 acc = 0;
            for (k = 0; k < n; k++)
                acc += (i128)a[i * n + k] * s->p[k][j];
            am[i][j] = sat64(rsh(acc, 30));
        }
    for (i = 0; i < n; i++)
        for (j = i; j < n; j++) {
            i128 acc = 0;
            int64_t v;
            for (k = 0; k < n; k++)
                acc += (i128)a[j * n + k] * am[i][k];
            v = clampp(clampp(sat64(rsh(acc, 30))) + q[i * n + j]);
            if (i == j && v < 0) v = 0;
            s->p[i][j] = s->p[j][i] = v;
        }
    for (i = 0; i < n; i++)
        s->x[i] = xn[i];
}

static void model_update(struct mdl *s, const fx_q30_t *h, int64_t r, int32_t z)
{
    unsigned n = s->n, i, j;
    int64_t v[4], k[4], w[4], hv, sv, y;
    i128 acc;
    for (i = 0; i < n; i++) {
        acc = 0;
        for (j = 0; j < n; j++)
            acc += (i128)h[j] * s->p[i][j];
        v[i] = sat64(rsh(acc, 30));
    }
    acc = 0;
    for (i = 0; i < n; i++)
        acc += (i128)h[i] * v[i];
    hv = clampp(sat64(rsh(acc, 30)));
    sv = hv + r;
    acc = 0;
    for (i = 0; i < n; i++)
        acc += (i128)h[i] * s->x[i];
    y = ((int64_t)z * 65536) - sat64(rsh(acc, 30));
    for (i = 0; i < n; i++) {
        k[i] = sat64(rdiv((i128)v[i] * 1073741824, sv));
        w[i] = sat64(rsh((i128)sv * k[i], 30));
    }
    for (i = 0; i < n; i++)
        s->x[i] = clampx(sat64((i128)s->x[i] + sat64(rsh((i128)k[i] * y, 30))));
    for (i = 0; i < n; i++)
        for (j = i; j < n; j++) {
            i128 t = (i128)w[i] * k[j] - (i128)k[i] * v[j] - (i128)v[i] * k[j];
            int64_t pij = clampp(sat64((i128)s->p[i][j] + sat64(rsh(t, 30))));
            if (i == j && pij < 0) pij = 0;
            s->p[i][j] = s->p[j][i] = pij;
        }
}

/* A random positive semi-definite n x n matrix in P format, L L' with |L| < 2^lbits. */
static void rnd_psd(unsigned n, int64_t *m, unsigned lbits)
{
    int64_t l[16] = {0};
    unsigned i, j, k;
    for (i = 0; i < n * n; i++)
        l[i] = rnd_range(-((int64_t)1 << lbits), (int64_t)1 << lbits);
    for (i = 0; i < n; i++)
        for (j = 0; j < n; j++) {
            int64_t s = 0;
            for (k = 0; k < n; k++)
                s += l[i * n + k] * l[j * n + k];
            m[i * n + j] = s;
        }
}

static void test_kf_bit_exact(void)
{
    unsigned trial, mismatches = 0, steps = 0, saturated = 0;
    double worst_pred = 0; /* worst |error| / bound of A P A' + Q, unsaturated steps */
    for (trial = 0; trial < 400; trial++) {
        unsigned n = 1 + trial % 4, nu = trial % 3, i, j, step;
        struct kf f;
        struct mdl s;
        int64_t p0[16], q[16], r = 0;
        fx_q30_t a[16], b[16], h[4];
        int32_t x0[4];
        /* stable-ish A near identity with couplings, any B, H */
        for (i = 0; i < n; i++)
            for (j = 0; j < n; j++)
                a[i * n + j] = (fx_q30_t)(i == j ? rnd_range(0x30000000, 0x40000000)
                                                 : rnd_range(-0x04000000, 0x04000000));
        for (i = 0; i < n * 4; i++)
            b[i] = (fx_q30_t)rnd_range(-0x01000000, 0x01000000);
        for (i = 0; i < n; i++) {
            h[i] = (fx_q30_t)rnd_range(-0x40000000, 0x40000000);
            x0[i] = (int32_t)rnd_range(-0x01000000, 0x01000000);
        }
        rnd_psd(n, p0, 20 + trial % 9);
        rnd_psd(n, q, 4 + trial % 20);
        r = rnd_range(1, (int64_t)1 << (10 + trial % 40));
        REQUIRE(kf_init(&f, n, x0, p0) == INC_OK);
        s.n = n;
        for (i = 0; i < n; i++) {
            s.x[i] = (int64_t)x0[i] * 65536;
            for (j = 0; j < n; j++)
                s.p[i][j] = p0[i * n + j];
        }
        for (step = 0; step < 50; step++) {
            int32_t u[4], z;
            int perr;
            struct kf_model m = {(uint8_t)n, (uint8_t)nu, a, b, q};
            int64_t pin[4][4];
            for (i = 0; i < 4; i++)
                u[i] = (int32_t)rnd_range(-0x100000, 0x100000);
            for (i = 0; i < n; i++)
                for (j = 0; j < n; j++)
                    pin[i][j] = f.p[i][j];
            perr = kf_predict(&f, &m, u);
            /* Saturation (INC_ERR_OVERFLOW) is part of the contract and of the model. */
            if (perr != INC_OK && perr != INC_ERR_OVERFLOW) mismatches++;
            if (perr != INC_OK) saturated++;
            model_predict(&s, a, b, nu, u, q);
            /* bound of A P A' + Q against exact math, when nothing saturated */
            for (i = 0; i < n && perr == INC_OK; i++)
                for (j = 0; j < n; j++) {
                    i128 e = (i128)q[i * n + j] * ((i128)1 << 60);
                    unsigned k, l;
                    double sa = 0, err, bound;
                    for (k = 0; k < n; k++)
                        for (l = 0; l < n; l++)
                            e += (i128)a[i * n + k] * pin[k][l] * a[j * n + l];
                    double sb = 0;
                    /* the stored (i, j) is (min, max) mirrored: its second rounding used the row
                     * max(i, j) of A; the bound uses the larger row sum of the two */
                    for (k = 0; k < n; k++) {
                        sa += (a[j * n + k] < 0 ? -a[j * n + k] : a[j * n + k]) / 1073741824.0;
                        sb += (a[i * n + k] < 0 ? -a[i * n + k] : a[i * n + k]) / 1073741824.0;
                    }
                    if (sb > sa) sa = sb;
                    err = (double)(((i128)f.p[i][j] * ((i128)1 << 60)) - e) / 1152921504606846976.0;
                    bound = 0.5 * (1 + sa);
                    if (err < 0) err = -err;
                    if (err / bound > worst_pred) worst_pred = err / bound;
                }
            z = (int32_t)rnd_range(-0x01000000, 0x01000000);
            perr = kf_update_row(&f, h, r, z);
            if (perr != INC_OK && perr != INC_ERR_OVERFLOW) mismatches++;
            if (perr != INC_OK) saturated++;
            model_update(&s, h, r, z);
            for (i = 0; i < n; i++) {
                if (f.x[i] != s.x[i]) mismatches++;
                for (j = 0; j < n; j++)
                    if (f.p[i][j] != s.p[i][j]) mismatches++;
            }
            steps++;
        }
    }
    CHECK_EQ_INT(mismatches, 0);
    CHECK(worst_pred <= 1.0);
    CHECK(saturated < steps / 10);
    printf("kf: %u steps bit-exact (%u calls saturated); A P A' + Q worst error = %.3f of its "
           "bound\n",
           steps, saturated, worst_pred);
}

/* The Joseph update against exact math: with the exact gain v / s, P+ = P - v v' / s. The
 * firmware rounds the gain to Q30 and each term once; the header promises
 * |P+ - (P - v v' / s)| <= 2 LSB + 2^-28 max|P| (v and s being its own stored operands). */
static void test_joseph_vs_exact(void)
{
    unsigned trial, bad = 0;
    double worst = 0;
    for (trial = 0; trial < 2000; trial++) {
        unsigned n = 1 + trial % 4, i, j;
        struct kf f;
        int64_t p0[16], r, v[4], pmax = 1, s;
        fx_q30_t h[4];
        rnd_psd(n, p0, 10 + trial % 19);
        for (i = 0; i < n; i++)
            h[i] = (fx_q30_t)rnd_range(-0x40000000, 0x40000000);
        r = rnd_range(1, (int64_t)1 << (5 + trial % 50));
        REQUIRE(kf_init(&f, n, NULL, p0) == INC_OK);
        for (i = 0; i < n * n; i++)
            if (p0[i] > pmax) pmax = p0[i];
        /* exact v and s of the stored P (v rounded like the firmware: it is a stored operand) */
        for (i = 0; i < n; i++) {
            i128 acc = 0;
            for (j = 0; j < n; j++)
                acc += (i128)h[j] * p0[i * n + j];
            v[i] = (int64_t)rsh(acc, 30);
        }
        {
            i128 acc = 0;
            for (i = 0; i < n; i++)
                acc += (i128)h[i] * v[i];
            s = (int64_t)rsh(acc, 30) + r;
        }
        if (kf_update_row(&f, h, r, 0) != INC_OK) bad++;
        for (i = 0; i < n; i++)
            for (j = 0; j < n; j++) {
                /* exact: P - v_i v_j / s, as a double with the division done in i128 */
                double exact = (double)p0[i * n + j] - (double)rdiv((i128)v[i] * v[j], s);
                double err = (double)f.p[i][j] - exact;
                double bound = 2.0 + (double)pmax * 0x1p-28;
                if (err < 0) err = -err;
                if (err / bound > worst) worst = err / bound;
            }
    }
    CHECK_EQ_INT(bad, 0);
    CHECK(worst <= 1.0);
    printf("kf Joseph: worst error = %.3f of (2 LSB + 2^-28 max|P|)\n", worst);
}

/* kf_adapt: independent model of [CN110567483] steps 2-3 with the documented roundings. */
static void test_adapt_bit_exact(void)
{
    unsigned trial, mism = 0, steps = 0;
    for (trial = 0; trial < 200; trial++) {
        struct kf_adapt_config c;
        struct kf_adapt f;
        int32_t hist[KF_ADAPT_WIN_MAX];
        unsigned cnt = 0, head = 0, k, step;
        int64_t x = 0, p = 0, sum = 0;
        c.window = 2 + trial % (KF_ADAPT_WIN_MAX - 1);
        c.c = rnd_range(1, (int64_t)1 << (10 + trial % 40));
        c.d = rnd_range(0, (int64_t)1 << (10 + trial % 30));
        c.a = rnd_range(-((int64_t)1 << 50), (int64_t)1 << 50);
        c.b = (fx_q16_t)rnd_range(-0x400000, 0x400000);
        c.p0 = rnd_range(0, (int64_t)1 << 50);
        REQUIRE(kf_adapt_init(&f, &c) == INC_OK);
        k = c.window;
        for (step = 0; step < 300; step++) {
            int32_t z = (int32_t)rnd_range(-0x02000000, 0x02000000), est;
            struct kf_adapt_step st;
            if (kf_adapt_process(&f, z, &est, &st) != INC_OK) mism++;
            /* model */
            if (cnt == k)
                sum -= hist[head];
            else
                cnt++;
            hist[head] = z;
            sum += z;
            head = (head + 1) % k;
            if (cnt == 1) {
                x = (int64_t)z * 65536;
                p = c.p0;
            } else {
                int32_t dz = (int32_t)rdiv((i128)cnt * z - sum, cnt - 1);
                i128 qq = (i128)c.c + (i128)c.d * (dz < 0 ? -(i128)dz : dz);
                int64_t q = qq > KF_P_MAX ? KF_P_MAX : (int64_t)qq;
                int64_t r, pm, kk;
                r = clampp(sat64(rsh(((i128)c.a * 65536) + (i128)c.b * q, 16)));
                if (r < 0) r = -r;
                pm = p + q;
                if (pm > KF_P_MAX) pm = KF_P_MAX;
                kk = (int64_t)rdiv((i128)pm << 30, pm + r);
                x += (int64_t)rsh((i128)kk * (((int64_t)z * 65536) - x), 30);
                p = (int64_t)rsh((i128)((1 << 30) - kk) * pm, 30);
                if (st.dz != dz || st.q != q || st.r != r || st.k != kk) mism++;
            }
            if (f.x != x || f.p != p || est != (int32_t)rsh(x, 16)) mism++;
            steps++;
        }
    }
    CHECK_EQ_INT(mism, 0);
    printf("kf_adapt: %u steps bit-exact\n", steps);
}

/* kf_sigma: round(sqrt(P / 2^16)) through an integer square root of P and a rounding shift by 8:
 * |error| <= 0.5 LSB + 2^-8 LSB (header) against the exact root, for P over its whole range. */
static void test_sigma_bound(void)
{
    unsigned i;
    double worst = 0;
    for (i = 0; i < 200000; i++) {
        struct kf f;
        int64_t p = (int64_t)(rnd64() >> (4 + rnd64() % 60)); /* every magnitude up to 2^60 */
        long double exact;
        double err;
        if (p > KF_P_MAX) p = KF_P_MAX;
        REQUIRE(kf_init(&f, 1, NULL, &p) == INC_OK);
        exact = sqrtl((long double)p / 65536.0L);
        err = (double)fabsl((long double)kf_sigma(&f, 0) - exact);
        if (err > worst) worst = err;
    }
    printf("kf_sigma: worst error %.6f LSB (bound 0.5 + 1/256)\n", worst);
    CHECK(worst <= 0.5 + 1.0 / 256);
}

int main(void)
{
    UNIT_RUN(test_sigma_bound);
    UNIT_RUN(test_kf_bit_exact);
    UNIT_RUN(test_joseph_vs_exact);
    UNIT_RUN(test_adapt_bit_exact);
    return unit_report();
}
