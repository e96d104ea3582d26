/*
 * test_fx_arith.c - shifts, saturation, conversions, multiply, divide (int32 and int64 / uint32),
 * reciprocal, accumulation.
 *
 * Every result here is exact math followed by one documented rounding, so the tests compare
 * with exact integer references (fx_test.h, written independently of base/fx) and require
 * equality: that proves |error| <= 0.5 LSB and the tie rule at once.
 * Random sweep: FX_DENSITY(1000000, 200000) pairs per function (full = host preset /
 * reduced = QEMU and host-sanitize).
 */
#include "fx_test_int.h"

#define N_RANDOM FX_DENSITY(1000000L, 200000L)

static const int32_t edge32[] = {
    INT32_MIN,   INT32_MIN + 1,
    -1073741824, -65537,
    -65536,      -65535,
    -32769,      -32768,
    -32767,      -3,
    -2,          -1,
    0,           1,
    2,           3,
    32767,       32768,
    32769,       65535,
    65536,       65537,
    1073741824,  INT32_MAX - 1,
    INT32_MAX,
};
#define N_EDGE (sizeof edge32 / sizeof edge32[0])

/* floor(x / 2^s) by C division (truncating) corrected for negative remainders. */
static int64_t floor_pow2(int64_t x, unsigned s)
{
    int64_t d = (int64_t)1 << s, q = x / d;
    if (x % d != 0 && x < 0) q--;
    return q;
}

static void test_asr_and_uabs(void)
{
    size_t i;
    unsigned s;
    for (i = 0; i < N_EDGE; i++) {
        int32_t x = edge32[i];
        for (s = 0; s <= 31u; s++)
            CHECK_EQ_INT(fx_asr32(x, s), floor_pow2(x, s));
        CHECK_EQ_INT(fx_asr32(x, 32), x < 0 ? -1 : 0);
        CHECK_EQ_INT(fx_asr32(x, 200), x < 0 ? -1 : 0);
        for (s = 0; s <= 62u; s++) {
            int64_t big = (int64_t)x * 4294967296LL + 12345; /* exercise the high word */
            CHECK_EQ_INT(fx_asr64(big, s), floor_pow2(big, s));
        }
        CHECK_EQ_INT(fx_asr64((int64_t)x, 64), x < 0 ? -1 : 0);
        CHECK_EQ_HEX(fx_uabs32(x), x < 0 ? (uint32_t)(-(int64_t)x) : (uint32_t)x);
    }
    CHECK_EQ_INT(fx_asr64(INT64_MIN, 63), -1);
    CHECK_EQ_INT(fx_asr64(INT64_MIN, 62), -2);
    CHECK_EQ_INT(fx_asr64(INT64_MAX, 62), 1);
    CHECK_EQ_HEX(fx_uabs32(INT32_MIN), 0x80000000u);
    CHECK_EQ_HEX(fx_uabs64(INT64_MIN), 0x8000000000000000ull);
    CHECK_EQ_HEX(fx_uabs64(-5), 5u);
}

static void test_saturating_basics(void)
{
    size_t i, j;
    for (i = 0; i < N_EDGE; i++) {
        int32_t a = edge32[i];
        CHECK_EQ_INT(fx_abs(a), a == INT32_MIN ? INT32_MAX : (a < 0 ? -a : a));
        CHECK_EQ_INT(fx_neg(a), fxt_sat(-(int64_t)a));
        CHECK_EQ_INT(fx_q16_from_int(a), fxt_sat((int64_t)a * 65536));
        CHECK_EQ_INT(fx_q16_to_q30(a), fxt_sat((int64_t)a * 16384));
        CHECK_EQ_INT(fx_lshift_sat32(a, 0), a);
        CHECK_EQ_INT(fx_lshift_sat32(a, 31), fxt_sat((int64_t)a * 2147483648LL));
        CHECK_EQ_INT(fx_lshift_sat32(a, 40), a > 0 ? INT32_MAX : (a < 0 ? INT32_MIN : 0));
        for (j = 0; j < N_EDGE; j++) {
            int32_t b = edge32[j];
            CHECK_EQ_INT(fx_add(a, b), fxt_sat((int64_t)a + b));
            CHECK_EQ_INT(fx_sub(a, b), fxt_sat((int64_t)a - b));
        }
    }
    CHECK_EQ_INT(fx_sat32(INT64_MAX), INT32_MAX);
    CHECK_EQ_INT(fx_sat32(INT64_MIN), INT32_MIN);
    CHECK_EQ_INT(fx_sat32((int64_t)INT32_MAX + 1), INT32_MAX);
    CHECK_EQ_INT(fx_sat32((int64_t)INT32_MIN - 1), INT32_MIN);
    CHECK_EQ_INT(fx_sat32(-7), -7);
    CHECK_EQ_INT(fx_clamp(5, -3, 3), 3);
    CHECK_EQ_INT(fx_clamp(-5, -3, 3), -3);
    CHECK_EQ_INT(fx_clamp(2, -3, 3), 2);
    CHECK_EQ_INT(fx_clamp(INT32_MIN, INT32_MIN, INT32_MAX), INT32_MIN);
    CHECK_EQ_INT(fx_clamp(0, 3, -3), -3); /* lo > hi: documented as hi */
    CHECK_EQ_INT(fx_q16_from_int(32767), 32767 * 65536);
    CHECK_EQ_INT(fx_q16_from_int(-32768), INT32_MIN);
    CHECK_EQ_INT(fx_q16_from_int(32768), INT32_MAX);
}

