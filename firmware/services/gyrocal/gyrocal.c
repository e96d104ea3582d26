/*
 * gyrocal.c - gyro bias calibration on the ADIS1636x/1640x driver (see inclino/gyrocal.h).
 *
 * [ADI-IMU-QS] ("optimising bias accuracy and stability") gives the three options and the
 * conditions: 819.2 SPS (SMPL_PRD = 0x01), thermal stability (read TEMP_OUT), zero rotation
 * including vibration, and more averaging for a better estimate (the Allan curve). Where the
 * seed's text and the fact sheet disagree (14- vs 13-bit offset, DIN 0xBE04 vs bit 3) the
 * driver's constants decide: 13 bits (docs/sensor-facts.md §3.4, the ADI example) and the GLOB_CMD bit.
 *
 * Arithmetic: the manual mode keeps exact int64 sums of the output counts. With k = 80 x LSB
 * offset counts per output count (4, 2, 1 at +-300, 150, 75 deg/s), 80 x mean deg/s = k S / N,
 * rounded once (ties away from zero, fx_div64). The processor-side correction is 4 k S / N in
 * 1/320 deg/s. Nothing is converted through an intermediate rounded mean.
 */
#include "inclino/gyrocal.h"

#include <stddef.h>

#include "inclino/fx.h"

#define MAX_AVG_SAMPLES (1u << 18) /* N sum c^2 <= N^2 2^26 <= 2^62 */
#define Q16_PER_OFF_LSB 819        /* 0.0125 deg/s in Q16.16 = 819.2 */
#define Q16_PER_PROC_LSB 205       /* 1/320 deg/s in Q16.16 = 204.8 */
#define ST_WINDOW 819u             /* 1 s at 819.2 SPS */
#define MAX_ADEV_Q16 (1L << 24)

static const char *const reason_text[GYROCAL_REASONS] = {
    "done",
    "done, offset saturated at the register limit",
    "refused: the part is moving",
    "refused: temperature not settled",
    "aborted: motion during calibration (old offset kept)",
    "aborted: temperature changed during calibration (old offset kept)",
    "aborted: verification of the corrected output failed (old offset kept)",
    "failed: bus or device error",
};

const char *gyrocal_reason_text(enum gyrocal_reason r)
{
    return (unsigned)r < (unsigned)GYROCAL_REASONS ? reason_text[r] : "unknown";
}

/* Output LSB in 1/1e6 deg/s and k = offset counts per output count. */
static int range_scale(enum adis_imu_range range, uint32_t *lsb_udps, unsigned *k)
{
    switch (range) {
    case ADIS_IMU_RANGE_300:
        *lsb_udps = 50000u;
        *k = 4u;
        return INC_OK;
    case ADIS_IMU_RANGE_150:
        *lsb_udps = 25000u;
        *k = 2u;
        return INC_OK;
    case ADIS_IMU_RANGE_75:
        *lsb_udps = 12500u;
        *k = 1u;
        return INC_OK;
    default: return INC_ERR_INVAL;
    }
}

/* Variance limit for a noise sd given as num/den counts, with the 6-sigma margin of a W = 819
 * estimate: 1 + 6 sqrt(2 / 818) = 1.2967, plus the quantisation 1/12 and one count of rounding. */
static uint64_t var_limit(uint64_t num, uint64_t den)
{
    return (num * num * 12967u) / (den * den * 10000u) + 1u;
}

int gyrocal_default_cfg(struct gyrocal_cfg *cfg, const struct adis_imu_variant_info *vi,
                        enum adis_imu_range range)
{
    uint32_t lsb_udps, lsb_ug;
    unsigned k;
    if (cfg == NULL || vi == NULL) {
        return INC_ERR_NULL;
    }
    if (range_scale(range, &lsb_udps, &k) != INC_OK || vi->accel_lsb_ug == 0u) {
        return INC_ERR_INVAL;
    }
    lsb_ug = vi->accel_lsb_ug;
    cfg->still.window = ST_WINDOW;
    cfg->still.windows_required = 2u;
    /* [ADI-IMU-QS]: unfiltered gyro noise below 1 deg/s rms -> sd = 1e6 / lsb_udps counts. */
    cfg->still.gyro_var_max = var_limit(1000000u, lsb_udps);
    /* [U] accelerometer noise: 10 mg rms assumed (docs/unconfirmed-facts.md). */
    cfg->still.accel_var_max = var_limit(10000u, lsb_ug);
    /* [U] 5 deg/s: above any uncalibrated bias, so a still part is never refused for its bias. */
    cfg->still.gyro_mean_max = 5000000u / lsb_udps;
    cfg->still.accel_one_g = (int32_t)((1000000u + lsb_ug / 2u) / lsb_ug);
    cfg->still.accel_norm_tol = 100000u / lsb_ug;                /* 100 mg */
    cfg->still.accel_drift_max = (3000u + lsb_ug - 1u) / lsb_ug; /* 3 mg, at least 1 count */
    cfg->thermal.avg_n = ST_WINDOW;                              /* 1 s points */
    cfg->thermal.span = 30u;                                     /* 30 s window */
    cfg->thermal.max_change = 1u;                                /* 1 TEMP_OUT LSB (0.136/0.14 C) */
    cfg->settle_timeout_ms = 15u * 60u * 1000u;                  /* [ADI-IMU-QS]: up to 10-15 min */
    cfg->manual_samples = GYROCAL_MANUAL_SAMPLES;
    cfg->manual_to_register = true;
    cfg->flash_update = true;
    cfg->adev_q16[GYROCAL_AUTONULL] = GYROCAL_ADEV_AUTONULL_Q16;
    cfg->adev_q16[GYROCAL_PRECISION] = GYROCAL_ADEV_PRECISION_Q16;
    cfg->adev_q16[GYROCAL_MANUAL] = GYROCAL_ADEV_MANUAL_Q16;
    cfg->verify_samples = 2u * ST_WINDOW;
    cfg->verify_sigmas = 6u;
    return INC_OK;
}

