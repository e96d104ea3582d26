/*
 * SCA3000 pure conversions: decoding of the register words, counts -> ug / Q16.16 g and the
 * D01 temperature -> Q16.16 degC, against vectors computed with exact rational arithmetic
 * (Python fractions, round half away from zero), plus an exhaustive sweep that proves the
 * stated error bound (0.5 LSB of Q16.16) over every input.
 */
#include "inclino/sca3000.h"
#include "unit.h"

#include <stddef.h>

struct vec {
    int32_t in;
    int32_t out;
};

static void test_decode_accel(void)
{
    int16_t c = 0x5555;
    CHECK_OK(sca3000_accel_counts_from_word(0x0000, &c));
    CHECK_EQ_INT(c, 0);
    CHECK_OK(sca3000_accel_counts_from_word(0x0008, &c));
    CHECK_EQ_INT(c, 1);
    CHECK_OK(sca3000_accel_counts_from_word(0xFFF8, &c));
    CHECK_EQ_INT(c, -1);
    CHECK_OK(sca3000_accel_counts_from_word(0x7FF8, &c));
    CHECK_EQ_INT(c, 4095);
    CHECK_OK(sca3000_accel_counts_from_word(0x8000, &c));
    CHECK_EQ_INT(c, -4096);
    CHECK_OK(sca3000_accel_counts_from_word(0x29A8, &c)); /* 1333 << 3 */
    CHECK_EQ_INT(c, 1333);
    CHECK_OK(
        sca3000_accel_counts_from_word(0xD658, &c)); /* -1333 << 3 (two's complement, 16 bit) */
    CHECK_EQ_INT(c, -1333);
    /* bits[2:0] are always 0 on the part: anything else is not a reply of the part. */
    c = 77;
    CHECK_ERR(sca3000_accel_counts_from_word(0xFFFF, &c), INC_ERR_BUS);
    CHECK_ERR(sca3000_accel_counts_from_word(0x0001, &c), INC_ERR_BUS);
    CHECK_ERR(sca3000_accel_counts_from_word(0x0004, &c), INC_ERR_BUS);
    CHECK_EQ_INT(c, 77); /* untouched on error */
    CHECK_ERR(sca3000_accel_counts_from_word(0x0000, NULL), INC_ERR_NULL);
}

static void test_decode_ring_and_temp(void)
{
    CHECK_EQ_INT(sca3000_ring_counts_from_word(0x0000), 0);
    CHECK_EQ_INT(sca3000_ring_counts_from_word(0x0020), 4);
    CHECK_EQ_INT(sca3000_ring_counts_from_word(0xFFE0), -4);
    CHECK_EQ_INT(sca3000_ring_counts_from_word(0x7FE0), 4092);
    CHECK_EQ_INT(sca3000_ring_counts_from_word(0x8000), -4096);
    CHECK_EQ_INT(sca3000_ring_counts_from_word(0x001F), 0);   /* bits[4:0] are not data */
    CHECK_EQ_INT(sca3000_ring_counts_from_word(0x0A60), 332); /* 83 << 5 */

    CHECK_EQ_INT(sca3000_temp_counts_from_word(0x2080), 260); /* 260 << 5 */
    CHECK_EQ_INT(sca3000_temp_counts_from_word(0x3FE0), 511);
    CHECK_EQ_INT(sca3000_temp_counts_from_word(0xC000), 0); /* bits 15:14 are not data */
    CHECK_EQ_INT(sca3000_temp_counts_from_word(0x001F), 0); /* nor bits 4:0 */
    CHECK_EQ_INT(sca3000_temp_counts_from_word(0x1AC0), 214);
}

static void check_accel_vectors(enum sca3000_variant v, const struct vec *t, size_t n, int32_t ug)
{
    size_t i;
    CHECK_EQ_INT(sca3000_ug_per_lsb(v), ug);
    for (i = 0; i < n; i++) {
        int32_t g = 0x7777, u = 0;
        CHECK_OK(sca3000_accel_g_from_counts(t[i].in, v, &g));
        CHECK_EQ_INT(g, t[i].out);
        CHECK_OK(sca3000_accel_ug_from_counts(t[i].in, v, &u));
        CHECK_EQ_INT(u, t[i].in * ug);
    }
}

static void test_accel_vectors(void)
{
    static const struct vec d01[] = {
        {0, 0},     {1, 49},       {-1, -49},       {2, 98},        {-2, -98},       {7, 344},
        {-7, -344}, {1333, 65520}, {-1333, -65520}, {4095, 201277}, {-4096, -201327}};
    static const struct vec e02[] = {
        {0, 0},     {1, 66},       {-1, -66},       {2, 131},       {-2, -131},      {7, 459},
        {-7, -459}, {1333, 87359}, {-1333, -87359}, {4095, 268370}, {-4096, -268435}};
    static const struct vec e04[] = {
        {0, 0},     {1, 131},       {-1, -131},       {2, 262},       {-2, -262},      {7, 918},
        {-7, -918}, {1333, 174719}, {-1333, -174719}, {4095, 536740}, {-4096, -536871}};
    static const struct vec e05[] = {
        {0, 0},      {1, 410},       {-1, -410},       {2, 819},        {-2, -819},       {7, 2867},
        {-7, -2867}, {1333, 545997}, {-1333, -545997}, {4095, 1677312}, {-4096, -1677722}};
    check_accel_vectors(SCA3000_D01, d01, sizeof(d01) / sizeof(d01[0]), 750);
    check_accel_vectors(SCA3000_E02, e02, sizeof(e02) / sizeof(e02[0]), 1000);
    check_accel_vectors(SCA3000_E04, e04, sizeof(e04) / sizeof(e04[0]), 2000);
    check_accel_vectors(SCA3000_E05, e05, sizeof(e05) / sizeof(e05[0]), 6250);
}

