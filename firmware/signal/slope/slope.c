/* slope.c - EPB slope estimator (see slope.h and docs/slope.md). */
#include "inclino/slope.h"

#include <stddef.h>

/* k at r = 2^-n, n = 0..48, Q16: k = sqrt(2) erfc^-1(2^-n), two-sided Gaussian tail
 * (generated in double precision by bisection on erfc; tests/slope checks it against libm).
 * n never exceeds 48: runs < 2^32 and E >= 2^-16 give r > 2^-48. */
static const int32_t k_table[49] = {
    0,      44203,  75389,  100540, 122076, 141156, 158437, 174330, 189113, 202983,
    216085, 228531, 240408, 251785, 262719, 273257, 283438, 293295, 302857, 312148,
    321190, 330000, 338597, 346994, 355204, 363239, 371111, 378827, 386397, 393829,
    401130, 408306, 415364, 422310, 429147, 435882, 442519, 449061, 455513, 461878,
    468160, 474361, 480486, 486535, 492513, 498422, 504263, 510040, 515754,
};

/* log2(1 + i/32) in Q16, i = 0..32. */
static const uint16_t log2_table[33] = {
    0,     2909,  5732,  8473,  11136, 13727, 16248, 18704, 21098, 23433, 25711,
    27936, 30109, 32234, 34312, 36346, 38336, 40286, 42196, 44068, 45904, 47705,
    49472, 51207, 52911, 54584, 56229, 57845, 59434, 60997, 62534, 64047, 65535,
};

/* log2(x) in Q16 for x >= 1 (x = 0 gives 0). |error| <= 2e-4 (linear interpolation). */
static int32_t log2_q16(uint64_t x)
{
    unsigned p = 0;
    uint64_t m;
    uint32_t idx, frac;
    if (x == 0u) {
        return 0;
    }
    while ((x >> p) > 1u) {
        p++;
    }
    /* Mantissa as a 32-bit fraction of [1, 2): f = x / 2^p - 1 in Q32. */
    m = p >= 32u ? (x >> (p - 32u)) : (x << (32u - p));
    m &= 0xFFFFFFFFull;
    idx = (uint32_t)(m >> 27);              /* top 5 bits: table interval */
    frac = (uint32_t)((m >> 11) & 0xFFFFu); /* next 16 bits: position inside it */
    return (int32_t)(p << 16) + log2_table[idx] +
           (int32_t)(((uint32_t)(log2_table[idx + 1u] - log2_table[idx]) * frac + 0x8000u) >> 16);
}

int slope_sigma_factor(uint32_t runs, fx_q16_t expected_q16, fx_q16_t *k)
{
    int32_t n; /* log2(M / E) in Q16 */
    uint32_t i, f;
    if (k == NULL) {
        return INC_ERR_NULL;
    }
    if (runs == 0u || expected_q16 <= 0) {
        return INC_ERR_INVAL;
    }
    /* log2(M / E) = log2(M * 2^16) - log2(E_raw). */
    n = log2_q16((uint64_t)runs << 16) - log2_q16((uint64_t)(uint32_t)expected_q16);
    if (n < 4 * 65536) {
        return INC_ERR_INVAL; /* r > 2^-4: not a tail worth a factor */
    }
    if (n >= 48 * 65536) {
        n = 48 * 65536 - 1; /* not reachable with uint32 runs and Q16 E (see k_table) */
    }
    i = (uint32_t)n >> 16;
    f = (uint32_t)n & 0xFFFFu;
    *k = k_table[i] + (int32_t)(((int64_t)(k_table[i + 1u] - k_table[i]) * f + 0x8000) >> 16);
    return INC_OK;
}

/* 100 * num / den in Q16 %, num and den in one fixed-point unit, |num| < 2^40, |den| < 2^40:
 * round to nearest, ties away from zero (|error| <= 0.5 LSB), saturated to INT32_MIN/MAX; den
 * == 0 gives INT32_MAX or INT32_MIN by the sign of num (0 for 0 / 0). One division, so one
 * rounding: |num| * 100 * 2^16 < 2^40 * 2^22.7 < 2^63. */
