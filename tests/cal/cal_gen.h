/*
 * cal_gen.h - deterministic generators of the tests/cal firmware tests: integer only (no libm,
 * no floating point), so the bit-identity test that uses only this header also runs on
 * rv32imac. Random temperature models and records within the calrec limits.
 */
#ifndef INCLINO_CAL_GEN_H
#define INCLINO_CAL_GEN_H

#include <stdint.h>
#include <string.h>

#include "inclino/cal.h"
#include "unit.h"

/* Uniform integer in [lo, hi] (hi - lo < 2^32). */
static inline int64_t calt_range(uint32_t *s, int64_t lo, int64_t hi)
{
    const uint64_t span = (uint64_t)(hi - lo) + 1u;
    const uint64_t r = ((uint64_t)unit_rand32(s) << 32) | unit_rand32(s);
    return lo + (int64_t)(r % span);
}

/* A random model of `kind` within the limits; ylim is the y-format limit (raw). Every fourth
 * model puts its y parameters at +-ylim to reach the worst rounding propagation. */
static inline void random_model(uint32_t *s, int32_t kind, int32_t ylim, unsigned k,
                                struct calrec_tmodel *m)
{
    unsigned i;
    const int extreme = (k % 4u) == 0u;
    memset(m, 0, sizeof *m);
    m->kind = kind;
    for (i = 0; i < CALREC_TM_PARAMS; i++) {
        m->p[i] = extreme ? ((unit_rand32(s) & 1u) ? ylim : -ylim)
                          : (int32_t)calt_range(s, -ylim, ylim);
    }
    switch (kind) {
    case CALREC_TM_LINEAR:
    case CALREC_TM_PARABOLA:
    case CALREC_TM_LORENTZ_CUBIC:
        m->t_ref = (int32_t)calt_range(s, CALREC_LIM_T_MIN, CALREC_LIM_T_MAX);
        m->t_span = (int32_t)calt_range(s, CALREC_LIM_SPAN_MIN,
                                        (k % 3u) ? 60 * 65536 : CALREC_LIM_SPAN_MAX);
        break;
    case CALREC_TM_PWL:
        m->n = (int32_t)calt_range(s, 2, CALREC_TM_PARAMS);
        {
            const int32_t most = (CALREC_LIM_T_MAX - CALREC_LIM_T_MIN) / (m->n - 1);
            m->t_span = (int32_t)calt_range(
                s, CALREC_LIM_SPAN_MIN, most < CALREC_LIM_SPAN_MAX ? most : CALREC_LIM_SPAN_MAX);
        }
        m->t_ref = (int32_t)calt_range(s, CALREC_LIM_T_MIN,
                                       CALREC_LIM_T_MAX - (m->n - 1) * m->t_span);
        break;
    default: break;
    }
    if (kind == CALREC_TM_LORENTZ || kind == CALREC_TM_LORENTZ_CUBIC) {
        m->p[2] = (int32_t)calt_range(s, CALREC_LIM_SPAN_MIN,
                                      (k % 2u) ? 80 * 65536 : CALREC_LIM_WIDTH_MAX);
        m->p[3] = (int32_t)calt_range(s, CALREC_LIM_T_MIN, CALREC_LIM_T_MAX);
    }
    /* Unused words 0, as a checked record has them. */
    {
        unsigned used = kind == CALREC_TM_LINEAR          ? 2u
                        : kind == CALREC_TM_PARABOLA      ? 3u
                        : kind == CALREC_TM_LORENTZ       ? 4u
                        : kind == CALREC_TM_LORENTZ_CUBIC ? 7u
                                                          : (unsigned)m->n;
        for (i = used; i < CALREC_TM_PARAMS; i++) {
            m->p[i] = 0;
        }
    }
}

/* A random valid record: every coefficient within the calrec limits; `extreme` puts the
 * nonlinearity and cross-axis terms at their limits, otherwise typical magnitudes. */
static inline void random_record(uint32_t *s, int extreme, unsigned k, struct calrec *r)
{
    static const int32_t kinds[6] = {CALREC_TM_NONE,    CALREC_TM_LINEAR, CALREC_TM_PARABOLA,
                                     CALREC_TM_LORENTZ, CALREC_TM_PWL,    CALREC_TM_LORENTZ_CUBIC};
    unsigned a, j;
    calrec_set_default(r);
    r->binding.family = CALREC_FAMILY_ADIS163XX;
    r->binding.product = 16364;
    for (a = 0; a < 3u; a++) {
        struct calrec_tmodel tb, ts;
        r->acc_offset[a] = (int32_t)calt_range(s, -3277, 3277);          /* +-50 mg */
        r->acc_gain[a] = (int32_t)calt_range(s, 1020054733, 1127428915); /* 0.95..1.05 */
        for (j = 0; j < 3u; j++) {
            r->acc_misalign[a][j] =
                a == j ? (int32_t)calt_range(s, 1052266987, 1095216660)
                       : (int32_t)(extreme ? ((unit_rand32(s) & 1u) ? CALREC_LIM_MISALIGN_OFFDIAG
                                                                    : -CALREC_LIM_MISALIGN_OFFDIAG)
                                           : calt_range(s, -21474836, 21474836)); /* 0.02 */
        }
        if (extreme) {
            r->acc_nonlin[a][0] = (int32_t)calt_range(s, -CALREC_LIM_NONLIN_C01,
                                                      CALREC_LIM_NONLIN_C01);
            r->acc_nonlin[a][1] = (int32_t)calt_range(s, -CALREC_LIM_NONLIN_C01,
                                                      CALREC_LIM_NONLIN_C01);
            r->acc_nonlin[a][2] = (unit_rand32(s) & 1u) ? CALREC_LIM_NONLIN_C23
                                                        : -CALREC_LIM_NONLIN_C23;
            r->acc_nonlin[a][3] = (unit_rand32(s) & 1u) ? CALREC_LIM_NONLIN_C23
                                                        : -CALREC_LIM_NONLIN_C23;
        } else {
            r->acc_nonlin[a][2] = (int32_t)calt_range(s, -53687091, 53687091); /* 0.05 */
            r->acc_nonlin[a][3] = (int32_t)calt_range(s, -53687091, 53687091);
        }
        /* Temperature models: bias up to +-20 mg, scale deviation up to +-1 %, every kind. */
        random_model(s, kinds[(k + a) % 6u], 1311, k, &tb);
        random_model(s, kinds[(k + a + 3u) % 6u], 10737418, k + 1u, &ts);
        r->acc_tbias[a] = tb;
        r->acc_tscale[a] = ts;
        r->gyro_offset[a] = (int32_t)calt_range(s, -CALREC_LIM_GYRO_OFFSET, CALREC_LIM_GYRO_OFFSET);
        r->gyro_scale[a] = (int32_t)calt_range(s, CALREC_LIM_GAIN_MIN, CALREC_LIM_GAIN_MAX);
    }
    r->valid = true;
}

#endif
