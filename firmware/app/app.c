/*
 * app.c - the EPB application pipeline (see app.h; docs/epb-demo.md).
 *
 * Why the pieces are put together this way:
 *  - The calibration is bound to the sensor (calrec binding): a record for another part, a torn
 *    or corrupt one, or none at all must never correct this part, so calstore_load's status is
 *    kept and the application runs uncalibrated (pass-through, never valid) on any failure.
 *  - The temperature models are re-evaluated only when the temperature has moved by
 *    temp_step_c: cal_acc_set_temp costs two divisions per axis, cal_acc_apply none (cal.h).
 *  - The stillness windows are aligned with the blocks (avg_n is a multiple of the window), so
 *    "still over the block" is exactly "no window of the block failed, and at rest at its end".
 *  - [ADI-EPB]'s noise term assumes white noise of a known rms. The vehicle adds engine vibration
 *    and passengers to the part's own noise, so the rms measured in the block's stillness
 *    windows is used when it is larger than the rated one: a vibrating car gets a wider bound,
 *    never a falsely tight one. The window variance is rescaled by W / (W - 1) (the detector's
 *    population variance is biased low by that factor) and its root rounded up.
 *  - [ADI-EPB]'s Table 1 lists the temperature term as compensated only by the three-point
 *    calibration; the compensated term is used only where the record's model was calibrated
 *    (its range), otherwise the uncompensated one.
 */
#include "inclino/app.h"

#include <stddef.h>

#include "inclino/compiler.h"
/* The calibration record's binding takes the sensor's identity field by field: same numbers. */
_Static_assert((int)SENSOR_FAMILY_SCA3000 == (int)CALREC_FAMILY_SCA3000, "family numbers");
_Static_assert((int)SENSOR_FAMILY_ADIS1625X == (int)CALREC_FAMILY_ADIS1625X, "family numbers");
_Static_assert((int)SENSOR_FAMILY_ADIS163XX == (int)CALREC_FAMILY_ADIS163XX, "family numbers");

/* Internal block flag: every sample so far carried a temperature (bit 31, never reported). */
#define BLOCK_ALL_TEMP 0x80000000u

/* ---- Configuration -------------------------------------------------------------------------- */

static bool budget_ok(const struct app_budget *b)
{
    return b->sensitivity >= 0 && b->sensitivity < FX_Q30_HALF && b->offset_g >= 0 &&
           b->offset_drift_g >= 0 && b->nonlinearity_g >= 0 && b->temp_comp_g >= 0 &&
           b->temp_uncomp_g >= 0 && b->sensitivity_uncal >= 0 &&
           b->sensitivity_uncal < FX_Q30_HALF && b->tscale_uncomp >= 0 &&
           b->tscale_uncomp < FX_Q30_HALF && b->offset_uncal_g >= 0 && b->noise_sigma_g >= 0 &&
           b->lifetime_runs >= 1u && b->exceed_expected > 0;
}

/* Q16 of milli-g, for the constants below. */
#define MG(x) ((fx_q16_t)(((x)*65536 + 500) / 1000))

