/*
 * test_fx_div64.c - fx_udivmod64 / fx_divmod64 (base/fx/fx_div64.c) are C's 64-bit division,
 * bit for bit.
 *
 * Two independent proofs for every pair: (1) the defining properties, checked without any
 * division (a 64 x 64 -> 128-bit product from 32-bit halves): n = q d + r exactly and r < d
 * (unsigned); |n| = |q| |d| + |r|, |r| < |d|, r of n's sign, q of the sign of n d (signed). They
 * fix q and r uniquely. (2) The compiler's own `/` and `%`: on the host the machine's divide
 * instruction; on the Cortex-M0+ those operators are __aeabi_uldivmod / __aeabi_ldivmod, which
 * fx_div64.c provides there, so the comparison proves the entry points' register hand-over
 * (quotient r0:r1, remainder r2:r3). Inputs: edge cases and random pairs of every magnitude
 * (each operand shifted right by a random 0..63). A CRC-32 of the results of the first 20 000
 * random pairs is a constant across targets.
 */
#include "fx_test_int.h"

#define DIV64_CRC 0x52da9cfau /* the test prints the value it computes */

static uint32_t crc;
static bool crc_on; /* the first DIV64_CRC_PAIRS random pairs: the same on every target */
#define DIV64_CRC_PAIRS 20000ul

