/*
 * kf.c - the small fixed-point Kalman filter (see inclino/kf.h and docs/kalman.md).
 *
 * [KF-SCA3000] gives the five equations; this file keeps their order. Choices and why:
 *  - Covariances are int64 with 48 fractional bits for Q16 states (P format, kf.h): the angle and
 *    gyro-bias covariances of an 819.2 Hz filter span ~16 decades. Every product goes through an
 *    exact 128-bit intermediate (fx128) and is rounded once, ties away from zero.
 *  - The state keeps 16 extra fractional bits: with a gain of 10^-3 and an innovation of a few
 *    LSB the correction is below one raw LSB; rounded to the raw unit it would be lost every step
 *    and the estimate would stall short of the truth (the classic fixed-point Kalman dead band).
 *  - Measurement rows are applied one at a time (R diagonal): the gain is then P h' / s with a
 *    scalar s, so equation (4) needs n divisions and no matrix inverse.
 *  - Equation (5) in Joseph form. For one row with v = P h' and s = h P h' + r it expands to
 *      P+ = P - k v' - v k' + s k k'
 *    which equals (I - k h) P (I - k h)' + k r k' for ANY k, so the rounding of k costs no
 *    symmetry or positivity (the textbook (I - K H) P loses both in fixed point). Only the upper
 *    triangle is computed and mirrored: P is symmetric by construction. Its diagonal is
 *      P+_ii = (P_ii - v_i^2 / s) + s (k_i - v_i / s)^2 >= 0
 *    in exact arithmetic; the final rounding can give -1 LSB, which is clamped to 0.
 */
#include "inclino/kf.h"

#include <stddef.h>

#include "inclino/compiler.h"
#include "inclino/fx128.h"

/* ---- helpers ------------------------------------------------------------------------------ */

/* INC_NOINLINE (inclino/compiler.h) keeps a helper out of line so that its 128-bit temporaries
 * live in its own short frame instead of adding to the caller's (gcc merges inlined frames). */

static int64_t clamp_p(int64_t v, bool *sat)
{
    if (v > KF_P_MAX) {
        *sat = true;
        return KF_P_MAX;
    }
    if (v < -KF_P_MAX) {
        *sat = true;
        return -KF_P_MAX;
    }
    return v;
}

static int64_t clamp_x(int64_t v, bool *sat)
{
    if (v > KF_X_LIMIT) {
        *sat = true;
        return KF_X_LIMIT;
    }
    if (v < -KF_X_LIMIT) {
        *sat = true;
        return -KF_X_LIMIT;
    }
    return v;
}

/* acc + c * v for a Q30 coefficient c. Zero coefficients (sparse A, B, H) cost nothing and a
 * coefficient of exactly 1 adds v * 2^30 without a multiply (the same exact value). */
static inline fx_i128_t mac_q30(fx_i128_t acc, fx_q30_t c, int64_t v)
{
    if (c == 0) return acc;
    if (c == FX_Q30_ONE) {
        fx_i128_t t;
        t.lo = (uint64_t)v << 30;                                   /* two's complement bits */
        t.hi = (uint64_t)(v < 0 ? -1 - ((-1 - v) >> 34) : v >> 34); /* floor(v / 2^34) */
        return fx_i128_add(acc, t);
    }
    return fx_i128_mac(acc, c, v);
}

/* Checks a symmetric matrix s (n x n row-major, P format): diagonal in [0, KF_P_MAX],
 * |off-diagonal| <= KF_P_MAX, symmetric, every 2x2 principal minor >= 0. */
static bool cov_ok(const int64_t *s, unsigned n)
{
    unsigned i, j;
    for (i = 0; i < n; i++) {
        int64_t d = s[i * n + i];
        if (d < 0 || d > KF_P_MAX) return false;
        for (j = i + 1u; j < n; j++) {
            int64_t o = s[i * n + j];
            if (o != s[j * n + i]) return false;
            if (o < -KF_P_MAX || o > KF_P_MAX) return false;
            if (o != 0 && fx_i128_cmp(fx_i128_mul(o, o), fx_i128_mul(d, s[j * n + j])) > 0) {
                return false;
            }
        }
    }
    return true;
}

