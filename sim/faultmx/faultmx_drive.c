/* faultmx_drive.c - the fault matrix of the driving attitude output (see sim/faultmx_drive.h). */
#include "inclino/sim/faultmx_drive.h"

#include <math.h>
#include <string.h>

#include "inclino/app.h"
#include "inclino/app_esc.h"
#include "inclino/can_frames.h"
#include "inclino/error.h"
#include "inclino/sim/inertial.h"
#include "inclino/sim/vehicle.h"

#define RATE_MHZ 819200u
#define SPEED_PERIOD 16u /* samples per speed frame (19.5 ms) */
#define AUX_RATE 250.0
#define AUX_LSB 0.00075
#define AUX_NOISE 0.005
#define AUX_RANGE 3.0
#define IMU_RANGE 18.0

static const char *const names[FMXD_FAULTS] = {
    "none",       "stuck_acc",    "stuck_gyro",  "frozen",    "bias_acc",
    "bias_gyro",  "noise_burst",  "saturation",  "drift_acc", "drift_gyro",
    "speed_lost", "speed_frozen", "speed_stuck", "aux_bias",  "read_error"};

const char *fmxd_fault_name(enum fmxd_fault f)
{
    return (unsigned)f < (unsigned)FMXD_FAULTS ? names[f] : "?";
}

static fx_q16_t q16(double v)
{
    double s = v * 65536.0;
    if (s > 2147483647.0) s = 2147483647.0;
    if (s < -2147483648.0) s = -2147483648.0;
    return (fx_q16_t)lround(s);
}

static int script_wait(void *dev, uint32_t timeout_ns)
{
    (void)dev;
    (void)timeout_ns;
    return INC_ERR_UNSUPPORTED;
}

static int script_read(void *dev, struct sensor_sample *out)
{
    (void)dev;
    (void)out;
    return INC_ERR_UNSUPPORTED; /* samples come from the scenario */
}

static int script_identity(void *dev, struct sensor_identity *out)
{
    (void)dev;
    memset(out, 0, sizeof(*out));
    out->family = SENSOR_FAMILY_ADIS163XX;
    out->product = 16405u;
    return INC_OK;
}

static const struct sensor_ops script_ops = {NULL, script_wait,     script_read, NULL,
                                             NULL, script_identity, NULL};

/* The true "up" in the sensor frame: R(q)^T e_z, the third row of R(q). */
static void true_up(const double q[4], double up[3])
{
    up[0] = 2.0 * (q[1] * q[3] - q[0] * q[2]);
    up[1] = 2.0 * (q[2] * q[3] + q[0] * q[1]);
    up[2] = 1.0 - 2.0 * (q[1] * q[1] + q[2] * q[2]);
}

static double wrap180(double d)
{
    while (d > 180.0)
        d -= 360.0;
    while (d < -180.0)
        d += 360.0;
    return d;
}

/* The output's error against the truth, deg: max of |roll|, |pitch| and inclination errors. */
static double out_err(const struct app_esc_output *o, const double qt[4])
{
    const double r2d = 180.0 / 3.14159265358979323846;
    double ut[3], ue[3], qe[4], dot, n;
    int k;
    for (k = 0; k < 4; k++)
        qe[k] = o->q[k] / 1073741824.0;
    true_up(qt, ut);
    true_up(qe, ue);
    n = sqrt(ue[0] * ue[0] + ue[1] * ue[1] + ue[2] * ue[2]);
    dot = (ut[0] * ue[0] + ut[1] * ue[1] + ut[2] * ue[2]) / n;
    if (dot > 1.0) dot = 1.0;
    {
        const double incl = acos(dot) * r2d;
        const double rt = atan2(ut[1], ut[2]) * r2d, pt = asin(fmax(-1.0, fmin(1.0, -ut[0]))) * r2d;
        const double er = fabs(wrap180(o->roll_deg / 65536.0 - rt));
        const double ep = fabs(o->pitch_deg / 65536.0 - pt);
        return fmax(incl, fmax(er, ep));
    }
}

