/*
 * att_score - score an attitude estimate against a recording with truth (docs/attitude.md).
 *
 *   att_score TRUTH.csv[.gz] EST.csv[.gz] [--name NAME] [--t-min S] [--require KEY<=V|KEY>=V]...
 *
 * TRUTH: a CSV with the columns t_s, truth_qw, truth_qx, truth_qy, truth_qz (nan where the
 * truth is lost) and movement (the BROAD benchmark's layout; tools/vehicle_sim writes the same).
 * EST: one row per TRUTH row with t_s, q_w, q_x, q_y, q_z, att_bound_deg, att_valid (imu_replay's
 * output). Either may be "-" (standard input) and either may be gzip'd. Prints one line:
 *   name=.. n=.. rms_deg=.. max_deg=.. valid_frac=.. over_bound_frac=.. max_err_over_bound=..
 *   max_valid_err_deg=.. median_bound_deg=.. roll_rms_deg=.. roll_max_deg=.. pitch_rms_deg=..
 *   pitch_max_deg=.. result=pass|fail
 * Every --require is checked against those keys; the first that fails is named on stderr.
 * Exit 0 (every requirement met), 1 (one failed), 2 (bad arguments or input).
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "inclino/attscore.h"
#include "inclino/error.h"
#include "inclino/tool_cli.h"
#include "inclino/sim/imu_csv.h"

#define MAX_REQ 32

struct req {
    char key[40];
    int ge; /* 1: >=, 0: <= */
    double v;
};

static void usage(FILE *f)
{
    fprintf(f, "usage: att_score TRUTH.csv[.gz] EST.csv[.gz] [--name NAME] [--t-min S]\n"
               "                 [--require KEY<=V|KEY>=V]...\n"
               "keys: n rms_deg max_deg valid_frac over_bound_frac max_err_over_bound\n"
               "      max_valid_err_deg median_bound_deg roll_rms_deg roll_max_deg pitch_rms_deg\n"
               "      pitch_max_deg\n");
}

/* A finite decimal number, the whole field (tools/lib/cli; the caller's message names the
 * option). */
static int parse_double(const char *s, double *out)
{
    int rc;
    cli_set_quiet(1);
    rc = cli_parse_double("value", s, -1e300, 1e300, 0, out);
    cli_set_quiet(0);
    return rc == INC_OK ? 0 : -1;
}

static int read_table(const char *path, const struct imu_csv_spec *spec, int n,
                      struct imu_csv_cols *t)
{
    char msg[512];
    int err;
    FILE *f = imu_csv_open(path);
    if (f == NULL) {
        fprintf(stderr, "att_score: cannot open %s: %s\n", path, strerror(errno));
        return -1;
    }
    err = imu_csv_read_named(f, path, spec, n, t, msg, sizeof msg);
    if (fclose(f) != 0 && err == INC_OK) {
        imu_csv_cols_free(t);
        fprintf(stderr, "att_score: %s: read error\n", path);
        return -1;
    }
    if (err != INC_OK) {
        fprintf(stderr, "att_score: %s (%s)\n", msg, inc_err_name(err));
        return -1;
    }
    return 0;
}

static double key_value(const struct attscore_result *r, const char *key, int *found)
{
    *found = 1;
    if (strcmp(key, "n") == 0) return (double)r->n;
    if (strcmp(key, "rms_deg") == 0) return r->rms_deg;
    if (strcmp(key, "max_deg") == 0) return r->max_deg;
    if (strcmp(key, "valid_frac") == 0) return r->valid_frac;
    if (strcmp(key, "over_bound_frac") == 0) return r->over_bound_frac;
    if (strcmp(key, "max_err_over_bound") == 0) return r->max_err_over_bound;
    if (strcmp(key, "max_valid_err_deg") == 0) return r->max_valid_err_deg;
    if (strcmp(key, "median_bound_deg") == 0) return r->median_bound_deg;
    if (strcmp(key, "roll_rms_deg") == 0) return r->roll_rms_deg;
    if (strcmp(key, "roll_max_deg") == 0) return r->roll_max_deg;
    if (strcmp(key, "pitch_rms_deg") == 0) return r->pitch_rms_deg;
    if (strcmp(key, "pitch_max_deg") == 0) return r->pitch_max_deg;
    *found = 0;
    return 0.0;
}