static int32_t ratio_pct(int64_t num, int64_t den)
{
    int64_t p, q, r;
    if (den == 0) {
        return num > 0 ? INT32_MAX : (num < 0 ? INT32_MIN : 0);
    }
    p = num * (100 * 65536);
    q = p / den; /* C11: truncates toward zero on every target */
    r = p % den;
    if (2u * fx_uabs64(r) >= fx_uabs64(den)) {
        q += ((p < 0) != (den < 0)) ? -1 : 1;
    }
    return fx_sat32(q);
}

fx_q16_t slope_grade_pct(fx_q16_t deg)
{
    fx_q30_t s, c;
    fx_sincos_deg(deg, &s, &c); /* one quadrant reduction; same values as sin / cos */
    return ratio_pct(s, c);     /* c == 0 only at +-90 deg, where s = +-1 */
}

/* The grade of the direction (a_s, a_h), a_s in Q16 g and a_h = (negative ? -1 : 1) sqrt(h2), h2
 * in Q32 g^2: 100 a_s / a_h with a_h to Q30 (round(sqrt(h2 2^28))) when |a_s| < 2^26 and h2 <
 * 2^34 (|a_h| < 4 g): the norm's relative rounding is 2^-31 / |a_h| (a_h in g), below 0.01 LSB
 * of grade within +-60 deg; else in Q16 (a magnitude the estimate flags anyway). */
static int32_t grade_of(int64_t a_s, uint64_t h2, bool negative)
{
    const bool fine = fx_uabs64(a_s) < (1ull << 26) && h2 < (1ull << 34);
    const int64_t h = fine ? (int64_t)fx_isqrt64_round(h2 << 28) : (int64_t)fx_isqrt64_round(h2);
    return ratio_pct(fine ? a_s * (1 << 14) : a_s, negative ? -h : h);
}

/* The single-axis grade of a_s (Q16 g) on a 1 g gravity: a_h = sqrt(1 g^2 - a_s^2); at |a_s|
 * >= 1 g a_h = 0 (saturated). */
static int32_t grade_1g(int64_t a_s)
{
    const uint64_t m = fx_uabs64(a_s);
    return grade_of(a_s, m < (1u << 16) ? (1ull << 32) - m * m : 0u, false);
}

int slope_cfg_check(const struct slope_cfg *cfg)
{
    const struct slope_budget *b;
    if (cfg == NULL) {
        return INC_ERR_NULL;
    }
    b = &cfg->budget;
    if ((cfg->method != SLOPE_SINGLE_AXIS && cfg->method != SLOPE_TWO_AXIS) ||
        cfg->slope_axis > 2u || cfg->gravity_axis > 2u ||
        (cfg->method == SLOPE_TWO_AXIS && cfg->slope_axis == cfg->gravity_axis)) {
        return INC_ERR_INVAL;
    }
    if (b->sensitivity < 0 || b->sensitivity >= FX_Q30_HALF || b->offset_g < 0 ||
        b->nonlinearity_g < 0 || b->temperature_g < 0 || b->noise_sigma_g < 0 || b->k_sigma <= 0) {
        return INC_ERR_INVAL;
    }
    if (cfg->max_slope_deg <= 0 || cfg->max_slope_deg > FX_DEG_90 || cfg->max_bound_deg <= 0 ||
        cfg->magnitude_tol_g <= 0) {
        return INC_ERR_INVAL;
    }
    return INC_OK;
}

/* k * sigma / sqrt(N), rounded up so the bound never shrinks through rounding (Q16 g). */
static int64_t noise_term(const struct slope_budget *b, uint32_t n)
{
    /* k*sigma in Q32, divided by sqrt(N): ceil(k*sigma*2^16 / sqrt(N)) in Q16 uses
     * isqrt(N * 2^32) = floor(sqrt(N) * 2^16), which only makes the term larger. */
    const uint64_t ks = (uint64_t)(uint32_t)b->k_sigma * (uint32_t)b->noise_sigma_g; /* Q32 */
    const uint64_t root = fx_isqrt64((uint64_t)n << 32);                             /* Q16 */
    if (root == 0u) {
        return INT32_MAX;
    }
    return (int64_t)((ks + root - 1u) / root);
}

