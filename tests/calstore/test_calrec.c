/* Calibration record: golden bytes, round trip, range limits (struct and image paths agree),
 * binding rules, decode errors incl. every single-bit flip, NULL and size arguments. */
#include <string.h>

#include "fixture.h"
#include "inclino/calrec.h"
#include "unit.h"

#include "golden_v2.h"

static void test_golden_bytes(void)
{
    struct calrec r, back;
    uint8_t img[CALREC_IMAGE_SIZE];
    uint32_t seq = 0;
    unsigned i, diffs = 0;

    fix_record(&r);
    CHECK_OK(calrec_check(&r));
    REQUIRE(calrec_encode(&r, 7u, img, sizeof img) == INC_OK);
    for (i = 0; i < CALREC_IMAGE_SIZE; i++) {
        if (img[i] != golden_v2[i]) {
            if (diffs++ < 8u) {
                CHECK_EQ_HEX(img[i], golden_v2[i]);
            }
        }
    }
    CHECK_EQ_INT(diffs, 0);
    CHECK_EQ_HEX(calrec_get_le32(&img[CALREC_OFF_CRC]), GOLDEN_V2_CRC);
    /* And the golden image decodes to exactly the record. */
    CHECK_OK(calrec_decode(golden_v2, sizeof golden_v2, &r.binding, &back, &seq));
    CHECK_EQ_INT(seq, 7);
    CHECK(back.valid);
    r.valid = true;
    CHECK(fix_record_equal(&back, &r));
}

static void test_round_trip(void)
{
    static const uint32_t seqs[] = {0u, 1u, 0x7FFFFFFFu, 0x80000000u, 0xFFFFFFFFu};
    struct calrec r, back;
    uint8_t img[CALREC_IMAGE_SIZE + 8];
    unsigned v, a;
    uint32_t seq;

    for (v = 0; v < sizeof seqs / sizeof seqs[0]; v++) {
        fix_record_variant(&r, (int)v);
        /* Push several fields to their negative and positive extremes. */
        for (a = 0; a < CALREC_AXES; a++) {
            r.acc_offset[a] = (v & 1u) ? -CALREC_LIM_ACC_OFFSET : CALREC_LIM_ACC_OFFSET;
            r.gyro_offset[a] = (v & 1u) ? CALREC_LIM_GYRO_OFFSET : -CALREC_LIM_GYRO_OFFSET;
            r.acc_misalign[a][(a + 1u) % 3u] = -CALREC_LIM_MISALIGN_OFFDIAG;
        }
        memset(img, 0xA5, sizeof img);
        REQUIRE(calrec_encode(&r, seqs[v], img, sizeof img) == INC_OK);
        CHECK_EQ_HEX(img[CALREC_IMAGE_SIZE], 0xA5u); /* nothing written past the image */
        CHECK_OK(calrec_decode(img, CALREC_IMAGE_SIZE, &r.binding, &back, &seq));
        CHECK_EQ_HEX(seq, seqs[v]);
        r.valid = true;
        CHECK(fix_record_equal(&back, &r));
    }
}

/* ---- Range limits: one table, checked on the struct and on the image. ---------------------- */

#define FIELD(name, expr)                  \
    static int32_t *name(struct calrec *r) \
    {                                      \
        return &(expr);                    \
    }
