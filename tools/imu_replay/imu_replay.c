/*
 * imu_replay - run recorded IMU data through the firmware (docs/imu-replay.md).
 *
 *   imu_replay [options] IN.csv[.gz]        (IN may be "-": standard input, gzip or plain)
 *
 * Every row is converted to what the chosen part would deliver (--part: the generic part keeps
 * the values, rounded to Q16 and clipped at the configured full scale; a named part is quantised
 * to its LSBs and range and converted back with the driver's own conversions); then, sample by
 * sample, the attitude estimator (--estimator: att, the 3D estimator, by default; adapt, the
 * patented per-axis method; tilt, its angle stage alone) and the EPB application (calibration,
 * stillness, block average, slope with its bound) run on it. One output row per input row
 * (--blocks: only rows that complete a slope estimate), CSV, starting with
 *   t_s,q_w,q_x,q_y,q_z,roll_deg,pitch_deg,att_bound_deg,att_valid
 * (q: sensor to earth, v_earth = q v_sensor q^-1, z up). A summary goes to standard error, its
 * last line machine-readable (key=value).
 *
 * Input: a header names the columns. With t_s, gyr_x_dps, gyr_y_dps, gyr_z_dps, acc_x_g,
 * acc_y_g, acc_z_g (the layout of the BROAD benchmark's files) columns are found by name, extra
 * columns are ignored, and temp_c, speed_mps, yaw_rate_dps are used where present (the last two:
 * vehicle aiding). Otherwise the positional layout: time, gyro x y z, accel x y z [, temperature]
 * (7 or 8 numbers, optional header). Any bad row stops the run before anything is written, with
 * the line named. Exit status 0, 1 for bad input (the message names the line), 2 for bad options,
 * files or write errors.
 */
#define _GNU_SOURCE
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "inclino/adapt_tilt.h"
#include "inclino/adis_imu.h"
#include "inclino/app.h"
#include "inclino/att.h"
#include "inclino/calstore.h"
#include "inclino/sca3000.h"
#include "inclino/sim/imu_csv.h"
#include "inclino/simflash.h"
#include "inclino/sensor.h"
#include "inclino/tilt.h"
#include "inclino/tool_cli.h"

#define RAD2DEG (180.0 / 3.14159265358979323846)

/* ---- Parts ---------------------------------------------------------------------------------- */

struct part {
    const char *name;
    bool generic; /* no part: values kept (Q16), clipped at --gyro-fs / --acc-fs */
    bool adis;
    uint32_t acc_lsb_ug; /* ADIS: the variant's LSB; SCA3000: sca3000_ug_per_lsb */
    int variant;         /* enum adis_imu_variant / enum sca3000_variant */
    int family_1640x;    /* ADIS: 1 = 1640x (TEMP_OUT 0.14), 0 = 1636x (0.136) */
    bool temp;           /* the part has a temperature output */
};

static const struct part parts[] = {
    {"generic", true, false, 0u, 0, 0, true},
    {"adis16405", false, true, 3333u, ADIS_IMU_ADIS16405, 1, true},
    {"adis16400", false, true, 3333u, ADIS_IMU_ADIS16400, 1, true},
    {"adis16364", false, true, 1000u, ADIS_IMU_ADIS16364, 0, true},
    {"adis16362", false, true, 333u, ADIS_IMU_ADIS16362, 0, true},
    {"adis16360", false, true, 3333u, ADIS_IMU_ADIS16360, 0, true},
    {"sca3000-d01", false, false, 750u, SCA3000_D01, 0, true},
    {"sca3000-e02", false, false, 1000u, SCA3000_E02, 0, false},
    {"sca3000-e04", false, false, 2000u, SCA3000_E04, 0, false},
    {"sca3000-e05", false, false, 6250u, SCA3000_E05, 0, false},
};
#define N_PARTS (sizeof parts / sizeof parts[0])

/* value / lsb rounded half away from zero, clamped to [lo, hi]; *sat when clamped. */
static int32_t quant(double value, double lsb, int32_t lo, int32_t hi, bool *sat)
{
    const double c = value / lsb;
    const double r = c < 0.0 ? -floor(-c + 0.5) : floor(c + 0.5);
    if (r < (double)lo) {
        *sat = true;
        return lo;
    }
    if (r > (double)hi) {
        *sat = true;
        return hi;
    }
    return (int32_t)r;
}

/* value rounded to Q16 and clipped at +-fs; *sat when at or beyond fs - fs / 256. */
static int32_t q16_clip(double value, double fs, bool *sat)
{
    const double c = fmin(fmax(value, -fs), fs) * 65536.0;
    if (fabs(value) >= fs * (1.0 - 1.0 / 256.0)) *sat = true;
    return (int32_t)(c < 0.0 ? -floor(-c + 0.5) : floor(c + 0.5));
}

/* One row as the part would deliver it (nominal-scaled Q16, inclino/sensor.h). gyro_fs, acc_fs: the
 * generic part's full scale. sat_axes: bits 0-2 gyro x y z, 3-5 accel x y z saturated. */
static void quantise_row(const struct part *p, const double *v, bool have_temp, double gyro_fs,
                         double acc_fs, struct sensor_sample *s, unsigned *sat_axes)
{
    bool tsat = false;
    unsigned i;
    memset(s, 0, sizeof(*s));
    *sat_axes = 0u;
    for (i = 0; i < 3u; i++) {
        bool ga = false, aa = false;
        if (p->generic) {
            s->accel_g[i] = q16_clip(v[4 + i], acc_fs, &aa);
            s->gyro_dps[i] = q16_clip(v[1 + i], gyro_fs, &ga);
        } else if (p->adis) {
            const int32_t ca = quant(v[4 + i] * 1e6, (double)p->acc_lsb_ug, -8192, 8191, &aa);
            const int32_t cg = quant(v[1 + i], 0.05, -8192, 8191, &ga);
            (void)adis_imu_accel_g_from_counts(ca, p->acc_lsb_ug, &s->accel_g[i]);
            (void)adis_imu_gyro_dps_from_counts(cg, ADIS_IMU_RANGE_300, &s->gyro_dps[i]);
            aa = aa || ca <= -8192 || ca >= 8191;
            ga = ga || cg <= -8192 || cg >= 8191;
        } else {
            int32_t g = 0;
            const int32_t ca = quant(v[4 + i] * 1e6, (double)p->acc_lsb_ug, -4096, 4095, &aa);
            (void)sca3000_accel_g_from_counts(ca, (enum sca3000_variant)p->variant, &g);
            s->accel_g[i] = g;
            aa = aa || ca <= -4096 || ca >= 4095;
        }
        if (ga) {
            *sat_axes |= 1u << i;
            s->flags |= SENSOR_S_GYRO_SAT_X << i;
        }
        if (aa) {
            *sat_axes |= 8u << i;
            s->flags |= SENSOR_S_ACCEL_SAT_X << i;
        }
    }
    s->flags |= SENSOR_S_HAVE_ACCEL | (p->adis || p->generic ? SENSOR_S_HAVE_GYRO : 0u);
    if (have_temp && p->temp) {
        if (p->generic) {
            s->temp_c = q16_clip(v[7], 1000.0, &tsat);
        } else if (p->adis) {
            const double lsb = p->family_1640x ? 0.14 : 0.136;
            const int32_t c = quant(v[7] - 25.0, lsb, -2048, 2047, &tsat);
            (void)adis_imu_temp_c_from_counts(
                c, p->family_1640x ? ADIS_IMU_FAMILY_1640X : ADIS_IMU_FAMILY_1636X, &s->temp_c);
        } else {
            /* counts = T * 1.8 + 214.6 (sca3000.h, the Linux formula) */
            const int32_t raw = quant(v[7] * 1.8 + 214.6, 1.0, 0, 511, &tsat);
            (void)sca3000_temp_c_from_counts(raw, &s->temp_c);
        }
        s->flags |= SENSOR_S_HAVE_TEMP;
    }
}