/* The driver's settings in force (the driver is ready: gyrocal_init checked it). */
static struct adis_imu_settings settings(const struct gyrocal *g)
{
    struct adis_imu_settings st;
    (void)adis_imu_get_settings(g->imu, &st);
    return st;
}

static uint64_t now_ns(const struct gyrocal *g)
{
    return hal_now_ns(adis_imu_hal(g->imu));
}

int gyrocal_init(struct gyrocal *g, struct adis_imu *imu, const struct gyrocal_cfg *cfg)
{
    struct adis_imu_settings st;
    unsigned m;
    int err;
    if (g == NULL || imu == NULL || cfg == NULL) {
        return INC_ERR_NULL;
    }
    g->ready = false;
    if (adis_imu_get_settings(imu, &st) != INC_OK) {
        return INC_ERR_STATE; /* the driver has not passed init */
    }
    if (cfg->manual_samples < 2u || cfg->manual_samples > MAX_AVG_SAMPLES ||
        cfg->verify_samples > MAX_AVG_SAMPLES || cfg->verify_sigmas < 1u ||
        cfg->verify_sigmas > 100u) {
        return INC_ERR_INVAL;
    }
    for (m = 0; m < (unsigned)GYROCAL_MODES; m++) {
        if (cfg->adev_q16[m] <= 0 || cfg->adev_q16[m] > MAX_ADEV_Q16) {
            return INC_ERR_INVAL;
        }
    }
    err = still_init(&g->still, &cfg->still);
    if (err == INC_OK) {
        err = still_thermal_init(&g->thermal, &cfg->thermal);
    }
    if (err != INC_OK) {
        return err;
    }
    g->imu = imu;
    g->cfg = *cfg;
    g->corr.valid = false;
    g->corr.corr[0] = g->corr.corr[1] = g->corr.corr[2] = 0;
    g->fed = 0;
    g->missed = 0;
    g->ready = true;
    return INC_OK;
}

#define NEEDED (ADIS_IMU_CH_GYROS | ADIS_IMU_CH_ACCELS | ADIS_IMU_CH(ADIS_IMU_CH_TEMP0))

int gyrocal_feed(struct gyrocal *g, const struct adis_imu_sample *s)
{
    int err;
    if (g == NULL || s == NULL) {
        return INC_ERR_NULL;
    }
    if (!g->ready) {
        return INC_ERR_STATE;
    }
    if ((s->valid & NEEDED) != NEEDED) {
        return INC_ERR_STALE;
    }
    err = still_push(&g->still, &s->counts[ADIS_IMU_CH_GYRO_X], &s->counts[ADIS_IMU_CH_ACCEL_X],
                     NULL);
    if (err == INC_OK) {
        err = still_thermal_push(&g->thermal, s->counts[ADIS_IMU_CH_TEMP0], NULL);
    }
    if (err == INC_OK && g->fed < UINT32_MAX) {
        g->fed++;
    }
    return err;
}

/* One burst sample at the next data-ready (or after one sample period without data-ready). */
static int read_one(struct gyrocal *g, struct adis_imu_sample *s, uint32_t *missed_acc)
{
    uint32_t missed = 0;
    if (settings(g).dr_enabled) {
        const int err = adis_imu_wait_ready(g->imu, 0, &missed);
        if (err != INC_OK) {
            return err;
        }
        g->missed += missed;
        if (missed_acc != NULL) {
            *missed_acc += missed;
        }
    } else {
        hal_delay_ns(adis_imu_hal(g->imu), adis_imu_current_period_ns(g->imu));
    }
    return adis_imu_read_sample(g->imu, s);
}