static void test_rounding_shifts(void)
{
    size_t i;
    unsigned s;
    uint32_t st = 0x1234567u;
    long k;
    /* ties away from zero */
    CHECK_EQ_INT(fx_rshift_round32(3, 1), 2);
    CHECK_EQ_INT(fx_rshift_round32(-3, 1), -2);
    CHECK_EQ_INT(fx_rshift_round32(1, 1), 1);
    CHECK_EQ_INT(fx_rshift_round32(-1, 1), -1);
    CHECK_EQ_INT(fx_rshift_round32(5, 2), 1); /* 1.25 */
    CHECK_EQ_INT(fx_rshift_round32(-5, 2), -1);
    CHECK_EQ_INT(fx_rshift_round32(-6, 2), -2); /* -1.5 */
    CHECK_EQ_INT(fx_rshift_round32(6, 2), 2);
    CHECK_EQ_INT(fx_rshift_round32(-7, 2), -2);
    CHECK_EQ_INT(fx_rshift_round32(INT32_MIN, 31), -1);
    CHECK_EQ_INT(fx_rshift_round32(INT32_MIN, 32), -1); /* -0.5 -> -1 */
    CHECK_EQ_INT(fx_rshift_round32(INT32_MAX, 32), 0);
    CHECK_EQ_INT(fx_rshift_round32(INT32_MAX, 31), 1);
    CHECK_EQ_INT(fx_rshift_round32(INT32_MIN, 33), 0);
    CHECK_EQ_INT(fx_rshift_round32(INT32_MIN, 1000), 0);
    CHECK_EQ_INT(fx_rshift_round32(-32768, 16), -1); /* -0.5 */
    CHECK_EQ_INT(fx_rshift_round32(32768, 16), 1);
    CHECK_EQ_INT(fx_rshift_round32(32767, 16), 0);
    CHECK_EQ_INT(fx_rshift_round64(INT64_MIN, 63), -1);
    CHECK_EQ_INT(fx_rshift_round64(INT64_MIN, 64), -1); /* exactly -0.5 */
    CHECK_EQ_INT(fx_rshift_round64(INT64_MAX, 64), 0);
    CHECK_EQ_INT(fx_rshift_round64(INT64_MAX, 63), 1);
    CHECK_EQ_INT(fx_rshift_round64(INT64_MAX, 1), 4611686018427387904LL); /* no overflow */
    CHECK_EQ_INT(fx_rshift_round64(INT64_MIN, 65), 0);
    CHECK_EQ_INT(fx_rshift_round64(-3, 1), -2);
    CHECK_EQ_INT(fx_rshift_round64(3, 1), 2);
    for (i = 0; i < N_EDGE; i++) {
        for (s = 0; s <= 31u; s++) {
            int32_t x = edge32[i];
            CHECK_EQ_INT(fx_rshift_round32(x, s), unit_round_div(x, (int64_t)1 << s));
        }
    }
    for (k = 0; k < N_RANDOM / 16; k++) {
        int32_t x = fxt_rand_scaled(&st);
        int64_t y = (int64_t)fxt_rand_scaled(&st) * (int64_t)(unit_rand32(&st) >> 2);
        s = unit_rand32(&st) % 32u;
        CHECK_EQ_INT(fx_rshift_round32(x, s), unit_round_div(x, (int64_t)1 << s));
        s = unit_rand32(&st) % 62u;
        CHECK_EQ_INT(fx_rshift_round64(y, s), unit_round_div(y, (int64_t)1 << s));
        /* odd symmetry */
        if (x != INT32_MIN)
            CHECK_EQ_INT(fx_rshift_round32(-x, s % 32u), -fx_rshift_round32(x, s % 32u));
    }
    /* Conversions are rounding shifts */
    CHECK_EQ_INT(fx_q16_round_int(FX_Q16_ONE + FX_Q16_HALF), 2);
    CHECK_EQ_INT(fx_q16_round_int(-FX_Q16_ONE - FX_Q16_HALF), -2);
    CHECK_EQ_INT(fx_q16_round_int(FX_Q16_HALF - 1), 0);
    CHECK_EQ_INT(fx_q30_to_q16(FX_Q30_ONE), FX_Q16_ONE);
    CHECK_EQ_INT(fx_q30_to_q16(8192), 1); /* 0.5 LSB Q16 -> away */
    CHECK_EQ_INT(fx_q30_to_q16(-8192), -1);
    CHECK_EQ_INT(fx_q30_to_q16(8191), 0);
    CHECK_EQ_INT(fx_q30_to_q16(INT32_MIN), -131072);
}

