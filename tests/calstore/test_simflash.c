/* The NOR flash emulation itself: erase/program semantics, reprogram policies, alignment,
 * steps, the three power-cut modes and their torn states, and the fault back doors. */
#include <string.h>

#include "inclino/simflash.h"
#include "unit.h"

static uint8_t mem[4 * 64];
static const struct simflash_geometry geo = {64u, 4u, 4u}; /* page 64 B, 4 pages, unit 4 B */

static void setup(struct simflash *f)
{
    int err = simflash_init(f, mem, sizeof mem, &geo);
    CHECK_OK(err);
}

static void test_init(void)
{
    struct simflash f;
    struct simflash_geometry g = geo;
    unsigned i, erased = 0;

    memset(mem, 0, sizeof mem);
    setup(&f);
    for (i = 0; i < sizeof mem; i++) {
        erased += mem[i] == 0xFFu;
    }
    CHECK_EQ_INT(erased, sizeof mem);
    CHECK(simflash_powered(&f));
    CHECK_EQ_INT(simflash_steps(&f), 0);
    CHECK_ERR(simflash_init(NULL, mem, sizeof mem, &geo), INC_ERR_NULL);
    CHECK_ERR(simflash_init(&f, NULL, sizeof mem, &geo), INC_ERR_NULL);
    CHECK_ERR(simflash_init(&f, mem, sizeof mem, NULL), INC_ERR_NULL);
    CHECK_ERR(simflash_init(&f, mem, sizeof mem - 1u, &geo), INC_ERR_INVAL);
    g.prog_size = 3;
    CHECK_ERR(simflash_init(&f, mem, sizeof mem, &g), INC_ERR_INVAL);
    g = geo;
    g.page_count = 0;
    CHECK_ERR(simflash_init(&f, mem, sizeof mem, &g), INC_ERR_INVAL);
    g = geo;
    g.page_size = 0x10000u;
    g.page_count = 0x10000u; /* 4 GiB does not fit uint32 */
    CHECK_ERR(simflash_init(&f, mem, sizeof mem, &g), INC_ERR_INVAL);
}

static void test_program_semantics(void)
{
    struct simflash f;
    uint8_t d[8], r[8];

    setup(&f);
    memset(d, 0xF0, 4);
    CHECK_OK(simflash_program(&f, 8, d, 4));
    memset(d, 0x3C, 4);
    CHECK_OK(simflash_program(&f, 8, d, 4)); /* reprogram: AND */
    CHECK_OK(simflash_read(&f, 8, r, 4));
    CHECK_EQ_HEX(r[0], 0x30u);
    CHECK_EQ_HEX(r[3], 0x30u);
    CHECK_EQ_INT(simflash_get_stats(&f)->reprograms, 1);
    CHECK_EQ_INT(simflash_get_stats(&f)->prog_units, 2);
    CHECK_EQ_INT(simflash_steps(&f), 2);

    /* Programming 0xFF into an erased unit is not a reprogram; the unit stays erased. */
    memset(d, 0xFF, 4);
    CHECK_OK(simflash_program(&f, 12, d, 4));
    CHECK_EQ_INT(simflash_get_stats(&f)->reprograms, 1);

    simflash_set_reprogram(&f, SIMFLASH_REPROGRAM_ERROR);
    memset(d, 0x00, 4);
    CHECK_ERR(simflash_program(&f, 8, d, 4), INC_ERR_IO);
    CHECK_OK(simflash_read(&f, 8, r, 4));
    CHECK_EQ_HEX(r[0], 0x30u);   /* unchanged */
    CHECK(simflash_powered(&f)); /* a refused program is not a power cut */

    /* Erase restores 0xFF over exactly one page. */
    CHECK_OK(simflash_program(&f, 64, d, 4));
    CHECK_OK(simflash_erase(&f, 0));
    CHECK_OK(simflash_read(&f, 8, r, 4));
    CHECK_EQ_HEX(r[0], 0xFFu);
    CHECK_OK(simflash_read(&f, 64, r, 4));
    CHECK_EQ_HEX(r[0], 0x00u);
    CHECK_EQ_INT(simflash_get_stats(&f)->erases, 1);
}

