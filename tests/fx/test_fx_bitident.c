/*
 * test_fx_bitident.c - bit identity across targets.
 *
 * Every fx function is run over one fixed deterministic input set (xorshift32 from a fixed seed,
 * plus the int32 extremes) and all outputs, including return codes, are folded into a CRC-32
 * (IEEE 802.3, reflected 0xEDB88320) byte by byte in little-endian order, so the checksum does
 * not depend on the host's byte order. The expected value is a constant: the host, Cortex-M0+,
 * M3, M4F (and rv32imac when its tests run) must all produce exactly these bits.
 * If a deliberate change of an algorithm changes the outputs, the accuracy tests must still
 * pass and the constant is updated in the same commit, with the reason.
 */
#include "fx_test_int.h"

#define FX_BITIDENT_N 4096
#define FX_BITIDENT_CRC 0xa1fe51d9u /* the test prints the value it computes */

static uint32_t crc;

static void crc_byte(uint8_t b)
{
    int k;
    crc ^= b;
    for (k = 0; k < 8; k++)
        crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
}

static void put32(uint32_t v)
{
    crc_byte((uint8_t)v);
    crc_byte((uint8_t)(v >> 8));
    crc_byte((uint8_t)(v >> 16));
    crc_byte((uint8_t)(v >> 24));
}

static void puti(int32_t v)
{
    put32((uint32_t)v);
}

static void put64(uint64_t v)
{
    put32((uint32_t)v);
    put32((uint32_t)(v >> 32));
}

static void run_one(int32_t a, int32_t b, uint32_t r)
{
    unsigned s = r % 64u, f = (r >> 8) % 32u;
    int32_t q = 0;
    uint64_t u64 = ((uint64_t)(uint32_t)a << 32) | (uint32_t)b;
    fx_q30_t sn = 0, cs = 0;

    puti(fx_add(a, b));
    puti(fx_sub(a, b));
    puti(fx_abs(a));
    puti(fx_neg(a));
    puti(fx_asr32(a, s));
    put64((uint64_t)fx_asr64((int64_t)a * b, s));
    puti(fx_lshift_sat32(a, f));
    puti(fx_rshift_round32(a, s));
    put64((uint64_t)fx_rshift_round64((int64_t)a * b, s));
    puti(fx_q30_to_q16(a));
    puti(fx_q16_to_q30(b));
    puti(fx_mul_q16(a, b));
    puti(fx_mul_q30(a, b));
    puti(fx_mul_shift(a, b, s));
    puti(fx_div(a, b, f, &q));
    puti(q);
    puti(fx_div_q16(a, b, &q));
    puti(q);
    puti(fx_recip_q30(b, &q));
    puti(q);
    put32(fx_isqrt32((uint32_t)a));
    put32(fx_isqrt64(u64));
    put32(fx_isqrt64_round(u64));
    puti(fx_sqrt_q16(a));
    puti(fx_sqrt_q30(b));
    puti(fx_atan2_deg(a, b));
    puti(fx_atan2_deg(fx_asr32(a, r % 31u), b)); /* unequal magnitudes */
    puti(fx_asin_deg(a));
    puti(fx_asin_deg(fx_asr32(b, 1)));
    fx_sincos_deg(a, &sn, &cs);
    puti(sn);
    puti(cs);
    puti(fx_sin_deg(b));
    puti(fx_cos_deg(b));
}

static void test_checksum(void)
{
    static const int32_t ext[] = {INT32_MIN, INT32_MIN + 1, -FX_Q30_ONE, -FX_Q16_ONE,   -1,       0,
                                  1,         FX_Q16_ONE,    FX_Q30_ONE,  INT32_MAX - 1, INT32_MAX};
    uint32_t st = 0x1F0E2D3Cu;
    struct fx_sum acc;
    int32_t mean = 0;
    size_t i, j;
    int n;

    crc = 0xFFFFFFFFu;
    fx_sum_reset(&acc);
    for (i = 0; i < sizeof ext / sizeof ext[0]; i++)
        for (j = 0; j < sizeof ext / sizeof ext[0]; j++)
            run_one(ext[i], ext[j], (uint32_t)(i * 11u + j));
    for (n = 0; n < FX_BITIDENT_N; n++) {
        int32_t a = fxt_rand_scaled(&st), b = fxt_rand_scaled(&st);
        uint32_t r = unit_rand32(&st);
        run_one(a, b, r);
        (void)fx_sum_add(&acc, a);
    }
    CHECK_OK(fx_sum_mean(&acc, &mean));
    puti(mean);
    put64((uint64_t)acc.sum);
    crc ^= 0xFFFFFFFFu;
    printf("MEASURED fx bit-identity CRC-32 = 0x%08lx over %d random + %u extreme input sets\n",
           (unsigned long)crc, FX_BITIDENT_N,
           (unsigned)(sizeof ext / sizeof ext[0] * sizeof ext / sizeof ext[0]));
    CHECK_EQ_HEX(crc, FX_BITIDENT_CRC);
}

int main(void)
{
    UNIT_RUN(test_checksum);
    return unit_report();
}
