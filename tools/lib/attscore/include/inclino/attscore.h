/*
 * attscore.h - the inclination-error metric of the BROAD benchmark and the integrity figures of
 * an attitude estimate (module inclino_attscore, host). docs/attitude.md, "How it is scored".
 *
 * Metric (Laidig, Weygers, Seel 2021, docs/references.md [BROAD]): per sample
 * q_err = q_est * inverse(q_truth); the inclination error is 2 acos(min(1, sqrt(w^2 + z^2))) of
 * q_err, in degrees: the angle between the estimated and the true direction of gravity, which
 * does not depend on heading. Samples scored: movement = 1, truth finite, t >= t_min (5 s).
 * Integrity: among the scored samples the estimator marked valid, the fraction whose error
 * exceeds the stated bound, and the largest error / bound.
 */
#ifndef INCLINO_ATTSCORE_H
#define INCLINO_ATTSCORE_H

#include <stdbool.h>
#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Inclination error in degrees between two quaternions (w, x, y, z; need not be unit). NaN when
 * either has zero norm or a non-finite component. */
double attscore_incl_err_deg(const double qe[4], const double qt[4]);

/* One sample of a trial: the truth, its flags, and the estimate with its bound and validity. */
struct attscore_sample {
    double t_s;
    double q_truth[4]; /* NaN: truth lost */
    int movement;      /* 1: scored phase */
    double q_est[4];
    double bound_deg; /* the estimator's bound (NaN: none stated) */
    bool valid;
};

struct attscore_result {
    size_t n;                  /* samples scored */
    double rms_deg, max_deg;   /* inclination error over the scored samples */
    size_t n_valid;            /* scored samples marked valid */
    double valid_frac;         /* n_valid / n */
    size_t n_over;             /* valid scored samples whose error exceeds the bound */
    double over_bound_frac;    /* n_over / n_valid (0 when none is valid) */
    double max_err_over_bound; /* largest error / bound among valid scored samples */
    double max_valid_err_deg;  /* largest error among valid scored samples */
    double median_bound_deg;   /* median bound over the scored samples */
    /* Roll and pitch errors (ZYX Euler angles of both quaternions, roll wrapped to +-180 deg)
     * over the scored samples: meaningful for a vehicle, whose pitch stays far from +-90 deg. */
    double roll_rms_deg, roll_max_deg, pitch_rms_deg, pitch_max_deg;
};

/* Roll (about x) and pitch (about y) of q (w, x, y, z) in the ZYX Euler convention, deg. */
void attscore_roll_pitch_deg(const double q[4], double *roll_deg, double *pitch_deg);

/* Score n samples; t_min_s: samples before it are not scored. Returns 0, or -1 for bad arguments
 * (NULL) or when memory runs out. A non-finite error counts as 180 deg. */
int attscore_score(const struct attscore_sample *s, size_t n, double t_min_s,
                   struct attscore_result *r);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_ATTSCORE_H */
