/*
 * calrec.c - calibration record: default, range checks, little-endian codec.
 *
 * Why an explicit codec and not memcpy of the struct: the image has to be identical whether the
 * host tool on x86-64, a Cortex-M or a RISC-V part wrote it, so every word goes through
 * calrec_put_le32 / calrec_get_le32 in the documented order, whatever the CPU's byte order. The
 * struct's members are all 32-bit words declared in image order (and bool valid last); the
 * asserts below pin that it has no padding before `valid`, so the codec and the range checks
 * walk it by word index. The golden-bytes test in tests/calstore pins the order.
 *
 * Why the range checks are strict (unused words must be 0, kinds must be known): a record with a
 * valid CRC can still come from a buggy or newer tool; anything this firmware cannot interpret
 * exactly is refused rather than half-used. Limits are sanity bounds far outside what a working
 * part produces ([ADI-EPB] budget: 15 mg initial offset, 30 mg/g sensitivity error, 50 mg drift)
 * and far inside what would make the fixed-point stages overflow.
 */
#include "inclino/calrec.h"

#include "inclino/crc32.h"

/* The layout constants of calrec.h must tile the image exactly. */
_Static_assert(CALREC_OFF_BINDING == CALREC_HEADER_SIZE, "binding follows the header");
_Static_assert(CALREC_OFF_ACC_OFFSET == CALREC_OFF_BINDING + 6u * 4u, "layout");
_Static_assert(CALREC_OFF_ACC_GAIN == CALREC_OFF_ACC_OFFSET + CALREC_AXES * 4u, "layout");
_Static_assert(CALREC_OFF_ACC_MISALIGN == CALREC_OFF_ACC_GAIN + CALREC_AXES * 4u, "layout");
_Static_assert(CALREC_OFF_ACC_NONLIN == CALREC_OFF_ACC_MISALIGN + CALREC_AXES * CALREC_AXES * 4u,
               "layout");
_Static_assert(CALREC_OFF_ACC_TBIAS ==
                   CALREC_OFF_ACC_NONLIN + CALREC_AXES * CALREC_NONLIN_TERMS * 4u,
               "layout");
_Static_assert(CALREC_TMODEL_SIZE == (4u + CALREC_TM_PARAMS) * 4u, "layout");
_Static_assert(CALREC_OFF_ACC_TSCALE == CALREC_OFF_ACC_TBIAS + CALREC_AXES * CALREC_TMODEL_SIZE,
               "layout");
_Static_assert(CALREC_OFF_GYRO_OFFSET == CALREC_OFF_ACC_TSCALE + CALREC_AXES * CALREC_TMODEL_SIZE,
               "layout");
_Static_assert(CALREC_OFF_GYRO_SCALE == CALREC_OFF_GYRO_OFFSET + CALREC_AXES * 4u, "layout");
_Static_assert(CALREC_OFF_CRC == CALREC_OFF_GYRO_SCALE + CALREC_AXES * 4u, "layout");
_Static_assert(CALREC_IMAGE_SIZE == CALREC_OFF_CRC + 4u, "layout");

/* The in-RAM record, less `valid`, is the image's words [CALREC_OFF_BINDING, CALREC_OFF_CRC) in
 * image order, each a uint32_t or int32_t: the codec and the checks below walk it by word index.
 * Asserted here, so a compiler that padded the struct could not build a wrong codec. */
_Static_assert(sizeof(struct calrec_binding) == 6u * 4u, "binding is 6 words");
_Static_assert(sizeof(struct calrec_tmodel) == CALREC_TMODEL_SIZE, "model is 20 words");
_Static_assert(offsetof(struct calrec, acc_offset) == CALREC_OFF_ACC_OFFSET - CALREC_OFF_BINDING,
               "struct layout = image layout");
_Static_assert(offsetof(struct calrec, acc_gain) == CALREC_OFF_ACC_GAIN - CALREC_OFF_BINDING,
               "struct layout = image layout");
_Static_assert(offsetof(struct calrec, acc_misalign) ==
                   CALREC_OFF_ACC_MISALIGN - CALREC_OFF_BINDING,
               "struct layout = image layout");
_Static_assert(offsetof(struct calrec, acc_nonlin) == CALREC_OFF_ACC_NONLIN - CALREC_OFF_BINDING,
               "struct layout = image layout");
_Static_assert(offsetof(struct calrec, acc_tbias) == CALREC_OFF_ACC_TBIAS - CALREC_OFF_BINDING,
               "struct layout = image layout");
