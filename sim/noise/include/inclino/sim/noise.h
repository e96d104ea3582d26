/*
 * sim/noise.h - seeded, reproducible error models for the simulated inertial parts (module
 * inclino_sim_noise, prefix sim_noise_), and the analytic Allan variance of what they produce.
 *
 * One struct sim_noise is one part's sensing-element error model. It plugs into any model that
 * takes a struct sim_error_model (sim/inertial.h) through sim_noise_hook(). Per channel (three
 * gyro axes in deg/s, three accelerometer axes in g) it adds to the true input:
 *
 *   constant bias      b0                                           (unit)
 *   temperature drift  tc * (T - 25 degC)                           (unit per degC)
 *   white noise        N / sqrt(dt) * w[k]      Allan: N / sqrt(tau) (N in unit/sqrt(Hz); for a
 *                                               gyro in deg/s/sqrt(Hz) = deg/sqrt(s), the ARW)
 *   bias instability   a sum of first-order Gauss-Markov processes with equal variance and
 *                      correlation times spread geometrically (3 per decade) over
 *                      [bi_tc_min_s, bi_tc_max_s]: a flicker (1/f) approximation whose Allan
 *                      deviation is flat at 0.664 * B (the IEEE 952 bias-instability floor)
 *                      within +-3 % for 10 * bi_tc_min_s <= tau <= bi_tc_max_s / 4; it rolls
 *                      off outside (-17 % at 2 * bi_tc_min_s)
 *   rate random walk   x[k+1] = x[k] + K * sqrt(dt) * w[k]  Allan: K * sqrt(tau / 3)
 *                      (K in unit/sqrt(s); starts at 0)
 *   quantisation       the sum is rounded to a multiple of `quantum` (0: off). This is the
 *                      sensing element's own step; the part model still quantises its output
 *                      registers itself (e.g. 0.05 deg/s per LSB on ADIS1636x/1640x).
 *
 * The Gauss-Markov states start from their stationary distribution (the part has been powered
 * for a while: the slow components are part of the unknown bias the calibration has to find).
 * All randomness comes from one struct sim_rng seeded from cfg.seed: the same seed and the same
 * sequence of calls give bit-identical outputs on every host and under QEMU.
 *
 * Units are doubles: this is simulation code; the firmware never uses floating point.
 */
#ifndef INCLINO_SIM_NOISE_H
#define INCLINO_SIM_NOISE_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/sim/inertial.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SIM_NOISE_GM_MAX 16u  /* Gauss-Markov components per channel (3 per decade) */
#define SIM_NOISE_CHANNELS 6u /* 0..2 gyro x, y, z; 3..5 accel x, y, z */
#define SIM_NOISE_GYRO(axis) (axis)
#define SIM_NOISE_ACCEL(axis) (3u + (axis))

/* Allan deviation floor of flicker rate noise: sqrt(2 ln 2 / pi) * B (IEEE Std 952, annex C). */
#define SIM_NOISE_BI_FLOOR 0.664

/* Error terms of one channel. All fields >= 0 except bias and temp_coeff (any sign); zero turns
 * a term off. Units: the channel's unit u (deg/s for a gyro, g for an accelerometer). */
struct sim_noise_axis {
    double bias;             /* constant bias, u */
    double temp_coeff;       /* bias drift, u per degC away from 25 degC (input temp_c) */
    double white;            /* N: white noise density, u/sqrt(Hz) */
    double bias_instability; /* B: u; correlated part's Allan floor = 0.664 B */
    double bi_tc_min_s;      /* shortest Gauss-Markov correlation time, s (> 0 when B > 0) */
    double bi_tc_max_s;      /* longest, s; bi_tc_min_s < bi_tc_max_s <= 1e5 * bi_tc_min_s */
    double rrw;              /* K: rate random walk, u/sqrt(s) */
    double quantum;          /* element quantisation step, u (0: none) */
};

struct sim_noise_cfg {
    struct sim_noise_axis ch[SIM_NOISE_CHANNELS]; /* see SIM_NOISE_GYRO / SIM_NOISE_ACCEL */
    double temp_white_c; /* white noise on the temperature input, degC rms per sample */
    uint64_t seed;
};

/* Internal state of one channel (read-only for callers). */
struct sim_noise_chan {
    unsigned n_gm;                  /* Gauss-Markov components in use */
    double gm_tc[SIM_NOISE_GM_MAX]; /* correlation times, s */
    double gm_sigma;                /* stationary standard deviation of each component */
    double gm_x[SIM_NOISE_GM_MAX];  /* states */
    double gm_a[SIM_NOISE_GM_MAX];  /* exp(-dt / tc) for the cached dt */
    double gm_w[SIM_NOISE_GM_MAX];  /* gm_sigma * sqrt(1 - a^2) */
    double rrw_x;                   /* rate random walk state */
    double white_sd;                /* N / sqrt(dt) */
    double rrw_sd;                  /* K * sqrt(dt) */
    double last_bias;               /* correlated bias of the last sample (no white noise) */
};

struct sim_noise {
    struct sim_noise_cfg cfg;
    struct sim_rng rng;
    struct sim_noise_chan ch[SIM_NOISE_CHANNELS];
    double dt_s;  /* interval the coefficients are cached for (0: none) */
    double spare; /* second deviate of the last polar-method pair */
    bool spare_valid;
    uint64_t samples; /* apply() calls so far */
};

