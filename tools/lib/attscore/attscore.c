/* attscore.c - the BROAD inclination metric and integrity figures (see inclino/attscore.h). */
#include "inclino/attscore.h"

#include <math.h>
#include <stdlib.h>

#define RAD2DEG (180.0 / 3.14159265358979323846)

double attscore_incl_err_deg(const double a[4], const double b[4])
{
    /* q_err = a * conj(b) / |b|^2; its w and z components only. */
    const double an = a[0] * a[0] + a[1] * a[1] + a[2] * a[2] + a[3] * a[3];
    const double bn = b[0] * b[0] + b[1] * b[1] + b[2] * b[2] + b[3] * b[3];
    const double w = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
    const double z = -a[0] * b[3] - a[1] * b[2] + a[2] * b[1] + a[3] * b[0];
    double c;
    if (!(an > 0.0) || !(bn > 0.0) || !isfinite(an) || !isfinite(bn)) return NAN;
    c = sqrt((w * w + z * z) / (an * bn));
    if (c > 1.0) c = 1.0;
    return 2.0 * acos(c) * RAD2DEG;
}

void attscore_roll_pitch_deg(const double q[4], double *roll_deg, double *pitch_deg)
{
    const double n = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    const double w = q[0] / n, x = q[1] / n, y = q[2] / n, z = q[3] / n;
    double sp = 2.0 * (w * y - z * x);
    if (sp > 1.0) sp = 1.0;
    if (sp < -1.0) sp = -1.0;
    *roll_deg = atan2(2.0 * (w * x + y * z), 1.0 - 2.0 * (x * x + y * y)) * RAD2DEG;
    *pitch_deg = asin(sp) * RAD2DEG;
}

static double wrap180(double d)
{
    while (d > 180.0)
        d -= 360.0;
    while (d < -180.0)
        d += 360.0;
    return d;
}

static int cmp_double(const void *x, const void *y)
{
    const double a = *(const double *)x, b = *(const double *)y;
    return a < b ? -1 : (a > b ? 1 : 0);
}

static bool finite4(const double q[4])
{
    return isfinite(q[0]) && isfinite(q[1]) && isfinite(q[2]) && isfinite(q[3]);
}

int attscore_score(const struct attscore_sample *s, size_t n, double t_min_s,
                   struct attscore_result *r)
{
    double sum2 = 0.0, sum_r = 0.0, sum_p = 0.0, *bounds;
    size_t i, k = 0;
    if (s == NULL || r == NULL) return -1;
    bounds = malloc((n ? n : 1u) * sizeof(*bounds));
    if (bounds == NULL) return -1;
    r->n = r->n_valid = r->n_over = 0;
    r->rms_deg = r->max_deg = r->valid_frac = r->over_bound_frac = 0.0;
    r->max_err_over_bound = r->max_valid_err_deg = r->median_bound_deg = 0.0;
    r->roll_rms_deg = r->roll_max_deg = r->pitch_rms_deg = r->pitch_max_deg = 0.0;
    for (i = 0; i < n; i++) {
        double e;
        if (s[i].movement != 1 || !(s[i].t_s >= t_min_s) || !finite4(s[i].q_truth)) continue;
        e = attscore_incl_err_deg(s[i].q_est, s[i].q_truth);
        if (!isfinite(e)) e = 180.0;
        {
            double re, pe, rt, pt, dr, dp;
            if (finite4(s[i].q_est) && isfinite(e) && e < 180.0) {
                attscore_roll_pitch_deg(s[i].q_est, &re, &pe);
                attscore_roll_pitch_deg(s[i].q_truth, &rt, &pt);
                dr = fabs(wrap180(re - rt));
                dp = fabs(pe - pt);
            } else {
                dr = dp = 180.0;
            }
            sum_r += dr * dr;
            sum_p += dp * dp;
            if (dr > r->roll_max_deg) r->roll_max_deg = dr;
            if (dp > r->pitch_max_deg) r->pitch_max_deg = dp;
        }
        sum2 += e * e;
        if (e > r->max_deg) r->max_deg = e;
        bounds[k++] = isfinite(s[i].bound_deg) ? s[i].bound_deg : INFINITY;
        if (s[i].valid) {
            /* A valid sample with no finite bound is over it by definition. */
            const double ratio = s[i].bound_deg > 0.0 ? e / s[i].bound_deg : INFINITY;
            r->n_valid++;
            if (!(e <= s[i].bound_deg)) r->n_over++;
            if (!(ratio <= r->max_err_over_bound)) r->max_err_over_bound = ratio;
            if (e > r->max_valid_err_deg) r->max_valid_err_deg = e;
        }
    }
    r->n = k;
    if (k > 0) {
        r->rms_deg = sqrt(sum2 / (double)k);
        r->roll_rms_deg = sqrt(sum_r / (double)k);
        r->pitch_rms_deg = sqrt(sum_p / (double)k);
        r->valid_frac = (double)r->n_valid / (double)k;
        qsort(bounds, k, sizeof(*bounds), cmp_double);
        r->median_bound_deg = bounds[k / 2];
    }
    if (r->n_valid > 0) r->over_bound_frac = (double)r->n_over / (double)r->n_valid;
    free(bounds);
    return 0;
}
