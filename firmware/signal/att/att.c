/*
 * att.c - 3D attitude estimator, integer only (see att.h for the method and the interface).
 *
 * FORMATS used inside (never at the interface unless att.h says so):
 *   Q30  quaternions, rotation matrices, unit vectors, gains <= 1, half-angle h (rad)
 *   Q26  g: accelerometer in the gyro frame, filtered gravity y, residual L (range +-32 g)
 *   Q32  g per step: the low-pass rate state u (limited to +-0.375 g per step)
 *   Q28  1/|y| (range (0, 8)), |y|^2 (range [0, 8))
 *   Q24  deg/s: bias b (clamped to +-bias_max <= 20), motion-bias gain; 1/(P+W) normalised
 *   Q20  deg: drift bound D (clamped to [0, 180])
 *   Q16  deg/s, g, deg at the interface; 1/sqrt(P)
 *   int64 exact products, summed before one rounding.
 * ROUNDING: every right shift that drops bits rounds to nearest, ties away from zero (as fx.h):
 *   rnd()/mulr() where the result's range is proven by the formats above (the call site says
 *   why), rnds()/mulrs() saturating to int32 elsewhere, rnd32() for int32. Error <= 0.5 LSB of
 *   the result. The first-order averages (rest detection, residual) use gains 2^-n: tau is
 *   rounded to a power of two samples (0.45 s and 3.6 s at 285.7 Hz for the defaults).
 * DECIMATION: a sample counter (tick, mod 4) runs the slow parts at 1/4 of the rate, each on
 *   its own tick to keep the worst single update low: tick 0 the bias Kalman filter at rest or
 *   the first half of the motion-bias update, tick 1 its second half, tick 2 the quaternion
 *   renormalisation (|q| drifts < 2 LSB per step in between), tick 3 the sqrt(P) tracker.
 * OUTPUT: att_update leaves q_g and gf; att_get_quat composes q = q_a (x) q_g on demand.
 * MULTIPLY: mul64() is the exact 32x32 -> 64 product. On Cortex-M0+ (no long multiply) it is
 *   formed from four 16x16 -> 32 MULS instead of a libgcc call; the value is the same exact
 *   product everywhere, so the outputs stay bit-identical.
 */
#include "inclino/att.h"

#include <limits.h>

/* ---- arithmetic helpers ------------------------------------------------------------------ */

/* The helpers are forced inline: the project's cross builds use -Os, where GCC would otherwise
 * call them (tens of calls per sample). Semantics are plain C11 either way. */
#if defined(__GNUC__)
#define ATT_INLINE static inline __attribute__((always_inline))
#else
#define ATT_INLINE static inline
#endif

/* floor(x / 2^s), the fx_asr32 / fx_asr64 formulas (negative values are never shifted). */
ATT_INLINE int32_t asr32(int32_t x, unsigned s)
{
    return x >= 0 ? (x >> s) : -1 - ((-1 - x) >> s);
}

ATT_INLINE int64_t asr64(int64_t x, unsigned s)
{
    return x >= 0 ? (x >> s) : -1 - ((-1 - x) >> s);
}

ATT_INLINE int32_t sat32(int64_t x)
{
    return x > INT32_MAX ? INT32_MAX : (x < INT32_MIN ? INT32_MIN : (int32_t)x);
}

ATT_INLINE uint32_t uabs32(int32_t x)
{
    return x < 0 ? 0u - (uint32_t)x : (uint32_t)x;
}

#define ONE30 ((int32_t)0x40000000)
#define HALF30 ((int32_t)0x20000000)

/* Exact a*b (|a*b| <= 2^62). */
ATT_INLINE int64_t mul64(int32_t a, int32_t b)
{
#if defined(__ARM_ARCH_6M__) || defined(ATT_MUL16)
    /* a = ah 2^16 + al with ah signed (floor), al in [0, 2^16): every partial product fits
     * int32 (|ah bh| <= 2^30, |ah bl| < 2^31), al bl fits uint32. */
    int32_t ah = asr32(a, 16), bh = asr32(b, 16);
    int32_t al = (int32_t)((uint32_t)a & 0xFFFFu), bl = (int32_t)((uint32_t)b & 0xFFFFu);
    uint32_t lo = (uint32_t)al * (uint32_t)bl, t;
    int32_t hi = ah * bh, m = ah * bl;
    t = (uint32_t)m << 16; /* (m mod 2^16) 2^16; the rest of m 2^16 goes to the high word */
    hi += asr32(m, 16);
    lo += t;
    hi += (lo < t);
    m = al * bh;
    t = (uint32_t)m << 16;
    hi += asr32(m, 16);
    lo += t;
    hi += (lo < t);
    return (int64_t)hi * 4294967296 + (int64_t)lo;
#else
    return (int64_t)a * b;
#endif
}

/* round(x / 2^s), ties away from zero; 1 <= s <= 62, |x| < 2^63 - 2^62. The caller guarantees
 * that the result fits int32 (every call site states why); rnds() saturates instead.
 * floor((x + 2^(s-1) - [x < 0]) / 2^s) is round-half-up for x >= 0 and minus round-half-up of
 * |x| for x < 0, i.e. ties away from zero, with one add and one arithmetic shift. */
ATT_INLINE int32_t rnd(int64_t x, unsigned s)
{
    return (int32_t)asr64(x + ((int64_t)1 << (s - 1u)) - (x < 0), s);
}

/* As rnd, saturated to int32 (used where the range is not proven). */
ATT_INLINE int32_t rnds(int64_t x, unsigned s)
{
    return sat32(asr64(x + ((int64_t)1 << (s - 1u)) - (x < 0), s));
}

/* round(a*b / 2^s), ties away: |error| <= 0.5 LSB; the result must fit (see rnd). */
ATT_INLINE int32_t mulr(int32_t a, int32_t b, unsigned s)
{
    return rnd(mul64(a, b), s);
}

/* As mulr, saturated to int32. */
ATT_INLINE int32_t mulrs(int32_t a, int32_t b, unsigned s)
{
    return rnds(mul64(a, b), s);
}

/* round(x / 2^s) of an int32, ties away from zero; 1 <= s <= 30, |x| < 2^31 - 2^29. */
ATT_INLINE int32_t rnd32(int32_t x, unsigned s)
{
    return asr32(x + (int32_t)(1u << (s - 1u)) - (x < 0), s);
}

ATT_INLINE int32_t sat(int64_t x)
{
    return sat32(x);
}

ATT_INLINE int32_t clampi(int32_t x, int32_t lim)
{
    return x > lim ? lim : (x < -lim ? -lim : x);
}

ATT_INLINE uint32_t umax(uint32_t a, uint32_t b)
{
    return a > b ? a : b;
}

ATT_INLINE uint32_t umin(uint32_t a, uint32_t b)
{
    return a < b ? a : b;
}

/* sqrt(2) - 1 in Q30: max + (sqrt2 - 1) * (sum of the others) >= Euclidean norm in 2D and 3D
 * (the norm is convex, so the linear form dominates it on the unit cube once it does at the
 * corners: 1, 1.4142, 1.8284 >= 1, 1.4142, 1.7321); it exceeds the norm by at most 8.3 %. */
