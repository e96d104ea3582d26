/*
 * test_fx128.c - proves the contracts of inclino/fx128.h.
 *
 * Every target: exact vectors computed with Python's big integers (fx128_vectors.h, from
 * gen_fx128_vectors.py): products, saturating sums and differences, rounding shifts for every
 * shift class (0, <64, 64, >64, 128, >128) with ties, and divisions with ties, zero divisors and
 * out-of-range quotients. On a host compiler with __int128 the same functions are also compared
 * with the compiler's 128-bit arithmetic on random operands of every magnitude.
 */
#include <stdint.h>
#include <stdio.h>

#include "fx128_vectors.h"
#include "fx_test_int.h"
#include "inclino/fx128.h"
#include "unit.h"

#define N_OF(a) (sizeof(a) / sizeof((a)[0]))

static fx_i128_t mk(uint64_t lo, uint64_t hi)
{
    fx_i128_t r;
    r.lo = lo;
    r.hi = hi;
    return r;
}

static void test_mul_vectors(void)
{
    size_t i;
    for (i = 0; i < N_OF(V_MUL); i++) {
        fx_i128_t p = fx_i128_mul(V_MUL[i].a, V_MUL[i].b);
        CHECK_EQ_HEX(p.lo, V_MUL[i].lo);
        CHECK_EQ_HEX(p.hi, V_MUL[i].hi);
    }
}

static void test_add_sub_vectors(void)
{
    size_t i;
    for (i = 0; i < N_OF(V_ADD); i++) {
        fx_i128_t a = mk(V_ADD[i].alo, V_ADD[i].ahi), b = mk(V_ADD[i].blo, V_ADD[i].bhi);
        fx_i128_t s = fx_i128_add(a, b), d = fx_i128_sub(a, b);
        CHECK_EQ_HEX(s.lo, V_ADD[i].slo);
        CHECK_EQ_HEX(s.hi, V_ADD[i].shi);
        CHECK_EQ_HEX(d.lo, V_ADD[i].dlo);
        CHECK_EQ_HEX(d.hi, V_ADD[i].dhi);
    }
}

static void test_shift_vectors(void)
{
    size_t i;
    for (i = 0; i < N_OF(V_SHR); i++) {
        bool sat = false;
        int64_t r = fx_i128_rshift_round(mk(V_SHR[i].lo, V_SHR[i].hi), V_SHR[i].s, &sat);
        CHECK_EQ_INT(r, V_SHR[i].r);
        CHECK_EQ_INT(sat, V_SHR[i].sat);
        /* sat is only ever set, never cleared */
        sat = true;
        (void)fx_i128_rshift_round(mk(V_SHR[i].lo, V_SHR[i].hi), V_SHR[i].s, &sat);
        CHECK(sat);
        /* NULL flag pointer is allowed */
        CHECK_EQ_INT(fx_i128_rshift_round(mk(V_SHR[i].lo, V_SHR[i].hi), V_SHR[i].s, NULL),
                     V_SHR[i].r);
    }
}

static void test_div_vectors(void)
{
    size_t i;
    for (i = 0; i < N_OF(V_DIV); i++) {
        int64_t q = 12345;
        int err = fx_i128_div_i64(mk(V_DIV[i].lo, V_DIV[i].hi), V_DIV[i].den, &q);
        CHECK_EQ_INT(err, V_DIV[i].err);
        CHECK_EQ_INT(q, V_DIV[i].q);
    }
    CHECK_ERR(fx_i128_div_i64(fx_i128_from_i64(1), 1, NULL), INC_ERR_NULL);
}

static void test_small_helpers(void)
{
    fx_i128_t m1 = fx_i128_from_i64(-1), z = fx_i128_from_i64(0),
              big = fx_i128_mul(INT64_MIN, INT64_MIN);
    CHECK_EQ_HEX(m1.lo, UINT64_MAX);
    CHECK_EQ_HEX(m1.hi, UINT64_MAX);
    CHECK(fx_i128_is_neg(m1));
    CHECK(!fx_i128_is_neg(z));
    CHECK(!fx_i128_is_neg(big)); /* 2^126 */
    CHECK_EQ_INT(fx_i128_cmp(m1, z), -1);
    CHECK_EQ_INT(fx_i128_cmp(z, m1), 1);
    CHECK_EQ_INT(fx_i128_cmp(big, big), 0);
    CHECK_EQ_INT(fx_i128_cmp(big, fx_i128_from_i64(INT64_MAX)), 1);
    CHECK_EQ_INT(fx_i128_cmp(fx_i128_from_i64(-5), fx_i128_from_i64(-4)), -1);
    CHECK_EQ_INT(fx_i128_cmp(fx_i128_mul(INT64_MIN, INT64_MAX), fx_i128_from_i64(INT64_MIN)), -1);
    /* mac = add(acc, mul) with saturation */
    {
        fx_i128_t acc = fx_i128_mac(fx_i128_from_i64(7), 3, -5);
        CHECK_EQ_INT(fx_i128_rshift_round(acc, 0, NULL), -8);
        acc = fx_i128_mac(big, INT64_MIN, INT64_MIN); /* 2^127: saturates to 2^127 - 1 */
        CHECK_EQ_HEX(acc.hi, UINT64_MAX >> 1);
        CHECK_EQ_HEX(acc.lo, UINT64_MAX);
    }
}

