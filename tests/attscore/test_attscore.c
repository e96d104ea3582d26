/*
 * test_attscore.c - the attitude scorer (inclino/attscore.h) and the named-column CSV reader it
 * uses (inclino/sim/imu_csv.h): the metric on known rotations, heading ignored, which samples
 * are scored, the integrity counts, and the reader's rules and refusals. Host only.
 */
#define _DEFAULT_SOURCE
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <zlib.h>

#include "inclino/attscore.h"
#include "inclino/error.h"
#include "inclino/sim/imu_csv.h"
#include "unit.h"

#define DEG (3.14159265358979323846 / 180.0)

static void quat_axis(double ax, double ay, double az, double deg, double q[4])
{
    const double n = sqrt(ax * ax + ay * ay + az * az), h = deg * DEG / 2.0;
    q[0] = cos(h);
    q[1] = sin(h) * ax / n;
    q[2] = sin(h) * ay / n;
    q[3] = sin(h) * az / n;
}

static void test_metric(void)
{
    double a[4], b[4], z[4] = {0, 0, 0, 0};
    quat_axis(1, 0, 0, 10.0, a);
    quat_axis(1, 0, 0, 0.0, b);
    CHECK_NEAR(attscore_incl_err_deg(a, b), 10.0, 1e-9);
    /* Heading does not count: a rotation about earth z (applied on the left) is no error. */
    {
        double h[4], ha[4];
        quat_axis(0, 0, 1, 77.0, h);
        ha[0] = h[0] * a[0] - h[3] * a[3];
        ha[1] = h[0] * a[1] - h[3] * a[2];
        ha[2] = h[0] * a[2] + h[3] * a[1];
        ha[3] = h[0] * a[3] + h[3] * a[0];
        CHECK_NEAR(attscore_incl_err_deg(ha, a), 0.0, 1e-6);
    }
    /* Scale does not matter; sign does not matter (q and -q are one rotation). */
    quat_axis(0, 1, 0, 30.0, a);
    b[0] = -2 * a[0];
    b[1] = -2 * a[1];
    b[2] = -2 * a[2];
    b[3] = -2 * a[3];
    CHECK_NEAR(attscore_incl_err_deg(a, b), 0.0, 1e-6);
    quat_axis(0, 1, 0, 0.0, b);
    CHECK_NEAR(attscore_incl_err_deg(a, b), 30.0, 1e-9);
    quat_axis(1, 1, 0, 180.0, a);
    CHECK_NEAR(attscore_incl_err_deg(a, b), 180.0, 1e-6);
    CHECK(isnan(attscore_incl_err_deg(z, b)));
    {
        double r, p;
        quat_axis(0, 1, 0, -20.0, a);
        attscore_roll_pitch_deg(a, &r, &p);
        CHECK_NEAR(r, 0.0, 1e-9);
        CHECK_NEAR(p, -20.0, 1e-9);
        quat_axis(1, 0, 0, 170.0, a);
        attscore_roll_pitch_deg(a, &r, &p);
        CHECK_NEAR(r, 170.0, 1e-9);
    }
}

static void test_score(void)
{
    struct attscore_sample s[6];
    struct attscore_result r;
    unsigned i;
    for (i = 0; i < 6u; i++) {
        s[i].t_s = 4.0 + i;
        quat_axis(1, 0, 0, 0.0, s[i].q_truth);
        s[i].movement = 1;
        quat_axis(1, 0, 0, 1.0 + i, s[i].q_est); /* error 1 + i deg */
        s[i].bound_deg = 3.5;
        s[i].valid = true;
    }
    s[1].movement = 0;     /* t 5: not scored (rest) */
    s[2].q_truth[0] = NAN; /* t 6: truth lost */
    s[5].valid = false;    /* t 9, error 6: not valid */
    REQUIRE(attscore_score(s, 6u, 5.0, &r) == 0);
    /* scored: t 7 (err 4), t 8 (err 5), t 9 (err 6); t 4 is before t_min */
    CHECK_EQ_INT(r.n, 3);
    CHECK_NEAR(r.rms_deg, sqrt((16.0 + 25.0 + 36.0) / 3.0), 1e-9);
    CHECK_NEAR(r.max_deg, 6.0, 1e-9);
    CHECK_EQ_INT(r.n_valid, 2);
    CHECK_EQ_INT(r.n_over, 2);
    CHECK_NEAR(r.over_bound_frac, 1.0, 1e-12);
    CHECK_NEAR(r.max_err_over_bound, 5.0 / 3.5, 1e-9);
    CHECK_NEAR(r.max_valid_err_deg, 5.0, 1e-9);
    CHECK_NEAR(r.median_bound_deg, 3.5, 1e-12);
    /* errors are about x alone: all in roll */
    CHECK_NEAR(r.roll_rms_deg, r.rms_deg, 1e-9);
    CHECK_NEAR(r.roll_max_deg, 6.0, 1e-9);
    CHECK_NEAR(r.pitch_max_deg, 0.0, 1e-9);
    CHECK(attscore_score(NULL, 1u, 0.0, &r) != 0);
    /* A valid sample without a bound is over it. */
    s[3].bound_deg = NAN;
    REQUIRE(attscore_score(s, 6u, 5.0, &r) == 0);
    CHECK_EQ_INT(r.n_over, 2);
    CHECK(isinf(r.max_err_over_bound));
}

static int read_text(const char *text, const struct imu_csv_spec *spec, int n,
                     struct imu_csv_cols *t, char *msg, size_t len)
{
    int err;
    FILE *f = tmpfile();
    if (f == NULL) return -1000;
    fputs(text, f);
    rewind(f);
    err = imu_csv_read_named(f, "in.csv", spec, n, t, msg, len);
    fclose(f);
    return err;
}