#define SQ2M1_Q30 ((int32_t)444758426) /* rounded up */
/* the same as 107/256 = 0.41797 (>= sqrt(2) - 1) for the 32-bit bound arithmetic */
#define SQ2M1_256 107
/* limit of the filter rate state u, Q32 g per step (0.375): keeps rnd32(u, .) in its range;
 * with tau_acc x rate >= 64 and |x - y| <= 31 g, |u| stays below 0.31 in the worst case */
#define U_MAX ((int32_t)0x5FFFFFFF)
/* cos(8 deg) in Q30: the fast output path (series) is used while gf_z >= this. */
#define COS8_Q30 ((int32_t)1063292242)
/* 0.0112 in Q30 (gz >= cos 8.6 deg): the largest d = 1 - gz for the series of 1/sqrt(2(1 + gz)) */
#define D_SERIES_MAX ((int32_t)12025908)
/* 1/sqrt(2) in Q30 */
#define RSQRT2_Q30 ((int32_t)759250125)
/* 180/pi in Q16 */
#define RAD2DEG_Q16 ((int32_t)3754936)
/* sqrt(3) in Q30 */
#define SQRT3_Q30 ((int32_t)1859775394) /* rounded up */

/* ---- quaternion / rotation pieces -------------------------------------------------------- */

/* R(q) in Q30 from a unit Q30 quaternion: 9 exact products, one rounding per entry
 * (|error| <= 0.5 LSB + the quaternion's own deviation from unit norm). */
static void quat_to_mat(const int32_t q[4], int32_t R[9])
{
    int64_t xx = mul64(q[1], q[1]), yy = mul64(q[2], q[2]), zz = mul64(q[3], q[3]);
    int64_t xy = mul64(q[1], q[2]), xz = mul64(q[1], q[3]), yz = mul64(q[2], q[3]);
    int64_t wx = mul64(q[0], q[1]), wy = mul64(q[0], q[2]), wz = mul64(q[0], q[3]);
    R[0] = rnd(((int64_t)1 << 60) - 2 * (yy + zz), 30); /* 1 - 2(y^2 + z^2) in [-1, 1]: formed in
                                                          * int64 so that -1 needs no 2 in Q30 */
    R[1] = rnd(xy - wz, 29);
    R[2] = rnd(xz + wy, 29);
    R[3] = rnd(xy + wz, 29);
    R[4] = rnd(((int64_t)1 << 60) - 2 * (xx + zz), 30);
    R[5] = rnd(yz - wx, 29);
    R[6] = rnd(xz - wy, 29);
    R[7] = rnd(yz + wx, 29);
    R[8] = rnd(((int64_t)1 << 60) - 2 * (xx + yy), 30);
}

/* o = R v (R Q30, v any Q format, o same format), saturating; |error| <= 0.5 LSB + |v| x the
 * entries' error. o may alias v. */
static void mat_vec(const int32_t R[9], const int32_t v[3], int32_t o[3])
{
    int32_t r0 = rnd(mul64(R[0], v[0]) + mul64(R[1], v[1]) + mul64(R[2], v[2]), 30);
    int32_t r1 = rnd(mul64(R[3], v[0]) + mul64(R[4], v[1]) + mul64(R[5], v[2]), 30);
    int32_t r2 = rnd(mul64(R[6], v[0]) + mul64(R[7], v[1]) + mul64(R[8], v[2]), 30);
    o[0] = r0;
    o[1] = r1;
    o[2] = r2;
}

/* o = a (x) b with a[3] == 0 (a rotation about a horizontal axis), Q30; 12 products, one
 * rounding per component: |error| <= 0.5 LSB + 2 x the inputs' rounding. o may alias b. */
static void quat_mul_h(const int32_t a[4], const int32_t b[4], int32_t o[4])
{
    int32_t w = rnd(mul64(a[0], b[0]) - mul64(a[1], b[1]) - mul64(a[2], b[2]), 30);
    int32_t x = rnd(mul64(a[0], b[1]) + mul64(a[1], b[0]) + mul64(a[2], b[3]), 30);
    int32_t y = rnd(mul64(a[0], b[2]) - mul64(a[1], b[3]) + mul64(a[2], b[0]), 30);
    int32_t z = rnd(mul64(a[0], b[3]) + mul64(a[1], b[2]) - mul64(a[2], b[1]), 30);
    o[0] = w;
    o[1] = x;
    o[2] = y;
    o[3] = z;
}

/* q <- q / |q| by one Newton step f = 1 - (|q|^2 - 1)/2 (Q30). For | |q|^2 - 1 | <= 2^-20 the
 * Newton residual (3/8) e^2 is < 2^-40; the result is unit within 2 LSB (4 roundings). */
static void quat_renorm(int32_t q[4])
{
    int64_t n2 = mul64(q[0], q[0]) + mul64(q[1], q[1]) + mul64(q[2], q[2]) + mul64(q[3], q[3]);
    int32_t f = sat((int64_t)ONE30 - rnd(n2 - ((int64_t)1 << 60), 31));
    q[0] = mulr(q[0], f, 30);
    q[1] = mulr(q[1], f, 30);
    q[2] = mulr(q[2], f, 30);
    q[3] = mulr(q[3], f, 30);
}

/* k = 1/sqrt(2 (1 + gz)) for gz = 1 - d, d in [0, 0.0112] (gz >= cos 8.6 deg), Q30:
 * (1/2)(1 - d/2)^(-1/2) = 1/2 + d/8 + 3 d^2/64 + 5 d^3/256 + ...; the truncation is
 * < 35/4096 d^4 / (1 - d) < 1.4e-10 (0.15 LSB) and the 3 roundings 1.5 LSB: |error| < 2 LSB. */
static int32_t half_rsqrt_series(int32_t d)
{
    int32_t k = 5 * (1 << 22);
    k = 3 * (1 << 24) + mulr(d, k, 30);
    k = (1 << 27) + mulr(d, k, 30);
    return HALF30 + mulr(d, k, 30);
}

/* ---- init-time helpers (divisions allowed) ------------------------------------------------ */

/* round(2^p / d) by binary long division (init only); requires d in [1, 2^62) and the
 * quotient < 2^32. Exact to the final rounding (ties away). */
static uint64_t div_pow2(unsigned p, uint64_t d)
{
    uint64_t r = 1, q = 0;
    unsigned i;
    if (r >= d) {
        r -= d;
        q = 1;
    }
    for (i = 0; i < p; i++) {
        r <<= 1;
        q <<= 1;
        if (r >= d) {
            r -= d;
            q |= 1u;
        }
    }
    if (r >= d - r) q++;
    return q;
}

static unsigned bitlen64(uint64_t x)
{
    unsigned n = 0;
    while (x) {
        x >>= 1;
        n++;
    }
    return n;
}

/* round(a * b / 2^32) of two Q16 values as uint32 count (e.g. seconds x Hz -> samples). */
static uint32_t q16_prod_round(fx_q16_t a, fx_q16_t b)
{
    uint64_t p = (uint64_t)(uint32_t)a * (uint32_t)b;
    return (uint32_t)((p + ((uint64_t)1 << 31)) >> 32);
}

