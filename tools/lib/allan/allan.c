/*
 * allan.c - overlapping Allan deviation and read-offs (see sim/allan.h).
 *
 * The record's mean is removed before integrating: the second difference cancels a constant
 * exactly in real arithmetic, and removing it keeps theta small, so the differences keep their
 * precision in double over records of 10^7 samples and more.
 *
 * The samples are also scaled by 2^-e, e the binary exponent of the largest |y|, and the ADEV by
 * 2^e at the end: multiplying by a power of two is exact, so results are unchanged, but the mean's
 * sum and the squares of the differences cannot overflow for finite samples near DBL_MAX (nor
 * underflow for tiny ones). A result that still is not finite is refused (INC_ERR_RANGE).
 */
#include "inclino/sim/allan.h"

#include <math.h>
#include <stdlib.h>

#include "inclino/error.h"

/* The binary exponent e of max |y[k]| (frexp: max = f 2^e, 0.5 <= f < 1); 0 when all are 0. */
static int scale_exponent(const double *y, size_t n)
{
    double mx = 0.0;
    int e = 0;
    size_t k;
    for (k = 0; k < n; k++) {
        const double a = fabs(y[k]);
        if (a > mx) {
            mx = a;
        }
    }
    if (mx > 0.0) {
        (void)frexp(mx, &e);
    }
    return e;
}

/* *out = theta, theta[k] = integral of (y 2^-e - mean) dt: 0, INC_ERR_NO_SPACE, or
 * INC_ERR_RANGE (not finite; nothing allocated). */
static int integrate(const double *y, size_t n, double dt_s, int e, double **out)
{
    double *theta = malloc((n + 1u) * sizeof(*theta));
    double mean = 0.0, acc = 0.0;
    size_t k;
    *out = NULL;
    if (theta == NULL) {
        return INC_ERR_NO_SPACE;
    }
    for (k = 0; k < n; k++) {
        mean += ldexp(y[k], -e);
    }
    mean /= (double)n;
    theta[0] = 0.0;
    for (k = 0; k < n; k++) {
        acc += (ldexp(y[k], -e) - mean) * dt_s;
        theta[k + 1u] = acc;
    }
    if (!isfinite(acc)) {
        free(theta);
        return INC_ERR_RANGE;
    }
    *out = theta;
    return INC_OK;
}

static double avar_m(const double *theta, size_t n, double dt_s, size_t m)
{
    const size_t terms = n - 2u * m + 1u;
    const double tau = (double)m * dt_s;
    double s = 0.0;
    size_t k;
    for (k = 0; k < terms; k++) {
        const double d = theta[k + 2u * m] - 2.0 * theta[k + m] + theta[k];
        s += d * d;
    }
    return s / (2.0 * tau * tau * (double)terms);
}

double sim_allan_at(const double *y, size_t n, double dt_s, uint64_t m)
{
    double *theta, v;
    int e;
    if (y == NULL || !(dt_s > 0.0) || m < 1u || n < 3u || m > (uint64_t)((n - 1u) / 2u)) {
        return -1.0;
    }
    e = scale_exponent(y, n);
    if (integrate(y, n, dt_s, e, &theta) != INC_OK) {
        return -1.0;
    }
    v = ldexp(sqrt(avar_m(theta, n, dt_s, (size_t)m)), e);
    free(theta);
    return isfinite(v) ? v : -1.0;
}

