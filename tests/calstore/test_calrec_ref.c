/* Calibration record, differential: the firmware codec against the frozen field-by-field
 * implementation it replaced (calrec_ref.c). For a set of base records covering every model kind
 * and every word of the image set to every limit, limit +-1 and other edge values: the same
 * codes from calrec_check / calrec_encode / calrec_check_image / calrec_decode, byte-identical
 * images and identical decoded records (or the safe default). Plus the binding rules over edge
 * values of every field for every family, and the header and length paths. */
#include <string.h>

#include "calrec_ref.h"
#include "fixture.h"
#include "inclino/calrec.h"
#include "unit.h"

/* The struct is the image's words [16, 652) (asserted in calrec.c); the test patches it so. */
#define WORDS ((CALREC_OFF_CRC - CALREC_OFF_BINDING) / 4u)

static unsigned mismatches;

static void note(const char *what, unsigned base, unsigned word, int32_t v, int got, int want)
{
    if (mismatches++ < 10u) {
        unit_fail(__FILE__, __LINE__, "%s: base %u word %u value %ld: got %d, ref %d", what, base,
                  word, (long)v, got, want);
    }
}

static void patch_rec(struct calrec *r, unsigned w, int32_t v)
{
    memcpy((unsigned char *)r + 4u * (w - CALREC_OFF_BINDING / 4u), &v, 4u);
}

/* Base records: the golden record, then each model slot set to each kind in a valid form. */
static void make_model(struct calrec_tmodel *m, int kind, int32_t ylim, unsigned n)
{
    unsigned k;
    memset(m, 0, sizeof *m);
    m->kind = kind;
    switch (kind) {
    case CALREC_TM_LINEAR:
    case CALREC_TM_PARABOLA:
    case CALREC_TM_LORENTZ_CUBIC:
        m->t_ref = 25 * CALREC_Q16_ONE;
        m->t_span = 40 * CALREC_Q16_ONE;
        for (k = 0; k < (kind == CALREC_TM_LINEAR ? 2u : 3u); k++) {
            m->p[k] = (k & 1u) ? -ylim : ylim;
        }
        if (kind == CALREC_TM_LORENTZ_CUBIC) {
            m->p[2] = 30 * CALREC_Q16_ONE;
            m->p[3] = 20 * CALREC_Q16_ONE;
            m->p[4] = ylim / 3;
            m->p[5] = -ylim;
            m->p[6] = ylim;
        }
        break;
    case CALREC_TM_LORENTZ:
        m->p[0] = -ylim;
        m->p[1] = ylim;
        m->p[2] = CALREC_LIM_WIDTH_MAX;
        m->p[3] = CALREC_LIM_T_MIN;
        break;
    case CALREC_TM_PWL:
        m->n = (int32_t)n;
        m->t_ref = -20 * CALREC_Q16_ONE;
        m->t_span = (CALREC_LIM_T_MAX - m->t_ref) / (int32_t)(n - 1u); /* last knot at limit */
        if (m->t_span > CALREC_LIM_SPAN_MAX) {
            m->t_span = CALREC_LIM_SPAN_MAX;
        }
        for (k = 0; k < n; k++) {
            m->p[k] = (int32_t)k * (ylim / 16) - ylim / 2;
        }
        break;
    default: break;
    }
}

#define BASES (1u + 6u * CALREC_TM_KIND_COUNT + 2u)

