/* navrun.c - simulated drives of the navigation mode (inclino/navrun.h). */
#include "inclino/navrun.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "inclino/app_nav.h"
#include "inclino/error.h"
#include "inclino/sim/gps.h"
#include "inclino/sim/vehicle.h"

#define PI 3.14159265358979323846
#define RATE_HZ 1000.0
#define GYRO_DIV 4u   /* ADIS16255: 250 SPS on the 1 kHz grid (the part: 256 SPS) */
#define ACC_DIV 8u    /* SCA3000-E02 normal mode: 125 Hz */
#define CYCLE_DIV 13u /* 13 ms */
#define SCA_LSB_UG 1000u

/* ---- drives --------------------------------------------------------------------------------- */

static void seg(struct veh_scenario *sc, double dur, double v, double a, double kappa, double kramp,
                double ksine)
{
    struct veh_segment *g;
    if (sc->n_seg >= VEH_MAX_SEGMENTS) return;
    g = &sc->seg[sc->n_seg++];
    memset(g, 0, sizeof *g);
    g->duration_s = dur;
    g->v_target_mps = v;
    g->a_max_mps2 = a;
    g->jerk_mps3 = 4.0;
    g->kappa_1pm = kappa;
    g->kappa_ramp_s = kramp;
    g->kappa_sine = ksine;
    g->road_ramp_s = 1.0;
    g->rough = 0.3;
    g->engine = true;
}

/* A turn of `deg` at speed v on radius r: kappa = 1/r for deg/(kappa v) s (ramps of 1 s in and
 * out are symmetric, so the integral of kappa v keeps the angle). */
static void turn(struct veh_scenario *sc, double v, double r, double deg)
{
    const double k = (deg > 0 ? 1.0 : -1.0) / r;
    const double d = fabs(deg) * PI / 180.0 / (fabs(k) * v);
    seg(sc, d, v, 2.0, k, 1.0, 0.0);
    seg(sc, 1.0, v, 2.0, 0.0, 1.0, 0.0);
}

/* Lane change of `y` metres (left positive) over `dur` seconds at speed v: one period of a sine
 * of curvature, amplitude 2 pi y / L^2, L = v dur. */
static void lane(struct veh_scenario *sc, double v, double y, double dur)
{
    const double L = v * dur;
    seg(sc, dur, v, 2.0, 0.0, 0.5, 2.0 * PI * y / (L * L));
}

struct drive {
    const char *name, *summary;
    void (*build)(struct veh_scenario *sc, struct sim_gps_cfg *g);
};

static void start(struct veh_scenario *sc, const char *name)
{
    memset(sc, 0, sizeof *sc);
    strncpy(sc->name, name, VEH_NAME_MAX - 1u);
    sc->heading_deg = 30.0;
    sc->temp0_c = sc->temp1_c = 25.0;
    sc->temp_tau_s = 1000.0;
    seg(sc, VEH_REST_S + 3.0, 0.0, 2.0, 0.0, 1.0, 0.0); /* at rest: the gate learns the offset */
}

static void add_outage(struct sim_gps_cfg *g, double t0, double dur)
{
    if (g->n_outages < SIM_GPS_MAX_EVENTS) {
        g->outage[g->n_outages].t0_s = t0;
        g->outage[g->n_outages].duration_s = dur;
        g->n_outages++;
    }
}

static double sc_time(const struct veh_scenario *sc)
{
    return veh_scenario_duration(sc);
}

static void d_straight(struct veh_scenario *sc, struct sim_gps_cfg *g)
{
    start(sc, "straight");
    seg(sc, 20.0, 30.0, 2.0, 0.0, 1.0, 0.0);
    seg(sc, 40.0, 30.0, 2.0, 0.0, 1.0, 0.0);
    /* a fix that jumps: 50 m off for 2 s */
    g->jump[0].t0_s = 45.0;
    g->jump[0].duration_s = 2.0;
    g->jump[0].de_m = 30.0;
    g->jump[0].dn_m = -40.0;
    g->n_jumps = 1u;
}

static void d_accel_brake(struct veh_scenario *sc, struct sim_gps_cfg *g)
{
    (void)g;
    start(sc, "accel_brake");
    seg(sc, 12.0, 25.0, 3.0, 0.0, 1.0, 0.0);
    seg(sc, 5.0, 25.0, 3.0, 0.0, 1.0, 0.0);
    seg(sc, 6.0, 9.0, 4.0, 0.0, 1.0, 0.0);
    seg(sc, 8.0, 25.0, 3.0, 0.0, 1.0, 0.0);
    seg(sc, 9.0, 0.0, 4.0, 0.0, 1.0, 0.0);
    seg(sc, 3.0, 0.0, 4.0, 0.0, 1.0, 0.0);
}

