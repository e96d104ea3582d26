/* Temperature-model evaluation (cal_tmodel_eval) against a double-precision reference of the
 * record's semantics (version 2: polynomial kinds held in [t_ref - t_span, t_ref + t_span], PWL
 * held at its end knots, T clamped to [-100, 200] degC): random models within the calrec limits
 * for both y formats (bias g Q16, scale deviation Q30) including parameters at the limits, swept
 * over temperatures beyond the range; exact values where the math is exact; refusals. Host and
 * QEMU. */
#include "inclino/cal.h"
#include "cal_ref.h"

static void sweep_kind(const char *name, int32_t kind, double bound)
{
    static const int32_t ylims[2] = {CALREC_LIM_TBIAS, CALREC_LIM_TSCALE};
    const unsigned models = CALT_DENSITY(3000u, 300u), temps = CALT_DENSITY(400u, 80u);
    struct calt_err e = {0.0, 0};
    uint32_t s = 0x1234567u + (uint32_t)kind;
    unsigned f, k, j;
    for (f = 0; f < 2u; f++) {
        for (k = 0; k < models; k++) {
            struct calrec_tmodel m;
            random_model(&s, kind, ylims[f], k, &m);
            for (j = 0; j < temps; j++) {
                int32_t t, y = 0;
                /* Mostly inside the range, some beyond it, a few at the int32 ends. */
                if (j == 0)
                    t = INT32_MIN;
                else if (j == 1)
                    t = INT32_MAX;
                else if (j == 2)
                    t = m.t_ref;
                else
                    t = (int32_t)calt_range(&s, -150 * 65536, 250 * 65536);
                CHECK_OK(cal_tmodel_eval(&m, t, &y));
                calt_err_add(&e, (double)y - ref_eval(&m, t));
            }
        }
    }
    calt_report(name, &e, bound);
    CHECK(e.max <= bound);
}

static void test_linear(void)
{
    sweep_kind("tmodel linear", CALREC_TM_LINEAR, 0.57);
}
static void test_parabola(void)
{
    sweep_kind("tmodel parabola", CALREC_TM_PARABOLA, 1.25);
}
static void test_lorentz(void)
{
    sweep_kind("tmodel lorentz", CALREC_TM_LORENTZ, 0.75);
}
static void test_pwl(void)
{
    sweep_kind("tmodel pwl", CALREC_TM_PWL, 0.63);
}
static void test_lorentz_cubic(void)
{
    sweep_kind("tmodel lorentz+cubic", CALREC_TM_LORENTZ_CUBIC, 2.7);
}

