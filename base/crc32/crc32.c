/*
 * crc32.c - CRC-32 (IEEE 802.3), nibble-table implementation.
 *
 * Why a 16-entry table: the whole-byte table costs 1 KiB of flash, the bit-by-bit loop eight
 * shift/xor steps per byte. Processing one nibble at a time needs 64 bytes of table and two
 * steps per byte; the record is checked once at boot and once per write, so this is the
 * smallest form that is still far from mattering for time (see docs/benchmarks.md).
 *
 * Table entry n is the register after shifting the 4-bit value n through the reflected
 * polynomial 0xEDB88320 four times; tests/calstore checks every entry against a bitwise
 * reference and the standard check value.
 */
#include "inclino/crc32.h"

static const uint32_t crc32_nibble[16] = {
    0x00000000u, 0x1DB71064u, 0x3B6E20C8u, 0x26D930ACu, 0x76DC4190u, 0x6B6B51F4u,
    0x4DB26158u, 0x5005713Cu, 0xEDB88320u, 0xF00F9344u, 0xD6D6A3E8u, 0xCB61B38Cu,
    0x9B64C2B0u, 0x86D3D2D4u, 0xA00AE278u, 0xBDBDF21Cu,
};

uint32_t crc32_update(uint32_t crc, const uint8_t *data, size_t len)
{
    uint32_t reg;
    size_t i;

    if (data == NULL) {
        return crc;
    }
    /* A finished CRC is the register XOR 0xFFFFFFFF, so undoing the final XOR resumes it. */
    reg = crc ^ 0xFFFFFFFFu;
    for (i = 0; i < len; i++) {
        reg ^= data[i];
        reg = (reg >> 4) ^ crc32_nibble[reg & 0x0Fu];
        reg = (reg >> 4) ^ crc32_nibble[reg & 0x0Fu];
    }
    return reg ^ 0xFFFFFFFFu;
}
