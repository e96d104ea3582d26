/* Per-sample correction (cal_acc_*, cal_gyro_*): pass-through when uncalibrated, exact identity,
 * the error bound of cal_acc_apply against exact math on the state's coefficients, the
 * end-to-end error (set_temp + apply) against the double model of the record, the plausibility
 * refusal and its recovery, range flags; the gyro correction and its bound. Host and QEMU. */
#include "inclino/cal.h"
#include "cal_ref.h"

/* Exact chain on given off (Q16 raw), inv (Q30 raw) and the record's words; raw Q16 out. */
static void ref_apply_state(const struct calrec *r, const double off[3], const double inv[3],
                            const fx_q16_t in[3], double out[3])
{
    double n[3];
    unsigned i;
    for (i = 0; i < 3u; i++) {
        const double v = ((double)in[i] - off[i]) * inv[i] / CALT_Q30; /* Q16 raw */
        const double x = clampd(v / CALT_Q16, -1.25, 1.25);            /* g */
        const int32_t *c = r->acc_nonlin[i];
        const double d = (c[0] + x * (c[1] + x * (c[2] + x * (double)c[3]))) / CALT_Q30; /* g */
        n[i] = v + d * CALT_Q16;
    }
    for (i = 0; i < 3u; i++) {
        out[i] = (r->acc_misalign[i][0] * n[0] + r->acc_misalign[i][1] * n[1] +
                  r->acc_misalign[i][2] * n[2]) /
                 CALT_Q30;
    }
}

static void test_uncalibrated(void)
{
    struct cal_acc st;
    struct cal_gyro g;
    struct calrec r;
    const fx_q16_t in[3] = {123, -456, 65536};
    fx_q16_t out[3];
    CHECK_ERR(cal_acc_init(&st, NULL, 0), INC_ERR_NOT_CALIBRATED);
    CHECK_ERR(cal_acc_apply(&st, in, out), INC_ERR_NOT_CALIBRATED);
    CHECK(out[0] == 123 && out[1] == -456 && out[2] == 65536);
    CHECK_ERR(cal_acc_set_temp(&st, 0), INC_ERR_NOT_CALIBRATED);
    calrec_set_default(&r); /* valid = false: what calstore gives when nothing is stored */
    CHECK_ERR(cal_acc_init(&st, &r, 0), INC_ERR_NOT_CALIBRATED);
    CHECK_ERR(cal_gyro_init(&g, &r), INC_ERR_NOT_CALIBRATED);
    CHECK_ERR(cal_gyro_apply(&g, in, out), INC_ERR_NOT_CALIBRATED);
    CHECK(out[0] == 123);
    /* A record marked valid but out of range (never from calrec_decode) is refused. */
    r.valid = true;
    r.binding.family = CALREC_FAMILY_SCA3000;
    r.binding.product = CALREC_SCA3000_D01;
    r.acc_gain[1] = 0;
    CHECK_ERR(cal_acc_init(&st, &r, 0), INC_ERR_RANGE);
    CHECK_ERR(cal_acc_apply(&st, in, out), INC_ERR_NOT_CALIBRATED);
    CHECK_ERR(cal_gyro_init(&g, &r), INC_ERR_RANGE);
    CHECK_ERR(cal_acc_init(NULL, &r, 0), INC_ERR_NULL);
    CHECK_ERR(cal_acc_apply(&st, NULL, out), INC_ERR_NULL);
    CHECK_ERR(cal_gyro_apply(&g, in, NULL), INC_ERR_NULL);
}

static void test_identity_exact(void)
{
    struct cal_acc st;
    struct cal_gyro g;
    struct calrec r;
    uint32_t s = 3u;
    unsigned k;
    calrec_set_default(&r);
    r.binding.family = CALREC_FAMILY_SCA3000;
    r.binding.product = CALREC_SCA3000_D01;
    r.valid = true;
    CHECK_OK(cal_acc_init(&st, &r, FX_Q16_INT(25)));
    CHECK_OK(cal_gyro_init(&g, &r));
    for (k = 0; k < CALT_DENSITY(100000u, 2000u); k++) {
        fx_q16_t in[3], out[3], go[3];
        unsigned i;
        for (i = 0; i < 3u; i++) {
            in[i] = (fx_q16_t)calt_range(&s, -CAL_ACC_IN_MAX, CAL_ACC_IN_MAX);
        }
        CHECK_OK(cal_acc_apply(&st, in, out));
        CHECK_OK(cal_gyro_apply(&g, in, go));
        for (i = 0; i < 3u; i++) {
            CHECK_EQ_INT(out[i], in[i]);
            CHECK_EQ_INT(go[i], in[i]);
        }
    }
}

