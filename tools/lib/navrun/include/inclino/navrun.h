/*
 * navrun.h - the simulated drives of the navigation mode (module inclino_navrun, layer tool):
 * a drive with truth (sim/vehicle), the SCA3000 and ADIS16255 readings it gives (the vehicle
 * model's sensor errors at the parts' resolution and rates), the GPS receiver's NMEA sentences
 * (sim/gps: correlated noise, latency, outages, jumps), all fed to the application's navigation
 * mode (app_nav: NMEA parser, stillness gate, dead reckoning) every 13 ms, and the figures of
 * docs/navigation.md. Used by tools/nav_demo and tests/nav.
 *
 * Figures of a drive:
 *   gap prediction error: over each 1 s gap between two fixes, the displacement the dead
 *     reckoning integrated (the track without the fix corrections applied during the gap)
 *     against the true displacement, at the end of the gap; the same for holding the last fix
 *     (displacement 0) and straight-line extrapolation of the last fix's speed and course;
 *   absolute error: |track - truth| on every cycle whose position is valid, against its bound;
 *     the same for speed and heading;
 *   no-fix windows (outages): prediction error at the end of the window (from the last fix
 *     before it) for the track, holding and extrapolation, and the heading change error across
 *     it.
 */
#ifndef INCLINO_NAVRUN_H
#define INCLINO_NAVRUN_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

struct navrun_cfg {
    unsigned passes; /* gyro averaging passes 1..4 */
    unsigned avg_w;  /* window per pass */
    uint64_t seed;
    FILE *csv;          /* per-cycle track, truth and bounds (NULL: none) */
    FILE *fix_csv;      /* per-epoch fixes (NULL: none) */
    unsigned csv_every; /* a row every n cycles (>= 1) */
};

struct navrun_stat {
    unsigned n;
    double max, sum2;
};

struct navrun_result {
    char name[32];
    double duration_s;
    struct navrun_stat gap_dr, gap_hold, gap_extrap; /* prediction error at the end of 1 s gaps */
    struct navrun_stat abs_pos, abs_speed, abs_heading; /* on valid cycles */
    unsigned cycles, valid_pos, valid_speed, valid_heading;
    unsigned viol_pos, viol_speed, viol_heading;      /* valid but outside the bound */
    double outage_s;                                  /* longest window without fixes */
    double out_dr_m, out_hold_m, out_extrap_m;        /* prediction error at its end */
    double out_heading_err_deg, out_heading_turn_deg; /* heading change error, true change */
    bool out_pos_valid_end;                           /* position still valid at its end */
    unsigned fixes, fixes_refused, jump_epochs, nmea_errors, offsets;
    double final_speed_err_mps;
};

unsigned navrun_count(void);
const char *navrun_name(unsigned i);
const char *navrun_summary(unsigned i);
void navrun_default_cfg(struct navrun_cfg *c);
/* Run drive i. 0 or a negative error. */
int navrun_drive(unsigned i, const struct navrun_cfg *cfg, struct navrun_result *r);

static inline double navrun_rms(const struct navrun_stat *s)
{
    return s->n ? __builtin_sqrt(s->sum2 / s->n) : 0.0;
}

#ifdef __cplusplus
}
#endif

#endif