static void make_base(struct calrec *r, unsigned b)
{
    fix_record(r);
    if (b == 0u) {
        return;
    }
    b--;
    if (b < 6u * CALREC_TM_KIND_COUNT) {
        unsigned slot = b / CALREC_TM_KIND_COUNT;
        int kind = (int)(b % CALREC_TM_KIND_COUNT);
        struct calrec_tmodel *m = slot < 3u ? &r->acc_tbias[slot] : &r->acc_tscale[slot - 3u];
        make_model(m, kind, slot < 3u ? CALREC_LIM_TBIAS : CALREC_LIM_TSCALE, 2u + 7u * slot % 15u);
        return;
    }
    /* PWL with the most knots in bias x, and the fewest in scale z. */
    make_model(&r->acc_tbias[0], CALREC_TM_PWL, CALREC_LIM_TBIAS, CALREC_TM_PARAMS);
    make_model(&r->acc_tscale[2], CALREC_TM_PWL, CALREC_LIM_TSCALE, 2u);
    if (b > 6u * CALREC_TM_KIND_COUNT) {
        r->binding.family = CALREC_FAMILY_SCA3000;
        r->binding.product = CALREC_SCA3000_E05;
        r->binding.revision = 0xFFu;
        r->binding.serial = 0;
        r->binding.lot_id1 = 0;
        r->binding.lot_id2 = 0;
    }
}

static const int32_t lims[] = {
    CALREC_LIM_ACC_OFFSET,
    CALREC_LIM_GAIN_MIN,
    CALREC_LIM_GAIN_MAX,
    CALREC_LIM_MISALIGN_OFFDIAG,
    CALREC_LIM_NONLIN_C01,
    CALREC_LIM_NONLIN_C23,
    CALREC_LIM_TBIAS,
    CALREC_LIM_TSCALE,
    CALREC_LIM_T_MIN,
    CALREC_LIM_T_MAX,
    CALREC_LIM_SPAN_MIN,
    CALREC_LIM_SPAN_MAX,
    CALREC_LIM_WIDTH_MAX,
    CALREC_LIM_GYRO_OFFSET,
    CALREC_Q30_ONE,
    INT32_MAX,
    INT32_MIN + 1,
    0,
    1,
    2,
    3,
    4,
    5,
    6,
    7,
    15,
    16,
    17,
};

/* x modulo 2^32 as an int32 (two's complement, without signed overflow). */
static int32_t wrap32(int64_t x)
{
    const uint32_t u = (uint32_t)(uint64_t)x;
    return u <= (uint32_t)INT32_MAX ? (int32_t)u : (int32_t)(u - 0x80000000u) + INT32_MIN;
}

/* Every edge value for word w of base record r: the fixed list +-1 and negated, and for a PWL
 * model the t_span / t_ref that put the last knot exactly at the limit, +-1. */
static unsigned values(const struct calrec *r, unsigned w, int32_t *out)
{
    unsigned i, n = 0;
    for (i = 0; i < sizeof lims / sizeof lims[0]; i++) {
        const int64_t v = lims[i]; /* in 64 bits: a limit may be INT32_MAX (wrapped below) */
        out[n++] = wrap32(v);
        out[n++] = wrap32(-v);
        out[n++] = wrap32(v + 1);
        out[n++] = wrap32(v - 1);
        out[n++] = wrap32(-v + 1);
        out[n++] = wrap32(-v - 1);
    }
    if (w >= CALREC_OFF_ACC_TBIAS / 4u && w < CALREC_OFF_GYRO_OFFSET / 4u) {
        unsigned mi = (w - CALREC_OFF_ACC_TBIAS / 4u) / 20u;
        const struct calrec_tmodel *m = mi < 3u ? &r->acc_tbias[mi] : &r->acc_tscale[mi - 3u];
        if (m->kind == CALREC_TM_PWL && m->n >= 2) {
            int32_t span = (CALREC_LIM_T_MAX - m->t_ref) / (m->n - 1);
            int32_t ref = CALREC_LIM_T_MAX - (m->n - 1) * m->t_span;
            for (i = 0; i < 3u; i++) {
                out[n++] = span - 1 + (int32_t)i;
                out[n++] = ref - 1 + (int32_t)i;
            }
        }
    }
    return n;
}

