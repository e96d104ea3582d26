/*
 * The EPB application's logic on scripted samples (no simulated bus): the calibration binding and
 * what every load status does, the per-estimate budget composition (calibrated or not, the
 * temperature model covering the temperature or not, the margin, the measured noise), the block
 * and stillness bookkeeping, read errors and saturation, and the end-of-line steps with exact
 * expected values. Host, QEMU (Cortex-M) and rv32imac.
 */
#include <string.h>

#include "inclino/app.h"
#include "unit.h"

/* ---- A scripted sensor ------------------------------------------------------------------------ */

struct script {
    struct sensor_sample s; /* what every read returns ... */
    int32_t wobble_x;       /* ... with x + wobble on odd reads, x - wobble on even ones */
    int32_t wobble_yz;      /* ... and y, z likewise */
    uint32_t fail_every;    /* every n-th read fails (0: never) */
    int fail_err;
    int id_err; /* identity read error */
    struct sensor_identity id;
    uint32_t reads;
};

static int script_read(void *ctx, struct sensor_sample *out)
{
    struct script *p = ctx;
    p->reads++;
    if (p->fail_every != 0u && p->reads % p->fail_every == 0u) {
        return p->fail_err;
    }
    *out = p->s;
    out->accel_g[0] += (p->reads & 1u) ? p->wobble_x : -p->wobble_x;
    out->accel_g[1] += (p->reads & 1u) ? p->wobble_yz : -p->wobble_yz;
    out->accel_g[2] += (p->reads & 1u) ? p->wobble_yz : -p->wobble_yz;
    return INC_OK;
}

static int script_wait(void *ctx, uint32_t timeout_ns)
{
    (void)ctx;
    (void)timeout_ns;
    return INC_OK;
}

static int script_identity(void *ctx, struct sensor_identity *out)
{
    const struct script *p = ctx;
    if (p->id_err != INC_OK) {
        return p->id_err;
    }
    *out = p->id;
    return INC_OK;
}

/* The record binding of an identity (the application copies it field by field). */
static struct calrec_binding bind_of(const struct sensor_identity *id)
{
    struct calrec_binding b;
    b.family = id->family;
    b.product = id->product;
    b.revision = id->revision;
    b.serial = id->serial;
    b.lot_id1 = id->lot_id1;
    b.lot_id2 = id->lot_id2;
    return b;
}

static const struct sensor_ops script_ops = {NULL, script_wait,     script_read, NULL,
                                             NULL, script_identity, NULL};

static struct script sc;
static struct sensor sensor = {&script_ops, &sc};

#define G(mg) ((fx_q16_t)(((mg)*65536 + ((mg) >= 0 ? 500 : -500)) / 1000))

static void script_reset(void)
{
    memset(&sc, 0, sizeof sc);
    sc.s.accel_g[0] = G(100);
    sc.s.accel_g[1] = 0;
    sc.s.accel_g[2] = G(995);
    sc.s.temp_c = FX_Q16_INT(25);
    sc.s.flags = SENSOR_S_HAVE_GYRO | SENSOR_S_HAVE_TEMP;
    sc.id.family = SENSOR_FAMILY_ADIS163XX;
    sc.id.product = 16405u;
}

/* ---- A RAM flash for the store ------------------------------------------------------------------ */

#define PAGE 1024u
static uint8_t flash[2u * PAGE];

static int ram_read(void *ctx, uint32_t addr, uint8_t *buf, uint32_t len)
{
    (void)ctx;
    memcpy(buf, &flash[addr], len);
    return INC_OK;
}

static int ram_program(void *ctx, uint32_t addr, const uint8_t *buf, uint32_t len)
{
    uint32_t i;
    (void)ctx;
    for (i = 0; i < len; i++) {
        flash[addr + i] &= buf[i];
    }
    return INC_OK;
}

static int ram_erase(void *ctx, uint32_t addr)
{
    (void)ctx;
    memset(&flash[addr], 0xFF, PAGE);
    return INC_OK;
}

static const struct calstore_flash_ops ram_ops = {ram_read, ram_program, ram_erase};
static struct calstore store;

static void store_reset(void)
{
    static const struct calstore_config c = {&ram_ops,        NULL,       PAGE, 8u,
                                             CALSTORE_ERASED, {0u, PAGE}, PAGE};
    memset(flash, 0xFF, sizeof flash);
    REQUIRE(calstore_init(&store, &c) == INC_OK);
}

/* A record for the scripted sensor: x offset +10 mg, x gain 1.01, parabola temperature models
 * of bias and scale centred at 25 degC over +-40 degC. */
static void make_record(struct calrec *r, bool tscale)
{
    unsigned i;
    calrec_set_default(r);
    r->binding = bind_of(&sc.id);
    r->acc_offset[0] = G(10);
    r->acc_gain[0] = 1084479242; /* 1.01 */
    for (i = 0; i < 3u; i++) {
        r->acc_tbias[i].kind = CALREC_TM_PARABOLA;
        r->acc_tbias[i].t_ref = FX_Q16_INT(25);
        r->acc_tbias[i].t_span = FX_Q16_INT(40);
        r->acc_tbias[i].p[1] = G(1);
        if (tscale) {
            r->acc_tscale[i].kind = CALREC_TM_LINEAR;
            r->acc_tscale[i].t_ref = FX_Q16_INT(25);
            r->acc_tscale[i].t_span = FX_Q16_INT(40);
            r->acc_tscale[i].p[1] = 1073742; /* 0.1 % */
        }
    }
}

static struct app app;
static struct app_cfg cfg;

