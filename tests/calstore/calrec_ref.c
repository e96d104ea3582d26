/*
 * calrec_ref.c - frozen copy of the field-by-field calrec.c that preceded the table-driven
 * codec, with every public function renamed ref_calrec_*. test_calrec_ref.c runs it side by side
 * with the firmware codec as an oracle: same return code, same image bytes, same decoded record
 * for every mutated record and image. Do not "fix" or restructure this file: its value is that
 * it is the old, independently written implementation.
 */
#include "calrec_ref.h"

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

uint32_t ref_calrec_get_le32(const uint8_t *p)
{
    return (uint32_t)p[0] | ((uint32_t)p[1] << 8) | ((uint32_t)p[2] << 16) | ((uint32_t)p[3] << 24);
}

void ref_calrec_put_le32(uint8_t *p, uint32_t v)
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

static void tmodel_default(struct calrec_tmodel *m)
{
    unsigned k;
    m->kind = CALREC_TM_NONE;
    m->n = 0;
    m->t_ref = 0;
    m->t_span = 0;
    for (k = 0; k < CALREC_TM_PARAMS; k++) {
        m->p[k] = 0;
    }
}

void ref_calrec_set_default(struct calrec *rec)
{
    unsigned a, k;

    if (rec == NULL) {
        return;
    }
    rec->binding.family = 0;
    rec->binding.product = 0;
    rec->binding.revision = 0;
    rec->binding.serial = 0;
    rec->binding.lot_id1 = 0;
    rec->binding.lot_id2 = 0;
    for (a = 0; a < CALREC_AXES; a++) {
        rec->acc_offset[a] = 0;
        rec->acc_gain[a] = CALREC_Q30_ONE;
        for (k = 0; k < CALREC_AXES; k++) {
            rec->acc_misalign[a][k] = (a == k) ? CALREC_Q30_ONE : 0;
        }
        for (k = 0; k < CALREC_NONLIN_TERMS; k++) {
            rec->acc_nonlin[a][k] = 0;
        }
        tmodel_default(&rec->acc_tbias[a]);
        tmodel_default(&rec->acc_tscale[a]);
        rec->gyro_offset[a] = 0;
        rec->gyro_scale[a] = CALREC_Q30_ONE;
    }
    rec->valid = false;
}

int ref_calrec_check_binding(const struct calrec_binding *b)
{
    if (b == NULL) {
        return INC_ERR_NULL;
    }
    if (b->product == 0u || b->product > 0xFFFFu || b->revision > 0xFFu || b->serial > 0xFFFFu ||
        b->lot_id1 > 0xFFFFu || b->lot_id2 > 0xFFFFu) {
        return INC_ERR_INVAL;
    }
    switch (b->family) {
    case CALREC_FAMILY_SCA3000:
        /* No serial or lot registers on the SCA3000 (docs/sensor-facts.md §1.3). */
        if (b->serial != 0u || b->lot_id1 != 0u || b->lot_id2 != 0u) {
            return INC_ERR_INVAL;
        }
        return INC_OK;
    case CALREC_FAMILY_ADIS1625X:
    case CALREC_FAMILY_ADIS163XX:
        /* REVID is an SCA3000 register; the ADIS parts identify by PROD_ID (docs/sensor-facts.md §3.5). */
        if (b->revision != 0u) {
            return INC_ERR_INVAL;
        }
        return INC_OK;
    case CALREC_FAMILY_GENERIC: return INC_OK; /* the common ranges above only */
    default: return INC_ERR_INVAL;
    }
}

bool ref_calrec_binding_equal(const struct calrec_binding *a, const struct calrec_binding *b)
{
    if (a == NULL || b == NULL) {
        return false;
    }
    return a->family == b->family && a->product == b->product && a->revision == b->revision &&
           a->serial == b->serial && a->lot_id1 == b->lot_id1 && a->lot_id2 == b->lot_id2;
}

static bool in_range(int32_t v, int32_t lo, int32_t hi)
{
    return v >= lo && v <= hi;
}

static bool all_in_range(const int32_t *v, unsigned n, int32_t lo, int32_t hi)
{
    unsigned i;
    for (i = 0; i < n; i++) {
        if (!in_range(v[i], lo, hi)) {
            return false;
        }
    }
    return true;
}

