/* gps.c - simulated GPS receiver writing NMEA 0183 (inclino/sim/gps.h). */
#include "inclino/sim/gps.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "inclino/error.h"

#define PI 3.14159265358979323846
#define WGS84_A 6378137.0
#define WGS84_E2 0.00669437999014

void sim_gps_default_cfg(struct sim_gps_cfg *c, uint64_t seed)
{
    memset(c, 0, sizeof *c);
    c->lat0_deg = 48.1;
    c->lon0_deg = 11.5;
    c->utc0_s = 12.0 * 3600.0;
    c->pos_sigma_m = 2.5;
    c->pos_tau_s = 60.0;
    c->pos_white_m = 0.3;
    c->vel_sigma_mps = 0.05;
    c->latency_s = 0.080;
    c->latency_jitter_s = 0.010;
    c->seed = seed;
    c->talker[0] = 'G';
    c->talker[1] = 'N';
}

int sim_gps_init(struct sim_gps *g, const struct sim_gps_cfg *cfg)
{
    double s, w;
    if (g == NULL || cfg == NULL) return INC_ERR_NULL;
    if (cfg->n_outages > SIM_GPS_MAX_EVENTS || cfg->n_jumps > SIM_GPS_MAX_EVENTS ||
        !(cfg->pos_tau_s > 0.0) || fabs(cfg->lat0_deg) > 80.0)
        return INC_ERR_INVAL;
    memset(g, 0, sizeof *g);
    g->cfg = *cfg;
    sim_rng_seed(&g->rng, cfg->seed ^ 0x6e6d6561ull);
    s = sin(cfg->lat0_deg * PI / 180.0);
    w = 1.0 - WGS84_E2 * s * s;
    g->m_per_deg_n = WGS84_A * (1.0 - WGS84_E2) / (w * sqrt(w)) * PI / 180.0;
    g->m_per_deg_e = WGS84_A * cos(cfg->lat0_deg * PI / 180.0) / sqrt(w) * PI / 180.0;
    g->gm[0] = cfg->pos_sigma_m * sim_rng_gauss(&g->rng);
    g->gm[1] = cfg->pos_sigma_m * sim_rng_gauss(&g->rng);
    return INC_OK;
}

void sim_gps_to_latlon(const struct sim_gps *g, double e_m, double n_m, double *lat_deg,
                       double *lon_deg)
{
    *lat_deg = g->cfg.lat0_deg + n_m / g->m_per_deg_n;
    *lon_deg = g->cfg.lon0_deg + e_m / g->m_per_deg_e;
}

static int in_window(const struct sim_gps_window *w, unsigned n, double t, unsigned *which)
{
    unsigned i;
    for (i = 0; i < n; i++) {
        if (t >= w[i].t0_s && t < w[i].t0_s + w[i].duration_s) {
            if (which != NULL) *which = i;
            return 1;
        }
    }
    return 0;
}

static int put(char *out, size_t cap, size_t *n, const char *body)
{
    unsigned x = 0;
    size_t i, len = strlen(body);
    int k;
    for (i = 0; i < len; i++)
        x ^= (unsigned char)body[i];
    k = snprintf(out + *n, cap - *n, "$%s*%02X\r\n", body, x);
    if (k < 0 || (size_t)k >= cap - *n) return INC_ERR_NO_SPACE;
    *n += (size_t)k;
    return INC_OK;
}

/* ddmm.mmmmmmm / dddmm.mmmmmmm with 7 decimals of minutes. */
static void fmt_angle(char *buf, size_t cap, double deg, int deg_digits, char pos, char neg)
{
    const char h = deg < 0.0 ? neg : pos;
    double a = fabs(deg);
    long long units = llround(a * 60.0e7); /* 1e-7 minutes */
    long long d = units / 600000000ll, m = units % 600000000ll;
    snprintf(buf, cap, "%0*lld%02lld.%07lld,%c", deg_digits, d, m / 10000000ll, m % 10000000ll, h);
}

