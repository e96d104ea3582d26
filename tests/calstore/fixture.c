/* fixture.c - see fixture.h. */
#include "fixture.h"

#include <string.h>

#include "inclino/crc32.h"

void fix_binding(struct calrec_binding *b)
{
    b->family = CALREC_FAMILY_ADIS163XX;
    b->product = 16364u; /* PROD_ID 0x3FEC, docs/sensor-facts.md §3.5 */
    b->revision = 0u;
    b->serial = 0x1234u;
    b->lot_id1 = 0xA5A5u;
    b->lot_id2 = 0x0042u;
}

void fix_record(struct calrec *r)
{
    unsigned a, k;
    static const int32_t tscale_pwl[9] = {-1300000, -975000, -650000, -325000, 0,
                                          162779,   325558,  488337,  651116};

    calrec_set_default(r);
    fix_binding(&r->binding);
    r->acc_offset[0] = -1311;    /* -20 mg */
    r->acc_offset[1] = 655;      /* +10 mg */
    r->acc_offset[2] = 3277;     /* +50 mg */
    r->acc_gain[0] = 1084479242; /* 1.01 */
    r->acc_gain[1] = 1063004406; /* 0.99 */
    r->acc_gain[2] = 1076426179; /* 1.0025 */
    for (a = 0; a < CALREC_AXES; a++) {
        for (k = 0; k < CALREC_AXES; k++) {
            r->acc_misalign[a][k] = (a == k) ? CALREC_Q30_ONE
                                             : (int32_t)(2147484 * (int32_t)(a + 1) -
                                                         1073742 * (int32_t)k);
        }
        r->acc_nonlin[a][0] = -(int32_t)a * 1000;
        r->acc_nonlin[a][1] = (int32_t)a * 2000;
        r->acc_nonlin[a][2] = 10737418;  /* 0.01 /g */
        r->acc_nonlin[a][3] = -85899346; /* -0.08 /g^2 */
    }
    /* x: [ADI-EPB] three-point parabola, centred at 25 degC, span 40 degC. */
    r->acc_tbias[0].kind = CALREC_TM_PARABOLA;
    r->acc_tbias[0].t_ref = 25 * CALREC_Q16_ONE;
    r->acc_tbias[0].t_span = 40 * CALREC_Q16_ONE;
    r->acc_tbias[0].p[0] = -655;
    r->acc_tbias[0].p[1] = 1310;
    r->acc_tbias[0].p[2] = -328;
    /* y: linear. */
    r->acc_tbias[1].kind = CALREC_TM_LINEAR;
    r->acc_tbias[1].t_ref = 25 * CALREC_Q16_ONE;
    r->acc_tbias[1].t_span = 40 * CALREC_Q16_ONE;
    r->acc_tbias[1].p[0] = 100;
    r->acc_tbias[1].p[1] = -2000;
    /* z: Lorentz, y0 = -500 LSB, height 900 LSB, w = 30 degC, Tc = 20 degC. */
    r->acc_tbias[2].kind = CALREC_TM_LORENTZ;
    r->acc_tbias[2].p[0] = -500;
    r->acc_tbias[2].p[1] = 900;
    r->acc_tbias[2].p[2] = 30 * CALREC_Q16_ONE;
    r->acc_tbias[2].p[3] = 20 * CALREC_Q16_ONE;
    /* x scale: 9-knot table, -20..60 degC every 10 degC ([TEMP-LORENTZ]'s sweep). */
    r->acc_tscale[0].kind = CALREC_TM_PWL;
    r->acc_tscale[0].n = 9;
    r->acc_tscale[0].t_ref = -20 * CALREC_Q16_ONE;
    r->acc_tscale[0].t_span = 10 * CALREC_Q16_ONE;
    for (k = 0; k < 9u; k++) {
        r->acc_tscale[0].p[k] = tscale_pwl[k];
    }
    /* y scale: none; z scale: linear 151.6 ppm/degC over a 1 degC span. */
    r->acc_tscale[2].kind = CALREC_TM_LINEAR;
    r->acc_tscale[2].t_ref = 25 * CALREC_Q16_ONE;
    r->acc_tscale[2].t_span = CALREC_Q16_ONE;
    r->acc_tscale[2].p[0] = 0;
    r->acc_tscale[2].p[1] = 162779;
    r->gyro_offset[0] = 32768;  /* 0.5 deg/s */
    r->gyro_offset[1] = -16384; /* -0.25 deg/s */
    r->gyro_offset[2] = 196608; /* 3 deg/s */
    r->gyro_scale[0] = CALREC_Q30_ONE;
    r->gyro_scale[1] = 1074815566; /* 1.001 */
    r->gyro_scale[2] = 1072668082; /* 0.999 */
}

void fix_record_variant(struct calrec *r, int variant)
{
    fix_record(r);
    r->acc_offset[0] = -1311 + 17 * variant;
    r->gyro_offset[2] = 196608 - 1000 * variant;
    r->acc_tbias[1].p[1] = -2000 + variant;
}

static bool tm_equal(const struct calrec_tmodel *a, const struct calrec_tmodel *b)
{
    unsigned k;
    if (a->kind != b->kind || a->n != b->n || a->t_ref != b->t_ref || a->t_span != b->t_span) {
        return false;
    }
    for (k = 0; k < CALREC_TM_PARAMS; k++) {
        if (a->p[k] != b->p[k]) {
            return false;
        }
    }
    return true;
}