static void d_lane_change(struct veh_scenario *sc, struct sim_gps_cfg *g)
{
    (void)g;
    start(sc, "lane_change");
    seg(sc, 18.0, 30.0, 2.0, 0.0, 1.0, 0.0);
    seg(sc, 5.0, 30.0, 2.0, 0.0, 1.0, 0.0);
    lane(sc, 30.0, 3.5, 3.0);
    seg(sc, 6.0, 30.0, 2.0, 0.0, 1.0, 0.0);
    lane(sc, 30.0, -3.5, 3.0);
    seg(sc, 6.0, 30.0, 2.0, 0.0, 1.0, 0.0);
    lane(sc, 30.0, 3.5, 2.5);
    seg(sc, 6.0, 30.0, 2.0, 0.0, 1.0, 0.0);
}

static void small_turns(struct veh_scenario *sc, double sign)
{
    seg(sc, 10.0, 20.0, 2.0, 0.0, 1.0, 0.0);
    seg(sc, 4.0, 20.0, 2.0, 0.0, 1.0, 0.0);
    turn(sc, 20.0, 400.0, 4.0 * sign);
    seg(sc, 3.0, 20.0, 2.0, 0.0, 1.0, 0.0);
    turn(sc, 20.0, 400.0, -4.0 * sign); /* back to the original direction ([KF-SCA3000]) */
    seg(sc, 4.0, 20.0, 2.0, 0.0, 1.0, 0.0);
}

static void d_small_left(struct veh_scenario *sc, struct sim_gps_cfg *g)
{
    (void)g;
    start(sc, "turn_small_left");
    small_turns(sc, 1.0);
}

static void d_small_right(struct veh_scenario *sc, struct sim_gps_cfg *g)
{
    (void)g;
    start(sc, "turn_small_right");
    small_turns(sc, -1.0);
}

static void turn90(struct veh_scenario *sc, struct sim_gps_cfg *g, double sign)
{
    double t0;
    seg(sc, 10.0, 15.0, 2.0, 0.0, 1.0, 0.0);
    seg(sc, 4.0, 15.0, 2.0, 0.0, 1.0, 0.0);
    t0 = sc_time(sc);
    turn(sc, 15.0, 30.0, 90.0 * sign);
    seg(sc, 6.0, 15.0, 2.0, 0.0, 1.0, 0.0);
    /* no fix from 1 s before the turn to 2 s after it */
    add_outage(g, t0 - 1.0, sc_time(sc) - 6.0 + 2.0 - (t0 - 1.0));
}

static void d_turn90_left(struct veh_scenario *sc, struct sim_gps_cfg *g)
{
    start(sc, "turn90_left");
    turn90(sc, g, 1.0);
}

static void d_turn90_right(struct veh_scenario *sc, struct sim_gps_cfg *g)
{
    start(sc, "turn90_right");
    turn90(sc, g, -1.0);
}

static void d_roundabout(struct veh_scenario *sc, struct sim_gps_cfg *g)
{
    (void)g;
    start(sc, "roundabout");
    seg(sc, 8.0, 10.0, 2.0, 0.0, 1.0, 0.0);
    seg(sc, 3.0, 10.0, 2.0, 0.0, 1.0, 0.0);
    turn(sc, 10.0, 20.0, -30.0); /* enter to the right */
    turn(sc, 10.0, 15.0, 270.0); /* round the island */
    turn(sc, 10.0, 20.0, -60.0); /* leave to the right */
    seg(sc, 6.0, 10.0, 2.0, 0.0, 1.0, 0.0);
}

static void d_stop_go(struct veh_scenario *sc, struct sim_gps_cfg *g)
{
    int i;
    (void)g;
    start(sc, "stop_and_go");
    for (i = 0; i < 4; i++) {
        seg(sc, 6.0, 12.0, 2.5, 0.0, 1.0, 0.0);
        seg(sc, 3.0, 12.0, 2.5, 0.0, 1.0, 0.0);
        seg(sc, 6.0, 0.0, 3.0, 0.0, 1.0, 0.0);
        seg(sc, 4.0, 0.0, 3.0, 0.0, 1.0, 0.0); /* standing: the gate learns again */
    }
}

