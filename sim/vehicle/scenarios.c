/*
 * scenarios.c - the named scenario presets (sim/vehicle.h, docs/vehicle-scenarios.md).
 *
 * Each preset is built from pieces that start and end at standstill; every preset begins with
 * VEH_REST_S at rest. The 20-minute drive strings the same pieces together with stops between
 * them and a die temperature rising from 10 to 40 degC.
 */
#include "inclino/sim/vehicle.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "inclino/error.h"

#define KMH (1.0 / 3.6)

struct bld {
    struct veh_scenario *sc;
    struct veh_segment cur;
    double t;
    int err;
};

static void emit(struct bld *b, double dur)
{
    if (b->sc->n_seg >= VEH_MAX_SEGMENTS || !(dur > 0.0)) {
        b->err = 1;
        return;
    }
    b->cur.duration_s = dur;
    b->sc->seg[b->sc->n_seg++] = b->cur;
    b->t += dur;
    b->cur.kappa_sine = 0.0;
    b->cur.event = false;
}

static void speed(struct bld *b, double v, double a, double jerk)
{
    b->cur.v_target_mps = v;
    b->cur.a_max_mps2 = a;
    b->cur.jerk_mps3 = jerk;
}

static void curve(struct bld *b, double kappa, double ramp_s)
{
    b->cur.kappa_1pm = kappa;
    b->cur.kappa_ramp_s = ramp_s;
}

static void road(struct bld *b, double grade_pct, double bank_deg, double ramp_s)
{
    b->cur.grade_pct = grade_pct;
    b->cur.bank_deg = bank_deg;
    b->cur.road_ramp_s = ramp_s;
}

static void event(struct bld *b, double after_s, int kind, double h, double len)
{
    struct veh_event *e;
    if (b->sc->n_ev >= VEH_MAX_EVENTS) {
        b->err = 1;
        return;
    }
    e = &b->sc->ev[b->sc->n_ev++];
    e->t_s = b->t + after_s;
    e->kind = kind;
    e->height_m = h;
    e->length_m = len;
}

/* Time to change speed by dv at a with the jerk taper, plus margin. */
static double ramp_time(double dv, double a, double jerk)
{
    return fabs(dv) / a + a / jerk + 1.5;
}

static void rest(struct bld *b, double dur)
{
    speed(b, 0.0, 3.0, 10.0);
    emit(b, dur);
}

static void go(struct bld *b, double v, double a, double jerk)
{
    speed(b, v, a, jerk);
    emit(b, ramp_time(v, a, jerk));
}

static void stop(struct bld *b, double from_v, double a, double jerk)
{
    speed(b, 0.0, a, jerk);
    emit(b, ramp_time(from_v, a, jerk) + 1.0);
}

/* ---- pieces (each from standstill to standstill) -------------------------------------------- */

/* Steady-state circular driving: R = 60 m at the speed giving 0.5 g, for 30 s. */
static void p_cornering(struct bld *b, double lat_g, double radius_m, double hold_s)
{
    double v = sqrt(lat_g * VEH_G * radius_m);
    go(b, v, 2.0, 3.0);
    emit(b, 3.0);
    curve(b, 1.0 / radius_m, 3.0);
    emit(b, 3.0 + hold_s);
    curve(b, 0.0, 3.0);
    emit(b, 5.0);
    stop(b, v, 3.0, 6.0);
}

/* 100 km/h to standstill at 0.8 g. */
static void p_braking(struct bld *b)
{
    double v = 100.0 * KMH;
    go(b, v, 3.0, 4.0);
    emit(b, 4.0);
    speed(b, 0.0, 0.8 * VEH_G, 25.0);
    emit(b, 6.0);
}

/* Full-throttle acceleration at 0.35 g to 100 km/h, then a normal stop. */
static void p_acceleration(struct bld *b)
{
    double v = 100.0 * KMH;
    speed(b, v, 0.35 * VEH_G, 12.0);
    emit(b, ramp_time(v, 0.35 * VEH_G, 12.0));
    emit(b, 3.0);
    stop(b, v, 2.5, 5.0);
}

/* ISO 3888-1 style double lane change at 80 km/h: 3.5 m over 40 m, 25 m in the other lane,
 * back over 40 m. A full sine of curvature over T moves the car sideways by
 * kappa_amp v^2 T^2 / (2 pi) and returns the heading. */
static void p_lane_change(struct bld *b, double v_kmh, int count)
{
    double v = v_kmh * KMH, T = 40.0 / v, amp = 3.5 * 2.0 * 3.14159265358979 / (40.0 * 40.0);
    int i;
    go(b, v, 2.5, 4.0);
    emit(b, 4.0);
    for (i = 0; i < count; i++) {
        b->cur.kappa_sine = amp;
        emit(b, T);
        emit(b, 25.0 / v);
        b->cur.kappa_sine = -amp;
        emit(b, T);
        emit(b, 5.0);
    }
    stop(b, v, 3.0, 6.0);
}