/* ---- set-up ------------------------------------------------------------------------------- */

int kf_init(struct kf *f, unsigned n, const int32_t *x0, const int64_t *p0)
{
    unsigned i, j;
    if (f == NULL) return INC_ERR_NULL;
    f->n = 0;
    f->overflow = false;
    for (i = 0; i < KF_N_MAX; i++) {
        f->x[i] = 0;
        for (j = 0; j < KF_N_MAX; j++)
            f->p[i][j] = 0;
    }
    if (p0 == NULL) return INC_ERR_NULL;
    if (n < 1u || n > KF_N_MAX) return INC_ERR_INVAL;
    if (!cov_ok(p0, n)) return INC_ERR_INVAL;
    for (i = 0; i < n; i++) {
        f->x[i] = x0 == NULL ? 0 : (int64_t)x0[i] * ((int64_t)1 << KF_X_FRAC);
        for (j = 0; j < n; j++)
            f->p[i][j] = p0[i * n + j];
    }
    f->n = (uint8_t)n;
    return INC_OK;
}

int kf_model_check(const struct kf_model *m, unsigned n)
{
    if (m == NULL) return INC_ERR_NULL;
    if (m->n != n || n < 1u || n > KF_N_MAX || m->nu > KF_U_MAX) return INC_ERR_INVAL;
    if (m->a == NULL || m->q == NULL || (m->nu > 0u && m->b == NULL)) return INC_ERR_NULL;
    return cov_ok(m->q, n) ? INC_OK : INC_ERR_INVAL;
}

static bool r_ok(int64_t r)
{
    return r >= 1 && r <= KF_P_MAX;
}

int kf_meas_check(const struct kf_meas *ms, unsigned n)
{
    unsigned i;
    if (ms == NULL) return INC_ERR_NULL;
    if (ms->n != n || n < 1u || n > KF_N_MAX || ms->m < 1u || ms->m > KF_M_MAX) {
        return INC_ERR_INVAL;
    }
    if (ms->h == NULL || ms->r == NULL) return INC_ERR_NULL;
    for (i = 0; i < ms->m; i++) {
        if (!r_ok(ms->r[i])) return INC_ERR_INVAL;
    }
    return INC_OK;
}

/* ---- equations (1) and (2) ---------------------------------------------------------------- */

/* (1) x = A x + B u. B u is formed in the state's internal scale (u * 2^KF_X_FRAC). */
INC_NOINLINE static void predict_x(struct kf *f, const struct kf_model *m, const int32_t *u,
                                   bool *sat)
{
    int64_t xn[KF_N_MAX];
    unsigned n = f->n, i, j;
    for (i = 0; i < n; i++) {
        fx_i128_t acc = fx_i128_from_i64(0);
        for (j = 0; j < n; j++)
            acc = mac_q30(acc, m->a[i * n + j], f->x[j]);
        for (j = 0; j < m->nu; j++) {
            acc = mac_q30(acc, m->b[i * m->nu + j], (int64_t)u[j] * ((int64_t)1 << KF_X_FRAC));
        }
        xn[i] = clamp_x(fx_i128_rshift_round(acc, FX_Q30_SHIFT, sat), sat);
    }
    for (i = 0; i < n; i++)
        f->x[i] = xn[i];
}

