/*
 * test_fx_sqrt.c - integer and fixed-point square roots.
 *
 * Floor and rounded roots are checked with exact integer criteria (no floating point):
 *   r = floor(sqrt(n))  <=>  r^2 <= n <= r^2 + 2r
 *   r = round(sqrt(n))  <=>  r^2 - r < n <= r^2 + r      (ties cannot occur)
 * which prove "exact" (floor) and |error| <= 0.5 LSB (rounded). The double reference is only used
 * to print the measured error.
 *
 * Densities (full = host preset / reduced = QEMU and host-sanitize):
 *   fx_isqrt32 exhaustive n < 2^24 / 2^19; every k^2 - 1, k^2, k^2 + k, k^2 + k + 1 for all
 *              k < 2^16 (both); every power of two +-3; random 2^20 / 2^16.
 *   fx_isqrt64 and fx_isqrt64_round: every power of two +-3; k^2 boundaries for the last 2^16 /
 *              2^14 k below 2^32 and random k; random n 2^20 / 2^16.
 *   fx_sqrt_q16 / fx_sqrt_q30: every 521st / 32771st code of [0, 2^31), plus all codes
 *              < 2^16 / 2^14, plus random 2^20 / 2^16.
 */
#include "fx_test.h"

static int floor_ok(uint64_t n, uint64_t r)
{
    /* r <= 2^32 - 1, so r^2 and r^2 + 2r fit in uint64 */
    return r <= 0xFFFFFFFFu && r * r <= n && n - r * r <= 2u * r;
}

static int round_ok(uint64_t n, uint64_t r)
{
    if (r == 0) return n == 0;
    return r <= 0xFFFFFFFFu && n > r * r - r && n <= r * r + r;
}

/* fx_isqrt64_round is exact-rounded up to 2^64 - 2^32; above, it saturates (checked apart). */
static int round64_bad(uint64_t n)
{
    return n <= 0xFFFFFFFF00000000ull && !round_ok(n, fx_isqrt64_round(n));
}

static void test_isqrt32(void)
{
    const uint32_t n_exh = FX_DENSITY(1u << 24, 1u << 19);
    const long n_rand = FX_DENSITY(1L << 20, 1L << 16);
    unsigned long bad = 0, total = 0;
    uint32_t n, k, st = 7u;
    unsigned e;
    long i;
    for (n = 0; n < n_exh; n++, total++)
        bad += !floor_ok(n, fx_isqrt32(n));
    for (k = 1; k < 65536u; k++) {
        uint32_t sq = k * k, c[4];
        int j;
        c[0] = sq - 1u;
        c[1] = sq;
        c[2] = sq + k;
        c[3] = sq + k + 1u; /* may wrap to 0 for k = 65535: still a valid input */
        for (j = 0; j < 4; j++, total++)
            bad += !floor_ok(c[j], fx_isqrt32(c[j]));
        CHECK(fx_isqrt32(sq) == k && fx_isqrt32(sq - 1u) == k - 1u);
    }
    for (e = 0; e < 32u; e++) {
        int d;
        for (d = -3; d <= 3; d++, total++) {
            uint32_t v = (uint32_t)((int64_t)((uint64_t)1 << e) + d);
            bad += !floor_ok(v, fx_isqrt32(v));
        }
    }
    for (i = 0; i < n_rand; i++, total++) {
        uint32_t v = unit_rand32(&st) >> (unit_rand32(&st) % 32u);
        bad += !floor_ok(v, fx_isqrt32(v));
    }
    CHECK_EQ_INT(fx_isqrt32(0), 0);
    CHECK_EQ_INT(fx_isqrt32(1), 1);
    CHECK_EQ_INT(fx_isqrt32(UINT32_MAX), 65535);
    CHECK_EQ_INT(fx_isqrt32(0xFFFE0001u), 65535); /* 65535^2 */
    CHECK_EQ_INT(fx_isqrt32(0xFFFE0000u), 65534);
    CHECK_EQ_INT(bad, 0);
    printf("MEASURED fx_isqrt32: exact (floor) on %lu inputs\n", total);
}