/* The smallest q with q * q >= v (bisection; the test's own, independent of fx_isqrt64). */
static uint64_t ceil_sqrt(uint64_t v)
{
    uint64_t lo = 0, hi = 0xFFFFFFFFull;
    while (lo < hi) {
        const uint64_t mid = lo + (hi - lo) / 2u;
        if (mid * mid >= v) {
            hi = mid;
        } else {
            lo = mid + 1u;
        }
    }
    return lo;
}

static void cfg_small(void)
{
    REQUIRE(app_cfg_default(&cfg, 819200u) == INC_OK);
    cfg.still.window = 16u;
    cfg.avg_n = 64u;
    cfg.noise_floor_g = 0;         /* scripted samples are noiseless (test_noise_floor) */
    cfg.budget.offset_drift_g = 0; /* nor do they age (test_offset_change) */
    cfg.temp_step_max_c = 0;       /* and their temperature jumps (test_temp_plausibility) */
}

/* Run one block of scripted samples through app_step. */
static int run_block(struct app_result *r)
{
    uint32_t k;
    for (k = 0; k < 10u * cfg.avg_n; k++) {
        struct sensor_sample s;
        bool done = false;
        const int err = script_read(&sc, &s);
        const int e2 = app_step(&app, &s, err, NULL, &done, r);
        if (e2 != INC_OK) {
            return e2;
        }
        if (done) {
            return INC_OK;
        }
    }
    return INC_ERR_TIMEOUT;
}

/* ---- Tests -------------------------------------------------------------------------------------- */

static void test_cfg(void)
{
    struct app_cfg c;
    CHECK_ERR(app_cfg_default(NULL, 819200u), INC_ERR_NULL);
    CHECK_ERR(app_cfg_default(&c, 9999u), INC_ERR_INVAL);
    CHECK_ERR(app_cfg_default(&c, 10000001u), INC_ERR_INVAL);
    REQUIRE(app_cfg_default(&c, 819200u) == INC_OK);
    CHECK_EQ_INT(c.still.window, 256); /* round(819.2 * 0.3125) */
    CHECK_EQ_INT(c.avg_n, 2048);
    CHECK_EQ_INT(c.budget.nonlinearity_g, 655); /* 10 mg */
    CHECK_EQ_INT(c.budget.temp_uncomp_g, 3277); /* 50 mg */
    CHECK_OK(app_cfg_check(&c));
    REQUIRE(app_cfg_default(&c, 250000u) == INC_OK);
    CHECK_EQ_INT(c.still.window, 78);
    CHECK_EQ_INT(c.avg_n, 624);
    CHECK_ERR(app_cfg_check(NULL), INC_ERR_NULL);
    c.avg_n = 625u; /* not a multiple of the window */
    CHECK_ERR(app_cfg_check(&c), INC_ERR_INVAL);
    c.avg_n = 78u * 27532115u; /* 2^31 + 58: the exact sums would overflow */
    CHECK_ERR(app_cfg_check(&c), INC_ERR_INVAL);
    c.avg_n = 624u;
    c.temp_step_c = 0;
    CHECK_ERR(app_cfg_check(&c), INC_ERR_INVAL);
    c.temp_step_c = FX_Q16_HALF;
    c.budget.offset_g = -1;
    CHECK_ERR(app_cfg_check(&c), INC_ERR_INVAL);
    c.budget.offset_g = 0;
    c.budget.exceed_expected = FX_Q16_ONE; /* E / M = 1/10 > 2^-4: not a tail */
    c.budget.lifetime_runs = 10u;
    CHECK_ERR(app_cfg_check(&c), INC_ERR_INVAL);
    c.budget.lifetime_runs = 200000u;
    c.budget.exceed_expected = 66;
    c.slope.slope_axis = 2u; /* same as the gravity axis */
    CHECK_ERR(app_cfg_check(&c), INC_ERR_INVAL);
    c.slope.slope_axis = 0u;
    c.temp_margin_c = -1;
    CHECK_ERR(app_cfg_check(&c), INC_ERR_INVAL);
}

static void test_init_errors(void)
{
    static const struct sensor_ops no_wait = {NULL, NULL, script_read, NULL, NULL, script_identity,
                                              NULL};
    struct sensor bad = {NULL, &sc};
    struct sensor bad2 = {&no_wait, &sc};
    struct app_result r;
    bool done;
    script_reset();
    cfg_small();
    CHECK_ERR(app_init(NULL, &cfg, &sensor, NULL), INC_ERR_NULL);
    CHECK_ERR(app_init(&app, &cfg, &bad, NULL), INC_ERR_NULL);
    CHECK_ERR(app_init(&app, &cfg, &bad2, NULL), INC_ERR_NULL);
    sc.id_err = INC_ERR_BUS;
    CHECK_ERR(app_init(&app, &cfg, &sensor, NULL), INC_ERR_BUS);
    CHECK(!app.ready);
    CHECK_ERR(app_step(&app, &sc.s, 0, NULL, &done, &r), INC_ERR_STATE);
    CHECK_ERR(app_measure(&app, &r), INC_ERR_STATE);
    CHECK(!app_calibrated(&app));
    cfg.still.window = 1u;
    sc.id_err = INC_OK;
    CHECK_ERR(app_init(&app, &cfg, &sensor, NULL), INC_ERR_INVAL);
}