static void d_outage(struct veh_scenario *sc, struct sim_gps_cfg *g)
{
    double t0;
    start(sc, "outage_2min");
    seg(sc, 15.0, 25.0, 2.0, 0.0, 1.0, 0.0);
    seg(sc, 5.0, 25.0, 2.0, 0.0, 1.0, 0.0);
    t0 = sc_time(sc);
    seg(sc, 30.0, 25.0, 2.0, 0.0, 1.0, 0.0);
    turn(sc, 25.0, 500.0, 20.0);
    seg(sc, 30.0, 25.0, 2.0, 0.0, 1.0, 0.0);
    turn(sc, 25.0, 500.0, -20.0);
    seg(sc, 60.0, 25.0, 2.0, 0.0, 1.0, 0.0);
    add_outage(g, t0, 120.0);
}

static const struct drive drives[] = {
    {"straight", "30 m/s straight, a fix that jumps 50 m for 2 s", d_straight},
    {"accel_brake", "0-25 m/s at 3 m/s^2, braking to 9 and to 0 at 4 m/s^2", d_accel_brake},
    {"lane_change", "three 3.5 m lane changes at 30 m/s (3 s, 3 s, 2.5 s)", d_lane_change},
    {"turn_small_left", "4 deg left then 4 deg right back, 20 m/s", d_small_left},
    {"turn_small_right", "4 deg right then 4 deg left back, 20 m/s", d_small_right},
    {"turn90_left", "90 deg left on 30 m at 15 m/s, no fix through the turn", d_turn90_left},
    {"turn90_right", "90 deg right on 30 m at 15 m/s, no fix through the turn", d_turn90_right},
    {"roundabout", "enter right, 270 deg round a 15 m island, leave right, 10 m/s", d_roundabout},
    {"stop_and_go", "four stops from 12 m/s, 4 s standing each", d_stop_go},
    {"outage_2min", "25 m/s with two 20 deg bends, GPS lost for 120 s", d_outage},
};

#define N_DRIVES (sizeof drives / sizeof drives[0])

unsigned navrun_count(void)
{
    return (unsigned)N_DRIVES;
}

const char *navrun_name(unsigned i)
{
    return i < N_DRIVES ? drives[i].name : NULL;
}

const char *navrun_summary(unsigned i)
{
    return i < N_DRIVES ? drives[i].summary : NULL;
}

void navrun_default_cfg(struct navrun_cfg *c)
{
    memset(c, 0, sizeof *c);
    c->passes = 2u;
    c->avg_w = 4u;
    c->seed = 11u;
    c->csv_every = 1u;
}

/* ---- the run -------------------------------------------------------------------------------- */

static void stat_add(struct navrun_stat *s, double v)
{
    v = fabs(v);
    s->n++;
    s->sum2 += v * v;
    if (v > s->max) s->max = v;
}

static double wrap180(double d)
{
    d = fmod(d + 180.0, 360.0);
    if (d < 0) d += 360.0;
    return d - 180.0;
}

#define Q16(x) ((int32_t)llround((x)*65536.0))

struct pending {
    char text[512];
    size_t len;
    struct sim_gps_epoch ep;
    bool used;
};

/* The state at the first cycle after each whole second (an epoch time). */
struct snap {
    long sec;          /* the epoch (-1: none) */
    bool accepted;     /* the fix of that epoch was used */
    double t;          /* cycle time */
    double dr_e, dr_n; /* pure dead reckoning (track - corrections) */
    double tr_e, tr_n; /* truth */
    double spd, crs;   /* the fix's speed and course (extrapolation) */
    double h, th;      /* unwrapped heading, truth */
    bool pos_valid, heading_valid;
};
#define N_SNAP 8

