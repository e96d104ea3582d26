/*
 * can_run - the application's CAN output on a simulated drive, through the S32K1 FlexCAN driver
 * and its register model (docs/can.md).
 *
 *   can_run --log FILE.log --csv FILE.csv [--scenario NAME] [--duration S] [--seed N]
 *           [--speed-period N] [--speed-loss A:B]
 *
 * Per sample of the scenario (sim/vehicle, 819.2 samples/s): the sample goes through app_esc_step
 * (EPB blocks while parked, attitude while driving). Every speed-period samples (default 16,
 * 19.5 ms) the vehicle side packs the VEH_Speed frame (E2E protected) and the model receives it;
 * the application side takes it through the driver (s32k_flexcan_receive) and the speed receiver
 * (can_speed_rx_cycle), whose output is the vehicle input of the following samples. Between
 * A and B seconds (--speed-loss) no speed frame is sent. Each output of the application is packed
 * (can_pack_output) and sent with s32k_flexcan_send; the model writes the candump log.
 * The CSV has one row per sent frame, in log order, with the values the application computed
 * (full precision, before scaling).
 *
 * Last line on stdout: summary: tool=can_run status=ok|error frames=N slope=N attitude=N
 *   status_frames=N speed_usable=N speed_rejected=N att_valid=N slope_valid=N tx_errors=N
 *   unmapped=N duration_s=S
 * Exit status: 0 ok, 1 bad usage or a set-up failure, 2 an output could not be written.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "inclino/app.h"
#include "inclino/app_esc.h"
#include "inclino/can_frames.h"
#include "inclino/error.h"
#include "inclino/s32k_flexcan.h"
#include "inclino/sim/s32k_bus.h"
#include "inclino/sim/s32k_flexcan_model.h"
#include "inclino/sim/vehicle.h"
#include "inclino/tool_summary.h"

#define RATE_MHZ 819200u
/* the log's time 0: 2023-11-14 22:13:20 UTC, a fixed wall-clock epoch as candump writes */
#define CAN_RUN_EPOCH_S 1700000000u

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

static fx_q16_t q16(double v)
{
    double s = v * 65536.0;
    if (s > 2147483647.0) s = 2147483647.0;
    if (s < -2147483648.0) s = -2147483648.0;
    return (fx_q16_t)lround(s);
}

static double dq(fx_q16_t v)
{
    return v / 65536.0;
}

static void usage(void)
{
    fprintf(stderr,
            "usage: can_run --log FILE.log --csv FILE.csv [--scenario NAME] [--duration S]\n"
            "               [--seed N] [--speed-period N] [--speed-loss A:B]\n");
}

