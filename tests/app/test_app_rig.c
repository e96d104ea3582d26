/*
 * The EPB application through the real drivers on the simulated board (sim/epb_rig.h): the
 * adapters (identity, samples, missed data-ready, device alarms), the end of line with exact
 * expected values on an ideal part, the record saved in the emulated flash and loaded after a
 * power cycle, a car on a slope (valid, within the bound), and the bad cases: no record, a
 * corrupt one, a foreign one, a car that drives off. Zero timing violations throughout.
 * Host and QEMU; small blocks (64 samples) to keep QEMU quick.
 */
#include <math.h>
#include <string.h>

#include "inclino/sim/epb_rig_state.h"
#include "adis_imu_regs.h" /* white-box: the driver's register map */
#include "unit.h"

static struct epb_rig rig;
static struct app_cfg cfg;

#define PI 3.14159265358979323846

static void cfg_small(void)
{
    REQUIRE(app_cfg_default(&cfg, epb_rig_rate_mhz(&rig)) == INC_OK);
    cfg.still.window = 16u;
    cfg.avg_n = 64u;
    /* 64-sample blocks on app_cfg_default's Table 1 terms: the ageing term would take the bound
     * past 2 deg; the offset-change check is tested in tests/app/test_app_logic.c and on this
     * rig by the fault matrix (tools/fault_matrix, docs/safety.md). */
    cfg.budget.offset_drift_g = 0;
}

/* The end of line on the rig: faces of n samples at 25 degC, on-device six-position, saved. */
static int eol(uint32_t n, struct calrec *rec, struct calstore_info *info)
{
    struct app_face faces[CAL_FACES];
    int f, err;
    for (f = 0; f < CAL_FACES; f++) {
        epb_rig_station(&rig, f, 25.0);
        epb_rig_wait(&rig, 0.05);
        err = app_eol_face(&rig.app, n, FX_Q16_INT(1) / 20, FX_Q16_INT(2), &faces[f]);
        if (err != INC_OK) return err;
    }
    calrec_set_default(rec);
    err = app_eol_six_position(faces, rec);
    return err != INC_OK ? err : app_eol_save(&rig.app, rec, &rig.store, info);
}

static void park(double grade_pct, bool engine, double drive_off_s)
{
    struct epb_rig_vehicle v;
    epb_rig_vehicle_default(&v);
    v.slope_deg = atan(grade_pct / 100.0) * 180.0 / PI;
    v.bump_rate_hz = 0.0;
    if (!engine) v.idle_rpm = 0.0;
    v.drive_off_s = drive_off_s;
    epb_rig_park(&rig, &v);
    epb_rig_wait(&rig, 0.1);
}

/* Ideal part (no error, no noise): every number of the chain is exact. */
/* counts of the ADIS16405 (3.333 mg) in Q16 g, by the driver's conversion */
static int32_t accel_g(int32_t counts)
{
    int32_t g = 0;
    CHECK_OK(adis_imu_accel_g_from_counts(counts, 3333u, &g));
    return g;
}

