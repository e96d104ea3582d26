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
    case CALREC_TM_LORENTZ: y = m->p[0] + m->p[1] * lorentz(t, m->p[2], m->p[3]); break;
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
    default: break;
    }
    return y;
}

#endif