/* n in [1, 30] with 2^n nearest to tau * fs samples (geometric rounding at 2^(n+1/2)). */
static uint8_t pow2_samples(fx_q16_t tau, fx_q16_t fs)
{
    uint64_t ns = (uint64_t)(uint32_t)tau * (uint32_t)fs; /* samples in Q32 */
    uint8_t n = 1;
    /* 2^(n + 1/2) in Q32 = 2^n * 1.41421356 * 2^32 */
    while (n < 30u && ns >= (((uint64_t)6074001000u) << n))
        n++;
    return n;
}

/* Low-pass coefficients for fs tau = FT (Q32 samples): k2 = 2 / (fs tau) (decay of u per
 * step) = m2 / 2^s2 and k1 = k2^2 / 2 (gain on x - y), scaled for Q26 -> Q32 (x 2^6), as
 * mantissas in [2^30, 2^31) with shifts. k2 = 2^33 / FT: m = round(2^(30 + L) / FT), s = L - 3
 * (L = bit length of FT < 2^49, so s <= 46). Relative error of each coefficient < 2^-30. */
static int lp_coeffs(uint64_t FT, int32_t *k1m, uint8_t *k1s, int32_t *k2m, uint8_t *k2s)
{
    unsigned L = bitlen64(FT), s, sh = 0;
    uint64_t mm = div_pow2(30u + L, FT), m2;
    s = L - 3u;
    if (mm >= 0x80000000ull) {
        mm = (mm + 1u) >> 1;
        s--;
    }
    *k2m = (int32_t)mm;
    *k2s = (uint8_t)s;
    /* k1 * 2^6 = k2^2 * 2^5 = m^2 / 2^(2s - 5) -> mantissa m^2 / 2^sh < 2^31 */
    m2 = mm * mm;
    while ((m2 >> sh) >= 0x80000000ull)
        sh++;
    *k1m = (int32_t)((m2 + ((uint64_t)1 << (sh - 1u))) >> sh);
    if (2u * s < 5u + sh + 1u || 2u * s - 5u - sh > 62u) return INC_ERR_INVAL;
    *k1s = (uint8_t)(2u * s - 5u - sh);
    return INC_OK;
}

static bool in_range(fx_q16_t x, int32_t lo, int32_t hi)
{
    return x >= lo && x <= hi;
}

#define Q16(x) ((int32_t)((x)*65536))
/* fractional Q16 constants written as integers (no non-integer literals in this file) */
#define Q16_FRAC(num, den) ((int32_t)(((int64_t)(num)*65536 + (den) / 2) / (den)))

int att_config_default(struct att_config *cfg, fx_q16_t sample_rate_hz)
{
    if (cfg == NULL) return INC_ERR_NULL;
    cfg->sample_rate_hz = sample_rate_hz;
    cfg->tau_acc_s = Q16(3);
    cfg->tau_acc_rest_s = Q16_FRAC(3, 2);
    cfg->rest_tau_s = Q16_FRAC(1, 2);
    cfg->rest_gyro_dps = Q16(2);
    cfg->rest_acc_g = Q16_FRAC(5, 100);
    cfg->rest_min_s = Q16_FRAC(3, 2);
    cfg->bias_max_dps = Q16(2);
    cfg->bias_sigma0_dps = Q16_FRAC(1, 2);
    cfg->bias_sigma_rest_dps = Q16_FRAC(3, 100);
    cfg->bias_forget_s = Q16(100);
    cfg->bias_motion_tau_s = Q16(25);
    cfg->bias_motion_gate_g = Q16(1);
    cfg->gyro_fs_dps = Q16(2000);
    cfg->acc_fs_g = Q16(16);
    cfg->bound_floor_deg = Q16_FRAC(6, 10);
    cfg->bound_gyro_sf = (fx_q30_t)((((int64_t)2) << 30) / 1000); /* 0.002 */
    cfg->bound_bias_k = Q16(3);
    cfg->bound_lin_k = Q16_FRAC(5, 100);
    cfg->bound_lin_tau_s = Q16(3);
    cfg->bound_latency_s = Q16_FRAC(4, 1000);
    cfg->bound_arw_dps_rts = Q16_FRAC(1, 100);
    cfg->bound_sat_dps = Q16(200);
    cfg->bound_limit_deg = Q16(5);
    cfg->bound_lever_m = Q16(2);
    cfg->require_aiding = 0u;
    cfg->fault_hold_s = Q16(1);
    return INC_OK;
}

/* Seeds of the Newton trackers from P (exact, division). */
static void seed_bias_trackers(struct att *a)
{
    int32_t sn = a->W_n + (a->pw_e ? rnd(a->P, a->pw_e) : a->P); /* (P + W) / 2^e, Q30 */
    int32_t s16 = fx_sqrt_q30(a->P) >> 14;                       /* sqrt(P), Q16 (seed only) */
    (void)fx_div(1 << 24, sn, 30, &a->rpw);                      /* Q24 */
    if (s16 < 1) s16 = 1;
    (void)fx_div(1 << 16, s16, 16, &a->zb); /* Q16 */
    a->sigb = fx_sqrt_q30(a->P);
}

int att_reset(struct att *a)
{
    int i;
    if (a == NULL) return INC_ERR_NULL;
    if ((a->flags & 1u) == 0u) return INC_ERR_STATE;
    a->q[0] = ONE30;
    a->q[1] = a->q[2] = a->q[3] = 0;
    for (i = 0; i < 3; i++) {
        a->y[i] = 0;
        a->u[i] = 0;
        a->gf[i] = 0;
        a->glp[i] = 0;
        a->alp[i] = 0;
        a->b[i] = 0;
        a->su[i] = 0;
    }
    a->tick = 0;
    a->mb_ok = false;
    a->mb_pend = false;
    a->cr[0] = a->cr[1] = a->cr[2] = 0;
    a->gw = 0;
    a->gf[2] = ONE30;
    a->ry = 0;
    a->P = a->P0;
    seed_bias_trackers(a);
    a->D = 0;
    a->L = 0;
    a->AL = 0;
    a->yaw_lp = 0;
    a->bound = FX_DEG_180;
    a->v_prev = 0;
    a->n_init = 0;
    a->rest_n = 0;
    a->fault_n = 0;
    a->fault = 0;
    a->flags = 1u; /* initialised; rest, valid, v_prev, lp-seeded cleared */
    return INC_OK;
}

