/*
 * kf_adapt.h - the adaptive per-axis Kalman filter of [CN110567483], steps 1 to 3 (module inclino_kf,
 * prefix kf_adapt_).
 *
 * One scalar filter per axis; kf_adapt6 runs six of them (gyro x, y, z, accel x, y, z, the
 * seed's in_wx .. in_az) with constants per axis. Every sample z(k):
 *   step 2   dz   = (k * Z(k) - (Z(k) + Z(k-1) + ... + Z(k-k+1))) / (k - 1)
 *                 = the mean of the k-1 differences Z(k) - Z(k-i), i = 1..k-1
 *            Q(k) = C + D * |dz|
 *            R(k) = |A + B * Q(k)|
 *   step 3   X-   = X(k-1)                     (the prediction is the previous estimate)
 *            P-   = P(k-1) + Q(k)
 *            K    = P- / (P- + R(k))
 *            X(k) = X- + K (Z(k) - X-)
 *            P(k) = (1 - K) P-
 * k is the window: the current sample and the k-1 before it, sliding. The printed dz ([CN110567483],
 * step 2) divides by k - 1 but its sum leaves Z(k) out, which is not the mean difference it
 * names; with Z(k) in the sum it is (docs/references.md). A growing window from the first
 * sample (the patent's literal k) would make dz insensitive to new samples after a long run, so
 * the window slides. Until k samples have arrived the samples seen so far are used (n of them,
 * dz over n - 1 differences); the first sample sets X = Z and dz = 0.
 *
 * FORMATS (as inclino/kf.h; "raw" is the axis's sample unit, normally Q16 deg/s or Q16 g):
 *   Z, estimate     int32 raw. The estimate is kept internally with KF_X_FRAC = 16 extra bits.
 *   dz              int32 raw, round(.) ties away from zero, saturated to int32 (|error| <= 0.5).
 *   C, A, Q, R, P   int64 P format (raw^2 * 2^16; for Q16 samples unit^2 * 2^48, KF_P_ONE_Q16).
 *   D               int64, raw * 2^16 (for Q16 samples: D in the sample unit times 2^32), so that
 *                   D * |dz| is in P format. Q = C + D |dz| is exact, then saturated to KF_P_MAX.
 *   B               fx_q16_t, dimensionless, any sign. R = |A + round(B Q / 2^16)|, saturated to
 *                   KF_P_MAX (|error| <= 0.5 LSB before the absolute value).
 *   K               Q30 in [0, 1]: round(P- 2^30 / (P- + R)) (|error| <= 0.5 LSB Q30).
 *   P               round((2^30 - K) P- / 2^30) (|error| <= 0.5 LSB).
 * RANGES: C in [1, KF_P_MAX] (C > 0 keeps P- + R > 0), D in [0, KF_P_MAX], A in
 *   [-KF_P_MAX, KF_P_MAX], any B, p0 in [0, KF_P_MAX], window k in 2..KF_ADAPT_WIN_MAX.
 *   Q, R and P- are clamped to KF_P_MAX; P stays in [0, KF_P_MAX] because 0 <= K <= 1. Nothing
 *   can overflow: the window sum is int64 (k * 2^31 < 2^37), products are 128-bit.
 * COST per sample: one 64/32 division (dz), one 128/64 division (K), six 128-bit products;
 * RAM per axis sizeof(struct kf_adapt) (216 bytes on 32-bit targets with KF_ADAPT_WIN_MAX 32).
 * Instruction counts, flash and RAM: docs/benchmarks.md; tuning of C, D, A, B: docs/kalman.md
 * ("Tuning procedure").
 */
#ifndef INCLINO_KF_ADAPT_H
#define INCLINO_KF_ADAPT_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/error.h"
#include "inclino/fx.h"
#include "inclino/kf.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Largest window k (samples incl. the current one). Each axis keeps k samples of history
 * (4 bytes each). Override at compile time for a different memory budget. */
#ifndef KF_ADAPT_WIN_MAX
#define KF_ADAPT_WIN_MAX 32u
#endif