_Static_assert(offsetof(struct calrec, acc_tscale) == CALREC_OFF_ACC_TSCALE - CALREC_OFF_BINDING,
               "struct layout = image layout");
_Static_assert(offsetof(struct calrec, gyro_offset) == CALREC_OFF_GYRO_OFFSET - CALREC_OFF_BINDING,
               "struct layout = image layout");
_Static_assert(offsetof(struct calrec, gyro_scale) == CALREC_OFF_GYRO_SCALE - CALREC_OFF_BINDING,
               "struct layout = image layout");
_Static_assert(offsetof(struct calrec, valid) == CALREC_OFF_CRC - CALREC_OFF_BINDING,
               "struct layout = image layout");

/* Image word indices (byte offset / 4). */
#define W_BINDING (CALREC_OFF_BINDING / 4u)
#define W_ACC_OFFSET (CALREC_OFF_ACC_OFFSET / 4u)
#define W_ACC_TBIAS (CALREC_OFF_ACC_TBIAS / 4u)
#define W_GYRO_OFFSET (CALREC_OFF_GYRO_OFFSET / 4u)
#define W_CRC (CALREC_OFF_CRC / 4u)
#define REC_WORDS (W_CRC - W_BINDING)            /* stored words of struct calrec: 159 */
#define BINDING_WORDS (W_ACC_OFFSET - W_BINDING) /* 6 */
#define TM_WORDS (CALREC_TMODEL_SIZE / 4u)       /* 20 */
#define TM_COUNT (2u * CALREC_AXES)              /* acc_tbias[0..2], then acc_tscale[0..2] */
#define SCALARS_LOW (W_ACC_TBIAS - W_ACC_OFFSET) /* acc_offset .. acc_nonlin: 27 words */
#define SCALARS_HIGH (W_CRC - W_GYRO_OFFSET)     /* gyro_offset, gyro_scale: 6 words */
_Static_assert(CALREC_OFF_GYRO_OFFSET == CALREC_OFF_ACC_TBIAS + TM_COUNT * CALREC_TMODEL_SIZE,
               "the six models are contiguous");

uint32_t calrec_get_le32(const uint8_t *p)
{
    return (uint32_t)p[0] | ((uint32_t)p[1] << 8) | ((uint32_t)p[2] << 16) | ((uint32_t)p[3] << 24);
}

void calrec_put_le32(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)(v & 0xFFu);
    p[1] = (uint8_t)((v >> 8) & 0xFFu);
    p[2] = (uint8_t)((v >> 16) & 0xFFu);
    p[3] = (uint8_t)((v >> 24) & 0xFFu);
}

/* uint32 -> int32 two's complement without relying on implementation-defined conversion. */
static int32_t u32_to_i32(uint32_t v)
{
    if (v <= (uint32_t)INT32_MAX) {
        return (int32_t)v;
    }
    return (int32_t)(v - 0x80000000u) - INT32_MAX - 1;
}

/* Word i of a record or binding (every member is a uint32_t or int32_t, see the asserts). */
static uint32_t word_get(const void *base, unsigned i)
{
    return *(const uint32_t *)(const void *)((const unsigned char *)base + 4u * i);
}

static void word_set(void *base, unsigned i, uint32_t v)
{
    *(uint32_t *)(void *)((unsigned char *)base + 4u * i) = v;
}

void calrec_set_default(struct calrec *rec)
{
    unsigned i;

    if (rec == NULL) {
        return;
    }
    /* Binding 0, offsets, nonlinearity and every model word 0 (kind 0 = CALREC_TM_NONE)... */
    for (i = 0; i < REC_WORDS; i++) {
        word_set(rec, i, 0u);
    }
    /* ...then the unit gains, scales and misalignment diagonal. */
    for (i = 0; i < CALREC_AXES; i++) {
        rec->acc_gain[i] = CALREC_Q30_ONE;
        rec->acc_misalign[i][i] = CALREC_Q30_ONE;
        rec->gyro_scale[i] = CALREC_Q30_ONE;
    }
    rec->valid = false;
}