int att_init(struct att *a, const struct att_config *c)
{
    uint64_t F, FT;

    int64_t pr, W;

    uint32_t e;

    if (a == NULL || c == NULL) return INC_ERR_NULL;
    a->flags = 0;
    F = (uint64_t)(uint32_t)c->sample_rate_hz;
    if (!in_range(c->sample_rate_hz, Q16(100), Q16(4000)) ||
        !in_range(c->tau_acc_s, Q16_FRAC(1, 2), Q16(30)) ||
        !(c->tau_acc_rest_s == 0 || in_range(c->tau_acc_rest_s, Q16_FRAC(1, 2), c->tau_acc_s)) ||
        !in_range(c->rest_tau_s, Q16_FRAC(5, 100), Q16(5)) ||
        !in_range(c->rest_gyro_dps, 1, Q16(50)) || !in_range(c->rest_acc_g, 1, Q16(1)) ||
        !in_range(c->rest_min_s, 0, Q16(60)) || !in_range(c->bias_max_dps, 1, Q16(20)) ||
        !in_range(c->bias_sigma0_dps, Q16_FRAC(1, 100), Q16_FRAC(99, 100)) ||
        !in_range(c->bias_sigma_rest_dps, Q16_FRAC(1, 1000), c->bias_sigma0_dps) ||
        !in_range(c->bias_forget_s, Q16(1), Q16(10000)) ||
        !(c->bias_motion_tau_s == 0 || in_range(c->bias_motion_tau_s, Q16(6), Q16(10000))) ||
        (c->bias_motion_tau_s != 0 && (int64_t)c->bias_motion_tau_s < 2 * (int64_t)c->tau_acc_s) ||
        !in_range(c->bias_motion_gate_g, Q16_FRAC(1, 100), Q16(16)) ||
        !in_range(c->gyro_fs_dps, Q16(100), Q16(4000)) || !in_range(c->acc_fs_g, Q16(1), Q16(16)) ||
        !in_range(c->bound_floor_deg, 0, Q16(10)) || c->bound_gyro_sf < 0 ||
        c->bound_gyro_sf > ONE30 / 10 || !in_range(c->bound_bias_k, 0, Q16(10)) ||
        !in_range(c->bound_lin_k, 0, Q16(100)) ||
        !in_range(c->bound_lin_tau_s, Q16_FRAC(1, 10), Q16(100)) ||
        !in_range(c->bound_latency_s, 0, Q16_FRAC(1, 10)) ||
        !in_range(c->bound_arw_dps_rts, 0, Q16(1)) || !in_range(c->bound_sat_dps, 0, Q16(4000)) ||
        !in_range(c->bound_limit_deg, 1, Q16(90)) || !in_range(c->fault_hold_s, 0, Q16(60)) ||
        !in_range(c->bound_lever_m, 0, Q16(10)) || c->require_aiding > 1u) {
        return INC_ERR_INVAL;
    }
    /* tau_acc * rate >= 64 keeps the filter rate state u within +-0.5 g per step */
    if (q16_prod_round(c->tau_acc_s, c->sample_rate_hz) < 64u) return INC_ERR_INVAL;
    /* |h| = |w| dt / 2 <= 0.343 rad for the strapdown series: rate >= gyro full scale / 20 */
    if ((int64_t)c->gyro_fs_dps > 20 * (int64_t)c->sample_rate_hz) return INC_ERR_INVAL;

    a->fs_q16 = c->sample_rate_hz;
    (void)fx_div(FX_Q16_ONE, c->sample_rate_hz, 30, &a->dt_q30);

    /* half angle per deg/s: h_Q30 = w_Q16 * pi / (360 fs) * 2^14 = w_Q16 * base / 2^31 with
     * base = pi 2^61 / (360 F), F = fs in Q16. */
    {
        uint64_t base = 7244019458077122560ull / (360u * F); /* pi * 2^61 */
        unsigned s = 31;
        while (base >= 0x80000000ull) {
            base = (base + 1u) >> 1;
            s--;
        }
        a->kh_m = (int32_t)base;
        a->kh_s = (uint8_t)s;
    }
    FT = F * (uint64_t)(uint32_t)c->tau_acc_s; /* fs tau in Q32 */
    if (lp_coeffs(FT, a->k1_m, a->k1_s, a->k2_m, a->k2_s) != INC_OK) return INC_ERR_INVAL;
    {
        fx_q16_t tr = c->tau_acc_rest_s ? c->tau_acc_rest_s : c->tau_acc_s;
        if (q16_prod_round(tr, c->sample_rate_hz) < 64u) return INC_ERR_INVAL;
        if (lp_coeffs(F * (uint64_t)(uint32_t)tr, a->k1_m + 1, a->k1_s + 1, a->k2_m + 1,
                      a->k2_s + 1) != INC_OK) {
            return INC_ERR_INVAL;
        }
    }
    /* dt / tau gains, Q30: 2^62 / (F * T) */
    /* first-order averages with a gain 2^-n: tau rounded to a power of two samples */
    a->kr_sh = pow2_samples(c->rest_tau_s, c->sample_rate_hz);
    a->kl_sh = pow2_samples(c->bound_lin_tau_s, c->sample_rate_hz);
    a->ky_sh = pow2_samples(Q16_FRAC(1, 4), c->sample_rate_hz);
    /* lever terms: c1 = d (pi/180)^2 / g0 = d x 3.10626e-5 g per (deg/s)^2, Q40 from Q16 m
     * (x 2^24 x 3.10626e-5 = 521.15, taken as 522: rounded up, a bound); c2 = d (pi/180) / g0
     * x fs / 2^ky (the low-pass's time constant), Q30: pi/180/g0 = 1910982 / 2^30 */
    a->lev_c1 = c->bound_lever_m * 522;
    a->lev_c2 = (int32_t)((((int64_t)c->bound_lever_m * c->sample_rate_hz) >> 16) * 1910983 >>
                          (16u + a->ky_sh));
    a->leak[0] = (int32_t)((((uint64_t)1 << 62) + FT / 2u) / FT);
    {
        uint64_t FTr = F *
                       (uint64_t)(uint32_t)(c->tau_acc_rest_s ? c->tau_acc_rest_s : c->tau_acc_s);
        a->leak[1] = (int32_t)((((uint64_t)1 << 62) + FTr / 2u) / FTr);
    }

    /* bias Kalman filter, Q30 (deg/s)^2 */
    a->P0 = (int32_t)(((uint64_t)(uint32_t)c->bias_sigma0_dps * (uint32_t)c->bias_sigma0_dps +
                       2u) >>
                      2);
    {
        uint64_t den = F * (uint32_t)c->bias_forget_s;             /* fs * T in Q32 */
        a->V = (int32_t)((46116860184273879ull + den / 2u) / den); /* 0.01 * 2^62 / den */
    }
    if (a->V < 16) return INC_ERR_INVAL;
    pr = (int64_t)(((uint64_t)(uint32_t)c->bias_sigma_rest_dps * (uint32_t)c->bias_sigma_rest_dps +
                    2u) >>
                   2);
    W = (int64_t)(((uint64_t)pr * (uint64_t)pr + (uint64_t)a->V / 2u) / (uint64_t)a->V) + pr;
    /* the filter runs every 4th sample: 4 samples of variance growth per step, and the
     * measurement noise of one step is that of 4 samples (W / 4), so that the gain per second
     * stays the per-sample filter's */
    a->V *= 4;
    W = (W + 2) / 4;
    e = 0;
    while ((W + a->P0) >= ((int64_t)ONE30 << e))
        e++;
    a->pw_e = (uint8_t)e;
    a->W_n = e ? (int32_t)((W + ((int64_t)1 << (e - 1u))) >> e) : (int32_t)W;
    if (a->W_n < ONE30 / 127) return INC_ERR_INVAL; /* keeps 1/(P+W) in Q24 */

    /* motion bias: deg/s per rad of correction = (1/tau_mb) * 180/pi, Q24 */
    a->g_mb = c->bias_motion_tau_s ? (int32_t)(62997375797124ull / (uint32_t)c->bias_motion_tau_s)
                                   : 0;
    (void)fx_div(1 << 20, c->bias_motion_gate_g, 16, &a->ig_mb);

    a->c_lin = fx_mul_q16(c->bound_lin_k, RAD2DEG_Q16);
    a->sf = c->bound_gyro_sf;
    a->kb = c->bound_bias_k;
    a->lat = c->bound_latency_s * 16384; /* Q16 -> Q30, exact (<= 0.1 s) */
    a->bsat = c->bound_sat_dps;
    {
        /* ARW: 3 N sqrt(t) <= 1.5 N (t / sqrt(tau) + sqrt(tau)) for every t (equality at tau) */
        int32_t st = fx_sqrt_q16(c->tau_acc_s), r; /* sqrt(tau), Q16, >= 0.707 */
        int32_t n15 = c->bound_arw_dps_rts + c->bound_arw_dps_rts / 2;
        (void)fx_div(n15, st, 16, &r);
        a->arw_rate = r;
        a->floor_q16 = c->bound_floor_deg + fx_mul_q16(n15, st);
    }
    a->limit_q16 = c->bound_limit_deg;
    a->need_aid = c->require_aiding != 0u;
    a->bmax16 = c->bias_max_dps;
    a->bmax24 = c->bias_max_dps * 256;
    a->gyro_lim = c->gyro_fs_dps - c->gyro_fs_dps / 256;
    a->acc_lim = c->acc_fs_g - c->acc_fs_g / 256;
    a->gyro_max = c->gyro_fs_dps + c->gyro_fs_dps / 8;
    a->acc_max = c->acc_fs_g + c->acc_fs_g / 8;
    a->gap_deg20 = mulrs(rnds(mul64(c->gyro_fs_dps, a->dt_q30), 26), SQRT3_Q30, 30);
    {
        int32_t tg = rnd32(c->rest_gyro_dps, 8), ta = rnd32(c->rest_acc_g, 4); /* Q8 deg/s, Q12 g */
        a->rest_thg2 = tg * tg;
        a->rest_tha2 = ta * ta;
    }
    a->rest_min_n = q16_prod_round(c->rest_min_s, c->sample_rate_hz);
    a->init_n = q16_prod_round(c->tau_acc_s, c->sample_rate_hz);
    a->fault_hold_n = q16_prod_round(c->fault_hold_s, c->sample_rate_hz);
    (void)fx_div(c->sample_rate_hz, 642689, 16, &a->fsg); /* fs / 9.80665 m/s^2 per g, Q16 */

    a->flags = 1u;
    return att_reset(a);
}