/* (2) P = A P A' + Q: first AP (rounded once), then (AP) A' for the upper triangle. */
INC_NOINLINE static void predict_p(struct kf *f, const struct kf_model *m, bool *sat)
{
    int64_t am[KF_N_MAX][KF_N_MAX];
    unsigned n = f->n, i, j, k;
    for (i = 0; i < n; i++) {
        for (j = 0; j < n; j++) {
            fx_i128_t acc = fx_i128_from_i64(0);
            for (k = 0; k < n; k++)
                acc = mac_q30(acc, m->a[i * n + k], f->p[k][j]);
            am[i][j] = fx_i128_rshift_round(acc, FX_Q30_SHIFT, sat);
        }
    }
    for (i = 0; i < n; i++) {
        for (j = i; j < n; j++) {
            fx_i128_t acc = fx_i128_from_i64(0);
            int64_t v;
            for (k = 0; k < n; k++)
                acc = mac_q30(acc, m->a[j * n + k], am[i][k]);
            v = fx_i128_rshift_round(acc, FX_Q30_SHIFT, sat);
            /* Both terms are clamped to 2^60 first, so their sum cannot overflow int64. */
            v = clamp_p(v, sat);
            v = clamp_p(v + m->q[i * n + j], sat);
            if (i == j && v < 0) v = 0;
            f->p[i][j] = v;
            f->p[j][i] = v;
        }
    }
}

int kf_predict(struct kf *f, const struct kf_model *m, const int32_t *u)
{
    bool sat = false;
    int err;

    if (f == NULL) return INC_ERR_NULL;
    if (f->n == 0u) return INC_ERR_STATE;
    err = kf_model_check(m, f->n);
    if (err != INC_OK) return err;
    if (m->nu > 0u && u == NULL) return INC_ERR_NULL;
    predict_x(f, m, u, &sat);
    predict_p(f, m, &sat);
    if (sat) {
        f->overflow = true;
        return INC_ERR_OVERFLOW;
    }
    return INC_OK;
}

/* ---- equations (3), (4), (5) -------------------------------------------------------------- */

/* h P h' and the innovation z - h x, in separate small frames (stack economy on Cortex-M0+). */
INC_NOINLINE static int64_t row_dot_v(const fx_q30_t *h, const int64_t *v, unsigned n, bool *sat)
{
    fx_i128_t acc = fx_i128_from_i64(0);
    unsigned i;
    for (i = 0; i < n; i++)
        acc = mac_q30(acc, h[i], v[i]);
    return fx_i128_rshift_round(acc, FX_Q30_SHIFT, sat);
}

/* k = v / s in Q30 (int64: |k| <= sqrt(P_ii / s) <= 2^30 for a valid P, i.e. 2^60 raw), then
 * x += k y. Returns k. */
INC_NOINLINE static int64_t gain_and_state(int64_t *x, int64_t v, int64_t s, int64_t y, bool *sat)
{
    int64_t k, dx;
    if (fx_i128_div_i64(fx_i128_mul(v, (int64_t)1 << FX_Q30_SHIFT), s, &k) != INC_OK) *sat = true;
    dx = fx_i128_rshift_round(fx_i128_mul(k, y), FX_Q30_SHIFT, sat);
    *x = clamp_x(
        fx_i128_rshift_round(fx_i128_add(fx_i128_from_i64(*x), fx_i128_from_i64(dx)), 0u, sat),
        sat);
    return k;
}

/* P+_ij = P_ij - k_i v_j - v_i k_j + (s k_i) k_j, rounded once (Joseph form, see the top). */
INC_NOINLINE static int64_t joseph(int64_t pij, int64_t ki, int64_t vi, int64_t kj, int64_t vj,
                                   int64_t wi, bool *sat)
{
    fx_i128_t t = fx_i128_mul(wi, kj);
    t = fx_i128_sub(t, fx_i128_mul(ki, vj));
    t = fx_i128_sub(t, fx_i128_mul(vi, kj));
    t = fx_i128_add(fx_i128_from_i64(pij),
                    fx_i128_from_i64(fx_i128_rshift_round(t, FX_Q30_SHIFT, sat)));
    return clamp_p(fx_i128_rshift_round(t, 0u, sat), sat);
}