FIELD(f_acc_off0, r->acc_offset[0])
FIELD(f_acc_gain1, r->acc_gain[1])
FIELD(f_mis00, r->acc_misalign[0][0])
FIELD(f_mis01, r->acc_misalign[0][1])
FIELD(f_nl10, r->acc_nonlin[1][0])
FIELD(f_nl21, r->acc_nonlin[2][1])
FIELD(f_nl03, r->acc_nonlin[0][3])
FIELD(f_gyoff2, r->gyro_offset[2])
FIELD(f_gysc0, r->gyro_scale[0])
FIELD(f_tb0_p2, r->acc_tbias[0].p[2])
FIELD(f_tb0_tref, r->acc_tbias[0].t_ref)
FIELD(f_tb0_span, r->acc_tbias[0].t_span)
FIELD(f_tb0_n, r->acc_tbias[0].n)
FIELD(f_tb0_p3, r->acc_tbias[0].p[3])
FIELD(f_tb1_p2, r->acc_tbias[1].p[2])
FIELD(f_tb2_tref, r->acc_tbias[2].t_ref)
FIELD(f_tb2_w, r->acc_tbias[2].p[2])
FIELD(f_tb2_tc, r->acc_tbias[2].p[3])
FIELD(f_tb2_a, r->acc_tbias[2].p[1])
FIELD(f_ts0_kind, r->acc_tscale[0].kind)
FIELD(f_ts0_n, r->acc_tscale[0].n)
FIELD(f_ts0_p9, r->acc_tscale[0].p[9])
FIELD(f_ts0_p8, r->acc_tscale[0].p[8])
FIELD(f_ts0_span, r->acc_tscale[0].t_span)
FIELD(f_ts1_p0, r->acc_tscale[1].p[0])
FIELD(f_ts1_tref, r->acc_tscale[1].t_ref)
FIELD(f_ts1_kind, r->acc_tscale[1].kind)
FIELD(f_ts2_p1, r->acc_tscale[2].p[1])

struct limit_case {
    const char *what;
    int32_t *(*field)(struct calrec *r);
    uint32_t off; /* image offset, written out from the layout table in the docs */
    int32_t ok;   /* accepted (at the limit) */
    int32_t bad;  /* rejected (one step beyond) */
};

static const struct limit_case limits[] = {
    {"acc_offset max", f_acc_off0, 40, 32768, 32769},
    {"acc_offset min", f_acc_off0, 40, -32768, -32769},
    {"acc_gain min", f_acc_gain1, 56, 805306368, 805306367},
    {"acc_gain max", f_acc_gain1, 56, 1342177280, 1342177281},
    {"acc_gain negative (swapped +-1g)", f_acc_gain1, 56, 1073741824, -1073741824},
    {"misalign diag min", f_mis00, 64, 805306368, 805306367},
    {"misalign offdiag max", f_mis01, 68, 134217728, 134217729},
    {"misalign offdiag min", f_mis01, 68, -134217728, -134217729},
    {"nonlin c0 max", f_nl10, 116, 67108864, 67108865},
    {"nonlin c1 min", f_nl21, 136, -67108864, -67108865},
    {"nonlin c3 max", f_nl03, 112, 268435456, 268435457},
    {"gyro_offset max", f_gyoff2, 636, 1966080, 1966081},
    {"gyro_offset INT32_MIN", f_gyoff2, 636, -1966080, INT32_MIN},
    {"gyro_scale max", f_gysc0, 640, 1342177280, 1342177281},
    {"parabola a max", f_tb0_p2, 172, 32768, 32769},
    {"parabola t_ref max", f_tb0_tref, 156, 13107200, 13107201},
    {"parabola t_span min", f_tb0_span, 160, 65536, 65535},
    {"parabola n must be 0", f_tb0_n, 152, 0, 1},
    {"parabola unused p3", f_tb0_p3, 176, 0, 1},
    {"linear unused p2", f_tb1_p2, 252, 0, 1},
    {"lorentz t_ref must be 0", f_tb2_tref, 316, 0, 1},
    {"lorentz w min", f_tb2_w, 332, 65536, 65535},
    {"lorentz w max", f_tb2_w, 332, 26214400, 26214401},
    {"lorentz Tc min", f_tb2_tc, 336, -6553600, -6553601},
    {"lorentz A min", f_tb2_a, 328, -32768, -32769},
    {"unknown model kind", f_ts0_kind, 388, 4, 6},
    {"negative model kind", f_ts0_kind, 388, 4, -1},
    {"pwl n max", f_ts0_n, 392, 16, 17},
    {"pwl n = 0", f_ts0_n, 392, 9, 0},
    {"pwl word beyond n", f_ts0_p9, 440, 0, 1},
    {"pwl y max (scale limit)", f_ts0_p8, 436, 134217728, 134217729},
    {"pwl last knot <= 200 degC", f_ts0_span, 400, 1802240, 1802241},
    {"none: p0 must be 0", f_ts1_p0, 484, 0, 1},
    {"none: t_ref must be 0", f_ts1_tref, 476, 0, 65536},
    {"none -> unknown kind", f_ts1_kind, 468, 0, 99},
    {"linear scale slope min", f_ts2_p1, 568, -134217728, -134217729},
};

