/*
 * Cycle <-> ns conversion (hal/cycles): exact where the clock divides 1e9, within the
 * documented bounds everywhere else, against references computed exactly in 64-bit integers.
 * Runs on the host, under QEMU on Cortex-M and on rv32: the results are bit-identical.
 */
#include <stddef.h>
#include <stdint.h>

#include "inclino/hal_cycles.h"
#include "unit.h"

static const uint32_t clocks[] = {
    HAL_CYC_HZ_MIN, 1000003u,   8000000u,   16000000u,  25000000u,  48000000u,  72000000u,
    120000000u,     168000000u, 180000000u, 216000000u, 480000000u, 999999999u, HAL_CYC_HZ_MAX,
};

static const uint64_t cycle_counts[] = {
    0u,
    1u,
    2u,
    3u,
    999u,
    1000u,
    0xFFFFFFu,
    0x1000000u,
    0xFFFFFFFFu,
    0x100000000ull,
    0x100000001ull,
    0x123456789ull,
    (1ull << 40) + 12345u,
    (1ull << 48) - 1u,
    1ull << 53,
};

static const uint32_t delays_ns[] = {
    0u,    1u,    2u,     39u,      40u,        41u,         100u,        999u,
    1000u, 1001u, 65535u, 1000000u, 123456789u, 1000000000u, 0xFFFFFFFFu,
};

/* floor(cycles * 1e9 / hz), exact: split cycles into whole seconds and a remainder. */
static uint64_t ref_ns(uint64_t cycles, uint32_t hz)
{
    return (cycles / hz) * 1000000000ull + ((cycles % hz) * 1000000000ull) / hz;
}

/* ceil(ns * hz / 1e9), exact: ns * hz < 2^32 * 2^30. */
static uint64_t ref_cycles(uint32_t ns, uint32_t hz)
{
    return ((uint64_t)ns * hz + 999999999u) / 1000000000u;
}

static void test_init_rejects_bad_arguments(void)
{
    struct hal_cyc_conv c = {0xAAAAAAAAu, 0x5555u, 0x7777u};
    CHECK_ERR(hal_cyc_init(NULL, 25000000u), INC_ERR_NULL);
    CHECK_ERR(hal_cyc_init(&c, 0u), INC_ERR_INVAL);
    CHECK_ERR(hal_cyc_init(&c, HAL_CYC_HZ_MIN - 1u), INC_ERR_INVAL);
    CHECK_ERR(hal_cyc_init(&c, HAL_CYC_HZ_MAX + 1u), INC_ERR_INVAL);
    CHECK_ERR(hal_cyc_init(&c, 0xFFFFFFFFu), INC_ERR_INVAL);
    /* A rejected init leaves the struct alone. */
    CHECK_EQ_HEX(c.hz, 0xAAAAAAAAu);
    CHECK_EQ_HEX(c.ns_per_cyc_q32, 0x5555u);
    CHECK_EQ_HEX(c.cyc_per_ns_q32, 0x7777u);
    CHECK_OK(hal_cyc_init(&c, HAL_CYC_HZ_MIN));
    CHECK_OK(hal_cyc_init(&c, HAL_CYC_HZ_MAX));
}

static void test_factors(void)
{
    struct hal_cyc_conv c;
    REQUIRE(hal_cyc_init(&c, 25000000u) == 0);
    CHECK_EQ_INT(c.hz, 25000000);
    CHECK_EQ_HEX(c.ns_per_cyc_q32, 40ull << 32); /* 40 ns per cycle, exactly */
    CHECK_EQ_HEX(c.cyc_per_ns_q32, 107374183u);  /* ceil(0.025 * 2^32) */
    REQUIRE(hal_cyc_init(&c, HAL_CYC_HZ_MAX) == 0);
    CHECK_EQ_HEX(c.ns_per_cyc_q32, 1ull << 32);
    CHECK_EQ_HEX(c.cyc_per_ns_q32, 1ull << 32);
    REQUIRE(hal_cyc_init(&c, 168000000u) == 0);
    CHECK_EQ_HEX(c.ns_per_cyc_q32, 25565281523ull); /* floor(1e9 * 2^32 / 168e6) */
    CHECK_EQ_HEX(c.cyc_per_ns_q32, 721554506u);     /* ceil(168e6 * 2^32 / 1e9) */
}