static int read_feed(struct gyrocal *g, struct adis_imu_sample *s, uint32_t *missed_acc)
{
    int err = read_one(g, s, missed_acc);
    if (err == INC_OK) {
        err = gyrocal_feed(g, s);
    }
    return err;
}

int gyrocal_monitor(struct gyrocal *g, uint32_t n)
{
    struct adis_imu_sample s;
    uint32_t i;
    if (g == NULL) {
        return INC_ERR_NULL;
    }
    if (!g->ready) {
        return INC_ERR_STATE;
    }
    for (i = 0; i < n; i++) {
        const int err = read_feed(g, &s, NULL);
        if (err != INC_OK) {
            return err;
        }
    }
    return INC_OK;
}

bool gyrocal_at_rest(const struct gyrocal *g)
{
    return g != NULL && g->ready && still_at_rest(&g->still);
}

bool gyrocal_settled(const struct gyrocal *g)
{
    return g != NULL && g->ready && still_thermal_settled(&g->thermal);
}

struct gyrocal_correction gyrocal_correction_get(const struct gyrocal *g)
{
    struct gyrocal_correction c = {{0, 0, 0}, false};
    if (g != NULL && g->ready) {
        c = g->corr;
    }
    return c;
}

int32_t gyrocal_correct_q16(const struct gyrocal_correction *c, unsigned axis, int32_t gyro_dps_q16)
{
    int32_t add = 0;
    if (c == NULL || !c->valid || axis > 2u) {
        return gyro_dps_q16;
    }
    /* corr / 320 deg/s = corr x 65536 / 320 = corr x 1024 / 5 Q16; |corr x 1024| <= 2^25. */
    (void)fx_div((int32_t)c->corr[axis] * 1024, 5, 0, &add);
    return fx_add(gyro_dps_q16, add);
}

/* ---- statistics helpers ---------------------------------------------------------------------- */

struct sums {
    int64_t s[3];   /* sum of counts */
    uint64_t s2[3]; /* sum of counts^2 */
    uint32_t n;
};

static void sums_clear(struct sums *a)
{
    unsigned i;
    for (i = 0; i < 3u; i++) {
        a->s[i] = 0;
        a->s2[i] = 0u;
    }
    a->n = 0;
}

static void sums_add(struct sums *a, const struct adis_imu_sample *smp)
{
    unsigned i;
    for (i = 0; i < 3u; i++) {
        const int64_t c = smp->counts[ADIS_IMU_CH_GYRO_X + i]; /* 14-bit: |c| <= 8192 */
        a->s[i] += c;
        a->s2[i] += (uint64_t)(c * c);
    }
    a->n++;
}

/* Mean output of axis i in deg/s Q16.16: S k / (80 N) x 65536 = S k 4096 / (5 N), rounded. */
static int32_t mean_q16(const struct sums *a, unsigned i, unsigned k)
{
    return fx_div64(a->s[i] * (int64_t)k * 4096, 5u * a->n);
}

/*
 * Standard error of the mean of axis i, deg/s Q16.16, for output samples that went through the
 * part's Bartlett filter of `taps` per stage (SENS_AVG M = log2 taps). The filter lowers the
 * per-sample variance by g = (2 taps^2 + 1) / (3 taps^3) but not the variance of a long mean, so
 * se^2 = var / (g n): without that factor the estimate would be sqrt(g) too small (0.41 at the
 * default M = 2). An estimate: truncating divisions, white noise assumed.
 */
static int32_t se_q16(const struct sums *a, unsigned i, unsigned k, uint32_t taps)
{
    const uint64_t n = a->n;
    const uint64_t sa = fx_uabs64(a->s[i]);
    const uint64_t gnum = 3u * (uint64_t)taps * taps * taps, gden = 2u * (uint64_t)taps * taps + 1u;
    uint64_t num, v16, v32;
    if (n < 2u) {
        return 0;
    }
    num = n * a->s2[i] - sa * sa; /* n^2 x variance, <= n^2 2^26 <= 2^62 */
    v16 = ((num / n) << 16) / n;  /* variance, counts^2 Q16 (num / n <= 2^44) */
    v32 = (v16 << 16) / n;        /* variance of the mean, counts^2 Q32 (<= 2^58) */
    /* / g: gnum <= 3 * 2^18; multiply first while it cannot overflow, else divide first */
    v32 = v32 < ((uint64_t)1 << 43) ? v32 * gnum / gden : v32 / gden * gnum;
    return fx_div64((int64_t)fx_isqrt64(v32) * (int64_t)k, 80u); /* counts Q16 -> deg/s Q16 */
}

/* sqrt(a^2 + b^2) for Q16 magnitudes < 2^24. */
static int32_t hypot_q16(int32_t a, int32_t b)
{
    const uint64_t ua = fx_uabs32(a), ub = fx_uabs32(b);
    return (int32_t)fx_isqrt64_round(ua * ua + ub * ub);
}