int fmxd_run(const struct fmxd_setup *s, const struct fmxd_case *c, struct fmxd_result *out)
{
    static struct veh_scenario sc;
    static struct veh_sim sim;
    static struct app app;
    static struct app_esc esc;
    struct veh_config vcfg;
    struct app_cfg acfg;
    struct app_esc_cfg ecfg;
    const struct sensor sensor = {&script_ops, NULL};
    struct can_speed_rx srx;
    struct e2e_p01_protect_state veh_tx;
    struct app_vehicle veh = {false, 0, 0};
    struct can_frame last_frame;
    struct sim_rng rng_aux, rng_fault;
    struct veh_sample vs;
    double aux_bias[3], aux_val[3] = {0.0, 0.0, 1.0}, next_aux = 0.0, held_gyr[3], held_acc[3];
    double held_temp = 0.0, stuck_speed = 0.0;
    bool have_frame = false, aux_ok = false, on = false;
    uint64_t n = 0, onset_n = 0;
    const unsigned ax = c->axis > 2u ? 0u : c->axis;
    int err, k;

    memset(out, 0, sizeof(*out));
    out->modelled = 1;
    out->latency = UINT32_MAX;
    if (veh_preset_by_name(c->scenario, &sc) != INC_OK) return INC_ERR_INVAL;
    veh_config_default(&vcfg);
    vcfg.rate_hz = VEH_RATE_ADIS;
    vcfg.seed = s->seed;
    vcfg.accel_bias_sd_g = 1e-3; /* a part after end-of-line calibration (tests/att_vehicle) */
    err = veh_sim_init(&sim, &sc, &vcfg);
    if (err != INC_OK) return err;
    err = app_cfg_default(&acfg, RATE_MHZ);
    if (err == INC_OK) err = app_init(&app, &acfg, &sensor, NULL);
    if (err == INC_OK) err = app_esc_cfg_default(&ecfg, RATE_MHZ);
    if (err != INC_OK) return err;
    /* the ADIS1640x's noise and gyro range, as tools/can_run sets them */
    ecfg.att.rest_gyro_dps = FX_Q16_INT(5);
    ecfg.att.rest_acc_g = FX_Q16_ONE / 10;
    ecfg.att.gyro_fs_dps = q16(409.55);
    if (s->diagnostics) {
        err = app_esc_diag_default(&ecfg);
        if (err != INC_OK) return err;
        if (!s->aux) ecfg.xchk_thr_g = 0;
    }
    err = app_esc_init(&esc, &ecfg);
    if (err != INC_OK) return err;
    can_speed_rx_init(&srx, 5u);
    e2e_p01_protect_init(&veh_tx);
    sim_rng_seed(&rng_aux, s->seed * 7u + 5u);
    sim_rng_seed(&rng_fault, s->seed * 7u + 6u);
    for (k = 0; k < 3; k++)
        aux_bias[k] = 1e-3 * sim_rng_gauss(&rng_aux);
    memset(held_gyr, 0, sizeof(held_gyr));
    memset(held_acc, 0, sizeof(held_acc));

    while (veh_sim_next(&sim, &vs)) {
        struct sensor_sample ss;
        struct app_esc_output o;
        bool have = false;
        int read_err = INC_OK;
        const double t = vs.t_s;
        if (!on && c->fault != FMXD_NONE && t >= c->onset_s) {
            on = true;
            onset_n = n;
            memcpy(held_gyr, vs.gyr_dps, sizeof(held_gyr));
            memcpy(held_acc, vs.acc_g, sizeof(held_acc));
            held_temp = vs.temp_c;
            stuck_speed = vs.speed_mps;
        }
        /* ---- the fault on the IMU's sample ---- */
        if (on) {
            const double dt_on = t - c->onset_s;
            switch (c->fault) {
            case FMXD_STUCK_ACC: vs.acc_g[ax] = held_acc[ax]; break;
            case FMXD_STUCK_GYRO: vs.gyr_dps[ax] = held_gyr[ax]; break;
            case FMXD_FROZEN:
                memcpy(vs.gyr_dps, held_gyr, sizeof(held_gyr));
                memcpy(vs.acc_g, held_acc, sizeof(held_acc));
                vs.temp_c = held_temp;
                break;
            case FMXD_BIAS_ACC: vs.acc_g[ax] += c->amp; break;
            case FMXD_BIAS_GYRO: vs.gyr_dps[ax] += c->amp; break;
            case FMXD_NOISE_BURST:
                if (dt_on < 1.0) {
                    for (k = 0; k < 3; k++)
                        vs.acc_g[k] += c->amp * sim_rng_gauss(&rng_fault);
                }
                break;
            case FMXD_SATURATION: vs.acc_g[ax] = IMU_RANGE; break;
            case FMXD_DRIFT_ACC: vs.acc_g[ax] += c->amp * dt_on; break;
            case FMXD_DRIFT_GYRO: vs.gyr_dps[ax] += c->amp * dt_on; break;
            case FMXD_READ_ERROR:
                if (dt_on < c->amp) read_err = INC_ERR_BUS;
                break;
            default: break;
            }
        }
        /* ---- the speed frame (the vehicle side, then the application's receiver) ---- */
        if (n % SPEED_PERIOD == 0u) {
            struct can_frame f;
            const struct can_frame *rx = NULL;
            if (on && c->fault == FMXD_SPEED_LOST) {
                rx = NULL;
            } else if (on && c->fault == FMXD_SPEED_FROZEN && have_frame) {
                rx = &last_frame;
            } else {
                const double v = on && c->fault == FMXD_SPEED_STUCK ? stuck_speed : vs.speed_mps;
                can_pack_speed(&veh_tx, true, q16(v), true, q16(vs.yaw_rate_dps), &f);
                last_frame = f;
                have_frame = true;
                rx = &f;
            }
            can_speed_rx_cycle(&srx, rx, &veh);
        }
        /* ---- the second accelerometer (sample and hold at its rate) ---- */
        if (s->aux && t >= next_aux) {
            aux_ok = true;
            for (k = 0; k < 3; k++) {
                double a = vs.true_acc_g[k] + aux_bias[k] + AUX_NOISE * sim_rng_gauss(&rng_aux);
                if (on && c->fault == FMXD_AUX_BIAS && k == (int)ax) a += c->amp;
                a = AUX_LSB * floor(a / AUX_LSB + 0.5);
                if (fabs(a) >= AUX_RANGE) {
                    a = a > 0 ? AUX_RANGE : -AUX_RANGE;
                    aux_ok = false; /* saturated: the check holds */
                }
                aux_val[k] = a;
            }
            next_aux += 1.0 / AUX_RATE;
        }
        if (s->aux) {
            const fx_q16_t a3[3] = {q16(aux_val[0]), q16(aux_val[1]), q16(aux_val[2])};
            app_esc_set_aux_accel(&esc, a3, aux_ok);
        }
        /* ---- the IMU's sample into the application ---- */
        memset(&ss, 0, sizeof ss);
        for (k = 0; k < 3; k++) {
            ss.accel_g[k] = q16(vs.acc_g[k]);
            ss.gyro_dps[k] = q16(vs.gyr_dps[k]);
            if (fabs(vs.acc_g[k]) >= IMU_RANGE) ss.flags |= SENSOR_S_ACCEL_SAT_X << k;
        }
        ss.temp_c = q16(vs.temp_c);
        ss.flags |= SENSOR_S_HAVE_ACCEL | SENSOR_S_HAVE_GYRO | SENSOR_S_HAVE_TEMP;
        ss.t_ns = (uint64_t)llround(t * 1e9);
        if (read_err != INC_OK) {
            out->read_errors++;
            if (!out->detected) {
                out->detected = true;
                out->latency = (uint32_t)(n - onset_n);
            }
        }
        err = app_esc_step(&esc, &app, &ss, read_err, &veh, &o, &have);
        n++;
        if (err != INC_OK && err != read_err) return err;
        if (read_err != INC_OK) continue;
        if (s->diagnostics) {
            const double thr = o.veh_thr_g / 65536.0;
            const double ratio = thr > 0.0 ? o.veh_level_g / 65536.0 / thr : 0.0;
            if (ratio > out->max_veh_ratio) out->max_veh_ratio = ratio;
            if (o.xchk_level_g / 65536.0 > out->max_xchk_g)
                out->max_xchk_g = o.xchk_level_g / 65536.0;
            if (!on)
                out->false_diag |= (uint8_t)(o.diag &
                                             (APP_ESC_D_FLAT | APP_ESC_D_VEH | APP_ESC_D_XCHK));
        }
        if (!have || o.mode != APP_MODE_DRIVING) continue;
        if (!on) {
            if (o.valid) out->valid_before++;
            if (c->fault != FMXD_NONE) continue;
        }
        {
            const double e = out_err(&o, vs.q);
            const double b = o.bound_deg / 65536.0;
            out->outputs++;
            out->diag_word |= o.diag;
            out->att_word |= o.att_fault;
            if (o.valid) {
                out->valid++;
                if (e > b) out->valid_wrong++;
                if (b > out->max_bound_deg) out->max_bound_deg = b;
                if (b <= 2.0) out->valid_b[0]++;
                if (b <= 5.0) out->valid_b[1]++;
                if (b <= 10.0) out->valid_b[2]++;
                if (e >= out->max_err_deg) {
                    out->max_err_deg = e;
                    out->bound_deg = b;
                }
            } else if (!out->detected && c->fault != FMXD_NONE &&
                       (o.diag != 0u || o.att_fault != 0u)) {
                out->detected = true;
                out->latency = (uint32_t)(n - 1u - onset_n);
            }
        }
    }
    return INC_OK;
}