static void test_limits(void)
{
    unsigned i;
    for (i = 0; i < sizeof limits / sizeof limits[0]; i++) {
        const struct limit_case *c = &limits[i];
        struct calrec r, back;
        uint8_t img[CALREC_IMAGE_SIZE], ok_img[CALREC_IMAGE_SIZE];
        int err;

        /* Struct path. */
        fix_record(&r);
        *c->field(&r) = c->ok;
        err = calrec_check(&r);
        if (err) {
            unit_fail(__FILE__, __LINE__, "%s: ok value %ld rejected (%d)", c->what, (long)c->ok,
                      err);
        }
        REQUIRE(calrec_encode(&r, 1u, ok_img, sizeof ok_img) == INC_OK);
        /* The table's offset really is where the encoder put the field. */
        CHECK_EQ_HEX(calrec_get_le32(&ok_img[c->off]), (uint32_t)c->ok);
        *c->field(&r) = c->bad;
        CHECK_ERR(calrec_check(&r), INC_ERR_RANGE);
        memset(img, 0x5A, sizeof img);
        CHECK_ERR(calrec_encode(&r, 1u, img, sizeof img), INC_ERR_RANGE);
        CHECK_EQ_HEX(img[0], 0x5Au); /* a refused encode writes nothing */

        /* Image path: the same value patched into a sealed image. */
        memcpy(img, ok_img, sizeof img);
        CHECK_OK(calrec_check_image(img, sizeof img, &r.binding));
        calrec_put_le32(&img[c->off], (uint32_t)c->bad);
        fix_reseal(img);
        err = calrec_check_image(img, sizeof img, &r.binding);
        if (err != INC_ERR_RANGE) {
            unit_fail(__FILE__, __LINE__, "%s: image with %ld gave %d, want RANGE", c->what,
                      (long)c->bad, err);
        }
        CHECK_ERR(calrec_decode(img, sizeof img, &r.binding, &back, NULL), INC_ERR_RANGE);
        CHECK(fix_record_is_default(&back));
    }
}

/* LORENTZ_CUBIC (format version 2): accepted inside its limits, round trip exact, every limit
 * and unused word enforced on the struct and on the image. */