/* Residual estimate: sqrt(a^2 + q^2/12), q the correction's resolution in Q16. */
static int32_t residual_q16(int32_t adev, int32_t q)
{
    const uint64_t ua = fx_uabs32(adev);
    return (int32_t)fx_isqrt64_round(ua * ua + ((uint64_t)q * (uint64_t)q) / 12u);
}

/* ---- procedure helpers ------------------------------------------------------------------------ */

static void result_start(struct gyrocal *g, enum gyrocal_mode mode, struct gyrocal_result *res)
{
    unsigned i;
    res->mode = (uint8_t)mode;
    res->reason = GYROCAL_DONE;
    for (i = 0; i < 3u; i++) {
        res->old_offset[i] = res->new_offset[i] = 0;
        res->saturated[i] = res->proc_saturated[i] = false;
        res->proc_corr[i] = g->corr.valid ? g->corr.corr[i] : 0;
        res->mean_q16[i] = res->residual_q16[i] = 0;
        res->verify_mean_q16[i] = res->verify_limit_q16[i] = 0;
    }
    res->samples = 0;
    res->missed = 0;
    res->t_avg_start_ns = res->t_avg_end_ns = 0;
    res->t_start_ns = res->t_end_ns = now_ns(g);
}

static int finish(struct gyrocal *g, struct gyrocal_result *res, enum gyrocal_reason why, int err)
{
    res->reason = (uint8_t)why;
    res->t_end_ns = now_ns(g);
    return err;
}

static int read_offsets(struct gyrocal *g, int32_t off[3])
{
    unsigned i;
    for (i = 0; i < 3u; i++) {
        const int err = adis_imu_get_gyro_offset(g->imu, i, &off[i]);
        if (err != INC_OK) {
            return err;
        }
    }
    return INC_OK;
}

static int write_offsets(struct gyrocal *g, const int32_t off[3])
{
    unsigned i;
    for (i = 0; i < 3u; i++) {
        const int err = adis_imu_set_gyro_offset(g->imu, i, off[i]);
        if (err != INC_OK) {
            return err;
        }
    }
    return INC_OK;
}

static bool at_limit(int32_t off)
{
    return off <= ADIS_IMU_GYRO_OFF_MIN || off >= ADIS_IMU_GYRO_OFF_MAX;
}

/* Restore SMPL_PRD / SENS_AVG saved at the start of a procedure (when they changed). */
static int restore_settings(struct gyrocal *g, uint8_t prd, uint16_t avg)
{
    const struct adis_imu_settings st = settings(g);
    int err = INC_OK;
    if ((st.sens_avg & 0x07FFu) != (avg & 0x07FFu)) {
        err = adis_imu_set_filter(
            g->imu, avg & ADIS_IMU_SENS_AVG_M_MASK,
            (enum adis_imu_range)((avg >> ADIS_IMU_SENS_AVG_RANGE_SHIFT) & 7u));
    }
    if (err == INC_OK && st.smpl_prd != prd) {
        err = adis_imu_set_sample_period(g->imu, prd);
    }
    return err;
}

/*
 * After a procedure: read (and feed) samples until the stillness window that spans the end of
 * the procedure has been judged and at least verify_samples were read; the verification sums go
 * to *v. Returns a driver error or 0.
 */
static int post_read(struct gyrocal *g, struct sums *v, uint32_t *missed)
{
    struct adis_imu_sample s;
    const uint32_t w_end = still_window_count(&g->still);
    int err = adis_imu_dr_flush(g->imu);
    sums_clear(v);
    while (err == INC_OK &&
           (v->n < g->cfg.verify_samples || still_window_count(&g->still) <= w_end)) {
        err = read_feed(g, &s, missed);
        if (err == INC_OK && v->n < g->cfg.verify_samples) {
            sums_add(v, &s);
        }
    }
    return err;
}

/* Verification of the corrected output: per axis |mean| <= sigmas x sqrt(se^2 + r^2); axes whose
 * register or correction saturated are reported but not judged. True when it passes. */
static bool verify(const struct gyrocal *g, const struct sums *v, unsigned k, const int16_t corr[3],
                   bool corr_valid, struct gyrocal_result *res)
{
    struct gyrocal_correction c;
    const uint32_t taps = 1u << settings(g).taps_log2;
    bool ok = true;
    unsigned i;
    if (v->n < 2u) {
        return true;
    }
    for (i = 0; i < 3u; i++) {
        c.corr[i] = corr[i];
    }
    c.valid = corr_valid;
    for (i = 0; i < 3u; i++) {
        const int32_t m = gyrocal_correct_q16(&c, i, mean_q16(v, i, k));
        const int32_t se = se_q16(v, i, k, taps);
        const int64_t lim = (int64_t)g->cfg.verify_sigmas * hypot_q16(se, res->residual_q16[i]);
        res->verify_mean_q16[i] = m;
        res->verify_limit_q16[i] = fx_sat32(lim);
        if (!res->saturated[i] && !res->proc_saturated[i] && (int64_t)fx_uabs32(m) > lim) {
            ok = false;
        }
    }
    return ok;
}

