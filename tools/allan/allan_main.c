/*
 * allan - overlapping Allan deviation of a gyro (or any rate) record: from a CSV file or from a
 * simulated run of a configured error model. Prints the angle random walk (ADEV at tau = 1 s)
 * and the bias instability (minimum / 0.664); writes the curve as CSV, SVG and a gnuplot script.
 * docs/noise-and-allan.md has examples.
 *
 *   allan --csv FILE|- [--col K] [--time-col K | --rate-hz F] [--scale S] [--unit U]
 *   allan --sim adis|separated [--seconds T] [--seed S] [--sample-hz F] [--no-quant] [--theory]
 *   common: [--per-decade P] [--min-clusters C] [--min-rel-err E] [--out curve.csv] [--svg plot.svg]
 *           [--gnuplot plot.gp [--png plot.png]] [--quiet]
 *
 * --sim adis: the x gyro of the simulated ADIS1636x/1640x (sim/noise.h presets) sampled at
 * 819.2 SPS with no Bartlett filtering (SENS_AVG M = 0), each sample quantised to the output
 * register (14-bit two's complement, 0.05 deg/s per LSB) unless --no-quant.
 * --sim separated: the well-separated test part (SIM_NOISE_SEP_*), 2 SPS, no quantisation.
 * Default lengths: 20 000 s (adis), 10^6 s (separated).
 * Exit status: 0 ok, 1 bad usage, 2 bad input, 3 computation failed.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "inclino/tool_cli.h"
#include "inclino/tool_summary.h"
#include "inclino/error.h"
#include "inclino/sim/allan.h"
#include "inclino/sim/inertial.h"
#include "inclino/sim/noise.h"

#define MAX_POINTS 1024u
#define ADIS_GYRO_LSB 0.05 /* deg/s per LSB, +-300 deg/s range (docs/sensor-facts.md §3.3) */
#define ADIS_GYRO_BITS 14u

struct args {
    const char *csv, *sim, *out, *svg, *gp, *png, *unit;
    unsigned col, per_decade;
    int time_col;
    double rate_hz, scale, seconds, sample_hz, min_clusters, max_rel_err;
    unsigned long long seed;
    int quant, theory, quiet;
};

static void usage(void)
{
    fprintf(
        stderr,
        "usage: allan --csv FILE|- [--col K] [--time-col K | --rate-hz F] [--scale S] [--unit U]\n"
        "       allan --sim adis|separated [--seconds T] [--seed S] [--sample-hz F]\n"
        "             [--no-quant] [--theory]\n"
        "       common: [--per-decade P] [--min-clusters C] [--min-rel-err E]\n"
        "               [--out curve.csv] [--svg plot.svg]\n"
        "               [--gnuplot plot.gp [--png plot.png]] [--quiet]\n");
}

/* Every number through tools/lib/cli: decimal, the whole field, inside the stated range. */
static int parse_value(const char *o, const char *v, struct args *a)
{
    uint32_t u = 0;
    int rc;
    if (strcmp(o, "--col") == 0) {
        rc = cli_parse_u32(o, v, 0, 999, &u);
        a->col = u;
    } else if (strcmp(o, "--time-col") == 0) {
        rc = cli_parse_int(o, v, 0, 999, &a->time_col);
    } else if (strcmp(o, "--rate-hz") == 0) {
        rc = cli_parse_double(o, v, 1e-6, 1e9, 0, &a->rate_hz);
    } else if (strcmp(o, "--scale") == 0) {
        rc = cli_parse_double(o, v, -1e300, 1e300, 0, &a->scale);
        if (rc == INC_OK && a->scale == 0.0) {
            cli_error("%s: '%s' is out of range (accepted: a non-zero decimal number in "
                      "-1e300..1e300)",
                      o, v);
            rc = INC_ERR_RANGE;
        }
    } else if (strcmp(o, "--seconds") == 0) {
        rc = cli_parse_double(o, v, 1e-3, 1e7, 0, &a->seconds);
    } else if (strcmp(o, "--sample-hz") == 0) {
        rc = cli_parse_double(o, v, 1e-3, 1e6, 0, &a->sample_hz);
    } else if (strcmp(o, "--seed") == 0) {
        uint64_t seed = 0;
        rc = cli_parse_u64(o, v, 0, UINT64_MAX, &seed);
        a->seed = seed;
    } else if (strcmp(o, "--per-decade") == 0) {
        rc = cli_parse_u32(o, v, 1, 100, &u);
        a->per_decade = u;
    } else if (strcmp(o, "--min-clusters") == 0) {
        rc = cli_parse_double(o, v, 2.0, 1e12, 0, &a->min_clusters);
    } else if (strcmp(o, "--min-rel-err") == 0) {
        rc = cli_parse_double(o, v, 1e-6, 0.999999, 0, &a->max_rel_err);
    } else {
        cli_error("unknown option %s", o);
        rc = INC_ERR_INVAL;
    }
    return rc;
}