/* No store: uncalibrated. The budget switches to the uncalibrated terms; nothing is valid. */
static void test_uncalibrated(void)
{
    struct app_result r;
    struct slope_cfg scfg;
    struct slope_input in;
    struct slope_result expect;
    fx_q16_t k;
    script_reset();
    cfg_small();
    REQUIRE(app_init(&app, &cfg, &sensor, NULL) == INC_OK);
    CHECK_ERR(app.cal_status, INC_ERR_NOT_CALIBRATED);
    CHECK(!app_calibrated(&app));
    REQUIRE(run_block(&r) == INC_OK);
    CHECK_EQ_INT(r.n, 64);
    CHECK_EQ_INT(r.accel_g[0], G(100)); /* passed through */
    CHECK_EQ_INT(r.accel_g[2], G(995));
    CHECK_EQ_INT(r.temp_c, FX_Q16_INT(25));
    CHECK_EQ_INT(r.still_state, STILL_AT_REST);
    CHECK_EQ_INT(r.motion_windows, 0);
    /* Zero variance: sqrt((0 + 1) * 16 / 15) rounded up -> 2 LSB. */
    CHECK_EQ_INT(r.sigma_meas_g, 2);
    REQUIRE(slope_sigma_factor(200000u, 66, &k) == INC_OK);
    CHECK_EQ_INT(r.budget.k_sigma, k);
    CHECK_EQ_INT(r.budget.sensitivity, cfg.budget.sensitivity_uncal + cfg.budget.tscale_uncomp);
    CHECK_EQ_INT(r.budget.offset_g, cfg.budget.offset_uncal_g);
    CHECK_EQ_INT(r.budget.temperature_g, cfg.budget.temp_uncomp_g);
    CHECK_EQ_INT(r.budget.noise_sigma_g, cfg.budget.noise_sigma_g);
    CHECK_EQ_HEX(r.flags, APP_F_NOT_CALIBRATED | APP_F_TEMP_UNCOMP);
    CHECK(!r.valid);
    CHECK(!r.slope.valid);
    CHECK((r.slope.flags & SLOPE_F_NOT_CALIBRATED) != 0u);
    /* The estimate is slope_estimate on the same mean with the composed budget, exactly. */
    scfg = cfg.slope;
    scfg.budget = r.budget;
    memset(&in, 0, sizeof in);
    in.accel_g[0] = G(100);
    in.accel_g[2] = G(995);
    in.n_samples = 64u;
    in.still = true;
    in.calibrated = false;
    REQUIRE(slope_estimate(&scfg, &in, &expect) == INC_OK);
    CHECK_EQ_INT(r.slope.slope_deg, expect.slope_deg);
    CHECK_EQ_INT(r.slope.bound_deg, expect.bound_deg);
    CHECK_EQ_INT(r.slope.flags, expect.flags);
    CHECK_EQ_INT(r.cal_status, INC_ERR_NOT_CALIBRATED);
}

/* A record bound to the sensor: the correction is cal_acc_apply's, the budget the calibrated
 * one, compensated where the models cover the temperature (with the margin). */
static void test_calibrated(void)
{
    struct calrec rec;
    struct cal_acc ref;
    struct app_result r;
    fx_q16_t out[3];
    script_reset();
    cfg_small();
    store_reset();
    make_record(&rec, true);
    REQUIRE(calstore_save(&store, &rec, NULL) == INC_OK);
    REQUIRE(app_init(&app, &cfg, &sensor, &store) == INC_OK);
    CHECK_OK(app.cal_status);
    CHECK(app_calibrated(&app));
    REQUIRE(run_block(&r) == INC_OK);
    rec.valid = true;
    REQUIRE(cal_acc_init(&ref, &rec, FX_Q16_INT(25)) == INC_OK);
    REQUIRE(cal_acc_apply(&ref, sc.s.accel_g, out) == INC_OK);
    CHECK_EQ_INT(r.accel_g[0], out[0]);
    CHECK_EQ_INT(r.accel_g[2], out[2]);
    CHECK(out[0] != sc.s.accel_g[0]); /* the correction did something */
    CHECK_EQ_INT(r.budget.sensitivity, cfg.budget.sensitivity);
    CHECK_EQ_INT(r.budget.offset_g, cfg.budget.offset_g);
    CHECK_EQ_INT(r.budget.temperature_g, cfg.budget.temp_comp_g);
    CHECK_EQ_INT(r.flags, 0);
    CHECK(r.valid);
    CHECK(r.slope.valid);

    /* 65.5 degC: outside 25 +- 40 but within the 1 degC margin -> still compensated. */
    sc.s.temp_c = FX_Q16_INT(65) + FX_Q16_HALF;
    REQUIRE(run_block(&r) == INC_OK);
    CHECK_EQ_INT(r.budget.temperature_g, cfg.budget.temp_comp_g);
    CHECK_EQ_INT(r.flags, 0);
    REQUIRE(cal_acc_init(&ref, &rec, sc.s.temp_c) == INC_OK);
    REQUIRE(cal_acc_apply(&ref, sc.s.accel_g, out) == INC_OK);
    CHECK_EQ_INT(r.accel_g[0], out[0]); /* models re-evaluated at the new temperature */
    /* 66.5 degC: beyond the margin -> the uncompensated terms. */
    sc.s.temp_c = FX_Q16_INT(66) + FX_Q16_HALF;
    REQUIRE(run_block(&r) == INC_OK);
    CHECK_EQ_INT(r.budget.temperature_g, cfg.budget.temp_uncomp_g);
    CHECK_EQ_INT(r.budget.sensitivity, cfg.budget.sensitivity + cfg.budget.tscale_uncomp);
    CHECK_EQ_HEX(r.flags, APP_F_TEMP_UNCOMP);
    /* No temperature output: uncompensated too (and the default temperature is used). */
    sc.s.temp_c = FX_Q16_INT(25);
    sc.s.flags = SENSOR_S_HAVE_GYRO;
    REQUIRE(run_block(&r) == INC_OK);
    CHECK_EQ_HEX(r.flags, APP_F_TEMP_UNCOMP);
    CHECK_EQ_INT(r.temp_c, cfg.temp_default_c);

    /* A record with no scale model: offset compensated, scale not. */
    script_reset();
    store_reset();
    make_record(&rec, false);
    REQUIRE(calstore_save(&store, &rec, NULL) == INC_OK);
    REQUIRE(app_init(&app, &cfg, &sensor, &store) == INC_OK);
    REQUIRE(run_block(&r) == INC_OK);
    CHECK_EQ_INT(r.budget.temperature_g, cfg.budget.temp_comp_g);
    CHECK_EQ_INT(r.budget.sensitivity, cfg.budget.sensitivity + cfg.budget.tscale_uncomp);
    CHECK_EQ_HEX(r.flags, APP_F_TEMP_UNCOMP);
}

