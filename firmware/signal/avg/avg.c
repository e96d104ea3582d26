/*
 * avg.c - averaging and decimation filters (see inclino/avg.h).
 *
 * Why exact sums and one rounding: [ADI-EPB] ("noise") averages to cut rms noise by sqrt(n), and
 * [ADI-IMU-QS]'s manual calibration averages 82 000 gyro samples; a filter that rounded at every
 * stage would add up to 0.5 LSB per stage of bias-free but correlated error, which at the 1/320
 * deg/s level of the processor-side correction is not negligible. Integer sums are exact, so a
 * running (add new, subtract old) sum never drifts, and the only error left is the final
 * rounding. Rounding is to nearest with ties away from zero, the convention of the fixed-point
 * core (docs/fixed-point.md), so the filters are odd functions: filter(-x) == -filter(x).
 */
#include "inclino/avg.h"

#include <stddef.h>

/* log2(v) when v is a power of two (v >= 1), else -1. */
static int log2_exact(uint64_t v)
{
    int s = 0;
    if (v == 0u || (v & (v - 1u)) != 0u) {
        return -1;
    }
    while (v > 1u) {
        v >>= 1;
        s++;
    }
    return s;
}

/* round(sum / div), ties away from zero; |sum| <= div * 2^31 so the result fits int32. */
static int32_t div_round(int64_t sum, uint32_t div, bool pow2, unsigned shift)
{
    if (pow2) {
        return (int32_t)fx_rshift_round64(sum, shift);
    }
    return fx_div64(sum, div); /* div >= 1 and the quotient fits: never saturates */
}

/* ---- Block ---------------------------------------------------------------------------------- */

int avg_block_init(struct avg_block *b, uint32_t n)
{
    if (b == NULL) {
        return INC_ERR_NULL;
    }
    b->n = 0;
    fx_sum_reset(&b->acc);
    if (n == 0u) {
        return INC_ERR_INVAL;
    }
    if (n > AVG_MAX_DIVISOR) {
        return INC_ERR_OVERFLOW;
    }
    b->n = n;
    return INC_OK;
}

int avg_block_push(struct avg_block *b, int32_t x, int32_t *mean, bool *done)
{
    int err;
    if (b == NULL || mean == NULL || done == NULL) {
        return INC_ERR_NULL;
    }
    *done = false;
    if (b->n == 0u) {
        return INC_ERR_STATE;
    }
    err = fx_sum_add(&b->acc, x); /* count < n <= 2^31 here: cannot overflow */
    if (err != INC_OK) {
        return err;
    }
    if (b->acc.count == b->n) {
        err = fx_sum_mean(&b->acc, mean);
        fx_sum_reset(&b->acc);
        *done = err == INC_OK;
    }
    return err;
}

int avg_block_partial(const struct avg_block *b, int32_t *mean, uint32_t *count)
{
    if (b == NULL || mean == NULL || count == NULL) {
        return INC_ERR_NULL;
    }
    if (b->n == 0u || b->acc.count == 0u) {
        return INC_ERR_STATE;
    }
    *count = b->acc.count;
    return fx_sum_mean(&b->acc, mean);
}

void avg_block_restart(struct avg_block *b)
{
    if (b != NULL) {
        fx_sum_reset(&b->acc);
    }
}

/* ---- Moving --------------------------------------------------------------------------------- */

int avg_moving_init(struct avg_moving *m, int32_t *line, uint32_t capacity, uint32_t w)
{
    int s;
    if (m == NULL) {
        return INC_ERR_NULL;
    }
    m->w = 0;
    m->line = NULL;
    if (line == NULL) {
        return INC_ERR_NULL;
    }
    if (w > AVG_MAX_DIVISOR) {
        return INC_ERR_OVERFLOW;
    }
    if (w == 0u || w > capacity) {
        return INC_ERR_INVAL;
    }
    s = log2_exact(w);
    m->line = line;
    m->w = w;
    m->pow2 = s >= 0;
    m->shift = s >= 0 ? (unsigned)s : 0u;
    avg_moving_restart(m);
    return INC_OK;
}

void avg_moving_restart(struct avg_moving *m)
{
    if (m != NULL) {
        m->head = 0;
        m->count = 0;
        m->sum = 0;
    }
}

int avg_moving_push(struct avg_moving *m, int32_t x, int32_t *mean, bool *full)
{
    if (m == NULL || mean == NULL || full == NULL) {
        return INC_ERR_NULL;
    }
    if (m->w == 0u) {
        return INC_ERR_STATE;
    }
    if (m->count == m->w) {
        m->sum -= m->line[m->head]; /* the sample leaving the window */
    } else {
        m->count++;
    }
    m->sum += x;
    m->line[m->head] = x;
    m->head = m->head + 1u == m->w ? 0u : m->head + 1u;
    *full = m->count == m->w;
    *mean = div_round(m->sum, m->count, *full && m->pow2, m->shift);
    return INC_OK;
}

/* ---- Cascade -------------------------------------------------------------------------------- */

