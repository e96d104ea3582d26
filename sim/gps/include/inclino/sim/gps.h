/*
 * sim/gps.h - a simulated GPS receiver (module inclino_sim_gps, prefix sim_gps_): from the truth
 * of a drive it writes the NMEA 0183 sentences a receiver would send (RMC, GGA, VTG), with the
 * errors a real one has. docs/navigation.md, "Simulated receiver".
 *
 * Errors (all from one seeded sim_rng: the same seed gives the same bytes on every host):
 *   - position: a first-order Gauss-Markov error per axis (sigma pos_sigma_m, correlation time
 *     pos_tau_s: the slowly wandering error of a real receiver, several metres) plus white noise
 *     (pos_white_m);
 *   - velocity: white noise per axis (vel_sigma_mps) on the true velocity; speed and course are
 *     computed from it (so the course is noisy at low speed, as from a receiver's Doppler);
 *   - latency: the sentences of the epoch valid at t are delivered at t + latency_s + a uniform
 *     jitter in [0, latency_jitter_s);
 *   - outages: in [t0, t0 + duration) the receiver reports no fix (RMC status V and empty
 *     fields, GGA quality 0, VTG empty, mode N);
 *   - jumps: in [t0, t0 + duration) the position is offset by (de, dn) metres (multipath or a
 *     bad re-acquisition), speed and course unaffected.
 * Coordinates: local east/north metres about (lat0, lon0) projected with the WGS-84 radii of
 * curvature at lat0 (the same projection as firmware/signal/nav, in double precision). Times
 * are printed as UTC hhmmss.ss from utc0_s of the day.
 */
#ifndef INCLINO_SIM_GPS_H
#define INCLINO_SIM_GPS_H

#include <stddef.h>
#include <stdint.h>

#include "inclino/sim/inertial.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SIM_GPS_MAX_EVENTS 8u

struct sim_gps_window {
    double t0_s, duration_s;
    double de_m, dn_m; /* jumps only */
};

struct sim_gps_cfg {
    double lat0_deg, lon0_deg;
    double utc0_s; /* time of day of t = 0 */
    double pos_sigma_m, pos_tau_s, pos_white_m;
    double vel_sigma_mps;
    double latency_s, latency_jitter_s;
    uint64_t seed;
    char talker[3]; /* "GP", "GN", ... */
    unsigned n_outages, n_jumps;
    struct sim_gps_window outage[SIM_GPS_MAX_EVENTS];
    struct sim_gps_window jump[SIM_GPS_MAX_EVENTS];
};

/* Defaults: 48.1 N 11.5 E, 2.5 m / 60 s Gauss-Markov + 0.3 m white, 0.05 m/s, 80 ms + 0-10 ms,
 * talker GN, no outage, no jump. */
void sim_gps_default_cfg(struct sim_gps_cfg *c, uint64_t seed);

struct sim_gps {
    struct sim_gps_cfg cfg;
    struct sim_rng rng;
    double gm[2];  /* Gauss-Markov state, m */
    double t_last; /* time of the last epoch (for the Gauss-Markov step) */
    int started;
    double m_per_deg_n, m_per_deg_e;
};

/* What one epoch reported, for the tools' CSV and the tests (in local metres). */
struct sim_gps_epoch {
    double t_valid_s, t_deliver_s;
    int fix;         /* 1: a fix was reported */
    int jump;        /* 1: inside a jump window */
    double e_m, n_m; /* reported position (local) */
    double err_e_m, err_n_m;
    double speed_mps, course_deg; /* reported (course: compass) */
};

int sim_gps_init(struct sim_gps *g, const struct sim_gps_cfg *cfg);

/*
 * The epoch valid at t_s with the true local position (pos_en, m) and velocity (vel_en, m/s).
 * Writes RMC, GGA and VTG, each "$...*hh\r\n", to out (cap bytes, NUL-terminated); returns the
 * number of bytes, or a negative error (INC_ERR_NO_SPACE, INC_ERR_NULL). *ep may be NULL.
 */
int sim_gps_epoch(struct sim_gps *g, double t_s, const double pos_en[2], const double vel_en[2],
                  char *out, size_t cap, struct sim_gps_epoch *ep);

/* Local metres <-> lat/lon degrees with the receiver's projection. */
void sim_gps_to_latlon(const struct sim_gps *g, double e_m, double n_m, double *lat_deg,
                       double *lon_deg);

#ifdef __cplusplus
}
#endif

#endif