static int parse(int argc, char **argv, struct args *a)
{
    int i;
    memset(a, 0, sizeof(*a));
    a->time_col = -1;
    a->scale = 1.0;
    a->quant = 1;
    a->seed = 1;
    a->unit = "deg/s";
    a->png = "allan.png";
    for (i = 1; i < argc; i++) {
        const char *o = argv[i];
        const char *v;
        if (strcmp(o, "--no-quant") == 0) {
            a->quant = 0;
            continue;
        }
        if (strcmp(o, "--theory") == 0) {
            a->theory = 1;
            continue;
        }
        if (strcmp(o, "--quiet") == 0) {
            a->quiet = 1;
            continue;
        }
        v = cli_value(argc, argv, &i);
        if (v == NULL) {
            return -1;
        }
        if (strcmp(o, "--csv") == 0)
            a->csv = v;
        else if (strcmp(o, "--sim") == 0)
            a->sim = v;
        else if (strcmp(o, "--out") == 0)
            a->out = v;
        else if (strcmp(o, "--svg") == 0)
            a->svg = v;
        else if (strcmp(o, "--gnuplot") == 0)
            a->gp = v;
        else if (strcmp(o, "--png") == 0)
            a->png = v;
        else if (strcmp(o, "--unit") == 0)
            a->unit = v;
        else if (parse_value(o, v, a) != INC_OK)
            return -1;
    }
    if (a->gp != NULL && a->out == NULL) {
        fprintf(stderr, "allan: --gnuplot needs --out (the script plots that CSV)\n");
        return -1;
    }
    if ((a->csv == NULL) == (a->sim == NULL)) {
        fprintf(stderr, "allan: give exactly one of --csv and --sim\n");
        return -1;
    }
    if (a->csv != NULL && a->time_col < 0 && a->rate_hz <= 0.0) {
        fprintf(stderr, "allan: a CSV needs --time-col or --rate-hz\n");
        return -1;
    }
    if (a->theory && a->sim == NULL) {
        fprintf(stderr, "allan: --theory needs --sim (the configured model)\n");
        return -1;
    }
    return 0;
}

/* Simulated record; fills *ax with the configuration used (for --theory). */
static int simulate(const struct args *a, double **y, size_t *n, double *dt,
                    struct sim_noise_axis *ax)
{
    struct sim_noise_cfg cfg;
    struct sim_noise *nm;
    double hz, secs;
    size_t k, cnt;
    int adis = strcmp(a->sim, "adis") == 0;
    if (!adis && strcmp(a->sim, "separated") != 0) {
        fprintf(stderr, "allan: --sim must be adis or separated\n");
        return INC_ERR_INVAL;
    }
    memset(&cfg, 0, sizeof(cfg));
    cfg.seed = a->seed;
    if (adis) {
        sim_noise_adis_gyro_axis(&cfg.ch[0]);
    } else {
        sim_noise_separated_axis(&cfg.ch[0]);
    }
    *ax = cfg.ch[0];
    hz = a->sample_hz > 0.0 ? a->sample_hz : (adis ? 819.2 : 2.0);
    secs = a->seconds > 0.0 ? a->seconds : (adis ? 20000.0 : 1e6);
    cnt = (size_t)(secs * hz + 0.5);
    if (cnt < 4u) {
        fprintf(stderr, "allan: run too short\n");
        return INC_ERR_INVAL;
    }
    nm = malloc(sizeof(*nm));
    *y = malloc(cnt * sizeof(**y));
    if (nm == NULL || *y == NULL || sim_noise_init(nm, &cfg) != INC_OK) {
        free(nm);
        free(*y);
        *y = NULL;
        return INC_ERR_NO_SPACE;
    }
    *dt = 1.0 / hz;
    for (k = 0; k < cnt; k++) {
        double v = sim_noise_step(nm, 0, 0.0, 25.0, *dt);
        if (adis && a->quant) {
            v = (double)sim_quantise(v, ADIS_GYRO_LSB, ADIS_GYRO_BITS, NULL) * ADIS_GYRO_LSB;
        }
        (*y)[k] = v;
    }
    if (adis && a->quant) {
        ax->quantum = ADIS_GYRO_LSB;
    }
    free(nm);
    *n = cnt;
    return INC_OK;
}

