/*
 * cal_test.h - helpers of the tests/cal firmware tests: sweep density (full on the host,
 * reduced under QEMU and the sanitizers), a deterministic generator, worst-error bookkeeping
 * and integer-only printing (newlib-nano's printf has no %f).
 */
#ifndef INCLINO_CAL_TEST_H
#define INCLINO_CAL_TEST_H

#include <math.h>
#include <stdint.h>
#include <stdio.h>

#include "unit.h"
#include "cal_gen.h"

/* CALT_DENSITY(full, reduced): the dense sweep on the host, a reduced one under QEMU (soft
 * float) and under ASan/UBSan (unit.h's UNIT_SIZE). */
#define CALT_DENSITY(full, reduced) UNIT_SIZE(full, reduced)

#define CALT_Q16 65536.0
#define CALT_Q30 1073741824.0

struct calt_err {
    double max;
    unsigned long count;
};

static inline void calt_err_add(struct calt_err *e, double err)
{
    err = fabs(err);
    e->count++;
    if (err > e->max) {
        e->max = err;
    }
}

/* "MEASURED <name>: max |error| = <x.xxx> LSB over <n> points (bound <b>)" */
static inline void calt_report(const char *name, const struct calt_err *e, double bound)
{
    long long m = (long long)(e->max * 1000.0 + 0.5), b = (long long)(bound * 1000.0 + 0.5);
    printf("MEASURED %s: max |error| = %lld.%03lld LSB over %lu points (bound %lld.%03lld)\n", name,
           m / 1000, m % 1000, e->count, b / 1000, b % 1000);
}

#endif
