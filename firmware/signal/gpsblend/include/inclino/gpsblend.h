/*
 * gpsblend.h - speed across the gaps between GPS fixes ([KF-SCA3000]), module inclino_gpsblend,
 * prefix gpsb_.
 *
 * GPS gives speed once a second; between fixes the speed is propagated from the along-track
 * acceleration every step (13 ms in [KF-SCA3000]) and blended with the last GPS speed:
 *   v_acc = v + a * g0 * dt                       (dead reckoning from the current estimate)
 *   v     = v_gps + K * (v_acc - v_gps)           (K = 1: trust the accelerometer)
 *   K^2   = A^2 / (A^2 + Q^2), then n rounds of K = K + (1 - K) * K
 * A is the acceleration, Q the accelerometer's noise at rest ([KF-SCA3000]: Q = 20 counts, i.e. the
 * same unit as A). When the vehicle cruises (|A| << Q) K is near 0 and the speed stays on the
 * GPS value; when it accelerates or turns (|A| >> Q) K goes to 1 and the accelerometer carries
 * it. Each round pushes K towards 1: one round is 1 - (1 - K)^2, [KF-SCA3000]'s preferred curve.
 * A GPS fix resets the speed to the fix.
 *
 * Fixed point: acceleration and Q in Q16.16 g, speed in Q16.16 m/s at the interface (Q32.32
 * inside, so the per-step rounding does not accumulate), K in Q30, dt in ns.
 */
#ifndef INCLINO_GPSBLEND_H
#define INCLINO_GPSBLEND_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/error.h"
#include "inclino/fx.h"

#ifdef __cplusplus
extern "C" {
#endif

#define GPSB_G0_Q16 ((fx_q16_t)642689) /* standard gravity 9.80665 m/s^2 in Q16 (0.3 ppm) */
#define GPSB_MAX_ROUNDS 8u

struct gpsb_cfg {
    fx_q16_t q_noise_g;   /* Q: at-rest noise of the acceleration (Q16 g), > 0 */
    uint8_t rounds;       /* n: rounds of K = K + (1 - K) K, 0..GPSB_MAX_ROUNDS (default 1) */
    uint32_t max_gap_ns;  /* longer without a fix -> speed not valid (e.g. 3 s), > 0 */
    uint32_t max_step_ns; /* a step longer than this is refused (INC_ERR_RANGE), 1..1e9 */
};

struct gpsb {
    struct gpsb_cfg cfg;
    int64_t v_q32;         /* blended speed, Q32.32 m/s */
    int64_t v_gps_q32;     /* last GPS speed, Q32.32 m/s */
    uint64_t since_fix_ns; /* time since the last fix */
    bool have_fix;
    bool ready;      /* initialised */
    fx_q30_t last_k; /* K of the last step (for logs and tests) */
};

/* The default configuration: Q as given, one round, 3 s gap, 100 ms maximum step. */
struct gpsb_cfg gpsb_default_cfg(fx_q16_t q_noise_g);

/* Initialise. Returns 0, INC_ERR_NULL or INC_ERR_INVAL (q <= 0, rounds > max, times out of
 * range). */
int gpsb_init(struct gpsb *s, const struct gpsb_cfg *cfg);

/*
 * The blending factor for acceleration a and noise q (Q16 g), after `rounds` rounds, in Q30
 * [0, 1]. |error| against the exact formula for the same inputs (q > 0): <= 4 LSB Q30 (4e-9)
 * with 0 rounds; each round at most doubles it and adds 0.5 LSB (<= 9 LSB after 1 round).
 * a == 0 gives exactly 0. q <= 0 gives 1 (no noise known: trust the accelerometer).
 */
fx_q30_t gpsb_factor(fx_q16_t a_g, fx_q16_t q_g, unsigned rounds);

/* A GPS fix: speed v (Q16 m/s). The blended speed is reset to it. */
int gpsb_fix(struct gpsb *s, fx_q16_t v_mps);

/*
 * One propagation step of dt_ns with along-track acceleration a (Q16 g). *v_mps (may be NULL)
 * gets the blended speed (Q16 m/s, rounded to nearest, saturating). Returns 0, INC_ERR_NULL,
 * INC_ERR_STATE (no fix yet: nothing to blend with; *v_mps = 0), INC_ERR_RANGE (dt_ns == 0 or
 * > max_step_ns: the step is refused, the state unchanged), or INC_ERR_TIMEOUT (the gap since the
 * last fix exceeds max_gap_ns: the speed is still propagated and returned but not to be trusted).
 * |a| is clamped to 16 g. Arithmetic per step against double precision on the same inputs:
 * a * g0 rounded to Q16 m/s^2 (3.8e-6 m/s^2), dv rounded once in Q32, K within 4e-9, the blend
 * rounded once in Q32: < 1e-7 m/s per 13 ms step, so < 1e-5 m/s over a 1 s gap.
 */
int gpsb_step(struct gpsb *s, fx_q16_t a_g, uint32_t dt_ns, fx_q16_t *v_mps);

/* The blended speed (Q16 m/s) and whether it is valid (a fix, within the gap). */
bool gpsb_speed(const struct gpsb *s, fx_q16_t *v_mps);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_GPSBLEND_H */