static void test_adis16405_exact(void)
{
    struct sim_calpart_params ideal;
    struct calrec rec;
    struct calstore_info info;
    struct app_result r;
    int32_t one, tenth, z;
    double th;
    sim_calpart_ideal(&ideal);
    REQUIRE(epb_rig_init(&rig, EPB_RIG_ADIS16405, &ideal, 1u) == INC_OK);
    cfg_small();
    cfg.budget.temp_uncomp_g = 0; /* an ideal part does not drift: no temperature model needed */
    cfg.noise_floor_g = 0;        /* nor has it noise: the noise-floor check would (rightly) trip */
    cfg.budget.tscale_uncomp = 0;
    REQUIRE(epb_rig_power_up(&rig, &cfg) == INC_OK);
    CHECK_ERR(rig.app.cal_status, INC_ERR_NOT_CALIBRATED);
    CHECK_EQ_INT(rig.app.id.family, CALREC_FAMILY_ADIS163XX);
    CHECK_EQ_INT(rig.app.id.product, 16405);
    CHECK_EQ_INT(rig.app.id.serial, 0);
    REQUIRE(eol(32u, &rec, &info) == INC_OK);
    /* 1 g = round(1 / 3.333 mg) = 300 counts: offset 0, gain = 300 counts in Q30, exactly. */
    one = accel_g(300);
    CHECK_EQ_INT(rec.acc_offset[0], 0);
    CHECK_EQ_INT(rec.acc_gain[0], (int64_t)one * 16384);
    CHECK_EQ_INT(rec.acc_gain[2], (int64_t)one * 16384);
    CHECK_EQ_INT(rec.gyro_offset[1], 0);
    CHECK_EQ_INT(info.seq, 1);
    CHECK_EQ_INT(info.used_slot, 0);

    /* Power cycle in the parked car (10 %: x = sin 5.71 deg -> 30 counts, z -> 299 counts). */
    park(10.0, false, -1.0);
    REQUIRE(epb_rig_power_up(&rig, &cfg) == INC_OK);
    CHECK_OK(rig.app.cal_status);
    CHECK(app_calibrated(&rig.app));
    REQUIRE(app_measure(&rig.app, &r) == INC_OK);
    tenth = accel_g(30);
    z = accel_g(299);
    {
        struct cal_acc ref;
        fx_q16_t in[3] = {tenth, 0, z}, out[3];
        REQUIRE(cal_acc_init(&ref, &rig.app.rec, FX_Q16_INT(25)) == INC_OK);
        REQUIRE(cal_acc_apply(&ref, in, out) == INC_OK);
        CHECK_EQ_INT(r.accel_g[0], out[0]);
        CHECK_EQ_INT(r.accel_g[2], out[2]);
        CHECK_NEAR_INT(out[0], FX_Q16_ONE / 10, 1); /* 30 / 300 counts */
        CHECK_EQ_INT(r.slope.slope_deg, fx_atan2_deg(out[0], out[2]));
    }
    CHECK(r.valid);
    CHECK_EQ_HEX(r.flags, APP_F_TEMP_UNCOMP); /* no model in the record, budget 0 for it */
    CHECK_EQ_INT(r.n, 64);
    CHECK_EQ_INT(r.missed, 0);
    th = atan(0.1) * 180.0 / PI;
    CHECK(fabs(r.slope.slope_deg / 65536.0 - th) <= r.slope.bound_deg / 65536.0);
    /* The quantisation (3.3 mg) is all that is left: 299/300 on z -> 0.019 deg. */
    CHECK_NEAR(r.slope.slope_deg / 65536.0, th, 0.03);
    CHECK_EQ_INT(epb_rig_violations(&rig), 0);
}

/* A part with errors and noise on the SCA3000 (no data-ready: paced reads). */
static void test_sca3000_part_a(void)
{
    struct calrec rec;
    struct calstore_info info;
    struct app_result r;
    double err_deg;
    REQUIRE(epb_rig_init(&rig, EPB_RIG_SCA3000_D01, NULL, 7u) == INC_OK);
    cfg_small();
    CHECK_EQ_INT(cfg.still.window, 16);
    REQUIRE(epb_rig_power_up(&rig, &cfg) == INC_OK);
    CHECK_EQ_INT(rig.app.id.family, CALREC_FAMILY_SCA3000);
    CHECK_EQ_INT(rig.app.id.product, CALREC_SCA3000_D01);
    CHECK_EQ_INT(rig.app.id.revision, SIM_SCA3000_REVID_DEFAULT);
    REQUIRE(eol(64u, &rec, &info) == INC_OK);
    /* Part A's x flip offset at 25 degC: bias + scale * nl2 (within the face noise). */
    CHECK_NEAR(rec.acc_offset[0] / 65536.0,
               sim_calpart_tcurve_eval(&rig.errors.p.acc_bias[0], 25.0, 0.0) +
                   sim_calpart_tcurve_eval(&rig.errors.p.acc_scale[0], 25.0, 0.0) *
                       rig.errors.p.acc_nl2[0],
               0.003);
    park(10.0, true, -1.0);
    /* At the calibration temperature: no model, but no drift either beyond the hysteresis
     * (0.1 mg): the test's budget says so, the rest is [ADI-EPB]'s. */
    cfg.budget.temp_uncomp_g = FX_Q16_ONE / 200; /* 5 mg */
    REQUIRE(epb_rig_power_up(&rig, &cfg) == INC_OK);
    CHECK_OK(rig.app.cal_status);
    REQUIRE(app_measure(&rig.app, &r) == INC_OK);
    REQUIRE(app_measure(&rig.app, &r) == INC_OK);
    CHECK(r.valid);
    CHECK_EQ_HEX(r.flags, APP_F_TEMP_UNCOMP);
    err_deg = r.slope.slope_deg / 65536.0 - atan(0.1) * 180.0 / PI;
    CHECK(fabs(err_deg) <= r.slope.bound_deg / 65536.0);
    CHECK(r.sigma_meas_g > FX_Q16_ONE / 1000); /* engine vibration measured (> 1 mg) */
    CHECK_EQ_INT(r.missed, 0);
    CHECK_EQ_INT(epb_rig_violations(&rig), 0);
}

