/*
 * adis_offset_counts: the user-offset encoding the ADIS drivers share (drivers/adis). Exact
 * vectors for each register it serves (ADIS16255 GYRO_OFF, ADIS1636x/1640x XGYRO_OFF, XACCL_OFF),
 * ties, the saturation edges of every width, bad arguments, and a random sweep against an
 * exact reference (unit_round_div, unit.h: floor division, then the tie rule). Integer only: it
 * also runs on rv32imac.
 */
#include "inclino/adis.h"
#include "unit.h"

static void test_registers(void)
{
    bool sat = true;
    /* ADIS16255 GYRO_OFF, 12 bits, 273/5 LSB per deg/s from Q16.16: 1 deg/s = 54.6 -> 55. */
    CHECK_EQ_INT(adis_offset_counts(65536LL * 273, 327680u, 12, &sat), 55);
    CHECK(!sat);
    CHECK_EQ_INT(adis_offset_counts(-65536LL * 273, 327680u, 12, &sat), -55);
    CHECK(!sat);
    /* a tie: 163840 x 273 / 327680 = 136.5 */
    CHECK_EQ_INT(adis_offset_counts(163840LL * 273, 327680u, 12, &sat), 137);
    CHECK_EQ_INT(adis_offset_counts(-163840LL * 273, 327680u, 12, &sat), -137);
    /* 40 deg/s = 2184 LSB: beyond the 12-bit range */
    CHECK_EQ_INT(adis_offset_counts(40LL * 65536 * 273, 327680u, 12, &sat), 2047);
    CHECK(sat);
    CHECK_EQ_INT(adis_offset_counts(-40LL * 65536 * 273, 327680u, 12, &sat), -2048);
    CHECK(sat);
    /* ADIS1636x/1640x XGYRO_OFF, 13 bits, x80 ([ADI-IMU-QS]): 0.03125 deg/s = 2.5 LSB -> 3. */
    CHECK_EQ_INT(adis_offset_counts(2048LL * 80, 65536u, 13, &sat), 3);
    CHECK(!sat);
    CHECK_EQ_INT(adis_offset_counts(-2048LL * 80, 65536u, 13, &sat), -3);
    CHECK_EQ_INT(adis_offset_counts(-51LL * 65536 * 80, 65536u, 13, &sat), -4080);
    CHECK(!sat);
    CHECK_EQ_INT(adis_offset_counts((int64_t)INT32_MAX * 80, 65536u, 13, &sat), 4095);
    CHECK(sat);
    /* XACCL_OFF, 12 bits, 1 mg LSB: 0.1 g = 6554 / 65536 g -> 100.006 -> 100. */
    CHECK_EQ_INT(adis_offset_counts(6554LL * 15625, 1000u * 1024u, 12, &sat), 100);
    CHECK(!sat);
}

static void test_edges(void)
{
    bool sat = false;
    unsigned bits;
    /* every width: the last value in range is not saturated, half an LSB beyond it is */
    for (bits = 2; bits <= 16u; bits++) {
        const int64_t hi = ((int64_t)1 << (bits - 1u)) - 1, lo = -hi - 1;
        CHECK_EQ_INT(adis_offset_counts(2 * hi - 1, 2u, bits, &sat), hi); /* hi - 0.5 -> hi */
        CHECK(!sat);
        CHECK_EQ_INT(adis_offset_counts(2 * hi + 1, 2u, bits, &sat), hi); /* hi + 0.5 -> hi + 1 */
        CHECK(sat);
        CHECK_EQ_INT(adis_offset_counts(2 * lo + 1, 2u, bits, &sat), lo); /* lo + 0.5 -> lo */
        CHECK(!sat);
        CHECK_EQ_INT(adis_offset_counts(2 * lo - 1, 2u, bits, &sat), lo); /* lo - 0.5 -> lo - 1 */
        CHECK(sat);
    }
    CHECK_EQ_INT(adis_offset_counts(INT64_MAX, 1u, 16, &sat), 32767);
    CHECK(sat);
    CHECK_EQ_INT(adis_offset_counts(INT64_MIN, 1u, 16, &sat), -32768);
    CHECK(sat);
    CHECK_EQ_INT(adis_offset_counts(INT64_MIN, UINT32_MAX, 16, &sat), -32768);
    CHECK(sat);
    CHECK_EQ_INT(adis_offset_counts(0, UINT32_MAX, 2, &sat), 0);
    CHECK(!sat);
    /* saturated may be NULL */
    CHECK_EQ_INT(adis_offset_counts(99999, 1u, 12, NULL), 2047);
    CHECK_EQ_INT(adis_offset_counts(-7, 2u, 12, NULL), -4);
    /* bad arguments: 0, flagged */
    sat = false;
    CHECK_EQ_INT(adis_offset_counts(5, 0u, 12, &sat), 0);
    CHECK(sat);
    sat = false;
    CHECK_EQ_INT(adis_offset_counts(5, 1u, 1, &sat), 0);
    CHECK(sat);
    sat = false;
    CHECK_EQ_INT(adis_offset_counts(5, 1u, 17, &sat), 0);
    CHECK(sat);
    CHECK_EQ_INT(adis_offset_counts(5, 0u, 12, NULL), 0);
}

static void test_random(void)
{
    uint32_t s = 0xADC0FFEEu;
    unsigned long bad = 0;
    long k;
    for (k = 0; k < UNIT_SIZE(1000000L, 100000L); k++) {
        /* |num| < 2^62, den 1 .. 2^32 - 1, bits 2..16, every magnitude */
        const uint64_t u = ((uint64_t)unit_rand32(&s) << 32 | unit_rand32(&s)) >> 2;
        const int64_t m = (int64_t)(u >> (unit_rand32(&s) % 63u));
        const int64_t num = (unit_rand32(&s) & 1u) ? -m : m;
        const uint32_t den = (unit_rand32(&s) >> (unit_rand32(&s) % 32u)) | 1u;
        const unsigned bits = 2u + unit_rand32(&s) % 15u;
        const int64_t hi = ((int64_t)1 << (bits - 1u)) - 1, lo = -hi - 1;
        const int64_t q = unit_round_div(num, den);
        const int64_t want = q > hi ? hi : (q < lo ? lo : q);
        bool sat = false;
        const int32_t got = adis_offset_counts(num, den, bits, &sat);
        if (got != want || sat != (q > hi || q < lo)) {
            bad++;
        }
    }
    CHECK_EQ_INT(bad, 0);
}

int main(void)
{
    UNIT_RUN(test_registers);
    UNIT_RUN(test_edges);
    UNIT_RUN(test_random);
    return unit_report();
}