int sim_allan_compute(const double *y, size_t n, double dt_s, const struct sim_allan_opts *opts,
                      struct sim_allan_point *pts, size_t max_pts, size_t *count)
{
    unsigned per_decade = 10u;
    double min_clusters = 10.0, m_limit;
    double *theta;
    size_t k, out = 0, last_m = 0;
    int err = INC_OK, e;
    if (y == NULL || pts == NULL || count == NULL) {
        return INC_ERR_NULL;
    }
    *count = 0;
    if (opts != NULL) {
        if (opts->per_decade != 0u) {
            per_decade = opts->per_decade;
        }
        if (opts->min_clusters != 0.0) {
            min_clusters = opts->min_clusters;
        }
    }
    if (n < 4u || !(dt_s > 0.0) || !isfinite(dt_s) || per_decade > 100u || !(min_clusters >= 2.0) ||
        !isfinite(min_clusters)) {
        return INC_ERR_INVAL;
    }
    for (k = 0; k < n; k++) {
        if (!isfinite(y[k])) {
            return INC_ERR_INVAL;
        }
    }
    m_limit = floor((double)n / min_clusters);
    if (m_limit > (double)((n - 1u) / 2u)) {
        m_limit = (double)((n - 1u) / 2u);
    }
    if (m_limit < 1.0) {
        return INC_ERR_RANGE;
    }
    e = scale_exponent(y, n);
    err = integrate(y, n, dt_s, e, &theta);
    if (err != INC_OK) {
        return err;
    }
    for (k = 0;; k++) {
        const double mf = floor(pow(10.0, (double)k / (double)per_decade) + 0.5);
        size_t m;
        if (mf > m_limit) {
            break;
        }
        m = (size_t)mf;
        if (m == last_m) {
            continue;
        }
        last_m = m;
        if (out == max_pts) {
            err = INC_ERR_NO_SPACE;
            break;
        }
        pts[out].m = m;
        pts[out].tau_s = (double)m * dt_s;
        pts[out].adev = ldexp(sqrt(avar_m(theta, n, dt_s, m)), e);
        pts[out].err = pts[out].adev / sqrt(2.0 * ((double)n / (double)m - 1.0));
        if (!isfinite(pts[out].adev) || !isfinite(pts[out].err) || !isfinite(pts[out].tau_s)) {
            err = INC_ERR_RANGE;
            out = 0;
            break;
        }
        out++;
    }
    free(theta);
    *count = out;
    return err;
}

double sim_allan_interp(const struct sim_allan_point *pts, size_t count, double tau_s)
{
    size_t i;
    if (pts == NULL || count == 0u || !(tau_s > 0.0)) {
        return -1.0;
    }
    for (i = 0; i < count; i++) {
        if (pts[i].tau_s == tau_s) {
            return pts[i].adev;
        }
        if (i + 1u < count && pts[i].tau_s < tau_s && tau_s < pts[i + 1u].tau_s) {
            const double f = log(tau_s / pts[i].tau_s) / log(pts[i + 1u].tau_s / pts[i].tau_s);
            if (!(pts[i].adev > 0.0) || !(pts[i + 1u].adev > 0.0)) {
                return -1.0;
            }
            return exp(log(pts[i].adev) + f * (log(pts[i + 1u].adev) - log(pts[i].adev)));
        }
    }
    return -1.0;
}

int sim_allan_readoff(const struct sim_allan_point *pts, size_t count, double max_rel_err,
                      struct sim_allan_readoff *r)
{
    size_t i, imin = 0, last = 0;
    bool found = false;
    if (pts == NULL || r == NULL) {
        return INC_ERR_NULL;
    }
    if (max_rel_err == 0.0) {
        max_rel_err = SIM_ALLAN_MIN_REL_ERR;
    }
    if (count == 0u || !(max_rel_err > 0.0)) {
        return INC_ERR_INVAL;
    }
    for (i = 0; i < count; i++) {
        if (!(pts[i].err <= max_rel_err * pts[i].adev)) {
            continue;
        }
        if (!found || pts[i].adev < pts[imin].adev) {
            imin = i;
        }
        found = true;
        last = i;
    }
    if (!found) {
        return INC_ERR_INVAL;
    }
    r->arw = sim_allan_interp(pts, count, 1.0);
    r->arw_valid = r->arw >= 0.0;
    if (!r->arw_valid) {
        r->arw = 0.0;
    }
    r->adev_min = pts[imin].adev;
    r->tau_min_s = pts[imin].tau_s;
    r->bias_instability = r->adev_min / SIM_ALLAN_BI_FACTOR;
    r->min_interior = imin > 0u && imin < last;
    return INC_OK;
}
