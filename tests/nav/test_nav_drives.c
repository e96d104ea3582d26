/*
 * The navigation mode on the simulated drives (tools/lib/navrun: sim/vehicle truth, the parts'
 * resolution and rates, sim/gps NMEA with correlated noise, latency, outages and a jump, through
 * app_nav's parser, stillness gate and dead reckoning). Asserts the figures of docs/navigation.md:
 *   - every valid position, speed and heading of every cycle of every drive inside its bound;
 *   - the 1 s gap prediction error at 30 m/s through the lane changes <= 0.5 m, against >= 25 m
 *     for holding the last fix;
 *   - the heading change across the 90-degree turns without a fix within 1 deg;
 *   - the 2-minute outage: the dead-reckoned track ends closer than a tenth of holding the fix;
 *   - the jump refused, the gyro offset learned at the stops;
 *   - the gap error not worse with more averaging passes beyond what the delay costs (1..4).
 * Host only (minutes of simulated driving).
 */
#include "inclino/navrun.h"
#include "unit.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static struct navrun_result res[16];

static const struct navrun_result *by_name(const char *n)
{
    unsigned i;
    for (i = 0; i < navrun_count(); i++)
        if (strcmp(res[i].name, n) == 0) return &res[i];
    return NULL;
}

static void test_drives(void)
{
    struct navrun_cfg c;
    unsigned i;
    const struct navrun_result *r;
    navrun_default_cfg(&c);
    REQUIRE(navrun_count() == 10u);
    for (i = 0; i < navrun_count(); i++) {
        REQUIRE(navrun_drive(i, &c, &res[i]) == 0);
        r = &res[i];
        printf("  %-16s gap DR %.3f hold %.1f extrap %.2f  pos %.2f speed %.3f heading %.2f  "
               "valid %u/%u/%u of %u  viol %u/%u/%u\n",
               r->name, r->gap_dr.max, r->gap_hold.max, r->gap_extrap.max, r->abs_pos.max,
               r->abs_speed.max, r->abs_heading.max, r->valid_pos, r->valid_speed, r->valid_heading,
               r->cycles, r->viol_pos, r->viol_speed, r->viol_heading);
        CHECK_EQ_INT(r->viol_pos, 0);
        CHECK_EQ_INT(r->viol_speed, 0);
        CHECK_EQ_INT(r->viol_heading, 0);
        CHECK(r->gap_dr.n >= 8u);
        CHECK(r->offsets >= 1u);         /* the gate learned the gyro offset at the start */
        CHECK_EQ_INT(r->nmea_errors, 0); /* the receiver's sentences all parse */
        /* the track is valid most of the time (not in the 2-minute outage) */
        if (strcmp(r->name, "outage_2min") != 0) CHECK(r->valid_pos * 10u >= r->cycles * 8u);
        /* dead reckoning beats holding the fix on every drive */
        CHECK(r->gap_dr.max < r->gap_hold.max / 5.0);
    }
    r = by_name("lane_change");
    REQUIRE(r != NULL);
    CHECK(r->gap_dr.max <= 0.5);
    CHECK(r->gap_hold.max >= 25.0);
    r = by_name("turn90_left");
    REQUIRE(r != NULL);
    CHECK(r->outage_s >= 5.0);
    CHECK_NEAR(r->out_heading_turn_deg, 90.0, 3.0);
    CHECK(fabs(r->out_heading_err_deg) <= 1.0);
    r = by_name("turn90_right");
    REQUIRE(r != NULL);
    CHECK_NEAR(r->out_heading_turn_deg, -90.0, 3.0);
    CHECK(fabs(r->out_heading_err_deg) <= 1.0);
    r = by_name("outage_2min");
    REQUIRE(r != NULL);
    CHECK(r->outage_s >= 119.0);
    CHECK(r->out_dr_m < r->out_hold_m / 10.0);
    CHECK(!r->out_pos_valid_end); /* its bound has grown beyond the limit: not valid */
    r = by_name("straight");
    REQUIRE(r != NULL);
    CHECK(r->jump_epochs >= 2u);
    CHECK(r->fixes_refused >= 1u);
}

static void test_passes(void)
{
    struct navrun_cfg c;
    struct navrun_result r;
    unsigned p;
    navrun_default_cfg(&c);
    for (p = 1; p <= 4u; p++) {
        c.passes = p;
        REQUIRE(navrun_drive(2u, &c, &r) == 0); /* lane_change */
        printf("  passes %u: lane gap DR %.3f m, heading max %.3f deg\n", p, r.gap_dr.max,
               r.abs_heading.max);
        CHECK(r.gap_dr.max <= 0.5);
        CHECK_EQ_INT(r.viol_pos + r.viol_speed + r.viol_heading, 0);
    }
}

int main(void)
{
    UNIT_RUN(test_drives);
    UNIT_RUN(test_passes);
    return unit_report();
}