static void test_accel_errors(void)
{
    int32_t g = 123;
    CHECK_ERR(sca3000_accel_g_from_counts(4096, SCA3000_D01, &g), INC_ERR_RANGE);
    CHECK_ERR(sca3000_accel_g_from_counts(-4097, SCA3000_D01, &g), INC_ERR_RANGE);
    CHECK_ERR(sca3000_accel_g_from_counts(0, SCA3000_E01, &g), INC_ERR_INVAL);
    CHECK_ERR(sca3000_accel_g_from_counts(0, (enum sca3000_variant)9, &g), INC_ERR_INVAL);
    CHECK_ERR(sca3000_accel_g_from_counts(0, SCA3000_D01, NULL), INC_ERR_NULL);
    CHECK_ERR(sca3000_accel_ug_from_counts(5000, SCA3000_E05, &g), INC_ERR_RANGE);
    CHECK_ERR(sca3000_accel_ug_from_counts(0, SCA3000_E01, &g), INC_ERR_INVAL);
    CHECK_EQ_INT(g, 123);
    CHECK_EQ_INT(sca3000_ug_per_lsb(SCA3000_E01), 0);
}

/* Every input of every variant: |q * 1e6 - counts * ug * 65536| <= 5e5 (0.5 LSB), and odd
 * symmetry (ties away from zero makes f(-c) = -f(c)). */
static void test_accel_bound_exhaustive(void)
{
    unsigned v;
    for (v = 0; v <= (unsigned)SCA3000_E05; v++) {
        const int64_t ug = (int64_t)sca3000_ug_per_lsb((enum sca3000_variant)v);
        int64_t worst = 0;
        int32_t c;
        unsigned bad = 0;
        for (c = -4096; c <= 4095; c++) {
            int32_t q = 0, qn = 0;
            int64_t diff;
            if (sca3000_accel_g_from_counts(c, (enum sca3000_variant)v, &q) != 0) {
                bad++;
                continue;
            }
            diff = (int64_t)q * 1000000 - (int64_t)c * ug * 65536;
            if (diff < 0) diff = -diff;
            if (diff > worst) worst = diff;
            if (c > -4096 &&
                (sca3000_accel_g_from_counts(-c, (enum sca3000_variant)v, &qn) != 0 || qn != -q)) {
                bad++;
            }
        }
        CHECK_EQ_INT(bad, 0);
        CHECK(worst <= 500000);
        CHECK(worst >= 400000); /* near the bound: the sweep really measures the rounding */
    }
}

static void test_temperature(void)
{
    static const struct vec t[] = {{0, -7813348},   {1, -7776939},  {214, -21845},
                                   {215, 14564},    {260, 1652964}, {322, 3910315},
                                   {511, 10791595}, {196, -677205}, {100, -4172459}};
    size_t i;
    int32_t c = 99;
    int32_t raw;
    int64_t worst = 0;
    for (i = 0; i < sizeof(t) / sizeof(t[0]); i++) {
        CHECK_OK(sca3000_temp_c_from_counts(t[i].in, &c));
        CHECK_EQ_INT(c, t[i].out);
    }
    for (raw = 0; raw <= 511; raw++) {
        int64_t d;
        CHECK_OK(sca3000_temp_c_from_counts(raw, &c));
        d = (int64_t)c * 18 - ((int64_t)raw * 10 - 2146) * 65536;
        if (d < 0) d = -d;
        if (d > worst) worst = d;
    }
    CHECK(worst <= 9); /* 0.5 LSB of Q16.16 in units of 1/18 */
    c = 99;
    CHECK_ERR(sca3000_temp_c_from_counts(512, &c), INC_ERR_RANGE);
    CHECK_ERR(sca3000_temp_c_from_counts(-1, &c), INC_ERR_RANGE);
    CHECK_ERR(sca3000_temp_c_from_counts(0, NULL), INC_ERR_NULL);
    CHECK_EQ_INT(c, 99);
}

int main(void)
{
    UNIT_RUN(test_decode_accel);
    UNIT_RUN(test_decode_ring_and_temp);
    UNIT_RUN(test_accel_vectors);
    UNIT_RUN(test_accel_errors);
    UNIT_RUN(test_accel_bound_exhaustive);
    UNIT_RUN(test_temperature);
    return unit_report();
}
