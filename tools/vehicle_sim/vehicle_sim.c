/*
 * vehicle_sim - write a vehicle scenario with truth as CSV (docs/vehicle-scenarios.md).
 *
 *   vehicle_sim --scenario NAME|list [--rate HZ] [--seed N] [--out FILE.csv] [--duration S]
 *               [--mount-deg R,P,Y] [--ideal]
 *
 * Prints one summary line on standard output:
 *   scenario=NAME samples=N duration_s=... max_lat_g=... max_lon_g=... max_roll_deg=...
 *   max_pitch_deg=...
 * Exit status: 0 ok, 1 bad usage or argument, 2 the output could not be written.
 */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "inclino/error.h"
#include "inclino/sim/vehicle.h"
#include "inclino/tool_cli.h"

static void usage(void)
{
    fprintf(
        stderr,
        "usage: vehicle_sim --scenario NAME|list [--rate HZ] [--seed N] [--out FILE.csv]\n"
        "                   [--duration S] [--mount-deg R,P,Y] [--accel-bias-mg X] [--ideal]\n"
        "  --rate HZ         output rate, 10..10000 (default 819.2; the low rate is 285.714)\n"
        "  --seed N          integer 0..18446744073709551615 (default 1)\n"
        "  --duration S      stop after S seconds (0 < S <= the scenario's length)\n"
        "  --mount-deg R,P,Y mounting misalignment roll, pitch, yaw in deg, each |x| <= 10\n"
        "  --accel-bias-mg X accelerometer turn-on bias, 1 sigma per axis, mg, 0..100 (default\n"
        "                    5: a factory-calibrated part; about 1 after end-of-line calibration)\n"
        "  --ideal           no sensor errors: every output is the truth\n");
}

/* A whole-field finite decimal number (tools/lib/cli: no blanks, no '+', no hex, nothing
 * after it), any range: the callers check theirs. */
static int parse_double(const char *s, double *v)
{
    return cli_parse_double("value", s, -1e300, 1e300, 0, v) == INC_OK ? 0 : -1;
}

static int parse_u64(const char *s, unsigned long long *v)
{
    uint64_t x = 0;
    if (cli_parse_u64("--seed", s, 0, UINT64_MAX, &x) != INC_OK) return -1;
    *v = x;
    return 0;
}

/* Three comma-separated numbers. */
static int parse_triple(const char *s, double v[3])
{
    char buf[128];
    char *parts[3];
    size_t n = strlen(s), i, k = 0;
    if (n == 0 || n >= sizeof(buf)) return -1;
    memcpy(buf, s, n + 1);
    parts[k++] = buf;
    for (i = 0; i < n; i++) {
        if (buf[i] == ',') {
            if (k == 3) return -1;
            buf[i] = '\0';
            parts[k++] = &buf[i + 1];
        }
    }
    if (k != 3) return -1;
    for (i = 0; i < 3; i++) {
        if (parse_double(parts[i], &v[i]) != 0) return -1;
    }
    return 0;
}

struct args {
    const char *scenario, *out;
    double rate, duration, mount[3], accel_bias_mg;
    unsigned long long seed;
    int ideal;
};

static int bad(const char *opt, const char *val, const char *why)
{
    fprintf(stderr, "vehicle_sim: %s '%s': %s\n", opt, val, why);
    return -1;
}

static int parse(int argc, char **argv, struct args *a)
{
    int i;
    memset(a, 0, sizeof(*a));
    a->rate = VEH_RATE_ADIS;
    a->seed = 1;
    a->accel_bias_mg = -1.0;
    for (i = 1; i < argc; i++) {
        const char *o = argv[i], *v;
        if (strcmp(o, "--ideal") == 0) {
            a->ideal = 1;
            continue;
        }
        if (strcmp(o, "--help") == 0 || strcmp(o, "-h") == 0) return 1;
        if (strcmp(o, "--scenario") != 0 && strcmp(o, "--rate") != 0 && strcmp(o, "--seed") != 0 &&
            strcmp(o, "--out") != 0 && strcmp(o, "--duration") != 0 &&
            strcmp(o, "--mount-deg") != 0 && strcmp(o, "--accel-bias-mg") != 0) {
            fprintf(stderr, "vehicle_sim: unknown option '%s'\n", o);
            return -1;
        }
        if (i + 1 >= argc) {
            fprintf(stderr, "vehicle_sim: %s needs a value\n", o);
            return -1;
        }
        v = argv[++i];
        if (strcmp(o, "--scenario") == 0) {
            a->scenario = v;
        } else if (strcmp(o, "--out") == 0) {
            if (*v == '\0') return bad(o, v, "empty file name");
            a->out = v;
        } else if (strcmp(o, "--rate") == 0) {
            if (parse_double(v, &a->rate) != 0) return bad(o, v, "not a number");
            if (!(a->rate >= 10.0 && a->rate <= 10000.0)) return bad(o, v, "outside 10..10000 Hz");
        } else if (strcmp(o, "--seed") == 0) {
            if (parse_u64(v, &a->seed) != 0) return bad(o, v, "not an unsigned 64-bit integer");
        } else if (strcmp(o, "--accel-bias-mg") == 0) {
            if (parse_double(v, &a->accel_bias_mg) != 0) return bad(o, v, "not a number");
            if (!(a->accel_bias_mg >= 0.0 && a->accel_bias_mg <= 100.0))
                return bad(o, v, "outside 0..100 mg");
        } else if (strcmp(o, "--duration") == 0) {
            if (parse_double(v, &a->duration) != 0) return bad(o, v, "not a number");
            if (!(a->duration > 0.0)) return bad(o, v, "must be > 0");
        } else {
            int k;
            if (parse_triple(v, a->mount) != 0) return bad(o, v, "not three numbers R,P,Y");
            for (k = 0; k < 3; k++) {
                if (!(fabs(a->mount[k]) <= 10.0)) return bad(o, v, "each angle within +-10 deg");
            }
        }
    }
    if (a->scenario == NULL) {
        fprintf(stderr, "vehicle_sim: --scenario is required\n");
        return -1;
    }
    return 0;
}