int avg_cascade_init(struct avg_cascade *c, int64_t *lines, uint32_t capacity, uint32_t w,
                     unsigned passes)
{
    uint64_t div = 1u;
    unsigned k;
    int s;
    if (c == NULL) {
        return INC_ERR_NULL;
    }
    c->w = 0;
    c->lines = NULL;
    if (lines == NULL) {
        return INC_ERR_NULL;
    }
    if (w == 0u || passes == 0u || passes > AVG_CASCADE_MAX_PASSES) {
        return INC_ERR_INVAL;
    }
    for (k = 0; k < passes; k++) {
        div *= w; /* <= 2^31 * 2^32 before the check: no uint64 wrap */
        if (div > AVG_MAX_DIVISOR) {
            return INC_ERR_OVERFLOW;
        }
    }
    if ((uint64_t)capacity < (uint64_t)w * passes) {
        return INC_ERR_INVAL;
    }
    s = log2_exact(div);
    c->lines = lines;
    c->w = w;
    c->passes = passes;
    c->divisor = (uint32_t)div;
    c->pow2 = s >= 0;
    c->shift = s >= 0 ? (unsigned)s : 0u;
    avg_cascade_restart(c);
    return INC_OK;
}

void avg_cascade_restart(struct avg_cascade *c)
{
    if (c != NULL) {
        c->head = 0;
        c->seen = 0;
        c->primed = false;
    }
}

uint32_t avg_cascade_taps(const struct avg_cascade *c)
{
    if (c == NULL || c->w == 0u) {
        return 0u;
    }
    return c->passes * (c->w - 1u) + 1u;
}

/* Steady state for a constant input x: pass k's inputs are x * W^k, its sum x * W^(k+1). */
static void cascade_prime(struct avg_cascade *c, int32_t x)
{
    int64_t v = x;
    unsigned k;
    uint32_t i;
    for (k = 0; k < c->passes; k++) {
        int64_t *line = c->lines + (size_t)k * c->w;
        for (i = 0; i < c->w; i++) {
            line[i] = v;
        }
        v *= (int64_t)c->w; /* |v| <= 2^31 * W^(k+1) <= 2^62 */
        c->sum[k] = v;
    }
    c->primed = true;
}

int avg_cascade_push(struct avg_cascade *c, int32_t x, int32_t *y, bool *full)
{
    int64_t v = x;
    unsigned k;
    uint32_t taps;
    if (c == NULL || y == NULL || full == NULL) {
        return INC_ERR_NULL;
    }
    if (c->w == 0u) {
        return INC_ERR_STATE;
    }
    taps = avg_cascade_taps(c);
    if (!c->primed) {
        cascade_prime(c, x);
    }
    for (k = 0; k < c->passes; k++) {
        int64_t *slot = c->lines + (size_t)k * c->w + c->head;
        /* |sum| <= W^(k+1) 2^31 and |old| <= W^k 2^31: no intermediate leaves int64. */
        c->sum[k] = (c->sum[k] - *slot) + v;
        *slot = v;
        v = c->sum[k];
    }
    c->head = c->head + 1u == c->w ? 0u : c->head + 1u;
    if (c->seen < taps) {
        c->seen++;
    }
    *full = c->seen >= taps;
    *y = div_round(v, c->divisor, c->pow2, c->shift);
    return INC_OK;
}

/* ---- Bartlett ------------------------------------------------------------------------------- */

int avg_bartlett_init(struct avg_bartlett *b, unsigned m, uint32_t d)
{
    if (b == NULL) {
        return INC_ERR_NULL;
    }
    b->n = 0;
    if (m > AVG_BARTLETT_MAX_M || d == 0u || d > (1u << m)) {
        return INC_ERR_INVAL;
    }
    b->m = m;
    b->n = 1u << m;
    b->d = d;
    avg_bartlett_restart(b);
    return INC_OK;
}

void avg_bartlett_restart(struct avg_bartlett *b)
{
    if (b != NULL) {
        b->head = 0;
        b->seen = 0;
        b->phase = 0;
        b->primed = false;
    }
}

int avg_bartlett_push(struct avg_bartlett *b, int32_t x, int32_t *y, bool *ready, bool *full)
{
    int64_t old;
    if (b == NULL || y == NULL || ready == NULL) {
        return INC_ERR_NULL;
    }
    *ready = false;
    if (b->n == 0u) {
        return INC_ERR_STATE;
    }
    if (!b->primed) {
        const int64_t s = (int64_t)x * b->n;
        uint32_t i;
        for (i = 0; i < b->n; i++) {
            b->x_line[i] = x;
            b->s_line[i] = s;
        }
        b->s1 = s;
        b->s2 = s * b->n; /* |x| 2^12 <= 2^43 */
        b->primed = true;
    }
    /* Stage 1: sum of the last N inputs. */
    b->s1 = (b->s1 - b->x_line[b->head]) + x;
    b->x_line[b->head] = x;
    /* Stage 2: sum of the last N stage-1 sums = triangular window of 2N - 1 inputs. */
    old = b->s_line[b->head];
    b->s_line[b->head] = b->s1;
    b->s2 = (b->s2 - old) + b->s1;
    b->head = (b->head + 1u) & (b->n - 1u);
    if (b->seen < 2u * b->n - 1u) {
        b->seen++;
    }
    if (full != NULL) {
        *full = b->seen >= 2u * b->n - 1u;
    }
    if (++b->phase == b->d) {
        b->phase = 0;
        *y = (int32_t)fx_rshift_round64(b->s2, 2u * b->m);
        *ready = true;
    }
    return INC_OK;
}