/* ---- An emulated flash (sim_flash): the calibration is loaded the way the firmware loads it ---- */

#define PAGE 1024u
#define PROG 8u
static uint8_t flash_mem[2u * PAGE];
static struct simflash flash;

/* ---- The replay sensor: the identity of the chosen part (its samples are the recorded rows,
 * fed to app_step one by one, so its wait and read are never called) --------------------------- */

struct replay_id {
    struct sensor_identity id;
};

static int replay_wait(void *dev, uint32_t timeout_ns)
{
    (void)dev;
    (void)timeout_ns;
    return INC_ERR_UNSUPPORTED;
}

static int replay_read(void *dev, struct sensor_sample *out)
{
    (void)dev;
    (void)out;
    return INC_ERR_UNSUPPORTED; /* rows are fed with app_step */
}

static int replay_identity(void *dev, struct sensor_identity *out)
{
    *out = ((const struct replay_id *)dev)->id;
    return INC_OK;
}

static const struct sensor_ops replay_ops = {NULL, replay_wait,     replay_read, NULL,
                                             NULL, replay_identity, NULL};

/* ---- Input: named columns (BROAD layout) or the positional layout --------------------------- */

enum { C_T, C_GX, C_GY, C_GZ, C_AX, C_AY, C_AZ, C_TEMP, C_SPEED, C_YAW, C_N };

static const struct imu_csv_spec named_spec[C_N] = {{"t_s", IMU_CSV_TIME},
                                                    {"gyr_x_dps", 0u},
                                                    {"gyr_y_dps", 0u},
                                                    {"gyr_z_dps", 0u},
                                                    {"acc_x_g", 0u},
                                                    {"acc_y_g", 0u},
                                                    {"acc_z_g", 0u},
                                                    {"temp_c", IMU_CSV_OPTIONAL},
                                                    {"speed_mps", IMU_CSV_OPTIONAL},
                                                    {"yaw_rate_dps", IMU_CSV_OPTIONAL}};

/* The rows in one form: v[C_N] per row (NaN where a column is absent), the file line. */
struct rows {
    double *v;
    long *line;
    size_t n;
    bool have_temp, have_vehicle;
};

static void rows_free(struct rows *r)
{
    free(r->v);
    free(r->line);
    r->v = NULL;
    r->line = NULL;
    r->n = 0;
}

/* The whole input in memory (a pipe can be read once), then parsed from a memory stream. */
static int slurp(const char *path, char **buf, size_t *len, char *msg, size_t msg_len)
{
    FILE *in = imu_csv_open(path);
    size_t cap = 1u << 20, n = 0, got;
    char *b;
    if (in == NULL) {
        snprintf(msg, msg_len, "%s: cannot open (%s)", path, strerror(errno));
        return 2;
    }
    b = malloc(cap);
    while (b != NULL && (got = fread(b + n, 1, cap - n, in)) > 0) {
        n += got;
        if (n == cap) {
            char *nb = realloc(b, cap * 2u);
            if (nb == NULL) {
                free(b);
                b = NULL;
                break;
            }
            b = nb;
            cap *= 2u;
        }
    }
    if (b == NULL || ferror(in)) {
        snprintf(msg, msg_len, "%s: %s", path, b == NULL ? "out of memory" : "read error");
        free(b);
        fclose(in);
        return 2;
    }
    fclose(in);
    *buf = b;
    *len = n;
    return 0;
}

/* Named layout when the first non-comment line has a field "t_s". */
static bool is_named(const char *buf, size_t len)
{
    size_t i = 0;
    while (i < len) {
        size_t e = i;
        while (e < len && buf[e] != '\n')
            e++;
        while (i < e && (buf[i] == ' ' || buf[i] == '\t'))
            i++;
        if (i < e && buf[i] != '#' && buf[i] != '\r') {
            size_t k = i;
            while (k < e) {
                size_t f = k;
                while (f < e && buf[f] != ',')
                    f++;
                while (k < f && buf[k] == ' ')
                    k++;
                if (k + 3u <= f && strncmp(buf + k, "t_s", 3) == 0) {
                    size_t m = k + 3u;
                    while (m < f && (buf[m] == ' ' || buf[m] == '\r'))
                        m++;
                    if (m == f) return true;
                }
                k = f + 1u;
            }
            return false;
        }
        i = e + 1u;
    }
    return false;
}