static void test_lorentz_cubic_kind(void)
{
    struct calrec r, back;
    uint8_t img[CALREC_IMAGE_SIZE];
    struct calrec_tmodel *m;
    unsigned i;
    /* Each case: which word, accepted value, rejected value. */
    static const struct {
        unsigned word; /* 2 = t_ref, 3 = t_span, 4 + k = p[k] */
        int32_t ok, bad;
    } cases[] = {
        {2, -6553600, -6553601},     /* t_ref >= -100 degC */
        {3, 65536, 65535},           /* t_span >= 1 degC */
        {3, 13107200, 13107201},     /* t_span <= 200 degC */
        {4 + 1, -32768, -32769},     /* height within the bias limit (0.5 g) */
        {4 + 2, 26214400, 26214401}, /* w <= 400 degC */
        {4 + 3, 13107200, 13107201}, /* Tc <= 200 degC */
        {4 + 6, 32768, 32769},       /* cubic coefficient within the bias limit */
        {4 + 7, 0, 1},               /* first unused word */
        {4 + 15, 0, -1},             /* last unused word */
    };

    fix_record(&r);
    m = &r.acc_tbias[1];
    m->kind = CALREC_TM_LORENTZ_CUBIC;
    m->t_ref = 20 * CALREC_Q16_ONE;
    m->t_span = 40 * CALREC_Q16_ONE;
    m->p[0] = -700;
    m->p[1] = 800;
    m->p[2] = 26 * CALREC_Q16_ONE;
    m->p[3] = -25 * CALREC_Q16_ONE;
    m->p[4] = 30;
    m->p[5] = -12;
    m->p[6] = -120;
    CHECK_OK(calrec_check(&r));
    REQUIRE(calrec_encode(&r, 3u, img, sizeof img) == INC_OK);
    /* tbias[y] starts at 148 + 80: kind, n, t_ref, t_span, p0.. */
    CHECK_EQ_HEX(calrec_get_le32(&img[228]), (uint32_t)CALREC_TM_LORENTZ_CUBIC);
    CHECK_EQ_HEX(calrec_get_le32(&img[228 + 16 + 24]), (uint32_t)-120);
    CHECK_OK(calrec_decode(img, sizeof img, &r.binding, &back, NULL));
    r.valid = true; /* decode marks its output valid */
    CHECK(fix_record_equal(&back, &r));
    r.valid = false;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        int32_t *w = cases[i].word == 2   ? &m->t_ref
                     : cases[i].word == 3 ? &m->t_span
                                          : &m->p[cases[i].word - 4];
        const int32_t keep = *w;
        uint8_t bad[CALREC_IMAGE_SIZE];
        *w = cases[i].ok;
        CHECK_OK(calrec_check(&r));
        *w = cases[i].bad;
        CHECK_ERR(calrec_check(&r), INC_ERR_RANGE);
        memcpy(bad, img, sizeof bad);
        calrec_put_le32(&bad[228 + 4 * cases[i].word], (uint32_t)cases[i].bad);
        fix_reseal(bad);
        CHECK_ERR(calrec_check_image(bad, sizeof bad, &r.binding), INC_ERR_RANGE);
        *w = keep;
    }
    m->n = 1; /* n is a PWL field */
    CHECK_ERR(calrec_check(&r), INC_ERR_RANGE);
    /* The scale-factor deviation limit (0.125 in Q30) applies to a tscale model. */
    r.acc_tscale[1] = *m;
    m->n = 0;
    r.acc_tscale[1].n = 0;
    r.acc_tscale[1].p[5] = CALREC_LIM_TSCALE;
    CHECK_OK(calrec_check(&r));
    r.acc_tscale[1].p[5] = CALREC_LIM_TSCALE + 1;
    CHECK_ERR(calrec_check(&r), INC_ERR_RANGE);
}

/* The smallest table: 2 knots is accepted, 1 knot is not (words beyond n all 0 in both). */
static void test_pwl_two_knots(void)
{
    struct calrec r;
    fix_record(&r);
    r.acc_tscale[1].kind = CALREC_TM_PWL;
    r.acc_tscale[1].n = 2;
    r.acc_tscale[1].t_ref = 0;
    r.acc_tscale[1].t_span = CALREC_LIM_SPAN_MAX; /* 0 and 200 degC: last knot at the limit */
    r.acc_tscale[1].p[0] = -5;
    r.acc_tscale[1].p[1] = 5;
    CHECK_OK(calrec_check(&r));
    r.acc_tscale[1].t_ref = 1;
    CHECK_ERR(calrec_check(&r), INC_ERR_RANGE);
    r.acc_tscale[1].t_ref = 0;
    r.acc_tscale[1].n = 1;
    r.acc_tscale[1].p[1] = 0;
    CHECK_ERR(calrec_check(&r), INC_ERR_RANGE);
}