int app_cfg_default(struct app_cfg *c, uint32_t rate_mhz)
{
    uint32_t w;
    if (c == NULL) {
        return INC_ERR_NULL;
    }
    if (rate_mhz < 10000u || rate_mhz > 10000000u) {
        return INC_ERR_INVAL;
    }
    /* W = round(rate * 0.3125 s) = round(rate_mhz * 5 / 16000). */
    w = (uint32_t)(((uint64_t)rate_mhz * 5u + 8000u) / 16000u);
    if (w < STILL_WINDOW_MIN) {
        w = STILL_WINDOW_MIN;
    }
    c->avg_n = 8u * w;
    c->still.window = w;
    c->still.windows_required = 2u;
    c->still.gyro_var_max = (uint64_t)32768u * 32768u;            /* (0.5 deg/s)^2, Q16^2 */
    c->still.accel_var_max = (uint64_t)MG(30) * (uint64_t)MG(30); /* (30 mg)^2, Q16^2 */
    c->still.gyro_mean_max = (uint32_t)FX_Q16_ONE;                /* 1 deg/s */
    c->still.accel_one_g = FX_Q16_ONE;
    c->still.accel_norm_tol = (uint32_t)MG(50);
    c->still.accel_drift_max = (uint32_t)MG(15);
    c->slope.method = SLOPE_TWO_AXIS;
    c->slope.slope_axis = 0u;
    c->slope.gravity_axis = 2u;
    c->slope.slope_axis_negative = false;
    c->slope.gravity_axis_negative = false;
    c->slope.max_slope_deg = FX_Q16_INT(30);
    c->slope.max_bound_deg = FX_Q16_INT(2);
    c->slope.magnitude_tol_g = MG(50);
    c->slope.budget.sensitivity = 0;
    c->slope.budget.offset_g = 0;
    c->slope.budget.nonlinearity_g = 0;
    c->slope.budget.temperature_g = 0;
    c->slope.budget.noise_sigma_g = 0;
    c->slope.budget.k_sigma = FX_Q16_INT(6);
    c->budget.sensitivity = 0;
    c->budget.offset_g = 0;
    c->budget.offset_drift_g = MG(10);
    c->budget.nonlinearity_g = MG(10);
    c->budget.temp_comp_g = 0; /* Table 1's 10 mg is offset_drift_g (app.h) */
    c->budget.temp_uncomp_g = MG(50);
    c->budget.tscale_uncomp = (fx_q30_t)5368709;      /* 0.005 */
    c->budget.sensitivity_uncal = (fx_q30_t)32212255; /* 0.03 */
    c->budget.offset_uncal_g = MG(15);
    c->budget.noise_sigma_g = MG(4);
    c->budget.lifetime_runs = 200000u;
    c->budget.exceed_expected = 66; /* 0.001 in Q16 */
    c->temp_default_c = FX_Q16_INT(25);
    c->temp_step_c = FX_Q16_HALF;
    c->temp_margin_c = FX_Q16_ONE;
    c->max_sensor_errors = 0u;
    c->noise_floor_g = (fx_q16_t)(c->budget.noise_sigma_g / APP_QUIET_DIV);
    c->temp_min_c = FX_Q16_INT(APP_TEMP_MIN_C);
    c->temp_max_c = FX_Q16_INT(APP_TEMP_MAX_C);
    c->temp_step_max_c = FX_Q16_INT(APP_TEMP_STEP_MAX_C);
    c->temp_ref_tol_c = FX_Q16_INT(APP_TEMP_REF_TOL_C);
    c->rec_offset_max_g = MG(APP_REC_OFFSET_MAX_MG);
    c->rec_gain_tol = (fx_q30_t)(((int64_t)APP_REC_GAIN_TOL_PPM << 30) / 1000000);
    c->rec_misalign_max = (fx_q30_t)(((int64_t)APP_REC_MISALIGN_MAX_URAD << 30) / 1000000);
    return INC_OK;
}

int app_cfg_check(const struct app_cfg *cfg)
{
    struct slope_cfg sc;
    fx_q16_t k;
    if (cfg == NULL) {
        return INC_ERR_NULL;
    }
    if (cfg->avg_n == 0u || cfg->avg_n > FX_SUM_MAX_COUNT || cfg->still.window < STILL_WINDOW_MIN ||
        cfg->still.window > STILL_WINDOW_MAX || cfg->avg_n % cfg->still.window != 0u ||
        cfg->temp_step_c <= 0 || cfg->temp_margin_c < 0 || cfg->noise_floor_g < 0 ||
        cfg->rec_offset_max_g < 0 || cfg->rec_gain_tol < 0 || cfg->rec_misalign_max < 0 ||
        cfg->temp_min_c > cfg->temp_max_c || cfg->temp_step_max_c < 0 || cfg->temp_ref_tol_c < 0 ||
        !budget_ok(&cfg->budget)) {
        return INC_ERR_INVAL;
    }
    if (slope_sigma_factor(cfg->budget.lifetime_runs, cfg->budget.exceed_expected, &k) != INC_OK) {
        return INC_ERR_INVAL;
    }
    /* The slope configuration with a budget of the kind app_step composes. */
    sc = cfg->slope;
    sc.budget.sensitivity = cfg->budget.sensitivity;
    sc.budget.offset_g = fx_add(cfg->budget.offset_g, cfg->budget.offset_drift_g);
    sc.budget.nonlinearity_g = cfg->budget.nonlinearity_g;
    sc.budget.temperature_g = cfg->budget.temp_comp_g;
    sc.budget.noise_sigma_g = cfg->budget.noise_sigma_g;
    sc.budget.k_sigma = k;
    return slope_cfg_check(&sc) == INC_OK ? INC_OK : INC_ERR_INVAL;
}