int calrec_check_binding(const struct calrec_binding *b)
{
    uint32_t ids;

    if (b == NULL) {
        return INC_ERR_NULL;
    }
    ids = b->serial | b->lot_id1 | b->lot_id2;
    if (b->product == 0u || b->product > 0xFFFFu || b->revision > 0xFFu || ids > 0xFFFFu) {
        return INC_ERR_INVAL;
    }
    switch (b->family) {
    case CALREC_FAMILY_SCA3000:
        /* No serial or lot registers on the SCA3000 (docs/sensor-facts.md §1.3). */
        return ids != 0u ? INC_ERR_INVAL : INC_OK;
    case CALREC_FAMILY_ADIS1625X:
    case CALREC_FAMILY_ADIS163XX:
        /* REVID is an SCA3000 register; the ADIS parts identify by PROD_ID (docs/sensor-facts.md §3.5). */
        return b->revision != 0u ? INC_ERR_INVAL : INC_OK;
    case CALREC_FAMILY_GENERIC: return INC_OK; /* the common ranges above only */
    default: return INC_ERR_INVAL;
    }
}

bool calrec_binding_equal(const struct calrec_binding *a, const struct calrec_binding *b)
{
    unsigned i;

    if (a == NULL || b == NULL) {
        return false;
    }
    for (i = 0; i < BINDING_WORDS; i++) {
        if (word_get(a, i) != word_get(b, i)) {
            return false;
        }
    }
    return true;
}

/* ---- Range checks: one table of inclusive limits, indexed by a word's class ----------------- */

enum lim_class {
    L_ZERO,     /* unused word: must be 0 */
    L_ACC_OFF,  /* acc_offset */
    L_GAIN,     /* acc_gain, misalignment diagonal, gyro_scale */
    L_OFFDIAG,  /* misalignment off-diagonal */
    L_C01,      /* nonlinearity c0, c1 */
    L_C23,      /* nonlinearity c2, c3 */
    L_GYRO_OFF, /* gyro_offset */
    L_TBIAS,    /* y parameter of a bias model */
    L_TSCALE,   /* y parameter of a scale-factor model */
    L_T,        /* temperature: t_ref, PWL first knot, Lorentz centre */
    L_SPAN,     /* t_span */
    L_WIDTH,    /* Lorentz full width */
    L_KNOTS,    /* PWL knot count */
    L_Y         /* in tm_class only: the model's y class (L_TBIAS or L_TSCALE) */
};

static const int32_t lim[L_Y][2] = {
    [L_ZERO] = {0, 0},
    [L_ACC_OFF] = {-CALREC_LIM_ACC_OFFSET, CALREC_LIM_ACC_OFFSET},
    [L_GAIN] = {CALREC_LIM_GAIN_MIN, CALREC_LIM_GAIN_MAX},
    [L_OFFDIAG] = {-CALREC_LIM_MISALIGN_OFFDIAG, CALREC_LIM_MISALIGN_OFFDIAG},
    [L_C01] = {-CALREC_LIM_NONLIN_C01, CALREC_LIM_NONLIN_C01},
    [L_C23] = {-CALREC_LIM_NONLIN_C23, CALREC_LIM_NONLIN_C23},
    [L_GYRO_OFF] = {-CALREC_LIM_GYRO_OFFSET, CALREC_LIM_GYRO_OFFSET},
    [L_TBIAS] = {-CALREC_LIM_TBIAS, CALREC_LIM_TBIAS},
    [L_TSCALE] = {-CALREC_LIM_TSCALE, CALREC_LIM_TSCALE},
    [L_T] = {CALREC_LIM_T_MIN, CALREC_LIM_T_MAX},
    [L_SPAN] = {CALREC_LIM_SPAN_MIN, CALREC_LIM_SPAN_MAX},
    [L_WIDTH] = {CALREC_LIM_SPAN_MIN, CALREC_LIM_WIDTH_MAX},
    [L_KNOTS] = {2, CALREC_TM_PARAMS},
};

/* Class of each scalar word: acc_offset[3], acc_gain[3], acc_misalign[3][3], acc_nonlin[3][4]
 * (image words W_ACC_OFFSET..), then gyro_offset[3], gyro_scale[3] (W_GYRO_OFFSET..). */
static const uint8_t scalar_class[SCALARS_LOW + SCALARS_HIGH] = {
    L_ACC_OFF,  L_ACC_OFF,  L_ACC_OFF,  L_GAIN,    L_GAIN,    L_GAIN, L_GAIN, L_OFFDIAG, L_OFFDIAG,
    L_OFFDIAG,  L_GAIN,     L_OFFDIAG,  L_OFFDIAG, L_OFFDIAG, L_GAIN, L_C01,  L_C01,     L_C23,
    L_C23,      L_C01,      L_C01,      L_C23,     L_C23,     L_C01,  L_C01,  L_C23,     L_C23,
    L_GYRO_OFF, L_GYRO_OFF, L_GYRO_OFF, L_GAIN,    L_GAIN,    L_GAIN,
};