int kf_update_row(struct kf *f, const fx_q30_t *h, int64_t r, int32_t z)
{
    int64_t v[KF_N_MAX], k[KF_N_MAX], s, y;
    unsigned n, i, j;
    bool sat = false;

    if (f == NULL || h == NULL) return INC_ERR_NULL;
    if (f->n == 0u) return INC_ERR_STATE;
    if (!r_ok(r)) return INC_ERR_INVAL;
    n = f->n;

    /* v = P h' and s = h P h' + r (the innovation variance, denominator of (4)). */
    for (i = 0; i < n; i++)
        v[i] = row_dot_v(h, f->p[i], n, &sat);
    s = clamp_p(row_dot_v(h, v, n, &sat), &sat) + r; /* |h P h'| <= 2^60, r <= 2^60 */
    if (s <= 0) return INC_ERR_DEGENERATE;

    /* Innovation of (3): z - H x, in the state's internal scale. */
    y = (int64_t)z * ((int64_t)1 << KF_X_FRAC) - row_dot_v(h, f->x, n, &sat);

    /* (4) k = v / s and (3) x += k y, state by state. */
    for (i = 0; i < n; i++)
        k[i] = gain_and_state(&f->x[i], v[i], s, y, &sat);

    /* (5) Joseph form, upper triangle, mirrored. */
    for (i = 0; i < n; i++) {
        int64_t wi = fx_i128_rshift_round(fx_i128_mul(s, k[i]), FX_Q30_SHIFT, &sat); /* ~ v_i */
        for (j = i; j < n; j++) {
            int64_t pij = joseph(f->p[i][j], k[i], v[i], k[j], v[j], wi, &sat);
            if (i == j && pij < 0) pij = 0; /* -1 LSB of rounding, see the file comment */
            f->p[i][j] = pij;
            f->p[j][i] = pij;
        }
    }
    if (sat) {
        f->overflow = true;
        return INC_ERR_OVERFLOW;
    }
    return INC_OK;
}

int kf_update(struct kf *f, const struct kf_meas *ms, const int32_t *z, uint32_t use_mask)
{
    unsigned i;
    int err, result = INC_OK;
    if (f == NULL || z == NULL) return INC_ERR_NULL;
    if (f->n == 0u) return INC_ERR_STATE;
    err = kf_meas_check(ms, f->n);
    if (err != INC_OK) return err;
    for (i = 0; i < ms->m; i++) {
        if ((use_mask & (1u << i)) == 0u) continue;
        err = kf_update_row(f, &ms->h[i * f->n], ms->r[i], z[i]);
        if (err == INC_ERR_OVERFLOW) {
            result = err;
        } else if (err != INC_OK) {
            return err;
        }
    }
    return result;
}

/* ---- read-out ----------------------------------------------------------------------------- */

int32_t kf_x(const struct kf *f, unsigned i)
{
    if (f == NULL || i >= f->n) return 0;
    /* |x| <= KF_X_LIMIT = INT32_MAX * 2^16: the rounded value fits int32. */
    return (int32_t)fx_rshift_round64(f->x[i], KF_X_FRAC);
}

int64_t kf_p(const struct kf *f, unsigned i, unsigned j)
{
    if (f == NULL || i >= f->n || j >= f->n) return 0;
    return f->p[i][j];
}

int32_t kf_sigma(const struct kf *f, unsigned i)
{
    int64_t p;
    if (f == NULL || i >= f->n) return 0;
    p = f->p[i][i];
    if (p <= 0) return 0;
    /* sqrt(raw^2 * 2^16) = raw * 2^8. */
    return (int32_t)fx_rshift_round64((int64_t)fx_isqrt64_round((uint64_t)p), KF_P_FRAC / 2u);
}

int64_t kf_var_from_sigma(int32_t sigma_raw)
{
    uint64_t m = fx_uabs32(sigma_raw);
    if (m >= ((uint64_t)1 << 22)) return KF_P_MAX;
    return (int64_t)(m * m) * ((int64_t)1 << KF_P_FRAC);
}

void kf_clear_overflow(struct kf *f)
{
    if (f != NULL) f->overflow = false;
}