static void compare_record(unsigned b, unsigned w, int32_t v, const struct calrec *r)
{
    uint8_t img[CALREC_IMAGE_SIZE + 4], ref_img[CALREC_IMAGE_SIZE + 4];
    int got, want;

    got = calrec_check(r);
    want = ref_calrec_check(r);
    if (got != want) {
        note("check", b, w, v, got, want);
    }
    memset(img, 0x5A, sizeof img);
    memset(ref_img, 0x5A, sizeof ref_img);
    got = calrec_encode(r, 0x01020304u + b, img, sizeof img);
    want = ref_calrec_encode(r, 0x01020304u + b, ref_img, sizeof ref_img);
    if (got != want || memcmp(img, ref_img, sizeof img) != 0) {
        note("encode", b, w, v, got, want);
    }
}

static void compare_image(unsigned b, unsigned w, int32_t v, const uint8_t *img,
                          const struct calrec_binding *e)
{
    struct calrec out, ref_out;
    uint32_t seq = 1, ref_seq = 2;
    int got, want;

    got = calrec_check_image(img, CALREC_IMAGE_SIZE, e);
    want = ref_calrec_check_image(img, CALREC_IMAGE_SIZE, e);
    if (got != want) {
        note("check_image", b, w, v, got, want);
    }
    memset(&out, 0x77, sizeof out);
    memset(&ref_out, 0x77, sizeof ref_out);
    got = calrec_decode(img, CALREC_IMAGE_SIZE, e, &out, &seq);
    want = ref_calrec_decode(img, CALREC_IMAGE_SIZE, e, &ref_out, &ref_seq);
    if (got != want || seq != ref_seq || !fix_record_equal(&out, &ref_out)) {
        note("decode", b, w, v, got, want);
    }
}

static void test_every_word_every_edge(void)
{
    static int32_t vals[6u * (sizeof lims / sizeof lims[0]) + 6u];
    unsigned b, w, i, n;

    for (b = 0; b < BASES; b++) {
        struct calrec base;
        uint8_t base_img[CALREC_IMAGE_SIZE];
        make_base(&base, b);
        if (ref_calrec_check(&base) != INC_OK) {
            unit_fail(__FILE__, __LINE__, "base %u invalid", b);
            continue;
        }
        REQUIRE(ref_calrec_encode(&base, 40u + b, base_img, sizeof base_img) == INC_OK);
        compare_record(b, 0, 0, &base);
        compare_image(b, 0, 0, base_img, &base.binding);
        for (w = CALREC_OFF_BINDING / 4u; w < CALREC_OFF_CRC / 4u; w++) {
            /* A base that only sets up one model (1 .. 6 * kinds) is varied in that model. */
            if (b >= 1u && b <= 6u * CALREC_TM_KIND_COUNT &&
                (w - CALREC_OFF_ACC_TBIAS / 4u) / 20u != (b - 1u) / CALREC_TM_KIND_COUNT) {
                continue;
            }
            n = values(&base, w, vals);
            for (i = 0; i < n; i++) {
                struct calrec r = base;
                uint8_t img[CALREC_IMAGE_SIZE];
                patch_rec(&r, w, vals[i]);
                compare_record(b, w, vals[i], &r);
                memcpy(img, base_img, sizeof img);
                calrec_put_le32(&img[4u * w], (uint32_t)vals[i]);
                fix_reseal(img);
                compare_image(b, w, vals[i], img, &base.binding);
                /* The same image judged against the patched binding (binding words only). */
                if (w < CALREC_OFF_ACC_OFFSET / 4u) {
                    compare_image(b, w, vals[i], img, &r.binding);
                }
            }
        }
    }
    CHECK_EQ_INT(mismatches, 0);
}