/* The detectors' verdict on the span since m0: motion, or a temperature change. Once settled,
 * a procedure tolerates one LSB more than the start condition (hysteresis): a part that just
 * met max_change would otherwise flap on the rounding of its points. */
static enum gyrocal_reason during(const struct gyrocal *g, uint32_t m0)
{
    uint32_t change = 0;
    if (still_motion_count(&g->still) != m0) {
        return GYROCAL_ABORTED_MOTION;
    }
    if (still_thermal_change(&g->thermal, &change) != INC_OK ||
        change > g->cfg.thermal.max_change + 1u) {
        return GYROCAL_ABORTED_THERMAL;
    }
    return GYROCAL_DONE;
}

/* Read until the stillness window in progress has been judged (nothing to do when none is in
 * progress), so the verdict covers every sample taken so far. */
static int close_window(struct gyrocal *g, uint32_t *missed)
{
    struct adis_imu_sample s;
    const uint32_t w = still_window_count(&g->still);
    int err = INC_OK;
    while (err == INC_OK && g->still.n != 0u && still_window_count(&g->still) == w) {
        err = read_feed(g, &s, missed);
    }
    return err;
}

static int reason_err(enum gyrocal_reason r)
{
    switch (r) {
    case GYROCAL_DONE: return INC_OK;
    case GYROCAL_SATURATED: return INC_ERR_RANGE;
    case GYROCAL_REFUSED_MOVING:
    case GYROCAL_ABORTED_MOTION: return INC_ERR_MOTION;
    case GYROCAL_REFUSED_THERMAL:
    case GYROCAL_ABORTED_THERMAL: return INC_ERR_THERMAL;
    default: return INC_ERR_ABORTED;
    }
}

/* Abort after the part's offsets may have changed: the old ones go back (registers only: the
 * flash is updated only after a successful verification). */
static int abort_restore(struct gyrocal *g, struct gyrocal_result *res, enum gyrocal_reason why,
                         uint8_t prd, uint16_t avg)
{
    unsigned i;
    int err = write_offsets(g, res->old_offset);
    const int err2 = restore_settings(g, prd, avg);
    for (i = 0; i < 3u; i++) {
        res->new_offset[i] = res->old_offset[i];
        res->saturated[i] = false;
        res->proc_corr[i] = g->corr.valid ? g->corr.corr[i] : 0;
        res->proc_saturated[i] = false;
    }
    if (err == INC_OK) {
        err = err2;
    }
    if (err != INC_OK) {
        return finish(g, res, GYROCAL_FAILED_DEVICE, err);
    }
    return finish(g, res, why, reason_err(why));
}

/* A driver error during a procedure: put back what can be put back, report the driver's code. */
static int fail_restore(struct gyrocal *g, struct gyrocal_result *res, int err, uint8_t prd,
                        uint16_t avg)
{
    (void)abort_restore(g, res, GYROCAL_FAILED_DEVICE, prd, avg);
    return finish(g, res, GYROCAL_FAILED_DEVICE, err);
}

/* ---- the modes ---------------------------------------------------------------------------- */

static int run_autonull(struct gyrocal *g, struct gyrocal_result *res, enum adis_imu_range range,
                        uint8_t prd, uint16_t avg, uint32_t m0)
{
    struct adis_imu_sample s;
    const uint32_t fill = (GYROCAL_AUTONULL_FILL_MS * 8192u + 9999u) / 10000u; /* 164 at 819.2 */
    enum gyrocal_reason why = GYROCAL_DONE;
    uint32_t i;
    int err = adis_imu_set_sample_period(g->imu, 0x01u);
    if (err == INC_OK) {
        err = adis_imu_set_filter(g->imu, GYROCAL_AUTONULL_M, range);
    }
    if (err == INC_OK) {
        err = adis_imu_dr_flush(g->imu);
    }
    /* 200 ms for the taps to fill ([ADI-IMU-QS]), watched by the detectors; then the window in
     * progress is judged before the part changes its offsets (a step it would read as motion). */
    for (i = 0; err == INC_OK && i < fill; i++) {
        err = read_feed(g, &s, &res->missed);
    }
    if (err == INC_OK) {
        err = close_window(g, &res->missed);
    }
    if (err == INC_OK) {
        why = during(g, m0);
    }
    if (why != GYROCAL_DONE) {
        return abort_restore(g, res, why, prd, avg);
    }
    if (err == INC_OK) {
        /* the part nulls its filter output: the last 2 N - 1 samples, N = 64 */
        const uint64_t span = (uint64_t)(2u * (1u << GYROCAL_AUTONULL_M) - 1u) *
                              adis_imu_current_period_ns(g->imu);
        res->t_avg_end_ns = now_ns(g);
        res->t_avg_start_ns = res->t_avg_end_ns > span ? res->t_avg_end_ns - span : 0u;
        err = adis_imu_command(g->imu, ADIS_IMU_CMD_AUTONULL);
        still_restart_window(&g->still);
    }
    if (err == INC_OK) {
        err = restore_settings(g, prd, avg);
    }
    return err;
}