int navrun_drive(unsigned i, const struct navrun_cfg *cfg, struct navrun_result *r)
{
    static struct veh_sim vs;
    static struct veh_scenario sc;
    static struct app_nav an;
    static struct pending q[4];
    struct veh_config vc;
    struct sim_gps_cfg gc;
    struct sim_gps gps;
    struct app_nav_cfg ac;
    struct veh_sample smp;
    struct nav_out out;
    static struct snap sn[N_SNAP];
    struct snap last_acc;
    double prev_pos[2] = {0, 0}, t_next_epoch = 1.0;
    double h_unwrap = 0, h_prev = 0, th_unwrap = 0, th_prev = 0;
    /* cppcheck-suppress unreadVariable ; set on every cycle before the snapshots read them */
    double dr_e = 0, dr_n = 0, gsum = 0, asum[3] = {0, 0, 0};
    bool h_init = false;
    uint64_t k, n;
    unsigned qi, cycle = 0;
    int rc;
    fx_q16_t acc[3] = {0, 0, FX_Q16_ONE};
    if (i >= N_DRIVES || cfg == NULL || r == NULL) return INC_ERR_INVAL;
    memset(r, 0, sizeof *r);
    strncpy(r->name, drives[i].name, sizeof r->name - 1u);
    sim_gps_default_cfg(&gc, cfg->seed * 7919u + i);
    drives[i].build(&sc, &gc);
    veh_config_default(&vc);
    vc.rate_hz = RATE_HZ;
    vc.seed = cfg->seed * 131u + i;
    vc.sensor_errors = true;
    vc.gyro_range_dps = 80.0;
    vc.gyro_lsb_dps = 80.0 / 4368.0; /* ADIS16255 at +-80 deg/s */
    vc.accel_range_g = 4.0;
    vc.accel_lsb_g = 0.001; /* SCA3000-E02 */
    if ((rc = veh_sim_init(&vs, &sc, &vc)) != INC_OK) return rc;
    if ((rc = sim_gps_init(&gps, &gc)) != INC_OK) return rc;
    ac = app_nav_default_cfg(SCA_LSB_UG);
    ac.nav.avg_passes = (uint8_t)cfg->passes;
    ac.nav.avg_w = (uint8_t)cfg->avg_w;
    ac.gps_latency_ns = (uint64_t)llround(gc.latency_s * 1e9);
    if ((rc = app_nav_init(&an, &ac)) != INC_OK) return rc;
    memset(q, 0, sizeof q);
    for (qi = 0; qi < N_SNAP; qi++)
        sn[qi].sec = -1;
    memset(&last_acc, 0, sizeof last_acc);
    last_acc.sec = -1;
    n = veh_sim_samples(&vs);
    r->duration_s = (double)n / RATE_HZ;
    if (cfg->csv != NULL)
        fprintf(cfg->csv, "t_s,true_e_m,true_n_m,nav_e_m,nav_n_m,pos_bound_m,pos_valid,speed_mps,"
                          "true_speed_mps,speed_bound_mps,heading_deg,true_heading_deg,"
                          "heading_bound_deg,k\n");
    if (cfg->fix_csv != NULL)
        fprintf(cfg->fix_csv, "t_valid_s,t_deliver_s,fix,jump,e_m,n_m,err_e_m,err_n_m,speed_mps,"
                              "course_deg\n");
    for (k = 0; k < n; k++) {
        double t, vel[2];
        if ((rc = veh_sim_next(&vs, &smp)) < 0) return rc;
        t = smp.t_s;
        vel[0] = (smp.pos_enu_m[0] - prev_pos[0]) * RATE_HZ;
        vel[1] = (smp.pos_enu_m[1] - prev_pos[1]) * RATE_HZ;
        if (k == 0) {
            vel[0] = vel[1] = 0.0;
        }
        prev_pos[0] = smp.pos_enu_m[0];
        prev_pos[1] = smp.pos_enu_m[1];
        /* truth heading, unwrapped */
        if (!h_init) {
            th_prev = smp.yaw_deg;
            th_unwrap = smp.yaw_deg;
        } else {
            th_unwrap += wrap180(smp.yaw_deg - th_prev);
            th_prev = smp.yaw_deg;
        }
        /* GPS epochs: sentences written at t, delivered after the latency */
        if (t >= t_next_epoch - 1e-9) {
            for (qi = 0; qi < 4u; qi++) {
                if (!q[qi].used) {
                    int len = sim_gps_epoch(&gps, t, smp.pos_enu_m, vel, q[qi].text,
                                            sizeof q[qi].text, &q[qi].ep);
                    if (len > 0) {
                        q[qi].len = (size_t)len;
                        q[qi].used = true;
                        if (cfg->fix_csv != NULL)
                            fprintf(cfg->fix_csv, "%.3f,%.3f,%d,%d,%.3f,%.3f,%.3f,%.3f,%.3f,%.2f\n",
                                    q[qi].ep.t_valid_s, q[qi].ep.t_deliver_s, q[qi].ep.fix,
                                    q[qi].ep.jump, q[qi].ep.e_m, q[qi].ep.n_m, q[qi].ep.err_e_m,
                                    q[qi].ep.err_n_m, q[qi].ep.speed_mps, q[qi].ep.course_deg);
                        if (q[qi].ep.jump) r->jump_epochs++;
                    }
                    break;
                }
            }
            t_next_epoch += 1.0;
        }
        for (qi = 0; qi < 4u; qi++) {
            if (q[qi].used && t >= q[qi].ep.t_deliver_s) {
                const uint64_t t_ns = (uint64_t)llround(t * 1e9);
                const uint32_t before = an.stats.fixes;
                /* in two reads, cut at a point that moves from epoch to epoch */
                const size_t cut = (size_t)(q[qi].ep.t_valid_s * 37.0) % (q[qi].len + 1u);
                (void)app_nav_uart(&an, q[qi].text, cut, t_ns);
                (void)app_nav_uart(&an, q[qi].text + cut, q[qi].len - cut, t_ns);
                if (an.stats.fixes != before && q[qi].ep.fix) {
                    const long sec = lround(q[qi].ep.t_valid_s);
                    struct snap *p = &sn[sec % N_SNAP];
                    if (p->sec == sec) {
                        p->accepted = true;
                        p->spd = q[qi].ep.speed_mps;
                        p->crs = q[qi].ep.course_deg;
                        if (last_acc.sec >= 0 && sec - last_acc.sec >= 2 &&
                            (double)(sec - last_acc.sec) > r->outage_s) {
                            /* a window without fixes ends here */
                            const double de = p->tr_e - last_acc.tr_e, dn = p->tr_n - last_acc.tr_n;
                            const double dt = p->t - last_acc.t, c = last_acc.crs * PI / 180.0;
                            r->outage_s = (double)(sec - last_acc.sec);
                            r->out_dr_m = hypot(p->dr_e - last_acc.dr_e - de,
                                                p->dr_n - last_acc.dr_n - dn);
                            r->out_hold_m = hypot(de, dn);
                            r->out_extrap_m = hypot(last_acc.spd * dt * sin(c) - de,
                                                    last_acc.spd * dt * cos(c) - dn);
                            r->out_heading_turn_deg = p->th - last_acc.th;
                            r->out_heading_err_deg = (p->h - last_acc.h) - (p->th - last_acc.th);
                            r->out_pos_valid_end = p->pos_valid;
                        }
                        last_acc = *p;
                    }
                }
                q[qi].used = false;
            }
        }
        /* sensors: each part's own filter averages its internal samples over its output
         * period (ADIS16255 SENS_AVG, SCA3000 low-pass), then the output is read */
        gsum += smp.gyr_dps[2];
        asum[0] += smp.acc_g[0];
        asum[1] += smp.acc_g[1];
        asum[2] += smp.acc_g[2];
        if (k % GYRO_DIV == GYRO_DIV - 1u) {
            const double lsb = 80.0 / 4368.0;
            (void)app_nav_gyro(&an, Q16(lsb * llround(gsum / GYRO_DIV / lsb)), 4000000u);
            gsum = 0.0;
        }
        if (k % ACC_DIV == ACC_DIV - 1u) {
            unsigned j;
            for (j = 0; j < 3u; j++) {
                acc[j] = Q16(0.001 * llround(asum[j] / ACC_DIV / 0.001));
                asum[j] = 0.0;
            }
            (void)app_nav_accel(&an, acc);
            if (getenv("NAVRUN_DEBUG") != NULL && k < 12000u && still_last(&an.still) != NULL &&
                an.stats.accel_samples % 125u == 0u) {
                const struct still_window *w = still_last(&an.still);
                fprintf(stderr, "t=%.2f why=%02x gvar=%llu avar=%llu,%llu,%llu gmean=%d state=%d\n",
                        t, w->why, (unsigned long long)w->gyro_var[2],
                        (unsigned long long)w->accel_var[0], (unsigned long long)w->accel_var[1],
                        (unsigned long long)w->accel_var[2], w->gyro_mean[2], (int)an.still.state);
            }
        }
        if (k % CYCLE_DIV == CYCLE_DIV - 1u) {
            double ne, nn, hd;
            (void)app_nav_cycle(&an, 13000000u, &out);
            cycle++;
            r->cycles++;
            ne = out.east_mm / 1000.0;
            nn = out.north_mm / 1000.0;
            dr_e = (double)(an.nav.e_q32 - an.nav.corr_e_q32) / 4294967296.0;
            dr_n = (double)(an.nav.n_q32 - an.nav.corr_n_q32) / 4294967296.0;
            hd = out.heading_deg / 65536.0;
            if (!h_init) {
                h_prev = hd;
                h_unwrap = hd;
                h_init = true;
            } else {
                h_unwrap += wrap180(hd - h_prev);
                h_prev = hd;
            }
            /* the truth frame: the nav's origin is the first fix, which carried GPS error;
             * the truth is compared in the nav frame through the receiver's projection of the
             * reference: truth_local - ref_local */
            {
                double ref_e = 0, ref_n = 0, te, tn;
                if (an.nav.have_ref) {
                    ref_e = (an.nav.ref_lon_e7 / 1e7 - gc.lon0_deg) * gps.m_per_deg_e;
                    ref_n = (an.nav.ref_lat_e7 / 1e7 - gc.lat0_deg) * gps.m_per_deg_n;
                }
                te = smp.pos_enu_m[0] - ref_e;
                tn = smp.pos_enu_m[1] - ref_n;
                if (out.pos_valid) {
                    const double pe = hypot(ne - te, nn - tn);
                    r->valid_pos++;
                    stat_add(&r->abs_pos, pe);
                    if (pe > out.pos_bound_mm / 1000.0) r->viol_pos++;
                }
                if (out.speed_valid) {
                    const double err = out.speed_mps / 65536.0 - smp.true_speed_mps;
                    r->valid_speed++;
                    stat_add(&r->abs_speed, err);
                    if (fabs(err) > out.speed_bound_mps / 65536.0) r->viol_speed++;
                }
                if (out.heading_valid) {
                    const double err = wrap180(hd - smp.yaw_deg);
                    r->valid_heading++;
                    stat_add(&r->abs_heading, err);
                    if (fabs(err) > out.heading_bound_deg / 65536.0) r->viol_heading++;
                }
                if (cfg->csv != NULL && cycle % (cfg->csv_every ? cfg->csv_every : 1u) == 0u)
                    fprintf(cfg->csv,
                            "%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%d,%.4f,%.4f,%.4f,%.3f,%.3f,%.3f,%.4f\n",
                            t, te, tn, ne, nn, out.pos_bound_mm / 1000.0, out.pos_valid ? 1 : 0,
                            out.speed_mps / 65536.0, smp.true_speed_mps,
                            out.speed_bound_mps / 65536.0, hd, fmod(smp.yaw_deg + 360.0, 360.0),
                            out.heading_bound_deg / 65536.0, out.k / 1073741824.0);
                /* the state at the first cycle after each whole second */
                if (fmod(t + 1e-9, 1.0) < 0.013 - 1e-9 && t > 0.5) {
                    const long sec = lround(floor(t + 1e-9));
                    struct snap *p = &sn[sec % N_SNAP], *g = &sn[(sec + N_SNAP - 1) % N_SNAP];
                    /* the gap that ends here: it started at the previous second's fix */
                    if (g->sec == sec - 1 && g->accepted && g->heading_valid) {
                        const double de = smp.pos_enu_m[0] - g->tr_e,
                                     dn = smp.pos_enu_m[1] - g->tr_n;
                        const double dt = t - g->t, c = g->crs * PI / 180.0;
                        stat_add(&r->gap_dr, hypot(dr_e - g->dr_e - de, dr_n - g->dr_n - dn));
                        if (getenv("NAVRUN_GAPS") != NULL)
                            fprintf(stderr, "gap %ld: dr %.3f hold %.2f (%.3f %.3f vs %.3f %.3f)\n",
                                    sec, hypot(dr_e - g->dr_e - de, dr_n - g->dr_n - dn),
                                    hypot(de, dn), dr_e - g->dr_e, dr_n - g->dr_n, de, dn);
                        stat_add(&r->gap_hold, hypot(de, dn));
                        stat_add(&r->gap_extrap,
                                 hypot(g->spd * dt * sin(c) - de, g->spd * dt * cos(c) - dn));
                    }
                    p->sec = sec;
                    p->accepted = false;
                    p->t = t;
                    p->dr_e = dr_e;
                    p->dr_n = dr_n;
                    p->tr_e = smp.pos_enu_m[0];
                    p->tr_n = smp.pos_enu_m[1];
                    p->h = h_unwrap;
                    p->th = th_unwrap;
                    p->pos_valid = out.pos_valid;
                    p->heading_valid = out.heading_valid;
                }
            }
        }
    }
    r->fixes = an.stats.fixes;
    r->fixes_refused = an.nav.fixes_refused;
    r->nmea_errors = an.stats.nmea_errors;
    r->offsets = an.stats.offsets;
    r->final_speed_err_mps = out.speed_mps / 65536.0 - smp.true_speed_mps;
    return INC_OK;
}
