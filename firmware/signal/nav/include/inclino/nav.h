/*
 * nav.h - dead reckoning between GPS fixes ([KF-SCA3000]), module inclino_nav, prefix nav_.
 * Freestanding C11, integer only, caller-allocated state, no heap. docs/navigation.md.
 *
 * A GPS receiver gives a fix once a second; between fixes the track is computed every 13 ms
 * from a yaw-rate gyro (ADIS16255) and a forward accelerometer axis (SCA3000):
 *   heading  the gyro rate minus its offset (learned at rest through the stillness gate,
 *            nav_gyro_offset), smoothed by P passes (1..4) of a W-sample moving average
 *            (avg_cascade, [KF-SCA3000]'s multi-pass averaging), integrated per gyro sample;
 *   speed    gpsb (gpsblend.h): the last GPS speed blended with the integrated acceleration by
 *            K^2 = A^2 / (A^2 + Q^2) and rounds of K = K + (1 - K) K; the acceleration is the
 *            gravity-compensated one of an attitude estimator when the caller has it
 *            (nav_in.a_comp), else the forward specific force minus the value it had at the
 *            last rest (nav_accel_rest: road grade and mounting pitch at that stop);
 *   position v (cos h, sin h) integrated every cycle in a local east/north frame about the first
 *            fix.
 * A new fix pulls the track back WITHOUT A JUMP: the fix is compared with the estimate at the
 * time it was valid (arrival minus the receiver latency; a ring of the last NAV_RING cycles),
 * and gain_pos times the difference is spread evenly over the next spread_cycles cycles (a
 * complementary filter: at 30 m/s a 1 m correction over 8 cycles moves the track by 1.2 cm per
 * 13 ms). A fix further from the estimate than (position bound + gps_bound) is a jump and is
 * refused; jump_reset consecutive refusals re-seat the track on the fix (the receiver was right).
 * The heading is pulled towards the GPS course the same way (gain_heading, at once: a fraction of
 * a degree) when the speed is at least course_min_mps.
 *
 * FRAMES AND UNITS. Heading h: Q16 degrees in [0, 360), 0 = east, 90 = north (counter-clockwise,
 * a left turn increases it; GPS course c maps to h = 90 - c). Position: east and north of the
 * reference (the first fix), inside Q32.32 metres (int64: +-2^31 m, resolution 2.3e-10 m), output
 * in int32 millimetres (+-2147 km). Speed: Q16 m/s, |v| <= NAV_V_MAX for the integration.
 * Projection of a fix: equirectangular about the reference latitude phi0 with the WGS-84 radii
 * of curvature M(phi0) (north) and N(phi0) cos(phi0) (east), in Q36 metres per 1e-7 deg; the
 * fix must be within NAV_REF_SPAN_E7 (0.5 deg, about 55 km) of the reference, else the frame is
 * re-based on that fix (nav_fix returns 1). Against exact math on the same radii: north 1e-8
 * relative, east 1e-6 relative up to 80 deg latitude (the reference latitude enters the sine in
 * Q16 degrees; 5 cm at 55 km, 1 mm per km), plus 0.5 LSB of Q32; against the true geodesic the flat-frame
 * error over 55 km is below 0.05 % (<= 27 m at the edge, a few cm over 1 km), the same for the
 * track and the fixes.
 *
 * ARITHMETIC PER CYCLE (against double precision on the same inputs): heading integrates the
 * averaged rate (Q16 deg/s, avg rounding 0.5 LSB) times dt exactly in Q16 deg x ns (no loss;
 * output rounded to Q16 deg, 0.5 LSB); sin/cos of fx_sincos_deg (5.3e-10); velocity components
 * rounded to Q16 m/s (7.6e-6 m/s); distance per cycle rounded once in Q32 m (1.2e-10 m).
 * Over a 1 s gap (77 cycles) the integration adds < 77 x 7.6e-6 x 0.013 m = 7.6e-6 m per axis:
 * tests/nav proves the track of a 60 s constant-rate turn (4615 cycles) against the same steps in
 * double precision within 0.6 mm (the 0.5 mm of the millimetre output included) and the heading
 * within 1 LSB Q16.
 *
 * BOUNDS (every output has one; all are error bounds against the truth under the stated
 * assumptions, not statistics):
 *   heading  B_h grows per gyro sample by (gyro_offset_bound + gyro_scale_bound |rate|) dt;
 *            the output adds |h_raw - h_avg| (the lag of the averaging: h_raw integrates the
 *            unsmoothed rate) and heading_noise_deg. A course update sets
 *            B_h = (1 - g) B_h + g cb, cb = course_bound x course_min / speed (the course is the
 *            direction of the velocity: its error bound falls as 1 / speed; course_bound holds
 *            at course_min). Assumes the offset error <= gyro_offset_bound
 *            and the scale error <= gyro_scale_bound (both configuration).
 *   speed    B_v = K (B_v + a_err dt) + (1 - K) (speed_bound + S) per cycle, K the blend factor
 *            of the step and S the integral of |A| + a_err since the fix (the GPS speed is
 *            stale by at most that): the blend's own error recursion. Assumes |acceleration
 *            error| <= accel_err_g.
 *   position B_p grows by (B_v + |v| (B_h + slip_deg) pi/180) dt per cycle (slip_deg: the
 *            side-slip the model leaves out); a fix applied over n cycles takes it to
 *            (1 - g/n) B_p + (g/n) gps_bound each cycle. Assumes |GPS error| <= gps_bound.
 *   VALIDITY: a flag is true when the quantity is initialised from a fix and its bound is at
 *   most the configured limit (pos_limit_m, speed_limit_mps, heading_limit_deg); the speed is
 *   also invalid while gpsb reports its gap exceeded (gpsb max_gap_ns). A valid output is
 *   within its bound of the truth; tests/nav asserts that on every cycle of the simulated drives.
 */