static int run_manual_average(struct gyrocal *g, struct gyrocal_result *res, struct sums *a,
                              uint32_t m0, enum gyrocal_reason *why)
{
    struct adis_imu_sample s;
    int err = adis_imu_dr_flush(g->imu);
    sums_clear(a);
    *why = GYROCAL_DONE;
    while (err == INC_OK && a->n < g->cfg.manual_samples) {
        const uint32_t w = still_window_count(&g->still);
        err = read_feed(g, &s, &res->missed);
        if (err != INC_OK) {
            break;
        }
        sums_add(a, &s);
        if (a->n == 1u) {
            res->t_avg_start_ns = s.t_ns;
        }
        res->t_avg_end_ns = s.t_ns;
        if (still_window_count(&g->still) != w) {
            *why = during(g, m0); /* judged once per window: stop at the first motion */
            if (*why != GYROCAL_DONE) {
                break;
            }
        }
    }
    res->samples = a->n;
    if (err == INC_OK && *why == GYROCAL_DONE) {
        /* the last samples' window judged before anything is written */
        err = close_window(g, &res->missed);
        if (err == INC_OK) {
            *why = during(g, m0);
        }
    }
    return err;
}

/* ---- one run, in phases ------------------------------------------------------------------- */

/* What the phases of one run share. */
struct run {
    enum gyrocal_mode mode;
    enum adis_imu_range range;
    unsigned k;      /* offset counts per output count */
    uint8_t prd;     /* SMPL_PRD at the start (put back at the end) */
    uint16_t avg;    /* SENS_AVG at the start */
    uint32_t m0;     /* motion count when the gate passed */
    int16_t corr[3]; /* processor-side correction after the run */
    bool corr_valid; /* it is in force */
    bool manual_reg; /* the registers are written (every mode but MANUAL to the processor) */
    struct sums a;   /* MANUAL: the average */
};

/*
 * Each phase returns true when the run goes on, false when it has ended: *err then holds the
 * run's return code and *res is finished.
 */

/* Check the mode and the range, save the settings and the old offsets. */
static bool run_prepare(struct gyrocal *g, enum gyrocal_mode mode, struct run *r,
                        struct gyrocal_result *res, int *err)
{
    const struct adis_imu_settings st = settings(g);
    uint32_t lsb_udps;
    unsigned i;
    if ((unsigned)mode >= (unsigned)GYROCAL_MODES) {
        *err = finish(g, res, GYROCAL_FAILED_DEVICE, INC_ERR_INVAL);
        return false;
    }
    r->mode = mode;
    r->range = adis_imu_gyro_range(g->imu);
    if (range_scale(r->range, &lsb_udps, &r->k) != INC_OK) {
        *err = finish(g, res, GYROCAL_FAILED_DEVICE, INC_ERR_INVAL);
        return false;
    }
    r->prd = st.smpl_prd;
    r->avg = st.sens_avg;
    *err = read_offsets(g, res->old_offset);
    if (*err != INC_OK) {
        *err = finish(g, res, GYROCAL_FAILED_DEVICE, *err);
        return false;
    }
    for (i = 0; i < 3u; i++) {
        res->new_offset[i] = res->old_offset[i];
        r->corr[i] = res->proc_corr[i];
    }
    r->corr_valid = g->corr.valid;
    r->manual_reg = mode != GYROCAL_MANUAL || g->cfg.manual_to_register;
    return true;
}