/* Acceleration error bound of one axis reading a (Q16 g), Q16 g, rounded up, capped at 2 g. */
static int32_t accel_bound(const struct slope_budget *b, int32_t a, int64_t noise)
{
    /* |a| * sensitivity, rounded up: ceil(|a| * s / 2^30). */
    const uint64_t sens = ((uint64_t)fx_uabs32(a) * (uint32_t)b->sensitivity +
                           ((1ull << 30) - 1u)) >>
                          30;
    int64_t e = (int64_t)sens + b->offset_g + b->nonlinearity_g + b->temperature_g + noise;
    return e > 2 * FX_Q16_ONE ? 2 * FX_Q16_ONE : (int32_t)e;
}

static int32_t axis_value(const struct slope_input *in, uint8_t axis, bool negative)
{
    return negative ? fx_neg(in->accel_g[axis]) : in->accel_g[axis];
}

static fx_q16_t asin_of_g(int64_t a_q16)
{
    /* Q16 g -> Q30 ratio, clamped to [-1, 1] (fx_asin_deg clamps too, but the shift must not
     * overflow). */
    if (a_q16 > FX_Q16_ONE) a_q16 = FX_Q16_ONE;
    if (a_q16 < -FX_Q16_ONE) a_q16 = -FX_Q16_ONE;
    return fx_asin_deg((fx_q30_t)(a_q16 * (1 << 14)));
}

static int32_t absdiff(int32_t a, int32_t b)
{
    return fx_abs(fx_sub(a, b));
}

static int32_t max32(int32_t a, int32_t b)
{
    return a > b ? a : b;
}

/* |grade at a corner of the box - the estimate's grade|; a saturated grade (a corner or the
 * estimate at or past 90 deg) makes it unbounded: INT32_MAX. */
static int32_t grade_change(int32_t corner, int32_t grade)
{
    if (corner == INT32_MAX || corner == INT32_MIN || grade == INT32_MAX || grade == INT32_MIN) {
        return INT32_MAX;
    }
    return absdiff(corner, grade);
}

/* Grade LSBs added to the corners' largest grade change: the corner's own rounding (0.5 LSB) and
 * the norm's (below 0.01 LSB within +-60 deg), rounded up (slope.h). */
#define GRADE_BOUND_ROUNDING 2

int slope_estimate(const struct slope_cfg *cfg, const struct slope_input *in,
                   struct slope_result *out)
{
    int err;
    int64_t noise;
    int32_t s, ea, theta, bound = 0, grade_bound = 0;
    uint32_t flags = 0;
    if (out == NULL) {
        return INC_ERR_NULL;
    }
    out->valid = false;
    out->flags = 0;
    out->slope_deg = out->grade_pct = out->bound_deg = out->bound_pct = 0;
    out->accel_bound_g = out->noise_g = 0;
    if (in == NULL) {
        return INC_ERR_NULL;
    }
    err = slope_cfg_check(cfg);
    if (err != INC_OK) {
        return err;
    }
    if (in->n_samples == 0u) {
        return INC_ERR_INVAL;
    }
    noise = noise_term(&cfg->budget, in->n_samples);
    s = axis_value(in, cfg->slope_axis, cfg->slope_axis_negative);
    ea = accel_bound(&cfg->budget, s, noise);