/* Binding rules: every field over edge values, for each family 0..5. */
static void test_binding_edges(void)
{
    static const uint32_t edge[] = {0u,      1u,      0xFEu,    0xFFu,       0x100u,
                                    0xFFFEu, 0xFFFFu, 0x10000u, 0x80000000u, 0xFFFFFFFFu};
    unsigned fam, f, i;
    unsigned bad = 0;

    for (fam = 0; fam <= 5u; fam++) {
        for (f = 1; f < 6u; f++) {
            for (i = 0; i < sizeof edge / sizeof edge[0]; i++) {
                struct calrec_binding b;
                uint32_t *w = &b.product;
                fix_binding(&b);
                b.family = fam;
                if (fam == CALREC_FAMILY_SCA3000) {
                    b.serial = 0;
                    b.lot_id1 = 0;
                    b.lot_id2 = 0;
                }
                switch (f) {
                case 1: w = &b.product; break;
                case 2: w = &b.revision; break;
                case 3: w = &b.serial; break;
                case 4: w = &b.lot_id1; break;
                default: w = &b.lot_id2; break;
                }
                *w = edge[i];
                if (calrec_check_binding(&b) != ref_calrec_check_binding(&b)) {
                    if (bad++ < 4u) {
                        unit_fail(__FILE__, __LINE__, "family %u field %u value 0x%lx", fam, f,
                                  (unsigned long)edge[i]);
                    }
                }
            }
        }
    }
    CHECK_EQ_INT(bad, 0);
}

/* Header words, lengths and NULLs give the same codes, and both defaults are identical. */
static void test_header_and_lengths(void)
{
    static const uint32_t hv[] = {0u,   1u,   2u,   3u,   20u,          652u,
                                  655u, 656u, 657u, 660u, CALREC_MAGIC, 0xFFFFFFFFu};
    static const size_t lens[] = {0u, 3u, 15u, 16u, 17u, 655u, 656u, 700u};
    struct calrec r, ref_r;
    struct calrec_binding e;
    unsigned word, i, l;
    uint8_t img[700];

    fix_binding(&e);
    memset(&r, 0x11, sizeof r);
    memset(&ref_r, 0x11, sizeof ref_r);
    calrec_set_default(&r);
    ref_calrec_set_default(&ref_r);
    CHECK(fix_record_equal(&r, &ref_r));
    CHECK(fix_record_is_default(&r));
    fix_record(&r);
    for (word = 0; word < 4u; word++) {
        for (i = 0; i < sizeof hv / sizeof hv[0]; i++) {
            for (l = 0; l < sizeof lens / sizeof lens[0]; l++) {
                struct calrec out, ref_out;
                REQUIRE(calrec_encode(&r, 9u, img, sizeof img) == INC_OK);
                memset(&img[CALREC_IMAGE_SIZE], 0, sizeof img - CALREC_IMAGE_SIZE);
                calrec_put_le32(&img[4u * word], hv[i]);
                fix_reseal(img);
                CHECK_EQ_INT(calrec_check_image(img, lens[l], &e),
                             ref_calrec_check_image(img, lens[l], &e));
                CHECK_EQ_INT(calrec_decode(img, lens[l], &e, &out, NULL),
                             ref_calrec_decode(img, lens[l], &e, &ref_out, NULL));
                CHECK(fix_record_equal(&out, &ref_out));
            }
        }
    }
    CHECK_EQ_INT(calrec_encode(&r, 1u, img, CALREC_IMAGE_SIZE - 1u),
                 ref_calrec_encode(&r, 1u, img, CALREC_IMAGE_SIZE - 1u));
    CHECK_EQ_INT(calrec_check_image(img, 656u, NULL), ref_calrec_check_image(img, 656u, NULL));
    CHECK_EQ_INT(calrec_check(NULL), ref_calrec_check(NULL));
    CHECK(calrec_binding_equal(&e, &r.binding) == ref_calrec_binding_equal(&e, &r.binding));
    e.lot_id2 ^= 0x100u;
    CHECK(calrec_binding_equal(&e, &r.binding) == ref_calrec_binding_equal(&e, &r.binding));
    CHECK(!calrec_binding_equal(&e, &r.binding));
}

int main(void)
{
    UNIT_RUN(test_binding_edges);
    UNIT_RUN(test_header_and_lengths);
    UNIT_RUN(test_every_word_every_edge);
    return unit_report();
}