#ifndef INCLINO_NAV_H
#define INCLINO_NAV_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "inclino/avg.h"
#include "inclino/error.h"
#include "inclino/fx.h"
#include "inclino/gpsblend.h"

#ifdef __cplusplus
extern "C" {
#endif

#define NAV_RING 32u             /* cycles of history for latency (32 x 13 ms = 416 ms) */
#define NAV_AVG_MAX_W 16u        /* largest averaging window */
#define NAV_V_MAX_MPS 100        /* |v| clamp of the integration */
#define NAV_REF_SPAN_E7 5000000  /* 0.5 deg: a fix further from the reference re-bases */
#define NAV_MAX_DT_NS 100000000u /* longest cycle or gyro sample interval (100 ms) */
#define NAV_BOUND_MAX_Q16 ((int64_t)1 << 46) /* bounds saturate at 2^30 m / deg / m/s */

struct nav_cfg {
    uint32_t cycle_ns;       /* nominal cycle (13 ms), for the ring; 1 ms .. 100 ms */
    uint8_t avg_passes;      /* 1..4 passes of averaging */
    uint8_t avg_w;           /* window of each pass, 1..NAV_AVG_MAX_W */
    struct gpsb_cfg blend;   /* speed blending (Q, rounds, gap) */
    fx_q16_t gain_pos;       /* Q16 (0, 1]: fraction of the position innovation applied */
    uint8_t spread_cycles;   /* 1..64: cycles the correction is spread over */
    fx_q16_t gain_heading;   /* Q16 [0, 1]: fraction of the course innovation applied */
    fx_q16_t course_min_mps; /* Q16: slower than this, the course is not used */
    uint8_t jump_reset;      /* consecutive refused fixes that re-seat the track, 1..255 */
    /* error model (bounds) */
    fx_q16_t gps_bound_m;       /* Q16 m: |fix position error| <= this */
    fx_q16_t speed_bound_mps;   /* Q16 m/s: |fix speed error| <= this */
    fx_q16_t course_bound_deg;  /* Q16 deg: |fix course error| <= this (at course_min) */
    fx_q16_t accel_err_g;       /* Q16 g: |acceleration error| after compensation */
    fx_q16_t gyro_offset_bound; /* Q16 deg/s: residual offset after the stillness gate */
    fx_q16_t gyro_offset_uncal; /* Q16 deg/s: offset bound before any */
    fx_q16_t gyro_scale_bound;  /* Q30: relative scale error */
    fx_q16_t heading_noise_deg; /* Q16 deg: added to the heading bound */
    fx_q16_t slip_deg;          /* Q16 deg: side slip the model ignores */
    fx_q16_t pos_limit_m;       /* validity limits, Q16 */
    fx_q16_t speed_limit_mps;
    fx_q16_t heading_limit_deg;
};

/* One fix, in the receiver's own numbers (gps_nmea.h formats). */
struct nav_fix_in {
    int32_t lat_e7, lon_e7;
    uint32_t speed_mmps;
    uint16_t course_cdeg; /* compass course (0 = north, clockwise) */
    bool has_speed, has_course;
    uint64_t t_valid_ns; /* the time the fix is valid at, on the nav clock (arrival - latency) */
};

/* Outputs of a cycle. */
struct nav_out {
    uint64_t t_ns;
    int32_t east_mm, north_mm; /* of the reference */
    uint32_t pos_bound_mm;
    bool pos_valid;
    fx_q16_t speed_mps, speed_bound_mps;
    bool speed_valid;
    fx_q16_t heading_deg, heading_bound_deg; /* [0, 360), 0 = east, counter-clockwise */
    bool heading_valid;
    fx_q30_t k; /* blend factor of the cycle */
};

struct nav_hist {
    uint64_t t_ns;
    int64_t e_q32, n_q32; /* position */
    int64_t h;            /* heading, Q16 deg x ns */
    int64_t v_q32;        /* blended speed Q32 m/s */
};

struct nav {
    struct nav_cfg cfg;
    struct avg_cascade avg;
    int64_t avg_lines[NAV_AVG_MAX_W * AVG_CASCADE_MAX_PASSES];
    struct gpsb blend;
    bool ready, have_ref, have_heading, have_offset, have_rest_accel;
    int32_t ref_lat_e7, ref_lon_e7;
    int64_t k_n_q36, k_e_q36; /* metres per 1e-7 deg, Q36 */
    uint64_t t_ns;
    int64_t e_q32, n_q32;
    int64_t h;     /* averaged-rate heading, Q16 deg x ns, [0, 360 deg) */
    int64_t h_raw; /* raw-rate heading (same origin): for the lag bound */
    fx_q16_t gyro_offset;
    fx_q16_t rest_accel_g;
    /* pending correction */
    int64_t pend_e_q32, pend_n_q32;
    uint8_t pend_left;
    int64_t corr_e_q32, corr_n_q32; /* every correction applied so far (the fixes' share of
                                       the track: track - corr is the pure dead reckoning) */
    uint8_t jumps;                  /* consecutive refused fixes */
    /* bounds, Q16 (int64) */
    int64_t b_h_ns;  /* heading, Q16 deg x ns */
    int64_t b_v_q16; /* speed */
    int64_t b_p_q16; /* position */
    int64_t s_q16;   /* integral of |A| + a_err since the fix, Q16 m/s */
    bool speed_gap;  /* gpsb: gap exceeded */
    fx_q16_t v_q16;  /* last blended speed */
    fx_q30_t k;
    struct nav_hist ring[NAV_RING];
    uint32_t ring_head, ring_count;
    /* statistics */
    uint32_t fixes, fixes_refused, resets, course_updates;
};

/* Defaults for [KF-SCA3000]'s set-up: 13 ms, 2 passes of 4, Q = q_noise_g, one round, gain 0.25
 * over 8 cycles, course gain 0.1 above 8 m/s, 3 refused fixes re-seat; bounds: GPS 15 m,
 * 0.5 m/s, 3 deg; accel 0.02 g; gyro offset 0.05 deg/s (0.5 before the gate), scale 0.5 %,
 * heading noise 0.1 deg, slip 1 deg; limits 50 m, 2 m/s, 10 deg. */
struct nav_cfg nav_default_cfg(fx_q16_t q_noise_g);

/* INC_ERR_NULL, INC_ERR_INVAL (a field outside its range), else 0. */
int nav_init(struct nav *s, const struct nav_cfg *cfg);

/* Gyro offset from the stillness gate (the mean rate over a still window): subtracted from
 * every later sample; from now on the heading bound grows with gyro_offset_bound instead of
 * gyro_offset_uncal. */
int nav_gyro_offset(struct nav *s, fx_q16_t offset_dps);

/* Forward specific force at rest (Q16 g): subtracted when nav_in.a_comp is false. */
int nav_accel_rest(struct nav *s, fx_q16_t a_fwd_g);

/* One gyro sample: yaw rate (Q16 deg/s, left positive), dt_ns since the previous sample
 * (1 .. NAV_MAX_DT_NS, else INC_ERR_RANGE and the sample is not used). */
int nav_gyro(struct nav *s, fx_q16_t rate_dps, uint32_t dt_ns);

struct nav_in {
    fx_q16_t a_fwd_g; /* forward acceleration, Q16 g (mean over the cycle) */
    bool a_comp;      /* true: gravity already removed (attitude estimator) */
    uint32_t dt_ns;   /* cycle length, 1 .. NAV_MAX_DT_NS */
};

/* One 13 ms cycle: speed blend, position integration, pending correction; fills *out.
 * INC_ERR_NULL, INC_ERR_RANGE (dt out of range: nothing advances), else 0. */
int nav_step(struct nav *s, const struct nav_in *in, struct nav_out *out);

/*
 * A fix. Returns 0 (used), 1 (used to start or re-base the frame), INC_ERR_REJECTED (a jump:
 * refused, s->jumps counts it), INC_ERR_RANGE (t_valid older than the ring or in the future:
 * refused), INC_ERR_INVAL (coordinates out of range), INC_ERR_NULL.
 */
int nav_fix(struct nav *s, const struct nav_fix_in *fix);

/* Projection of a fix into the current frame (Q32 m); INC_ERR_STATE without a reference,
 * INC_ERR_RANGE beyond NAV_REF_SPAN_E7. */
int nav_project(const struct nav *s, int32_t lat_e7, int32_t lon_e7, int64_t *e_q32,
                int64_t *n_q32);

/* WGS-84 metres per 1e-7 deg at latitude lat_e7, Q36 (north and east). */
void nav_radii_q36(int32_t lat_e7, int64_t *k_n_q36, int64_t *k_e_q36);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_NAV_H */
