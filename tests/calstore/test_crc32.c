/* CRC-32 (IEEE 802.3): standard vectors, the nibble table against a bitwise reference,
 * chaining, and the NULL rule. Expected values are the published check value and values
 * computed with Python's zlib.crc32, not with this code. */
#include <string.h>

#include "inclino/crc32.h"
#include "unit.h"

/* Bit-at-a-time reference, written from the definition (reflected poly 0xEDB88320). */
static uint32_t crc_ref(const uint8_t *d, size_t n)
{
    uint32_t c = 0xFFFFFFFFu;
    size_t i;
    int b;
    for (i = 0; i < n; i++) {
        c ^= d[i];
        for (b = 0; b < 8; b++) {
            c = (c & 1u) ? (c >> 1) ^ 0xEDB88320u : c >> 1;
        }
    }
    return c ^ 0xFFFFFFFFu;
}

static void test_known_vectors(void)
{
    static const char fox[] = "The quick brown fox jumps over the lazy dog";
    uint8_t buf[32];
    unsigned i;

    CHECK_EQ_HEX(crc32_update(0, (const uint8_t *)"123456789", 9), 0xCBF43926u);
    CHECK_EQ_HEX(crc32_update(0, (const uint8_t *)"123456789", 9), CRC32_CHECK_VALUE);
    CHECK_EQ_HEX(crc32_update(0, (const uint8_t *)"", 0), 0x00000000u);
    CHECK_EQ_HEX(crc32_update(0, (const uint8_t *)"a", 1), 0xE8B7BE43u);
    CHECK_EQ_HEX(crc32_update(0, (const uint8_t *)fox, strlen(fox)), 0x414FA339u);
    memset(buf, 0x00, sizeof buf);
    CHECK_EQ_HEX(crc32_update(0, buf, sizeof buf), 0x190A55ADu);
    memset(buf, 0xFF, sizeof buf);
    CHECK_EQ_HEX(crc32_update(0, buf, sizeof buf), 0xFF6CAB0Bu);
    for (i = 0; i < sizeof buf; i++) {
        buf[i] = (uint8_t)i;
    }
    CHECK_EQ_HEX(crc32_update(0, buf, sizeof buf), 0x91267E8Au);
}

static void test_against_bitwise_reference(void)
{
    uint8_t buf[300];
    uint32_t x = 12345u;
    unsigned i, n;

    for (i = 0; i < sizeof buf; i++) {
        x = x * 1103515245u + 12345u;
        buf[i] = (uint8_t)(x >> 16);
    }
    /* Every single byte value (covers all 16 table entries in both nibble positions). */
    for (i = 0; i < 256u; i++) {
        uint8_t b = (uint8_t)i;
        CHECK_EQ_HEX(crc32_update(0, &b, 1), crc_ref(&b, 1));
    }
    for (n = 0; n <= sizeof buf; n += 7u) {
        CHECK_EQ_HEX(crc32_update(0, buf, n), crc_ref(buf, n));
    }
}

static void test_chaining(void)
{
    static const uint8_t d[] = "123456789";
    unsigned split;
    for (split = 0; split <= 9u; split++) {
        uint32_t c = crc32_update(0, d, split);
        c = crc32_update(c, d + split, 9u - split);
        CHECK_EQ_HEX(c, 0xCBF43926u);
    }
}

static void test_null_data(void)
{
    CHECK_EQ_HEX(crc32_update(0x12345678u, NULL, 0), 0x12345678u);
    CHECK_EQ_HEX(crc32_update(0x12345678u, NULL, 100), 0x12345678u);
    CHECK_EQ_HEX(crc32_update(0, NULL, 5), 0u);
}

int main(void)
{
    UNIT_RUN(test_known_vectors);
    UNIT_RUN(test_against_bitwise_reference);
    UNIT_RUN(test_chaining);
    UNIT_RUN(test_null_data);
    return unit_report();
}