static void test_named_reader(void)
{
    static const struct imu_csv_spec spec[] = {
        {"t_s", IMU_CSV_TIME}, {"b", IMU_CSV_NAN_OK}, {"c", 0u}, {"d", IMU_CSV_OPTIONAL}};
    struct imu_csv_cols t;
    char msg[256];
    /* Columns found by name, in any order; extras ignored (even non-numbers); nan where allowed. */
    REQUIRE(read_text("# comment\nx,c,t_s,b\nfoo,3,0.5,nan\nbar,4,0.75,2\n", spec, 4, &t, msg,
                      sizeof msg) == INC_OK);
    CHECK_EQ_INT(t.n, 2);
    CHECK(t.present[0] && t.present[1] && t.present[2] && !t.present[3]);
    CHECK_NEAR(imu_csv_at(&t, 0, 0), 0.5, 0.0);
    CHECK(isnan(imu_csv_at(&t, 0, 1)));
    CHECK_NEAR(imu_csv_at(&t, 1, 1), 2.0, 0.0);
    CHECK_NEAR(imu_csv_at(&t, 1, 2), 4.0, 0.0);
    CHECK(isnan(imu_csv_at(&t, 1, 3)));
    CHECK_EQ_INT(t.line[1], 4);
    imu_csv_cols_free(&t);
    /* Refusals, each naming the problem. */
    CHECK_EQ_INT(read_text("t_s,b\n0,1\n", spec, 4, &t, msg, sizeof msg), INC_ERR_FORMAT);
    CHECK(strstr(msg, "no column 'c'") != NULL);
    CHECK_EQ_INT(read_text("t_s,b,c,c\n0,1,2,3\n", spec, 4, &t, msg, sizeof msg), INC_ERR_FORMAT);
    CHECK(strstr(msg, "twice") != NULL);
    CHECK_EQ_INT(read_text("t_s,b,c\n0,1,nan\n", spec, 4, &t, msg, sizeof msg), INC_ERR_FORMAT);
    CHECK(strstr(msg, "'c'") != NULL);
    CHECK_EQ_INT(read_text("t_s,b,c\n0,inf,1\n", spec, 4, &t, msg, sizeof msg), INC_ERR_FORMAT);
    CHECK_EQ_INT(read_text("t_s,b,c\n0,1,2\n0,1,2\n", spec, 4, &t, msg, sizeof msg),
                 INC_ERR_FORMAT);
    CHECK(strstr(msg, "does not increase") != NULL);
    CHECK_EQ_INT(read_text("t_s,b,c\n-1,1,2\n", spec, 4, &t, msg, sizeof msg), INC_ERR_FORMAT);
    CHECK_EQ_INT(read_text("t_s,b,c\n0,1\n", spec, 4, &t, msg, sizeof msg), INC_ERR_FORMAT);
    CHECK(strstr(msg, "line 2") != NULL);
    CHECK_EQ_INT(read_text("t_s,b,c\n", spec, 4, &t, msg, sizeof msg), INC_ERR_FORMAT);
    CHECK_EQ_INT(read_text("", spec, 4, &t, msg, sizeof msg), INC_ERR_FORMAT);
    CHECK_EQ_INT(read_text("t_s,b,c\n0,1,2x\n", spec, 4, &t, msg, sizeof msg), INC_ERR_FORMAT);
    CHECK(t.n == 0 && t.v == NULL);
    CHECK_EQ_INT(imu_csv_read_named(NULL, "x", spec, 4, &t, msg, sizeof msg), INC_ERR_NULL);
}

/* imu_csv_open reads gzip and plain files alike; a missing file is NULL. */
static void test_open(void)
{
    static const struct imu_csv_spec spec[] = {{"t_s", IMU_CSV_TIME}, {"v", 0u}};
    const char *text = "t_s,v\n0,1\n0.5,2\n";
    char gz[] = "/tmp/inclino_attscore_XXXXXX", plain[] = "/tmp/inclino_attscore_XXXXXX";
    struct imu_csv_cols t;
    char msg[128];
    int fd = mkstemp(gz), fd2 = mkstemp(plain);
    gzFile z;
    FILE *f;
    REQUIRE(fd >= 0 && fd2 >= 0);
    close(fd);
    REQUIRE(write(fd2, text, strlen(text)) == (ssize_t)strlen(text));
    close(fd2);
    z = gzopen(gz, "wb");
    REQUIRE(z != NULL);
    CHECK(gzputs(z, text) == (int)strlen(text));
    CHECK(gzclose(z) == Z_OK);
    f = imu_csv_open(gz);
    REQUIRE(f != NULL);
    CHECK_EQ_INT(imu_csv_read_named(f, gz, spec, 2, &t, msg, sizeof msg), INC_OK);
    fclose(f);
    CHECK_EQ_INT(t.n, 2);
    CHECK_NEAR(imu_csv_at(&t, 1, 1), 2.0, 0.0);
    imu_csv_cols_free(&t);
    f = imu_csv_open(plain);
    REQUIRE(f != NULL);
    CHECK_EQ_INT(imu_csv_read_named(f, plain, spec, 2, &t, msg, sizeof msg), INC_OK);
    fclose(f);
    CHECK_EQ_INT(t.n, 2);
    imu_csv_cols_free(&t);
    remove(gz);
    remove(plain);
    CHECK(imu_csv_open("/nonexistent/inclino.csv") == NULL);
}

int main(void)
{
    UNIT_RUN(test_open);
    UNIT_RUN(test_metric);
    UNIT_RUN(test_score);
    UNIT_RUN(test_named_reader);
    return unit_report();
}
