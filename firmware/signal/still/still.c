/*
 * still.c - stillness and thermal-settling detection (see inclino/still.h).
 *
 * Why windows and not a sliding variance: a window's sums need no delay line (O(1) memory per
 * axis), the variance is exact, and the decision latency (at most one window) is irrelevant to
 * the users: calibration checks still_motion_count() over its whole averaging span, and the EPB
 * slope is taken only from windows judged quiet.
 * Why deviations from the window's first sample: the variance does not depend on the origin,
 * and the deviations of a still part are small, so d^2 and W sum d^2 stay inside 64 bits for any
 * int32 input (raw counts or Q16.16), which a plain sum of x^2 would not.
 * Why the mean and norm tests: a part turning at a constant rate, or accelerating steadily, has
 * no variance at all ([ADI-IMU-QS] asks for "zero rotation", not for "constant rotation").
 */
#include "inclino/still.h"

#include <stddef.h>

#include "inclino/fx.h"

int still_init(struct still *s, const struct still_cfg *cfg)
{
    if (s == NULL || cfg == NULL) {
        return INC_ERR_NULL;
    }
    s->ready = false;
    if (cfg->window < STILL_WINDOW_MIN || cfg->window > STILL_WINDOW_MAX ||
        cfg->windows_required == 0u || cfg->gyro_var_max > STILL_VAR_LIMIT ||
        cfg->accel_var_max > STILL_VAR_LIMIT || cfg->accel_one_g < 0 ||
        cfg->accel_one_g > (int32_t)STILL_ONE_G_MAX ||
        (cfg->accel_one_g > 0 && cfg->accel_norm_tol >= (uint32_t)cfg->accel_one_g)) {
        return INC_ERR_INVAL;
    }
    s->cfg = *cfg;
    s->ready = true;
    still_reset(s);
    return INC_OK;
}

static void window_clear(struct still *s)
{
    unsigned i;
    for (i = 0; i < 6u; i++) {
        s->sum[i] = 0;
        s->sum2[i] = 0;
    }
    s->n = 0;
    s->overrange = false;
}

void still_restart_window(struct still *s)
{
    if (s != NULL && s->ready) {
        window_clear(s);
    }
}

void still_reset(struct still *s)
{
    unsigned i;
    if (s == NULL) {
        return;
    }
    window_clear(s);
    s->quiet_run = 0;
    s->windows = 0;
    s->motion_windows = 0;
    s->state = STILL_UNKNOWN;
    for (i = 0; i < 3u; i++) {
        s->last.gyro_mean[i] = s->last.accel_mean[i] = 0;
        s->last.gyro_var[i] = s->last.accel_var[i] = 0u;
    }
    s->last.quiet = false;
    s->last.why = 0u;
}

/* Axis i of the finished window: mean (rounded), variance (floor) and the exact test
 * var <= var_max, i.e. W sum d^2 - (sum d)^2 <= var_max W^2 (both sides < 2^63). */
static bool axis_stats(const struct still *s, unsigned i, uint64_t var_max, int32_t *mean,
                       uint64_t *var)
{
    const uint64_t w = s->cfg.window;
    const uint64_t a = fx_uabs64(s->sum[i]);              /* <= W 2^20 <= 2^31 */
    const uint64_t v = w * s->sum2[i] - a * a;            /* >= 0 (Cauchy-Schwarz), <= 2^62 */
    const int32_t m = fx_div64(s->sum[i], s->cfg.window); /* window >= 2, |mean d| < 2^31 */
    *mean = fx_sat32((int64_t)s->ref[i] + m);
    *var = v / (w * w);
    return v <= var_max * w * w;
}

static void window_finish(struct still *s)
{
    struct still_window *l = &s->last;
    uint8_t why = s->overrange ? STILL_WHY_OVERRANGE : 0u;
    int32_t prev_accel[3];
    unsigned i;
    for (i = 0; i < 3u; i++) {
        prev_accel[i] = l->accel_mean[i];
    }
    for (i = 0; i < 3u; i++) {
        if (!axis_stats(s, i, s->cfg.gyro_var_max, &l->gyro_mean[i], &l->gyro_var[i])) {
            why |= STILL_WHY_GYRO_VAR;
        }
        if (!axis_stats(s, 3u + i, s->cfg.accel_var_max, &l->accel_mean[i], &l->accel_var[i])) {
            why |= STILL_WHY_ACCEL_VAR;
        }
        if (s->cfg.gyro_mean_max > 0u && fx_uabs32(l->gyro_mean[i]) > s->cfg.gyro_mean_max) {
            why |= STILL_WHY_GYRO_MEAN;
        }
    }
    if (s->cfg.accel_one_g > 0) {
        const uint64_t g = (uint64_t)s->cfg.accel_one_g, tol = s->cfg.accel_norm_tol;
        uint64_t n2 = 0;
        bool big = false;
        for (i = 0; i < 3u; i++) {
            const uint64_t a = fx_uabs32(l->accel_mean[i]);
            big |= a > (uint64_t)STILL_ONE_G_MAX;
            n2 += a * a; /* 3 * 2^60 at most when !big */
        }
        if (big || n2 < (g - tol) * (g - tol) || n2 > (g + tol) * (g + tol)) {
            why |= STILL_WHY_ACCEL_NORM;
        }
    }
    if (s->cfg.accel_drift_max > 0u && s->windows > 0u) {
        for (i = 0; i < 3u; i++) {
            const int64_t dm = (int64_t)l->accel_mean[i] - prev_accel[i];
            if (fx_uabs64(dm) > s->cfg.accel_drift_max) {
                why |= STILL_WHY_ACCEL_DRIFT;
            }
        }
    }
    l->why = why;
    l->quiet = why == 0u;
    if (s->windows < UINT32_MAX) {
        s->windows++;
    }
    if (l->quiet) {
        if (s->quiet_run < UINT32_MAX) {
            s->quiet_run++;
        }
        s->state = s->quiet_run >= s->cfg.windows_required ? STILL_AT_REST : STILL_SETTLING;
    } else {
        s->quiet_run = 0;
        if (s->motion_windows < UINT32_MAX) {
            s->motion_windows++;
        }
        s->state = STILL_MOVING;
    }
    window_clear(s);
}

