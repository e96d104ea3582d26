/*
 * noise.c - see sim/noise.h.
 *
 * Why these forms (IEEE Std 952-1997 annex C; docs/noise-and-allan.md):
 *  - White rate noise of density N sampled at dt has per-sample variance N^2/dt; the mean of m
 *    samples then has variance N^2/(m dt), so the Allan variance is N^2/tau for every tau = m dt.
 *  - Flicker rate noise (the bias-instability floor) cannot be generated exactly with finite
 *    state; a sum of first-order Gauss-Markov processes with correlation times spaced evenly in
 *    log time and equal variances has a 1/f spectrum between the corner frequencies, which is
 *    the usual practical approximation. Three per decade keeps the ripple of the floor within
 *    +-2 % between 10 tc_min and tc_max / 4.
 *    The common variance is set so the Allan deviation of the sum averages 0.664 B over the
 *    band (the IEEE 952 floor of flicker noise of coefficient B).
 *  - The discrete Gauss-Markov step x' = a x + sigma sqrt(1 - a^2) w with a = exp(-dt/tc) is
 *    the exact discretisation: the stationary variance stays sigma^2 for any dt.
 */
#include "inclino/sim/noise.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

#include "inclino/error.h"

#define GM_PER_DECADE 3.0
#define GM_MAX_SPAN 1e5 /* 5 decades: 16 components at 3 per decade */
#define NORM_POINTS 41

/* Allan variance of a unit-variance first-order Gauss-Markov process at x = tau / tc. */
static double gm_avar_unit(double x)
{
    if (x < 1e-4) {
        /* Series: (2/3) x - (1/2) x^2 + ...; the closed form cancels catastrophically here. */
        return (2.0 / 3.0) * x - 0.5 * x * x;
    }
    return (2.0 * x - 3.0 + 4.0 * exp(-x) - exp(-2.0 * x)) / (x * x);
}

/*
 * Standard normal deviates by Marsaglia's polar method: two per accepted pair of uniforms, one
 * log and one sqrt, the second kept for the next call. About three times cheaper than
 * sim_rng_gauss (one Box-Muller value per call), which matters for 10^7-sample Allan runs.
 * Deterministic: the stream depends only on the seed and the call sequence.
 */
static double gauss(struct sim_noise *n)
{
    double u, v, s, f;
    if (n->spare_valid) {
        n->spare_valid = false;
        return n->spare;
    }
    do {
        u = 2.0 * sim_rng_uniform(&n->rng) - 1.0;
        v = 2.0 * sim_rng_uniform(&n->rng) - 1.0;
        s = u * u + v * v;
    } while (s >= 1.0 || s == 0.0);
    f = sqrt(-2.0 * log(s) / s);
    n->spare = v * f;
    n->spare_valid = true;
    return u * f;
}

static bool finite_nonneg(double v)
{
    return isfinite(v) && v >= 0.0;
}

int sim_noise_gm_layout(const struct sim_noise_axis *ax, unsigned *n_gm, double *tc, double *sigma)
{
    double lo, hi, span, band_lo, band_hi, mean = 0.0;
    unsigned n, k, i;
    if (ax == NULL || n_gm == NULL || tc == NULL || sigma == NULL) {
        return INC_ERR_NULL;
    }
    if (!finite_nonneg(ax->bias_instability)) {
        return INC_ERR_INVAL;
    }
    if (ax->bias_instability == 0.0) {
        *n_gm = 0;
        *sigma = 0.0;
        return INC_OK;
    }
    lo = ax->bi_tc_min_s;
    hi = ax->bi_tc_max_s;
    if (!isfinite(lo) || !isfinite(hi) || !(lo > 0.0) || !(hi > lo)) {
        return INC_ERR_INVAL;
    }
    span = hi / lo;
    if (span > GM_MAX_SPAN * 1.000001) {
        return INC_ERR_INVAL;
    }
    n = (unsigned)ceil(log10(span) * GM_PER_DECADE - 1e-9) + 1u;
    if (n < 2u) {
        n = 2u;
    }
    if (n > SIM_NOISE_GM_MAX) {
        return INC_ERR_INVAL;
    }
    for (k = 0; k < n; k++) {
        tc[k] = lo * pow(span, (double)k / (double)(n - 1u));
    }
    /* Normalise over the band where the sum is flat (it rolls off within a decade of either end:
     * -17 % at 2 tc_min); a narrow range uses its geometric centre. */
    band_lo = 10.0 * lo;
    band_hi = 0.25 * hi;
    if (!(band_hi > band_lo)) {
        band_lo = band_hi = sqrt(lo * hi);
    }
    for (i = 0; i < NORM_POINTS; i++) {
        const double tau = band_lo * pow(band_hi / band_lo, (double)i / (double)(NORM_POINTS - 1));
        double s = 0.0;
        for (k = 0; k < n; k++) {
            s += gm_avar_unit(tau / tc[k]);
        }
        mean += s / NORM_POINTS;
    }
    *n_gm = n;
    *sigma = SIM_NOISE_BI_FLOOR * ax->bias_instability / sqrt(mean);
    return INC_OK;
}

