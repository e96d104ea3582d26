/*
 * sim/inertial.h - what every simulated inertial part shares: its physical inputs, the hooks
 * that produce them (physics) and distort them (error model), and quantisation to register
 * counts.
 *
 * A model samples at its own internal rate in virtual time. At each internal sample it:
 *   1. asks the physics hook for the true inputs at that instant (angular rate, specific force,
 *      temperature, supply); with no hook, the static `input` of the model is used;
 *   2. passes them through the error-model hook (bias, scale factor, noise, temperature drift,
 *      misalignment...), if one is installed; with none, the part is ideal;
 *   3. runs its own digital path (the ADIS Bartlett filter, ...), then scales, saturates at the
 *      part's range and quantises to its output format (sim_quantise below).
 * Simulation code may use double; the firmware never does.
 */
#ifndef INCLINO_SIM_INERTIAL_H
#define INCLINO_SIM_INERTIAL_H

#include <stdbool.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* True physical inputs of a part at one instant (sensor frame). */
struct sim_inertial_input {
    double rate_dps[3]; /* angular rate about x, y, z in deg/s */
    double accel_g[3];  /* specific force along x, y, z in g (at rest, level: z = +1 g) */
    double temp_c;      /* die temperature in deg C */
    double supply_v;    /* supply voltage in V */
};

/* Physics hook: fill *in with the true inputs at virtual time t_ns. */
struct sim_physics {
    void (*sample)(void *ctx, uint64_t t_ns, struct sim_inertial_input *in);
    void *ctx;
};

/*
 * Error-model hook: called once per internal sample with the true inputs; writes what the
 * sensing element reports (same units) to *out. dt_s is the internal sample period, for noise
 * densities and random walks. It must be deterministic for a given seed (no global RNG).
 */
struct sim_error_model {
    void (*apply)(void *ctx, const struct sim_inertial_input *in, struct sim_inertial_input *out,
                  uint64_t t_ns, double dt_s);
    void *ctx;
};

/* Fill *in with a part at rest, level (z up), 25 deg C, 5.0 V. */
void sim_inertial_at_rest(struct sim_inertial_input *in);

/*
 * value / lsb rounded to the nearest count (half away from zero) and saturated to a `bits`-wide
 * two's complement range [-2^(bits-1), 2^(bits-1) - 1]. *saturated (may be NULL) tells whether
 * the range was exceeded. bits in 2..31.
 */
int32_t sim_quantise(double value, double lsb, unsigned bits, bool *saturated);

/* The same for an unsigned (offset binary) output: [0, 2^bits - 1]. */
uint32_t sim_quantise_unsigned(double value, double lsb, unsigned bits, bool *saturated);

/* Encode a signed count into `bits` of a register (two's complement, upper bits clear). */
uint16_t sim_twos(int32_t count, unsigned bits);

/*
 * A small deterministic PRNG for models and error models (xoshiro128** style state, seeded by
 * splitmix64), so runs are reproducible on every host and under QEMU.
 */
struct sim_rng {
    uint32_t s[4];
};
void sim_rng_seed(struct sim_rng *r, uint64_t seed);
uint32_t sim_rng_u32(struct sim_rng *r);
double sim_rng_uniform(struct sim_rng *r); /* [0, 1) */
double sim_rng_gauss(struct sim_rng *r);   /* standard normal (Box-Muller, one value per call) */

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_SIM_INERTIAL_H */
