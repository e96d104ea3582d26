/*
 * cal_ref.h - double-precision references of the firmware calibration (tests only): the
 * temperature models with the record's semantics, the whole correction chain, and random
 * models/records within the calrec limits.
 */
#ifndef INCLINO_CAL_REF_H
#define INCLINO_CAL_REF_H

#include <math.h>
#include <string.h>

#include "inclino/cal.h"
#include "cal_test.h"

#define T_LO (-100.0 * CALT_Q16)
#define T_HI (200.0 * CALT_Q16)

static inline double clampd(double v, double lo, double hi)
{
    return v < lo ? lo : (v > hi ? hi : v);
}

static inline double lorentz(double t, double w, double tc)
{
    const double r = 2.0 * (t - tc) / w;
    return 1.0 / (1.0 + r * r);
}

/* The model in double, on raw words (T and parameters as stored), y in raw LSB of its format. */
static inline double ref_eval(const struct calrec_tmodel *m, int32_t t_raw)
{
    const double t = clampd((double)t_raw, T_LO, T_HI);
    double th, u, y = 0.0;
    switch (m->kind) {
    case CALREC_TM_LINEAR:
    case CALREC_TM_PARABOLA:
    case CALREC_TM_LORENTZ_CUBIC:
        th = clampd(t, (double)m->t_ref - m->t_span, (double)m->t_ref + m->t_span);
        u = (th - m->t_ref) / m->t_span;
        if (m->kind == CALREC_TM_LINEAR) {
            y = m->p[0] + m->p[1] * u;
        } else if (m->kind == CALREC_TM_PARABOLA) {
            y = m->p[0] + m->p[1] * u + m->p[2] * u * u;
        } else {
            y = m->p[0] + m->p[1] * lorentz(th, m->p[2], m->p[3]) + m->p[4] * u + m->p[5] * u * u +
                m->p[6] * u * u * u;
        }
        break;
    case CALREC_TM_LORENTZ:
        y = m->p[0] + m->p[1] * lorentz(t, m->p[2], m->p[3]);
        break;
    case CALREC_TM_PWL: {
        const double last = (double)m->t_ref + (double)(m->n - 1) * m->t_span;
        double s;
        int i;
        th = clampd(t, m->t_ref, last);
        s = (th - m->t_ref) / m->t_span;
        i = (int)floor(s);
        if (i > m->n - 2) {
            i = m->n - 2;
        }
        y = m->p[i] + (double)(m->p[i + 1] - m->p[i]) * (s - i);
        break;
    }
    default:
        break;
    }
    return y;
}

/* A random model of `kind` within the limits; ylim is the y-format limit (raw). Every fourth
 * model puts its y parameters at +-ylim to reach the worst rounding propagation. */
static inline void random_model(uint32_t *s, int32_t kind, int32_t ylim, unsigned k, struct calrec_tmodel *m)
{
    unsigned i;
    const int extreme = (k % 4u) == 0u;
    memset(m, 0, sizeof *m);
    m->kind = kind;
    for (i = 0; i < CALREC_TM_PARAMS; i++) {
        m->p[i] = extreme ? ((calt_rand(s) & 1u) ? ylim : -ylim) : (int32_t)calt_range(s, -ylim, ylim);
    }
    switch (kind) {
    case CALREC_TM_LINEAR:
    case CALREC_TM_PARABOLA:
    case CALREC_TM_LORENTZ_CUBIC:
        m->t_ref = (int32_t)calt_range(s, CALREC_LIM_T_MIN, CALREC_LIM_T_MAX);
        m->t_span = (int32_t)calt_range(s, CALREC_LIM_SPAN_MIN, (k % 3u) ? 60 * 65536 : CALREC_LIM_SPAN_MAX);
        break;
    case CALREC_TM_PWL:
        m->n = (int32_t)calt_range(s, 2, CALREC_TM_PARAMS);
        {
            const int32_t most = (CALREC_LIM_T_MAX - CALREC_LIM_T_MIN) / (m->n - 1);
            m->t_span = (int32_t)calt_range(s, CALREC_LIM_SPAN_MIN, most < CALREC_LIM_SPAN_MAX ? most : CALREC_LIM_SPAN_MAX);
        }
        m->t_ref = (int32_t)calt_range(s, CALREC_LIM_T_MIN, CALREC_LIM_T_MAX - (m->n - 1) * m->t_span);
        break;
    default:
        break;
    }
    if (kind == CALREC_TM_LORENTZ || kind == CALREC_TM_LORENTZ_CUBIC) {
        m->p[2] = (int32_t)calt_range(s, CALREC_LIM_SPAN_MIN, (k % 2u) ? 80 * 65536 : CALREC_LIM_WIDTH_MAX);
        m->p[3] = (int32_t)calt_range(s, CALREC_LIM_T_MIN, CALREC_LIM_T_MAX);
    }
    /* Unused words 0, as a checked record has them. */
    {
        unsigned used = kind == CALREC_TM_LINEAR ? 2u : kind == CALREC_TM_PARABOLA ? 3u :
                        kind == CALREC_TM_LORENTZ ? 4u : kind == CALREC_TM_LORENTZ_CUBIC ? 7u :
                        (unsigned)m->n;
        for (i = used; i < CALREC_TM_PARAMS; i++) {
            m->p[i] = 0;
        }
    }
}

#endif