/* ---- per-sample pieces -------------------------------------------------------------------- */

/* 1/|y| (Q28) exactly (slow path: square root and division). Returns false if |y| is
 * implausible (< 0.125 g or >= 2.83 g). */
static bool ry_exact(struct att *a, uint64_t n2_q52)
{
    uint32_t mag = fx_isqrt64(n2_q52);                       /* |y| in Q26 */
    if (mag < (1u << 23) || mag >= 189812531u) return false; /* 0.125 g, 2.8284 g */
    (void)fx_div(1 << 26, (int32_t)mag, 28, &a->ry);
    return true;
}

/* The filtered gravity left the 8 deg cone about z (rare; at the first sample always).
 * Re-base the gyro frame: q <- q_a (x) q, y <- R(q_a) y, u <- R(q_a) u, su and cr likewise, with q_a
 * the smallest rotation taking gf to z, computed exactly (square root, division). Afterwards
 * gf ~ z. A linear filter commutes with a fixed rotation, so this changes no output. */
static void rebase(struct att *a)
{
    int32_t qa[4], R[9], s2, k;
    if (a->gf[2] < 0) {
        /* 180 deg about x first: (w x y z) <- [0 1 0 0] (x) q; vectors (x, -y, -z) */
        int32_t w = a->q[0], x = a->q[1], y = a->q[2], z = a->q[3];
        a->q[0] = fx_neg(x);
        a->q[1] = w;
        a->q[2] = fx_neg(z);
        a->q[3] = y;
        a->y[1] = fx_neg(a->y[1]);
        a->y[2] = fx_neg(a->y[2]);
        a->u[1] = fx_neg(a->u[1]);
        a->u[2] = fx_neg(a->u[2]);
        a->su[1] = fx_neg(a->su[1]);
        a->su[2] = fx_neg(a->su[2]);
        a->cr[1] = fx_neg(a->cr[1]);
        a->cr[2] = fx_neg(a->cr[2]);
        a->gf[1] = fx_neg(a->gf[1]);
        a->gf[2] = fx_neg(a->gf[2]);
    }
    if (a->gf[2] >= COS8_Q30) return; /* the flip was enough */
    s2 = ONE30 + a->gf[2];            /* 1 + gz in [1, 1.99] */
    if (a->gf[2] >= ONE30 - D_SERIES_MAX) {
        /* the usual case: just outside the 8 deg cone, the series is exact enough (< 2 LSB) */
        k = half_rsqrt_series(ONE30 - a->gf[2]);
    } else {
        int32_t sq = fx_sqrt_q30(s2);         /* sqrt(1 + gz), 0.5 LSB */
        (void)fx_div(RSQRT2_Q30, sq, 30, &k); /* 1 / sqrt(2 (1 + gz)), 0.5 LSB */
    }
    qa[0] = mulr(s2, k, 30);
    qa[1] = mulr(a->gf[1], k, 30);
    qa[2] = fx_neg(mulr(a->gf[0], k, 30));
    qa[3] = 0;
    quat_mul_h(qa, a->q, a->q);
    quat_renorm(a->q);
    quat_to_mat(qa, R);
    mat_vec(R, a->y, a->y);
    mat_vec(R, a->u, a->u);
    mat_vec(R, a->su, a->su);
    mat_vec(R, a->cr, a->cr); /* a pending motion-bias correction is a gyro-frame vector too */
    a->gf[0] = mulr(a->y[0], a->ry, 24);
    a->gf[1] = mulr(a->y[1], a->ry, 24);
    a->gf[2] = mulr(a->y[2], a->ry, 24);
}

/* Strapdown step: q <- q (x) dq, dq = [cos|h|, sin|h|/|h| h], h = w dt / 2 (rad, Q30) from
 * w (Q16 deg/s), then one Newton renormalisation.
 * h_i = round(w_i kh_m / 2^kh_s), kh = pi / (360 fs) to 2^-27 relative (att_init).
 * The series cos = 1 - t/2 + t^2/24 - t^3/720 and sin(x)/x = 1 - t/6 + t^2/120 - t^3/5040
 * (t = |h|^2) leave t^4/40320 and t^4/362880: with |h| <= 0.2 rad (2000 deg/s on every axis at
 * 150 Hz; 0.105 at 285.7 Hz) that is < 0.04 LSB Q30; at the config limit (|h| <= 0.343 rad)
 * < 5 LSB. Each of the 9 roundings of the series and dq costs <= 0.5 LSB, the product one
 * rounding per component: the step's max error against exact math is <= 4 LSB Q30 per
 * component (measured by test_att: see STATUS.md), and |q| = 1 within 2 LSB afterwards. */