    if (cfg->method == SLOPE_SINGLE_AXIS) {
        int32_t lo_d;
        theta = asin_of_g(s);
        /* asin is monotonic: the extremes of the box are its ends. */
        bound = absdiff(asin_of_g((int64_t)s + ea), theta);
        lo_d = absdiff(theta, asin_of_g((int64_t)s - ea));
        if (lo_d > bound) {
            bound = lo_d;
        }
        if ((int64_t)fx_uabs32(s) > (int64_t)FX_Q16_ONE + cfg->magnitude_tol_g) {
            flags |= SLOPE_F_MAGNITUDE;
        }
        /* the grade is monotonic in a_s too: its extremes are at the same two ends */
        out->grade_pct = grade_1g(s);
        grade_bound = max32(grade_change(grade_1g((int64_t)s + ea), out->grade_pct),
                            grade_change(grade_1g((int64_t)s - ea), out->grade_pct));
    } else {
        /* The gravity component perpendicular to the slope axis is the norm of the gravity
         * axis and the cross axis: with a cross slope (roll) phi, A_g alone is cos(theta)
         * cos(phi), and atan2(A_s, A_g) would overstate the slope (by 0.4 deg at 30 deg of
         * slope and 10 deg of roll). Its sign is the gravity axis's (upright: positive). */
        const uint8_t ca = (uint8_t)(3u - cfg->slope_axis - cfg->gravity_axis);
        const int32_t gz = axis_value(in, cfg->gravity_axis, cfg->gravity_axis_negative);
        const int32_t gc = in->accel_g[ca];
        const int32_t eg = accel_bound(&cfg->budget, gz, noise);
        const int32_t ec = accel_bound(&cfg->budget, gc, noise);
        const uint64_t az = fx_uabs32(gz), ac = fx_uabs32(gc);
        const uint64_t h2 = az * az + ac * ac; /* Q32, < 2^63 */
        int64_t g = fx_isqrt64_round(h2);      /* Q16 */
        /* The norm over the box (|gz| +- eg, |gc| +- ec) lies in [h_lo, h_hi] (it grows with
         * each magnitude): h_lo rounded down, h_hi up. */
        const uint64_t zl = az > (uint64_t)eg ? az - (uint64_t)eg : 0u;
        const uint64_t cl = ac > (uint64_t)ec ? ac - (uint64_t)ec : 0u;
        const uint64_t zh = az + (uint64_t)eg, ch = ac + (uint64_t)ec;
        const uint64_t hl2 = zl * zl + cl * cl, hh2 = zh * zh + ch * ch;
        int64_t h_lo = (int64_t)fx_isqrt64(hl2), h_hi = (int64_t)fx_isqrt64(hh2);
        const uint64_t mag2 = (uint64_t)((int64_t)s * s) + h2; /* Q32 */
        const int64_t mag = fx_isqrt64_round(mag2);            /* Q16 */
        unsigned c;
        if ((uint64_t)h_hi * (uint64_t)h_hi < hh2) {
            h_hi++;
        }
        if (gz < 0) { /* upside down: flagged below; the estimate keeps the quadrant */
            g = -g;
            h_lo = -h_lo;
            h_hi = -h_hi;
        }
        theta = fx_atan2_deg(s, fx_sat32(g));
        out->grade_pct = grade_of(s, h2, gz < 0);
        /* Over a box that does not contain the origin, atan2 takes its extremes at the
         * corners, and so does the grade a_s / a_h (monotonic in each); a box that contains it
         * (no gravity left) is flagged by the magnitude test. */
        for (c = 0; c < 4u; c++) {
            const int32_t cs = fx_sat32((int64_t)s + ((c & 1u) ? ea : -ea));
            const int32_t cg = fx_sat32((c & 2u) ? h_hi : h_lo);
            bound = max32(bound, absdiff(fx_atan2_deg(cs, cg), theta));
            grade_bound = max32(grade_bound, grade_change(ratio_pct(cs, cg), out->grade_pct));
        }
        if (mag > (int64_t)FX_Q16_ONE + cfg->magnitude_tol_g ||
            mag < (int64_t)FX_Q16_ONE - cfg->magnitude_tol_g || gz <= eg || h_lo <= ea) {
            flags |= SLOPE_F_MAGNITUDE;
        }
    }
    if (!in->still) flags |= SLOPE_F_NOT_STILL;
    if (!in->calibrated) flags |= SLOPE_F_NOT_CALIBRATED;
    if (fx_abs(theta) > cfg->max_slope_deg) flags |= SLOPE_F_OUT_OF_RANGE;
    if (bound > cfg->max_bound_deg) flags |= SLOPE_F_BOUND;

    out->slope_deg = theta;
    out->bound_deg = bound;
    out->accel_bound_g = ea;
    out->noise_g = noise > INT32_MAX ? INT32_MAX : (int32_t)noise;
    out->bound_pct = fx_add(grade_bound, GRADE_BOUND_ROUNDING);
    out->flags = flags;
    out->valid = flags == 0u;
    return INC_OK;
}
