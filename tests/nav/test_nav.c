/*
 * Dead reckoning (firmware/signal/nav): configuration checks, the integration against a
 * double-precision run of the same steps (the header's arithmetic bound), the projection against
 * the WGS-84 radii, the heading wrap, a fix pulling the track back spread over the cycles (no
 * jump), a latency-delayed fix compared at its valid time, the jump gate and the re-seat, and the
 * bounds and validity flags. Fixed point only in the code under test; runs on every target.
 */
#include "inclino/nav.h"
#include "unit.h"

#include <math.h>

#define PI 3.14159265358979323846
#define Q16(x) ((int32_t)lround((x)*65536.0))

static struct nav nv;

static struct nav_cfg cfg_default(void)
{
    return nav_default_cfg(Q16(0.02));
}

static void fix_at(double e_m, double n_m, double speed, double course_deg, uint64_t t_valid)
{
    /* local metres -> lat/lon about the reference 48.1 N 11.5 E with the nav's own radii */
    int64_t kn, ke;
    struct nav_fix_in f;
    nav_radii_q36(481000000, &kn, &ke);
    f.lat_e7 = 481000000 + (int32_t)lround(n_m / ((double)kn / 68719476736.0));
    f.lon_e7 = 115000000 + (int32_t)lround(e_m / ((double)ke / 68719476736.0));
    f.speed_mmps = (uint32_t)lround(speed * 1000.0);
    f.course_cdeg = (uint16_t)lround(fmod(course_deg + 360.0, 360.0) * 100.0) % 36000u;
    f.has_speed = true;
    f.has_course = true;
    f.t_valid_ns = t_valid;
    (void)nav_fix(&nv, &f);
}

static void test_cfg(void)
{
    struct nav_cfg c = cfg_default();
    CHECK_OK(nav_init(&nv, &c));
    CHECK_ERR(nav_init(NULL, &c), INC_ERR_NULL);
    c.avg_passes = 5u;
    CHECK_ERR(nav_init(&nv, &c), INC_ERR_INVAL);
    c = cfg_default();
    c.avg_w = 0u;
    CHECK_ERR(nav_init(&nv, &c), INC_ERR_INVAL);
    c = cfg_default();
    c.spread_cycles = 0u;
    CHECK_ERR(nav_init(&nv, &c), INC_ERR_INVAL);
    c = cfg_default();
    c.gps_bound_m = 0;
    CHECK_ERR(nav_init(&nv, &c), INC_ERR_INVAL);
    c = cfg_default();
    CHECK_OK(nav_init(&nv, &c));
    CHECK_ERR(nav_gyro(&nv, 0, 0u), INC_ERR_RANGE);
    CHECK_ERR(nav_gyro(&nv, 0, NAV_MAX_DT_NS + 1u), INC_ERR_RANGE);
    {
        struct nav_in in = {0, false, 0u};
        struct nav_out o;
        CHECK_ERR(nav_step(&nv, &in, &o), INC_ERR_RANGE);
        in.dt_ns = 13000000u;
        CHECK_OK(nav_step(&nv, &in, &o));
        CHECK(!o.pos_valid && !o.speed_valid && !o.heading_valid); /* nothing known yet */
    }
}

static void test_radii(void)
{
    static const double lats[] = {0.0, 30.0, 48.1, -60.0, 80.0};
    unsigned i;
    for (i = 0; i < 5u; i++) {
        const double p = lats[i] * PI / 180.0, s = sin(p), w = 1.0 - 0.00669437999014 * s * s;
        const double mn = 6378137.0 * (1.0 - 0.00669437999014) / (w * sqrt(w)) * PI / 180.0 * 1e-7;
        const double me = 6378137.0 * cos(p) / sqrt(w) * PI / 180.0 * 1e-7;
        int64_t kn, ke;
        nav_radii_q36((int32_t)lround(lats[i] * 1e7), &kn, &ke);
        /* the latitude enters the sine in Q16 degrees (7.6e-6 deg rounding): <= 1e-6 relative
         * up to 80 deg */
        CHECK_NEAR((double)kn / 68719476736.0, mn, mn * 1e-8);
        CHECK_NEAR((double)ke / 68719476736.0, me, me * 1e-6);
    }
}

/* Constant speed, constant turn rate, no corrections: the fixed-point track against the same
 * steps in double precision, 60 s (4615 cycles). */