static int32_t ref_mul(int32_t a, int32_t b, unsigned s)
{
    return fxt_sat(unit_round_div((int64_t)a * b, (int64_t)1 << s));
}

static void test_multiply(void)
{
    size_t i, j;
    long k;
    uint32_t st = 0xC0FFEEu;
    unsigned long bad16 = 0, bad30 = 0, badsh = 0, badodd = 0;
    for (i = 0; i < N_EDGE; i++) {
        for (j = 0; j < N_EDGE; j++) {
            int32_t a = edge32[i], b = edge32[j];
            CHECK_EQ_INT(fx_mul_q16(a, b), ref_mul(a, b, 16));
            CHECK_EQ_INT(fx_mul_q30(a, b), ref_mul(a, b, 30));
            CHECK_EQ_INT(fx_mul_q16_q30(a, b), ref_mul(a, b, 30));
            CHECK_EQ_INT(fx_mul_shift(a, b, 0), fxt_sat((int64_t)a * b));
            CHECK_EQ_INT(fx_mul_shift(a, b, 16), ref_mul(a, b, 16));
            CHECK_EQ_INT(fx_mul_shift(a, b, 61), ref_mul(a, b, 61));
        }
    }
    for (k = 0; k < N_RANDOM; k++) {
        int32_t a = fxt_rand_scaled(&st), b = fxt_rand_scaled(&st);
        unsigned s = unit_rand32(&st) % 62u;
        if (fx_mul_q16(a, b) != ref_mul(a, b, 16)) bad16++;
        if (fx_mul_q30(a, b) != ref_mul(a, b, 30)) bad30++;
        if (fx_mul_shift(a, b, s) != ref_mul(a, b, s)) badsh++;
        if (a != INT32_MIN) { /* odd symmetry where nothing saturates */
            int32_t p = fx_mul_q16(a, b);
            if (p != INT32_MIN && p != INT32_MAX && fx_mul_q16(-a, b) != -p) badodd++;
        }
    }
    CHECK_EQ_INT(bad16, 0);
    CHECK_EQ_INT(bad30, 0);
    CHECK_EQ_INT(badsh, 0);
    CHECK_EQ_INT(badodd, 0);
    /* named cases: values, ties, saturation */
    CHECK_EQ_INT(fx_mul_q16(FX_Q16_ONE, FX_Q16_ONE), FX_Q16_ONE);
    CHECK_EQ_INT(fx_mul_q16(FX_Q16_INT(3), -FX_Q16_HALF), -FX_Q16_INT(3) / 2);
    CHECK_EQ_INT(fx_mul_q16(1, 32768), 1);   /* 0.5 LSB -> 1 */
    CHECK_EQ_INT(fx_mul_q16(-1, 32768), -1); /* -0.5 LSB -> -1 */
    CHECK_EQ_INT(fx_mul_q16(1, 32767), 0);
    CHECK_EQ_INT(fx_mul_q16(INT32_MIN, INT32_MIN), INT32_MAX);
    CHECK_EQ_INT(fx_mul_q16(INT32_MIN, INT32_MAX), INT32_MIN);
    CHECK_EQ_INT(fx_mul_q16(INT32_MIN, FX_Q16_ONE), INT32_MIN);
    CHECK_EQ_INT(fx_mul_q16(INT32_MIN, -FX_Q16_ONE), INT32_MAX);
    CHECK_EQ_INT(fx_mul_q30(FX_Q30_ONE, FX_Q30_ONE), FX_Q30_ONE);
    CHECK_EQ_INT(fx_mul_q30(INT32_MIN, FX_Q30_ONE), INT32_MIN); /* -2 * 1 = -2: exact */
    CHECK_EQ_INT(fx_mul_q30(INT32_MIN, INT32_MIN), INT32_MAX);  /* 4 saturates */
    CHECK_EQ_INT(fx_mul_q30(FX_Q30_HALF, 3), 2);                /* 1.5 LSB -> 2 */
    CHECK_EQ_INT(fx_mul_q30(-FX_Q30_HALF, 3), -2);
    CHECK_EQ_INT(fx_mul_q16_q30(FX_Q16_INT(1000), FX_Q30_HALF), FX_Q16_INT(500));
    CHECK_EQ_INT(fx_mul_q16_q30(FX_Q16_INT(30000), FX_Q30_ONE + FX_Q30_HALF), INT32_MAX);
}