/* Every non-zero load status leaves the application uncalibrated. */
static void test_binding_and_store(void)
{
    struct calrec rec;
    struct app_result r;
    script_reset();
    cfg_small();
    store_reset();
    /* erased flash */
    REQUIRE(app_init(&app, &cfg, &sensor, &store) == INC_OK);
    CHECK_ERR(app.cal_status, INC_ERR_NOT_CALIBRATED);
    /* a record of another part (an ADIS16364 with a serial number) */
    make_record(&rec, true);
    rec.binding.product = 16364u;
    rec.binding.serial = 0x42u;
    REQUIRE(calstore_save(&store, &rec, NULL) == INC_OK);
    REQUIRE(app_init(&app, &cfg, &sensor, &store) == INC_OK);
    CHECK_ERR(app.cal_status, INC_ERR_MISMATCH);
    CHECK(!app_calibrated(&app));
    REQUIRE(run_block(&r) == INC_OK);
    CHECK(!r.valid);
    CHECK((r.flags & APP_F_NOT_CALIBRATED) != 0u);
    CHECK_EQ_INT(r.accel_g[0], G(100)); /* not corrected with a foreign record */
    /* corrupt: one bit of the stored image flipped */
    store_reset();
    make_record(&rec, true);
    REQUIRE(calstore_save(&store, &rec, NULL) == INC_OK);
    flash[100] ^= 0x10u;
    REQUIRE(app_init(&app, &cfg, &sensor, &store) == INC_OK);
    CHECK_ERR(app.cal_status, INC_ERR_CRC);
    CHECK(!app_calibrated(&app));
}

/* Motion, saturation and read errors invalidate a block; the slope is still reported. */
static void test_block_flags(void)
{
    struct app_result r;
    struct calrec rec;
    script_reset();
    cfg_small();
    store_reset();
    make_record(&rec, true);
    REQUIRE(calstore_save(&store, &rec, NULL) == INC_OK);
    REQUIRE(app_init(&app, &cfg, &sensor, &store) == INC_OK);
    /* +-100 mg on x every other sample: variance (100 mg)^2 > (30 mg)^2 */
    sc.wobble_x = G(100);
    REQUIRE(run_block(&r) == INC_OK);
    CHECK(!r.valid);
    CHECK((r.flags & APP_F_NOT_STILL) != 0u);
    CHECK((r.slope.flags & SLOPE_F_NOT_STILL) != 0u);
    CHECK_EQ_INT(r.motion_windows, 4);
    CHECK_EQ_INT(r.still_state, STILL_MOVING);
    {
        /* Two calibrated values alternate: the window variance is ((hi - lo) / 2)^2 (floor);
         * the rms is ceil(sqrt((v + 1) * 16 / 15)). */
        struct cal_acc ref;
        fx_q16_t in[3], hi[3], lo[3];
        uint64_t v, q;
        rec.valid = true;
        REQUIRE(cal_acc_init(&ref, &rec, FX_Q16_INT(25)) == INC_OK);
        memcpy(in, sc.s.accel_g, sizeof in);
        in[0] = sc.s.accel_g[0] + G(100);
        REQUIRE(cal_acc_apply(&ref, in, hi) == INC_OK);
        in[0] = sc.s.accel_g[0] - G(100);
        REQUIRE(cal_acc_apply(&ref, in, lo) == INC_OK);
        v = (uint64_t)((int64_t)(hi[0] - lo[0]) * (hi[0] - lo[0]) / 4);
        v = ((v + 1u) * 16u + 14u) / 15u;
        q = ceil_sqrt(v);
        CHECK_EQ_INT(r.sigma_meas_g, q); /* the measured noise widens the bound */
        CHECK(r.sigma_meas_g > G(98));
    }
    CHECK_EQ_INT(r.budget.noise_sigma_g, r.sigma_meas_g);
    /* still again: at rest after two quiet windows, within the next block */
    sc.wobble_x = 0;
    REQUIRE(run_block(&r) == INC_OK);
    CHECK(r.valid);
    /* saturation */
    sc.s.flags |= SENSOR_S_ACCEL_SAT_X;
    REQUIRE(run_block(&r) == INC_OK);
    CHECK(!r.valid);
    CHECK_EQ_HEX(r.flags, APP_F_SATURATED);
    CHECK(r.slope.valid); /* the slope itself passed: the application says no */
    sc.s.flags &= ~SENSOR_S_ACCEL_SAT_X;
    /* one failed read in four: counted, the block takes 64 good samples */
    sc.fail_every = 4u;
    sc.fail_err = INC_ERR_TIMEOUT;
    REQUIRE(run_block(&r) == INC_OK);
    CHECK_EQ_INT(r.n, 64);
    CHECK(r.sensor_errors >= 21u);
    CHECK_EQ_HEX(r.flags, APP_F_SENSOR);
    CHECK(!r.valid);
    cfg.max_sensor_errors = 100u;
    REQUIRE(app_init(&app, &cfg, &sensor, &store) == INC_OK);
    REQUIRE(run_block(&r) == INC_OK);
    CHECK(r.valid);
    /* a dead sensor: app_measure gives up with its error */
    sc.fail_every = 1u;
    sc.fail_err = INC_ERR_BUS;
    sc.reads = 0;
    CHECK_ERR(app_measure(&app, &r), INC_ERR_BUS);
    CHECK_EQ_INT(sc.reads, 3u * cfg.avg_n); /* gave up after three blocks' worth of failures */
    sc.fail_every = 0u;
    CHECK_OK(app_measure(&app, &r));
    CHECK(r.valid);
    /* the missed-sample count of the adapter is summed */
    sc.s.missed = 2u;
    CHECK_OK(app_measure(&app, &r));
    CHECK_EQ_INT(r.missed, 128);
}

