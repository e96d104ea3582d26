/*
 * kf.h - small linear Kalman filter in fixed point (module inclino_kf, prefix kf_).
 *
 * The five equations of [KF-SCA3000] for 1 to KF_N_MAX states:
 *   (1) x(k|k-1) = A x(k-1|k-1) + B u(k)                       kf_predict
 *   (2) P(k|k-1) = A P(k-1|k-1) A' + Q                          kf_predict
 *   (3) x(k|k)   = x(k|k-1) + Kg(k) (z(k) - H x(k|k-1))         kf_update
 *   (4) Kg(k)    = P(k|k-1) H' / (H P(k|k-1) H' + R)            kf_update
 *   (5) P(k|k)   = (I - Kg(k) H) P(k|k-1)                        kf_update, in Joseph form
 * R must be diagonal: the rows of z are applied one after the other as scalar updates, which is
 * the same filter as (3)-(5) with the matrix inverse (docs/kalman.md), needs one division per
 * state and row instead of an inverse, and lets a caller drop a rejected row (kf_update's mask).
 * (5) is computed in Joseph form, (I - K h) P (I - K h)' + K r K', which keeps P symmetric and
 * positive semi-definite even though K is rounded. Freestanding C11, integer only, no heap;
 * caller-owned state (struct kf) and caller-owned model matrices (struct kf_model / kf_meas, CMSIS
 * style: pointers to row-major arrays, which may be static const or rebuilt per step).
 *
 * UNITS AND FORMATS. The caller chooses a "raw" integer unit per state, per control input and
 * per measurement row (normally Q16 physical quantities: Q16 deg, Q16 deg/s, Q16 g). Then:
 *   x   int64 x_i * 2^KF_X_FRAC (16 extra fractional bits: sub-LSB increments accumulate instead
 *       of stalling when the gain is small). |x| <= KF_X_LIMIT (the int32 raw range); kf_x()
 *       returns the state rounded to its raw unit.
 *   u, z int32 raw.
 *   A, B, H  fx_q30_t ratios raw-to-raw, |entry| < 2. Choose the raw units so that this holds
 *       (e.g. angle += dt * rate: Q16 deg, Q16 deg/s and dt in seconds as a Q30 ratio).
 *   P, Q, R  int64, "P format": variance in raw_i * raw_j units times 2^KF_P_FRAC. For Q16 states
 *       that is the physical covariance times 2^48: 1 LSB = 3.55e-15 unit^2, and KF_P_MAX = 2^60
 *       is 4096 unit^2 ((64 unit)^2). Why int64 with 48 fractional bits: an angle (deg^2) and a
 *       gyro bias ((deg/s)^2) per step at 819.2 Hz span ~16 decades (P0 of 10^3 deg^2 down to a
 *       bias process noise of 10^-12 (deg/s)^2 per step), which int32 Q16 cannot hold; 2^-48..2^12
 *       does, with >= 8 significant bits at 10^-12 (docs/kalman.md, "Representation").
 *   K   int64 Q30 (internal).
 * Every product is formed exactly in 128 bits (inclino/fx128.h) and rounded once to nearest,
 * ties away from zero.
 *
 * RANGES. Q and P0: symmetric, diagonal in [0, KF_P_MAX], |off-diagonal| <= KF_P_MAX and
 *   q_ij^2 <= q_ii q_jj (every 2x2 principal minor >= 0; for n >= 3 the caller must also make
 *   them positive semi-definite as a whole). R: each entry in [1, KF_P_MAX]. Results that leave
 *   the ranges saturate (P to +-KF_P_MAX, diagonal never below 0; x to +-KF_X_LIMIT); the call
 *   then returns INC_ERR_OVERFLOW and f->overflow stays set until kf_clear_overflow(). A
 *   filter whose models respect these ranges and whose P stays below KF_P_MAX never saturates.
 *
 * ERROR against exact math on the same stored operands: every stored quantity is its exact
 *   formula rounded once to nearest (<= 0.5 LSB of its format): x-, A P (internal), v = P h',
 *   h P h', the innovation, k = v / s (Q30), s k, each correction k y and each Joseph term. So:
 *     predict  x-: <= 0.5 LSB (internal); P-(i, j): <= 0.5 (1 + max(sum_k |a_ik|, sum_k |a_jk|))
 *              LSB (two roundings: A P, then (A P) A');
 *     update   P+(i, j): within 2 LSB + 2^-28 max|P| of the exact P - v v' / s (the rounding of
 *              the gain, which the Joseph form turns into a second-order term).
 *   tests/kf/test_kf_exact.c proves both and checks the firmware bit for bit against an
 *   independent __int128 model of these roundings; tests/kf/test_kf_ref.cpp compares 10^6-step
 *   runs with the double-precision Eigen reference (sim/kfref).
 *
 * COST per call (n states, nu inputs, one measurement row; zero entries of A, B and h skip their
 *   products): predict n (n + nu) + n^3 + n^2 (n + 1) / 2 128-bit multiply-adds and one
 *   validation of Q; update n^2 + 5n + 3 n (n + 1) / 2 products and n 128/64 divisions (one
 *   shift-subtract step per quotient bit, ~31 for |k| < 1). Measured instructions, flash and RAM:
 *   docs/benchmarks.md, "Kalman and tilt".
 */
#ifndef INCLINO_KF_H
#define INCLINO_KF_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/error.h"
#include "inclino/fx.h"