/* Class of model words n, t_ref, t_span, p0..p6 per kind (p7..p15 are L_ZERO for every kind;
 * PWL's p words are L_Y below n and L_ZERO from n on). */
#define TM_CLASSED 10u
static const uint8_t tm_class[CALREC_TM_KIND_COUNT][TM_CLASSED] = {
    [CALREC_TM_NONE] = {L_ZERO, L_ZERO, L_ZERO, L_ZERO, L_ZERO, L_ZERO, L_ZERO, L_ZERO, L_ZERO,
                        L_ZERO},
    [CALREC_TM_LINEAR] = {L_ZERO, L_T, L_SPAN, L_Y, L_Y, L_ZERO, L_ZERO, L_ZERO, L_ZERO, L_ZERO},
    [CALREC_TM_PARABOLA] = {L_ZERO, L_T, L_SPAN, L_Y, L_Y, L_Y, L_ZERO, L_ZERO, L_ZERO, L_ZERO},
    [CALREC_TM_LORENTZ] = {L_ZERO, L_ZERO, L_ZERO, L_Y, L_Y, L_WIDTH, L_T, L_ZERO, L_ZERO, L_ZERO},
    [CALREC_TM_PWL] = {L_KNOTS, L_T, L_SPAN},
    [CALREC_TM_LORENTZ_CUBIC] = {L_ZERO, L_T, L_SPAN, L_Y, L_Y, L_WIDTH, L_T, L_Y, L_Y, L_Y},
};

static bool in_class(int32_t v, unsigned c)
{
    return v >= lim[c][0] && v <= lim[c][1];
}

/* m: the model's 20 words (kind, n, t_ref, t_span, p[16]); yc: the class of its y format. */
static bool tmodel_ok(const int32_t *m, unsigned yc)
{
    const int32_t kind = m[0];
    unsigned k;

    if (kind < 0 || kind >= CALREC_TM_KIND_COUNT) {
        return false;
    }
    for (k = 1; k < TM_WORDS; k++) {
        unsigned c = (k <= TM_CLASSED) ? tm_class[kind][k - 1u] : L_ZERO;
        if (kind == CALREC_TM_PWL && k >= 4u) {
            /* n (word 1) already passed [2, CALREC_TM_PARAMS]. */
            c = (k - 4u < (unsigned)m[1]) ? L_Y : L_ZERO;
        }
        if (!in_class(m[k], c == L_Y ? yc : c)) {
            return false;
        }
    }
    /* The last PWL knot at or below 200 degC. No overflow in int32: with the limits just
     * checked, (n - 1) * t_span <= 15 * 200 degC = 196608000 and t_ref <= 200 degC = 13107200
     * in Q16.16, sum < 2^31 (and no 64-bit multiply, which Cortex-M0+ would take from libgcc). */
    return kind != CALREC_TM_PWL || m[2] + (m[1] - 1) * m[3] <= CALREC_LIM_T_MAX;
}

/* Image word w (index = byte offset / 4) as int32: from img, or when img is NULL from rec. */
static int32_t word_at(const uint8_t *img, const struct calrec *rec, unsigned w)
{
    return u32_to_i32(img != NULL ? calrec_get_le32(&img[4u * w]) : word_get(rec, w - W_BINDING));
}

/* Every coefficient word of the image img, or of rec when img is NULL, within its limits. */
static bool coeffs_ok(const uint8_t *img, const struct calrec *rec)
{
    int32_t m[TM_WORDS];
    unsigned i, k;

    for (i = 0; i < SCALARS_LOW + SCALARS_HIGH; i++) {
        unsigned w = (i < SCALARS_LOW) ? W_ACC_OFFSET + i : W_GYRO_OFFSET - SCALARS_LOW + i;
        if (!in_class(word_at(img, rec, w), scalar_class[i])) {
            return false;
        }
    }
    for (i = 0; i < TM_COUNT; i++) {
        for (k = 0; k < TM_WORDS; k++) {
            m[k] = word_at(img, rec, W_ACC_TBIAS + TM_WORDS * i + k);
        }
        if (!tmodel_ok(m, i < CALREC_AXES ? L_TBIAS : L_TSCALE)) {
            return false;
        }
    }
    return true;
}

