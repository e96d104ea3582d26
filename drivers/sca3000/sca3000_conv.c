/*
 * sca3000_conv.c - pure SCA3000 conversions (see sca3000.h for formats, ranges and rounding).
 *
 * Data alignment: docs/sensor-facts.md §1.4 (Linux realbits 13 / shift 3 for direct reads, realbits 11 /
 * shift 5 for the ring; temperature 9 bits at [13:5]). Sensitivity: docs/sensor-facts.md §1.1. Every
 * signed value is built from unsigned fields by subtraction, never by shifting a negative
 * number, so the results are the same on every compiler and target.
 */
#include "inclino/sca3000.h"

#include "inclino/fx.h"

/* ug per LSB: 0.75, 1, 2 and 6.25 mg (Linux scale in um/s^2 divided by 9.81). */
static const uint32_t ug_per_lsb[4] = {750u, 1000u, 2000u, 6250u};

int sca3000_accel_counts_from_word(uint16_t word, int16_t *count)
{
    uint32_t u;
    if (count == NULL) {
        return INC_ERR_NULL;
    }
    if ((word & 0x0007u) != 0u) {
        return INC_ERR_BUS;
    }
    u = (uint32_t)word >> 3; /* 0..8191, bit 12 is the sign */
    *count = (int16_t)((int32_t)u - ((u & 0x1000u) != 0u ? 8192 : 0));
    return INC_OK;
}

int16_t sca3000_ring_counts_from_word(uint16_t word)
{
    const uint32_t u = (uint32_t)word >> 5; /* 0..2047, bit 10 is the sign */
    const int32_t s = (int32_t)u - ((u & 0x400u) != 0u ? 2048 : 0);
    return (int16_t)(s * 4);
}

uint16_t sca3000_temp_counts_from_word(uint16_t word)
{
    return (uint16_t)((word >> 5) & 0x1FFu);
}

uint32_t sca3000_ug_per_lsb(enum sca3000_variant v)
{
    if ((unsigned)v > (unsigned)SCA3000_E05) {
        return 0u;
    }
    return ug_per_lsb[v];
}

int sca3000_accel_ug_from_counts(int32_t counts, enum sca3000_variant v, int32_t *ug)
{
    const uint32_t lsb = sca3000_ug_per_lsb(v);
    if (ug == NULL) {
        return INC_ERR_NULL;
    }
    if (lsb == 0u) {
        return INC_ERR_INVAL;
    }
    if (counts < -4096 || counts > 4095) {
        return INC_ERR_RANGE;
    }
    *ug = counts * (int32_t)lsb; /* |.| <= 4096 * 6250 = 25.6e6 */
    return INC_OK;
}

int sca3000_accel_g_from_counts(int32_t counts, enum sca3000_variant v, int32_t *g_q16)
{
    int32_t ug;
    int err;
    if (g_q16 == NULL) {
        return INC_ERR_NULL;
    }
    err = sca3000_accel_ug_from_counts(counts, v, &ug); /* the same checks; ug is exact */
    if (err != INC_OK) {
        return err;
    }
    /* |ug * 65536| <= 4096 * 6250 * 65536 = 1.7e12: exact in int64. */
    *g_q16 = fx_div64((int64_t)ug * 65536, 1000000u);
    return INC_OK;
}

int sca3000_temp_c_from_counts(int32_t raw9, int32_t *c_q16)
{
    if (c_q16 == NULL) {
        return INC_ERR_NULL;
    }
    if (raw9 < 0 || raw9 > 511) {
        return INC_ERR_RANGE;
    }
    /* (raw - 214.6) / 1.8 degC = (10 raw - 2146) / 18; x 65536 stays below 2^24 * 18. */
    *c_q16 = fx_div64(((int64_t)raw9 * 10 - 2146) * 65536, 18u);
    return INC_OK;
}