#ifdef __cplusplus
extern "C" {
#endif

#define KF_N_MAX 4u /* states */
#define KF_U_MAX 4u /* control inputs */
#define KF_M_MAX 4u /* measurement rows per kf_update call */

#define KF_X_FRAC 16u /* internal state = raw * 2^16 */
#define KF_P_FRAC 16u /* covariance = raw_i * raw_j * 2^16 */

/* Largest |P|, |Q|, R entry: 2^60 (4096 unit^2 for Q16 states). Leaves 2^3 of headroom for the
 * sums inside A P A' before int64 would overflow. */
#define KF_P_MAX ((int64_t)1 << 60)
/* Largest |x|: the int32 raw range, so kf_x() always fits int32. */
#define KF_X_LIMIT ((int64_t)INT32_MAX * 65536)

/* 1 unit^2 in P format for Q16 states (2^48). E.g. (0.5 deg)^2 = KF_P_ONE_Q16 / 4. */
#define KF_P_ONE_Q16 ((int64_t)1 << 48)

/* The filter state. Caller-allocated; set up by kf_init. The fields may be read directly
 * (formats above); write them only through the functions. */
struct kf {
    int64_t x[KF_N_MAX];           /* state, raw * 2^KF_X_FRAC */
    int64_t p[KF_N_MAX][KF_N_MAX]; /* covariance, P format, symmetric */
    uint8_t n;                     /* states, 1..KF_N_MAX; 0 = not initialised */
    bool overflow;                 /* sticky: a result saturated since init/clear */
};

/* Equations (1) and (2): the transition. Row-major arrays owned by the caller. */
struct kf_model {
    uint8_t n;         /* states, must equal the filter's */
    uint8_t nu;        /* control inputs, 0..KF_U_MAX */
    const fx_q30_t *a; /* A, n x n, Q30 */
    const fx_q30_t *b; /* B, n x nu, Q30 (may be NULL when nu == 0) */
    const int64_t *q;  /* Q, n x n, P format (symmetric, see RANGES) */
};

/* Equations (3) to (5): m measurement rows with diagonal R. */
struct kf_meas {
    uint8_t n;         /* states, must equal the filter's */
    uint8_t m;         /* rows, 1..KF_M_MAX */
    const fx_q30_t *h; /* H, m x n, Q30 */
    const int64_t *r;  /* diagonal of R, m entries, P format in the row's raw unit, >= 1 */
};

/* Set up a filter of n states with x = x0 (raw, NULL: zeros) and P = p0 (n x n row-major, P
 * format, see RANGES). Errors: INC_ERR_NULL (f or p0 NULL), INC_ERR_INVAL (n outside 1..KF_N_MAX,
 * or p0 outside its ranges). On error f->n is 0 and every other call refuses the filter. */
int kf_init(struct kf *f, unsigned n, const int32_t *x0, const int64_t *p0);

/* Check a model (dimensions, pointers, Q ranges) without running it. 0 or INC_ERR_NULL /
 * INC_ERR_INVAL as kf_predict would return. */
int kf_model_check(const struct kf_model *m, unsigned n);

/* Check a measurement model (dimensions, pointers, 1 <= r <= KF_P_MAX). */
int kf_meas_check(const struct kf_meas *ms, unsigned n);

/* Equations (1) and (2). u: nu raw inputs (may be NULL when nu == 0).
 * Returns 0; INC_ERR_NULL (f, m, a, q, or b/u with nu > 0); INC_ERR_STATE (f not initialised);
 * INC_ERR_INVAL (m->n != f->n, nu > KF_U_MAX, Q outside its ranges): the filter is unchanged;
 * INC_ERR_OVERFLOW: done, but a result saturated (see RANGES). */
int kf_predict(struct kf *f, const struct kf_model *m, const int32_t *u);

/* Equations (3) to (5) for one scalar measurement z (raw) with row h (n entries, Q30) and
 * variance r (P format, 1..KF_P_MAX). Returns 0; INC_ERR_NULL; INC_ERR_STATE; INC_ERR_INVAL (r out
 * of range; filter unchanged); INC_ERR_DEGENERATE (h P h' + r rounds to <= 0, which needs a P
 * that is not positive semi-definite; filter unchanged); INC_ERR_OVERFLOW (done, saturated). */
int kf_update_row(struct kf *f, const fx_q30_t *h, int64_t r, int32_t z);

/* The rows i of ms whose bit (1u << i) is set in use_mask, in index order, each by
 * kf_update_row. A rejected measurement is simply left out of the mask (the filter coasts on
 * the prediction for it). Returns 0, or the first error (rows after a failing one are not
 * applied); INC_ERR_OVERFLOW does not stop the loop and is returned at the end. */
int kf_update(struct kf *f, const struct kf_meas *ms, const int32_t *z, uint32_t use_mask);

/* State i rounded to its raw unit (ties away from zero). 0 when f is NULL or i >= f->n. */
int32_t kf_x(const struct kf *f, unsigned i);

/* P(i, j) in P format. 0 when f is NULL or i, j >= f->n. */
int64_t kf_p(const struct kf *f, unsigned i, unsigned j);

/* Standard deviation sqrt(P(i, i)) in the raw unit of state i, rounded to nearest
 * (|error| <= 0.5 LSB + the 2^-8 LSB resolution of P). 0 when f is NULL or i >= f->n. */
int32_t kf_sigma(const struct kf *f, unsigned i);

/* A variance in P format from a standard deviation in raw units: sigma^2 * 2^KF_P_FRAC, exact,
 * saturated to KF_P_MAX (|sigma| >= 2^22 raw). */
int64_t kf_var_from_sigma(int32_t sigma_raw);

/* Clear the sticky overflow flag. */
void kf_clear_overflow(struct kf *f);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_KF_H */