static void test_binding_rules(void)
{
    struct calrec_binding b, e;

    fix_binding(&b);
    CHECK_OK(calrec_check_binding(&b));
    b.family = 0;
    CHECK_ERR(calrec_check_binding(&b), INC_ERR_INVAL);
    b.family = 5; /* the first family not in enum calrec_family */
    CHECK_ERR(calrec_check_binding(&b), INC_ERR_INVAL);
    b.family = CALREC_FAMILY_GENERIC; /* an IMU no driver reads: the common ranges only */
    b.revision = 7;
    CHECK_OK(calrec_check_binding(&b));
    b.product = 0;
    CHECK_ERR(calrec_check_binding(&b), INC_ERR_INVAL);
    fix_binding(&b);
    b.product = 0;
    CHECK_ERR(calrec_check_binding(&b), INC_ERR_INVAL);
    b.product = 0x10000u;
    CHECK_ERR(calrec_check_binding(&b), INC_ERR_INVAL);
    fix_binding(&b);
    b.revision = 1; /* REVID belongs to the SCA3000 */
    CHECK_ERR(calrec_check_binding(&b), INC_ERR_INVAL);
    fix_binding(&b);
    b.serial = 0x10000u;
    CHECK_ERR(calrec_check_binding(&b), INC_ERR_INVAL);
    fix_binding(&b);
    b.lot_id2 = 0x10000u;
    CHECK_ERR(calrec_check_binding(&b), INC_ERR_INVAL);

    /* SCA3000: variant code + REVID, no serial. */
    memset(&b, 0, sizeof b);
    b.family = CALREC_FAMILY_SCA3000;
    b.product = CALREC_SCA3000_E02;
    b.revision = 0xFFu;
    CHECK_OK(calrec_check_binding(&b));
    b.revision = 0x100u;
    CHECK_ERR(calrec_check_binding(&b), INC_ERR_INVAL);
    b.revision = 0x12u;
    b.serial = 1;
    CHECK_ERR(calrec_check_binding(&b), INC_ERR_INVAL);
    b.serial = 0;
    b.lot_id1 = 1;
    CHECK_ERR(calrec_check_binding(&b), INC_ERR_INVAL);

    /* ADIS16255: part number only. */
    memset(&b, 0, sizeof b);
    b.family = CALREC_FAMILY_ADIS1625X;
    b.product = 16255u;
    CHECK_OK(calrec_check_binding(&b));

    fix_binding(&b);
    fix_binding(&e);
    CHECK(calrec_binding_equal(&b, &e));
    e.lot_id1 ^= 1u;
    CHECK(!calrec_binding_equal(&b, &e));
    CHECK(!calrec_binding_equal(NULL, &e));
    CHECK(!calrec_binding_equal(&b, NULL));
    CHECK_ERR(calrec_check_binding(NULL), INC_ERR_NULL);
}

static void test_wrong_sensor(void)
{
    struct calrec_binding e;
    struct calrec out;
    uint32_t seq = 99;
    unsigned field;

    for (field = 0; field < 6u; field++) {
        fix_binding(&e);
        switch (field) {
        case 0: e.family = CALREC_FAMILY_ADIS1625X; break;
        case 1: e.product = 16365u; break;
        case 2:
            e.family = CALREC_FAMILY_SCA3000;
            e.product = CALREC_SCA3000_D01;
            e.revision = 0x21u;
            e.serial = 0;
            e.lot_id1 = 0;
            e.lot_id2 = 0;
            break;
        case 3: e.serial = 0x1235u; break;
        case 4: e.lot_id1 = 0xA5A4u; break;
        default: e.lot_id2 = 0x0043u; break;
        }
        CHECK_ERR(calrec_decode(golden_v2, sizeof golden_v2, &e, &out, &seq), INC_ERR_MISMATCH);
        CHECK(fix_record_is_default(&out));
        CHECK_EQ_INT(seq, 0);
    }
    /* An invalid expected binding is a caller error, not a mismatch. */
    fix_binding(&e);
    e.family = 0;
    CHECK_ERR(calrec_decode(golden_v2, sizeof golden_v2, &e, &out, &seq), INC_ERR_INVAL);
    CHECK(fix_record_is_default(&out));
}