static const char HEADER[] = "t_s,gyr_x_dps,gyr_y_dps,gyr_z_dps,acc_x_g,acc_y_g,acc_z_g,truth_qw,"
                             "truth_qx,truth_qy,truth_qz,movement,speed_mps,yaw_rate_dps,temp_c\n";

int main(int argc, char **argv)
{
    static struct veh_scenario sc;
    static struct cli_out out;
    static struct veh_sim sim;
    struct veh_config cfg;
    struct veh_sample o;
    struct args a;
    FILE *f = NULL;
    unsigned long long n = 0;
    double max_lat = 0.0, max_lon = 0.0, max_roll = 0.0, max_pitch = 0.0, last_t = 0.0;
    int rc, werr = 0;
    cli_set_program("vehicle_sim");
    cli_set_quiet(1); /* parse's own messages name the option and the range */
    rc = parse(argc, argv, &a);
    cli_set_quiet(0);
    if (rc != 0) {
        usage();
        return rc > 0 ? 0 : 1;
    }
    if (strcmp(a.scenario, "list") == 0) {
        size_t i;
        for (i = 0; i < veh_preset_count(); i++) {
            if (veh_preset_build(i, &sc) != INC_OK) return 1;
            printf("%-13s %7.1f s  %s\n", veh_preset_name(i), veh_scenario_duration(&sc),
                   veh_preset_summary(i));
        }
        return fflush(stdout) == 0 ? 0 : 2;
    }
    if (veh_preset_by_name(a.scenario, &sc) != INC_OK) {
        fprintf(stderr, "vehicle_sim: unknown scenario '%s' (--scenario list)\n", a.scenario);
        return 1;
    }
    if (a.duration > veh_scenario_duration(&sc) + 1e-9) {
        fprintf(stderr, "vehicle_sim: --duration %g is longer than %s (%.1f s)\n", a.duration,
                sc.name, veh_scenario_duration(&sc));
        return 1;
    }
    veh_config_default(&cfg);
    cfg.rate_hz = a.rate;
    cfg.seed = a.seed;
    cfg.sensor_errors = !a.ideal;
    if (a.accel_bias_mg >= 0.0) cfg.accel_bias_sd_g = a.accel_bias_mg * 1e-3;
    memcpy(cfg.mount_deg, a.mount, sizeof(cfg.mount_deg));
    if (veh_sim_init(&sim, &sc, &cfg) != INC_OK) {
        fprintf(stderr, "vehicle_sim: bad configuration\n");
        return 1;
    }
    if (a.out != NULL) {
        /* the safe writer (tools/lib/cli): a temporary file renamed when every write succeeded;
         * never a FIFO, a symlink or a device */
        if (cli_out_open(&out, "--out", a.out, NULL, 0) != INC_OK) return 2;
        f = out.f;
        if (fputs(HEADER, f) < 0) werr = 1;
    }
    while (!werr && veh_sim_next(&sim, &o)) {
        if (a.duration > 0.0 && o.t_s >= a.duration - 1e-12) break;
        n++;
        last_t = o.t_s;
        if (fabs(o.path_acc_g[1]) > max_lat) max_lat = fabs(o.path_acc_g[1]);
        if (fabs(o.path_acc_g[0]) > max_lon) max_lon = fabs(o.path_acc_g[0]);
        if (fabs(o.roll_deg) > max_roll) max_roll = fabs(o.roll_deg);
        if (fabs(o.pitch_deg) > max_pitch) max_pitch = fabs(o.pitch_deg);
        if (f != NULL &&
            fprintf(f, "%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.9f,%.9f,%.9f,%.9f,%d,%.4f,%.3f,%.2f\n",
                    o.t_s, o.gyr_dps[0], o.gyr_dps[1], o.gyr_dps[2], o.acc_g[0], o.acc_g[1],
                    o.acc_g[2], o.q[0], o.q[1], o.q[2], o.q[3], o.movement, o.speed_mps,
                    o.yaw_rate_dps, o.temp_c) < 0) {
            werr = 1;
        }
    }
    if (f != NULL) {
        if (werr) {
            cli_out_discard(&out);
        } else if (cli_out_close(&out) != INC_OK) {
            return 2;
        }
    }
    if (werr) {
        fprintf(stderr, "vehicle_sim: write error on %s\n", a.out);
        return 2;
    }
    printf("scenario=%s samples=%llu duration_s=%.3f max_lat_g=%.3f max_lon_g=%.3f "
           "max_roll_deg=%.2f max_pitch_deg=%.2f\n",
           sc.name, n, n > 0 ? last_t + 1.0 / a.rate : 0.0, max_lat, max_lon, max_roll, max_pitch);
    return fflush(stdout) == 0 ? 0 : 2;
}