/* --out, --svg, --gnuplot through the safe writer (tools/lib/cli): 0, or 3 when one of them
 * could not be written (its target left as it was). */
static int write_outputs(const struct args *a, const struct sim_allan_point *pts, size_t count,
                         const double *theory, const struct sim_allan_readoff *r)
{
    const char *inputs[1];
    struct cli_out o;
    int err = 0;
    inputs[0] = a->csv;
    if (a->out != NULL) {
        if (cli_out_open(&o, "--out", a->out, inputs, 1) != INC_OK) {
            err = 3;
        } else if (sim_allan_write_csv(o.f, pts, count, theory) != INC_OK) {
            fprintf(stderr, "allan: cannot write %s\n", a->out);
            cli_out_discard(&o);
            err = 3;
        } else if (cli_out_close(&o) != INC_OK) {
            err = 3;
        }
    }
    if (a->svg != NULL) {
        if (cli_out_open(&o, "--svg", a->svg, inputs, 1) != INC_OK) {
            err = 3;
        } else if (sim_allan_write_svg(o.f, pts, count, theory, r,
                                       a->sim != NULL ? "Allan deviation (simulated)"
                                                      : "Allan deviation",
                                       a->unit) != INC_OK) {
            fprintf(stderr, "allan: cannot write %s\n", a->svg);
            cli_out_discard(&o);
            err = 3;
        } else if (cli_out_close(&o) != INC_OK) {
            err = 3;
        }
    }
    if (a->gp != NULL) {
        if (cli_out_open(&o, "--gnuplot", a->gp, inputs, 1) != INC_OK) {
            err = 3;
        } else if (sim_allan_write_gnuplot(o.f, a->out, a->png, a->theory != 0, "Allan deviation",
                                           a->unit) != INC_OK) {
            fprintf(stderr, "allan: cannot write %s\n", a->gp);
            cli_out_discard(&o);
            err = 3;
        } else if (cli_out_close(&o) != INC_OK) {
            err = 3;
        }
    }
    return err;
}