static int check_axis(const struct sim_noise_axis *ax)
{
    if (!isfinite(ax->bias) || !isfinite(ax->temp_coeff) || !finite_nonneg(ax->white) ||
        !finite_nonneg(ax->bias_instability) || !finite_nonneg(ax->rrw) ||
        !finite_nonneg(ax->quantum)) {
        return INC_ERR_INVAL;
    }
    return INC_OK;
}

int sim_noise_init(struct sim_noise *n, const struct sim_noise_cfg *cfg)
{
    unsigned c, k;
    if (n == NULL || cfg == NULL) {
        return INC_ERR_NULL;
    }
    memset(n, 0, sizeof(*n));
    if (!finite_nonneg(cfg->temp_white_c)) {
        return INC_ERR_INVAL;
    }
    for (c = 0; c < SIM_NOISE_CHANNELS; c++) {
        struct sim_noise_chan *ch = &n->ch[c];
        int err = check_axis(&cfg->ch[c]);
        if (err == INC_OK) {
            err = sim_noise_gm_layout(&cfg->ch[c], &ch->n_gm, ch->gm_tc, &ch->gm_sigma);
        }
        if (err != INC_OK) {
            memset(n, 0, sizeof(*n));
            return err;
        }
    }
    n->cfg = *cfg;
    sim_rng_seed(&n->rng, cfg->seed);
    /* Stationary start, drawn in channel and component order (part of the reproducible stream). */
    for (c = 0; c < SIM_NOISE_CHANNELS; c++) {
        struct sim_noise_chan *ch = &n->ch[c];
        for (k = 0; k < ch->n_gm; k++) {
            ch->gm_x[k] = ch->gm_sigma * gauss(n);
        }
    }
    return INC_OK;
}

static void set_dt(struct sim_noise *n, double dt_s)
{
    unsigned c, k;
    for (c = 0; c < SIM_NOISE_CHANNELS; c++) {
        struct sim_noise_chan *ch = &n->ch[c];
        const struct sim_noise_axis *ax = &n->cfg.ch[c];
        for (k = 0; k < ch->n_gm; k++) {
            const double a = exp(-dt_s / ch->gm_tc[k]);
            ch->gm_a[k] = a;
            ch->gm_w[k] = ch->gm_sigma * sqrt(1.0 - a * a);
        }
        ch->white_sd = ax->white / sqrt(dt_s);
        ch->rrw_sd = ax->rrw * sqrt(dt_s);
    }
    n->dt_s = dt_s;
}

/* Advance channel c by one sample; returns the error to add (white and quantisation excluded
 * from last_bias). Draw order per sample: Gauss-Markov components, white, random walk. */
static double chan_step(struct sim_noise *n, unsigned c, double temp_c, double *white)
{
    struct sim_noise_chan *ch = &n->ch[c];
    const struct sim_noise_axis *ax = &n->cfg.ch[c];
    double b = ax->bias + ax->temp_coeff * (temp_c - 25.0);
    unsigned k;
    for (k = 0; k < ch->n_gm; k++) {
        ch->gm_x[k] = ch->gm_a[k] * ch->gm_x[k] + ch->gm_w[k] * gauss(n);
        b += ch->gm_x[k];
    }
    *white = ch->white_sd > 0.0 ? ch->white_sd * gauss(n) : 0.0;
    b += ch->rrw_x;
    if (ch->rrw_sd > 0.0) {
        /* The walk moves after the sample: x[0] = 0, as documented. */
        ch->rrw_x += ch->rrw_sd * gauss(n);
    }
    ch->last_bias = b;
    return b;
}

static double quantise(double v, double q)
{
    double c;
    if (!(q > 0.0)) {
        return v;
    }
    c = v / q;
    c = c < 0.0 ? -floor(-c + 0.5) : floor(c + 0.5);
    return c * q;
}

double sim_noise_step(struct sim_noise *n, unsigned chan, double truth, double temp_c, double dt_s)
{
    double white, b;
    if (n == NULL || chan >= SIM_NOISE_CHANNELS || !(dt_s > 0.0)) {
        return truth;
    }
    if (dt_s != n->dt_s) {
        set_dt(n, dt_s);
    }
    b = chan_step(n, chan, temp_c, &white);
    return quantise(truth + b + white, n->cfg.ch[chan].quantum);
}