static int read_rows(const char *path, struct rows *r, char *msg, size_t msg_len)
{
    char *buf = NULL;
    size_t len = 0;
    FILE *m;
    int err;
    memset(r, 0, sizeof(*r));
    err = slurp(path, &buf, &len, msg, msg_len);
    if (err != 0) return err;
    m = fmemopen(buf, len > 0 ? len : 1u, "r");
    if (m == NULL || len == 0) {
        snprintf(msg, msg_len, "%s: %s", path, len == 0 ? "empty input" : "cannot read");
        if (m != NULL) fclose(m);
        free(buf);
        return len == 0 ? 1 : 2;
    }
    if (is_named(buf, len)) {
        struct imu_csv_cols t;
        err = imu_csv_read_named(m, path, named_spec, C_N, &t, msg, msg_len);
        if (err == INC_OK && t.n < 2u) {
            snprintf(msg, msg_len, "%s: %zu data rows; at least 2 are needed", path, t.n);
            imu_csv_cols_free(&t);
            err = INC_ERR_FORMAT;
        }
        if (err == INC_OK) {
            r->v = t.v;
            r->line = t.line;
            r->n = t.n;
            r->have_temp = t.present[C_TEMP];
            r->have_vehicle = t.present[C_SPEED] && t.present[C_YAW];
            if (t.present[C_SPEED] != t.present[C_YAW]) {
                snprintf(msg, msg_len, "%s: speed_mps and yaw_rate_dps go together", path);
                rows_free(r);
                err = INC_ERR_FORMAT;
            }
        }
    } else {
        struct imu_csv_table t = {NULL, 0, 0, 0};
        err = imu_csv_read(m, path, &t, msg, msg_len);
        if (err == INC_OK) {
            r->v = malloc(t.n * C_N * sizeof(double));
            r->line = malloc(t.n * sizeof(long));
            if (r->v == NULL || r->line == NULL) {
                snprintf(msg, msg_len, "out of memory");
                rows_free(r);
                err = INC_ERR_NO_SPACE;
            } else {
                size_t i;
                for (i = 0; i < t.n; i++) {
                    int c;
                    for (c = 0; c < C_N; c++)
                        r->v[i * C_N + (size_t)c] = c < t.cols ? t.rows[i].v[c] : NAN;
                    r->line[i] = t.rows[i].line;
                }
                r->n = t.n;
                r->have_temp = t.cols == 8;
            }
            imu_csv_free(&t);
        }
    }
    fclose(m);
    free(buf);
    if (err == INC_OK) return 0;
    return err == INC_ERR_FORMAT ? 1 : 2;
}

static int cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : (x > y ? 1 : 0);
}

/* ---- The sensor frame: a signed permutation of the axes (a proper rotation) ----------------- */

struct frame {
    int axis[3]; /* estimator axis i = sign[i] * sensor axis axis[i] */
    int sign[3];
    double q[4]; /* the rotation from the sensor frame to the estimator frame, as a quaternion */
};

/* "x,y,z" (default), "-y,x,z", ...: each of x y z once, optionally signed; determinant +1. */
static bool frame_parse(const char *s, struct frame *f)
{
    double m[3][3] = {{0}};
    double det, tr;
    int i, used = 0;
    const char *p = s;
    for (i = 0; i < 3; i++) {
        int sign = 1;
        if (*p == '-' || *p == '+') sign = *p++ == '-' ? -1 : 1;
        if (*p < 'x' || *p > 'z') return false;
        f->axis[i] = *p - 'x';
        f->sign[i] = sign;
        if ((used & (1 << f->axis[i])) != 0) return false;
        used |= 1 << f->axis[i];
        p++;
        if (i < 2 && *p++ != ',') return false;
        m[i][f->axis[i]] = sign;
    }
    if (*p != '\0') return false;
    det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
          m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
          m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    if (det < 0.5) return false;
    /* m maps sensor vectors to estimator vectors; q is the quaternion of that rotation
     * (v_est = q v_sensor q^-1), so the output sensor to earth is q_est * q. */
    tr = m[0][0] + m[1][1] + m[2][2];
    if (tr > -0.99) {
        const double w = sqrt(1.0 + tr) / 2.0;
        f->q[0] = w;
        f->q[1] = (m[2][1] - m[1][2]) / (4.0 * w);
        f->q[2] = (m[0][2] - m[2][0]) / (4.0 * w);
        f->q[3] = (m[1][0] - m[0][1]) / (4.0 * w);
    } else {
        /* a half turn: the axis is the column of m + I that is not zero */
        int k;
        for (k = 0; k < 2; k++)
            if (m[k][k] > 0.5) break;
        f->q[0] = 0.0;
        f->q[1] = f->q[2] = f->q[3] = 0.0;
        f->q[1 + k] = 1.0;
    }
    return true;
}

static void frame_apply(const struct frame *f, const int32_t in[3], int32_t out[3])
{
    int i;
    for (i = 0; i < 3; i++) {
        const int32_t v = in[f->axis[i]];
        out[i] = f->sign[i] < 0 ? (v == INT32_MIN ? INT32_MAX : -v) : v;
    }
}

static unsigned frame_sat(const struct frame *f, unsigned sat)
{
    unsigned o = 0u;
    int i;
    for (i = 0; i < 3; i++) {
        if ((sat >> f->axis[i]) & 1u) o |= 1u << i;
        if ((sat >> (3 + f->axis[i])) & 1u) o |= 8u << i;
    }
    return o;
}

/* a * b */
static void qmul(const double a[4], const double b[4], double o[4])
{
    o[0] = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
    o[1] = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
    o[2] = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
    o[3] = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
}

/* ---- att parameters from the command line ------------------------------------------------- */

struct att_param {
    const char *name;
    size_t off;
    int q30; /* 1: Q30 ratio, 0: Q16 */
    const char *what;
};

#define ATT_P(field, q30, what)                               \
    {                                                         \
#field, offsetof(struct att_config, field), q30, what \
    }
static const struct att_param att_params[] = {
    ATT_P(tau_acc_s, 0, "accelerometer low-pass time constant, s"),
    ATT_P(tau_acc_rest_s, 0, "the same at rest, s (0: tau_acc_s)"),
    ATT_P(rest_tau_s, 0, "rest-detection low-pass, s"),
    ATT_P(rest_gyro_dps, 0, "rest threshold on the gyro deviation, deg/s"),
    ATT_P(rest_acc_g, 0, "rest threshold on the accelerometer deviation, g"),
    ATT_P(rest_min_s, 0, "time below the thresholds before rest, s"),
    ATT_P(bias_max_dps, 0, "gyro bias clamp (the part's bias range), deg/s"),
    ATT_P(bias_sigma0_dps, 0, "initial bias sigma, deg/s"),
    ATT_P(bias_sigma_rest_dps, 0, "rest-update noise, deg/s"),
    ATT_P(bias_forget_s, 0, "bias variance growth time, s"),
    ATT_P(bias_motion_tau_s, 0, "motion bias time constant, s (0: off)"),
    ATT_P(bias_motion_gate_g, 0, "residual at which the motion bias update stops, g"),
    ATT_P(bound_floor_deg, 0, "bound floor, deg"),
    ATT_P(bound_gyro_sf, 1, "gyro scale and misalignment error in the bound, ratio"),
    ATT_P(bound_bias_k, 0, "multiplier on the bias sigma in the bound"),
    ATT_P(bound_lin_k, 0, "multiplier on the mean horizontal residual in the bound"),
    ATT_P(bound_lin_tau_s, 0, "averaging of the residual, s"),
    ATT_P(bound_arw_dps_rts, 0, "gyro angle random walk in the bound, deg/sqrt(s)"),
    ATT_P(bound_latency_s, 0, "output time-tag uncertainty, s"),
    ATT_P(bound_sat_dps, 0, "drift rate per saturated gyro axis, deg/s"),
    ATT_P(bound_lever_m, 0, "with aiding: the sensor's largest distance from the rear axle, m"),
    ATT_P(bound_limit_deg, 0, "valid only while the bound is at most this, deg"),
    ATT_P(fault_hold_s, 0, "invalid this long after a fault, s"),
};
#define N_ATT_PARAMS (sizeof att_params / sizeof att_params[0])