/* Gate: at rest now (every mode), thermally settled (MANUAL may wait for it first). */
static bool run_gate(struct gyrocal *g, struct run *r, struct gyrocal_result *res, int *err)
{
    if (!still_at_rest(&g->still)) {
        *err = finish(g, res, GYROCAL_REFUSED_MOVING, INC_ERR_MOTION);
        return false;
    }
    if (r->mode == GYROCAL_MANUAL && !still_thermal_settled(&g->thermal)) {
        struct adis_imu_sample s;
        const uint64_t deadline = res->t_start_ns + (uint64_t)g->cfg.settle_timeout_ms * 1000000u;
        *err = adis_imu_set_sample_period(g->imu, 0x01u);
        while (*err == INC_OK && !still_thermal_settled(&g->thermal) && now_ns(g) < deadline) {
            *err = read_feed(g, &s, &res->missed);
        }
        if (*err != INC_OK) {
            (void)restore_settings(g, r->prd, r->avg);
            *err = finish(g, res, GYROCAL_FAILED_DEVICE, *err);
            return false;
        }
        if (!still_thermal_settled(&g->thermal) || !still_at_rest(&g->still)) {
            *err = restore_settings(g, r->prd, r->avg);
            if (*err != INC_OK) {
                *err = finish(g, res, GYROCAL_FAILED_DEVICE, *err);
            } else {
                *err = still_at_rest(&g->still)
                           ? finish(g, res, GYROCAL_REFUSED_THERMAL, INC_ERR_THERMAL)
                           : finish(g, res, GYROCAL_REFUSED_MOVING, INC_ERR_MOTION);
            }
            return false;
        }
    }
    if (!still_thermal_settled(&g->thermal)) {
        *err = finish(g, res, GYROCAL_REFUSED_THERMAL, INC_ERR_THERMAL);
        return false;
    }
    r->m0 = still_motion_count(&g->still);
    return true;
}

/* PRECISION: the part averages 30 s at its own settings and is busy meanwhile: no sample can be
 * read, so motion in that time shows only in the verification. */
static bool step_precision(struct gyrocal *g, struct run *r, struct gyrocal_result *res, int *err)
{
    enum gyrocal_reason why = GYROCAL_DONE;
    *err = close_window(g, &res->missed);
    if (*err == INC_OK) {
        why = during(g, r->m0);
    }
    if (why != GYROCAL_DONE) {
        *err = finish(g, res, why, reason_err(why));
        return false;
    }
    if (*err == INC_OK) {
        res->t_avg_start_ns = now_ns(g);
        res->t_avg_end_ns = res->t_avg_start_ns +
                            (uint64_t)ADIS_IMU_PRECISION_AUTONULL_MS * 1000000u;
        *err = adis_imu_command(g->imu, ADIS_IMU_CMD_PRECISION_AUTONULL);
        still_restart_window(&g->still); /* samples before the 30 s gap: not one window */
    }
    return true;
}

/* MANUAL: the average at 819.2 SPS; nothing is written yet. */
static bool step_manual(struct gyrocal *g, struct run *r, struct gyrocal_result *res, int *err)
{
    enum gyrocal_reason why = GYROCAL_DONE;
    *err = adis_imu_set_sample_period(g->imu, 0x01u);
    if (*err == INC_OK) {
        *err = run_manual_average(g, res, &r->a, r->m0, &why);
    }
    if (*err == INC_OK && why != GYROCAL_DONE) {
        /* nothing written yet: the old offsets are still in place */
        *err = restore_settings(g, r->prd, r->avg);
        *err = *err != INC_OK ? finish(g, res, GYROCAL_FAILED_DEVICE, *err)
                              : finish(g, res, why, reason_err(why));
        return false;
    }
    return true;
}

/* The procedure of the mode; a driver error puts back what can be put back. */
static bool run_step(struct gyrocal *g, struct run *r, struct gyrocal_result *res, int *err)
{
    switch (r->mode) {
    case GYROCAL_AUTONULL:
        *err = run_autonull(g, res, r->range, r->prd, r->avg, r->m0);
        if (res->reason != GYROCAL_DONE) {
            return false; /* aborted inside, already restored */
        }
        break;
    case GYROCAL_PRECISION:
        if (!step_precision(g, r, res, err)) {
            return false;
        }
        break;
    default:
        if (!step_manual(g, r, res, err)) {
            return false;
        }
        break;
    }
    if (*err != INC_OK) {
        *err = fail_restore(g, res, *err, r->prd, r->avg);
        return false;
    }
    return true;
}

/* MANUAL: the new offsets and the processor-side correction from the average, and their
 * residual estimates; the registers written when the run writes them. */