/* ---- Block bookkeeping ------------------------------------------------------------------------ */

static void offset_ref_reset(struct app *a);

static int64_t abs64(int64_t v)
{
    return v < 0 ? -v : v;
}

/* The record against the part type's limits (app_cfg rec_*; 0: that check off). */
static bool rec_plausible(const struct app_cfg *c, const struct calrec *r)
{
    unsigned i, j;
    for (i = 0; i < 3u; i++) {
        if (c->rec_offset_max_g > 0 && abs64(r->acc_offset[i]) > c->rec_offset_max_g) {
            return false;
        }
        if (c->rec_gain_tol > 0 && abs64((int64_t)r->acc_gain[i] - FX_Q30_ONE) > c->rec_gain_tol) {
            return false;
        }
        for (j = 0; j < 3u; j++) {
            if (i != j && c->rec_misalign_max > 0 &&
                abs64(r->acc_misalign[i][j]) > c->rec_misalign_max) {
                return false;
            }
        }
    }
    return true;
}

static void block_reset(struct app *a)
{
    unsigned i;
    for (i = 0; i < 3u; i++) {
        fx_sum_reset(&a->sum_a[i]);
        fx_sum_reset(&a->sum_g[i]);
    }
    fx_sum_reset(&a->sum_t);
    a->n = 0;
    a->missed = 0;
    a->errors = 0;
    a->flags = 0;
    a->var_max = 0;
    a->motion_start = still_motion_count(&a->still);
    still_restart_window(&a->still);
}

int app_init(struct app *a, const struct app_cfg *cfg, const struct sensor *sensor,
             struct calstore *store)
{
    struct sensor_identity sid;
    int err;
    if (a == NULL || cfg == NULL || sensor == NULL || sensor->ops == NULL ||
        sensor->ops->wait_ready == NULL || sensor->ops->read == NULL ||
        sensor->ops->identity == NULL) {
        return INC_ERR_NULL;
    }
    a->ready = false;
    err = app_cfg_check(cfg);
    if (err != INC_OK) {
        return err;
    }
    a->cfg = *cfg;
    a->sensor = *sensor;
    err = still_init(&a->still, &cfg->still);
    if (err != INC_OK) {
        return err;
    }
    err = slope_sigma_factor(cfg->budget.lifetime_runs, cfg->budget.exceed_expected, &a->k_sigma);
    if (err != INC_OK) {
        return INC_ERR_INVAL;
    }
    err = sensor_get_identity(sensor, &sid);
    if (err != INC_OK) {
        return err;
    }
    a->id.family = sid.family;
    a->id.product = sid.product;
    a->id.revision = sid.revision;
    a->id.serial = sid.serial;
    a->id.lot_id1 = sid.lot_id1;
    a->id.lot_id2 = sid.lot_id2;
    /* calstore_load leaves the safe default (valid == false) in a->rec on any failure. */
    calrec_set_default(&a->rec);
    a->cal_status = store != NULL ? calstore_load(store, &a->id, &a->rec, NULL)
                                  : INC_ERR_NOT_CALIBRATED;
    if (a->cal_status == INC_OK && !rec_plausible(cfg, &a->rec)) {
        a->cal_status = INC_ERR_RANGE; /* intact, bound to this part, but not of its type */
        calrec_set_default(&a->rec);
    }
    err = cal_acc_init(&a->acc, a->rec.valid ? &a->rec : NULL, cfg->temp_default_c);
    if (a->cal_status == INC_OK && err != INC_OK) {
        a->cal_status = err; /* a record that cannot describe this part at any temperature */
    }
    (void)cal_gyro_init(&a->gyro, a->rec.valid ? &a->rec : NULL);
    a->temp_set = false;
    a->temp_applied = cfg->temp_default_c;
    a->temp_prev_set = false;
    a->temp_ref_set = false;
    block_reset(a);
    offset_ref_reset(a);
    a->ready = true;
    return INC_OK;
}

static void offset_ref_reset(struct app *a)
{
    a->ref_set = false;
    a->offset_fault = false;
    a->ref_noise_g = 0;
    a->ref_a[0] = a->ref_a[1] = a->ref_a[2] = 0;
}

void app_set_temp_ref(struct app *a, fx_q16_t t_c, bool valid)
{
    if (a != NULL) {
        a->temp_ref_set = valid;
        a->temp_ref_c = t_c;
    }
}

