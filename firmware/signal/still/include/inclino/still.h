/*
 * still.h - stillness (at-rest) and thermal-settling detection (module inclino_still, prefix
 * still_). Freestanding C11, integer only, caller-allocated state, no heap.
 *
 * They gate what must only run on a part at rest and at a steady temperature: gyro bias
 * calibration ([ADI-IMU-QS]: "zero rotation, including vibration" and "thermal stability", read
 * TEMP_OUT to confirm) and the EPB slope measurement ([ADI-EPB]: average while engine, passing
 * traffic and passengers shake the car, reject what is not still).
 *
 * STILLNESS: the samples are cut into consecutive windows of W samples. Per window and per axis
 * the detector computes, exactly, the mean and the (population) variance
 *     var = (W sum d^2 - (sum d)^2) / W^2,   d = x - (first sample of the window),
 * and calls the window QUIET when every axis passes every enabled test:
 *     gyro variance  <= gyro_var_max         (vibration, rotation changes)
 *     accel variance <= accel_var_max        (shocks, vibration)
 *     |gyro mean|    <= gyro_mean_max        (steady rotation has no variance; 0 = test off)
 *     | |accel mean| - 1 g | <= accel_norm_tol (steady acceleration / free fall; one_g 0 = off)
 *     |accel mean - previous window's accel mean| <= accel_drift_max per axis (a slow turn about
 *                                              a horizontal axis tilts gravity; 0 = test off;
 *                                              needs a previous window)
 *     no sample further than STILL_DEV_MAX from the window's first sample (else: moving)
 * The part is AT REST after windows_required consecutive quiet windows; one noisy window makes
 * it MOVING at once. Units: whatever the samples are (raw counts, Q16.16...): thresholds are in
 * the same unit (variance in unit^2). The comparisons are exact integer comparisons (no
 * rounding); the reported variance is rounded down (floor of the exact rational), the mean to
 * nearest (ties away from zero).
 *
 * Choosing thresholds: for white noise of sd s, a window's variance estimate has relative sd
 * sqrt(2 / (W - 1)); var_max = s^2 (1 + 6 sqrt(2 / (W - 1))) keeps false "moving" below 1e-9 per
 * window. docs/averaging.md has the numbers for the ADIS1636x/1640x.
 *
 * THERMAL SETTLING: temperature samples are block-averaged (avg_n samples per point, to beat the
 * output's quantisation noise); the last `span` points form the window. SETTLED when the window
 * is full and max - min over it <= max_change ([ADI-IMU-QS]: wait for the initial thermal settling,
 * read TEMP_OUT to confirm it). The points are rounded means, so a true change of up to
 * max_change + 1 LSB can pass: choose max_change one LSB below the change that must be refused.
 */
#ifndef INCLINO_STILL_H
#define INCLINO_STILL_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/avg.h"
#include "inclino/error.h"