static void test_mul_q32(void)
{
    CHECK_EQ_HEX(hal_cyc_mul_q32(0u, 0xFFFFFFFFFFFFFFFFull), 0u);
    CHECK_EQ_HEX(hal_cyc_mul_q32(1ull << 32, 1ull << 32), 1ull << 32);
    CHECK_EQ_HEX(hal_cyc_mul_q32(1ull << 63, 2u), 1ull << 32);
    CHECK_EQ_HEX(hal_cyc_mul_q32(0xFFFFFFFFFFFFFFFFull, 1u), 0xFFFFFFFFu);
    CHECK_EQ_HEX(hal_cyc_mul_q32(0xFFFFFFFFFFFFFFFFull, 1ull << 32), 0xFFFFFFFFFFFFFFFFull);
    CHECK_EQ_HEX(hal_cyc_mul_q32((1ull << 40) + 7u, 3ull << 32), 3ull * ((1ull << 40) + 7u));
    /* (2^32 - 1)^2 / 2^32 = 2^32 - 2 + 1/2^32 -> floor 2^32 - 2 */
    CHECK_EQ_HEX(hal_cyc_mul_q32(0xFFFFFFFFu, 0xFFFFFFFFu), 0xFFFFFFFEu);
    /* (2^64 - 1) * (2^32 + 1) / 2^32 does not fit 64 bits: it wraps, as documented */
    CHECK_EQ_HEX(hal_cyc_mul_q32(0xFFFFFFFFFFFFFFFFull, 0x100000001ull), 0xFFFFFFFEull);
}

static void test_exact_clocks_convert_exactly(void)
{
    struct hal_cyc_conv c;
    size_t i;
    REQUIRE(hal_cyc_init(&c, 25000000u) == 0);
    for (i = 0; i < sizeof(cycle_counts) / sizeof(cycle_counts[0]); i++) {
        CHECK_EQ_HEX(hal_cyc_to_ns(&c, cycle_counts[i]), cycle_counts[i] * 40u);
    }
    REQUIRE(hal_cyc_init(&c, HAL_CYC_HZ_MAX) == 0);
    for (i = 0; i < sizeof(delays_ns) / sizeof(delays_ns[0]); i++) {
        CHECK_EQ_HEX(hal_ns_to_cyc_ceil(&c, delays_ns[i]), delays_ns[i]);
        CHECK_EQ_HEX(hal_cyc_to_ns(&c, delays_ns[i]), delays_ns[i]);
    }
    REQUIRE(hal_cyc_init(&c, HAL_CYC_HZ_MIN) == 0);
    CHECK_EQ_HEX(hal_cyc_to_ns(&c, 1ull << 53), (1ull << 53) * 1000u);
}

static void test_to_ns_within_bound(void)
{
    size_t h, i;
    for (h = 0; h < sizeof(clocks) / sizeof(clocks[0]); h++) {
        struct hal_cyc_conv c;
        uint64_t prev = 0u;
        REQUIRE(hal_cyc_init(&c, clocks[h]) == 0);
        for (i = 0; i < sizeof(cycle_counts) / sizeof(cycle_counts[0]); i++) {
            uint64_t cyc = cycle_counts[i];
            uint64_t got = hal_cyc_to_ns(&c, cyc);
            uint64_t ref = ref_ns(cyc, clocks[h]);
            /* ref - ceil(cycles / 2^32) <= got <= ref (see hal_cycles.h) */
            uint64_t slack = (cyc >> 32) + ((cyc & 0xFFFFFFFFu) != 0u ? 1u : 0u);
            CHECK(got <= ref);
            CHECK(got + slack >= ref);
            CHECK(got >= prev); /* the counts are increasing: so are the results */
            prev = got;
        }
    }
}

static void test_ns_to_cycles_never_short(void)
{
    size_t h, i;
    for (h = 0; h < sizeof(clocks) / sizeof(clocks[0]); h++) {
        struct hal_cyc_conv c;
        REQUIRE(hal_cyc_init(&c, clocks[h]) == 0);
        for (i = 0; i < sizeof(delays_ns) / sizeof(delays_ns[0]); i++) {
            uint64_t got = hal_ns_to_cyc_ceil(&c, delays_ns[i]);
            uint64_t ref = ref_cycles(delays_ns[i], clocks[h]);
            CHECK(got >= ref);
            CHECK(got <= ref + 1u);
        }
    }
    {
        struct hal_cyc_conv c;
        REQUIRE(hal_cyc_init(&c, 25000000u) == 0);
        CHECK_EQ_INT(hal_ns_to_cyc_ceil(&c, 0u), 0);
        CHECK_EQ_INT(hal_ns_to_cyc_ceil(&c, 1u), 1);
        /* Exactly 25 and 25e6 cycles; the factor is rounded up, so one more (within bound). */
        CHECK_EQ_INT(hal_ns_to_cyc_ceil(&c, 1000u), 26);
        CHECK_EQ_INT(hal_ns_to_cyc_ceil(&c, 1000000000u), 25000001);
    }
}

int main(void)
{
    UNIT_RUN(test_init_rejects_bad_arguments);
    UNIT_RUN(test_factors);
    UNIT_RUN(test_mul_q32);
    UNIT_RUN(test_exact_clocks_convert_exactly);
    UNIT_RUN(test_to_ns_within_bound);
    UNIT_RUN(test_ns_to_cycles_never_short);
    return unit_report();
}