/* The binding an image carries, read without a check (calrec_image_binding): the golden image's
 * is the fixture's; too short an image or a NULL is refused and leaves *out as it was. */
static void test_image_binding(void)
{
    struct calrec_binding want, got, keep;
    fix_binding(&want);
    memset(&got, 0x5A, sizeof got);
    CHECK_OK(calrec_image_binding(golden_v2, sizeof golden_v2, &got));
    CHECK(calrec_binding_equal(&got, &want));
    CHECK_OK(calrec_image_binding(golden_v2, CALREC_OFF_BINDING + 24u, &got)); /* just enough */
    memset(&got, 0x5A, sizeof got);
    keep = got;
    CHECK_ERR(calrec_image_binding(golden_v2, CALREC_OFF_BINDING + 23u, &got), INC_ERR_INVAL);
    CHECK(memcmp(&got, &keep, sizeof got) == 0);
    CHECK_ERR(calrec_image_binding(NULL, sizeof golden_v2, &got), INC_ERR_NULL);
    CHECK_ERR(calrec_image_binding(golden_v2, sizeof golden_v2, NULL), INC_ERR_NULL);
}

static void test_header_errors(void)
{
    struct calrec_binding e;
    struct calrec out;
    uint8_t img[CALREC_IMAGE_SIZE];

    fix_binding(&e);
    memcpy(img, golden_v2, sizeof img);
    /* Version 1 (the layout before LORENTZ_CUBIC) and a future version 3 are both refused. */
    calrec_put_le32(&img[CALREC_OFF_VERSION], 1u);
    fix_reseal(img);
    CHECK_ERR(calrec_decode(img, sizeof img, &e, &out, NULL), INC_ERR_VERSION);
    CHECK(fix_record_is_default(&out));
    calrec_put_le32(&img[CALREC_OFF_VERSION], 3u);
    fix_reseal(img);
    CHECK_ERR(calrec_decode(img, sizeof img, &e, &out, NULL), INC_ERR_VERSION);
    CHECK(fix_record_is_default(&out));
    calrec_put_le32(&img[CALREC_OFF_VERSION], 0u);
    fix_reseal(img);
    CHECK_ERR(calrec_decode(img, sizeof img, &e, &out, NULL), INC_ERR_VERSION);

    memcpy(img, golden_v2, sizeof img);
    calrec_put_le32(&img[CALREC_OFF_LENGTH], 660u);
    fix_reseal(img);
    CHECK_ERR(calrec_decode(img, sizeof img, &e, &out, NULL), INC_ERR_VERSION);

    memcpy(img, golden_v2, sizeof img);
    img[0] = 'X';
    CHECK_ERR(calrec_decode(img, sizeof img, &e, &out, NULL), INC_ERR_CRC);

    memcpy(img, golden_v2, sizeof img);
    CHECK_ERR(calrec_decode(img, CALREC_IMAGE_SIZE - 1u, &e, &out, NULL), INC_ERR_INVAL);
    CHECK_ERR(calrec_decode(img, 3u, &e, &out, NULL), INC_ERR_INVAL);
    CHECK(fix_record_is_default(&out));
}