static void sweep_apply(int extreme, double bound_state, double bound_model, const char *name)
{
    const unsigned records = CALT_DENSITY(2000u, 200u), samples = CALT_DENSITY(200u, 50u);
    struct calt_err es = {0.0, 0}, em = {0.0, 0};
    uint32_t s = extreme ? 0xBEEFu : 0xCAFEu;
    unsigned k, j, refused = 0;
    char label[64];
    for (k = 0; k < records; k++) {
        struct calrec r;
        struct cal_acc st;
        fx_q16_t t;
        int err;
        random_record(&s, extreme, k, &r);
        REQUIRE(calrec_check(&r) == INC_OK);
        t = (fx_q16_t)calt_range(&s, -40 * 65536, 125 * 65536);
        err = cal_acc_init(&st, &r, t);
        if (err == INC_ERR_RANGE) {
            refused++;
            continue;
        }
        CHECK_OK(err);
        for (j = 0; j < samples; j++) {
            fx_q16_t in[3], out[3];
            double ref_s[3], ref_m[3], off[3], inv[3];
            unsigned i;
            for (i = 0; i < 3u; i++) {
                /* Mostly within +-2 g (tilt, vibration), some up to the input limit. */
                in[i] = (fx_q16_t)calt_range(&s, (j % 8u) ? -2 * 65536 : -CAL_ACC_IN_MAX,
                                             (j % 8u) ? 2 * 65536 : CAL_ACC_IN_MAX);
            }
            CHECK_OK(cal_acc_apply(&st, in, out));
            /* Against exact math on the state's own off and inv_gain. */
            for (i = 0; i < 3u; i++) {
                off[i] = st.off[i];
                inv[i] = st.inv_gain[i];
            }
            ref_apply_state(&r, off, inv, in, ref_s);
            /* Against the double-precision model of the record at t. */
            for (i = 0; i < 3u; i++) {
                const double b = r.acc_offset[i] + ref_eval(&r.acc_tbias[i], t);
                const double kk = r.acc_gain[i] / CALT_Q30 *
                                  (1.0 + ref_eval(&r.acc_tscale[i], t) / CALT_Q30);
                off[i] = b;
                inv[i] = CALT_Q30 / kk;
            }
            ref_apply_state(&r, off, inv, in, ref_m);
            for (i = 0; i < 3u; i++) {
                calt_err_add(&es, out[i] - ref_s[i]);
                calt_err_add(&em, out[i] - ref_m[i]);
            }
        }
    }
    snprintf(label, sizeof label, "cal_acc_apply %s vs state", name);
    calt_report(label, &es, bound_state);
    snprintf(label, sizeof label, "cal_acc_set_temp+apply %s vs double model", name);
    calt_report(label, &em, bound_model);
    CHECK(es.max <= bound_state);
    CHECK(em.max <= bound_model);
    CHECK(refused < records / 10u + 1u);
}

static void test_apply_typical(void)
{
    sweep_apply(0, 1.75, 5.0, "typical");
}
static void test_apply_extreme(void)
{
    sweep_apply(1, 3.5, 18.0, "at the limits");
}