static void test_alignment_and_range(void)
{
    struct simflash f;
    uint8_t d[8] = {0};

    setup(&f);
    CHECK_ERR(simflash_program(&f, 2, d, 4), INC_ERR_INVAL);
    CHECK_ERR(simflash_program(&f, 0, d, 6), INC_ERR_INVAL);
    CHECK_ERR(simflash_program(&f, 256, d, 4), INC_ERR_INVAL);
    CHECK_ERR(simflash_program(&f, 252, d, 8), INC_ERR_INVAL);
    CHECK_ERR(simflash_program(&f, 0xFFFFFFFCu, d, 8), INC_ERR_INVAL);
    CHECK_ERR(simflash_erase(&f, 32), INC_ERR_INVAL);
    CHECK_ERR(simflash_erase(&f, 256), INC_ERR_INVAL);
    CHECK_ERR(simflash_read(&f, 250, d, 8), INC_ERR_INVAL);
    CHECK_ERR(simflash_read(NULL, 0, d, 1), INC_ERR_NULL);
    CHECK_ERR(simflash_program(&f, 0, NULL, 4), INC_ERR_NULL);
    CHECK_ERR(simflash_erase(NULL, 0), INC_ERR_NULL);
    CHECK_EQ_INT(simflash_steps(&f), 0);
    CHECK_OK(simflash_read(&f, 256, d, 0)); /* empty read at the end is fine */
}

/* Program 3 units of 0x00 at 0 with a cut on the 2nd step in the given mode. */
static void cut_program(struct simflash *f, enum simflash_cut_mode mode, uint32_t seed,
                        uint8_t r[12])
{
    uint8_t d[12];
    memset(d, 0x00, sizeof d);
    setup(f);
    CHECK_OK(simflash_cut_power_at(f, 2, mode, seed));
    CHECK_ERR(simflash_program(f, 0, d, 12), INC_ERR_IO);
    CHECK(!simflash_powered(f));
    CHECK_OK(simflash_peek(f, 0, r, 12));
}

static void test_power_cut_program(void)
{
    struct simflash f;
    uint8_t r[12], b[4];
    uint32_t seed;
    unsigned partial = 0, i;

    cut_program(&f, SIMFLASH_CUT_BEFORE, 1, r);
    CHECK_EQ_HEX(r[0], 0x00u);
    CHECK_EQ_HEX(r[3], 0x00u);
    CHECK_EQ_HEX(r[4], 0xFFu); /* the cut unit: untouched */
    CHECK_EQ_HEX(r[8], 0xFFu); /* after the cut: never started */
    CHECK_EQ_INT(simflash_steps(&f), 2);
    /* Everything fails until power returns, and changes nothing. */
    CHECK_ERR(simflash_read(&f, 0, b, 4), INC_ERR_IO);
    CHECK_ERR(simflash_erase(&f, 0), INC_ERR_IO);
    CHECK_ERR(simflash_program(&f, 8, b, 4), INC_ERR_IO);
    CHECK_EQ_INT(simflash_steps(&f), 2);
    CHECK_EQ_HEX(mem[0], 0x00u);
    simflash_power_on(&f);
    CHECK_OK(simflash_read(&f, 8, b, 4));
    CHECK_EQ_HEX(b[0], 0xFFu);

    cut_program(&f, SIMFLASH_CUT_AFTER, 1, r);
    CHECK_EQ_HEX(r[4], 0x00u);
    CHECK_EQ_HEX(r[7], 0x00u);
    CHECK_EQ_HEX(r[8], 0xFFu);

    /* Torn: only bits being cleared may change, deterministic per seed, and genuinely partial. */
    for (seed = 1; seed <= 20u; seed++) {
        uint8_t r2[12];
        unsigned zeros = 0;
        cut_program(&f, SIMFLASH_CUT_TORN, seed, r);
        cut_program(&f, SIMFLASH_CUT_TORN, seed, r2);
        CHECK(memcmp(r, r2, sizeof r) == 0);
        CHECK_EQ_HEX(r[8] & r[9] & r[10] & r[11], 0xFFu);
        for (i = 4; i < 8u; i++) {
            unsigned b2;
            for (b2 = 0; b2 < 8u; b2++) {
                zeros += !((r[i] >> b2) & 1u);
            }
        }
        partial += zeros > 0u && zeros < 32u;
    }
    CHECK(partial >= 18u);
}