/* A left curve (R 200 m, 80 km/h) banked 6 deg (right side high) on a 5 % upgrade. */
static void p_banked_slope(struct bld *b)
{
    double v = 80.0 * KMH;
    go(b, v, 2.5, 4.0);
    emit(b, 3.0);
    curve(b, 1.0 / 200.0, 4.0);
    road(b, 5.0, -6.0, 4.0);
    emit(b, 29.0);
    curve(b, 0.0, 4.0);
    road(b, 0.0, 0.0, 4.0);
    emit(b, 7.0);
    stop(b, v, 3.0, 6.0);
}

/* Rough road at 50 km/h with potholes, then a very rough stretch at 36 km/h. */
static void p_rough(struct bld *b)
{
    double v = 50.0 * KMH;
    go(b, v, 2.0, 4.0);
    b->cur.rough = 1.0;
    event(b, 6.0, VEH_EV_POTHOLE_LEFT, 0.05, 0.6);
    event(b, 13.0, VEH_EV_POTHOLE_RIGHT, 0.04, 0.8);
    event(b, 19.0, VEH_EV_POTHOLE_LEFT, 0.06, 0.5);
    event(b, 25.0, VEH_EV_POTHOLE_RIGHT, 0.03, 1.0);
    emit(b, 30.0);
    speed(b, 36.0 * KMH, 1.5, 3.0);
    b->cur.rough = 2.0;
    event(b, 8.0, VEH_EV_POTHOLE_LEFT, 0.05, 0.7);
    emit(b, 15.0);
    b->cur.rough = 0.0;
    stop(b, 10.0, 2.5, 5.0);
}

/* Speed bumps: short bumps at 15 and 10 km/h, a road hump at 25 km/h. */
static void p_bumps(struct bld *b)
{
    go(b, 15.0 * KMH, 1.5, 3.0);
    event(b, 2.0, VEH_EV_BUMP, 0.06, 0.6);
    emit(b, 5.0);
    speed(b, 10.0 * KMH, 1.5, 3.0);
    emit(b, 4.0);
    event(b, 1.0, VEH_EV_BUMP, 0.08, 0.5);
    emit(b, 5.0);
    speed(b, 25.0 * KMH, 1.5, 3.0);
    emit(b, 5.0);
    event(b, 1.0, VEH_EV_BUMP, 0.075, 3.7);
    emit(b, 5.0);
    stop(b, 25.0 * KMH, 2.0, 4.0);
}

/* Parking: full lock left forward, full lock right in reverse, straighten, forward. */
static void p_parking(struct bld *b)
{
    const double lock = 1.0 / 5.0;
    curve(b, lock, 1.5);
    emit(b, 2.0);
    speed(b, 1.5, 0.8, 1.5);
    emit(b, 7.0);
    stop(b, 1.5, 1.0, 2.0);
    curve(b, -lock, 2.0);
    emit(b, 2.5);
    speed(b, -1.2, 0.8, 1.5);
    emit(b, 7.0);
    stop(b, 1.2, 1.0, 2.0);
    curve(b, 0.0, 1.5);
    emit(b, 2.0);
    speed(b, 1.0, 0.8, 1.5);
    emit(b, 4.0);
    stop(b, 1.0, 1.0, 2.0);
}

/* A stop on a hill: up onto an 8 % grade at 30 km/h, stop, idle, pull away uphill, level. */
static void p_hill_stop(struct bld *b, double idle_s)
{
    double v = 30.0 * KMH;
    go(b, v, 2.0, 4.0);
    road(b, 8.0, 0.0, 4.0);
    emit(b, 6.0);
    stop(b, v, 2.5, 5.0);
    rest(b, idle_s);
    go(b, v, 2.0, 4.0);
    road(b, 0.0, 0.0, 4.0);
    emit(b, 6.0);
    stop(b, v, 2.5, 5.0);
}

/* Engine start and idle at standstill on a slope (10 % grade, 2 deg bank). */
static void p_idle_slope(struct bld *b, double idle_s, bool mark_event)
{
    b->cur.engine = true;
    b->cur.event = mark_event;
    event(b, 0.0, VEH_EV_ENGINE_START, 0.0, 0.0);
    rest(b, idle_s);
    b->cur.engine = false;
    b->cur.event = false;
}

/* ---- presets ------------------------------------------------------------------------------- */

static void start(struct bld *b, struct veh_scenario *sc, const char *name, const char *summary,
                  double heading)
{
    memset(sc, 0, sizeof(*sc));
    memset(b, 0, sizeof(*b));
    b->sc = sc;
    snprintf(sc->name, sizeof(sc->name), "%s", name);
    sc->summary = summary;
    sc->heading_deg = heading;
    sc->temp0_c = 25.0;
    sc->temp1_c = 27.0;
    sc->temp_tau_s = 300.0;
    b->cur.engine = true;
    b->cur.a_max_mps2 = 3.0;
    b->cur.jerk_mps3 = 10.0;
}

static void b_cornering(struct bld *b)
{
    rest(b, VEH_REST_S);
    p_cornering(b, 0.5, 60.0, 30.0);
    rest(b, 5.0);
}

