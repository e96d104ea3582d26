/*
 * sim/calpart.h - a simulated inertial part with the errors that calibration removes, packaged as
 * a sim_error_model (sim/inertial.h) so it plugs into any device model, or is sampled directly
 * by the calibration-station simulator (tools/calstation).
 *
 * Accelerometer, per sensing element i (x, y, z), for the true specific force a (g):
 *     x_i   = sum_j axis[i][j] * a_j                     misalignment / cross-axis (row i = the
 *                                                         direction element i senses)
 *     h_i   = x_i + nl2_i * x_i^2 + nl3_i * x_i^3         element nonlinearity (g)
 *     out_i = bias_i(T, m) + scale_i(T, m) * h_i + noise  (g; what the part reports, before the
 *                                                         device model quantises it)
 * Gyro, per axis: out_i = gyro_bias_i + gyro_scale_i * rate_i + noise (deg/s).
 * The temperature is passed through unchanged (the device model quantises its own TEMP_OUT).
 *
 * Temperature curve (struct sim_calpart_tcurve), after [TEMP-LORENTZ]: a Lorentz-like peak that is
 * deliberately NOT exactly any model the station fits:
 *     y(T, m) = y0 + height / (1 + ((T - centre) / (width / 2))^2) + lin * u + cubic * u^3
 *               + hyst * m,            u = (T - SIM_CALPART_T_MID) / SIM_CALPART_T_HALF
 * m is the heating/cooling hysteresis state in [-1, 1]: it moves by 2 * dT / hyst_travel_c with
 * every temperature change and is clamped, so after heating by hyst_travel_c degC or more it is
 * +1 (heating branch), after cooling by as much -1. It starts at 0.
 *
 * Deterministic: the noise comes from the part's own sim_rng, seeded at init.
 */
#ifndef INCLINO_SIM_CALPART_H
#define INCLINO_SIM_CALPART_H

#include <stdint.h>

#include "inclino/sim/inertial.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SIM_CALPART_T_MIN (-20.0) /* [TEMP-LORENTZ]'s temperature range, degC */
#define SIM_CALPART_T_MAX 60.0
#define SIM_CALPART_T_MID 20.0 /* centre and half span of that range: u = -1..1 */
#define SIM_CALPART_T_HALF 40.0

/* [TEMP-LORENTZ]'s magnitudes that sim_calpart_normalise() imposes on a part. */
#define SIM_CALPART_PAPER_BIAS_SPREAD_G 0.014   /* Bmax - Bmin over the 10 degC points */
#define SIM_CALPART_PAPER_SCALE_PPM_PER_C 151.6 /* (Kmax-Kmin)/Kmean * 1e6 / 80 */

struct sim_calpart_tcurve {
    double y0;       /* baseline (g for bias; g/g for scale factor) */
    double height;   /* Lorentz peak height above y0 at T = centre */
    double centre_c; /* Lorentz centre, degC (may lie outside the measured range) */
    double width_c;  /* Lorentz full width at half maximum, degC (> 0) */
    double lin;      /* coefficient of u */
    double cubic;    /* coefficient of u^3: the "small cubic term" */
    double hyst;     /* hysteresis half amplitude: heating branch +hyst, cooling branch -hyst */
};

struct sim_calpart_params {
    struct sim_calpart_tcurve acc_bias[3];  /* accelerometer bias, g */
    struct sim_calpart_tcurve acc_scale[3]; /* accelerometer scale factor, g/g (nominal 1) */
    double acc_axis[3][3];                  /* misalignment rows (identity = ideal) */
    double acc_nl2[3];                      /* quadratic nonlinearity, 1/g */
    double acc_nl3[3];                      /* cubic nonlinearity, 1/g^2 */
    double acc_noise_g;                     /* white noise rms per sample, g */
    double gyro_bias_dps[3];                /* gyro bias, deg/s */
    double gyro_scale[3];                   /* gyro scale factor (nominal 1) */
    double gyro_noise_dps;                  /* white noise rms per sample, deg/s */
    double hyst_travel_c;                   /* temperature travel that switches branches, > 0 */
};

struct sim_calpart {
    struct sim_calpart_params p;
    struct sim_rng rng;
    double m;      /* hysteresis state, [-1, 1] */
    double last_t; /* temperature of the previous sample */
    int have_last;
};

/* y(T, m) of one curve (see the top of this file). */
double sim_calpart_tcurve_eval(const struct sim_calpart_tcurve *c, double t_c, double m);

/*
 * [TEMP-LORENTZ]'s metrics of the hysteresis-free curves (m = 0) at the points -20, -10, ..., 60 degC:
 * bias spread max - min (g) of axis `axis`, and scale-factor drift (Kmax - Kmin) / Kmean * 1e6 /
 * 80 (ppm/degC).
 */
double sim_calpart_bias_spread(const struct sim_calpart_params *p, int axis);
double sim_calpart_scale_ppm_per_c(const struct sim_calpart_params *p, int axis);

/*
 * Scale the temperature-dependent terms (height, lin, cubic; not y0 or hyst) of every axis so
 * that the bias spread is SIM_CALPART_PAPER_BIAS_SPREAD_G and the scale-factor drift
 * SIM_CALPART_PAPER_SCALE_PPM_PER_C exactly. Curves with no temperature term are left alone.
 */
void sim_calpart_normalise(struct sim_calpart_params *p);

/*
 * Part "A": hand-shaped so that its fits land near [TEMP-LORENTZ]'s figures (a falling Lorentz tail
 * with its peak below the range, a small cubic term and +-0.1 mg / +-10 ppm hysteresis),
 * normalised to the paper's magnitudes. Also typical offsets, gains, misalignment (about
 * 0.5 deg), a 10 mg nonlinearity at 0.5 g ([ADI-EPB]'s budget figure), 3 mg noise.
 */
void sim_calpart_paper(struct sim_calpart_params *p);

/*
 * A part with curves drawn from `seed` (centre, width, sign, linear and cubic shares, offsets,
 * gains, misalignment, nonlinearity), then normalised to the paper's magnitudes. Different seeds
 * give different curves; a zero seed is allowed.
 */
void sim_calpart_seeded(struct sim_calpart_params *p, uint64_t seed);

/* An ideal part: no error at all (identity). */
void sim_calpart_ideal(struct sim_calpart_params *p);

/* Copy the parameters, seed the noise, reset the hysteresis state (m = 0). */
void sim_calpart_init(struct sim_calpart *part, const struct sim_calpart_params *p,
                      uint64_t noise_seed);

/* Set the hysteresis state directly (clamped to [-1, 1]), e.g. to start on a branch. */
void sim_calpart_set_hysteresis(struct sim_calpart *part, double m);

/* The error-model hook (sim/inertial.h); ctx is a struct sim_calpart *. */
void sim_calpart_apply(void *ctx, const struct sim_inertial_input *in,
                       struct sim_inertial_input *out, uint64_t t_ns, double dt_s);

/* The hook as a struct ready for a device model. */
struct sim_error_model sim_calpart_error_model(struct sim_calpart *part);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_SIM_CALPART_H */