/* round(num * 2^f / den), ties away from zero, unsaturated (exact integer reference). */
static int64_t exact_div(int32_t num, int32_t den, unsigned f)
{
    int64_t n = (int64_t)num * ((int64_t)1 << f), d = den;
    if (d < 0) {
        n = -n;
        d = -d;
    }
    return unit_round_div(n, d);
}

static int32_t ref_div(int32_t num, int32_t den, unsigned f)
{
    return fxt_sat(exact_div(num, den, f));
}

/* fx_div against the reference: value and return code. Returns 1 on mismatch. */
static int div_mismatch(int32_t num, int32_t den, unsigned f)
{
    int32_t q = 0;
    int rc = fx_div(num, den, f, &q);
    int64_t e;
    if (den == 0)
        return rc != INC_ERR_INVAL || q != (num > 0 ? INT32_MAX : (num < 0 ? INT32_MIN : 0));
    e = exact_div(num, den, f);
    return q != fxt_sat(e) || rc != ((e >= INT32_MIN && e <= INT32_MAX) ? INC_OK : INC_ERR_RANGE);
}

static void test_divide(void)
{
    size_t i, j;
    long k;
    int32_t q = 0;
    uint32_t st = 0xBADC0DEu;
    unsigned long bad = 0, badodd = 0;
    /* divide by zero: documented saturation and INC_ERR_INVAL */
    CHECK_ERR(fx_div_q16(FX_Q16_ONE, 0, &q), INC_ERR_INVAL);
    CHECK_EQ_INT(q, INT32_MAX);
    CHECK_ERR(fx_div_q16(-1, 0, &q), INC_ERR_INVAL);
    CHECK_EQ_INT(q, INT32_MIN);
    q = 77;
    CHECK_ERR(fx_div_q30(0, 0, &q), INC_ERR_INVAL);
    CHECK_EQ_INT(q, 0);
    CHECK_ERR(fx_div(1, 1, 32, &q), INC_ERR_INVAL);
    CHECK_EQ_INT(q, 0);
    CHECK_ERR(fx_div(1, 1, 0, NULL), INC_ERR_NULL);
    /* ties and signs */
    CHECK_OK(fx_div(1, 2, 0, &q));
    CHECK_EQ_INT(q, 1);
    CHECK_OK(fx_div(-1, 2, 0, &q));
    CHECK_EQ_INT(q, -1);
    CHECK_OK(fx_div(1, -2, 0, &q));
    CHECK_EQ_INT(q, -1);
    CHECK_OK(fx_div(-3, -2, 0, &q));
    CHECK_EQ_INT(q, 2);
    CHECK_OK(fx_div(1, 3, 0, &q));
    CHECK_EQ_INT(q, 0);
    CHECK_OK(fx_div(2, 3, 0, &q));
    CHECK_EQ_INT(q, 1);
    CHECK_OK(fx_div_q16(FX_Q16_ONE, FX_Q16_INT(3), &q));
    CHECK_EQ_INT(q, 21845); /* 0.333328 */
    CHECK_OK(fx_div_q16(FX_Q16_INT(2), FX_Q16_INT(3), &q));
    CHECK_EQ_INT(q, 43691); /* 0.666672: 43690.67 rounds up */
    CHECK_OK(fx_div_q30(FX_Q30_HALF, FX_Q30_ONE, &q));
    CHECK_EQ_INT(q, FX_Q30_HALF);
    /* saturation */
    CHECK_ERR(fx_div_q16(INT32_MIN, 1, &q), INC_ERR_RANGE);
    CHECK_EQ_INT(q, INT32_MIN);
    CHECK_ERR(fx_div_q16(INT32_MIN, -FX_Q16_ONE, &q), INC_ERR_RANGE); /* +32768 */
    CHECK_EQ_INT(q, INT32_MAX);
    CHECK_OK(fx_div_q16(INT32_MIN, FX_Q16_ONE, &q)); /* -32768 fits */
    CHECK_EQ_INT(q, INT32_MIN);
    CHECK_ERR(fx_div_q30(FX_Q30_ONE, FX_Q30_HALF, &q), INC_ERR_RANGE); /* 2 */
    CHECK_EQ_INT(q, INT32_MAX);
    CHECK_OK(fx_div_q30(-FX_Q30_ONE, FX_Q30_HALF, &q)); /* -2 fits */
    CHECK_EQ_INT(q, INT32_MIN);
    CHECK_ERR(fx_div(INT32_MIN, INT32_MIN, 31, &q), INC_ERR_RANGE); /* 2^31 */
    CHECK_EQ_INT(q, INT32_MAX);
    CHECK_ERR(fx_div(INT32_MIN, INT32_MAX, 31, &q), INC_ERR_RANGE); /* -2^31 - 1 */
    CHECK_EQ_INT(q, INT32_MIN);
    CHECK_OK(fx_div(INT32_MIN, 1, 0, &q));
    CHECK_EQ_INT(q, INT32_MIN);
    CHECK_ERR(fx_div(INT32_MIN, -1, 0, &q), INC_ERR_RANGE);
    CHECK_EQ_INT(q, INT32_MAX);
    /* edges x edges, every fractional width */
    for (i = 0; i < N_EDGE; i++) {
        for (j = 0; j < N_EDGE; j++) {
            unsigned f;
            for (f = 0; f <= 31u; f++)
                bad += (unsigned long)div_mismatch(edge32[i], edge32[j], f);
        }
    }
    for (k = 0; k < N_RANDOM; k++) {
        int32_t num = fxt_rand_scaled(&st), den = fxt_rand_scaled(&st);
        bad += (unsigned long)div_mismatch(num, den, unit_rand32(&st) % 32u);
        /* odd symmetry of the rounding */
        if (num != INT32_MIN && den != 0) {
            int32_t q1 = 0, q2 = 0;
            (void)fx_div(num, den, 16, &q1);
            (void)fx_div(-num, den, 16, &q2);
            if (q1 != INT32_MIN && q1 != INT32_MAX && q2 != -q1) badodd++;
        }
    }
    CHECK_EQ_INT(bad, 0);
    CHECK_EQ_INT(badodd, 0);
}