struct att_set {
    const struct att_param *p;
    double v;
};

/* ---- Options ------------------------------------------------------------------------------ */

enum estimator { EST_ATT, EST_ADAPT, EST_TILT };

struct opts {
    const struct part *part;
    const char *in, *out, *record;
    bool calibrated, blocks_only, no_aiding;
    int estimator;
    int tilt_mode;
    double block_s, gap_factor, rate_sps, gyro_fs, acc_fs;
    unsigned revid;
    struct frame frame;
    struct att_set att[N_ATT_PARAMS];
    size_t n_att;
    double nonlin_mg, temp_comp_mg, temp_uncomp_mg, offset_mg, sens_ppm, noise_mg;
};

static void usage(FILE *f)
{
    size_t i;
    struct att_config d;
    (void)att_config_default(&d, FX_Q16_INT(100));
    fprintf(
        f,
        "usage: imu_replay [options] IN.csv[.gz]   (IN may be - for standard input)\n"
        "  --estimator NAME   att (default): the 3D attitude estimator; adapt: the patented\n"
        "                     per-axis method (adaptive filter + angle stage); tilt: the angle\n"
        "                     stage alone\n"
        "  --tilt-mode MODE   adapt/tilt: feedback (default), printed, kf2\n"
        "  --att NAME=VALUE   att: set a parameter (list below); repeatable\n"
        "  --gyro-fs DPS      generic part: gyro full scale, deg/s (default 2000, 1..4000)\n"
        "  --acc-fs G         generic part: accelerometer full scale, g (default 16, 1..16)\n"
        "  --frame AXES       the estimator's x,y,z as signed sensor axes, e.g. -y,x,z (a\n"
        "                     rotation; default x,y,z); the output quaternion stays sensor to earth\n"
        "  --no-aiding        ignore the speed_mps / yaw_rate_dps columns\n"
        "  --part NAME        generic (default), adis16405, adis16400, adis16364, adis16362,\n"
        "                     adis16360, sca3000-d01, sca3000-e02, sca3000-e04, sca3000-e05\n"
        "  -o, --out FILE     output CSV (default: standard output)\n"
        "  --blocks           one row per slope estimate instead of one per sample\n"
        "  --record FILE      calibration record image (656 bytes, e.g. epb_demo --record-out)\n"
        "  --calibrated       the data is already calibrated (an identity record is used)\n"
        "  --block-s S        averaging block, s (default 2.5; rounded to stillness windows)\n"
        "  --rate SPS         nominal sample rate (default: from the median time step)\n"
        "  --gap-factor F     a step longer than F nominal periods is a gap (default 1.5)\n"
        "  --revid N          SCA3000 REVID for the record binding (default 0x52)\n"
        "  slope budget (default app_cfg_default's):\n"
        "  --nonlin-mg X --temp-comp-mg X --temp-uncomp-mg X --offset-mg X --sens-ppm X "
        "--noise-mg X\n"
        "att parameters (--att NAME=VALUE; default in brackets):\n");
    for (i = 0; i < N_ATT_PARAMS; i++) {
        const int32_t raw = *(const int32_t *)((const char *)&d + att_params[i].off);
        fprintf(f, "  %-20s %s [%g]\n", att_params[i].name, att_params[i].what,
                raw / (att_params[i].q30 ? 1073741824.0 : 65536.0));
    }
}

/* A number option through tools/lib/cli: decimal, the whole field, in [lo, hi]; the refusal
 * names the option and the range. */
static bool opt_num(const char *name, const char *s, double lo, double hi, double *out)
{
    if (s == NULL) {
        cli_error("%s needs a value", name);
        return false;
    }
    return cli_parse_double(name, s, lo, hi, 0, out) == INC_OK;
}

static bool parse_att(const char *s, struct opts *o)
{
    const char *eq = s != NULL ? strchr(s, '=') : NULL;
    size_t i;
    if (eq == NULL || o->n_att == N_ATT_PARAMS) return false;
    for (i = 0; i < N_ATT_PARAMS; i++) {
        if (strlen(att_params[i].name) == (size_t)(eq - s) &&
            strncmp(att_params[i].name, s, (size_t)(eq - s)) == 0) {
            o->att[o->n_att].p = &att_params[i];
            o->n_att++;
            return opt_num(att_params[i].name, eq + 1, att_params[i].q30 ? -1.99 : -32767.0,
                           att_params[i].q30 ? 1.99 : 32767.0, &o->att[o->n_att - 1u].v);
        }
    }
    return false;
}