/* Words p[from..CALREC_TM_PARAMS) must be 0. */
static bool tail_zero(const struct calrec_tmodel *m, unsigned from)
{
    return all_in_range(&m->p[from], CALREC_TM_PARAMS - from, 0, 0);
}

/* ylim: the limit of the y format of this model (bias or scale-factor deviation). */
static bool tmodel_ok(const struct calrec_tmodel *m, int32_t ylim)
{
    int32_t last;

    switch (m->kind) {
    case CALREC_TM_NONE: return m->n == 0 && m->t_ref == 0 && m->t_span == 0 && tail_zero(m, 0);
    case CALREC_TM_LINEAR:
    case CALREC_TM_PARABOLA: {
        unsigned np = (m->kind == CALREC_TM_LINEAR) ? 2u : 3u;
        return m->n == 0 && in_range(m->t_ref, CALREC_LIM_T_MIN, CALREC_LIM_T_MAX) &&
               in_range(m->t_span, CALREC_LIM_SPAN_MIN, CALREC_LIM_SPAN_MAX) &&
               all_in_range(m->p, np, -ylim, ylim) && tail_zero(m, np);
    }
    case CALREC_TM_LORENTZ:
        return m->n == 0 && m->t_ref == 0 && m->t_span == 0 && all_in_range(m->p, 2, -ylim, ylim) &&
               in_range(m->p[2], CALREC_LIM_SPAN_MIN, CALREC_LIM_WIDTH_MAX) &&
               in_range(m->p[3], CALREC_LIM_T_MIN, CALREC_LIM_T_MAX) && tail_zero(m, 4);
    case CALREC_TM_LORENTZ_CUBIC:
        return m->n == 0 && in_range(m->t_ref, CALREC_LIM_T_MIN, CALREC_LIM_T_MAX) &&
               in_range(m->t_span, CALREC_LIM_SPAN_MIN, CALREC_LIM_SPAN_MAX) &&
               all_in_range(m->p, 2, -ylim, ylim) &&
               in_range(m->p[2], CALREC_LIM_SPAN_MIN, CALREC_LIM_WIDTH_MAX) &&
               in_range(m->p[3], CALREC_LIM_T_MIN, CALREC_LIM_T_MAX) &&
               all_in_range(&m->p[4], 3, -ylim, ylim) && tail_zero(m, 7);
    case CALREC_TM_PWL:
        if (!in_range(m->n, 2, CALREC_TM_PARAMS) ||
            !in_range(m->t_ref, CALREC_LIM_T_MIN, CALREC_LIM_T_MAX) ||
            !in_range(m->t_span, CALREC_LIM_SPAN_MIN, CALREC_LIM_SPAN_MAX)) {
            return false;
        }
        /* No overflow in int32: with the limits just checked, (n - 1) * t_span <= 15 * 200 degC
         * = 196608000 and t_ref <= 200 degC = 13107200 in Q16.16, sum < 2^31 (and no 64-bit
         * multiply, which Cortex-M0+ would take from libgcc). */
        last = m->t_ref + (m->n - 1) * m->t_span;
        return last <= CALREC_LIM_T_MAX && all_in_range(m->p, (unsigned)m->n, -ylim, ylim) &&
               tail_zero(m, (unsigned)m->n);
    default: return false;
    }
}

/* The per-axis scalar terms of axis a (everything but the temperature models). */
struct axis_terms {
    int32_t acc_offset;
    int32_t acc_gain;
    int32_t misalign_row[CALREC_AXES];
    int32_t nonlin[CALREC_NONLIN_TERMS];
    int32_t gyro_offset;
    int32_t gyro_scale;
};