static void test_power_cut_program_on_data(void)
{
    /* Torn program over existing data never sets a bit and keeps bits the data keeps. */
    struct simflash f;
    uint8_t d[4] = {0x0F, 0xF0, 0xAA, 0x55}, first[4] = {0xCC, 0xCC, 0xCC, 0xCC}, r[4];
    uint32_t seed;
    unsigned i;
    for (seed = 1; seed <= 16u; seed++) {
        setup(&f);
        CHECK_OK(simflash_program(&f, 0, first, 4));
        CHECK_OK(simflash_cut_power_at(&f, 1, SIMFLASH_CUT_TORN, seed));
        CHECK_ERR(simflash_program(&f, 0, d, 4), INC_ERR_IO);
        CHECK_OK(simflash_peek(&f, 0, r, 4));
        for (i = 0; i < 4u; i++) {
            CHECK_EQ_HEX(r[i] & (uint8_t)~first[i], 0u);          /* no bit set */
            CHECK_EQ_HEX((first[i] & d[i]) & (uint8_t)~r[i], 0u); /* kept bits kept */
        }
    }
}

static void test_power_cut_erase(void)
{
    struct simflash f;
    uint8_t d[64], r[64], r2[64];
    uint32_t seed;
    unsigned mixed = 0, i;

    memset(d, 0x00, sizeof d);
    for (seed = 1; seed <= 10u; seed++) {
        unsigned ff = 0, zero = 0;
        setup(&f);
        CHECK_OK(simflash_program(&f, 64, d, 64));
        CHECK_OK(simflash_cut_power_at(&f, 1, SIMFLASH_CUT_TORN, seed));
        CHECK_ERR(simflash_erase(&f, 64), INC_ERR_IO);
        CHECK_OK(simflash_peek(&f, 64, r, 64));
        for (i = 0; i < 64u; i++) {
            ff += r[i] == 0xFFu;
            zero += r[i] == 0x00u;
        }
        mixed += ff < 64u && zero < 64u;
        setup(&f);
        CHECK_OK(simflash_program(&f, 64, d, 64));
        CHECK_OK(simflash_cut_power_at(&f, 1, SIMFLASH_CUT_TORN, seed));
        CHECK_ERR(simflash_erase(&f, 64), INC_ERR_IO);
        CHECK_OK(simflash_peek(&f, 64, r2, 64));
        CHECK(memcmp(r, r2, sizeof r) == 0);
        CHECK_OK(simflash_peek(&f, 0, r2, 64)); /* other pages untouched */
        CHECK_EQ_HEX(r2[0] & r2[63], 0xFFu);
    }
    CHECK(mixed >= 9u);

    setup(&f);
    CHECK_OK(simflash_program(&f, 0, d, 64));
    CHECK_OK(simflash_cut_power_at(&f, 1, SIMFLASH_CUT_BEFORE, 1));
    CHECK_ERR(simflash_erase(&f, 0), INC_ERR_IO);
    CHECK_EQ_HEX(mem[10], 0x00u);
    CHECK_EQ_INT(simflash_get_stats(&f)->erases, 0);
    setup(&f);
    CHECK_OK(simflash_program(&f, 0, d, 64));
    CHECK_OK(simflash_cut_power_at(&f, 1, SIMFLASH_CUT_AFTER, 1));
    CHECK_ERR(simflash_erase(&f, 0), INC_ERR_IO);
    CHECK_EQ_HEX(mem[10], 0xFFu);

    CHECK_ERR(simflash_cut_power_at(&f, 0, SIMFLASH_CUT_AFTER, 1), INC_ERR_INVAL);
    CHECK_ERR(simflash_cut_power_at(&f, 1, (enum simflash_cut_mode)7, 1), INC_ERR_INVAL);
    CHECK_ERR(simflash_cut_power_at(NULL, 1, SIMFLASH_CUT_AFTER, 1), INC_ERR_NULL);
}