int sim_gps_epoch(struct sim_gps *g, double t_s, const double pos_en[2], const double vel_en[2],
                  char *out, size_t cap, struct sim_gps_epoch *ep)
{
    char body[200], tm[48], lat[48], lon[48];
    size_t n = 0;
    double dt, e, nn, ve, vn, spd, crs, la, lo, tod;
    int fix, jump = 0, rc = INC_OK;
    unsigned which = 0;
    long long cs;
    if (g == NULL || pos_en == NULL || vel_en == NULL || out == NULL) return INC_ERR_NULL;
    if (cap == 0u) return INC_ERR_NO_SPACE;
    out[0] = '\0';
    /* Gauss-Markov step over the time since the previous epoch */
    dt = g->started ? t_s - g->t_last : 0.0;
    if (dt > 0.0) {
        const double phi = exp(-dt / g->cfg.pos_tau_s);
        g->gm[0] = phi * g->gm[0] +
                   sqrt(1.0 - phi * phi) * g->cfg.pos_sigma_m * sim_rng_gauss(&g->rng);
        g->gm[1] = phi * g->gm[1] +
                   sqrt(1.0 - phi * phi) * g->cfg.pos_sigma_m * sim_rng_gauss(&g->rng);
    }
    g->started = 1;
    g->t_last = t_s;
    e = pos_en[0] + g->gm[0] + g->cfg.pos_white_m * sim_rng_gauss(&g->rng);
    nn = pos_en[1] + g->gm[1] + g->cfg.pos_white_m * sim_rng_gauss(&g->rng);
    if (in_window(g->cfg.jump, g->cfg.n_jumps, t_s, &which)) {
        e += g->cfg.jump[which].de_m;
        nn += g->cfg.jump[which].dn_m;
        jump = 1;
    }
    ve = vel_en[0] + g->cfg.vel_sigma_mps * sim_rng_gauss(&g->rng);
    vn = vel_en[1] + g->cfg.vel_sigma_mps * sim_rng_gauss(&g->rng);
    spd = sqrt(ve * ve + vn * vn);
    crs = atan2(ve, vn) * 180.0 / PI; /* compass: 0 north, clockwise */
    if (crs < 0.0) crs += 360.0;
    fix = !in_window(g->cfg.outage, g->cfg.n_outages, t_s, NULL);
    tod = fmod(g->cfg.utc0_s + t_s, 86400.0);
    cs = llround(tod * 100.0);
    snprintf(tm, sizeof tm, "%02lld%02lld%02lld.%02lld", cs / 360000ll, cs / 6000ll % 60ll,
             cs / 100ll % 60ll, cs % 100ll);
    sim_gps_to_latlon(g, e, nn, &la, &lo);
    fmt_angle(lat, sizeof lat, la, 2, 'N', 'S');
    fmt_angle(lon, sizeof lon, lo, 3, 'E', 'W');
    if (fix) {
        snprintf(body, sizeof body, "%sRMC,%s,A,%s,%s,%.3f,%.2f,010124,,,A", g->cfg.talker, tm, lat,
                 lon, spd / 0.514444444, crs >= 359.995 ? 0.0 : crs);
        rc |= put(out, cap, &n, body);
        snprintf(body, sizeof body, "%sGGA,%s,%s,%s,1,09,0.9,520.0,M,47.0,M,,", g->cfg.talker, tm,
                 lat, lon);
        rc |= put(out, cap, &n, body);
        snprintf(body, sizeof body, "%sVTG,%.2f,T,,M,%.3f,N,%.3f,K,A", g->cfg.talker,
                 crs >= 359.995 ? 0.0 : crs, spd / 0.514444444, spd * 3.6);
        rc |= put(out, cap, &n, body);
    } else {
        snprintf(body, sizeof body, "%sRMC,%s,V,,,,,,,010124,,,N", g->cfg.talker, tm);
        rc |= put(out, cap, &n, body);
        snprintf(body, sizeof body, "%sGGA,%s,,,,,0,00,99.9,,,,,,", g->cfg.talker, tm);
        rc |= put(out, cap, &n, body);
        snprintf(body, sizeof body, "%sVTG,,T,,M,,N,,K,N", g->cfg.talker);
        rc |= put(out, cap, &n, body);
    }
    if (ep != NULL) {
        ep->t_valid_s = t_s;
        ep->t_deliver_s = t_s + g->cfg.latency_s +
                          g->cfg.latency_jitter_s * sim_rng_uniform(&g->rng);
        ep->fix = fix;
        ep->jump = jump;
        ep->e_m = e;
        ep->n_m = nn;
        ep->err_e_m = e - pos_en[0];
        ep->err_n_m = nn - pos_en[1];
        ep->speed_mps = spd;
        ep->course_deg = crs;
    } else {
        (void)sim_rng_uniform(&g->rng);
    }
    return rc != INC_OK ? INC_ERR_NO_SPACE : (int)n;
}