/* The temperature plausibility of a block with a temperature (app.h). */
static bool temp_plausible(struct app *a, fx_q16_t t)
{
    const struct app_cfg *c = &a->cfg;
    bool ok = t >= c->temp_min_c && t <= c->temp_max_c;
    if (c->temp_step_max_c > 0 && a->temp_prev_set &&
        abs64((int64_t)t - a->temp_prev_c) > c->temp_step_max_c) {
        ok = false;
    }
    if (c->temp_ref_tol_c > 0 && a->temp_ref_set &&
        abs64((int64_t)t - a->temp_ref_c) > c->temp_ref_tol_c) {
        ok = false;
    }
    a->temp_prev_set = true;
    a->temp_prev_c = t;
    return ok;
}

bool app_calibrated(const struct app *a)
{
    return a != NULL && a->ready && a->acc.calibrated;
}

void app_restart(struct app *a)
{
    if (a != NULL && a->ready) {
        block_reset(a);
        offset_ref_reset(a);
    }
}

/* ---- Budget composition ----------------------------------------------------------------------- */

/* True when model m was calibrated over a range that holds t (degC Q16) within margin. LORENTZ
 * states no range and is bounded by itself (between p0 and p0 + p1, calrec.h): it counts as
 * covering. */
static bool tmodel_covers(const struct calrec_tmodel *m, fx_q16_t t, fx_q16_t margin)
{
    int64_t lo, hi;
    switch (m->kind) {
    case CALREC_TM_LINEAR:
    case CALREC_TM_PARABOLA:
    case CALREC_TM_LORENTZ_CUBIC:
        lo = (int64_t)m->t_ref - m->t_span;
        hi = (int64_t)m->t_ref + m->t_span;
        break;
    case CALREC_TM_PWL:
        lo = m->t_ref;
        hi = (int64_t)m->t_ref + (int64_t)(m->n > 0 ? m->n - 1 : 0) * m->t_span;
        break;
    case CALREC_TM_LORENTZ: return true;
    default: return false;
    }
    return (int64_t)t >= lo - margin && (int64_t)t <= hi + margin;
}

/* ceil(sqrt(var * W / (W - 1))) in Q16 g from a window variance in Q16 g^2 (rounded down by
 * the detector, so +1 before the root keeps it an upper bound). */
static fx_q16_t sigma_from_var(uint64_t var, uint32_t w)
{
    uint64_t v = (var + 1u) * w;
    uint64_t r;
    v = (v + (w - 2u)) / (w - 1u);
    r = fx_isqrt64(v);
    if (r * r < v) {
        r++;
    }
    return r > (uint64_t)INT32_MAX ? INT32_MAX : (fx_q16_t)r;
}

/* The offset-change check (app.h): reference, comparison, latch. */
static void offset_check(struct app *a, struct app_result *res, bool still_cal)
{
    const fx_q16_t drift = a->cfg.budget.offset_drift_g;
    const fx_q16_t n = res->slope.noise_g;
    const uint8_t ax[2] = {a->cfg.slope.slope_axis, a->cfg.slope.gravity_axis};
    if (drift == 0) {
        return; /* no ageing term, no check (app.h) */
    }
    if (still_cal && !a->offset_fault) {
        if (!a->ref_set) {
            if (res->slope.valid && (res->flags & (APP_F_SENSOR | APP_F_SATURATED | APP_F_QUIET |
                                                   APP_F_TEMP_IMPLAUSIBLE)) == 0u) {
                unsigned i;
                for (i = 0; i < 3u; i++) {
                    a->ref_a[i] = res->accel_g[i];
                }
                a->ref_noise_g = n;
                a->ref_set = true;
            }
        } else {
            const int64_t tol = (int64_t)drift - n - a->ref_noise_g;
            unsigned i;
            for (i = 0; i < 2u; i++) {
                int64_t d = (int64_t)res->accel_g[ax[i]] - a->ref_a[ax[i]];
                d = d < 0 ? -d : d;
                if (tol <= 0 || d > tol) {
                    a->offset_fault = true;
                }
            }
        }
    }
    if (a->offset_fault) {
        res->flags |= APP_F_OFFSET_STEP;
    }
}