int calrec_check(const struct calrec *rec)
{
    int err;

    if (rec == NULL) {
        return INC_ERR_NULL;
    }
    err = calrec_check_binding(&rec->binding);
    if (err) {
        return err;
    }
    return coeffs_ok(NULL, rec) ? INC_OK : INC_ERR_RANGE;
}

/* ---- Encoder ------------------------------------------------------------------------------- */

int calrec_encode(const struct calrec *rec, uint32_t seq, uint8_t *img, size_t cap)
{
    unsigned i;
    int err;

    if (rec == NULL || img == NULL) {
        return INC_ERR_NULL;
    }
    err = calrec_check(rec);
    if (err) {
        return err;
    }
    if (cap < CALREC_IMAGE_SIZE) {
        return INC_ERR_NO_SPACE;
    }
    calrec_put_le32(&img[CALREC_OFF_MAGIC], CALREC_MAGIC);
    calrec_put_le32(&img[CALREC_OFF_VERSION], CALREC_VERSION);
    calrec_put_le32(&img[CALREC_OFF_LENGTH], CALREC_IMAGE_SIZE);
    calrec_put_le32(&img[CALREC_OFF_SEQ], seq);
    /* Binding and coefficients, word by word in declaration (= image) order; int32 -> uint32
     * is defined (modulo 2^32). */
    for (i = 0; i < REC_WORDS; i++) {
        calrec_put_le32(&img[CALREC_OFF_BINDING + 4u * i], word_get(rec, i));
    }
    calrec_put_le32(&img[CALREC_OFF_CRC], crc32_update(0, img, CALREC_OFF_CRC));
    return INC_OK;
}

/* ---- Checker and decoder ------------------------------------------------------------------- */

int calrec_check_image(const uint8_t *img, size_t len, const struct calrec_binding *expect)
{
    unsigned i;
    int err;

    if (img == NULL || expect == NULL) {
        return INC_ERR_NULL;
    }
    err = calrec_check_binding(expect);
    if (err) {
        return err;
    }
    if (len < CALREC_HEADER_SIZE) {
        return INC_ERR_INVAL;
    }
    if (calrec_get_le32(&img[CALREC_OFF_MAGIC]) != CALREC_MAGIC) {
        return INC_ERR_CRC;
    }
    if (calrec_get_le32(&img[CALREC_OFF_VERSION]) != CALREC_VERSION ||
        calrec_get_le32(&img[CALREC_OFF_LENGTH]) != CALREC_IMAGE_SIZE) {
        return INC_ERR_VERSION;
    }
    if (len < CALREC_IMAGE_SIZE) {
        return INC_ERR_INVAL;
    }
    if (crc32_update(0, img, CALREC_OFF_CRC) != calrec_get_le32(&img[CALREC_OFF_CRC])) {
        return INC_ERR_CRC;
    }
    for (i = 0; i < BINDING_WORDS; i++) {
        if (calrec_get_le32(&img[CALREC_OFF_BINDING + 4u * i]) != word_get(expect, i)) {
            return INC_ERR_MISMATCH;
        }
    }
    return coeffs_ok(img, NULL) ? INC_OK : INC_ERR_RANGE;
}

int calrec_image_binding(const uint8_t *img, size_t len, struct calrec_binding *out)
{
    unsigned i;
    if (img == NULL || out == NULL) {
        return INC_ERR_NULL;
    }
    if (len < CALREC_OFF_BINDING + 4u * BINDING_WORDS) {
        return INC_ERR_INVAL;
    }
    for (i = 0; i < BINDING_WORDS; i++) {
        word_set(out, i, calrec_get_le32(&img[CALREC_OFF_BINDING + 4u * i]));
    }
    return INC_OK;
}

int calrec_decode(const uint8_t *img, size_t len, const struct calrec_binding *expect,
                  struct calrec *out, uint32_t *seq)
{
    unsigned i;
    int err;

    if (seq != NULL) {
        *seq = 0;
    }
    if (out == NULL) {
        return INC_ERR_NULL;
    }
    /* Start from the safe default so that no early return can leave stale or partial data. */
    calrec_set_default(out);
    err = calrec_check_image(img, len, expect);
    if (err) {
        return err;
    }
    for (i = 0; i < REC_WORDS; i++) {
        word_set(out, i, calrec_get_le32(&img[CALREC_OFF_BINDING + 4u * i]));
    }
    out->valid = true;
    if (seq != NULL) {
        *seq = calrec_get_le32(&img[CALREC_OFF_SEQ]);
    }
    return INC_OK;
}