static void test_exact_points(void)
{
    struct calrec_tmodel m;
    int32_t y = 7;
    unsigned i;
    memset(&m, 0, sizeof m);
    CHECK_OK(cal_tmodel_eval(&m, 25 * 65536, &y)); /* NONE */
    CHECK_EQ_INT(y, 0);
    /* LINEAR at t_ref and at (and beyond) both ends: p0, p0 +- p1 exactly. */
    m.kind = CALREC_TM_LINEAR;
    m.t_ref = 20 * 65536;
    m.t_span = 40 * 65536;
    m.p[0] = -1234;
    m.p[1] = 5000;
    CHECK_OK(cal_tmodel_eval(&m, 20 * 65536, &y));
    CHECK_EQ_INT(y, -1234);
    CHECK_OK(cal_tmodel_eval(&m, 60 * 65536, &y));
    CHECK_EQ_INT(y, 3766);
    CHECK_OK(cal_tmodel_eval(&m, 85 * 65536, &y)); /* held, not extrapolated */
    CHECK_EQ_INT(y, 3766);
    CHECK_OK(cal_tmodel_eval(&m, INT32_MIN, &y));
    CHECK_EQ_INT(y, -6234);
    CHECK_OK(cal_tmodel_eval(&m, 40 * 65536, &y)); /* u = 0.5 */
    CHECK_EQ_INT(y, -1234 + 2500);
    /* PARABOLA: [ADI-EPB]'s three points pass exactly (u = -1, 0, +1). */
    m.kind = CALREC_TM_PARABOLA;
    m.p[2] = -700;
    CHECK_OK(cal_tmodel_eval(&m, -20 * 65536, &y));
    CHECK_EQ_INT(y, -1234 - 5000 - 700);
    /* LORENTZ: peak p0 + p1 at Tc, half height at Tc +- w/2. */
    memset(&m, 0, sizeof m);
    m.kind = CALREC_TM_LORENTZ;
    m.p[0] = 100;
    m.p[1] = 1000;
    m.p[2] = 30 * 65536;
    m.p[3] = -25 * 65536;
    CHECK_OK(cal_tmodel_eval(&m, -25 * 65536, &y));
    CHECK_EQ_INT(y, 1100);
    CHECK_OK(cal_tmodel_eval(&m, -10 * 65536, &y));
    CHECK_EQ_INT(y, 600);
    CHECK_OK(cal_tmodel_eval(&m, -40 * 65536, &y));
    CHECK_EQ_INT(y, 600);
    /* PWL: the knots exactly, midpoints halfway, held at the ends. */
    memset(&m, 0, sizeof m);
    m.kind = CALREC_TM_PWL;
    m.n = 9;
    m.t_ref = -20 * 65536;
    m.t_span = 10 * 65536;
    for (i = 0; i < 9u; i++) {
        m.p[i] = (int32_t)(i * i * 100u) - 1000;
    }
    for (i = 0; i < 9u; i++) {
        CHECK_OK(cal_tmodel_eval(&m, (int32_t)(-20 + 10 * (int)i) * 65536, &y));
        CHECK_EQ_INT(y, m.p[i]);
    }
    CHECK_OK(cal_tmodel_eval(&m, -15 * 65536, &y));
    CHECK_EQ_INT(y, (m.p[0] + m.p[1]) / 2);
    CHECK_OK(cal_tmodel_eval(&m, 100 * 65536, &y));
    CHECK_EQ_INT(y, m.p[8]);
    CHECK_OK(cal_tmodel_eval(&m, -100 * 65536, &y));
    CHECK_EQ_INT(y, m.p[0]);
}

static void test_refusals(void)
{
    struct calrec_tmodel m;
    int32_t y = 5;
    memset(&m, 0, sizeof m);
    CHECK_ERR(cal_tmodel_eval(NULL, 0, &y), INC_ERR_NULL);
    CHECK_ERR(cal_tmodel_eval(&m, 0, NULL), INC_ERR_NULL);
    m.kind = 99;
    CHECK_ERR(cal_tmodel_eval(&m, 0, &y), INC_ERR_INVAL);
    CHECK_EQ_INT(y, 0);
    m.kind = CALREC_TM_LINEAR; /* t_span 0 would divide by zero */
    CHECK_ERR(cal_tmodel_eval(&m, 0, &y), INC_ERR_INVAL);
    m.kind = CALREC_TM_LORENTZ; /* w 0 */
    CHECK_ERR(cal_tmodel_eval(&m, 0, &y), INC_ERR_INVAL);
    m.p[2] = 65536;
    m.p[3] = 300 * 65536; /* Tc beyond 200 degC */
    CHECK_ERR(cal_tmodel_eval(&m, 0, &y), INC_ERR_INVAL);
    m.kind = CALREC_TM_PWL;
    m.n = 17;
    m.t_span = 65536;
    CHECK_ERR(cal_tmodel_eval(&m, 0, &y), INC_ERR_INVAL);
    m.n = 1;
    CHECK_ERR(cal_tmodel_eval(&m, 0, &y), INC_ERR_INVAL);
    m.kind = -1;
    CHECK_ERR(cal_tmodel_eval(&m, 0, &y), INC_ERR_INVAL);
}

int main(void)
{
    UNIT_RUN(test_exact_points);
    UNIT_RUN(test_refusals);
    UNIT_RUN(test_linear);
    UNIT_RUN(test_parabola);
    UNIT_RUN(test_lorentz);
    UNIT_RUN(test_pwl);
    UNIT_RUN(test_lorentz_cubic);
    return unit_report();
}