static void finish_block(struct app *a, struct app_result *res)
{
    const struct app_budget *b = &a->cfg.budget;
    struct slope_cfg sc = a->cfg.slope;
    struct slope_input in;
    const bool cal = a->acc.calibrated;
    const bool t_have = (a->flags & BLOCK_ALL_TEMP) != 0u;
    bool off_comp = false, scale_comp = false;
    unsigned i;
    int32_t t_mean = a->cfg.temp_default_c;

    res->n = a->n;
    for (i = 0; i < 3u; i++) {
        (void)fx_sum_mean(&a->sum_a[i], &res->accel_g[i]);
        (void)fx_sum_mean(&a->sum_g[i], &res->gyro_dps[i]);
    }
    if (t_have) {
        (void)fx_sum_mean(&a->sum_t, &t_mean);
    }
    res->temp_c = t_mean;
    res->missed = a->missed;
    res->sensor_errors = a->errors;
    res->motion_windows = still_motion_count(&a->still) - a->motion_start;
    res->still_state = (uint8_t)still_state_get(&a->still);
    res->sigma_meas_g = sigma_from_var(a->var_max, a->cfg.still.window);
    res->cal_status = a->cal_status;

    if (cal && t_have) {
        const struct calrec *rc = &a->rec;
        const fx_q16_t mg = a->cfg.temp_margin_c;
        off_comp = tmodel_covers(&rc->acc_tbias[sc.slope_axis], t_mean, mg);
        scale_comp = tmodel_covers(&rc->acc_tscale[sc.slope_axis], t_mean, mg);
        if (sc.method == SLOPE_TWO_AXIS) {
            off_comp = off_comp && tmodel_covers(&rc->acc_tbias[sc.gravity_axis], t_mean, mg);
            scale_comp = scale_comp && tmodel_covers(&rc->acc_tscale[sc.gravity_axis], t_mean, mg);
        }
    }
    sc.budget.sensitivity = cal ? b->sensitivity : b->sensitivity_uncal;
    if (!scale_comp) {
        sc.budget.sensitivity = fx_add(sc.budget.sensitivity, b->tscale_uncomp);
        if (sc.budget.sensitivity >= FX_Q30_HALF) {
            sc.budget.sensitivity = FX_Q30_HALF - 1; /* the bound is flagged long before this */
        }
    }
    sc.budget.offset_g = cal ? fx_add(b->offset_g, b->offset_drift_g) : b->offset_uncal_g;
    sc.budget.nonlinearity_g = b->nonlinearity_g;
    sc.budget.temperature_g = off_comp ? b->temp_comp_g : b->temp_uncomp_g;
    sc.budget.noise_sigma_g = res->sigma_meas_g > b->noise_sigma_g ? res->sigma_meas_g
                                                                   : b->noise_sigma_g;
    sc.budget.k_sigma = a->k_sigma;
    res->budget = sc.budget;

    for (i = 0; i < 3u; i++) {
        in.accel_g[i] = res->accel_g[i];
    }
    in.n_samples = a->n;
    in.still = res->motion_windows == 0u && res->still_state == (uint8_t)STILL_AT_REST;
    in.calibrated = cal;
    (void)slope_estimate(&sc, &in, &res->slope); /* sc passed app_cfg_check's rules */

    res->flags = a->flags & ~BLOCK_ALL_TEMP;
    if (!cal) res->flags |= APP_F_NOT_CALIBRATED;
    if (!off_comp || !scale_comp) res->flags |= APP_F_TEMP_UNCOMP;
    if (a->errors > a->cfg.max_sensor_errors) res->flags |= APP_F_SENSOR;
    if (!in.still) res->flags |= APP_F_NOT_STILL;
    if (t_have && !temp_plausible(a, t_mean)) res->flags |= APP_F_TEMP_IMPLAUSIBLE;
    offset_check(a, res, cal && in.still);
    res->valid = res->slope.valid &&
                 (res->flags & (APP_F_SENSOR | APP_F_SATURATED | APP_F_QUIET | APP_F_OFFSET_STEP |
                                APP_F_TEMP_IMPLAUSIBLE)) == 0u;
}

/* ---- Per sample --------------------------------------------------------------------------------- */

/* app_step is never inlined (into app_measure, under link-time optimisation): the sample read
 * app_measure makes must run below app_measure's small frame, not below app_step's locals, which
 * would put them on the deepest stack path of the small images (docs/build.md, "Stack
 * analysis"). */