int main(int argc, char **argv)
{
    static const struct imu_csv_spec truth_spec[] = {
        {"t_s", IMU_CSV_TIME},        {"truth_qw", IMU_CSV_NAN_OK}, {"truth_qx", IMU_CSV_NAN_OK},
        {"truth_qy", IMU_CSV_NAN_OK}, {"truth_qz", IMU_CSV_NAN_OK}, {"movement", 0u}};
    static const struct imu_csv_spec est_spec[] = {
        {"t_s", IMU_CSV_TIME}, {"q_w", 0u},           {"q_x", 0u},      {"q_y", 0u},
        {"q_z", 0u},           {"att_bound_deg", 0u}, {"att_valid", 0u}};
    struct req req[MAX_REQ];
    int nreq = 0, i, fail = 0;
    const char *paths[2] = {NULL, NULL}, *name = NULL;
    double t_min = 5.0;
    struct imu_csv_cols tr, es;
    struct attscore_sample *s;
    struct attscore_result r;
    size_t k;

    for (i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            usage(stdout);
            return 0;
        } else if (strcmp(argv[i], "--name") == 0 && i + 1 < argc) {
            name = argv[++i];
        } else if (strcmp(argv[i], "--t-min") == 0 && i + 1 < argc) {
            if (parse_double(argv[++i], &t_min) != 0 || t_min < 0.0) {
                fprintf(stderr, "att_score: --t-min '%s' is not a number >= 0\n", argv[i]);
                return 2;
            }
        } else if (strcmp(argv[i], "--require") == 0 && i + 1 < argc) {
            const char *a = argv[++i], *op = strstr(a, "<=");
            int found;
            struct attscore_result probe = {0};
            if (op == NULL) op = strstr(a, ">=");
            if (op == NULL || op == a || (size_t)(op - a) >= sizeof req[0].key || nreq == MAX_REQ) {
                fprintf(stderr, "att_score: --require '%s': KEY<=V or KEY>=V\n", a);
                return 2;
            }
            memcpy(req[nreq].key, a, (size_t)(op - a));
            req[nreq].key[op - a] = '\0';
            req[nreq].ge = op[0] == '>';
            (void)key_value(&probe, req[nreq].key, &found);
            if (!found || parse_double(op + 2, &req[nreq].v) != 0) {
                fprintf(stderr, "att_score: --require '%s': unknown key or bad number\n", a);
                return 2;
            }
            nreq++;
        } else if (argv[i][0] == '-' && argv[i][1] != '\0') {
            fprintf(stderr, "att_score: unknown option '%s'\n", argv[i]);
            usage(stderr);
            return 2;
        } else if (paths[0] == NULL) {
            paths[0] = argv[i];
        } else if (paths[1] == NULL) {
            paths[1] = argv[i];
        } else {
            fprintf(stderr, "att_score: one truth and one estimate file only\n");
            return 2;
        }
    }
    if (paths[0] == NULL || paths[1] == NULL) {
        usage(stderr);
        return 2;
    }
    if (strcmp(paths[0], "-") == 0 && strcmp(paths[1], "-") == 0) {
        fprintf(stderr, "att_score: only one of the files can be standard input\n");
        return 2;
    }
    if (read_table(paths[0], truth_spec, 6, &tr) != 0) return 2;
    if (read_table(paths[1], est_spec, 7, &es) != 0) {
        imu_csv_cols_free(&tr);
        return 2;
    }
    if (tr.n != es.n) {
        fprintf(stderr, "att_score: %s has %zu rows but %s has %zu: one estimate per sample\n",
                paths[0], tr.n, paths[1], es.n);
        imu_csv_cols_free(&tr);
        imu_csv_cols_free(&es);
        return 2;
    }
    s = malloc((tr.n ? tr.n : 1u) * sizeof(*s));
    if (s == NULL) {
        fprintf(stderr, "att_score: out of memory\n");
        imu_csv_cols_free(&tr);
        imu_csv_cols_free(&es);
        return 2;
    }
    for (k = 0; k < tr.n; k++) {
        const double tt = imu_csv_at(&tr, k, 0), te = imu_csv_at(&es, k, 0);
        const double mv = imu_csv_at(&tr, k, 5), av = imu_csv_at(&es, k, 6);
        int c;
        if (fabs(tt - te) > 1e-6 * (1.0 + fabs(tt))) {
            fprintf(stderr, "att_score: row %zu: truth time %.9g s but estimate time %.9g s\n",
                    k + 1u, tt, te);
            fail = 2;
            break;
        }
        if ((mv != 0.0 && mv != 1.0) || (av != 0.0 && av != 1.0)) {
            fprintf(stderr, "att_score: row %zu: movement and att_valid must be 0 or 1\n", k + 1u);
            fail = 2;
            break;
        }
        s[k].t_s = tt;
        for (c = 0; c < 4; c++) {
            s[k].q_truth[c] = imu_csv_at(&tr, k, 1 + c);
            s[k].q_est[c] = imu_csv_at(&es, k, 1 + c);
        }
        s[k].movement = (int)mv;
        s[k].bound_deg = imu_csv_at(&es, k, 5);
        s[k].valid = av == 1.0;
    }
    if (fail == 0 && attscore_score(s, tr.n, t_min, &r) != 0) {
        fprintf(stderr, "att_score: out of memory\n");
        fail = 2;
    }
    free(s);
    imu_csv_cols_free(&tr);
    imu_csv_cols_free(&es);
    if (fail != 0) return fail;
    for (i = 0; i < nreq; i++) {
        int found;
        const double v = key_value(&r, req[i].key, &found);
        const int ok = req[i].ge ? v >= req[i].v : v <= req[i].v;
        if (!ok) {
            fprintf(stderr, "att_score: requirement %s %s %.6g failed: %.6g\n", req[i].key,
                    req[i].ge ? ">=" : "<=", req[i].v, v);
            fail = 1;
        }
    }
    printf("name=%s n=%zu rms_deg=%.4f max_deg=%.4f valid_frac=%.5f over_bound_frac=%.6f "
           "max_err_over_bound=%.4f max_valid_err_deg=%.4f median_bound_deg=%.4f "
           "roll_rms_deg=%.4f roll_max_deg=%.4f pitch_rms_deg=%.4f pitch_max_deg=%.4f result=%s\n",
           name != NULL ? name : "-", r.n, r.rms_deg, r.max_deg, r.valid_frac, r.over_bound_frac,
           r.max_err_over_bound, r.max_valid_err_deg, r.median_bound_deg, r.roll_rms_deg,
           r.roll_max_deg, r.pitch_rms_deg, r.pitch_max_deg, fail == 0 ? "pass" : "fail");
    if (fflush(stdout) != 0 || ferror(stdout)) {
        fprintf(stderr, "att_score: write error on standard output\n");
        return 2;
    }
    return fail;
}