static void test_faults(void)
{
    struct simflash f;
    uint8_t d[4] = {0, 0, 0, 0}, r[4];

    setup(&f);
    CHECK_OK(simflash_fail_op(&f, SIMFLASH_OP_READ, 2));
    CHECK_OK(simflash_read(&f, 0, r, 4));
    CHECK_ERR(simflash_read(&f, 0, r, 4), INC_ERR_IO);
    CHECK_OK(simflash_read(&f, 0, r, 4));
    CHECK(simflash_powered(&f));
    CHECK_OK(simflash_fail_op(&f, SIMFLASH_OP_PROGRAM, 1));
    CHECK_ERR(simflash_program(&f, 0, d, 4), INC_ERR_IO);
    CHECK_EQ_HEX(mem[0], 0xFFu);
    CHECK_OK(simflash_fail_op(&f, SIMFLASH_OP_ERASE, 1));
    CHECK_ERR(simflash_erase(&f, 0), INC_ERR_IO);
    CHECK_ERR(simflash_fail_op(&f, SIMFLASH_OP_ERASE, 0), INC_ERR_INVAL);
    CHECK_ERR(simflash_fail_op(&f, (enum simflash_op)3, 1), INC_ERR_INVAL);

    CHECK_OK(simflash_set_stuck(&f, 1, 0x81u));
    CHECK_OK(simflash_program(&f, 0, d, 4)); /* reports success... */
    CHECK_OK(simflash_read(&f, 0, r, 4));
    CHECK_EQ_HEX(r[0], 0x00u);
    CHECK_EQ_HEX(r[1], 0x81u); /* ...but two cells did not program */
    CHECK_OK(simflash_set_stuck(&f, 0, 0));
    CHECK_ERR(simflash_set_stuck(&f, 256, 1), INC_ERR_INVAL);

    CHECK_OK(simflash_flip_bit(&f, 0, 7));
    CHECK_EQ_HEX(mem[0], 0x80u);
    CHECK_ERR(simflash_flip_bit(&f, 0, 8), INC_ERR_INVAL);
    CHECK_ERR(simflash_flip_bit(&f, 256, 0), INC_ERR_INVAL);
    CHECK_OK(simflash_poke(&f, 100, (const uint8_t *)"\x12\x34", 2));
    CHECK_OK(simflash_peek(&f, 100, r, 2));
    CHECK_EQ_HEX(r[0], 0x12u);
    CHECK_EQ_HEX(r[1], 0x34u);
    CHECK_ERR(simflash_poke(&f, 255, d, 2), INC_ERR_INVAL);
    simflash_reset_stats(&f);
    CHECK_EQ_INT(simflash_get_stats(&f)->read_calls, 0);
}

static void test_calstore_ops_adapter(void)
{
    struct simflash f;
    uint8_t d[4] = {1, 2, 3, 4}, r[4];
    setup(&f);
    CHECK_OK(simflash_calstore_ops.program(&f, 4, d, 4));
    CHECK_OK(simflash_calstore_ops.read(&f, 4, r, 4));
    CHECK_EQ_HEX(r[3], 4u);
    CHECK_OK(simflash_calstore_ops.erase(&f, 0));
    CHECK_OK(simflash_calstore_ops.read(&f, 4, r, 4));
    CHECK_EQ_HEX(r[3], 0xFFu);
}

int main(void)
{
    UNIT_RUN(test_init);
    UNIT_RUN(test_program_semantics);
    UNIT_RUN(test_alignment_and_range);
    UNIT_RUN(test_power_cut_program);
    UNIT_RUN(test_power_cut_program_on_data);
    UNIT_RUN(test_power_cut_erase);
    UNIT_RUN(test_faults);
    UNIT_RUN(test_calstore_ops_adapter);
    return unit_report();
}