/* The noise-floor check: a quiet accelerometer axis is a frozen or stuck output. */
static void test_noise_floor(void)
{
    struct app_result r;
    struct calrec rec;
    script_reset();
    cfg_small();
    store_reset();
    make_record(&rec, true);
    REQUIRE(calstore_save(&store, &rec, NULL) == INC_OK);
    {
        struct app_cfg d;
        REQUIRE(app_cfg_default(&d, 819200u) == INC_OK);
        CHECK_EQ_INT(d.noise_floor_g, d.budget.noise_sigma_g / APP_QUIET_DIV); /* 4 mg / 4 */
        cfg.noise_floor_g = d.noise_floor_g;
    }
    REQUIRE(app_init(&app, &cfg, &sensor, &store) == INC_OK);
    /* constant samples (a frozen part): every window has variance 0 on every axis */
    REQUIRE(run_block(&r) == INC_OK);
    CHECK(!r.valid);
    CHECK((r.flags & APP_F_QUIET) != 0u);
    CHECK(r.slope.valid); /* the slope itself passed: the application says no */
    /* +-2 mg on x only: y and z still quiet (a stuck pair of axes) */
    sc.wobble_x = G(2);
    REQUIRE(run_block(&r) == INC_OK);
    CHECK((r.flags & APP_F_QUIET) != 0u);
    CHECK(!r.valid);
    /* +-2 mg on every axis (calibrated rms ~2 mg): above the 1 mg floor, valid */
    sc.wobble_yz = G(2);
    REQUIRE(run_block(&r) == INC_OK);
    CHECK_EQ_HEX(r.flags & APP_F_QUIET, 0u);
    CHECK(r.valid);
    /* a floor of 3 mg: the 2 mg part is "too quiet" */
    cfg.noise_floor_g = G(3);
    REQUIRE(app_init(&app, &cfg, &sensor, &store) == INC_OK);
    REQUIRE(run_block(&r) == INC_OK);
    CHECK((r.flags & APP_F_QUIET) != 0u);
    CHECK(!r.valid);
    sc.wobble_x = sc.wobble_yz = 0;
    cfg.noise_floor_g = 0; /* 0: no check */
    REQUIRE(app_init(&app, &cfg, &sensor, &store) == INC_OK);
    REQUIRE(run_block(&r) == INC_OK);
    CHECK((r.flags & APP_F_QUIET) == 0u);
    CHECK(r.valid);
    cfg.noise_floor_g = -1;
    CHECK_ERR(app_cfg_check(&cfg), INC_ERR_INVAL);
}

/* The offset-change check: the reference block, the tolerance, the latch, the restart. */
static void test_offset_change(void)
{
    struct app_result r;
    struct calrec rec;
    fx_q16_t tol;
    script_reset();
    cfg_small();
    store_reset();
    make_record(&rec, true);
    REQUIRE(calstore_save(&store, &rec, NULL) == INC_OK);
    {
        struct app_cfg d;
        REQUIRE(app_cfg_default(&d, 819200u) == INC_OK);
        CHECK_EQ_INT(d.budget.offset_drift_g, G(10)); /* [ADI-EPB]: 20 % of 50 mg */
    }
    cfg.budget.offset_drift_g = G(10);
    cfg.budget.nonlinearity_g = cfg.budget.temp_comp_g = 0; /* keep the bound below 2 deg */
    REQUIRE(app_init(&app, &cfg, &sensor, &store) == INC_OK);
    REQUIRE(run_block(&r) == INC_OK); /* the reference */
    CHECK(r.valid);
    CHECK_EQ_HEX(r.flags & APP_F_OFFSET_STEP, 0u);
    /* the bound carries the term: offset = residual + drift */
    CHECK_EQ_INT(r.budget.offset_g, cfg.budget.offset_g + cfg.budget.offset_drift_g);
    /* tolerance = drift - n - n_ref; the scripted block has the rated noise term on both */
    tol = cfg.budget.offset_drift_g - 2 * r.slope.noise_g;
    CHECK(tol > G(3) && tol < G(5));
    /* a change of 3 mg on x (through the record's gain: about 3 mg calibrated): not flagged */
    sc.s.accel_g[0] += G(3);
    REQUIRE(run_block(&r) == INC_OK);
    CHECK(r.valid);
    CHECK_EQ_HEX(r.flags & APP_F_OFFSET_STEP, 0u);
    /* 6 mg: flagged, not valid */
    sc.s.accel_g[0] += G(3);
    REQUIRE(run_block(&r) == INC_OK);
    CHECK(!r.valid);
    CHECK((r.flags & APP_F_OFFSET_STEP) != 0u);
    /* latched: back at the reference value, still flagged */
    sc.s.accel_g[0] -= G(6);
    REQUIRE(run_block(&r) == INC_OK);
    CHECK(!r.valid);
    CHECK((r.flags & APP_F_OFFSET_STEP) != 0u);
    /* app_restart takes a new reference */
    app_restart(&app);
    REQUIRE(run_block(&r) == INC_OK);
    CHECK(r.valid);
    CHECK_EQ_HEX(r.flags & APP_F_OFFSET_STEP, 0u);
    /* on the gravity axis too */
    sc.s.accel_g[2] -= G(8);
    REQUIRE(run_block(&r) == INC_OK);
    CHECK((r.flags & APP_F_OFFSET_STEP) != 0u);
    sc.s.accel_g[2] += G(8);
    /* a drift term too small for the noise terms: the check cannot tell, never valid after the
     * reference */
    cfg.budget.offset_drift_g = G(2);
    REQUIRE(app_init(&app, &cfg, &sensor, &store) == INC_OK);
    REQUIRE(run_block(&r) == INC_OK);
    CHECK(r.valid);
    REQUIRE(run_block(&r) == INC_OK);
    CHECK((r.flags & APP_F_OFFSET_STEP) != 0u);
    /* a block that is not still neither takes nor compares the reference */
    cfg.budget.offset_drift_g = G(10);
    sc.reads = 0;
    REQUIRE(app_init(&app, &cfg, &sensor, &store) == INC_OK);
    sc.wobble_x = G(100);
    REQUIRE(run_block(&r) == INC_OK);
    CHECK(!r.valid);
    CHECK_EQ_HEX(r.flags & APP_F_OFFSET_STEP, 0u);
    CHECK(!app.ref_set);
    sc.wobble_x = 0;
    /* 0: neither term nor check */
    cfg.budget.offset_drift_g = 0;
    REQUIRE(app_init(&app, &cfg, &sensor, &store) == INC_OK);
    REQUIRE(run_block(&r) == INC_OK);
    sc.s.accel_g[0] += G(50);
    REQUIRE(run_block(&r) == INC_OK);
    CHECK_EQ_HEX(r.flags & APP_F_OFFSET_STEP, 0u);
    CHECK_EQ_INT(r.budget.offset_g, cfg.budget.offset_g);
    sc.s.accel_g[0] -= G(50);
    cfg.budget.offset_drift_g = -1;
    CHECK_ERR(app_cfg_check(&cfg), INC_ERR_INVAL);
}