int main(int argc, char **argv)
{
    struct args a;
    struct sim_allan_opts opts;
    struct sim_allan_point *pts;
    struct sim_allan_readoff r;
    struct sim_noise_axis ax;
    double *y = NULL, *theory = NULL, dt = 0.0;
    size_t n = 0, count = 0, i;
    int err;
    tool_summary_begin("allan");
    cli_set_program("allan");
    if (parse(argc, argv, &a) != 0) {
        usage();
        return tool_summary_error("usage", 1);
    }
    if (a.csv != NULL) {
        size_t bad = 0;
        FILE *f = strcmp(a.csv, "-") == 0 ? stdin : fopen(a.csv, "r");
        if (f == NULL) {
            fprintf(stderr, "allan: cannot open %s\n", a.csv);
            return tool_summary_error("cannot-open", 2);
        }
        err = sim_allan_read_csv(f, a.col, a.time_col, a.scale, &y, &n, &dt, &bad);
        if (f != stdin) {
            fclose(f);
        }
        if (err != INC_OK) {
            fprintf(stderr, "allan: %s: line %zu: %s\n", a.csv, bad, inc_err_name(err));
            tool_summary_add("line", "%zu", bad);
            return tool_summary_error(inc_err_name(err), 2);
        }
        if (a.time_col < 0) {
            dt = 1.0 / a.rate_hz;
        }
    } else {
        err = simulate(&a, &y, &n, &dt, &ax);
        if (err != INC_OK) {
            return tool_summary_error(inc_err_name(err), err == INC_ERR_INVAL ? 1 : 3);
        }
    }
    pts = malloc(MAX_POINTS * sizeof(*pts));
    if (pts == NULL) {
        free(y);
        return tool_summary_error(inc_err_name(INC_ERR_NO_SPACE), 3);
    }
    opts.per_decade = a.per_decade;
    opts.min_clusters = a.min_clusters;
    err = sim_allan_compute(y, n, dt, &opts, pts, MAX_POINTS, &count);
    free(y);
    if (err != INC_OK || count == 0u) {
        fprintf(stderr, "allan: Allan deviation failed: %s\n", inc_err_name(err));
        free(pts);
        return tool_summary_error(inc_err_name(err != INC_OK ? err : INC_ERR_DEGENERATE), 3);
    }
    if (sim_allan_readoff(pts, count, a.max_rel_err, &r) != INC_OK) {
        fprintf(stderr,
                "allan: no point of the curve is certain to %.3g (relative); record "
                "longer or pass a larger --min-rel-err\n",
                a.max_rel_err > 0.0 ? a.max_rel_err : SIM_ALLAN_MIN_REL_ERR);
        free(pts);
        return tool_summary_error("uncertain", 3);
    }
    if (a.theory) {
        theory = malloc(count * sizeof(*theory));
        if (theory == NULL) {
            free(pts);
            return tool_summary_error(inc_err_name(INC_ERR_NO_SPACE), 3);
        }
        for (i = 0; i < count; i++) {
            theory[i] = sim_noise_adev(&ax, pts[i].tau_s, dt);
        }
    }
    printf("samples           %zu at %.6g s (%.6g s)\n", n, dt, (double)n * dt);
    if (r.arw_valid) {
        printf("ARW (ADEV at 1 s) %.5g %s*sqrt(s)", r.arw, a.unit);
        if (strcmp(a.unit, "deg/s") == 0) {
            printf(" = %.4g deg/sqrt(h)", r.arw * 60.0);
        }
        printf("\n");
    } else {
        printf("ARW (ADEV at 1 s) n/a (1 s outside the curve)\n");
    }
    printf("minimum           %.5g %s at tau = %.5g s%s\n", r.adev_min, a.unit, r.tau_min_s,
           r.min_interior ? "" : " (at the end of the curve: an upper bound)");
    printf("bias instability  %.5g %s (minimum / 0.664)", r.bias_instability, a.unit);
    if (strcmp(a.unit, "deg/s") == 0) {
        printf(" = %.4g deg/h", r.bias_instability * 3600.0);
    }
    printf("\n");
    if (a.theory) {
        printf("model             ADEV(1 s) %.5g, N %.5g, B %.5g, K %.5g; analytic minimum on "
               "the grid %.5g\n",
               sim_noise_adev(&ax, 1.0, dt), ax.white, ax.bias_instability, ax.rrw,
               sim_noise_adev(&ax, r.tau_min_s, dt));
    }
    if (!a.quiet) {
        printf("tau_s,adev,err%s\n", a.theory ? ",theory" : "");
        for (i = 0; i < count; i++) {
            if (a.theory) {
                printf("%.6g,%.6g,%.3g,%.6g\n", pts[i].tau_s, pts[i].adev, pts[i].err, theory[i]);
            } else {
                printf("%.6g,%.6g,%.3g\n", pts[i].tau_s, pts[i].adev, pts[i].err);
            }
        }
    }
    err = write_outputs(&a, pts, count, theory, &r);
    free(theory);
    free(pts);
    tool_summary_add("samples", "%zu", n);
    tool_summary_add("dt_s", "%.6g", dt);
    tool_summary_add("points", "%zu", count);
    tool_summary_add("unit", "%s", a.unit);
    if (r.arw_valid) {
        tool_summary_add("arw", "%.5g", r.arw);
    } else {
        tool_summary_add("arw", "n/a");
    }
    tool_summary_add("adev_min", "%.5g", r.adev_min);
    tool_summary_add("tau_min_s", "%.5g", r.tau_min_s);
    tool_summary_add("min_interior", "%d", r.min_interior ? 1 : 0);
    tool_summary_add("bias_instability", "%.5g", r.bias_instability);
    if (a.theory) {
        tool_summary_add("model_adev_1s", "%.5g", sim_noise_adev(&ax, 1.0, dt));
    }
    if (err != 0) {
        tool_summary_add("error", "io");
    }
    return tool_summary_end(err == 0 ? "ok" : "error", err);
}