/* Every single-bit flip anywhere in the image is rejected and leaves the safe default. */
static void test_every_bit_flip(void)
{
    struct calrec_binding e;
    struct calrec out;
    uint8_t img[CALREC_IMAGE_SIZE];
    unsigned byte, bit, accepted = 0, not_default = 0, wrong_code = 0;
    uint32_t seq;

    fix_binding(&e);
    memcpy(img, golden_v2, sizeof img);
    for (byte = 0; byte < CALREC_IMAGE_SIZE; byte++) {
        /* A flipped version or length word is reported as a version problem (the header is
         * judged before the CRC); anything else, magic included, as corruption. */
        int want = (byte >= CALREC_OFF_VERSION && byte < CALREC_OFF_SEQ) ? INC_ERR_VERSION
                                                                         : INC_ERR_CRC;
        for (bit = 0; bit < 8u; bit++) {
            int err;
            img[byte] ^= (uint8_t)(1u << bit);
            err = calrec_decode(img, sizeof img, &e, &out, &seq);
            accepted += (err == INC_OK);
            not_default += !fix_record_is_default(&out) || seq != 0u;
            if (err != want) {
                if (wrong_code++ < 4u) {
                    unit_fail(__FILE__, __LINE__, "flip %u.%u gave %d, want %d", byte, bit, err,
                              want);
                }
            }
            img[byte] ^= (uint8_t)(1u << bit);
        }
    }
    CHECK_EQ_INT(accepted, 0);
    CHECK_EQ_INT(not_default, 0);
    CHECK_EQ_INT(wrong_code, 0);
}

static void test_null_and_sizes(void)
{
    struct calrec r, out;
    struct calrec_binding e;
    uint8_t img[CALREC_IMAGE_SIZE];
    uint32_t seq = 5;

    fix_record(&r);
    fix_binding(&e);
    CHECK_ERR(calrec_check(NULL), INC_ERR_NULL);
    CHECK_ERR(calrec_encode(NULL, 0, img, sizeof img), INC_ERR_NULL);
    CHECK_ERR(calrec_encode(&r, 0, NULL, sizeof img), INC_ERR_NULL);
    memset(img, 0x33, sizeof img);
    CHECK_ERR(calrec_encode(&r, 0, img, sizeof img - 1u), INC_ERR_NO_SPACE);
    CHECK_EQ_HEX(img[0], 0x33u);
    CHECK_ERR(calrec_decode(golden_v2, sizeof golden_v2, &e, NULL, &seq), INC_ERR_NULL);
    CHECK_EQ_INT(seq, 0);
    out.valid = true;
    CHECK_ERR(calrec_decode(NULL, sizeof golden_v2, &e, &out, NULL), INC_ERR_NULL);
    CHECK(fix_record_is_default(&out));
    out.valid = true;
    CHECK_ERR(calrec_decode(golden_v2, sizeof golden_v2, NULL, &out, NULL), INC_ERR_NULL);
    CHECK(fix_record_is_default(&out));
    CHECK_ERR(calrec_check_image(NULL, 10, &e), INC_ERR_NULL);
    CHECK_ERR(calrec_check_image(golden_v2, sizeof golden_v2, NULL), INC_ERR_NULL);
    /* A record with the default (unbound) binding can never be stored. */
    calrec_set_default(&r);
    CHECK(fix_record_is_default(&r));
    CHECK_ERR(calrec_encode(&r, 0, img, sizeof img), INC_ERR_INVAL);
    calrec_set_default(NULL); /* must not crash */
    CHECK_EQ_HEX(calrec_get_le32((const uint8_t *)"\x01\x02\x03\x84"), 0x84030201u);
}

int main(void)
{
    UNIT_RUN(test_golden_bytes);
    UNIT_RUN(test_lorentz_cubic_kind);
    UNIT_RUN(test_round_trip);
    UNIT_RUN(test_limits);
    UNIT_RUN(test_pwl_two_knots);
    UNIT_RUN(test_binding_rules);
    UNIT_RUN(test_wrong_sensor);
    UNIT_RUN(test_image_binding);
    UNIT_RUN(test_header_errors);
    UNIT_RUN(test_every_bit_flip);
    UNIT_RUN(test_null_and_sizes);
    return unit_report();
}