static void crc_u64(uint64_t v)
{
    unsigned i;
    int k;
    if (!crc_on) return;
    for (i = 0; i < 8u; i++) {
        crc ^= (uint8_t)(v >> (8u * i));
        for (k = 0; k < 8; k++)
            crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
}

static uint64_t rand64(uint32_t *st)
{
    const uint64_t hi = unit_rand32(st);
    return (hi << 32) | unit_rand32(st);
}

/* a * b as 128 bits (hi, lo), from 32-bit halves: no division. */
static void mul128(uint64_t a, uint64_t b, uint64_t *hi, uint64_t *lo)
{
    const uint64_t a0 = (uint32_t)a, a1 = a >> 32, b0 = (uint32_t)b, b1 = b >> 32;
    const uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
    const uint64_t mid = (p00 >> 32) + (uint32_t)p01 + (uint32_t)p10;
    *lo = (mid << 32) | (uint32_t)p00;
    *hi = p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
}

/* n = q d + r exactly (no wrap) and r < d. */
static bool props_u(uint64_t n, uint64_t d, uint64_t q, uint64_t r)
{
    uint64_t hi, lo;
    mul128(q, d, &hi, &lo);
    return r < d && hi == 0u && lo <= UINT64_MAX - r && lo + r == n;
}

static uint64_t mag(int64_t v)
{
    return v < 0 ? 0u - (uint64_t)v : (uint64_t)v;
}

static bool props_s(int64_t n, int64_t d, int64_t q, int64_t r)
{
    if (!props_u(mag(n), mag(d), mag(q), mag(r))) return false;
    if (r != 0 && (r < 0) != (n < 0)) return false;
    return q == 0 || (q < 0) == ((n < 0) != (d < 0));
}

static unsigned bad_u, bad_s;

static void one_u(uint64_t n, uint64_t d)
{
    uint64_t r = 0;
    const uint64_t q = fx_udivmod64(n, d, &r);
    /* volatile: the compiler must divide at run time (on the M0+ through __aeabi_uldivmod) */
    volatile uint64_t vn = n, vd = d;
    const uint64_t cq = vn / vd, cr = vn % vd;
    crc_u64(q);
    crc_u64(r);
    if (!props_u(n, d, q, r) || q != cq || r != cr || fx_udivmod64(n, d, NULL) != q) {
        if (bad_u++ == 0u)
            printf("udivmod64 0x%llx / 0x%llx: 0x%llx r 0x%llx, C 0x%llx r 0x%llx\n",
                   (unsigned long long)n, (unsigned long long)d, (unsigned long long)q,
                   (unsigned long long)r, (unsigned long long)cq, (unsigned long long)cr);
    }
}

static void one_s(int64_t n, int64_t d)
{
    int64_t r = 0;
    const int64_t q = fx_divmod64(n, d, &r);
    volatile int64_t vn = n, vd = d;
    const int64_t cq = vn / vd, cr = vn % vd;
    crc_u64((uint64_t)q);
    crc_u64((uint64_t)r);
    if (!props_s(n, d, q, r) || q != cq || r != cr || fx_divmod64(n, d, NULL) != q) {
        if (bad_s++ == 0u)
            printf("divmod64 %lld / %lld: %lld r %lld, C %lld r %lld\n", (long long)n, (long long)d,
                   (long long)q, (long long)r, (long long)cq, (long long)cr);
    }
}

static const uint64_t edges[] = {0u,
                                 1u,
                                 2u,
                                 3u,
                                 7u,
                                 0xFFFFu,
                                 0x10000u,
                                 0x7FFFFFFFu,
                                 0x80000000u,
                                 0xFFFFFFFFu,
                                 0x100000000u,
                                 0x100000001u,
                                 0x123456789ABCDEFu,
                                 0x7FFFFFFFFFFFFFFFu,
                                 0x8000000000000000u,
                                 0x8000000000000001u,
                                 0xFFFFFFFF00000000u,
                                 0xFFFFFFFFFFFFFFFEu,
                                 0xFFFFFFFFFFFFFFFFu};
#define N_EDGES (sizeof(edges) / sizeof(edges[0]))

static void test_edges(void)
{
    unsigned i, j;
    bad_u = bad_s = 0u;
    for (i = 0; i < N_EDGES; i++) {
        for (j = 0; j < N_EDGES; j++) {
            const int64_t sn = (int64_t)(edges[i] >> 1), sd = (int64_t)(edges[j] >> 1);
            if (edges[j] != 0u) one_u(edges[i], edges[j]);
            if (sd != 0) {
                one_s(sn, sd);
                one_s(-sn, sd);
                one_s(sn, -sd);
                one_s(-sn, -sd);
            }
            if (edges[j] > 1u && (edges[j] >> 1) < (uint64_t)INT64_MAX)
                one_s(INT64_MIN, (int64_t)(edges[j] >> 1) + 1);
        }
    }
    CHECK_EQ_INT(bad_u, 0);
    CHECK_EQ_INT(bad_s, 0);
}

static void test_random(void)
{
    uint32_t st = 0x2545F491u;
    unsigned long k;
    const unsigned long n_pairs = (unsigned long)UNIT_SIZE(1000000, 20000);
    bad_u = bad_s = 0u;
    crc = 0xFFFFFFFFu;
    for (k = 0; k < n_pairs; k++) {
        crc_on = k < DIV64_CRC_PAIRS;
        /* one draw per statement: the order of two calls in one expression is unspecified */
        const uint64_t n0 = rand64(&st);
        const uint64_t n = n0 >> (unit_rand32(&st) % 64u);
        const uint64_t d0 = rand64(&st);
        const uint64_t d = d0 >> (unit_rand32(&st) % 64u);
        if (d == 0u) continue;
        one_u(n, d);
        if (!((int64_t)n == INT64_MIN && (int64_t)d == -1)) {
            one_s((int64_t)n, (int64_t)d);
        }
        if ((d >> 1) < (uint64_t)INT64_MAX)
            one_s((int64_t)(n >> 1) * ((k & 1u) ? -1 : 1), (int64_t)(d >> 1) + 1);
    }
    crc_on = false;
    CHECK_EQ_INT(bad_u, 0);
    CHECK_EQ_INT(bad_s, 0);
    /* the same bits on every target */
    printf("div64 crc of the first %lu pairs 0x%08lx\n", DIV64_CRC_PAIRS, (unsigned long)crc);
    CHECK_EQ_HEX(crc, DIV64_CRC);
}

/* What C leaves undefined, as fx.h documents it. */
static void test_documented_cases(void)
{
    uint64_t ur = 0;
    int64_t r = 0;
    CHECK_EQ_HEX(fx_udivmod64(12345u, 0u, &ur), UINT64_MAX);
    CHECK_EQ_HEX(ur, 12345u);
    CHECK_EQ_INT(fx_divmod64(5, 0, &r), INT64_MAX);
    CHECK_EQ_INT(r, 5);
    CHECK_EQ_INT(fx_divmod64(-5, 0, &r), INT64_MIN);
    CHECK_EQ_INT(r, -5);
    CHECK_EQ_INT(fx_divmod64(0, 0, &r), 0);
    CHECK_EQ_INT(r, 0);
    CHECK_EQ_INT(fx_divmod64(INT64_MIN, -1, &r), INT64_MIN);
    CHECK_EQ_INT(r, 0);
}

int main(void)
{
    UNIT_RUN(test_edges);
    UNIT_RUN(test_random);
    UNIT_RUN(test_documented_cases);
    return unit_report();
}