int main(int argc, char **argv)
{
    const char *log_path = NULL, *csv_path = NULL, *scen = "braking";
    double duration = 0.0, loss_a = -1.0, loss_b = -1.0;
    unsigned long seed = 1, speed_period = 16;
    tool_summary_begin("can_run");
    for (int i = 1; i < argc; i++) {
        const char *o = argv[i];
        if (i + 1 >= argc) {
            usage();
            return tool_summary_error("usage", 1);
        }
        const char *v = argv[++i];
        char *end = NULL;
        if (strcmp(o, "--log") == 0) {
            log_path = v;
        } else if (strcmp(o, "--csv") == 0) {
            csv_path = v;
        } else if (strcmp(o, "--scenario") == 0) {
            scen = v;
        } else if (strcmp(o, "--duration") == 0) {
            duration = strtod(v, &end);
            if (end == v || *end != '\0' || !(duration > 0.0)) {
                usage();
                return tool_summary_error("usage", 1);
            }
        } else if (strcmp(o, "--seed") == 0) {
            seed = strtoul(v, &end, 10);
            if (end == v || *end != '\0') {
                usage();
                return tool_summary_error("usage", 1);
            }
        } else if (strcmp(o, "--speed-period") == 0) {
            speed_period = strtoul(v, &end, 10);
            if (end == v || *end != '\0' || speed_period < 1 || speed_period > 1000) {
                usage();
                return tool_summary_error("usage", 1);
            }
        } else if (strcmp(o, "--speed-loss") == 0) {
            if (sscanf(v, "%lf:%lf", &loss_a, &loss_b) != 2 || !(loss_b > loss_a)) {
                usage();
                return tool_summary_error("usage", 1);
            }
        } else {
            usage();
            return tool_summary_error("usage", 1);
        }
    }
    if (log_path == NULL || csv_path == NULL) {
        usage();
        return tool_summary_error("usage", 1);
    }

    static struct veh_scenario sc;
    static struct veh_sim sim;
    struct veh_config vcfg;
    if (veh_preset_by_name(scen, &sc) != INC_OK) {
        fprintf(stderr, "can_run: unknown scenario '%s'\n", scen);
        return tool_summary_error("unknown-scenario", 1);
    }
    veh_config_default(&vcfg);
    vcfg.rate_hz = VEH_RATE_ADIS;
    vcfg.seed = seed;
    vcfg.accel_bias_sd_g = 1e-3; /* a part after end-of-line calibration (tests/att_vehicle) */
    if (veh_sim_init(&sim, &sc, &vcfg) != INC_OK) {
        return tool_summary_error("scenario", 1);
    }

    FILE *logf = fopen(log_path, "w");
    FILE *csv = fopen(csv_path, "w");
    if (logf == NULL || csv == NULL) {
        fprintf(stderr, "can_run: cannot open the outputs: %s\n", strerror(errno));
        return tool_summary_error("cannot-open", 2);
    }
    fputs("frame,t_s,id,mode,valid,slope_deg,grade_pct,slope_bound_deg,roll_deg,pitch_deg,"
          "att_bound_deg,grade_bound_pct,app_flags,slope_flags,att_fault,speed_ok\n",
          csv);

    /* the simulated S32K144: CAN0 and its model on the bus, the driver's _sim build */
    static struct s32k_flexcan_model model;
    struct s32k_flexcan can;
    struct s32k_flexcan_cfg ccfg;
    s32k_bus_reset();
    int rc = s32k_flexcan_model_init(&model, S32K_CAN0_BASE, 32u, logf, "can0");
    model.log_epoch_s = CAN_RUN_EPOCH_S;
    s32k_flexcan_cfg_default(&ccfg, CAN_ID_SPEED);
    if (rc == INC_OK) rc = s32k_flexcan_init(&can, &ccfg);
    if (rc != INC_OK) {
        return tool_summary_error(inc_err_name(rc), 1);
    }

    /* the application, uncalibrated (no record), ESC mode */
    static struct app app;
    static struct app_esc esc;
    struct app_cfg acfg;
    struct app_esc_cfg ecfg;
    const struct sensor sensor = {&script_ops, NULL};
    if (app_cfg_default(&acfg, RATE_MHZ) != INC_OK ||
        app_init(&app, &acfg, &sensor, NULL) != INC_OK ||
        app_esc_cfg_default(&ecfg, RATE_MHZ) != INC_OK) {
        return tool_summary_error("app", 1);
    }
    /* the ADIS1640x's noise, as imu_replay sets it for that part: rest thresholds that see rest
     * through the part's noise, and its 14-bit gyro range */
    ecfg.att.rest_gyro_dps = FX_Q16_INT(5);
    ecfg.att.rest_acc_g = FX_Q16_ONE / 10;
    ecfg.att.gyro_fs_dps = q16(409.55);
    if (app_esc_init(&esc, &ecfg) != INC_OK) {
        return tool_summary_error("app", 1);
    }
    struct can_tx tx;
    struct can_speed_rx srx;
    struct e2e_p01_protect_state veh_tx;
    can_tx_init(&tx);
    can_speed_rx_init(&srx, 5u);
    e2e_p01_protect_init(&veh_tx);
    struct app_vehicle veh = {false, 0, 0};

    unsigned long long n = 0, frames = 0, n_slope = 0, n_att = 0, n_status = 0, att_valid = 0,
                       slope_valid = 0, tx_errors = 0;
    struct veh_sample s;
    double last_t = 0.0;
    int werr = 0;
    while (veh_sim_next(&sim, &s)) {
        if (duration > 0.0 && s.t_s >= duration) break;
        last_t = s.t_s;
        uint64_t t_ns = (uint64_t)llround(s.t_s * 1e9);
        s32k_flexcan_model_set_time_ns(&model, t_ns);
        if (n % speed_period == 0u) {
            bool lost = s.t_s >= loss_a && s.t_s < loss_b;
            if (!lost) {
                struct can_frame sf;
                can_pack_speed(&veh_tx, true, q16(s.speed_mps), true, q16(s.yaw_rate_dps), &sf);
                (void)s32k_flexcan_model_inject(&model, (uint16_t)sf.id, sf.data, sf.dlc);
            }
            struct can_frame rf;
            uint16_t id;
            uint8_t dlc;
            bool ovr;
            int r = s32k_flexcan_receive(&can, &id, rf.data, &dlc, &ovr);
            rf.id = id;
            rf.dlc = dlc;
            can_speed_rx_cycle(&srx, r == INC_OK ? &rf : NULL, &veh);
        }
        struct sensor_sample ss;
        memset(&ss, 0, sizeof ss);
        for (int k = 0; k < 3; k++) {
            ss.accel_g[k] = q16(s.acc_g[k]);
            ss.gyro_dps[k] = q16(s.gyr_dps[k]);
        }
        ss.temp_c = q16(s.temp_c);
        ss.flags = SENSOR_S_HAVE_ACCEL | SENSOR_S_HAVE_GYRO | SENSOR_S_HAVE_TEMP;
        ss.t_ns = t_ns;
        struct app_esc_output out;
        bool have = false;
        rc = app_esc_step(&esc, &app, &ss, 0, &veh, &out, &have);
        n++;
        if (rc != INC_OK) {
            fprintf(stderr, "can_run: app_esc_step: %s\n", inc_err_name(rc));
            return tool_summary_error(inc_err_name(rc), 1);
        }
        if (!have) continue;
        struct can_frame fr[2];
        size_t nf = 0;
        bool speed_ok = veh.valid;
        if (can_pack_output(&tx, &out, speed_ok, fr, &nf) != INC_OK) {
            return tool_summary_error("pack", 1);
        }
        for (size_t k = 0; k < nf; k++) {
            if (s32k_flexcan_send(&can, (uint16_t)fr[k].id, fr[k].data, fr[k].dlc) != INC_OK) {
                tx_errors++;
                continue;
            }
            if (fr[k].id == CAN_ID_SLOPE) n_slope++;
            if (fr[k].id == CAN_ID_ATTITUDE) n_att++;
            if (fr[k].id == CAN_ID_STATUS) n_status++;
            bool parked = out.mode == APP_MODE_PARKED;
            bool valid = parked ? out.epb.slope.valid : out.valid;
            if (fr[k].id == CAN_ID_SLOPE && valid) slope_valid++;
            if (fr[k].id == CAN_ID_ATTITUDE && valid) att_valid++;
            if (fprintf(csv,
                        "%llu,%.6f,0x%03X,%u,%d,%.9f,%.9f,%.9f,%.9f,%.9f,%.9f,%.9f,%u,%u,%u,%d\n",
                        frames, s.t_s, (unsigned)fr[k].id, (unsigned)out.mode, valid ? 1 : 0,
                        parked ? dq(out.epb.slope.slope_deg) : 0.0,
                        parked ? dq(out.epb.slope.grade_pct) : 0.0,
                        parked ? dq(out.epb.slope.bound_deg) : 0.0, parked ? 0.0 : dq(out.roll_deg),
                        parked ? 0.0 : dq(out.pitch_deg), parked ? 0.0 : dq(out.bound_deg),
                        parked ? dq(out.epb.slope.bound_pct) : 0.0,
                        parked ? (unsigned)(out.epb.flags & 0xFFu) : 0u,
                        parked ? (unsigned)(out.epb.slope.flags & 0xFFu) : 0u,
                        parked ? 0u : (unsigned)out.att_fault, speed_ok ? 1 : 0) < 0) {
                werr = 1;
            }
            frames++;
        }
        if (s32k_flexcan_error_state(&can) != INC_OK) tx_errors++;
    }
    if (fclose(csv) != 0) werr = 1;
    if (fflush(logf) != 0 || fclose(logf) != 0) werr = 1;
    if (werr) {
        return tool_summary_error("io", 2);
    }
    const struct s32k_bus_stats *bs = s32k_bus_stats();
    printf("can_run: %s, %llu samples, %llu frames (%llu slope, %llu attitude, %llu status)\n",
           sc.name, n, frames, n_slope, n_att, n_status);
    tool_summary_add("scenario", "%s", sc.name);
    tool_summary_add("frames", "%llu", frames);
    tool_summary_add("slope", "%llu", n_slope);
    tool_summary_add("attitude", "%llu", n_att);
    tool_summary_add("status_frames", "%llu", n_status);
    tool_summary_add("speed_usable", "%u", (unsigned)srx.usable);
    tool_summary_add("speed_rejected", "%u", (unsigned)srx.rejected);
    tool_summary_add("att_valid", "%llu", att_valid);
    tool_summary_add("slope_valid", "%llu", slope_valid);
    tool_summary_add("tx_errors", "%llu", tx_errors);
    tool_summary_add("model_tx", "%u", (unsigned)model.stats.tx_frames);
    tool_summary_add("unmapped", "%u", (unsigned)(bs->unmapped_reads + bs->unmapped_writes));
    tool_summary_add("duration_s", "%.3f", n > 0 ? last_t + 1.0 / VEH_RATE_ADIS : 0.0);
    return tool_summary_end(tx_errors == 0 ? "ok" : "fail", tx_errors == 0 ? 0 : 1);
}