static void strapdown(int32_t q[4], const int32_t w[3], int32_t kh_m, unsigned kh_s, bool renorm)
{
    int32_t h[3], t, c, sn, pc, qn[4];
    int i;
    for (i = 0; i < 3; i++)
        h[i] = mulr(w[i], kh_m, kh_s);
    t = rnd(mul64(h[0], h[0]) + mul64(h[1], h[1]) + mul64(h[2], h[2]), 30); /* |h|^2 */
    /* cos|h| = 1 - t/2 + t^2/24 - t^3/720; sin|h|/|h| = 1 - t/6 + t^2/120 - t^3/5040 */
    pc = 44739243 - mulr(t, 1491308, 30); /* 1/24 - t/720 */
    pc = mulr(t, pc, 30) - HALF30;        /* -1/2 + t (...) */
    c = ONE30 + mulr(t, pc, 30);
    pc = 8947849 - mulr(t, 213044, 30); /* 1/120 - t/5040 */
    pc = mulr(t, pc, 30) - 178956971;   /* -1/6 + t (...) */
    sn = ONE30 + mulr(t, pc, 30);
    h[0] = mulr(sn, h[0], 30);
    h[1] = mulr(sn, h[1], 30);
    h[2] = mulr(sn, h[2], 30);
    qn[0] = rnd(mul64(q[0], c) - mul64(q[1], h[0]) - mul64(q[2], h[1]) - mul64(q[3], h[2]), 30);
    qn[1] = rnd(mul64(q[0], h[0]) + mul64(q[1], c) + mul64(q[2], h[2]) - mul64(q[3], h[1]), 30);
    qn[2] = rnd(mul64(q[0], h[1]) - mul64(q[1], h[2]) + mul64(q[2], c) + mul64(q[3], h[0]), 30);
    qn[3] = rnd(mul64(q[0], h[2]) + mul64(q[1], h[1]) - mul64(q[2], h[0]) + mul64(q[3], c), 30);
    if (renorm) quat_renorm(qn);
    for (i = 0; i < 4; i++)
        q[i] = qn[i];
}