static int parse_opts(int argc, char **argv, struct opts *o)
{
    int a;
    memset(o, 0, sizeof(*o));
    o->part = &parts[0];
    o->estimator = EST_ATT;
    o->tilt_mode = TILT_MODE_FEEDBACK;
    o->block_s = 2.5;
    o->gap_factor = 1.5;
    o->gyro_fs = 2000.0;
    o->acc_fs = 16.0;
    o->revid = SCA3000_REVID_DEFAULT;
    (void)frame_parse("x,y,z", &o->frame);
    o->nonlin_mg = o->temp_comp_mg = o->temp_uncomp_mg = o->offset_mg = o->sens_ppm = o->noise_mg =
        -1.0;
    for (a = 1; a < argc; a++) {
        const char *v = a + 1 < argc ? argv[a + 1] : NULL;
        const char *s = argv[a];
        bool ok = true;
        if (strcmp(s, "--part") == 0) {
            size_t i;
            ok = false;
            for (i = 0; v != NULL && i < N_PARTS; i++) {
                if (strcmp(v, parts[i].name) == 0) {
                    o->part = &parts[i];
                    ok = true;
                }
            }
            a++;
        } else if (strcmp(s, "--estimator") == 0) {
            ok = v != NULL;
            if (ok && strcmp(v, "att") == 0)
                o->estimator = EST_ATT;
            else if (ok && strcmp(v, "adapt") == 0)
                o->estimator = EST_ADAPT;
            else if (ok && strcmp(v, "tilt") == 0)
                o->estimator = EST_TILT;
            else
                ok = false;
            a++;
        } else if (strcmp(s, "--tilt-mode") == 0) {
            ok = v != NULL;
            if (ok && strcmp(v, "feedback") == 0)
                o->tilt_mode = TILT_MODE_FEEDBACK;
            else if (ok && strcmp(v, "printed") == 0)
                o->tilt_mode = TILT_MODE_SEED_PRINTED;
            else if (ok && strcmp(v, "kf2") == 0)
                o->tilt_mode = TILT_MODE_KF2;
            else
                ok = false;
            a++;
        } else if (strcmp(s, "--att") == 0) {
            ok = parse_att(v, o);
            a++;
        } else if (strcmp(s, "--gyro-fs") == 0) {
            ok = opt_num(s, v, 1.0, 4000.0, &o->gyro_fs);
            a++;
        } else if (strcmp(s, "--acc-fs") == 0) {
            ok = opt_num(s, v, 1.0, 16.0, &o->acc_fs);
            a++;
        } else if (strcmp(s, "--frame") == 0) {
            ok = v != NULL && frame_parse(v, &o->frame);
            a++;
        } else if (strcmp(s, "--no-aiding") == 0) {
            o->no_aiding = true;
        } else if (strcmp(s, "-o") == 0 || strcmp(s, "--out") == 0) {
            ok = v != NULL;
            o->out = v;
            a++;
        } else if (strcmp(s, "--record") == 0) {
            ok = v != NULL;
            o->record = v;
            a++;
        } else if (strcmp(s, "--calibrated") == 0) {
            o->calibrated = true;
        } else if (strcmp(s, "--blocks") == 0) {
            o->blocks_only = true;
        } else if (strcmp(s, "--block-s") == 0) {
            ok = opt_num(s, v, 0.001, 3600.0, &o->block_s);
            a++;
        } else if (strcmp(s, "--rate") == 0) {
            ok = opt_num(s, v, 10.0, 10000.0, &o->rate_sps);
            a++;
        } else if (strcmp(s, "--gap-factor") == 0) {
            ok = opt_num(s, v, 1.01, 1000.0, &o->gap_factor);
            a++;
        } else if (strcmp(s, "--revid") == 0) {
            uint32_t x = 0;
            ok = v != NULL && cli_parse_u32(s, v, 1, 254, &x) == INC_OK;
            o->revid = x;
            a++;
        } else if (strcmp(s, "--nonlin-mg") == 0) {
            ok = opt_num(s, v, 0.0, 1000.0, &o->nonlin_mg);
            a++;
        } else if (strcmp(s, "--temp-comp-mg") == 0) {
            ok = opt_num(s, v, 0.0, 1000.0, &o->temp_comp_mg);
            a++;
        } else if (strcmp(s, "--temp-uncomp-mg") == 0) {
            ok = opt_num(s, v, 0.0, 1000.0, &o->temp_uncomp_mg);
            a++;
        } else if (strcmp(s, "--offset-mg") == 0) {
            ok = opt_num(s, v, 0.0, 1000.0, &o->offset_mg);
            a++;
        } else if (strcmp(s, "--sens-ppm") == 0) {
            ok = opt_num(s, v, 0.0, 400000.0, &o->sens_ppm);
            a++;
        } else if (strcmp(s, "--noise-mg") == 0) {
            ok = opt_num(s, v, 0.0, 1000.0, &o->noise_mg);
            a++;
        } else if (strcmp(s, "-h") == 0 || strcmp(s, "--help") == 0) {
            usage(stdout);
            exit(0);
        } else if ((s[0] == '-' && s[1] != '\0') || o->in != NULL) {
            ok = false;
        } else {
            o->in = s;
        }
        if (!ok) {
            fprintf(stderr, "imu_replay: bad or missing value for '%s'\n", s);
            return 2;
        }
    }
    if (o->in == NULL) {
        fprintf(stderr, "imu_replay: no input file\n");
        return 2;
    }
    if (o->record != NULL && o->calibrated) {
        fprintf(stderr, "imu_replay: --record and --calibrated exclude each other\n");
        return 2;
    }
    return 0;
}

static fx_q16_t q16_mg(double mg)
{
    return (fx_q16_t)ceil(mg * 65.536);
}

static int32_t q16_of(double v)
{
    return (int32_t)lround(v * 65536.0);
}

/* ---- The attitude estimators behind one interface ------------------------------------------ */

struct est {
    int kind;
    struct att att;
    struct adapt_tilt adapt;
    struct tilt tilt;
};

static int est_init(struct est *e, const struct opts *o, double nominal, bool vehicle, char *msg,
                    size_t len)
{
    const uint32_t dt_ns = (uint32_t)fmin(fmax(nominal * 1e9 + 0.5, 1.0), 100e6);
    int err;
    e->kind = o->estimator;
    if (e->kind == EST_ATT) {
        struct att_config c;
        size_t i;
        err = att_config_default(&c, q16_of(1.0 / nominal));
        if (o->part->generic) {
            c.gyro_fs_dps = q16_of(o->gyro_fs);
            c.acc_fs_g = q16_of(o->acc_fs);
        } else if (o->part->adis) {
            /* The ADIS1636x/1640x output noise (about 0.9 deg/s and 9 mg rms per sample at
             * 819.2 SPS, docs/drivers-adis-imu.md) and a running engine's vibration keep the
             * default rest thresholds (tuned on a quieter IMU) from ever seeing rest: they scale
             * with the part's noise. */
            c.rest_gyro_dps = FX_Q16_INT(5);
            c.rest_acc_g = FX_Q16_ONE / 10;
            c.gyro_fs_dps = q16_of(409.55); /* 14-bit counts of 0.05 deg/s */
            /* the 14-bit output reaches 27 g; att takes at most 16 g (beyond: saturated) */
            c.acc_fs_g = q16_of(fmin(8191.0 * o->part->acc_lsb_ug * 1e-6, 16.0));
        } else {
            c.acc_fs_g = q16_of(4095.0 * o->part->acc_lsb_ug * 1e-6);
            c.gyro_fs_dps = FX_Q16_INT(100);
        }
        /* vehicle data (speed and yaw-rate columns, even when --no-aiding ignores them): the
         * car's rule, valid only with aiding (att.h require_aiding) */
        if (vehicle) c.require_aiding = 1u;
        for (i = 0; i < o->n_att; i++) {
            int32_t *f = (int32_t *)((char *)&c + o->att[i].p->off);
            *f = (int32_t)lround(o->att[i].v * (o->att[i].p->q30 ? 1073741824.0 : 65536.0));
        }
        if (err == INC_OK) err = att_init(&e->att, &c);
        if (err != INC_OK)
            snprintf(msg, len, "att_init refused the configuration (%s)", inc_err_name(err));
        return err;
    }
    if (e->kind == EST_ADAPT) {
        struct adapt_tilt_noise nz;
        struct adapt_tilt_config c;
        adapt_tilt_noise_default(&nz);
        err = adapt_tilt_config_default(&c, &nz, dt_ns);
        c.tilt.mode = (uint32_t)o->tilt_mode;
        if (err == INC_OK) err = adapt_tilt_init(&e->adapt, &c);
    } else {
        struct tilt_config c;
        err = tilt_config_default(&c, dt_ns);
        c.mode = (uint32_t)o->tilt_mode;
        if (err == INC_OK) err = tilt_init(&e->tilt, &c);
    }
    if (err != INC_OK) snprintf(msg, len, "estimator set-up failed (%s)", inc_err_name(err));
    return err;
}