/* A random int64 with a random magnitude (2^0 .. 2^62) and sign. */
static int64_t rand_i64(uint32_t *st)
{
    const uint64_t u = ((uint64_t)unit_rand32(st) << 32 | unit_rand32(st)) >> 2; /* [0, 2^62) */
    const int64_t m = (int64_t)(u >> (unit_rand32(st) % 63u));
    return (unit_rand32(st) & 1u) ? -m : m;
}

static void test_divide64(void)
{
    long k;
    uint32_t st = 0x5EED64u;
    unsigned long bad = 0, badodd = 0;
    /* den == 0: saturated by the sign of num, as fx_div */
    CHECK_EQ_INT(fx_div64(5, 0), INT32_MAX);
    CHECK_EQ_INT(fx_div64(-5, 0), INT32_MIN);
    CHECK_EQ_INT(fx_div64(0, 0), 0);
    /* ties away from zero, both signs */
    CHECK_EQ_INT(fx_div64(1, 2), 1);
    CHECK_EQ_INT(fx_div64(-1, 2), -1);
    CHECK_EQ_INT(fx_div64(5, 2), 3);
    CHECK_EQ_INT(fx_div64(-5, 2), -3);
    CHECK_EQ_INT(fx_div64(4, 3), 1);
    CHECK_EQ_INT(fx_div64(-5, 3), -2);
    CHECK_EQ_INT(fx_div64(-4, 3), -1);
    /* an ADIS-style scaling: 8191 counts x 0.05 deg/s in Q16 = 8191 x 32768 / 10 */
    CHECK_EQ_INT(fx_div64(8191LL * 32768, 10u), 26840269);
    CHECK_EQ_INT(fx_div64(-8192LL * 32768, 10u), -26843546);
    /* saturation at both ends, exactly at the limits, and the extreme inputs */
    CHECK_EQ_INT(fx_div64(INT32_MAX, 1u), INT32_MAX);
    CHECK_EQ_INT(fx_div64((int64_t)INT32_MAX + 1, 1u), INT32_MAX);
    CHECK_EQ_INT(fx_div64(INT32_MIN, 1u), INT32_MIN);
    CHECK_EQ_INT(fx_div64((int64_t)INT32_MIN - 1, 1u), INT32_MIN);
    CHECK_EQ_INT(fx_div64(2 * (int64_t)INT32_MAX + 1, 2u), INT32_MAX); /* 2^31 - 0.5 -> 2^31 */
    CHECK_EQ_INT(fx_div64(2 * (int64_t)INT32_MIN - 1, 2u), INT32_MIN); /* -2^31 - 0.5 */
    CHECK_EQ_INT(fx_div64(INT64_MAX, 1u), INT32_MAX);
    CHECK_EQ_INT(fx_div64(INT64_MIN, 1u), INT32_MIN);
    CHECK_EQ_INT(fx_div64(INT64_MIN, UINT32_MAX), INT32_MIN); /* -2147483648.5 */
    CHECK_EQ_INT(fx_div64(INT64_MAX, UINT32_MAX), INT32_MAX);
    CHECK_EQ_INT(fx_div64(INT64_MIN / 2, UINT32_MAX), -1073741824); /* -1073741824.25 */
    CHECK_EQ_INT(fx_div64(3, UINT32_MAX), 0);
    /* the same division as fx_sum_mean */
    {
        struct fx_sum acc;
        int32_t m = 0;
        acc.sum = -7 * (int64_t)FX_SUM_MAX_COUNT - (int64_t)FX_SUM_MAX_COUNT / 2;
        acc.count = FX_SUM_MAX_COUNT;
        CHECK_OK(fx_sum_mean(&acc, &m));
        CHECK_EQ_INT(fx_div64(acc.sum, acc.count), m);
        CHECK_EQ_INT(m, -8);
    }
    /* random numerators and denominators of every magnitude against the exact reference */
    for (k = 0; k < N_RANDOM; k++) {
        const int64_t num = rand_i64(&st);
        const uint32_t den = (unit_rand32(&st) >> (unit_rand32(&st) % 32u)) | 1u;
        const int32_t q = fx_div64(num, den);
        if (q != fxt_sat(unit_round_div(num, den))) bad++;
        if (q != INT32_MIN && q != INT32_MAX && fx_div64(-num, den) != -q) badodd++;
    }
    CHECK_EQ_INT(bad, 0);
    CHECK_EQ_INT(badodd, 0);
}