/* The record against the part type's limits at app_init. */
static void test_record_plausibility(void)
{
    struct calrec rec;
    struct app_cfg d;
    script_reset();
    REQUIRE(app_cfg_default(&d, 819200u) == INC_OK);
    CHECK_EQ_INT(d.rec_offset_max_g, G(100));
    CHECK_EQ_INT(d.rec_gain_tol, 107374182);    /* 0.1 in Q30 */
    CHECK_EQ_INT(d.rec_misalign_max, 37580963); /* 0.035 in Q30 */
    cfg_small();
    /* at the limits: loaded */
    store_reset();
    make_record(&rec, true);
    rec.acc_offset[1] = -G(100);
    rec.acc_gain[2] = FX_Q30_ONE + cfg.rec_gain_tol;
    rec.acc_misalign[0][1] = -cfg.rec_misalign_max;
    REQUIRE(calstore_save(&store, &rec, NULL) == INC_OK);
    REQUIRE(app_init(&app, &cfg, &sensor, &store) == INC_OK);
    CHECK_OK(app.cal_status);
    CHECK(app_calibrated(&app));
    /* one step beyond each: intact and bound to this part, but refused */
    {
        int k;
        for (k = 0; k < 3; k++) {
            struct app_result r;
            store_reset();
            make_record(&rec, true);
            if (k == 0) rec.acc_offset[1] = -G(100) - 1;
            if (k == 1) rec.acc_gain[2] = FX_Q30_ONE - cfg.rec_gain_tol - 1;
            if (k == 2) rec.acc_misalign[2][0] = cfg.rec_misalign_max + 1;
            REQUIRE(calstore_save(&store, &rec, NULL) == INC_OK);
            REQUIRE(app_init(&app, &cfg, &sensor, &store) == INC_OK);
            CHECK_ERR(app.cal_status, INC_ERR_RANGE);
            CHECK(!app_calibrated(&app));
            REQUIRE(run_block(&r) == INC_OK);
            CHECK(!r.valid);
            CHECK((r.flags & APP_F_NOT_CALIBRATED) != 0u);
        }
    }
    /* 0: that check off */
    cfg.rec_offset_max_g = 0;
    store_reset();
    make_record(&rec, true);
    rec.acc_offset[1] = G(300);
    REQUIRE(calstore_save(&store, &rec, NULL) == INC_OK);
    REQUIRE(app_init(&app, &cfg, &sensor, &store) == INC_OK);
    CHECK_OK(app.cal_status);
    cfg.rec_gain_tol = -1;
    CHECK_ERR(app_cfg_check(&cfg), INC_ERR_INVAL);
}

