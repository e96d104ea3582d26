/*
 * imu_replay - run a CSV of recorded IMU data through the firmware pipeline (docs/imu-replay.md).
 *
 *   imu_replay [options] IN.csv
 *
 * Every row is quantised to the chosen part's LSBs and output range and converted back with the
 * driver's own conversions, so the firmware sees exactly what it would read from that part; then
 * the EPB application (firmware/app: calibration, stillness, block average, slope with its bound)
 * and the tilt filter (firmware/signal/tilt: roll and pitch, [CN110567483] step 4) run on it, sample by
 * sample, with the real time step of each row. The estimates are written as CSV.
 *
 * Input: lines starting with '#' and blank lines are skipped; an optional header line (every
 * field a name: non-empty and not a number); then rows of 7 or 8 comma-separated numbers:
 *   time (s), gyro x, y, z (deg/s), accel x, y, z (g) [, temperature (degC)]
 * Time must increase strictly. A step longer than --gap-factor nominal periods is a gap: the
 * samples missed are counted (column gap) and the filters integrate over the real step. Any bad
 * row (a field that is not a number, NaN or infinite, the wrong number of fields, time not
 * increasing) stops the run before anything is written, with the line named. Exit status 0,
 * 1 for bad input (the message names the line), 2 for bad options or files.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "inclino/adis_imu.h"
#include "inclino/app.h"
#include "inclino/calstore.h"
#include "inclino/sim/imu_csv.h"
#include "inclino/simflash.h"
#include "inclino/sca3000.h"
#include "inclino/tilt.h"


/* ---- Parts ---------------------------------------------------------------------------------- */

struct part {
    const char *name;
    bool adis;
    uint32_t acc_lsb_ug; /* ADIS: the variant's LSB; SCA3000: sca3000_ug_per_lsb */
    int variant;         /* enum adis_imu_variant / enum sca3000_variant */
    int family_1640x;    /* ADIS: 1 = 1640x (TEMP_OUT 0.14), 0 = 1636x (0.136) */
    bool temp;           /* the part has a temperature output */
};