bool fix_record_equal(const struct calrec *x, const struct calrec *y)
{
    unsigned a, k;
    /* valid compared as a byte: a record left untouched by a failing call may hold a fill
     * pattern there, which is no valid bool to load */
    if (!calrec_binding_equal(&x->binding, &y->binding) ||
        memcmp(&x->valid, &y->valid, sizeof(bool)) != 0) {
        return false;
    }
    for (a = 0; a < CALREC_AXES; a++) {
        if (x->acc_offset[a] != y->acc_offset[a] || x->acc_gain[a] != y->acc_gain[a] ||
            x->gyro_offset[a] != y->gyro_offset[a] || x->gyro_scale[a] != y->gyro_scale[a] ||
            !tm_equal(&x->acc_tbias[a], &y->acc_tbias[a]) ||
            !tm_equal(&x->acc_tscale[a], &y->acc_tscale[a])) {
            return false;
        }
        for (k = 0; k < CALREC_AXES; k++) {
            if (x->acc_misalign[a][k] != y->acc_misalign[a][k]) {
                return false;
            }
        }
        for (k = 0; k < CALREC_NONLIN_TERMS; k++) {
            if (x->acc_nonlin[a][k] != y->acc_nonlin[a][k]) {
                return false;
            }
        }
    }
    return true;
}

bool fix_record_is_default(const struct calrec *r)
{
    /* Spelled out independently of calrec_set_default, so a wrong default is caught. */
    unsigned a, k;
    const struct calrec_binding *b = &r->binding;
    if (r->valid || b->family || b->product || b->revision || b->serial || b->lot_id1 ||
        b->lot_id2) {
        return false;
    }
    for (a = 0; a < CALREC_AXES; a++) {
        if (r->acc_offset[a] != 0 || r->acc_gain[a] != (1 << 30) || r->gyro_offset[a] != 0 ||
            r->gyro_scale[a] != (1 << 30)) {
            return false;
        }
        for (k = 0; k < CALREC_AXES; k++) {
            if (r->acc_misalign[a][k] != (a == k ? (1 << 30) : 0)) {
                return false;
            }
        }
        for (k = 0; k < CALREC_NONLIN_TERMS; k++) {
            if (r->acc_nonlin[a][k] != 0) {
                return false;
            }
        }
        for (k = 0; k < 2u; k++) {
            const struct calrec_tmodel *m = (k == 0) ? &r->acc_tbias[a] : &r->acc_tscale[a];
            unsigned p;
            if (m->kind != CALREC_TM_NONE || m->n || m->t_ref || m->t_span) {
                return false;
            }
            for (p = 0; p < CALREC_TM_PARAMS; p++) {
                if (m->p[p] != 0) {
                    return false;
                }
            }
        }
    }
    return true;
}

int fix_store_init(struct fix_store *fs, uint8_t *mem, uint32_t mem_size,
                   const struct fix_geometry *g)
{
    struct simflash_geometry geo;
    uint32_t slot = g->page_size * g->slot_pages;
    int err;

    memset(fs, 0, sizeof *fs);
    geo.page_size = g->page_size;
    geo.prog_size = g->prog_size;
    geo.page_count = 2u * g->slot_pages;
    err = simflash_init(&fs->flash, mem, mem_size, &geo);
    if (err) {
        return err;
    }
    simflash_set_reprogram(&fs->flash, g->reprogram);
    fs->size = 2u * slot;
    fs->cfg.ops = &simflash_calstore_ops;
    fs->cfg.ctx = &fs->flash;
    fs->cfg.page_size = g->page_size;
    fs->cfg.prog_size = g->prog_size;
    fs->cfg.erased_value = 0xFFu;
    fs->cfg.slot_addr[0] = 0;
    fs->cfg.slot_addr[1] = slot;
    fs->cfg.slot_size = slot;
    return calstore_init(&fs->store, &fs->cfg);
}

int fix_put_image(struct fix_store *fs, unsigned s, const uint8_t *img, uint32_t len)
{
    uint8_t commit[CALSTORE_PROG_MAX];
    uint32_t prog = fs->cfg.prog_size;
    uint32_t clen = prog > 4u ? prog : 4u;
    uint32_t coff = ((len + prog - 1u) / prog) * prog;
    uint32_t i;
    int err;

    for (i = 0; i < clen; i += 4u) {
        calrec_put_le32(&commit[i], CALSTORE_COMMIT);
    }
    err = simflash_poke(&fs->flash, fs->cfg.slot_addr[s], img, len);
    if (err) {
        return err;
    }
    return simflash_poke(&fs->flash, fs->cfg.slot_addr[s] + coff, commit, clen);
}

int fix_put_record(struct fix_store *fs, unsigned s, const struct calrec *r, uint32_t seq)
{
    uint8_t img[CALREC_IMAGE_SIZE];
    int err = calrec_encode(r, seq, img, sizeof img);
    if (err) {
        return err;
    }
    return fix_put_image(fs, s, img, sizeof img);
}

void fix_reseal(uint8_t *img)
{
    calrec_put_le32(&img[CALREC_OFF_CRC], crc32_update(0, img, CALREC_OFF_CRC));
}