static int apply_manual(struct gyrocal *g, struct run *r, struct gyrocal_result *res)
{
    const uint32_t taps = 1u << settings(g).taps_log2;
    unsigned i;
    for (i = 0; i < 3u; i++) {
        const int32_t d = -fx_div64(r->a.s[i] * (int64_t)r->k, r->a.n);            /* -80 x mean */
        const int32_t total = -fx_div64(r->a.s[i] * (int64_t)(4u * r->k), r->a.n); /* -320 x */
        int32_t fine = total;
        int32_t se;
        res->mean_q16[i] = mean_q16(&r->a, i, r->k);
        if (r->manual_reg) {
            int32_t nv = res->old_offset[i] + d;
            if (nv > ADIS_IMU_GYRO_OFF_MAX || nv < ADIS_IMU_GYRO_OFF_MIN) {
                nv = nv > 0 ? ADIS_IMU_GYRO_OFF_MAX : ADIS_IMU_GYRO_OFF_MIN;
                res->saturated[i] = true;
            }
            res->new_offset[i] = nv;
            /* what the register did not take: 4 units of 1/320 per register count */
            fine = total - 4 * (nv - res->old_offset[i]);
        }
        if (fine > INT16_MAX || fine < INT16_MIN) {
            fine = fine > 0 ? INT16_MAX : INT16_MIN;
            res->proc_saturated[i] = true;
        }
        r->corr[i] = (int16_t)fine;
        se = se_q16(&r->a, i, r->k, taps);
        /* resolution of what is applied without the application's help: the register when
         * writing it, the 1/320 deg/s correction otherwise */
        res->residual_q16[i] = residual_q16(
            se > g->cfg.adev_q16[GYROCAL_MANUAL] ? se : g->cfg.adev_q16[GYROCAL_MANUAL],
            r->manual_reg ? Q16_PER_OFF_LSB : Q16_PER_PROC_LSB);
    }
    r->corr_valid = true;
    if (r->manual_reg) {
        const int err = write_offsets(g, res->new_offset);
        if (err != INC_OK) {
            return err;
        }
        still_restart_window(&g->still); /* the output steps here */
    }
    return restore_settings(g, r->prd, r->avg);
}

/* AUTONULL / PRECISION: the part wrote its offsets; read them back. */
static int apply_register(struct gyrocal *g, struct run *r, struct gyrocal_result *res)
{
    const int err = read_offsets(g, res->new_offset);
    unsigned i;
    for (i = 0; i < 3u; i++) {
        res->saturated[i] = at_limit(res->new_offset[i]);
        res->residual_q16[i] = residual_q16(g->cfg.adev_q16[r->mode], Q16_PER_OFF_LSB);
        /* a processor-side correction in force belongs to the old register values */
        r->corr[i] = 0;
    }
    r->corr_valid = false;
    return err;
}

/* New offsets / correction and the residual estimate. */
static bool run_apply(struct gyrocal *g, struct run *r, struct gyrocal_result *res, int *err)
{
    unsigned i;
    *err = r->mode == GYROCAL_MANUAL ? apply_manual(g, r, res) : apply_register(g, r, res);
    if (*err != INC_OK) {
        *err = fail_restore(g, res, *err, r->prd, r->avg);
        return false;
    }
    for (i = 0; i < 3u; i++) {
        res->proc_corr[i] = r->corr[i];
    }
    return true;
}

/* After: the window spanning the end judged, the corrected output verified, the flash updated
 * and the correction put in force. Returns the run's code. */
static int run_verify(struct gyrocal *g, struct run *r, struct gyrocal_result *res)
{
    struct sums v;
    enum gyrocal_reason why;
    unsigned i;
    int err = post_read(g, &v, &res->missed);
    if (err != INC_OK) {
        return fail_restore(g, res, err, r->prd, r->avg);
    }
    why = during(g, r->m0);
    if (why != GYROCAL_DONE) {
        return abort_restore(g, res, why, r->prd, r->avg);
    }
    if (!verify(g, &v, r->k, r->corr, r->corr_valid, res)) {
        return abort_restore(g, res, GYROCAL_ABORTED_VERIFY, r->prd, r->avg);
    }
    if (g->cfg.flash_update && r->manual_reg) {
        /* GLOB_CMD[3]: the bit (DIN 0xBE08), not [ADI-IMU-QS]'s 0xBE04. */
        err = adis_imu_command(g->imu, ADIS_IMU_CMD_FLASH_UPDATE);
        if (err != INC_OK) {
            return fail_restore(g, res, err, r->prd, r->avg);
        }
    }
    for (i = 0; i < 3u; i++) {
        g->corr.corr[i] = r->corr[i];
    }
    g->corr.valid = r->corr_valid;
    for (i = 0; i < 3u; i++) {
        if (res->saturated[i] || res->proc_saturated[i]) {
            return finish(g, res, GYROCAL_SATURATED, INC_ERR_RANGE);
        }
    }
    return finish(g, res, GYROCAL_DONE, INC_OK);
}

int gyrocal_run(struct gyrocal *g, enum gyrocal_mode mode, struct gyrocal_result *res)
{
    struct run r;
    int err = INC_OK;
    if (g == NULL || res == NULL) {
        return INC_ERR_NULL;
    }
    if (!g->ready) {
        return INC_ERR_STATE;
    }
    result_start(g, mode, res);
    if (run_prepare(g, mode, &r, res, &err) && run_gate(g, &r, res, &err) &&
        run_step(g, &r, res, &err) && run_apply(g, &r, res, &err)) {
        err = run_verify(g, &r, res);
    }
    return err;
}