static bool axis_ok(const struct axis_terms *t, unsigned a)
{
    unsigned k;

    if (!in_range(t->acc_offset, -CALREC_LIM_ACC_OFFSET, CALREC_LIM_ACC_OFFSET) ||
        !in_range(t->acc_gain, CALREC_LIM_GAIN_MIN, CALREC_LIM_GAIN_MAX) ||
        !in_range(t->gyro_offset, -CALREC_LIM_GYRO_OFFSET, CALREC_LIM_GYRO_OFFSET) ||
        !in_range(t->gyro_scale, CALREC_LIM_GAIN_MIN, CALREC_LIM_GAIN_MAX)) {
        return false;
    }
    for (k = 0; k < CALREC_AXES; k++) {
        int32_t v = t->misalign_row[k];
        bool ok = (a == k) ? in_range(v, CALREC_LIM_GAIN_MIN, CALREC_LIM_GAIN_MAX)
                           : in_range(v, -CALREC_LIM_MISALIGN_OFFDIAG, CALREC_LIM_MISALIGN_OFFDIAG);
        if (!ok) {
            return false;
        }
    }
    return all_in_range(&t->nonlin[0], 2, -CALREC_LIM_NONLIN_C01, CALREC_LIM_NONLIN_C01) &&
           all_in_range(&t->nonlin[2], 2, -CALREC_LIM_NONLIN_C23, CALREC_LIM_NONLIN_C23);
}

static void axis_from_rec(const struct calrec *rec, unsigned a, struct axis_terms *t)
{
    unsigned k;
    t->acc_offset = rec->acc_offset[a];
    t->acc_gain = rec->acc_gain[a];
    for (k = 0; k < CALREC_AXES; k++) {
        t->misalign_row[k] = rec->acc_misalign[a][k];
    }
    for (k = 0; k < CALREC_NONLIN_TERMS; k++) {
        t->nonlin[k] = rec->acc_nonlin[a][k];
    }
    t->gyro_offset = rec->gyro_offset[a];
    t->gyro_scale = rec->gyro_scale[a];
}

int ref_calrec_check(const struct calrec *rec)
{
    struct axis_terms t;
    unsigned a;
    int err;

    if (rec == NULL) {
        return INC_ERR_NULL;
    }
    err = ref_calrec_check_binding(&rec->binding);
    if (err) {
        return err;
    }
    for (a = 0; a < CALREC_AXES; a++) {
        axis_from_rec(rec, a, &t);
        if (!axis_ok(&t, a) || !tmodel_ok(&rec->acc_tbias[a], CALREC_LIM_TBIAS) ||
            !tmodel_ok(&rec->acc_tscale[a], CALREC_LIM_TSCALE)) {
            return INC_ERR_RANGE;
        }
    }
    return INC_OK;
}

/* ---- Word access at image offsets ---------------------------------------------------------- */

static void put_i32(uint8_t *img, uint32_t off, int32_t v)
{
    ref_calrec_put_le32(&img[off], (uint32_t)v); /* int32 -> uint32 is defined (modulo 2^32) */
}

static int32_t get_i32(const uint8_t *img, uint32_t off)
{
    return u32_to_i32(ref_calrec_get_le32(&img[off]));
}

static void put_tmodel(uint8_t *img, uint32_t off, const struct calrec_tmodel *m)
{
    unsigned k;
    put_i32(img, off + 0u, m->kind);
    put_i32(img, off + 4u, m->n);
    put_i32(img, off + 8u, m->t_ref);
    put_i32(img, off + 12u, m->t_span);
    for (k = 0; k < CALREC_TM_PARAMS; k++) {
        put_i32(img, off + 16u + 4u * k, m->p[k]);
    }
}

static void get_tmodel(const uint8_t *img, uint32_t off, struct calrec_tmodel *m)
{
    unsigned k;
    m->kind = get_i32(img, off + 0u);
    m->n = get_i32(img, off + 4u);
    m->t_ref = get_i32(img, off + 8u);
    m->t_span = get_i32(img, off + 12u);
    for (k = 0; k < CALREC_TM_PARAMS; k++) {
        m->p[k] = get_i32(img, off + 16u + 4u * k);
    }
}

static void get_binding(const uint8_t *img, struct calrec_binding *b)
{
    b->family = ref_calrec_get_le32(&img[CALREC_OFF_BINDING + 0u]);
    b->product = ref_calrec_get_le32(&img[CALREC_OFF_BINDING + 4u]);
    b->revision = ref_calrec_get_le32(&img[CALREC_OFF_BINDING + 8u]);
    b->serial = ref_calrec_get_le32(&img[CALREC_OFF_BINDING + 12u]);
    b->lot_id1 = ref_calrec_get_le32(&img[CALREC_OFF_BINDING + 16u]);
    b->lot_id2 = ref_calrec_get_le32(&img[CALREC_OFF_BINDING + 20u]);
}