/* fx_muldiv is fx_div64 of the product, bit for bit, on each of its paths. */
static void test_muldiv(void)
{
    long k;
    uint32_t st = 0x3D1Fu;
    unsigned long bad = 0;
    CHECK_EQ_INT(fx_muldiv(0, 5u, 3u), 0);
    CHECK_EQ_INT(fx_muldiv(5, 1u, 0u), INT32_MAX);
    CHECK_EQ_INT(fx_muldiv(-5, 1u, 0u), INT32_MIN);
    CHECK_EQ_INT(fx_muldiv(1, 1u, 2u), 1); /* ties away from zero */
    CHECK_EQ_INT(fx_muldiv(-1, 1u, 2u), -1);
    CHECK_EQ_INT(fx_muldiv(8191, 32768u, 10u), 26840269); /* the ADIS gyro LSB */
    CHECK_EQ_INT(fx_muldiv(-8192, 32768u, 10u), -26843546);
    CHECK_EQ_INT(fx_muldiv(65535, 65535u, 1u), INT32_MAX); /* one-division path saturates */
    CHECK_EQ_INT(fx_muldiv(-65535, 65535u, 1u), INT32_MIN);
    CHECK_EQ_INT(fx_muldiv(0xFFFFFFFFLL, 1u, 2u), INT32_MAX); /* two-division path saturates */
    CHECK_EQ_INT(fx_muldiv(-0xFFFFFFFFLL, 1u, 2u), INT32_MIN);
    CHECK_EQ_INT(fx_muldiv(0xFFFFFFFFLL, 1u, 3u), 1431655765);
    CHECK_EQ_INT(fx_muldiv(-(1LL << 32) + 1, 0x7FFFFFFFu, 0xFFFFFFFFu), -INT32_MAX); /* fallback */
    for (k = 0; k < N_RANDOM; k++) {
        const int64_t xm = (int64_t)((((uint64_t)unit_rand32(&st) << 32) | unit_rand32(&st)) >>
                                     (32u + unit_rand32(&st) % 32u)); /* |x| < 2^32 */
        const int64_t x = (unit_rand32(&st) & 1u) ? -xm : xm;
        const uint32_t m = (unit_rand32(&st) >> 1) >> (unit_rand32(&st) % 32u); /* < 2^31 */
        const uint32_t d = unit_rand32(&st) >> (unit_rand32(&st) % 32u);
        if (fx_muldiv(x, m, d) != fx_div64(x * (int64_t)m, d)) bad++;
    }
    CHECK_EQ_INT((long)bad, 0);
}

