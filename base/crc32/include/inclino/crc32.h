/*
 * crc32.h - CRC-32 as used by IEEE 802.3, zlib and PNG ("CRC-32/ISO-HDLC").
 *
 * Parameters: polynomial 0x04C11DB7 processed bit-reflected (0xEDB88320), initial value
 * 0xFFFFFFFF, input and output reflected, final XOR 0xFFFFFFFF. Check value: the CRC of the nine
 * ASCII bytes "123456789" is 0xCBF43926; the CRC of zero bytes is 0x00000000.
 *
 * Interface in the zlib style: the running value passed in and returned is always a finished
 * CRC, so a CRC over several pieces is computed by chaining,
 *     crc = crc32_update(0, a, na); crc = crc32_update(crc, b, nb);
 * which equals crc32_update(0, ab, na + nb).
 *
 * Cost: a 16-entry (64-byte) const table, two lookups per byte (one per nibble); 120 bytes of
 * flash on Cortex-M. Size and instruction counts: docs/benchmarks.md ("Calibration storage").
 */
#ifndef INCLINO_CRC32_H
#define INCLINO_CRC32_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The CRC of "123456789", for self-tests. */
#define CRC32_CHECK_VALUE 0xCBF43926u

/*
 * CRC-32 of len bytes at data, continuing from crc (the CRC of everything before; 0 to start).
 * data may be NULL only when len is 0; a NULL data with len > 0 is treated as len 0 (the CRC of
 * nothing more), so the function has no failure and no undefined behaviour.
 */
uint32_t crc32_update(uint32_t crc, const uint8_t *data, size_t len);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_CRC32_H */
