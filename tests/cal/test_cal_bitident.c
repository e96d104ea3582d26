/*
 * test_cal_bitident.c - bit identity of firmware/signal/cal across targets.
 *
 * One fixed deterministic input set (xorshift32 from fixed seeds): random temperature models and
 * records within the calrec limits, temperatures beyond the range, inputs up to the limits and
 * beyond. Every output and return code is folded into a CRC-32 (reflected 0xEDB88320, bytes in
 * little-endian order, so the value does not depend on the CPU's byte order). The host,
 * Cortex-M and rv32imac must all produce this constant. Integer only (no libm), hence RV32.
 * A deliberate change of an algorithm that changes outputs updates the constant in the same
 * commit, with the accuracy tests still passing.
 */
#include "cal_gen.h"
#include "unit.h"

#include <stdio.h>

#define CAL_BITIDENT_CRC 0xc7c46fa0u /* the test prints the value it computes */

static uint32_t crc = 0xFFFFFFFFu;

static void put32(uint32_t v)
{
    unsigned i;
    int k;
    for (i = 0; i < 4u; i++) {
        crc ^= (uint8_t)(v >> (8u * i));
        for (k = 0; k < 8; k++) {
            crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
        }
    }
}

static void test_bitident(void)
{
    static const int32_t kinds[6] = {CALREC_TM_NONE,    CALREC_TM_LINEAR, CALREC_TM_PARABOLA,
                                     CALREC_TM_LORENTZ, CALREC_TM_PWL,    CALREC_TM_LORENTZ_CUBIC};
    uint32_t s = 0x5EED0001u;
    unsigned k, j;
    /* Temperature models, both y formats. */
    for (k = 0; k < 600u; k++) {
        struct calrec_tmodel m;
        random_model(&s, kinds[k % 6u], (k & 1u) ? CALREC_LIM_TSCALE : CALREC_LIM_TBIAS, k, &m);
        for (j = 0; j < 20u; j++) {
            int32_t y = 0;
            const int32_t t = j == 0   ? INT32_MIN
                              : j == 1 ? INT32_MAX
                                       : (int32_t)calt_range(&s, -150 * 65536, 250 * 65536);
            put32((uint32_t)cal_tmodel_eval(&m, t, &y));
            put32((uint32_t)y);
        }
    }
    /* Records: set_temp + apply, gyro. */
    for (k = 0; k < 200u; k++) {
        struct calrec r;
        struct cal_acc st;
        struct cal_gyro g;
        random_record(&s, (int)(k & 1u), k, &r);
        put32((uint32_t)cal_acc_init(&st, &r, (int32_t)calt_range(&s, -40 * 65536, 125 * 65536)));
        put32((uint32_t)cal_gyro_init(&g, &r));
        for (j = 0; j < 3u; j++) {
            put32((uint32_t)st.off[j]);
            put32((uint32_t)st.inv_gain[j]);
        }
        for (j = 0; j < 30u; j++) {
            fx_q16_t in[3], out[3];
            unsigned i;
            for (i = 0; i < 3u; i++) {
                in[i] = j == 0 ? (i ? INT32_MIN : INT32_MAX)
                               : (int32_t)calt_range(&s, -3 * 65536, 3 * 65536);
            }
            put32((uint32_t)cal_acc_apply(&st, in, out));
            for (i = 0; i < 3u; i++)
                put32((uint32_t)out[i]);
            put32((uint32_t)cal_gyro_apply(&g, in, out));
            for (i = 0; i < 3u; i++)
                put32((uint32_t)out[i]);
        }
    }
    /* Procedures. */
    for (k = 0; k < 2000u; k++) {
        fx_q16_t o = 0;
        fx_q30_t g = 0;
        const int32_t ap = (int32_t)calt_range(&s, 40000, 90000),
                      an = (int32_t)calt_range(&s, -90000, -40000);
        put32((uint32_t)cal_flip(ap, an, &o, &g));
        put32((uint32_t)o);
        put32((uint32_t)g);
    }
    {
        struct cal_turn t;
        const fx_q16_t off[3] = {27525, -50463, 9830};
        fx_q30_t sc = 0;
        put32((uint32_t)cal_turn_start(&t, off, 1310720));
        for (k = 0; k < 3277u; k++) {
            const fx_q16_t r[3] = {(int32_t)calt_range(&s, 5890000, 5910000),
                                   (int32_t)calt_range(&s, -60000, 60000), 0};
            put32((uint32_t)cal_turn_add(&t, r));
        }
        put32((uint32_t)cal_turn_scale(&t, 0, FX_Q16_INT(360), &sc));
        put32((uint32_t)sc);
        put32((uint32_t)t.angle_q32[1]);
        put32((uint32_t)(t.angle_q32[1] >> 32));
    }
    crc ^= 0xFFFFFFFFu;
    printf("cal bit identity CRC-32: 0x%08lx\n", (unsigned long)crc);
    CHECK_EQ_HEX(crc, CAL_BITIDENT_CRC);
}

int main(void)
{
    UNIT_RUN(test_bitident);
    return unit_report();
}