static const struct part parts[] = {
    {"adis16405", true, 3333u, ADIS_IMU_ADIS16405, 1, true},
    {"adis16400", true, 3333u, ADIS_IMU_ADIS16400, 1, true},
    {"adis16364", true, 1000u, ADIS_IMU_ADIS16364, 0, true},
    {"adis16362", true, 333u, ADIS_IMU_ADIS16362, 0, true},
    {"adis16360", true, 3333u, ADIS_IMU_ADIS16360, 0, true},
    {"sca3000-d01", false, 750u, SCA3000_D01, 0, true},
    {"sca3000-e02", false, 1000u, SCA3000_E02, 0, false},
    {"sca3000-e04", false, 2000u, SCA3000_E04, 0, false},
    {"sca3000-e05", false, 6250u, SCA3000_E05, 0, false},
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

/* One row as the part would deliver it (nominal-scaled Q16, inclino/sensor.h). */
static void quantise_row(const struct part *p, const double *v, bool have_temp,
                         struct sensor_sample *s)
{
    bool tsat = false;
    unsigned i;
    memset(s, 0, sizeof(*s));
    s->flags = SENSOR_S_HAVE_ACCEL | (p->adis ? SENSOR_S_HAVE_GYRO : 0u);
    for (i = 0; i < 3u; i++) {
        bool asat = false, gsat = false;
        if (p->adis) {
            const int32_t ca = quant(v[4 + i] * 1e6, (double)p->acc_lsb_ug, -8192, 8191, &asat);
            const int32_t cg = quant(v[1 + i], 0.05, -8192, 8191, &gsat);
            (void)adis_imu_accel_g_from_counts(ca, p->acc_lsb_ug, &s->accel_g[i]);
            (void)adis_imu_gyro_dps_from_counts(cg, ADIS_IMU_RANGE_300, &s->gyro_dps[i]);
            asat = asat || ca <= -8192 || ca >= 8191;
            gsat = gsat || cg <= -8192 || cg >= 8191;
        } else {
            int32_t g = 0;
            const int32_t ca = quant(v[4 + i] * 1e6, (double)p->acc_lsb_ug, -4096, 4095, &asat);
            (void)sca3000_accel_g_from_counts(ca, (enum sca3000_variant)p->variant, &g);
            s->accel_g[i] = g;
            asat = asat || ca <= -4096 || ca >= 4095;
        }
        if (asat) s->flags |= SENSOR_S_ACCEL_SAT_X << i;
        if (gsat) s->flags |= SENSOR_S_GYRO_SAT_X << i;
    }
    if (have_temp && p->temp) {
        if (p->adis) {
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

/* ---- CSV: inclino/sim/imu_csv.h ----------------------------------------------------------------- */

static int read_table(const char *path, struct imu_csv_table *t, char *msg, size_t msg_len)
{
    FILE *in = fopen(path, "r");
    int err;
    if (in == NULL) {
        snprintf(msg, msg_len, "%s: cannot open (%s)", path, strerror(errno));
        return 2;
    }
    err = imu_csv_read(in, path, t, msg, msg_len);
    fclose(in);
    return err == INC_OK ? 0 : (err == INC_ERR_FORMAT ? 1 : 2);
}

static int cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : (x > y ? 1 : 0);
}

/* ---- An emulated flash (sim_flash): the calibration is loaded the way the firmware loads it ---- */

#define PAGE 1024u
#define PROG 8u
static uint8_t flash_mem[2u * PAGE];
static struct simflash flash;

/* ---- The replay sensor: a struct sensor whose samples are the recorded rows, quantised as the
 * chosen part would deliver them, and whose identity is that part's ----------------------------- */

struct replay {
    struct sensor_identity id;
    const struct part *part;
    const struct imu_csv_table *t;
    double nominal, gap_factor; /* s; a step longer than gap_factor x nominal is a gap */
    size_t next;                /* the row the next read delivers */
};

static int replay_wait(void *dev, uint32_t timeout_ns)
{
    const struct replay *rp = dev;
    (void)timeout_ns;
    return rp->next < rp->t->n ? INC_OK : INC_ERR_TIMEOUT; /* a recording has no pacing */
}

static int replay_read(void *dev, struct sensor_sample *out)
{
    struct replay *rp = dev;
    const struct imu_csv_row *r;
    double dt;
    if (rp->next >= rp->t->n) {
        return INC_ERR_TIMEOUT; /* the recording is over */
    }
    r = &rp->t->rows[rp->next];
    dt = rp->next == 0u ? rp->nominal : r->v[0] - rp->t->rows[rp->next - 1u].v[0];
    quantise_row(rp->part, r->v, rp->t->cols == 8, out);
    out->missed = 0u;
    if (dt > rp->gap_factor * rp->nominal) {
        out->missed = (uint32_t)fmin(floor(dt / rp->nominal + 0.5) - 1.0, 4e9);
        if (out->missed == 0u) out->missed = 1u;
    }
    out->t_ns = (uint64_t)(r->v[0] * 1e9 + 0.5);
    rp->next++;
    return INC_OK;
}

static int replay_identity(void *dev, struct sensor_identity *out)
{
    *out = ((const struct replay *)dev)->id;
    return INC_OK;
}

static const struct sensor_ops replay_ops = {NULL, replay_wait,     replay_read, NULL,
                                             NULL, replay_identity, NULL};

/* ---- Options ----------------------------------------------------------------------------------- */

struct opts {
    const struct part *part;
    const char *in, *out, *record;
    bool calibrated, blocks_only;
    double block_s, gap_factor, rate_sps;
    unsigned revid;
    double nonlin_mg, temp_comp_mg, temp_uncomp_mg, offset_mg, sens_ppm, noise_mg;
};

static void usage(void)
{
    fprintf(
        stderr,
        "usage: imu_replay [options] IN.csv\n"
        "  --part NAME        adis16405 (default), adis16400, adis16364, adis16362, adis16360,\n"
        "                     sca3000-d01, sca3000-e02, sca3000-e04, sca3000-e05\n"
        "  -o, --out FILE     estimates CSV (default: standard output)\n"
        "  --blocks           one row per slope estimate instead of one per sample\n"
        "  --record FILE      calibration record image (656 bytes, e.g. epb_demo --record-out)\n"
        "  --calibrated       the data is already calibrated (an identity record is used)\n"
        "  --block-s S        averaging block, s (default 2.5; rounded to stillness windows)\n"
        "  --rate SPS         nominal sample rate (default: from the median time step)\n"
        "  --gap-factor F     a step longer than F nominal periods is a gap (default 1.5)\n"
        "  --revid N          SCA3000 REVID for the record binding (default 0x52)\n"
        "  budget (default [ADI-EPB] Table 1, app_cfg_default):\n"
        "  --nonlin-mg X --temp-comp-mg X --temp-uncomp-mg X --offset-mg X --sens-ppm X --noise-mg X\n");
}

static bool opt_num(const char *s, double lo, double hi, double *out)
{
    double d;
    if (s == NULL || imu_csv_number(s, &d) != 0 || d < lo || d > hi) return false;
    *out = d;
    return true;
}

static int parse_opts(int argc, char **argv, struct opts *o)
{
    int a;
    memset(o, 0, sizeof(*o));
    o->part = &parts[0];
    o->block_s = 2.5;
    o->gap_factor = 1.5;
    o->revid = SCA3000_REVID_DEFAULT;
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
            ok = opt_num(v, 0.001, 3600.0, &o->block_s);
            a++;
        } else if (strcmp(s, "--rate") == 0) {
            ok = opt_num(v, 10.0, 10000.0, &o->rate_sps);
            a++;
        } else if (strcmp(s, "--gap-factor") == 0) {
            ok = opt_num(v, 1.01, 1000.0, &o->gap_factor);
            a++;
        } else if (strcmp(s, "--revid") == 0) {
            char *end = NULL;
            const unsigned long x = v != NULL ? strtoul(v, &end, 0) : 0ul;
            ok = v != NULL && *v != '\0' && *end == '\0' && x >= 1u && x <= 254u;
            o->revid = (unsigned)x;
            a++;
        } else if (strcmp(s, "--nonlin-mg") == 0) {
            ok = opt_num(v, 0.0, 1000.0, &o->nonlin_mg);
            a++;
        } else if (strcmp(s, "--temp-comp-mg") == 0) {
            ok = opt_num(v, 0.0, 1000.0, &o->temp_comp_mg);
            a++;
        } else if (strcmp(s, "--temp-uncomp-mg") == 0) {
            ok = opt_num(v, 0.0, 1000.0, &o->temp_uncomp_mg);
            a++;
        } else if (strcmp(s, "--offset-mg") == 0) {
            ok = opt_num(v, 0.0, 1000.0, &o->offset_mg);
            a++;
        } else if (strcmp(s, "--sens-ppm") == 0) {
            ok = opt_num(v, 0.0, 400000.0, &o->sens_ppm);
            a++;
        } else if (strcmp(s, "--noise-mg") == 0) {
            ok = opt_num(v, 0.0, 1000.0, &o->noise_mg);
            a++;
        } else if (strcmp(s, "-h") == 0 || strcmp(s, "--help") == 0) {
            usage();
            exit(0);
        } else if (s[0] == '-' || o->in != NULL) {
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

/* ---- Main ------------------------------------------------------------------------------------- */

int main(int argc, char **argv)
{
    static struct app app;
    static struct calstore store;
    static struct tilt tilt;
    struct opts o;
    struct imu_csv_table t = {NULL, 0, 0, 0};
    struct app_cfg cfg;
    struct tilt_config tc;
    struct replay rid;
    struct sensor sensor = {&replay_ops, &rid};
    struct app_result last;
    char msg[512] = "";
    double *dts, nominal, period;
    uint32_t rate_mhz, windows, blocks = 0, gaps = 0, missed_total = 0;
    bool have_est = false, use_store = false;
    FILE *out;
    size_t i;
    int err = parse_opts(argc, argv, &o);
    if (err != 0) {
        usage();
        return err;
    }
    err = read_table(o.in, &t, msg, sizeof msg);
    if (err != 0) {
        fprintf(stderr, "imu_replay: %s\n", msg);
        free(t.rows);
        return err;
    }
    /* Nominal period: the option, or the median step of the recording. */
    dts = malloc((t.n - 1u) * sizeof(*dts));
    if (dts == NULL) {
        free(t.rows);
        return 2;
    }
    for (i = 1; i < t.n; i++)
        dts[i - 1] = t.rows[i].v[0] - t.rows[i - 1].v[0];
    qsort(dts, t.n - 1u, sizeof(*dts), cmp_double);
    nominal = o.rate_sps > 0.0 ? 1.0 / o.rate_sps : dts[(t.n - 1u) / 2u];
    free(dts);
    rate_mhz = (uint32_t)fmin(fmax(1000.0 / nominal + 0.5, 10000.0), 10000000.0);

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

    /* Identity of the replayed part (struct sensor_identity, as the driver reports it). */
    memset(&rid, 0, sizeof rid);
    rid.part = o.part;
    rid.t = &t;
    rid.nominal = nominal;
    rid.gap_factor = o.gap_factor;
    if (o.part->adis) {
        rid.id.family = SENSOR_FAMILY_ADIS163XX;
        rid.id.product = adis_imu_variant_info((enum adis_imu_variant)o.part->variant)->prod_id;
    } else {
        static const uint32_t code[4] = {SCA3000_PRODUCT_D01, SCA3000_PRODUCT_E02,
                                         SCA3000_PRODUCT_E04, SCA3000_PRODUCT_E05};
        rid.id.family = SENSOR_FAMILY_SCA3000;
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
            free(t.rows);
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
                free(t.rows);
                return 2;
            }
            /* The recording has no part to read a serial number from: the record's serial and lot
             * ids are taken, the family, product and revision must be the chosen part's. */
            b.family = calrec_get_le32(&img[CALREC_OFF_BINDING]);
            b.product = calrec_get_le32(&img[CALREC_OFF_BINDING + 4u]);
            b.revision = calrec_get_le32(&img[CALREC_OFF_BINDING + 8u]);
            b.serial = calrec_get_le32(&img[CALREC_OFF_BINDING + 12u]);
            b.lot_id1 = calrec_get_le32(&img[CALREC_OFF_BINDING + 16u]);
            b.lot_id2 = calrec_get_le32(&img[CALREC_OFF_BINDING + 20u]);
            rid.id.serial = b.serial;
            rid.id.lot_id1 = b.lot_id1;
            rid.id.lot_id2 = b.lot_id2;
            err = calrec_decode(img, len, &b, &rec, NULL);
            if (err != INC_OK) {
                fprintf(stderr, "imu_replay: %s: the record is refused (%s)\n", o.record,
                        inc_err_name(err));
                free(t.rows);
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
            free(t.rows);
            return 2;
        }
        use_store = true;
    }
    err = app_init(&app, &cfg, &sensor, use_store ? &store : NULL);
    if (err == INC_OK) {
        err = tilt_config_default(&tc, (uint32_t)fmin(fmax(nominal * 1e9, 1.0), 100e6));
    }
    if (err == INC_OK) {
        err = tilt_init(&tilt, &tc);
    }
    if (err != INC_OK) {
        fprintf(stderr, "imu_replay: set-up failed (%s)\n", inc_err_name(err));
        free(t.rows);
        return 2;
    }
    fprintf(
        stderr,
        "imu_replay: %zu rows, %s, nominal %.3f ms (%.1f SPS), blocks of %u samples, calibration: %s\n",
        t.n, o.part->name, nominal * 1e3, 1.0 / nominal, cfg.avg_n,
        app.cal_status == INC_OK
            ? (o.calibrated ? "data taken as calibrated" : "record loaded")
            : (app.cal_status == INC_ERR_NOT_CALIBRATED ? "none (uncalibrated)"
                                                        : inc_err_name(app.cal_status)));

    out = o.out != NULL ? fopen(o.out, "w") : stdout;
    if (out == NULL) {
        fprintf(stderr, "imu_replay: cannot write %s\n", o.out);
        free(t.rows);
        return 2;
    }
    fprintf(
        out,
        "line,time_s,dt_s,gap,accel_x_g,accel_y_g,accel_z_g,gyro_x_dps,gyro_y_dps,gyro_z_dps,temp_c,"
        "roll_deg,pitch_deg,roll_sigma_deg,pitch_sigma_deg,tilt_flags,tilt_valid,"
        "block,slope_deg,grade_pct,bound_deg,bound_pct,slope_flags,app_flags,valid\n");
    period = nominal;
    for (i = 0; i < t.n; i++) {
        const struct imu_csv_row *r = &t.rows[i];
        const double dt = i == 0 ? period : r->v[0] - t.rows[i - 1].v[0];
        struct sensor_sample s;
        struct app_corrected c;
        struct app_result res;
        struct tilt_input ti;
        struct tilt_output to;
        uint32_t gap = 0;
        bool done = false;
        unsigned k;
        err = sensor_next(&sensor, 0u, &s); /* row i, as the part would deliver it */
        if (err != INC_OK) {
            fprintf(stderr, "imu_replay: line %ld: the replay sensor failed (%s)\n", r->line,
                    inc_err_name(err));
            break;
        }
        gap = s.missed;
        if (gap != 0u) {
            gaps++;
            missed_total += gap;
        }
        err = app_step(&app, &s, INC_OK, &c, &done, &res);
        if (err != INC_OK) {
            fprintf(stderr, "imu_replay: line %ld: app_step failed (%s)\n", r->line,
                    inc_err_name(err));
            break;
        }
        for (k = 0; k < 3u; k++) {
            ti.accel_g[k] = c.accel_g[k];
            ti.gyro_dps[k] = c.gyro_dps[k];
        }
        ti.flags = ((c.flags & SENSOR_S_GYRO_SAT) ? TILT_IN_GYRO_SAT_X | TILT_IN_GYRO_SAT_Y : 0u) |
                   ((c.flags & SENSOR_S_ACCEL_SAT) ? TILT_IN_ACCEL_SAT : 0u);
        /* The real step of this row (a gap integrates over its whole length, or restarts). */
        err = tilt_step(&tilt, &ti, (uint32_t)fmin(fmax(dt * 1e9 + 0.5, 1.0), 4294967295.0), &to);
        if (err != INC_OK) {
            fprintf(stderr, "imu_replay: line %ld: tilt_step failed (%s)\n", r->line,
                    inc_err_name(err));
            break;
        }
        if (done) {
            last = res;
            have_est = true;
            blocks++;
        }
        if (o.blocks_only && !done) continue;
        fprintf(out,
                "%ld,%.9f,%.9f,%u,%.7f,%.7f,%.7f,%.6f,%.6f,%.6f,%.5f,%.6f,%.6f,%.6f,%.6f,%u,%d,%u",
                r->line, r->v[0], dt, gap, c.accel_g[0] / 65536.0, c.accel_g[1] / 65536.0,
                c.accel_g[2] / 65536.0, c.gyro_dps[0] / 65536.0, c.gyro_dps[1] / 65536.0,
                c.gyro_dps[2] / 65536.0, c.temp_c / 65536.0, to.angle_deg[TILT_ROLL] / 65536.0,
                to.angle_deg[TILT_PITCH] / 65536.0, to.sigma_deg[TILT_ROLL] / 65536.0,
                to.sigma_deg[TILT_PITCH] / 65536.0, to.flags, to.valid ? 1 : 0, blocks);
        if (have_est) {
            fprintf(out, ",%.6f,%.6f,%.6f,%.6f,%u,%u,%d\n", last.slope.slope_deg / 65536.0,
                    last.slope.grade_pct / 65536.0, last.slope.bound_deg / 65536.0,
                    last.slope.bound_pct / 65536.0, last.slope.flags, last.flags,
                    last.valid ? 1 : 0);
        } else {
            fprintf(out, ",,,,,,,\n");
        }
    }
    if (out != stdout && fclose(out) != 0) {
        fprintf(stderr, "imu_replay: write error on %s\n", o.out);
        err = INC_ERR_IO;
    }
    fprintf(stderr, "imu_replay: %u estimates, %u gaps (%u samples missed)", blocks, gaps,
            missed_total);
    if (have_est) {
        fprintf(stderr, "; last: slope %.4f deg (%.3f %%) +- %.4f deg, %s",
                last.slope.slope_deg / 65536.0, last.slope.grade_pct / 65536.0,
                last.slope.bound_deg / 65536.0, last.valid ? "valid" : "NOT valid");
    }
    fprintf(stderr, "\n");
    free(t.rows);
    return err == INC_OK ? 0 : 2;
}