void sim_noise_apply(void *ctx, const struct sim_inertial_input *in, struct sim_inertial_input *out,
                     uint64_t t_ns, double dt_s)
{
    struct sim_noise *n = ctx;
    unsigned c;
    (void)t_ns;
    if (in == NULL || out == NULL) {
        return;
    }
    *out = *in;
    if (n == NULL || !(dt_s > 0.0)) {
        return;
    }
    if (dt_s != n->dt_s) {
        set_dt(n, dt_s);
    }
    for (c = 0; c < SIM_NOISE_CHANNELS; c++) {
        double white;
        const double b = chan_step(n, c, in->temp_c, &white);
        const double q = n->cfg.ch[c].quantum;
        if (c < 3u) {
            out->rate_dps[c] = quantise(in->rate_dps[c] + b + white, q);
        } else {
            out->accel_g[c - 3u] = quantise(in->accel_g[c - 3u] + b + white, q);
        }
    }
    if (n->cfg.temp_white_c > 0.0) {
        out->temp_c = in->temp_c + n->cfg.temp_white_c * gauss(n);
    }
    n->samples++;
}

struct sim_error_model sim_noise_hook(struct sim_noise *n)
{
    struct sim_error_model m;
    m.apply = sim_noise_apply;
    m.ctx = n;
    return m;
}

double sim_noise_bias_now(const struct sim_noise *n, unsigned chan)
{
    if (n == NULL || chan >= SIM_NOISE_CHANNELS) {
        return 0.0;
    }
    return n->ch[chan].last_bias;
}

double sim_noise_avar(const struct sim_noise_axis *ax, double tau_s, double dt_s)
{
    double tc[SIM_NOISE_GM_MAX], sigma, v;
    unsigned n_gm, k;
    if (ax == NULL || !(tau_s > 0.0) || !(dt_s > 0.0) || check_axis(ax) != INC_OK ||
        sim_noise_gm_layout(ax, &n_gm, tc, &sigma) != INC_OK) {
        return -1.0;
    }
    v = ax->white * ax->white / tau_s + ax->rrw * ax->rrw * tau_s / 3.0 +
        ax->quantum * ax->quantum / 12.0 * dt_s / tau_s;
    for (k = 0; k < n_gm; k++) {
        v += sigma * sigma * gm_avar_unit(tau_s / tc[k]);
    }
    return v;
}

double sim_noise_adev(const struct sim_noise_axis *ax, double tau_s, double dt_s)
{
    const double v = sim_noise_avar(ax, tau_s, dt_s);
    return v < 0.0 ? v : sqrt(v);
}

void sim_noise_adis_gyro_axis(struct sim_noise_axis *ax)
{
    if (ax == NULL) {
        return;
    }
    memset(ax, 0, sizeof(*ax));
    ax->white = SIM_NOISE_ADIS_GYRO_ARW;
    ax->bias_instability = SIM_NOISE_ADIS_GYRO_BI;
    ax->bi_tc_min_s = SIM_NOISE_ADIS_GYRO_TC_MIN;
    ax->bi_tc_max_s = SIM_NOISE_ADIS_GYRO_TC_MAX;
    ax->rrw = SIM_NOISE_ADIS_GYRO_RRW;
}

void sim_noise_separated_axis(struct sim_noise_axis *ax)
{
    if (ax == NULL) {
        return;
    }
    memset(ax, 0, sizeof(*ax));
    ax->white = SIM_NOISE_SEP_WHITE;
    ax->bias_instability = SIM_NOISE_SEP_BI;
    ax->bi_tc_min_s = SIM_NOISE_SEP_TC_MIN;
    ax->bi_tc_max_s = SIM_NOISE_SEP_TC_MAX;
    ax->rrw = SIM_NOISE_SEP_RRW;
}

void sim_noise_adis_accel_axis(struct sim_noise_axis *ax)
{
    if (ax == NULL) {
        return;
    }
    memset(ax, 0, sizeof(*ax));
    ax->white = SIM_NOISE_ADIS_ACCEL_WHITE;
}

void sim_noise_adis_cfg(struct sim_noise_cfg *cfg, uint64_t seed)
{
    unsigned a;
    if (cfg == NULL) {
        return;
    }
    memset(cfg, 0, sizeof(*cfg));
    for (a = 0; a < 3u; a++) {
        sim_noise_adis_gyro_axis(&cfg->ch[SIM_NOISE_GYRO(a)]);
        sim_noise_adis_accel_axis(&cfg->ch[SIM_NOISE_ACCEL(a)]);
    }
    cfg->seed = seed;
}