/*
 * Validate cfg and initialise *n (Gauss-Markov states drawn from the stationary distribution).
 * Returns 0, INC_ERR_NULL, or INC_ERR_INVAL (a negative or non-finite density, B > 0 with a bad
 * correlation-time range, a band wider than SIM_NOISE_GM_MAX components can cover); *n is then
 * zeroed and unusable.
 */
int sim_noise_init(struct sim_noise *n, const struct sim_noise_cfg *cfg);

/* The hook to install in a part model (ctx = n). */
struct sim_error_model sim_noise_hook(struct sim_noise *n);

/* The hook's function: out = in + errors (gyro and accel channels, temperature noise);
 * supply_v is passed through. dt_s > 0 is the part's internal sample interval; t_ns unused. */
void sim_noise_apply(void *ctx, const struct sim_inertial_input *in, struct sim_inertial_input *out,
                     uint64_t t_ns, double dt_s);

/* One channel only, for tools that need a single stream fast: returns truth + errors for the
 * next sample (advances only this channel's states; the rng is shared). temp_c as for apply. */
double sim_noise_step(struct sim_noise *n, unsigned chan, double truth, double temp_c, double dt_s);

/* The correlated bias of channel chan at its last sample: constant + temperature term +
 * Gauss-Markov sum + random walk, without white noise and quantisation. This is the "true bias"
 * a calibration tries to estimate. 0 for a bad channel or before the first sample. */
double sim_noise_bias_now(const struct sim_noise *n, unsigned chan);

/*
 * Analytic Allan variance (u^2) of one channel's configuration at averaging time tau_s, for
 * samples at dt_s (quantisation is counted as white noise of variance quantum^2/12 per sample,
 * valid when the noise is much larger than the step). Continuous-time formulas:
 *   N^2 / tau  +  sigma^2 * sum_k f(tau / tc_k)  +  K^2 tau / 3  +  (q^2/12) dt / tau,
 *   f(x) = (2x - 3 + 4 e^-x - e^-2x) / x^2   (first-order Gauss-Markov, unit variance).
 * Returns a negative value for a bad configuration or tau_s <= 0.
 */
double sim_noise_avar(const struct sim_noise_axis *ax, double tau_s, double dt_s);

/* sqrt of sim_noise_avar, or a negative value on error. */
double sim_noise_adev(const struct sim_noise_axis *ax, double tau_s, double dt_s);

/* The Gauss-Markov layout the model uses for ax: component count, correlation times (s) and the
 * common standard deviation. Returns 0 or INC_ERR_INVAL / INC_ERR_NULL. With B == 0, *n_gm = 0. */
int sim_noise_gm_layout(const struct sim_noise_axis *ax, unsigned *n_gm, double *tc, double *sigma);

/*
 * ADIS1636x/1640x presets (docs/noise-and-allan.md). The gyro reproduces the Allan curve behind
 * [ADI-IMU-QS] (figure 6): 0.080 deg/s at 0.15 s, 0.0074 deg/s at 30 s (seed: about 0.008),
 * 0.0061 deg/s at 100 s and a flat minimum of 0.0061 deg/s at 100..150 s (seed: about 0.006
 * near 100 s):
 *   N = 0.031 deg/s/sqrt(Hz) (1.86 deg/sqrt(h)); B = 0.0068 deg/s, tc 0.5..2000 s;
 *   K = 0.00045 deg/s/sqrt(s); bias and temp_coeff 0 (the caller sets them per test).
 * Unfiltered noise at 819.2 SPS: 0.031 * sqrt(819.2) = 0.89 deg/s rms, within [ADI-IMU-QS]'s "less
 * than 1 deg/s rms".
 */
#define SIM_NOISE_ADIS_GYRO_ARW 0.031     /* deg/s/sqrt(Hz) */
#define SIM_NOISE_ADIS_GYRO_BI 0.0068     /* deg/s */
#define SIM_NOISE_ADIS_GYRO_TC_MIN 0.5    /* s */
#define SIM_NOISE_ADIS_GYRO_TC_MAX 2000.0 /* s */
#define SIM_NOISE_ADIS_GYRO_RRW 0.00045   /* deg/s/sqrt(s) */
/* Accelerometer white noise 0.2 mg/sqrt(Hz) (about 5.7 mg rms at 819.2 SPS). Assumed, not from
 * the seeds: docs/unconfirmed-facts.md. */
#define SIM_NOISE_ADIS_ACCEL_WHITE 0.0002 /* g/sqrt(Hz) */

/*
 * A part whose terms are well apart on the Allan curve, for checking read-offs (tests/allan):
 * N = 0.03 u/sqrt(Hz), B = 0.005 u (floor 0.00332 u), tc 10..20000 s, K = 2e-5 u/sqrt(s).
 * At tau = 1 s white noise is 99.9 % of the deviation; at the minimum (about 2600 s) the floor
 * is 97 % of it, so minimum / 0.664 reads B about 3 % high.
 */
#define SIM_NOISE_SEP_WHITE 0.03
#define SIM_NOISE_SEP_BI 0.005
#define SIM_NOISE_SEP_TC_MIN 10.0
#define SIM_NOISE_SEP_TC_MAX 20000.0
#define SIM_NOISE_SEP_RRW 2e-5
void sim_noise_separated_axis(struct sim_noise_axis *ax);

void sim_noise_adis_gyro_axis(struct sim_noise_axis *ax);
void sim_noise_adis_accel_axis(struct sim_noise_axis *ax);
/* All six channels with the presets above, temperature noise 0, the given seed. */
void sim_noise_adis_cfg(struct sim_noise_cfg *cfg, uint64_t seed);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_SIM_NOISE_H */