int still_push(struct still *s, const int32_t gyro[3], const int32_t accel[3], bool *window_done)
{
    unsigned i;
    if (window_done != NULL) {
        *window_done = false;
    }
    if (s == NULL || gyro == NULL || accel == NULL) {
        return INC_ERR_NULL;
    }
    if (!s->ready) {
        return INC_ERR_STATE;
    }
    for (i = 0; i < 6u; i++) {
        const int32_t x = i < 3u ? gyro[i] : accel[i - 3u];
        int64_t d;
        if (s->n == 0u) {
            s->ref[i] = x;
        }
        d = (int64_t)x - s->ref[i];
        if (d > STILL_DEV_MAX || d < -STILL_DEV_MAX) {
            /* Far beyond any threshold: the window fails; clamp to keep the sums bounded. */
            d = d > 0 ? STILL_DEV_MAX : -STILL_DEV_MAX;
            s->overrange = true;
        }
        s->sum[i] += d;
        s->sum2[i] += (uint64_t)(d * d);
    }
    if (++s->n == s->cfg.window) {
        window_finish(s);
        if (window_done != NULL) {
            *window_done = true;
        }
    }
    return INC_OK;
}

enum still_state still_state_get(const struct still *s)
{
    return (s == NULL || !s->ready) ? STILL_UNKNOWN : s->state;
}

bool still_at_rest(const struct still *s)
{
    return still_state_get(s) == STILL_AT_REST;
}

const struct still_window *still_last(const struct still *s)
{
    return (s == NULL || !s->ready || s->windows == 0u) ? NULL : &s->last;
}

uint32_t still_motion_count(const struct still *s)
{
    return (s == NULL || !s->ready) ? 0u : s->motion_windows;
}

uint32_t still_window_count(const struct still *s)
{
    return (s == NULL || !s->ready) ? 0u : s->windows;
}

/* ---- Thermal -------------------------------------------------------------------------------- */

int still_thermal_init(struct still_thermal *t, const struct still_thermal_cfg *cfg)
{
    int err;
    if (t == NULL || cfg == NULL) {
        return INC_ERR_NULL;
    }
    t->ready = false;
    if (cfg->span < 2u || cfg->span > STILL_THERMAL_SPAN_MAX) {
        return INC_ERR_INVAL;
    }
    err = avg_block_init(&t->blk, cfg->avg_n);
    if (err != INC_OK) {
        return err;
    }
    t->cfg = *cfg;
    t->ready = true;
    still_thermal_reset(t);
    return INC_OK;
}

void still_thermal_reset(struct still_thermal *t)
{
    if (t == NULL) {
        return;
    }
    avg_block_restart(&t->blk);
    t->head = 0;
    t->count = 0;
    t->change = 0;
    t->settled = false;
}

int still_thermal_push(struct still_thermal *t, int32_t temp, bool *point_done)
{
    int32_t mean = 0;
    bool done = false;
    int err;
    if (point_done != NULL) {
        *point_done = false;
    }
    if (t == NULL) {
        return INC_ERR_NULL;
    }
    if (!t->ready) {
        return INC_ERR_STATE;
    }
    err = avg_block_push(&t->blk, temp, &mean, &done);
    if (err != INC_OK || !done) {
        return err;
    }
    t->pts[t->head] = mean;
    t->head = t->head + 1u == t->cfg.span ? 0u : t->head + 1u;
    if (t->count < t->cfg.span) {
        t->count++;
    }
    if (t->count == t->cfg.span) {
        int32_t lo = t->pts[0], hi = t->pts[0];
        uint32_t i;
        for (i = 1; i < t->cfg.span; i++) {
            lo = t->pts[i] < lo ? t->pts[i] : lo;
            hi = t->pts[i] > hi ? t->pts[i] : hi;
        }
        t->change = (uint32_t)((int64_t)hi - lo);
        t->settled = t->change <= t->cfg.max_change;
    }
    if (point_done != NULL) {
        *point_done = true;
    }
    return INC_OK;
}

bool still_thermal_settled(const struct still_thermal *t)
{
    return t != NULL && t->ready && t->settled;
}

int still_thermal_change(const struct still_thermal *t, uint32_t *change)
{
    if (t == NULL || change == NULL) {
        return INC_ERR_NULL;
    }
    if (!t->ready || t->count < t->cfg.span) {
        return INC_ERR_STATE;
    }
    *change = t->change;
    return INC_OK;
}

int still_thermal_last(const struct still_thermal *t, int32_t *temp)
{
    if (t == NULL || temp == NULL) {
        return INC_ERR_NULL;
    }
    if (!t->ready || t->count == 0u) {
        return INC_ERR_STATE;
    }
    *temp = t->pts[t->head == 0u ? t->cfg.span - 1u : t->head - 1u];
    return INC_OK;
}