static void b_braking(struct bld *b)
{
    rest(b, VEH_REST_S);
    p_braking(b);
    rest(b, 5.0);
}

static void b_accel(struct bld *b)
{
    rest(b, VEH_REST_S);
    p_acceleration(b);
    rest(b, 4.0);
}

static void b_lane(struct bld *b)
{
    rest(b, VEH_REST_S);
    p_lane_change(b, 80.0, 2);
    rest(b, 4.0);
}

static void b_banked(struct bld *b)
{
    rest(b, VEH_REST_S);
    p_banked_slope(b);
    rest(b, 4.0);
}

static void b_rough(struct bld *b)
{
    rest(b, VEH_REST_S);
    p_rough(b);
    rest(b, 4.0);
}

static void b_bumps(struct bld *b)
{
    rest(b, VEH_REST_S);
    p_bumps(b);
    rest(b, 4.0);
}

static void b_parking(struct bld *b)
{
    rest(b, VEH_REST_S);
    p_parking(b);
    rest(b, 4.0);
}

static void b_idle(struct bld *b)
{
    road(b, 10.0, 2.0, 0.0);
    b->cur.engine = false;
    rest(b, VEH_REST_S);
    p_idle_slope(b, 60.0, true);
    rest(b, 5.0);
    b->sc->temp0_c = 20.0;
    b->sc->temp1_c = 24.0;
}

#define DRIVE_S 1200.0

static void b_drive(struct bld *b)
{
    int lap;
    b->sc->temp0_c = 10.0;
    b->sc->temp1_c = 40.0;
    b->sc->temp_tau_s = 500.0;
    rest(b, VEH_REST_S);
    for (lap = 0; lap < 2; lap++) {
        p_bumps(b);
        rest(b, 8.0);
        p_rough(b);
        rest(b, 10.0);
        p_banked_slope(b);
        rest(b, 6.0);
        p_lane_change(b, 80.0, 2);
        rest(b, 5.0);
        p_acceleration(b);
        rest(b, 4.0);
        p_cornering(b, lap == 0 ? 0.5 : 0.4, 60.0, 30.0);
        rest(b, 8.0);
        p_braking(b);
        rest(b, 6.0);
        p_parking(b);
        rest(b, 4.0);
        p_hill_stop(b, 25.0);
        rest(b, 4.0);
        p_cornering(b, 0.3, 40.0, 20.0);
        rest(b, 6.0);
    }
    if (b->t < DRIVE_S) {
        rest(b, DRIVE_S - b->t);
    } else {
        b->err = 1;
    }
}

struct preset {
    const char *name;
    const char *summary;
    double heading;
    void (*build)(struct bld *b);
};

static const struct preset PRESETS[] = {
    {"cornering", "steady cornering at 0.5 g lateral (R 60 m, 61.8 km/h) for 30 s", 30.0,
     b_cornering},
    {"braking", "0.8 g braking from 100 km/h to standstill", 0.0, b_braking},
    {"acceleration", "full acceleration at 0.35 g to 100 km/h", 90.0, b_accel},
    {"lane_change", "two double lane changes (3.5 m over 40 m) at 80 km/h", 45.0, b_lane},
    {"banked_slope", "left curve R 200 m at 80 km/h, 6 deg bank, 5 % upgrade", 120.0, b_banked},
    {"rough_road", "rough road at 50 and 36 km/h with five potholes", 200.0, b_rough},
    {"speed_bumps", "speed bumps at 15 and 10 km/h, a road hump at 25 km/h", 270.0, b_bumps},
    {"parking", "parking: full lock forward, full lock reversing, straighten", 10.0, b_parking},
    {"idle_slope", "engine start and 60 s idle at standstill on a 10 % grade, 2 deg bank", 60.0,
     b_idle},
    {"drive_20min", "20-minute drive mixing every piece, die temperature 10 -> 40 degC", 0.0,
     b_drive},
};

#define N_PRESETS (sizeof(PRESETS) / sizeof(PRESETS[0]))

size_t veh_preset_count(void)
{
    return N_PRESETS;
}

const char *veh_preset_name(size_t i)
{
    return i < N_PRESETS ? PRESETS[i].name : NULL;
}

const char *veh_preset_summary(size_t i)
{
    return i < N_PRESETS ? PRESETS[i].summary : NULL;
}

int veh_preset_build(size_t i, struct veh_scenario *sc)
{
    struct bld b;
    if (sc == NULL) return INC_ERR_NULL;
    if (i >= N_PRESETS) return INC_ERR_INVAL;
    start(&b, sc, PRESETS[i].name, PRESETS[i].summary, PRESETS[i].heading);
    PRESETS[i].build(&b);
    return b.err ? INC_ERR_INVAL : INC_OK;
}

int veh_preset_by_name(const char *name, struct veh_scenario *sc)
{
    size_t i;
    if (name == NULL || sc == NULL) return INC_ERR_NULL;
    for (i = 0; i < N_PRESETS; i++) {
        if (strcmp(name, PRESETS[i].name) == 0) return veh_preset_build(i, sc);
    }
    return INC_ERR_INVAL;
}