/* The 1636x reads its serial number and lot ids into the binding; a record of that part is
 * refused by an ADIS16364 with another serial (a different rig). */
static void test_identity_and_bad_records(void)
{
    static uint8_t saved[2048];
    struct calrec rec;
    struct calstore_info info;
    struct app_result r;
    struct sim_calpart_params ideal;
    uint16_t serial;
    sim_calpart_ideal(&ideal);
    REQUIRE(epb_rig_init(&rig, EPB_RIG_ADIS16364, &ideal, 3u) == INC_OK);
    cfg_small();
    REQUIRE(epb_rig_power_up(&rig, &cfg) == INC_OK);
    CHECK_EQ_INT(rig.app.id.product, 16364);
    CHECK_EQ_INT(rig.app.id.serial, sim_adis_imu_peek(&rig.adis, ADIS1636X_REG_SERIAL_NUM));
    CHECK_EQ_INT(rig.app.id.lot_id1, sim_adis_imu_peek(&rig.adis, ADIS1636X_REG_LOT_ID1));
    CHECK(rig.app.id.serial != 0u);
    REQUIRE(eol(16u, &rec, &info) == INC_OK);
    REQUIRE(simflash_peek(&rig.flash, 0u, saved, sizeof saved) == INC_OK);

    /* Same part, power cycle: calibrated. */
    REQUIRE(epb_rig_power_up(&rig, &cfg) == INC_OK);
    CHECK_OK(rig.app.cal_status);

    /* Another part of the same type (its serial number differs): the record is foreign. */
    serial = sim_adis_imu_peek(&rig.adis, ADIS1636X_REG_SERIAL_NUM);
    rig.adis.reg[ADIS1636X_REG_SERIAL_NUM / 2u] = (uint16_t)(serial ^
                                                             0x0077u); /* read-only: back door */
    REQUIRE(epb_rig_power_up(&rig, &cfg) == INC_OK);
    CHECK_ERR(rig.app.cal_status, INC_ERR_MISMATCH);
    CHECK(!app_calibrated(&rig.app));
    park(10.0, false, -1.0);
    REQUIRE(app_measure(&rig.app, &r) == INC_OK);
    CHECK(!r.valid);
    CHECK((r.flags & APP_F_NOT_CALIBRATED) != 0u);
    CHECK((r.slope.flags & SLOPE_F_NOT_CALIBRATED) != 0u);
    rig.adis.reg[ADIS1636X_REG_SERIAL_NUM / 2u] = serial;

    /* A corrupted flash: one bit of the record flipped -> no intact record. */
    REQUIRE(simflash_flip_bit(&rig.flash, 200u, 3u) == INC_OK);
    REQUIRE(epb_rig_power_up(&rig, &cfg) == INC_OK);
    CHECK_ERR(rig.app.cal_status, INC_ERR_CRC);
    REQUIRE(app_measure(&rig.app, &r) == INC_OK);
    CHECK(!r.valid);
    CHECK((r.flags & APP_F_NOT_CALIBRATED) != 0u);

    /* Restored: calibrated again. */
    REQUIRE(simflash_poke(&rig.flash, 0u, saved, sizeof saved) == INC_OK);
    REQUIRE(epb_rig_power_up(&rig, &cfg) == INC_OK);
    CHECK_OK(rig.app.cal_status);
    CHECK_EQ_INT(epb_rig_violations(&rig), 0);
}