struct est_out {
    double q[4]; /* estimator frame to earth */
    double roll, pitch, bound;
    bool valid, rest;
    unsigned fault;
};

/* quaternion of roll about x then pitch about y (yaw 0): R = Ry(pitch) Rx(roll) */
static void q_of_rp(double roll_deg, double pitch_deg, double q[4])
{
    const double r = roll_deg / RAD2DEG / 2.0, p = pitch_deg / RAD2DEG / 2.0;
    q[0] = cos(r) * cos(p);
    q[1] = sin(r) * cos(p);
    q[2] = cos(r) * sin(p);
    q[3] = -sin(r) * sin(p);
}

static int est_step(struct est *e, const int32_t g[3], const int32_t acc[3], unsigned sat, bool veh,
                    double speed, double yaw, uint32_t dt_ns, struct est_out *o, double limit_deg)
{
    int err;
    if (e->kind == EST_ATT) {
        struct att_sample s;
        int32_t q[4];
        fx_q16_t r, p;
        unsigned i;
        for (i = 0; i < 3u; i++) {
            s.gyro_dps[i] = g[i];
            s.acc_g[i] = acc[i];
        }
        s.sat = (uint8_t)sat;
        s.veh_valid = veh;
        s.speed_mps = veh ? q16_of(speed) : 0;
        s.yaw_rate_dps = veh ? q16_of(yaw) : 0;
        err = att_update(&e->att, &s);
        att_get_quat(&e->att, q);
        att_get_euler(&e->att, &r, &p);
        for (i = 0; i < 4u; i++)
            o->q[i] = q[i] / 1073741824.0;
        o->roll = r / 65536.0;
        o->pitch = p / 65536.0;
        o->bound = att_get_bound(&e->att) / 65536.0;
        o->valid = att_get_valid(&e->att);
        o->rest = att_get_rest(&e->att);
        o->fault = att_get_status(&e->att);
        return err == INC_ERR_RANGE ? INC_OK : err; /* a rejected sample is reported, not fatal */
    } else {
        struct tilt_input ti;
        struct tilt_output to;
        unsigned i;
        for (i = 0; i < 3u; i++) {
            ti.gyro_dps[i] = g[i];
            ti.accel_g[i] = acc[i];
        }
        ti.flags = ((sat & 1u) ? TILT_IN_GYRO_SAT_X : 0u) | ((sat & 2u) ? TILT_IN_GYRO_SAT_Y : 0u) |
                   ((sat & 0x38u) ? TILT_IN_ACCEL_SAT : 0u);
        err = e->kind == EST_ADAPT ? adapt_tilt_step(&e->adapt, &ti, dt_ns, &to, NULL)
                                   : tilt_step(&e->tilt, &ti, dt_ns, &to);
        if (err != INC_OK) return err;
        o->roll = to.angle_deg[TILT_ROLL] / 65536.0;
        o->pitch = to.angle_deg[TILT_PITCH] / 65536.0;
        q_of_rp(o->roll, o->pitch, o->q);
        /* The filter's own 1-sigma per axis as a 99.9 % bound of the inclination error
         * (3.29 sigma of the root sum of squares); docs/imu-replay.md says what this is worth. */
        o->bound = 3.29 * hypot(to.sigma_deg[0] / 65536.0, to.sigma_deg[1] / 65536.0);
        o->valid = to.valid && o->bound <= limit_deg;
        o->rest = false;
        o->fault = to.flags;
        return INC_OK;
    }
}

/* ---- Main ------------------------------------------------------------------------------------- */

struct counts {
    size_t rows, gyro_sat, acc_sat, rejected, valid, blocks, gaps;
    uint64_t missed; /* exact (a gap's count is below 2^53), never wrapped or clipped at 2^32 */
};

/* The att estimator runs at a fixed rate and steps over a gap sample by sample: a gap longer than
 * this (about 20 min at 819.2 SPS, 100 s at 10 kSPS) is refused as a broken time axis rather than
 * stepped for hours. The other estimators take a gap in one step and have no limit. */
#define ATT_GAP_MAX 1000000u

static int check_write(FILE *f, const char *name)
{
    if (ferror(f)) {
        fprintf(stderr, "imu_replay: write error on %s\n", name);
        return 2;
    }
    return 0;
}