/* The end-of-line verification: calibrated face against +-1 g. */
static void test_eol_verify(void)
{
    struct calrec rec;
    struct app_face f;
    struct cal_acc ref;
    fx_q16_t out[3], dev = -1;
    int64_t exp_dev = 0;
    unsigned i;
    script_reset();
    cfg_small();
    store_reset();
    make_record(&rec, false);
    REQUIRE(calstore_save(&store, &rec, NULL) == INC_OK);
    REQUIRE(app_init(&app, &cfg, &sensor, &store) == INC_OK);
    REQUIRE(app_calibrated(&app));
    /* a raw XP face: x = 1.01 g + 10 mg (the record's gain and offset) plus 3 mg, y 2 mg, z -1 mg */
    memset(&f, 0, sizeof f);
    f.accel_g[0] = G(1023);
    f.accel_g[1] = G(2);
    f.accel_g[2] = -G(1);
    f.temp_c = FX_Q16_INT(25);
    f.flags = SENSOR_S_HAVE_TEMP;
    rec.valid = true;
    REQUIRE(cal_acc_init(&ref, &rec, FX_Q16_INT(25)) == INC_OK);
    REQUIRE(cal_acc_apply(&ref, f.accel_g, out) == INC_OK);
    for (i = 0; i < 3u; i++) {
        int64_t d = (int64_t)out[i] - (i == 0u ? FX_Q16_ONE : 0);
        d = d < 0 ? -d : d;
        if (d > exp_dev) exp_dev = d;
    }
    CHECK(exp_dev > G(1) && exp_dev < G(5));
    CHECK_OK(app_eol_verify(&app, &f, CAL_FACE_XP, (fx_q16_t)exp_dev, &dev));
    CHECK_EQ_INT(dev, exp_dev);
    CHECK_ERR(app_eol_verify(&app, &f, CAL_FACE_XP, (fx_q16_t)exp_dev - 1, &dev), INC_ERR_RANGE);
    /* the same face claimed as XN: 2 g off */
    CHECK_ERR(app_eol_verify(&app, &f, CAL_FACE_XN, G(5), &dev), INC_ERR_RANGE);
    CHECK(dev > G(1990));
    CHECK_ERR(app_eol_verify(&app, &f, 6, G(5), NULL), INC_ERR_INVAL);
    CHECK_ERR(app_eol_verify(&app, &f, CAL_FACE_XP, -1, NULL), INC_ERR_INVAL);
    CHECK_ERR(app_eol_verify(NULL, &f, CAL_FACE_XP, G(5), NULL), INC_ERR_NULL);
    /* no record: nothing to verify */
    store_reset();
    REQUIRE(app_init(&app, &cfg, &sensor, &store) == INC_OK);
    CHECK_ERR(app_eol_verify(&app, &f, CAL_FACE_XP, G(5), NULL), INC_ERR_NOT_CALIBRATED);
}

/* The temperature plausibility: range, rate, second source. */
static void test_temp_plausibility(void)
{
    struct app_result r;
    struct calrec rec;
    struct app_cfg d;
    REQUIRE(app_cfg_default(&d, 819200u) == INC_OK);
    CHECK_EQ_INT(d.temp_min_c, FX_Q16_INT(-45));
    CHECK_EQ_INT(d.temp_max_c, FX_Q16_INT(130));
    CHECK_EQ_INT(d.temp_step_max_c, FX_Q16_INT(2));
    CHECK_EQ_INT(d.temp_ref_tol_c, FX_Q16_INT(15));
    script_reset();
    cfg_small();
    cfg.temp_step_max_c = d.temp_step_max_c;
    store_reset();
    make_record(&rec, true);
    REQUIRE(calstore_save(&store, &rec, NULL) == INC_OK);
    REQUIRE(app_init(&app, &cfg, &sensor, &store) == INC_OK);
    REQUIRE(run_block(&r) == INC_OK);
    CHECK(r.valid);
    CHECK_EQ_HEX(r.flags & APP_F_TEMP_IMPLAUSIBLE, 0u);
    /* +2 degC in a block: at the limit */
    sc.s.temp_c += FX_Q16_INT(2);
    REQUIRE(run_block(&r) == INC_OK);
    CHECK(r.valid);
    /* +2.5 degC: faster than a die warms */
    sc.s.temp_c += FX_Q16_INT(2) + FX_Q16_HALF;
    REQUIRE(run_block(&r) == INC_OK);
    CHECK(!r.valid);
    CHECK((r.flags & APP_F_TEMP_IMPLAUSIBLE) != 0u);
    /* steady again: plausible (not latched) */
    REQUIRE(run_block(&r) == INC_OK);
    CHECK(r.valid);
    /* the second source: 29.5 degC read, the board at 14.5 (15 off: at the limit), then 14 */
    app_set_temp_ref(&app, FX_Q16_INT(14) + FX_Q16_HALF, true);
    REQUIRE(run_block(&r) == INC_OK);
    CHECK(r.valid);
    app_set_temp_ref(&app, FX_Q16_INT(14), true);
    REQUIRE(run_block(&r) == INC_OK);
    CHECK(!r.valid);
    CHECK((r.flags & APP_F_TEMP_IMPLAUSIBLE) != 0u);
    app_set_temp_ref(&app, 0, false); /* none fitted */
    REQUIRE(run_block(&r) == INC_OK);
    CHECK(r.valid);
    /* the range, on a fresh instance (no previous block) */
    sc.s.temp_c = FX_Q16_INT(131);
    REQUIRE(app_init(&app, &cfg, &sensor, &store) == INC_OK);
    REQUIRE(run_block(&r) == INC_OK);
    CHECK((r.flags & APP_F_TEMP_IMPLAUSIBLE) != 0u);
    CHECK(!r.valid);
    sc.s.temp_c = FX_Q16_INT(-46);
    REQUIRE(app_init(&app, &cfg, &sensor, &store) == INC_OK);
    REQUIRE(run_block(&r) == INC_OK);
    CHECK((r.flags & APP_F_TEMP_IMPLAUSIBLE) != 0u);
    /* a part without temperature output: nothing to check */
    sc.s.flags &= ~SENSOR_S_HAVE_TEMP;
    REQUIRE(app_init(&app, &cfg, &sensor, &store) == INC_OK);
    REQUIRE(run_block(&r) == INC_OK);
    CHECK_EQ_HEX(r.flags & APP_F_TEMP_IMPLAUSIBLE, 0u);
    sc.s.flags |= SENSOR_S_HAVE_TEMP;
    sc.s.temp_c = FX_Q16_INT(25);
    cfg.temp_min_c = FX_Q16_INT(140); /* above temp_max_c */
    CHECK_ERR(app_cfg_check(&cfg), INC_ERR_INVAL);
}