#if defined(__SIZEOF_INT128__)
typedef __int128 i128;

static i128 to_n(fx_i128_t x)
{
    unsigned __int128 u = ((unsigned __int128)x.hi << 64) | x.lo;
    return (i128)u;
}

static fx_i128_t from_n(i128 v)
{
    unsigned __int128 u = (unsigned __int128)v;
    return mk((uint64_t)u, (uint64_t)(u >> 64));
}

static int64_t rnd64(uint32_t *st)
{
    uint64_t r = ((uint64_t)unit_rand32(st) << 32) | unit_rand32(st);
    unsigned sh = unit_rand32(st) % 64u;
    int64_t m = (int64_t)((r >> 1) >> sh);
    return (r & 1u) ? -m - 1 : m;
}

/* round(n / d) ties away, n, d as __int128, d != 0, |n/d| < 2^126. */
static i128 ref_round_div(i128 n, i128 d)
{
    int neg = (n < 0) != (d < 0);
    unsigned __int128 un = n < 0 ? -(unsigned __int128)n : (unsigned __int128)n;
    unsigned __int128 ud = d < 0 ? -(unsigned __int128)d : (unsigned __int128)d;
    unsigned __int128 q = un / ud, r = un % ud;
    if (r >= ud - r) q++;
    return neg ? -(i128)q : (i128)q;
}

static void test_random_against_int128(void)
{
    uint32_t st = 0x1234567u;
    long i, n = FX_DENSITY(2000000L, 100000L);
    unsigned fails = 0;
    for (i = 0; i < n && fails < 20u; i++) {
        int64_t a = rnd64(&st), b = rnd64(&st), c = rnd64(&st);
        i128 p = (i128)a * b;
        fx_i128_t fp = fx_i128_mul(a, b);
        unsigned s = unit_rand32(&st) % 127u;
        bool sat = false;
        int64_t r;
        i128 rr;
        if (to_n(fp) != p) fails++;
        /* accumulate: p + a*c (|sum| < 2^127) */
        if (to_n(fx_i128_mac(fp, a, c)) != p + (i128)a * c) fails++;
        if (to_n(fx_i128_sub(fp, fx_i128_from_i64(c))) != p - c) fails++;
        /* rounding shift */
        r = fx_i128_rshift_round(fp, s, &sat);
        rr = s == 0 ? p : ref_round_div(p, (i128)1 << s);
        if (rr > INT64_MAX || rr < INT64_MIN) {
            if (!sat || r != (rr > 0 ? INT64_MAX : INT64_MIN)) fails++;
        } else if (sat || r != (int64_t)rr) {
            fails++;
        }
        /* division by c */
        if (c != 0) {
            int64_t q = 0;
            int err = fx_i128_div_i64(fp, c, &q);
            i128 qq;
            unsigned __int128 up = p < 0 ? -(unsigned __int128)p : (unsigned __int128)p;
            unsigned __int128 uc = c < 0 ? -(unsigned __int128)c : (unsigned __int128)c;
            if ((up >> 64) >= uc) {
                if (err != INC_ERR_RANGE) fails++;
            } else {
                qq = ref_round_div(p, c);
                if (qq > INT64_MAX || qq < INT64_MIN) {
                    if (err != INC_ERR_RANGE || q != (qq > 0 ? INT64_MAX : INT64_MIN)) fails++;
                } else if (err != INC_OK || q != (int64_t)qq) {
                    fails++;
                }
            }
            /* a quotient that fits: (q * c + rem) / c */
            {
                int64_t q0 = rnd64(&st) / 4, q2 = 0;
                int64_t mc = c == INT64_MIN ? INT64_MAX : (c < 0 ? -c : c);
                i128 num = (i128)q0 * c + (i128)(rnd64(&st) % mc);
                if (fx_i128_div_i64(from_n(num), c, &q2) != INC_OK ||
                    q2 != (int64_t)ref_round_div(num, c)) {
                    fails++;
                }
            }
        }
    }
    CHECK_EQ_INT(fails, 0);
    printf("random vs __int128: %ld cases\n", i);
}
#endif

int main(void)
{
    UNIT_RUN(test_mul_vectors);
    UNIT_RUN(test_add_sub_vectors);
    UNIT_RUN(test_shift_vectors);
    UNIT_RUN(test_div_vectors);
    UNIT_RUN(test_small_helpers);
#if defined(__SIZEOF_INT128__)
    UNIT_RUN(test_random_against_int128);
#endif
    return unit_report();
}