/* The car drives off: the stillness detector and the magnitude test refuse the estimate. */
static void test_moving_and_alarms(void)
{
    struct calrec rec;
    struct calstore_info info;
    struct app_result r;
    struct sensor_sample s;
    struct sim_calpart_params ideal;
    sim_calpart_ideal(&ideal);
    ideal.acc_noise_g = 0.002;
    REQUIRE(epb_rig_init(&rig, EPB_RIG_ADIS16405, &ideal, 5u) == INC_OK);
    cfg_small();
    REQUIRE(epb_rig_power_up(&rig, &cfg) == INC_OK);
    REQUIRE(eol(32u, &rec, &info) == INC_OK);
    park(10.0, true, 0.0);
    REQUIRE(epb_rig_power_up(&rig, &cfg) == INC_OK);
    epb_rig_wait(&rig, 1.0); /* 0.12 g reached, road vibration */
    REQUIRE(app_measure(&rig.app, &r) == INC_OK);
    CHECK(!r.valid);
    CHECK((r.slope.flags & SLOPE_F_NOT_STILL) != 0u);
    CHECK((r.flags & APP_F_NOT_STILL) != 0u);
    CHECK(r.motion_windows > 0u);

    /* Missed data-ready: 5 sample periods without a read -> the next sample says 4 or 5. */
    park(10.0, false, -1.0);
    REQUIRE(sensor_next(&rig.sensor, 0u, &s) == INC_OK);
    epb_rig_wait(&rig, 5.0 / 819.2);
    REQUIRE(sensor_next(&rig.sensor, 0u, &s) == INC_OK);
    CHECK(s.missed >= 4u && s.missed <= 5u);
    CHECK_EQ_INT(s.flags, SENSOR_S_HAVE_ACCEL | SENSOR_S_HAVE_GYRO | SENSOR_S_HAVE_TEMP);
    CHECK_NEAR_INT(s.temp_c, FX_Q16_INT(25), FX_Q16_ONE / 10);

    /* An alarm in DIAG_STAT (EA on every output): reads fail, the block is not valid. */
    sim_adis_imu_raise_diag(&rig.adis, ADIS_IMU_DIAG_ALARM1);
    CHECK_ERR(sensor_next(&rig.sensor, 0u, &s), INC_ERR_DEVICE);
    CHECK_EQ_INT(s.flags, 0); /* nothing handed out with the error */
    app_restart(&rig.app);
    sim_adis_imu_raise_diag(&rig.adis, ADIS_IMU_DIAG_ALARM1);
    REQUIRE(app_measure(&rig.app, &r) == INC_OK);
    CHECK(r.sensor_errors >= 1u);
    CHECK((r.flags & APP_F_SENSOR) != 0u);
    CHECK(!r.valid);
    CHECK_EQ_INT(epb_rig_violations(&rig), 0);
}

/* The drivers' ops refuse what they cannot do, through the struct sensor the application uses. */
static void test_sensor_errors(void)
{
    struct adis_imu imu;
    struct sca3000 dev;
    struct sensor si = {&adis_imu_sensor_ops, &imu}, ss = {&sca3000_sensor_ops, &dev};
    struct sensor_sample s;
    struct sensor_identity id;
    memset(&imu, 0, sizeof imu);
    memset(&dev, 0, sizeof dev);
    CHECK_ERR(sensor_next(&si, 0u, &s), INC_ERR_STATE); /* driver not ready */
    CHECK_ERR(sensor_get_identity(&si, &id), INC_ERR_STATE);
    CHECK_ERR(sensor_next(&ss, 0u, &s), INC_ERR_STATE);
    REQUIRE(epb_rig_init(&rig, EPB_RIG_SCA3000_D01, NULL, 1u) == INC_OK);
    cfg_small();
    REQUIRE(epb_rig_power_up(&rig, &cfg) == INC_OK);
    CHECK_OK(sensor_next(&rig.sensor, 0u, &s));
    CHECK_EQ_INT(s.flags & (SENSOR_S_HAVE_ACCEL | SENSOR_S_HAVE_GYRO | SENSOR_S_HAVE_TEMP),
                 SENSOR_S_HAVE_ACCEL | SENSOR_S_HAVE_TEMP);
    REQUIRE(sca3000_set_mode(&rig.sca_dev, SCA3000_MODE_MOTION) == INC_OK);
    CHECK_ERR(sensor_wait_ready(&rig.sensor, 0u), INC_ERR_STATE); /* no output rate */
    CHECK_EQ_INT(epb_rig_violations(&rig), 0);
}

/* app_eol_fit_save: the same record as app_eol_six_position + app_eol_save, built in the
 * application's own record; the instance is then not ready until the next app_init, which
 * loads the new record, or after a failed save the one before. app_eol_face drops the block. */
