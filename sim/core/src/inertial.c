/* inertial.c - see sim/inertial.h. */
#include "inclino/sim/inertial.h"

#include <math.h>
#include <stddef.h>

void sim_inertial_at_rest(struct sim_inertial_input *in)
{
    if (in == NULL) {
        return;
    }
    in->rate_dps[0] = in->rate_dps[1] = in->rate_dps[2] = 0.0;
    in->accel_g[0] = in->accel_g[1] = 0.0;
    in->accel_g[2] = 1.0;
    in->temp_c = 25.0;
    in->supply_v = 5.0;
}

int32_t sim_quantise(double value, double lsb, unsigned bits, bool *saturated)
{
    const double hi = (double)((1L << (bits - 1u)) - 1L);
    const double lo = -(double)(1L << (bits - 1u));
    double c;
    bool sat = false;
    if (bits < 2u || bits > 31u || !(lsb > 0.0) || isnan(value)) {
        if (saturated != NULL) {
            *saturated = true;
        }
        return 0;
    }
    c = value / lsb;
    c = c < 0.0 ? -floor(-c + 0.5) : floor(c + 0.5);
    if (c > hi) {
        c = hi;
        sat = true;
    } else if (c < lo) {
        c = lo;
        sat = true;
    }
    if (saturated != NULL) {
        *saturated = sat;
    }
    return (int32_t)c;
}

uint32_t sim_quantise_unsigned(double value, double lsb, unsigned bits, bool *saturated)
{
    const double hi = (double)((1UL << bits) - 1UL);
    double c;
    bool sat = false;
    if (bits < 1u || bits > 31u || !(lsb > 0.0) || isnan(value)) {
        if (saturated != NULL) {
            *saturated = true;
        }
        return 0;
    }
    c = floor(value / lsb + 0.5);
    if (c > hi) {
        c = hi;
        sat = true;
    } else if (c < 0.0) {
        c = 0.0;
        sat = true;
    }
    if (saturated != NULL) {
        *saturated = sat;
    }
    return (uint32_t)c;
}

uint16_t sim_twos(int32_t count, unsigned bits)
{
    return (uint16_t)((uint32_t)count & ((1UL << bits) - 1UL));
}

static uint64_t splitmix64(uint64_t *x)
{
    uint64_t z = (*x += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

void sim_rng_seed(struct sim_rng *r, uint64_t seed)
{
    uint64_t a, b;
    if (r == NULL) {
        return;
    }
    a = splitmix64(&seed);
    b = splitmix64(&seed);
    r->s[0] = (uint32_t)a;
    r->s[1] = (uint32_t)(a >> 32);
    r->s[2] = (uint32_t)b;
    r->s[3] = (uint32_t)(b >> 32);
    if ((r->s[0] | r->s[1] | r->s[2] | r->s[3]) == 0u) {
        r->s[0] = 1u;
    }
}

static uint32_t rotl(uint32_t x, int k)
{
    return (x << k) | (x >> (32 - k));
}

uint32_t sim_rng_u32(struct sim_rng *r)
{
    const uint32_t result = rotl(r->s[1] * 5u, 7) * 9u;
    const uint32_t t = r->s[1] << 9;
    r->s[2] ^= r->s[0];
    r->s[3] ^= r->s[1];
    r->s[1] ^= r->s[2];
    r->s[0] ^= r->s[3];
    r->s[2] ^= t;
    r->s[3] = rotl(r->s[3], 11);
    return result;
}

double sim_rng_uniform(struct sim_rng *r)
{
    /* 53 random bits from two draws. */
    uint64_t hi = sim_rng_u32(r) >> 5, lo = sim_rng_u32(r) >> 6;
    return (double)(hi * 67108864ull + lo) * (1.0 / 9007199254740992.0);
}

double sim_rng_gauss(struct sim_rng *r)
{
    double u1 = sim_rng_uniform(r), u2 = sim_rng_uniform(r);
    if (u1 < 1e-300) {
        u1 = 1e-300;
    }
    return sqrt(-2.0 * log(u1)) * cos(6.283185307179586476925 * u2);
}