INC_NOINLINE int app_step(struct app *a, const struct sensor_sample *s, int read_err,
                          struct app_corrected *out, bool *done, struct app_result *res)
{
    struct app_corrected c;
    bool wdone = false;
    unsigned i;
    int err;
    if (a == NULL || done == NULL || res == NULL) {
        return INC_ERR_NULL;
    }
    *done = false;
    if (!a->ready) {
        return INC_ERR_STATE;
    }
    if (read_err != INC_OK) {
        if (a->errors < UINT32_MAX) {
            a->errors++;
        }
        return INC_OK;
    }
    if (s == NULL) {
        return INC_ERR_NULL;
    }
    c.flags = s->flags;
    c.temp_c = (s->flags & SENSOR_S_HAVE_TEMP) != 0u ? s->temp_c : a->cfg.temp_default_c;
    if (a->n == 0u) {
        a->flags |= BLOCK_ALL_TEMP;
    }
    if ((s->flags & SENSOR_S_HAVE_TEMP) == 0u) {
        a->flags &= ~BLOCK_ALL_TEMP;
    }
    if (a->acc.rec != NULL &&
        (!a->temp_set || fx_abs(fx_sub(c.temp_c, a->temp_applied)) >= a->cfg.temp_step_c)) {
        /* INC_ERR_RANGE leaves the state uncalibrated at this temperature (never a wrong
         * correction); a later temperature may bring it back. */
        (void)cal_acc_set_temp(&a->acc, c.temp_c);
        a->temp_applied = c.temp_c;
        a->temp_set = true;
    }
    err = cal_acc_apply(&a->acc, s->accel_g, c.accel_g);
    if (err == INC_ERR_RANGE) {
        a->flags |= APP_F_SATURATED;
    }
    if ((s->flags & SENSOR_S_HAVE_GYRO) != 0u) {
        if (cal_gyro_apply(&a->gyro, s->gyro_dps, c.gyro_dps) == INC_ERR_RANGE) {
            a->flags |= APP_F_SATURATED;
        }
    } else {
        c.gyro_dps[0] = c.gyro_dps[1] = c.gyro_dps[2] = 0;
    }
    if ((s->flags & (SENSOR_S_ACCEL_SAT | SENSOR_S_GYRO_SAT)) != 0u) {
        a->flags |= APP_F_SATURATED;
    }
    (void)still_push(&a->still, c.gyro_dps, c.accel_g, &wdone);
    if (wdone) {
        const struct still_window *w = still_last(&a->still);
        if (w != NULL) {
            const uint8_t sa = a->cfg.slope.slope_axis, ga = a->cfg.slope.gravity_axis;
            const uint64_t floor_g = (uint64_t)(uint32_t)a->cfg.noise_floor_g;
            if (w->accel_var[sa] > a->var_max) a->var_max = w->accel_var[sa];
            for (i = 0; i < 3u; i++) {
                if (w->accel_var[i] < floor_g * floor_g) {
                    a->flags |= APP_F_QUIET;
                }
            }
            if (a->cfg.slope.method == SLOPE_TWO_AXIS && w->accel_var[ga] > a->var_max) {
                a->var_max = w->accel_var[ga];
            }
        }
    }
    for (i = 0; i < 3u; i++) {
        (void)fx_sum_add(&a->sum_a[i], c.accel_g[i]);
        (void)fx_sum_add(&a->sum_g[i], c.gyro_dps[i]);
    }
    (void)fx_sum_add(&a->sum_t, c.temp_c);
    a->missed = (a->missed > UINT32_MAX - s->missed) ? UINT32_MAX : a->missed + s->missed;
    a->n++;
    if (out != NULL) {
        *out = c;
    }
    if (a->n >= a->cfg.avg_n) {
        finish_block(a, res);
        block_reset(a);
        *done = true;
    }
    return INC_OK;
}

int app_measure(struct app *a, struct app_result *res)
{
    struct sensor_sample s;
    bool done = false;
    if (a == NULL || res == NULL) {
        return INC_ERR_NULL;
    }
    if (!a->ready) {
        return INC_ERR_STATE;
    }
    for (;;) {
        const int err = sensor_next(&a->sensor, 0u, &s);
        const int e2 = app_step(a, &s, err, NULL, &done, res);
        if (e2 != INC_OK) {
            return e2;
        }
        if (done) {
            return INC_OK;
        }
        /* A part that keeps failing: give up on this block after as many failures as three
         * blocks' worth of samples (a live part fails now and then; a dead one always). */
        if (err != INC_OK && a->errors / 3u >= a->cfg.avg_n) {
            block_reset(a);
            return err;
        }
    }
}