static void axis_from_image(const uint8_t *img, unsigned a, struct axis_terms *t)
{
    unsigned k;
    t->acc_offset = get_i32(img, CALREC_OFF_ACC_OFFSET + 4u * a);
    t->acc_gain = get_i32(img, CALREC_OFF_ACC_GAIN + 4u * a);
    for (k = 0; k < CALREC_AXES; k++) {
        t->misalign_row[k] = get_i32(img, CALREC_OFF_ACC_MISALIGN + 4u * (CALREC_AXES * a + k));
    }
    for (k = 0; k < CALREC_NONLIN_TERMS; k++) {
        t->nonlin[k] = get_i32(img, CALREC_OFF_ACC_NONLIN + 4u * (CALREC_NONLIN_TERMS * a + k));
    }
    t->gyro_offset = get_i32(img, CALREC_OFF_GYRO_OFFSET + 4u * a);
    t->gyro_scale = get_i32(img, CALREC_OFF_GYRO_SCALE + 4u * a);
}

/* ---- Encoder ------------------------------------------------------------------------------- */

int ref_calrec_encode(const struct calrec *rec, uint32_t seq, uint8_t *img, size_t cap)
{
    unsigned a, k;
    int err;

    if (rec == NULL || img == NULL) {
        return INC_ERR_NULL;
    }
    err = ref_calrec_check(rec);
    if (err) {
        return err;
    }
    if (cap < CALREC_IMAGE_SIZE) {
        return INC_ERR_NO_SPACE;
    }
    ref_calrec_put_le32(&img[CALREC_OFF_MAGIC], CALREC_MAGIC);
    ref_calrec_put_le32(&img[CALREC_OFF_VERSION], CALREC_VERSION);
    ref_calrec_put_le32(&img[CALREC_OFF_LENGTH], CALREC_IMAGE_SIZE);
    ref_calrec_put_le32(&img[CALREC_OFF_SEQ], seq);
    ref_calrec_put_le32(&img[CALREC_OFF_BINDING + 0u], rec->binding.family);
    ref_calrec_put_le32(&img[CALREC_OFF_BINDING + 4u], rec->binding.product);
    ref_calrec_put_le32(&img[CALREC_OFF_BINDING + 8u], rec->binding.revision);
    ref_calrec_put_le32(&img[CALREC_OFF_BINDING + 12u], rec->binding.serial);
    ref_calrec_put_le32(&img[CALREC_OFF_BINDING + 16u], rec->binding.lot_id1);
    ref_calrec_put_le32(&img[CALREC_OFF_BINDING + 20u], rec->binding.lot_id2);
    for (a = 0; a < CALREC_AXES; a++) {
        put_i32(img, CALREC_OFF_ACC_OFFSET + 4u * a, rec->acc_offset[a]);
        put_i32(img, CALREC_OFF_ACC_GAIN + 4u * a, rec->acc_gain[a]);
        for (k = 0; k < CALREC_AXES; k++) {
            put_i32(img, CALREC_OFF_ACC_MISALIGN + 4u * (CALREC_AXES * a + k),
                    rec->acc_misalign[a][k]);
        }
        for (k = 0; k < CALREC_NONLIN_TERMS; k++) {
            put_i32(img, CALREC_OFF_ACC_NONLIN + 4u * (CALREC_NONLIN_TERMS * a + k),
                    rec->acc_nonlin[a][k]);
        }
        put_tmodel(img, CALREC_OFF_ACC_TBIAS + CALREC_TMODEL_SIZE * a, &rec->acc_tbias[a]);
        put_tmodel(img, CALREC_OFF_ACC_TSCALE + CALREC_TMODEL_SIZE * a, &rec->acc_tscale[a]);
        put_i32(img, CALREC_OFF_GYRO_OFFSET + 4u * a, rec->gyro_offset[a]);
        put_i32(img, CALREC_OFF_GYRO_SCALE + 4u * a, rec->gyro_scale[a]);
    }
    ref_calrec_put_le32(&img[CALREC_OFF_CRC], crc32_update(0, img, CALREC_OFF_CRC));
    return INC_OK;
}

/* ---- Checker and decoder ------------------------------------------------------------------- */