static void test_reciprocal(void)
{
    int32_t r = 0;
    CHECK_OK(fx_recip_q16(FX_Q16_ONE, &r));
    CHECK_EQ_INT(r, FX_Q16_ONE);
    CHECK_OK(fx_recip_q16(FX_Q16_INT(2), &r));
    CHECK_EQ_INT(r, FX_Q16_HALF);
    CHECK_OK(fx_recip_q16(FX_Q16_INT(-3), &r));
    CHECK_EQ_INT(r, -21845);
    CHECK_OK(fx_recip_q16(3, &r)); /* 2^32 / 3 = 1431655765.33 */
    CHECK_EQ_INT(r, 1431655765);
    CHECK_OK(fx_recip_q16(-2, &r)); /* -32768 exactly */
    CHECK_EQ_INT(r, INT32_MIN);
    CHECK_ERR(fx_recip_q16(2, &r), INC_ERR_RANGE);
    CHECK_EQ_INT(r, INT32_MAX);
    CHECK_ERR(fx_recip_q16(0, &r), INC_ERR_INVAL);
    CHECK_EQ_INT(r, INT32_MAX);
    CHECK_OK(fx_recip_q16(INT32_MIN, &r)); /* 1 / -32768 = -2 LSB */
    CHECK_EQ_INT(r, -2);
    CHECK_OK(fx_recip_q16(INT32_MAX, &r)); /* 2^32 / (2^31 - 1) = 2.000000001 */
    CHECK_EQ_INT(r, 2);
    CHECK_OK(fx_recip_q30(FX_Q30_ONE, &r));
    CHECK_EQ_INT(r, FX_Q30_ONE);
    CHECK_OK(fx_recip_q30(-FX_Q30_ONE, &r));
    CHECK_EQ_INT(r, -FX_Q30_ONE);
    CHECK_OK(fx_recip_q30(3 * (FX_Q30_ONE / 4), &r)); /* 4/3 */
    CHECK_EQ_INT(r, 1431655765);
    CHECK_OK(fx_recip_q30(INT32_MIN, &r)); /* -1/2 */
    CHECK_EQ_INT(r, -FX_Q30_HALF);
    CHECK_OK(fx_recip_q30(-FX_Q30_HALF, &r)); /* -2 */
    CHECK_EQ_INT(r, INT32_MIN);
    CHECK_ERR(fx_recip_q30(FX_Q30_HALF, &r), INC_ERR_RANGE);
    CHECK_EQ_INT(r, INT32_MAX);
    CHECK_ERR(fx_recip_q30(FX_Q30_HALF + 1, &r), INC_OK); /* 1.99999999814 */
    CHECK_EQ_INT(r, ref_div(FX_Q30_ONE, FX_Q30_HALF + 1, 30));
    CHECK_ERR(fx_recip_q30(0, NULL), INC_ERR_NULL);
}