static void test_plausibility_and_range(void)
{
    struct calrec r;
    struct cal_acc st;
    const fx_q16_t in[3] = {0, 0, 65536};
    fx_q16_t out[3];
    calrec_set_default(&r);
    r.binding.family = CALREC_FAMILY_SCA3000;
    r.binding.product = CALREC_SCA3000_D01;
    r.valid = true;
    /* gain 0.75 with a scale deviation falling to -0.125 at 60 degC: k = 0.656 fine, but with
     * another -0.125 from the linear term k = 0.5625 < 0.625 at the hot end. */
    r.acc_gain[2] = CALREC_LIM_GAIN_MIN;
    r.acc_tscale[2].kind = CALREC_TM_LINEAR;
    r.acc_tscale[2].t_ref = FX_Q16_INT(20);
    r.acc_tscale[2].t_span = FX_Q16_INT(40);
    r.acc_tscale[2].p[0] = -CALREC_LIM_TSCALE;
    r.acc_tscale[2].p[1] = -CALREC_LIM_TSCALE;
    REQUIRE(calrec_check(&r) == INC_OK);
    CHECK_OK(cal_acc_init(&st, &r, FX_Q16_INT(-20))); /* k = 0.75 * 1.0 */
    CHECK_OK(cal_acc_apply(&st, in, out));
    CHECK_NEAR(out[2], 65536 / 0.75, 1.0);
    CHECK_ERR(cal_acc_set_temp(&st, FX_Q16_INT(60)), INC_ERR_RANGE); /* k = 0.5625 */
    CHECK(!st.calibrated);
    CHECK_ERR(cal_acc_apply(&st, in, out), INC_ERR_NOT_CALIBRATED);
    CHECK_EQ_INT(out[2], 65536);
    CHECK_OK(cal_acc_set_temp(&st, FX_Q16_INT(20))); /* recovers: k = 0.656 */
    CHECK_OK(cal_acc_apply(&st, in, out));
    CHECK_NEAR(out[2], 65536 / (0.75 * 0.875), 1.0);
    /* Offset + tbias beyond 1 g. */
    r.acc_tscale[2].kind = CALREC_TM_NONE;
    r.acc_tscale[2].t_ref = r.acc_tscale[2].t_span = r.acc_tscale[2].p[0] = r.acc_tscale[2].p[1] =
        0;
    r.acc_offset[0] = CALREC_LIM_ACC_OFFSET;
    r.acc_tbias[0].kind = CALREC_TM_LORENTZ;
    r.acc_tbias[0].p[0] = CALREC_LIM_TBIAS - 1000;
    r.acc_tbias[0].p[1] = CALREC_LIM_TBIAS;
    r.acc_tbias[0].p[2] = FX_Q16_INT(10);
    r.acc_tbias[0].p[3] = FX_Q16_INT(0);
    REQUIRE(calrec_check(&r) == INC_OK);
    CHECK_OK(cal_acc_init(&st, &r, FX_Q16_INT(100))); /* 1 g - 1000 LSB + 0.5 g / 401 */
    CHECK_EQ_INT(st.off[0], 65536 - 1000 + 82);
    CHECK_ERR(cal_acc_set_temp(&st, FX_Q16_INT(0)), INC_ERR_RANGE); /* 1.5 g */
    /* Inputs beyond +-64 g are flagged, and never wrap. */
    r.acc_offset[0] = 0;
    r.acc_tbias[0].kind = CALREC_TM_NONE;
    memset(r.acc_tbias[0].p, 0, sizeof r.acc_tbias[0].p);
    REQUIRE(calrec_check(&r) == INC_OK);
    CHECK_OK(cal_acc_init(&st, &r, 0));
    {
        const fx_q16_t big[3] = {INT32_MAX, INT32_MIN, CAL_ACC_IN_MAX + 1};
        CHECK_ERR(cal_acc_apply(&st, big, out), INC_ERR_RANGE);
        CHECK(out[0] > 0 && out[1] < 0 && out[2] > 0);
    }
}

static void test_gyro(void)
{
    const unsigned records = CALT_DENSITY(3000u, 300u), samples = CALT_DENSITY(300u, 50u);
    struct calt_err e = {0.0, 0};
    uint32_t s = 41u;
    unsigned k, j;
    for (k = 0; k < records; k++) {
        struct calrec r;
        struct cal_gyro g;
        random_record(&s, 0, k, &r);
        REQUIRE(cal_gyro_init(&g, &r) == INC_OK);
        for (j = 0; j < samples; j++) {
            fx_q16_t in[3], out[3];
            unsigned i;
            for (i = 0; i < 3u; i++) {
                in[i] = (fx_q16_t)calt_range(&s, -CAL_GYRO_IN_MAX, CAL_GYRO_IN_MAX);
            }
            CHECK_OK(cal_gyro_apply(&g, in, out));
            for (i = 0; i < 3u; i++) {
                calt_err_add(&e, out[i] - ((double)in[i] - r.gyro_offset[i]) /
                                              (r.gyro_scale[i] / CALT_Q30));
            }
        }
        {
            const fx_q16_t fast[3] = {CAL_GYRO_IN_MAX + 1, 0, 0};
            fx_q16_t out[3];
            CHECK_ERR(cal_gyro_apply(&g, fast, out), INC_ERR_RANGE);
        }
    }
    calt_report("cal_gyro_apply", &e, 0.6);
    CHECK(e.max <= 0.6);
}

int main(void)
{
    UNIT_RUN(test_uncalibrated);
    UNIT_RUN(test_identity_exact);
    UNIT_RUN(test_apply_typical);
    UNIT_RUN(test_apply_extreme);
    UNIT_RUN(test_plausibility_and_range);
    UNIT_RUN(test_gyro);
    return unit_report();
}