static void test_isqrt64(void)
{
    const uint32_t k_last = FX_DENSITY(1u << 16, 1u << 14);
    const long n_rand = FX_DENSITY(1L << 20, 1L << 16);
    unsigned long bad = 0, badr = 0, total = 0;
    uint32_t st = 11u;
    unsigned e;
    long i;
    uint32_t j;
    for (e = 0; e < 64u; e++) {
        int d;
        for (d = -3; d <= 3; d++, total++) {
            uint64_t v = ((uint64_t)1 << e) + (uint64_t)(int64_t)d; /* wraps near 0: fine */
            bad += !floor_ok(v, fx_isqrt64(v));
            badr += round64_bad(v);
        }
    }
    for (j = 0; j < k_last; j++) {
        uint64_t k = 0xFFFFFFFFu - j, sq = k * k, c[5];
        int m;
        c[0] = sq - 1u;
        c[1] = sq;
        c[2] = sq + k;
        c[3] = sq + k + 1u;
        c[4] = sq - k;
        for (m = 0; m < 5; m++, total++) {
            bad += !floor_ok(c[m], fx_isqrt64(c[m]));
            badr += round64_bad(c[m]);
        }
    }
    for (i = 0; i < n_rand; i++, total += 3) {
        uint64_t k = unit_rand32(&st) >> (unit_rand32(&st) % 32u), sq = k * k;
        uint64_t v = (((uint64_t)unit_rand32(&st) << 32) | unit_rand32(&st)) >>
                     (unit_rand32(&st) % 64u);
        bad += !floor_ok(v, fx_isqrt64(v)) + !floor_ok(sq + k, fx_isqrt64(sq + k));
        bad += !floor_ok(sq - (k != 0), fx_isqrt64(sq - (k != 0)));
        badr += round64_bad(v) + round64_bad(sq + k) + round64_bad(sq - k) +
                round64_bad(sq + k + 1u);
    }
    CHECK_EQ_INT(fx_isqrt64(0), 0);
    CHECK_EQ_HEX(fx_isqrt64(UINT64_MAX), 0xFFFFFFFFu);
    CHECK_EQ_HEX(fx_isqrt64((uint64_t)1 << 62), 0x80000000u);
    CHECK_EQ_HEX(fx_isqrt64_round(0xFFFFFFFF00000000ull), 0xFFFFFFFFu); /* last exact */
    CHECK_EQ_HEX(fx_isqrt64_round(0xFFFFFFFF00000001ull), 0xFFFFFFFFu); /* saturated */
    CHECK_EQ_HEX(fx_isqrt64_round(UINT64_MAX), 0xFFFFFFFFu);
    CHECK_EQ_HEX(fx_isqrt64_round(2), 1u);
    CHECK_EQ_HEX(fx_isqrt64_round(3), 2u);
    CHECK_EQ_HEX(fx_isqrt64_round(6), 2u);
    CHECK_EQ_HEX(fx_isqrt64_round(7), 3u);
    CHECK_EQ_INT(bad, 0);
    CHECK_EQ_INT(badr, 0);
    printf("MEASURED fx_isqrt64: exact (floor), fx_isqrt64_round: <= 0.5 LSB, on %lu inputs\n",
           total);
}

/* One Q sqrt over a stride, all small codes and random codes. shift = 16 or 30. */
static void sweep_q(const char *name, fx_q16_t (*fn)(int32_t), unsigned shift)
{
    const uint32_t stride = FX_DENSITY(521u, 32771u);
    const uint32_t small = FX_DENSITY(1u << 16, 1u << 14);
    const long n_rand = FX_DENSITY(1L << 20, 1L << 16);
    struct fxt_err err = {0};
    unsigned long bad = 0;
    uint32_t x, st = 5u;
    long i;
    for (i = -1; i < (long)(0x80000000u / stride) + n_rand + (long)small; i++) {
        int32_t r;
        if (i < 0)
            x = 0x7FFFFFFFu;
        else if (i < (long)(0x80000000u / stride))
            x = (uint32_t)i * stride;
        else if (i < (long)(0x80000000u / stride) + (long)small)
            x = (uint32_t)(i - (long)(0x80000000u / stride));
        else
            x = (unit_rand32(&st) >> 1) >> (unit_rand32(&st) % 31u);
        r = fn((int32_t)x);
        bad += !round_ok((uint64_t)x << shift, (uint64_t)(uint32_t)r);
        fxt_err_add(&err, (double)r - sqrt(ldexp((double)x, (int)shift)), x, r);
    }
    CHECK_EQ_INT(bad, 0);
    FXT_CHECK_ERR(err, 0.5);
    fxt_report(name, &err, 1.0 / ldexp(1.0, (int)shift), "");
}

static void test_sqrt_q(void)
{
    sweep_q("fx_sqrt_q16", fx_sqrt_q16, 16);
    sweep_q("fx_sqrt_q30", fx_sqrt_q30, 30);
    CHECK_EQ_INT(fx_sqrt_q16(FX_Q16_ONE), FX_Q16_ONE);
    CHECK_EQ_INT(fx_sqrt_q16(FX_Q16_INT(4)), FX_Q16_INT(2));
    CHECK_EQ_INT(fx_sqrt_q16(FX_Q16_INT(2)), 92682); /* 1.4142136 * 65536 = 92681.9 */
    CHECK_EQ_INT(fx_sqrt_q16(INT32_MAX), 11863283);  /* 181.019 */
    CHECK_EQ_INT(fx_sqrt_q16(1), 256);               /* sqrt(2^-16) = 2^-8 */
    CHECK_EQ_INT(fx_sqrt_q16(-1), 0);                /* clamp */
    CHECK_EQ_INT(fx_sqrt_q16(INT32_MIN), 0);
    CHECK_EQ_INT(fx_sqrt_q30(FX_Q30_ONE), FX_Q30_ONE);
    CHECK_EQ_INT(fx_sqrt_q30(FX_Q30_ONE / 4), FX_Q30_HALF);
    CHECK_EQ_INT(fx_sqrt_q30(INT32_MAX), 1518500250); /* sqrt(2 - 2^-30) */
    CHECK_EQ_INT(fx_sqrt_q30(1), 32768);              /* sqrt(2^-30) = 2^-15 */
    CHECK_EQ_INT(fx_sqrt_q30(-5), 0);
}

int main(void)
{
    UNIT_RUN(test_isqrt32);
    UNIT_RUN(test_isqrt64);
    UNIT_RUN(test_sqrt_q);
    return unit_report();
}