static void test_accumulate(void)
{
    struct fx_sum acc;
    int32_t m = 12345;
    int32_t arr[1000];
    size_t i;

    fx_sum_reset(&acc);
    fx_sum_reset(NULL);
    CHECK_ERR(fx_sum_mean(&acc, &m), INC_ERR_STATE);
    CHECK_EQ_INT(m, 12345);
    CHECK_ERR(fx_sum_add(NULL, 1), INC_ERR_NULL);
    CHECK_ERR(fx_sum_mean(NULL, &m), INC_ERR_NULL);
    CHECK_ERR(fx_sum_mean(&acc, NULL), INC_ERR_NULL);
    /* ties away from zero */
    CHECK_OK(fx_sum_add(&acc, 1));
    CHECK_OK(fx_sum_add(&acc, 2));
    CHECK_OK(fx_sum_mean(&acc, &m));
    CHECK_EQ_INT(m, 2); /* 1.5 */
    fx_sum_reset(&acc);
    CHECK_OK(fx_sum_add(&acc, -1));
    CHECK_OK(fx_sum_add(&acc, -2));
    CHECK_OK(fx_sum_mean(&acc, &m));
    CHECK_EQ_INT(m, -2); /* -1.5 */
    CHECK_OK(fx_sum_add(&acc, -2));
    CHECK_OK(fx_sum_mean(&acc, &m));
    CHECK_EQ_INT(m, -2); /* -5/3 = -1.67 */
    CHECK_EQ_INT(acc.sum, -5);
    CHECK_EQ_INT(acc.count, 3);

    /* The extreme case: 2^31 samples of INT32_MIN sum to -2^62 without overflow; the mean is
     * exact; one more sample is refused with the sum intact. (The state is set directly: adding
     * 2^31 samples one by one would take minutes.) */
    acc.sum = (int64_t)INT32_MIN * (int64_t)(FX_SUM_MAX_COUNT - 1u);
    acc.count = FX_SUM_MAX_COUNT - 1u;
    CHECK_OK(fx_sum_add(&acc, INT32_MIN));
    CHECK_EQ_INT(acc.sum, -4611686018427387904LL);
    CHECK_EQ_HEX(acc.count, FX_SUM_MAX_COUNT);
    CHECK_OK(fx_sum_mean(&acc, &m));
    CHECK_EQ_INT(m, INT32_MIN);
    CHECK_ERR(fx_sum_add(&acc, 5), INC_ERR_OVERFLOW);
    CHECK_EQ_INT(acc.sum, -4611686018427387904LL);
    CHECK_EQ_HEX(acc.count, FX_SUM_MAX_COUNT);
    acc.sum = (int64_t)INT32_MAX * (int64_t)(FX_SUM_MAX_COUNT - 1u);
    acc.count = FX_SUM_MAX_COUNT - 1u;
    CHECK_OK(fx_sum_add(&acc, INT32_MAX));
    CHECK_OK(fx_sum_mean(&acc, &m));
    CHECK_EQ_INT(m, INT32_MAX);
    /* mean just below a tie with a huge count: (2^31 * 7 - 1) / 2^31 -> 7 */
    acc.sum = 7 * (int64_t)FX_SUM_MAX_COUNT - 1;
    acc.count = FX_SUM_MAX_COUNT;
    CHECK_OK(fx_sum_mean(&acc, &m));
    CHECK_EQ_INT(m, 7);
    acc.sum = 7 * (int64_t)FX_SUM_MAX_COUNT - (int64_t)FX_SUM_MAX_COUNT / 2; /* 6.5 */
    CHECK_OK(fx_sum_mean(&acc, &m));
    CHECK_EQ_INT(m, 7);
    acc.sum = -acc.sum; /* -6.5 */
    CHECK_OK(fx_sum_mean(&acc, &m));
    CHECK_EQ_INT(m, -7);

    /* array mean */
    for (i = 0; i < 1000; i++)
        arr[i] = INT32_MAX;
    CHECK_OK(fx_mean_i32(arr, 1000, &m));
    CHECK_EQ_INT(m, INT32_MAX);
    for (i = 0; i < 1000; i++)
        arr[i] = (int32_t)i - 600; /* mean -100.5 */
    CHECK_OK(fx_mean_i32(arr, 1000, &m));
    CHECK_EQ_INT(m, -101);
    CHECK_OK(fx_mean_i32(arr, 3, &m)); /* -600 -599 -598 */
    CHECK_EQ_INT(m, -599);
    m = 9;
    CHECK_ERR(fx_mean_i32(arr, 0, &m), INC_ERR_INVAL);
    CHECK_ERR(fx_mean_i32(arr, FX_SUM_MAX_COUNT + 1u, &m), INC_ERR_INVAL);
    CHECK_EQ_INT(m, 9);
    CHECK_ERR(fx_mean_i32(NULL, 3, &m), INC_ERR_NULL);
    CHECK_ERR(fx_mean_i32(arr, 3, NULL), INC_ERR_NULL);
    /* streaming and array agree, and equal the exact rounded mean */
    {
        uint32_t st = 99u;
        int64_t sum = 0;
        fx_sum_reset(&acc);
        for (i = 0; i < 1000; i++) {
            arr[i] = fxt_rand_scaled(&st);
            sum += arr[i];
            CHECK_OK(fx_sum_add(&acc, arr[i]));
        }
        CHECK_OK(fx_sum_mean(&acc, &m));
        CHECK_EQ_INT(m, unit_round_div(sum, 1000));
        CHECK_OK(fx_mean_i32(arr, 1000, &m));
        CHECK_EQ_INT(m, unit_round_div(sum, 1000));
    }
}

int main(void)
{
    UNIT_RUN(test_asr_and_uabs);
    UNIT_RUN(test_saturating_basics);
    UNIT_RUN(test_rounding_shifts);
    UNIT_RUN(test_multiply);
    UNIT_RUN(test_divide);
    UNIT_RUN(test_divide64);
    UNIT_RUN(test_muldiv);
    UNIT_RUN(test_reciprocal);
    UNIT_RUN(test_accumulate);
    return unit_report();
}