int att_update(struct att *a, const struct att_sample *smp)
{
    int32_t g[3], acc[3], w[3], R[9], ag[3], lev = 0;
    unsigned gsat = 0, asat = 0;
    bool rest_ok = true, init_done, grav_ok;
    int i;

    if (a == NULL || smp == NULL) return INC_ERR_NULL;
    if ((a->flags & 1u) == 0u) return INC_ERR_STATE;

    /* ---- input checks and saturation ---- */
    for (i = 0; i < 3; i++) {
        if (fx_abs(smp->gyro_dps[i]) > a->gyro_max || fx_abs(smp->acc_g[i]) > a->acc_max) break;
    }
    if (i < 3 || (smp->veh_valid &&
                  (fx_abs(smp->speed_mps) > Q16(200) || fx_abs(smp->yaw_rate_dps) > a->gyro_max))) {
        /* rejected: not propagated; the unknown rotation of this step goes into the bound */
        a->D = (int32_t)umin((uint32_t)a->D + (uint32_t)a->gap_deg20, (uint32_t)FX_DEG_180 << 4);
        a->fault |= ATT_FAULT_INPUT;
        a->fault_n = a->fault_hold_n + 1u;
        a->flags &= (uint8_t)~4u;
        return INC_ERR_RANGE;
    }
    for (i = 0; i < 3; i++) {
        g[i] = smp->gyro_dps[i];
        acc[i] = smp->acc_g[i];
        if (fx_abs(g[i]) >= a->gyro_lim || (smp->sat & (1u << i))) gsat++;
        if (fx_abs(acc[i]) >= a->acc_lim || (smp->sat & (8u << i))) asat++;
    }
    /* ---- vehicle aiding: subtract the kinematic acceleration (sensor x forward, z up) ---- */
    if (smp->veh_valid) {
        if (a->flags & 8u) {
            int32_t dv = smp->speed_mps - a->v_prev;        /* Q16 m/s, |dv| <= 400 */
            acc[0] = fx_sub(acc[0], mulrs(dv, a->fsg, 16)); /* dv/dt / g0 */
        }
        /* centripetal: yaw rate (rad/s) x v / g0 = yaw_dps x v x (pi/180 / 9.80665) */
        acc[1] = fx_sub(acc[1], mulrs(smp->yaw_rate_dps, mulr(smp->speed_mps, 1910982, 30), 16));
        /* keep the compensated specific force within the accelerometer's range */
        acc[0] = clampi(acc[0], a->acc_max);
        acc[1] = clampi(acc[1], a->acc_max);
        /* The lever's acceleration, which the aiding above misses: d (w^2 + |dw/dt|), dw/dt from
         * the yaw rate's 0.25 s low-pass (the rate sensor's noise and steps average out there).
         * |w| is limited to 400 deg/s for the square (no car turns faster). */
        {
            const int32_t yc = clampi(smp->yaw_rate_dps, Q16(400)) >> 8; /* Q8 deg/s */
            const int64_t t1 = rnd(mul64(yc, yc) * a->lev_c1, 30);       /* Q26 g */
            int64_t t2;
            if ((a->flags & 8u) == 0u) a->yaw_lp = smp->yaw_rate_dps;
            a->yaw_lp += rnd32(smp->yaw_rate_dps - a->yaw_lp, a->ky_sh);
            t2 = rnd(mul64((int32_t)uabs32(smp->yaw_rate_dps - a->yaw_lp), a->lev_c2), 20);
            lev = (int32_t)(t1 + t2 > (1 << 29) ? (1 << 29) : t1 + t2);
        }
        a->v_prev = smp->speed_mps;
        a->flags |= 8u;
        if (fx_abs(smp->speed_mps) >= Q16_FRAC(2, 10)) rest_ok = false;
    } else {
        a->flags &= (uint8_t)~8u;
    }

    /* ---- rest detection: deviation from first-order low-passes ---- */
    if ((a->flags & 16u) == 0u) {
        for (i = 0; i < 3; i++) {
            a->glp[i] = g[i];
            a->alp[i] = acc[i];
        }
        a->flags |= 16u;
    }
    {
        /* deviations after the low-pass step, squared in 32 bits: gyro in Q8 deg/s (|d| <= 50
         * deg/s, else no rest), accel in Q12 g (|d| <= 1 g, else no rest) */
        int32_t dg2 = 0, da2 = 0;
        for (i = 0; i < 3; i++) {
            /* |g|, |glp| <= gyro_max <= 4500 deg/s (2^28.2 in Q16): differences fit int32 */
            int32_t d = g[i] - a->glp[i];
            a->glp[i] += rnd32(d, a->kr_sh);
            d = rnd32(g[i] - a->glp[i], 8);
            if (fx_abs(d) > 12800)
                rest_ok = false;
            else
                dg2 += d * d;
            if (fx_abs(a->glp[i]) > a->bmax16) rest_ok = false;
            d = acc[i] - a->alp[i]; /* |acc|, |alp| <= 18 g */
            a->alp[i] += rnd32(d, a->kr_sh);
            d = rnd32(acc[i] - a->alp[i], 4);
            if (fx_abs(d) > 4096)
                rest_ok = false;
            else
                da2 += d * d;
        }
        if (dg2 >= a->rest_thg2 || da2 >= a->rest_tha2 || gsat || asat) rest_ok = false;
        if (rest_ok) {
            if (a->rest_n < a->rest_min_n) a->rest_n++;
        } else {
            a->rest_n = 0;
        }
        if (rest_ok && a->rest_n >= a->rest_min_n) {
            a->flags |= 2u;
        } else {
            a->flags &= (uint8_t)~2u;
        }
    }

    /* ---- bias: variance growth, rest update (scalar Kalman filter, same gain on 3 axes), run
     * every 4th sample on the 0.5 s low-passed gyro (V and W are scaled for the 4-sample step) */
    if (a->tick == 0u && a->P < a->P0)
        a->P += a->V; /* (the rest update and the motion-bias
                                                        * update share tick 0: never both) */
    if (a->tick == 0u && (a->flags & 2u)) {
        int32_t sn_n = a->W_n + (a->pw_e ? rnd(a->P, a->pw_e) : a->P); /* (P + W) / 2^e, Q30 */
        int32_t K;
        for (i = 0; i < 2; i++) { /* Newton: r <- r (2 - s r), tracks 1/s from below */
            int32_t tt = mulrs(sn_n, a->rpw, 24);
            if (tt < 1) tt = 1;
            a->rpw = mulrs(a->rpw, (int32_t)((int64_t)2 * ONE30 - tt), 30);
        }
        K = rnds(mul64(a->P, a->rpw), 24u + a->pw_e); /* P / (P + W), Q30 */
        for (i = 0; i < 3; i++) {
            /* at rest |glp| <= bias_max <= 20 deg/s: glp * 256 and the sums fit int32 */
            int32_t e = clampi(a->glp[i] * 256 - a->b[i], a->bmax24);
            a->b[i] = clampi(a->b[i] + mulr(K, e, 30), a->bmax24);
        }
        a->P -= mulr(K, a->P, 30);
        if (a->P < a->V) a->P = a->V;
    }
    /* sigma = sqrt(P) by tracking z = 1/sqrt(P) (one Newton step every 4th sample, tick 3) */
    if (a->tick == 3u) {
        int32_t sg = mulrs(a->P, a->zb, 16);          /* P z, Q30 */
        int32_t mm = mulrs(sg, a->zb, 16);            /* P z^2, Q30 */
        int32_t f = rnds((int64_t)3 * ONE30 - mm, 1); /* (3 - P z^2) / 2 */
        a->zb = mulrs(a->zb, f, 30);
        a->sigb = mulrs(sg, f, 30);
    }

    /* ---- strapdown with the bias-corrected rate ---- */
    for (i = 0; i < 3; i++)
        w[i] = g[i] - rnd32(a->b[i], 8); /* |g| <= 2^28.2, |b| <= 20 deg/s */
    strapdown(a->q, w, a->kh_m, a->kh_s, a->tick == 2u);

    /* ---- accelerometer in the gyro frame, 2nd-order low-pass there ---- */
    quat_to_mat(a->q, R);
    for (i = 0; i < 3; i++) {
        /* |acc| <= 18 g per axis: |ag| <= 31.2 g fits Q26; the filter input is limited to
         * +-15 g per axis so that x - y (|y| <= 15.6 g with the overshoot) fits Q26 too */
        ag[i] = clampi(
            rnd(mul64(R[3 * i], acc[0]) + mul64(R[3 * i + 1], acc[1]) + mul64(R[3 * i + 2], acc[2]),
                20),
            15 << 26);
    }
    init_done = a->n_init > a->init_n;
    if (!init_done) {
        if (!asat) {
            int32_t inv;
            a->n_init++;
            (void)fx_div(1, (int32_t)a->n_init, 30, &inv); /* 1/n, Q30 (init phase only) */
            for (i = 0; i < 3; i++)
                a->y[i] += mulr(ag[i] - a->y[i], inv, 30); /* a mean: |y| <= 15 g */
            if (a->n_init == a->init_n) a->n_init++;       /* done; u is still 0 */
        }
    } else {
        unsigned ks = (a->flags & 2u) ? 1u : 0u; /* at rest: the faster set (tau_acc_rest) */
        for (i = 0; i < 3; i++) {
            int64_t du = -(int64_t)rnd(mul64(a->u[i], a->k2_m[ks]), a->k2_s[ks]);
            if (!asat) du += rnd(mul64(ag[i] - a->y[i], a->k1_m[ks]), a->k1_s[ks]);
            a->u[i] = clampi(sat((int64_t)a->u[i] + du), U_MAX); /* state limit, see U_MAX */
            a->y[i] = clampi(a->y[i] + rnd32(a->u[i], 6), 16 << 26);
        }
    }

    /* ---- mean horizontal residual (gyro frame x, y; gf is within 8 deg of z) ---- */
    {
        uint32_t dx = uabs32(ag[0] - a->y[0]); /* |ag| <= 15 g, |y| <= 16 g */
        uint32_t dy = uabs32(ag[1] - a->y[1]);
        uint32_t dh = umax(dx, dy) + (umin(dx, dy) >> 8) * SQ2M1_256;
        if (dh > (uint32_t)(1 << 29))
            dh = (uint32_t)(1 << 29); /* 8 g: bound far beyond any limit */
        a->L += rnd32((int32_t)dh - a->L, a->kl_sh);
        a->AL += rnd32(lev - a->AL, a->kl_sh); /* the aiding's lever error, same averaging */
    }

    /* ---- unit filtered gravity: 1/|y| tracked by one Newton step per sample ---- */
    {
        int64_t n52 = mul64(a->y[0], a->y[0]) + mul64(a->y[1], a->y[1]) + mul64(a->y[2], a->y[2]);
        int32_t n2 = rnds(n52, 24); /* Q28, saturates at 8 */
        grav_ok = n2 >= (1 << 22) && n2 < INT32_MAX;
        if (grav_ok) {
            if (a->ry == 0) grav_ok = ry_exact(a, (uint64_t)n52);
            for (i = 0; grav_ok && i < 1; i++) {
                int32_t f, r2 = mulrs(a->ry, a->ry, 28);
                int32_t mm = mulrs(n2, r2, 26); /* |y|^2 r^2, Q30 */
                if (mm < ONE30 - ONE30 / 4 || mm > ONE30 + ONE30 / 4) {
                    grav_ok = ry_exact(a, (uint64_t)n52);
                    continue;
                }
                f = rnd((int64_t)3 * ONE30 - mm, 1); /* mm in [0.75, 1.25]: f in [0.875, 1.125] */
                a->ry = mulr(a->ry, f, 30);
            }
        }
        if (grav_ok) {
            a->gf[0] = mulr(a->y[0], a->ry, 24);
            a->gf[1] = mulr(a->y[1], a->ry, 24);
            a->gf[2] = mulr(a->y[2], a->ry, 24);
            a->fault &= (uint8_t)~ATT_FAULT_GRAVITY;
        } else {
            a->ry = 0;
            a->fault |= ATT_FAULT_GRAVITY;
        }
    }

    /* ---- motion bias: the correction gf x (sum of u)/|y| over 4 samples, back in the sensor
     * frame with R of the next sample (decimated by 4, split over ticks 0 and 1; at 1000 deg/s
     * the sensor turns 14 deg in a window, which scales the update by cos(7 deg) and is
     * harmless for a 25 s integrator). Weight 1 - L / gate: trusted only while the mean
     * horizontal residual (the disagreement of accel and prediction) is small. ---- */
    if (!(a->g_mb != 0 && init_done && grav_ok && (a->flags & 2u) == 0u && gsat == 0u &&
          asat == 0u)) {
        a->mb_ok = false;
    }
    for (i = 0; i < 3; i++)
        a->su[i] += rnd32(a->u[i], 2); /* |u| <= 0.5 g: sum of 4 quarters < 0.5 g */
    if (a->tick == 0u) {
        /* first half (tick 0): the window's correction in the gyro frame and its weight */
        a->mb_pend = false;
        if (a->mb_ok) {
            int32_t wm = ONE30 -
                         (int32_t)umin((uint32_t)ONE30, (uint32_t)rnds(mul64(a->L, a->ig_mb), 16));
            if (wm > 0) {
                int32_t un[3];
                for (i = 0; i < 3; i++)
                    un[i] = mulrs(a->su[i], a->ry, 28); /* Q30 rad */
                a->cr[0] = rnds(mul64(a->gf[1], un[2]) - mul64(a->gf[2], un[1]), 30);
                a->cr[1] = rnds(mul64(a->gf[2], un[0]) - mul64(a->gf[0], un[2]), 30);
                a->cr[2] = rnds(mul64(a->gf[0], un[1]) - mul64(a->gf[1], un[0]), 30);
                a->gw = mulr(wm, a->g_mb, 30); /* Q24 deg/s per rad */
                a->mb_pend = true;
            }
        }
        a->su[0] = a->su[1] = a->su[2] = 0;
        a->mb_ok = true;
    } else if (a->tick == 1u && a->mb_pend) {
        /* second half (tick 1): back to the sensor frame with R^T and integrate into b */
        for (i = 0; i < 3; i++) {
            int32_t es = rnds(mul64(R[i], a->cr[0]) + mul64(R[3 + i], a->cr[1]) +
                                  mul64(R[6 + i], a->cr[2]),
                              30); /* (R^T c)_i, Q30 rad */
            a->b[i] = clampi(a->b[i] + mulrs(es, a->gw, 30), a->bmax24);
        }
        a->mb_pend = false;
    }

    /* ---- re-base when the filtered gravity leaves the 8 deg cone ---- */
    if (grav_ok && a->gf[2] < COS8_Q30) rebase(a); /* 0-4 times per 3 min trial on the dev data */

    /* ---- integrity bound ---- */
    {
        uint32_t ax = uabs32(w[0]), ay = uabs32(w[1]), az = uabs32(w[2]);
        uint32_t mx = umax(ax, umax(ay, az)), wn;
        int32_t rate, lin, b;
        wn = mx + ((ax + ay + az - mx) >> 8) * SQ2M1_256; /* >= |w| - 2^-8 deg/s, Q16 */
        /* rate < 0.1 x 2^29.7 + 10 x 2^16 + 3 x 4000 x 2^16 + 2 x 2^16 < 2^31; D <= 180 deg Q20
         * plus one step (rate x dt < 2^28.4 Q20) fits int32 */
        rate = mulr(a->sf, (int32_t)wn, 30) + mulr(a->kb, rnd(a->sigb, 14), 16) +
               (int32_t)gsat * a->bsat + a->arw_rate;
        a->D += rnd(mul64(rate, a->dt_q30), 26);
        if (!asat && init_done) a->D -= mulr(a->D, a->leak[(a->flags & 2u) ? 1 : 0], 30);
        if (a->D > (FX_DEG_180 << 4)) a->D = FX_DEG_180 << 4;
        lin = grav_ok ? mulrs(mulr(a->L, a->ry, 38), a->c_lin, 16) +
                            mulrs(mulr(a->AL, a->ry, 38), RAD2DEG_Q16, 16)
                      : FX_DEG_180;
        b = sat((int64_t)a->floor_q16 + rnd(a->D, 4) + lin + mulr((int32_t)wn, a->lat, 30));
        if (b > FX_DEG_180 || !init_done) b = FX_DEG_180;
        a->bound = b;
    }
    if (a->fault_n > 0u) {
        a->fault_n--;
        if (a->fault_n == 0u) a->fault &= (uint8_t)~ATT_FAULT_INPUT;
    }
    a->tick = (uint8_t)((a->tick + 1u) & 3u);
    if (init_done && a->fault == 0u && a->bound <= a->limit_q16 &&
        (!a->need_aid || smp->veh_valid)) {
        a->flags |= 4u;
    } else {
        a->flags &= (uint8_t)~4u;
    }
    return INC_OK;
}