static void test_integration(void)
{
    struct nav_cfg c = cfg_default();
    struct nav_in in = {0, true, 13000000u};
    struct nav_out o;
    const double v = 20.0, r = 6.0, h0 = 90.0 - 30.0; /* course 30 -> heading 60 */
    double he = 0, hn = 0, h = h0, emax = 0, hmax = 0;
    unsigned ms, n = UNIT_SIZE(60000u, 20000u);
    c.gain_heading = 0;
    REQUIRE(nav_init(&nv, &c) == INC_OK);
    fix_at(0, 0, v, 30.0, 0u);
    REQUIRE(nv.have_heading && nv.have_ref);
    for (ms = 1; ms <= n; ms++) {
        if (ms % 4u == 0u) {
            REQUIRE(nav_gyro(&nv, Q16(r), 4000000u) == INC_OK);
            h += r * 0.004;
        }
        if (ms % 13u == 0u) {
            double hq;
            REQUIRE(nav_step(&nv, &in, &o) == INC_OK);
            /* the reference uses the heading the nav held (rounded to Q16 as it is) */
            hq = round(fmod(h, 360.0) * 65536.0) / 65536.0;
            he += v * 0.013 * cos(hq * PI / 180.0);
            hn += v * 0.013 * sin(hq * PI / 180.0);
            if (fabs(o.east_mm / 1000.0 - he) > emax) emax = fabs(o.east_mm / 1000.0 - he);
            if (fabs(o.north_mm / 1000.0 - hn) > emax) emax = fabs(o.north_mm / 1000.0 - hn);
            if (fabs(o.heading_deg / 65536.0 - fmod(h, 360.0)) > hmax)
                hmax = fabs(o.heading_deg / 65536.0 - fmod(h, 360.0));
        }
    }
    /* mm output rounding (0.5 mm) + the accumulated integration rounding (< 0.1 mm) */
    CHECK(emax <= 0.0006);
    CHECK(hmax <= 1.0 / 65536.0);
    /* and the circle: radius v / r (rad/s) = 190.99 m; the track stays on it within the
     * discretisation of 13 ms steps */
    {
        const double R = v / (r * PI / 180.0), cx = -R * sin(h0 * PI / 180.0),
                     cy = R * cos(h0 * PI / 180.0);
        const double d = hypot(o.east_mm / 1000.0 - cx, o.north_mm / 1000.0 - cy);
        CHECK(fabs(d - R) < 0.5);
    }
}

static void test_heading_wrap(void)
{
    struct nav_cfg c = cfg_default();
    struct nav_in in = {0, true, 13000000u};
    struct nav_out o;
    unsigned i;
    REQUIRE(nav_init(&nv, &c) == INC_OK);
    fix_at(0, 0, 10.0, 85.0, 0u); /* heading 5 deg */
    for (i = 0; i < 250u; i++) {  /* -10 deg/s for 1 s: 5 -> -5 = 355 */
        REQUIRE(nav_gyro(&nv, Q16(-10.0), 4000000u) == INC_OK);
        if (i % 3u == 2u) REQUIRE(nav_step(&nv, &in, &o) == INC_OK);
    }
    REQUIRE(nav_step(&nv, &in, &o) == INC_OK);
    CHECK_NEAR(o.heading_deg / 65536.0, 355.0, 1e-3);
    CHECK(o.heading_deg >= 0 && o.heading_deg < Q16(360.0));
}

/* A fix 5 m off: the correction arrives spread over spread_cycles, no step in the track. */
static void test_spread(void)
{
    struct nav_cfg c = cfg_default();
    struct nav_in in = {0, true, 13000000u};
    struct nav_out o;
    double prev_e = 0, maxstep = 0;
    unsigned i;
    uint64_t t = 0;
    c.gain_heading = 0;
    REQUIRE(nav_init(&nv, &c) == INC_OK);
    fix_at(0, 0, 10.0, 0.0, 0u); /* north at 10 m/s: east stays 0 */
    for (i = 0; i < 80u; i++) {
        REQUIRE(nav_step(&nv, &in, &o) == INC_OK);
        t += 13000000u;
    }
    CHECK_EQ_INT(o.east_mm, 0);
    prev_e = o.east_mm / 1000.0;
    /* a fix 5 m east of the track, valid now */
    fix_at(5.0, o.north_mm / 1000.0, 10.0, 0.0, t);
    for (i = 0; i < 100u; i++) {
        REQUIRE(nav_step(&nv, &in, &o) == INC_OK);
        if (fabs(o.east_mm / 1000.0 - prev_e) > maxstep)
            maxstep = fabs(o.east_mm / 1000.0 - prev_e);
        prev_e = o.east_mm / 1000.0;
    }
    /* gain 0.2 of 5 m = 1 m in 60 steps of 16.7 mm */
    CHECK_NEAR(o.east_mm / 1000.0, 1.0, 0.002);
    CHECK(maxstep <= 1.0 / 60.0 + 0.002);
    CHECK(o.pos_valid);
}