static void test_fit_save(void)
{
    struct app_face faces[CAL_FACES], swapped[CAL_FACES];
    struct calrec ref;
    struct calstore_info info;
    struct app_result r;
    struct sim_calpart_params part;
    bool done = false;
    int f, k;
    sim_calpart_ideal(&part);
    part.acc_bias[0].y0 = 0.02; /* offsets and gains the fit must find */
    part.acc_bias[2].y0 = -0.015;
    part.acc_scale[1].y0 = 1.01;
    REQUIRE(epb_rig_init(&rig, EPB_RIG_ADIS16405, &part, 7u) == INC_OK);
    cfg_small();
    REQUIRE(epb_rig_power_up(&rig, &cfg) == INC_OK);
    CHECK_ERR(rig.app.cal_status, INC_ERR_NOT_CALIBRATED);
    /* a block in progress, then a face: the block is dropped */
    for (k = 0; k < 5; k++) {
        struct sensor_sample smp;
        REQUIRE(sensor_next(&rig.app.sensor, 0u, &smp) == INC_OK);
        REQUIRE(app_step(&rig.app, &smp, 0, NULL, &done, &r) == INC_OK);
    }
    CHECK_EQ_INT(rig.app.n, 5);
    for (f = 0; f < CAL_FACES; f++) {
        epb_rig_station(&rig, f, 25.0);
        epb_rig_wait(&rig, 0.05);
        REQUIRE(app_eol_face(&rig.app, 32u, FX_Q16_INT(1) / 20, FX_Q16_INT(2), &faces[f]) ==
                INC_OK);
        CHECK_EQ_INT(rig.app.n, 0);
    }
    calrec_set_default(&ref);
    REQUIRE(app_eol_six_position(faces, &ref) == INC_OK);
    CHECK(ref.acc_offset[0] > FX_Q16_ONE / 100); /* the part's 20 mg */

    CHECK_ERR(app_eol_fit_save(NULL, faces, &rig.store, NULL), INC_ERR_NULL);
    CHECK_ERR(app_eol_fit_save(&rig.app, NULL, &rig.store, NULL), INC_ERR_NULL);
    CHECK_ERR(app_eol_fit_save(&rig.app, faces, NULL, NULL), INC_ERR_NULL);
    CHECK(rig.app.ready); /* refused before it touched the record */
    REQUIRE(app_eol_fit_save(&rig.app, faces, &rig.store, &info) == INC_OK);
    CHECK_EQ_INT(info.seq, 1);
    CHECK(!rig.app.ready);
    CHECK_ERR(app_measure(&rig.app, &r), INC_ERR_STATE);
    CHECK_ERR(app_eol_fit_save(&rig.app, faces, &rig.store, NULL), INC_ERR_STATE);
    CHECK_ERR(app_eol_face(&rig.app, 32u, FX_Q16_INT(1) / 20, FX_Q16_INT(2), &faces[0]),
              INC_ERR_STATE);

    /* Power cycle: the record of the fit, bound to this part. */
    REQUIRE(epb_rig_power_up(&rig, &cfg) == INC_OK);
    CHECK_OK(rig.app.cal_status);
    CHECK(app_calibrated(&rig.app));
    for (k = 0; k < 3; k++) {
        CHECK_EQ_INT(rig.app.rec.acc_offset[k], ref.acc_offset[k]);
        CHECK_EQ_INT(rig.app.rec.acc_gain[k], ref.acc_gain[k]);
        CHECK_EQ_INT(rig.app.rec.gyro_offset[k], ref.gyro_offset[k]);
    }
    CHECK(calrec_binding_equal(&rig.app.rec.binding, &rig.app.id));

    /* A failed fit (two faces swapped: cal_six_position refuses them): not ready, nothing
     * stored; the next app_init runs on the record before. */
    memcpy(swapped, faces, sizeof swapped);
    swapped[0] = faces[1];
    swapped[1] = faces[0];
    CHECK(app_eol_fit_save(&rig.app, swapped, &rig.store, &info) != INC_OK);
    CHECK(!rig.app.ready);
    REQUIRE(epb_rig_power_up(&rig, &cfg) == INC_OK);
    CHECK_OK(rig.app.cal_status);
    CHECK_EQ_INT(rig.app.rec.acc_offset[0], ref.acc_offset[0]);
    CHECK_EQ_INT(rig.app.rec.acc_gain[1], ref.acc_gain[1]);
    park(10.0, false, -1.0);
    REQUIRE(app_measure(&rig.app, &r) == INC_OK);
    CHECK_EQ_HEX(r.flags & APP_F_NOT_CALIBRATED, 0);
    CHECK_EQ_INT(epb_rig_violations(&rig), 0);
}

int main(void)
{
    UNIT_RUN(test_adis16405_exact);
    UNIT_RUN(test_sca3000_part_a);
    UNIT_RUN(test_identity_and_bad_records);
    UNIT_RUN(test_moving_and_alarms);
    UNIT_RUN(test_sensor_errors);
    UNIT_RUN(test_fit_save);
    return unit_report();
}