#define KF_ADAPT_AXES 6u /* gyro x, y, z, accel x, y, z ([CN110567483]: in_wx .. in_az) */

/* Constants of one axis ([CN110567483] step 2 names). */
struct kf_adapt_config {
    uint32_t window; /* k: samples in the window including the current one, 2..KF_ADAPT_WIN_MAX */
    int64_t c;       /* C: process noise constant, P format, 1..KF_P_MAX */
    int64_t d;       /* D: process noise slope per |dz|, raw * 2^16, 0..KF_P_MAX */
    int64_t a;       /* A: measurement noise constant, P format, |A| <= KF_P_MAX */
    fx_q16_t b;      /* B: measurement noise slope on Q, dimensionless Q16, any sign */
    int64_t p0;      /* P at the first sample, P format, 0..KF_P_MAX */
};

/* State of one axis. Caller-allocated, set up by kf_adapt_init. */
struct kf_adapt {
    struct kf_adapt_config cfg;
    int32_t hist[KF_ADAPT_WIN_MAX]; /* the last k samples (ring) */
    int64_t sum;                    /* exact sum of hist[0..count-1] */
    int64_t x;                      /* estimate, raw * 2^KF_X_FRAC */
    int64_t p;                      /* P format */
    uint32_t head;                  /* slot of the next sample */
    uint32_t count;                 /* samples in the window, 0..k */
    bool ready;                     /* initialised */
};

/* Diagnostics of one step (kf_adapt_process may be passed NULL instead). */
struct kf_adapt_step {
    int32_t dz;   /* step 2, raw */
    int64_t q, r; /* Q(k), R(k), P format */
    fx_q30_t k;   /* gain, Q30 in [0, 2^30] */
};

/* Check a configuration. 0, INC_ERR_NULL, INC_ERR_INVAL (a field outside RANGES). */
int kf_adapt_config_check(const struct kf_adapt_config *cfg);

/* Set up one axis. The first kf_adapt_process() then starts the filter at that sample.
 * INC_ERR_NULL / INC_ERR_INVAL as kf_adapt_config_check; on error the axis refuses every call. */
int kf_adapt_init(struct kf_adapt *f, const struct kf_adapt_config *cfg);

/* Forget the history and the estimate (the constants are kept): the next sample restarts it. */
void kf_adapt_restart(struct kf_adapt *f);

/* One sample z (raw): steps 2 and 3. *est = the new estimate (raw, rounded). step (may be NULL)
 * receives dz, Q, R and K. Returns 0; INC_ERR_NULL (f or est); INC_ERR_STATE (not initialised). */
int kf_adapt_process(struct kf_adapt *f, int32_t z, int32_t *est, struct kf_adapt_step *step);

/* A rejected or missing sample (saturated, out of range): the estimate is held, P grows by C
 * (the prediction step with the smallest process noise); the window is not touched, so dz keeps
 * comparing real samples. *est = the held estimate. Errors as kf_adapt_process. */
int kf_adapt_coast(struct kf_adapt *f, int32_t *est);

/* The estimate (raw, rounded); 0 before the first sample or when f is NULL. */
int32_t kf_adapt_estimate(const struct kf_adapt *f);

/* ---- six axes ------------------------------------------------------------------------------ */

struct kf_adapt6 {
    struct kf_adapt axis[KF_ADAPT_AXES];
};

/* cfg[6]: one configuration per axis, in the order gyro x, y, z, accel x, y, z. Errors as
 * kf_adapt_init for the first failing axis (then no axis is usable). */
int kf_adapt6_init(struct kf_adapt6 *f, const struct kf_adapt_config cfg[KF_ADAPT_AXES]);

/* z[6] raw samples in the same order; est[6] the estimates. use_mask bit i set: axis i takes
 * z[i]; clear: axis i coasts (kf_adapt_coast). Returns 0 or the first error. */
int kf_adapt6_process(struct kf_adapt6 *f, const int32_t z[KF_ADAPT_AXES], uint32_t use_mask,
                      int32_t est[KF_ADAPT_AXES]);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_KF_ADAPT_H */