/* A fix that arrives late (valid 80 ms ago) at the true position: no correction. */
static void test_latency(void)
{
    struct nav_cfg c = cfg_default();
    struct nav_in in = {0, true, 13000000u};
    struct nav_out o;
    unsigned i;
    uint64_t t = 0;
    double n_then = 0;
    REQUIRE(nav_init(&nv, &c) == INC_OK);
    fix_at(0, 0, 25.0, 0.0, 0u);
    for (i = 0; i < 100u; i++) {
        REQUIRE(nav_step(&nv, &in, &o) == INC_OK);
        t += 13000000u;
        if (i == 93u) n_then = o.north_mm / 1000.0; /* 6 cycles = 78 ms before the end */
    }
    fix_at(0, n_then, 25.0, 0.0, t - 78000000u);
    REQUIRE(nav_step(&nv, &in, &o) == INC_OK);
    CHECK(nv.pend_n_q32 < (1ll << 32) / 500 && nv.pend_n_q32 > -(1ll << 32) / 500); /* < 2 mm */
    /* a fix in the future or older than the ring is refused */
    {
        struct nav_fix_in f = {481000000, 115000000, 25000u, 0u, true, true, t + 100000000u};
        CHECK_ERR(nav_fix(&nv, &f), INC_ERR_RANGE);
        f.t_valid_ns = 1000u;
        CHECK_ERR(nav_fix(&nv, &f), INC_ERR_RANGE);
        f.lat_e7 = 910000000;
        CHECK_ERR(nav_fix(&nv, &f), INC_ERR_INVAL);
    }
}

static void test_jump(void)
{
    struct nav_cfg c = cfg_default();
    struct nav_in in = {0, true, 13000000u};
    struct nav_out o;
    struct nav_fix_in f;
    int64_t kn, ke;
    unsigned i, k;
    uint64_t t = 0;
    REQUIRE(nav_init(&nv, &c) == INC_OK);
    fix_at(0, 0, 0.0, 0.0, 0u);
    nav_radii_q36(481000000, &kn, &ke);
    for (k = 0; k < 3u; k++) {
        for (i = 0; i < 77u; i++) {
            REQUIRE(nav_step(&nv, &in, &o) == INC_OK);
            t += 13000000u;
        }
        /* 200 m east: far outside bound + gps_bound */
        f.lat_e7 = 481000000;
        f.lon_e7 = 115000000 + (int32_t)lround(200.0 / ((double)ke / 68719476736.0));
        f.speed_mmps = 0u;
        f.course_cdeg = 0u;
        f.has_speed = f.has_course = true;
        f.t_valid_ns = t;
        if (k < 2u) {
            CHECK_ERR(nav_fix(&nv, &f), INC_ERR_REJECTED);
            CHECK_EQ_INT(nv.e_q32, 0);
        } else {
            CHECK_OK(nav_fix(&nv, &f)); /* the third in a row re-seats the track */
            CHECK_NEAR((double)nv.e_q32 / 4294967296.0, 200.0, 0.01);
            CHECK_EQ_INT(nv.resets, 1);
        }
    }
}

/* Bounds: they grow without fixes, the flags drop at their limits. */
static void test_bounds(void)
{
    struct nav_cfg c = cfg_default();
    struct nav_in in = {0, true, 13000000u};
    struct nav_out o, o1;
    unsigned i;
    REQUIRE(nav_init(&nv, &c) == INC_OK);
    REQUIRE(nav_gyro_offset(&nv, 0) == INC_OK);
    fix_at(0, 0, 20.0, 0.0, 0u);
    REQUIRE(nav_step(&nv, &in, &o1) == INC_OK);
    CHECK(o1.pos_valid && o1.speed_valid && o1.heading_valid);
    CHECK_NEAR(o1.pos_bound_mm / 1000.0, 15.0, 0.5);
    CHECK(o1.heading_bound_deg >= c.course_bound_deg * 8 / 20);
    for (i = 0; i < 400u; i++) { /* 5.2 s without a fix */
        REQUIRE(nav_gyro(&nv, 0, 13000000u) == INC_OK);
        REQUIRE(nav_step(&nv, &in, &o) == INC_OK);
    }
    CHECK(o.pos_bound_mm > o1.pos_bound_mm);
    CHECK(o.heading_bound_deg > o1.heading_bound_deg);
    CHECK(!o.speed_valid); /* beyond gpsb's 4 s gap */
    for (i = 0; i < 4000u && o.pos_valid; i++) {
        REQUIRE(nav_gyro(&nv, 0, 13000000u) == INC_OK);
        REQUIRE(nav_step(&nv, &in, &o) == INC_OK);
    }
    CHECK(!o.pos_valid);
    CHECK(o.pos_bound_mm > 50000u);
}

int main(void)
{
    UNIT_RUN(test_cfg);
    UNIT_RUN(test_radii);
    UNIT_RUN(test_integration);
    UNIT_RUN(test_heading_wrap);
    UNIT_RUN(test_spread);
    UNIT_RUN(test_latency);
    UNIT_RUN(test_jump);
    UNIT_RUN(test_bounds);
    return unit_report();
}
