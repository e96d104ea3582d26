/*
 * nav_demo - the navigation mode on the simulated drives (docs/navigation.md): for each drive
 * the track error at the end of the 1 s gaps between fixes (dead reckoning against holding the
 * last fix and straight-line extrapolation), the absolute position, speed and heading errors of
 * the valid outputs against their bounds, and the longest window without fixes; then one
 * summary line.
 *
 *   nav_demo [--drive NAME] [--passes 1..4] [--seed N] [--csv FILE] [--fixes FILE]
 *            [--kcurve FILE]
 * --csv/--fixes write the track/truth and the fixes of the (one) drive given by --drive;
 * --kcurve writes the blend factor of [KF-SCA3000] (0..3 rounds of K = K + (1 - K) K against
 * A, Q = 20) computed by the firmware's gpsb_factor.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "inclino/gpsblend.h"
#include "inclino/navrun.h"
#include "inclino/tool_summary.h"

static int kcurve(const char *path)
{
    FILE *f = fopen(path, "w");
    int a;
    if (f == NULL) return 1;
    fprintf(f, "A,K0,K1,K2,K3\n");
    /* A and Q in the same unit (counts); the firmware takes Q16: scale both by 65536 / 1000 */
    for (a = 0; a <= 1000; a++) {
        const double A = a / 10.0;
        const fx_q16_t aq = (fx_q16_t)(A * 65.536 + 0.5), qq = (fx_q16_t)(20.0 * 65.536 + 0.5);
        unsigned r;
        fprintf(f, "%.1f", A);
        for (r = 0; r <= 3u; r++)
            fprintf(f, ",%.6f", gpsb_factor(aq, qq, r) / 1073741824.0);
        fprintf(f, "\n");
    }
    fclose(f);
    return 0;
}

int main(int argc, char **argv)
{
    struct navrun_cfg cfg;
    const char *only = NULL, *csv = NULL, *fixes = NULL, *kc = NULL;
    unsigned i, ran = 0, viol = 0;
    double lane_gap = -1, lane_hold = -1, t90 = 0, worst_gap = 0, out_dr = -1, out_hold = -1;
    int a;
    navrun_default_cfg(&cfg);
    for (a = 1; a < argc; a++) {
        if (strcmp(argv[a], "--drive") == 0 && a + 1 < argc)
            only = argv[++a];
        else if (strcmp(argv[a], "--passes") == 0 && a + 1 < argc)
            cfg.passes = (unsigned)atoi(argv[++a]);
        else if (strcmp(argv[a], "--seed") == 0 && a + 1 < argc)
            cfg.seed = (uint64_t)strtoull(argv[++a], NULL, 10);
        else if (strcmp(argv[a], "--csv") == 0 && a + 1 < argc)
            csv = argv[++a];
        else if (strcmp(argv[a], "--fixes") == 0 && a + 1 < argc)
            fixes = argv[++a];
        else if (strcmp(argv[a], "--kcurve") == 0 && a + 1 < argc)
            kc = argv[++a];
        else {
            fprintf(stderr,
                    "usage: nav_demo [--drive NAME] [--passes 1..4] [--seed N] [--csv FILE] "
                    "[--fixes FILE] [--kcurve FILE]\n");
            tool_summary_begin("nav_demo");
            return tool_summary_error("usage", 2);
        }
    }
    tool_summary_begin("nav_demo");
    if (cfg.passes < 1u || cfg.passes > 4u) return tool_summary_error("passes", 2);
    if (kc != NULL && kcurve(kc) != 0) return tool_summary_error("kcurve_file", 1);
    if ((csv != NULL || fixes != NULL) && only == NULL)
        return tool_summary_error("csv_needs_drive", 2);
    if (csv != NULL && (cfg.csv = fopen(csv, "w")) == NULL)
        return tool_summary_error("csv_file", 1);
    if (fixes != NULL && (cfg.fix_csv = fopen(fixes, "w")) == NULL)
        return tool_summary_error("fixes_file", 1);
    printf(
        "| drive | s | gaps | gap DR max / rms m | hold max m | extrap max m | pos err max m "
        "(valid %%) | speed err max m/s | heading err max deg | no-fix s | DR / hold / extrap "
        "at its end m | heading change err deg (turn) | fixes used / refused | offsets | bound violations |\n");
    printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (i = 0; i < navrun_count(); i++) {
        struct navrun_result r;
        int rc;
        if (only != NULL && strcmp(only, navrun_name(i)) != 0) continue;
        rc = navrun_drive(i, &cfg, &r);
        if (rc != 0) {
            fprintf(stderr, "nav_demo: drive %s: error %d\n", navrun_name(i), rc);
            return tool_summary_error("drive", 1);
        }
        ran++;
        viol += r.viol_pos + r.viol_speed + r.viol_heading;
        printf("| %s | %.0f | %u | %.3f / %.3f | %.1f | %.2f | %.2f (%.0f) | %.3f | %.2f | %.0f | "
               "%.2f / %.1f / %.2f | %.2f (%.1f) | %u / %u | %u | %u/%u/%u |\n",
               r.name, r.duration_s, r.gap_dr.n, r.gap_dr.max, navrun_rms(&r.gap_dr),
               r.gap_hold.max, r.gap_extrap.max, r.abs_pos.max,
               100.0 * r.valid_pos / (r.cycles ? r.cycles : 1u), r.abs_speed.max, r.abs_heading.max,
               r.outage_s, r.out_dr_m, r.out_hold_m, r.out_extrap_m, r.out_heading_err_deg,
               r.out_heading_turn_deg, r.fixes, r.fixes_refused, r.offsets, r.viol_pos,
               r.viol_speed, r.viol_heading);
        if (r.gap_dr.max > worst_gap) worst_gap = r.gap_dr.max;
        if (strcmp(r.name, "lane_change") == 0) {
            lane_gap = r.gap_dr.max;
            lane_hold = r.gap_hold.max;
        }
        if (strncmp(r.name, "turn90", 6) == 0 && __builtin_fabs(r.out_heading_err_deg) > t90)
            t90 = __builtin_fabs(r.out_heading_err_deg);
        if (strcmp(r.name, "outage_2min") == 0) {
            out_dr = r.out_dr_m;
            out_hold = r.out_hold_m;
        }
    }
    if (cfg.csv != NULL) fclose(cfg.csv);
    if (cfg.fix_csv != NULL) fclose(cfg.fix_csv);
    if (ran == 0u) return tool_summary_error("no_drive", 2);
    tool_summary_add("drives", "%u", ran);
    tool_summary_add("passes", "%u", cfg.passes);
    if (lane_gap >= 0) {
        tool_summary_add("lane_gap_max_m", "%.3f", lane_gap);
        tool_summary_add("lane_hold_max_m", "%.2f", lane_hold);
    }
    if (t90 > 0) tool_summary_add("turn90_heading_err_deg", "%.3f", t90);
    if (out_dr >= 0) {
        tool_summary_add("outage_dr_m", "%.1f", out_dr);
        tool_summary_add("outage_hold_m", "%.0f", out_hold);
    }
    tool_summary_add("gap_max_m", "%.3f", worst_gap);
    tool_summary_add("bound_violations", "%u", viol);
    return tool_summary_end("ok", 0);
}