static void test_eol(void)
{
    static const int32_t one = FX_Q16_ONE;
    struct app_face faces[CAL_FACES], f;
    struct calrec rec;
    static struct app app2;
    unsigned i, k;
    script_reset();
    cfg_small();
    store_reset();
    REQUIRE(app_init(&app, &cfg, &sensor, &store) == INC_OK);
    CHECK_ERR(app_eol_face(&app, 0u, G(50), FX_Q16_INT(2), &f), INC_ERR_INVAL);
    CHECK_ERR(app_eol_face(NULL, 8u, G(50), FX_Q16_INT(2), &f), INC_ERR_NULL);
    /* The six faces of a part with x offset +20 mg and gain 1.02, y and z ideal; gyro x 0.5 deg/s. */
    for (k = 0; k < CAL_FACES; k++) {
        memset(&sc.s.accel_g, 0, sizeof sc.s.accel_g);
        sc.s.accel_g[k / 2u] = (k & 1u) ? -one : one;
        if (k / 2u == 0u) {
            sc.s.accel_g[0] = (k & 1u) ? -G(1020) : G(1020);
        }
        sc.s.accel_g[0] += G(20);
        sc.s.gyro_dps[0] = FX_Q16_HALF;
        REQUIRE(app_eol_face(&app, 32u, G(50), FX_Q16_INT(2), &faces[k]) == INC_OK);
        CHECK_EQ_INT(faces[k].n, 32);
        CHECK_EQ_INT(faces[k].flags, SENSOR_S_HAVE_GYRO | SENSOR_S_HAVE_TEMP);
        for (i = 0; i < 3u; i++) {
            CHECK_EQ_INT(faces[k].accel_g[i], sc.s.accel_g[i]); /* raw means, exact */
        }
        CHECK_EQ_INT(faces[k].temp_c, FX_Q16_INT(25));
    }
    calrec_set_default(&rec);
    CHECK_ERR(app_eol_six_position(NULL, &rec), INC_ERR_NULL);
    REQUIRE(app_eol_six_position(faces, &rec) == INC_OK);
    CHECK_EQ_INT(rec.acc_offset[0], G(20));
    CHECK_EQ_INT(rec.acc_gain[0], (int64_t)G(1020) * 16384); /* (A+ - A-) / 2 in Q30, exact */
    CHECK_EQ_INT(rec.acc_offset[1], 0);
    CHECK_EQ_INT(rec.acc_gain[2], FX_Q30_ONE);
    CHECK_EQ_INT(rec.gyro_offset[0], FX_Q16_HALF);
    CHECK_EQ_INT(rec.gyro_offset[1], 0);
    /* Saved, bound to the sensor; a fresh instance loads it. */
    CHECK_ERR(app_eol_save(&app, &rec, NULL, NULL), INC_ERR_NULL);
    REQUIRE(app_eol_save(&app, &rec, &store, NULL) == INC_OK);
    {
        const struct calrec_binding b = bind_of(&sc.id);
        CHECK(calrec_binding_equal(&rec.binding, &b));
    }
    CHECK(!app_calibrated(&app)); /* the running instance keeps its state until a restart */
    REQUIRE(app_init(&app2, &cfg, &sensor, &store) == INC_OK);
    CHECK_OK(app2.cal_status);
    CHECK(app_calibrated(&app2));
    CHECK_EQ_INT(app2.rec.acc_offset[0], G(20));

    /* Faces out of order: refused, rec untouched. */
    f = faces[0];
    faces[0] = faces[1];
    faces[1] = f;
    CHECK_ERR(app_eol_six_position(faces, &rec), INC_ERR_DEGENERATE);
    CHECK_EQ_INT(rec.acc_offset[0], G(20));
    faces[1] = faces[0];
    faces[0] = f;
    /* A gyro offset beyond 30 deg/s */
    for (k = 0; k < CAL_FACES; k++) {
        faces[k].gyro_dps[1] = FX_Q16_INT(31);
    }
    CHECK_ERR(app_eol_six_position(faces, &rec), INC_ERR_RANGE);
    /* Without gyro the gyro offset is left alone. */
    for (k = 0; k < CAL_FACES; k++) {
        faces[k].flags = SENSOR_S_HAVE_TEMP;
    }
    rec.gyro_offset[1] = 7;
    REQUIRE(app_eol_six_position(faces, &rec) == INC_OK);
    CHECK_EQ_INT(rec.gyro_offset[1], 7);

    /* A face that moves: 100 mg wobble > the 50 mg span. */
    sc.wobble_x = G(100);
    CHECK_ERR(app_eol_face(&app, 32u, G(50), FX_Q16_INT(2), &f), INC_ERR_MOTION);
    sc.wobble_x = 0;
    sc.fail_every = 5u;
    sc.fail_err = INC_ERR_DEVICE;
    CHECK_ERR(app_eol_face(&app, 32u, G(50), FX_Q16_INT(2), &f), INC_ERR_DEVICE);
}

int main(void)
{
    UNIT_RUN(test_cfg);
    UNIT_RUN(test_init_errors);
    UNIT_RUN(test_uncalibrated);
    UNIT_RUN(test_calibrated);
    UNIT_RUN(test_binding_and_store);
    UNIT_RUN(test_block_flags);
    UNIT_RUN(test_noise_floor);
    UNIT_RUN(test_offset_change);
    UNIT_RUN(test_record_plausibility);
    UNIT_RUN(test_eol_verify);
    UNIT_RUN(test_temp_plausibility);
    UNIT_RUN(test_eol);
    return unit_report();
}