#ifdef __cplusplus
extern "C" {
#endif

#define STILL_WINDOW_MIN 2u
#define STILL_WINDOW_MAX 2048u              /* W sum d^2 <= 2^11 * 2^11 * 2^40 = 2^62 */
#define STILL_DEV_MAX (1L << 20)            /* |x - window's first sample| beyond: moving */
#define STILL_VAR_LIMIT ((uint64_t)1 << 40) /* largest variance threshold (= STILL_DEV_MAX^2) */
#define STILL_ONE_G_MAX (1L << 30)          /* largest accel_one_g (|a|^2 stays in uint64) */

/* Why the last window was not quiet (bit set per failed test). */
#define STILL_WHY_GYRO_VAR 0x01u
#define STILL_WHY_ACCEL_VAR 0x02u
#define STILL_WHY_GYRO_MEAN 0x04u
#define STILL_WHY_ACCEL_NORM 0x08u
#define STILL_WHY_OVERRANGE 0x10u
#define STILL_WHY_ACCEL_DRIFT 0x20u

enum still_state {
    STILL_UNKNOWN = 0, /* no complete window since init/reset */
    STILL_MOVING,      /* the last window was not quiet */
    STILL_SETTLING,    /* quiet, but for fewer than windows_required windows */
    STILL_AT_REST      /* windows_required consecutive quiet windows, the last one included */
};

struct still_cfg {
    uint32_t window;           /* W, samples per window, STILL_WINDOW_MIN..STILL_WINDOW_MAX */
    uint32_t windows_required; /* consecutive quiet windows for AT_REST, >= 1 */
    uint64_t gyro_var_max;     /* per-axis variance limit, gyro unit^2, <= STILL_VAR_LIMIT */
    uint64_t accel_var_max;    /* per-axis variance limit, accel unit^2, <= STILL_VAR_LIMIT */
    uint32_t gyro_mean_max;    /* |mean rate| limit per axis, gyro unit; 0 = no test */
    int32_t accel_one_g;       /* 1 g in accel units, 0..STILL_ONE_G_MAX; 0 = no norm test */
    uint32_t accel_norm_tol;   /* | |a| - 1 g | limit, accel units, < accel_one_g */
    uint32_t accel_drift_max;  /* window-to-window accel mean change limit per axis; 0 = off */
};

/* Statistics of the last complete window. */
struct still_window {
    int32_t gyro_mean[3], accel_mean[3]; /* rounded to nearest */
    uint64_t gyro_var[3], accel_var[3];  /* unit^2, rounded down */
    bool quiet;
    uint8_t why; /* STILL_WHY_* bits, 0 when quiet */
};

struct still {
    struct still_cfg cfg;
    int32_t ref[6];          /* first sample of the window: gyro x y z, accel x y z */
    int64_t sum[6];          /* sum of d */
    uint64_t sum2[6];        /* sum of d^2 */
    uint32_t n;              /* samples in the current window */
    bool overrange;          /* a |d| > STILL_DEV_MAX in the current window */
    uint32_t quiet_run;      /* consecutive quiet windows (saturating) */
    uint32_t windows;        /* complete windows since init/reset (saturating) */
    uint32_t motion_windows; /* non-quiet windows since init/reset (saturating) */
    enum still_state state;
    struct still_window last;
    bool ready; /* init succeeded */
};

/* Validate cfg (INC_ERR_INVAL for a field outside its range, INC_ERR_NULL) and start. */
int still_init(struct still *s, const struct still_cfg *cfg);

/* Forget all windows (state UNKNOWN, counters 0); the configuration is kept. */
void still_reset(struct still *s);

/* Drop the current, incomplete window only (state, counters and the last window kept). For a
 * step the caller made itself, e.g. a new offset written into the part: a window spanning it
 * would read as motion. */
void still_restart_window(struct still *s);

/* One sample of the three gyro and three accel axes. *window_done (may be NULL) is true when
 * this sample completed a window (the state and still_last() were updated). */
int still_push(struct still *s, const int32_t gyro[3], const int32_t accel[3], bool *window_done);

enum still_state still_state_get(const struct still *s); /* STILL_UNKNOWN for NULL */
bool still_at_rest(const struct still *s);
/* The last complete window, or NULL before the first. */
const struct still_window *still_last(const struct still *s);
/* Non-quiet windows since init/reset: a procedure records it at its start and refuses its result
 * if it changed (motion at any time during it). */
uint32_t still_motion_count(const struct still *s);
/* Complete windows since init/reset (saturating): a procedure waits for it to grow to know that
 * the window spanning its end has been judged. */
uint32_t still_window_count(const struct still *s);

/* ---- Thermal settling ---------------------------------------------------------------------- */

#define STILL_THERMAL_SPAN_MAX 32u

struct still_thermal_cfg {
    uint32_t avg_n;      /* temperature samples averaged per point, 1..2^31 */
    uint32_t span;       /* points in the window, 2..STILL_THERMAL_SPAN_MAX */
    uint32_t max_change; /* settled when max - min of the window's points <= this (temp unit) */
};

struct still_thermal {
    struct still_thermal_cfg cfg;
    struct avg_block blk;
    int32_t pts[STILL_THERMAL_SPAN_MAX];
    uint32_t head, count;
    uint32_t change; /* max - min of the current window (valid when count == span) */
    bool settled;
    bool ready;
};

/* INC_ERR_NULL / INC_ERR_INVAL / INC_ERR_OVERFLOW (avg_n > 2^31) for a bad configuration. */
int still_thermal_init(struct still_thermal *t, const struct still_thermal_cfg *cfg);
void still_thermal_reset(struct still_thermal *t);
/* One temperature sample (any unit, e.g. TEMP_OUT counts). *point_done (may be NULL) when it
 * completed a point and the verdict was updated. */
int still_thermal_push(struct still_thermal *t, int32_t temp, bool *point_done);
bool still_thermal_settled(const struct still_thermal *t);
/* max - min over the window; INC_ERR_STATE until span points exist. */
int still_thermal_change(const struct still_thermal *t, uint32_t *change);
/* The newest point (rounded mean temperature); INC_ERR_STATE before the first. */
int still_thermal_last(const struct still_thermal *t, int32_t *temp);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_STILL_H */