int ref_calrec_check_image(const uint8_t *img, size_t len, const struct calrec_binding *expect)
{
    struct calrec_binding b;
    struct calrec_tmodel m;
    struct axis_terms t;
    unsigned a;
    int err;

    if (img == NULL || expect == NULL) {
        return INC_ERR_NULL;
    }
    err = ref_calrec_check_binding(expect);
    if (err) {
        return err;
    }
    if (len < CALREC_HEADER_SIZE) {
        return INC_ERR_INVAL;
    }
    if (ref_calrec_get_le32(&img[CALREC_OFF_MAGIC]) != CALREC_MAGIC) {
        return INC_ERR_CRC;
    }
    if (ref_calrec_get_le32(&img[CALREC_OFF_VERSION]) != CALREC_VERSION ||
        ref_calrec_get_le32(&img[CALREC_OFF_LENGTH]) != CALREC_IMAGE_SIZE) {
        return INC_ERR_VERSION;
    }
    if (len < CALREC_IMAGE_SIZE) {
        return INC_ERR_INVAL;
    }
    if (crc32_update(0, img, CALREC_OFF_CRC) != ref_calrec_get_le32(&img[CALREC_OFF_CRC])) {
        return INC_ERR_CRC;
    }
    get_binding(img, &b);
    if (!ref_calrec_binding_equal(&b, expect)) {
        return INC_ERR_MISMATCH;
    }
    for (a = 0; a < CALREC_AXES; a++) {
        axis_from_image(img, a, &t);
        if (!axis_ok(&t, a)) {
            return INC_ERR_RANGE;
        }
        get_tmodel(img, CALREC_OFF_ACC_TBIAS + CALREC_TMODEL_SIZE * a, &m);
        if (!tmodel_ok(&m, CALREC_LIM_TBIAS)) {
            return INC_ERR_RANGE;
        }
        get_tmodel(img, CALREC_OFF_ACC_TSCALE + CALREC_TMODEL_SIZE * a, &m);
        if (!tmodel_ok(&m, CALREC_LIM_TSCALE)) {
            return INC_ERR_RANGE;
        }
    }
    return INC_OK;
}

int ref_calrec_decode(const uint8_t *img, size_t len, const struct calrec_binding *expect,
                      struct calrec *out, uint32_t *seq)
{
    unsigned a, k;
    int err;

    if (seq != NULL) {
        *seq = 0;
    }
    if (out == NULL) {
        return INC_ERR_NULL;
    }
    /* Start from the safe default so that no early return can leave stale or partial data. */
    ref_calrec_set_default(out);
    err = ref_calrec_check_image(img, len, expect);
    if (err) {
        return err;
    }
    get_binding(img, &out->binding);
    for (a = 0; a < CALREC_AXES; a++) {
        out->acc_offset[a] = get_i32(img, CALREC_OFF_ACC_OFFSET + 4u * a);
        out->acc_gain[a] = get_i32(img, CALREC_OFF_ACC_GAIN + 4u * a);
        for (k = 0; k < CALREC_AXES; k++) {
            out->acc_misalign[a][k] = get_i32(img,
                                              CALREC_OFF_ACC_MISALIGN + 4u * (CALREC_AXES * a + k));
        }
        for (k = 0; k < CALREC_NONLIN_TERMS; k++) {
            out->acc_nonlin[a][k] = get_i32(img, CALREC_OFF_ACC_NONLIN +
                                                     4u * (CALREC_NONLIN_TERMS * a + k));
        }
        get_tmodel(img, CALREC_OFF_ACC_TBIAS + CALREC_TMODEL_SIZE * a, &out->acc_tbias[a]);
        get_tmodel(img, CALREC_OFF_ACC_TSCALE + CALREC_TMODEL_SIZE * a, &out->acc_tscale[a]);
        out->gyro_offset[a] = get_i32(img, CALREC_OFF_GYRO_OFFSET + 4u * a);
        out->gyro_scale[a] = get_i32(img, CALREC_OFF_GYRO_SCALE + 4u * a);
    }
    out->valid = true;
    if (seq != NULL) {
        *seq = ref_calrec_get_le32(&img[CALREC_OFF_SEQ]);
    }
    return INC_OK;
}