int main(int argc, char **argv)
{
    static struct app app;
    static struct calstore store;
    static struct est est;
    struct opts o;
    struct rows t = {NULL, NULL, 0, false, false};
    struct app_cfg cfg;
    struct replay_id rid;
    const struct sensor sensor = {&replay_ops, &rid};
    struct app_result last;
    struct counts cnt;
    char msg[512] = "";
    double *dts, nominal, limit_deg = 5.0;
    uint32_t rate_mhz, windows;
    bool have_est = false, use_store = false, aiding;
    static struct cli_out out_file;
    FILE *out;
    size_t i;
    int err, status = 0;
    cli_set_program("imu_replay");
    err = parse_opts(argc, argv, &o);
    if (err != 0) {
        usage(stderr);
        return err;
    }
    err = read_rows(o.in, &t, msg, sizeof msg);
    if (err != 0) {
        fprintf(stderr, "imu_replay: %s\n", msg);
        return err;
    }
    memset(&cnt, 0, sizeof cnt);
    aiding = t.have_vehicle && !o.no_aiding;
    /* Nominal period: the option, or the median step of the recording. */
    dts = malloc((t.n - 1u) * sizeof(*dts));
    if (dts == NULL) {
        rows_free(&t);
        return 2;
    }
    for (i = 1; i < t.n; i++)
        dts[i - 1] = t.v[i * C_N] - t.v[(i - 1) * C_N];
    qsort(dts, t.n - 1u, sizeof(*dts), cmp_double);
    nominal = o.rate_sps > 0.0 ? 1.0 / o.rate_sps : dts[(t.n - 1u) / 2u];
    free(dts);
    if (!(nominal >= 1e-4 && nominal <= 0.1)) {
        fprintf(stderr, "imu_replay: a nominal period of %.6g s is outside 0.1 ms .. 100 ms\n",
                nominal);
        rows_free(&t);
        return 1;
    }
    rate_mhz = (uint32_t)fmin(fmax(1000.0 / nominal + 0.5, 10000.0), 10000000.0);
    for (i = 0; i < o.n_att; i++) {
        if (strcmp(o.att[i].p->name, "bound_limit_deg") == 0) limit_deg = o.att[i].v;
    }

    /* The application, configured as app_cfg_default for that rate, with the options. */
    (void)app_cfg_default(&cfg, rate_mhz);
    /* Clamped before the conversion: a file with microscopic time steps made this double exceed
     * uint32_t (undefined behaviour); app_init refuses a block that long anyway. */
    windows = (uint32_t)fmin(fmax(1.0, floor(o.block_s / nominal / cfg.still.window + 0.5)), 1e6);
    cfg.avg_n = windows * cfg.still.window;
    if (o.nonlin_mg >= 0.0) cfg.budget.nonlinearity_g = q16_mg(o.nonlin_mg);
    if (o.temp_comp_mg >= 0.0) cfg.budget.temp_comp_g = q16_mg(o.temp_comp_mg);
    if (o.temp_uncomp_mg >= 0.0) cfg.budget.temp_uncomp_g = q16_mg(o.temp_uncomp_mg);
    if (o.offset_mg >= 0.0) cfg.budget.offset_g = q16_mg(o.offset_mg);
    if (o.noise_mg >= 0.0) cfg.budget.noise_sigma_g = q16_mg(o.noise_mg);
    if (o.sens_ppm >= 0.0) cfg.budget.sensitivity = (fx_q30_t)ceil(o.sens_ppm * 1073.741824);

    /* Identity of the replayed part (calrec.h binding table; the generic part has none). */
    memset(&rid, 0, sizeof rid);
    if (o.part->adis) {
        rid.id.family = CALREC_FAMILY_ADIS163XX;
        rid.id.product = adis_imu_variant_info((enum adis_imu_variant)o.part->variant)->prod_id;
    } else if (!o.part->generic) {
        static const uint32_t code[4] = {CALREC_SCA3000_D01, CALREC_SCA3000_E02, CALREC_SCA3000_E04,
                                         CALREC_SCA3000_E05};
        rid.id.family = CALREC_FAMILY_SCA3000;
        rid.id.product = code[o.part->variant];
        rid.id.revision = o.revid;
    }
    if (o.record != NULL || o.calibrated) {
        static const struct simflash_geometry geo = {PAGE, 2u, PROG};
        static const struct calstore_config sc = {&simflash_calstore_ops, &flash,     PAGE, PROG,
                                                  CALSTORE_ERASED,        {0u, PAGE}, PAGE};
        struct calrec rec;
        if (simflash_init(&flash, flash_mem, sizeof flash_mem, &geo) != INC_OK ||
            calstore_init(&store, &sc) != INC_OK) {
            rows_free(&t);
            return 2;
        }
        if (o.record != NULL) {
            uint8_t img[CALREC_IMAGE_SIZE + 1];
            struct calrec_binding b;
            FILE *f = fopen(o.record, "rb");
            size_t len = f != NULL ? fread(img, 1, sizeof img, f) : 0u;
            if (f != NULL) fclose(f);
            if (len != CALREC_IMAGE_SIZE) {
                fprintf(stderr, "imu_replay: %s: not a %u-byte calibration record image\n",
                        o.record, CALREC_IMAGE_SIZE);
                rows_free(&t);
                return 2;
            }
            /* The recording has no part to read a serial number from: the record's serial and lot
             * ids are taken, the family, product and revision must be the chosen part's. */
            (void)calrec_image_binding(img, CALREC_IMAGE_SIZE, &b); /* the whole image is read */
            rid.id.serial = b.serial;
            rid.id.lot_id1 = b.lot_id1;
            rid.id.lot_id2 = b.lot_id2;
            err = calrec_decode(img, len, &b, &rec, NULL);
            if (err != INC_OK) {
                fprintf(stderr, "imu_replay: %s: the record is refused (%s)\n", o.record,
                        inc_err_name(err));
                rows_free(&t);
                return 2;
            }
        } else {
            calrec_set_default(&rec);
            rec.binding.family = rid.id.family;
            rec.binding.product = rid.id.product;
            rec.binding.revision = rid.id.revision;
            rec.binding.serial = rid.id.serial;
            rec.binding.lot_id1 = rid.id.lot_id1;
            rec.binding.lot_id2 = rid.id.lot_id2;
        }
        if (calstore_save(&store, &rec, NULL) != INC_OK) {
            rows_free(&t);
            return 2;
        }
        use_store = true;
    }
    err = app_init(&app, &cfg, &sensor, use_store ? &store : NULL);
    if (err != INC_OK) {
        fprintf(stderr, "imu_replay: set-up failed (%s)\n", inc_err_name(err));
        rows_free(&t);
        return 2;
    }
    if (est_init(&est, &o, nominal, t.have_vehicle, msg, sizeof msg) != INC_OK) {
        fprintf(stderr, "imu_replay: %s\n", msg);
        rows_free(&t);
        return 2;
    }
    fprintf(stderr,
            "imu_replay: %zu rows, %s, nominal %.3f ms (%.1f SPS), estimator %s, blocks of %u "
            "samples, calibration: %s%s\n",
            t.n, o.part->name, nominal * 1e3, 1.0 / nominal,
            o.estimator == EST_ATT ? "att" : (o.estimator == EST_ADAPT ? "adapt" : "tilt"),
            cfg.avg_n,
            app.cal_status == INC_OK
                ? (o.calibrated ? "data taken as calibrated" : "record loaded")
                : (app.cal_status == INC_ERR_NOT_CALIBRATED ? "none (uncalibrated)"
                                                            : inc_err_name(app.cal_status)),
            aiding ? ", vehicle aiding" : "");

    /* The output through the safe writer (tools/lib/cli): never the input or the record, a
     * FIFO, a symlink or a device; a temporary file renamed only when every write succeeded. */
    {
        const char *inputs[2];
        inputs[0] = o.in;
        inputs[1] = o.record;
        if (cli_out_open(&out_file, "--out", o.out != NULL ? o.out : "-", inputs, 2) != INC_OK) {
            rows_free(&t);
            return 2;
        }
        out = out_file.f;
    }
    fprintf(out, "t_s,q_w,q_x,q_y,q_z,roll_deg,pitch_deg,att_bound_deg,att_valid,att_rest,"
                 "att_fault,sat,line,dt_s,gap,accel_x_g,accel_y_g,accel_z_g,gyro_x_dps,"
                 "gyro_y_dps,gyro_z_dps,temp_c,block,slope_deg,grade_pct,bound_deg,bound_pct,"
                 "slope_flags,app_flags,valid\n");
    for (i = 0; i < t.n; i++) {
        const double *v = t.v + i * C_N;
        const double dt = i == 0 ? nominal : v[C_T] - t.v[(i - 1) * C_N + C_T];
        struct sensor_sample s;
        struct app_corrected c;
        struct app_result res;
        struct est_out eo;
        int32_t g[3], acc[3];
        double qo[4];
        uint64_t gap = 0, k;
        unsigned sat_axes, sat_est;
        bool done = false;
        quantise_row(o.part, v, t.have_temp, o.gyro_fs, o.acc_fs, &s, &sat_axes);
        if (dt > o.gap_factor * nominal) {
            /* times are at most IMU_CSV_TIME_MAX_S and nominal >= 0.1 ms: the count is exact in
             * double and far below 2^63; clipped anyway, never wrapped */
            const double g_samples = floor(dt / nominal + 0.5) - 1.0;
            gap = g_samples >= 9007199254740992.0 ? 9007199254740992u : (uint64_t)g_samples;
            if (gap == 0u) gap = 1u;
            if (o.estimator == EST_ATT && gap > ATT_GAP_MAX) {
                fprintf(stderr,
                        "imu_replay: line %ld: a gap of %llu samples (%.6g s) is longer than the "
                        "%u the att estimator steps over; split the recording\n",
                        t.line[i], (unsigned long long)gap, dt, ATT_GAP_MAX);
                status = 1;
                break;
            }
            cnt.gaps++;
            cnt.missed += gap;
        }
        /* the sample's field is 32-bit: saturated (the application saturates its sum too) */
        s.missed = gap > UINT32_MAX ? UINT32_MAX : (uint32_t)gap;
        s.t_ns = (uint64_t)(v[C_T] * 1e9 + 0.5);
        err = app_step(&app, &s, INC_OK, &c, &done, &res);
        if (err != INC_OK) {
            fprintf(stderr, "imu_replay: line %ld: app_step failed (%s)\n", t.line[i],
                    inc_err_name(err));
            status = 2;
            break;
        }
        frame_apply(&o.frame, c.gyro_dps, g);
        frame_apply(&o.frame, c.accel_g, acc);
        sat_est = frame_sat(&o.frame, sat_axes);
        /* A gap: the estimator steps over the missed samples with this one (the real interval);
         * att runs at a fixed rate, so it takes the sample once per period. */
        memset(&eo, 0, sizeof eo);
        for (k = 0; k <= (o.estimator == EST_ATT ? gap : 0u); k++) {
            err = est_step(&est, g, acc, sat_est, aiding, v[C_SPEED], v[C_YAW],
                           (uint32_t)fmin(fmax(dt * 1e9 + 0.5, 1.0), 4294967295.0), &eo, limit_deg);
            if (err != INC_OK) break;
        }
        if (err != INC_OK) {
            fprintf(stderr, "imu_replay: line %ld: the estimator failed (%s)\n", t.line[i],
                    inc_err_name(err));
            status = 2;
            break;
        }
        cnt.rows++;
        if (sat_axes & 7u) cnt.gyro_sat++;
        if (sat_axes & 0x38u) cnt.acc_sat++;
        if (eo.fault != 0u && o.estimator == EST_ATT) cnt.rejected++;
        if (eo.valid) cnt.valid++;
        if (done) {
            last = res;
            have_est = true;
            cnt.blocks++;
        }
        if (o.blocks_only && !done) continue;
        /* Output sensor to earth: q_est (estimator frame to earth) * q_frame (sensor to estimator
         * frame). frame.q maps sensor vectors into the estimator frame. */
        qmul(eo.q, o.frame.q, qo);
        fprintf(out,
                "%.9f,%.9f,%.9f,%.9f,%.9f,%.6f,%.6f,%.6f,%d,%d,%u,%u,%ld,%.9f,%llu,%.7f,%.7f,%.7f,"
                "%.6f,%.6f,%.6f,%.5f,%zu",
                v[C_T], qo[0], qo[1], qo[2], qo[3], eo.roll, eo.pitch, eo.bound, eo.valid ? 1 : 0,
                eo.rest ? 1 : 0, eo.fault, sat_axes, t.line[i], dt, (unsigned long long)gap,
                c.accel_g[0] / 65536.0, c.accel_g[1] / 65536.0, c.accel_g[2] / 65536.0,
                c.gyro_dps[0] / 65536.0, c.gyro_dps[1] / 65536.0, c.gyro_dps[2] / 65536.0,
                c.temp_c / 65536.0, cnt.blocks);
        if (have_est) {
            fprintf(out, ",%.6f,%.6f,%.6f,%.6f,%u,%u,%d\n", last.slope.slope_deg / 65536.0,
                    last.slope.grade_pct / 65536.0, last.slope.bound_deg / 65536.0,
                    last.slope.bound_pct / 65536.0, last.slope.flags, last.flags,
                    last.valid ? 1 : 0);
        } else {
            fprintf(out, ",,,,,,,\n");
        }
    }
    if (status == 0) status = check_write(out, o.out != NULL ? o.out : "standard output");
    if (status != 0) {
        cli_out_discard(&out_file);
    } else if (cli_out_close(&out_file) != INC_OK) {
        status = 2;
    }
    fprintf(stderr, "imu_replay: %zu estimates, %zu gaps (%llu samples missed)", cnt.blocks,
            cnt.gaps, (unsigned long long)cnt.missed);
    if (have_est) {
        fprintf(stderr, "; last: slope %.4f deg (%.3f %%) +- %.4f deg, %s",
                last.slope.slope_deg / 65536.0, last.slope.grade_pct / 65536.0,
                last.slope.bound_deg / 65536.0, last.valid ? "valid" : "NOT valid");
    }
    fprintf(stderr, "\n");
    fprintf(stderr,
            "summary: rows=%zu estimator=%s part=%s gyro_sat_rows=%zu acc_sat_rows=%zu "
            "att_fault_rows=%zu valid_rows=%zu valid_frac=%.5f blocks=%zu gaps=%zu missed=%llu "
            "last_slope_deg=%.4f last_slope_valid=%d status=%d\n",
            cnt.rows,
            o.estimator == EST_ATT ? "att" : (o.estimator == EST_ADAPT ? "adapt" : "tilt"),
            o.part->name, cnt.gyro_sat, cnt.acc_sat, cnt.rejected, cnt.valid,
            cnt.rows ? (double)cnt.valid / (double)cnt.rows : 0.0, cnt.blocks, cnt.gaps,
            (unsigned long long)cnt.missed, have_est ? last.slope.slope_deg / 65536.0 : 0.0,
            have_est && last.valid ? 1 : 0, status);
    rows_free(&t);
    return status;
}