/* ---- getters ------------------------------------------------------------------------------- */

void att_get_quat(const struct att *a, int32_t q[4])
{
    if (a == NULL || q == NULL) return;
    if (a->gf[2] >= COS8_Q30) {
        /* q = q_a (x) q_g, q_a = [sqrt((1 + gz)/2), gy k, -gx k, 0], k = 1/sqrt(2 (1 + gz)),
         * d = 1 - gz in [0, 0.0098] (the update keeps gf in the 8 deg cone) */
        int32_t d = ONE30 - a->gf[2], k, qa[4];
        k = half_rsqrt_series(d);
        qa[0] = 2 * k - mulr(d, k, 30); /* sqrt((1 + gz)/2) = (2 - d) k */
        qa[1] = mulr(a->gf[1], k, 30);
        qa[2] = fx_neg(mulr(a->gf[0], k, 30));
        qa[3] = 0;
        quat_mul_h(qa, a->q, q);
    } else {
        int i;
        for (i = 0; i < 4; i++)
            q[i] = a->q[i]; /* only before the first sample */
    }
}

fx_q16_t att_get_bound(const struct att *a)
{
    return a ? a->bound : FX_DEG_180;
}

bool att_get_valid(const struct att *a)
{
    return a != NULL && (a->flags & 4u) != 0u;
}

uint8_t att_get_status(const struct att *a)
{
    return a ? a->fault : 0u;
}

bool att_get_rest(const struct att *a)
{
    return a != NULL && (a->flags & 2u) != 0u;
}

void att_get_bias(const struct att *a, fx_q16_t bias_dps[3], fx_q16_t *sigma_dps)
{
    if (a == NULL) return;
    if (bias_dps) {
        int i;
        for (i = 0; i < 3; i++)
            bias_dps[i] = rnd32(a->b[i], 8);
    }
    if (sigma_dps) *sigma_dps = fx_rshift_round32(a->sigb, 14);
}

void att_get_up(const struct att *a, int32_t up[3])
{
    int32_t q[4];
    if (a == NULL || up == NULL) return;
    att_get_quat(a, q);
    /* third row of R(q): R^T e_z */
    up[0] = rnd(mul64(q[1], q[3]) - mul64(q[0], q[2]), 29);
    up[1] = rnd(mul64(q[2], q[3]) + mul64(q[0], q[1]), 29);
    up[2] = rnd(((int64_t)1 << 60) - 2 * (mul64(q[1], q[1]) + mul64(q[2], q[2])), 30);
}

void att_get_euler(const struct att *a, fx_q16_t *roll_deg, fx_q16_t *pitch_deg)
{
    int32_t up[3];
    if (a == NULL) return;
    att_get_up(a, up);
    if (roll_deg) *roll_deg = fx_atan2_deg(up[1], up[2]);
    if (pitch_deg) *pitch_deg = fx_asin_deg(fx_neg(up[0]));
}
