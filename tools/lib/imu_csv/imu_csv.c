/* imu_csv.c - the recorded-IMU CSV reader (see inclino/sim/imu_csv.h, docs/imu-replay.md). */
#include "inclino/sim/imu_csv.h"

#include <errno.h>
#include <math.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "inclino/error.h"
#include "inclino/sim/line.h"

static char *trim(char *s)
{
    char *e;
    while (*s == ' ' || *s == '\t')
        s++;
    e = s + strlen(s);
    while (e > s && (e[-1] == ' ' || e[-1] == '\t' || e[-1] == '\r' || e[-1] == '\n'))
        e--;
    *e = '\0';
    return s;
}

/* Split line at commas into at most max trimmed fields; max + 1 when there are more. */
static int split(char *line, char **f, int max)
{
    int n = 0;
    char *p = line;
    for (;;) {
        char *c = strchr(p, ',');
        if (n == max) return n + 1;
        f[n++] = trim(p);
        if (c == NULL) return n;
        *c = '\0';
        p = c + 1;
    }
}

int imu_csv_number(const char *s, double *out)
{
    char *end;
    if (*s == '\0') return 1;
    errno = 0;
    *out = strtod(s, &end);
    if (*end != '\0') return 1;
    if (!isfinite(*out)) return 2;
    return 0;
}

static const char *const col_names[8] = {"time",    "gyro x",  "gyro y",  "gyro z",
                                         "accel x", "accel y", "accel z", "temperature"};

static int fail(struct imu_csv_table *t, int err)
{
    imu_csv_free(t);
    return err;
}

int imu_csv_read(FILE *in, const char *name, struct imu_csv_table *t, char *msg, size_t msg_len)
{
    char buf[IMU_CSV_MAX_LINE + 1];
    char *f[IMU_CSV_MAX_FIELDS + 1];
    long line = 0, cols_line = 0;
    bool first = true;
    int got;
    if (in == NULL || name == NULL || t == NULL || msg == NULL || msg_len == 0) {
        return INC_ERR_NULL;
    }
    memset(t, 0, sizeof(*t));
    msg[0] = '\0';
    while ((got = sim_read_line(in, buf, sizeof buf)) != SIM_LINE_EOF) {
        char *s;
        int n, k;
        struct imu_csv_row r;
        line++;
        if (got == SIM_LINE_TOO_LONG) {
            snprintf(msg, msg_len, "%s line %ld: longer than %d characters", name, line,
                     IMU_CSV_MAX_LINE);
            return fail(t, INC_ERR_FORMAT);
        }
        if (got == SIM_LINE_NUL) {
            snprintf(msg, msg_len, "%s line %ld: NUL byte in the line", name, line);
            return fail(t, INC_ERR_FORMAT);
        }
        if (got == SIM_LINE_IO) {
            snprintf(msg, msg_len, "%s: read error", name);
            return fail(t, INC_ERR_IO);
        }
        s = trim(buf);
        if (*s == '\0' || *s == '#') continue;
        n = split(s, f, IMU_CSV_MAX_FIELDS);
        if (first) {
            double d;
            int k2, named = 0;
            first = false;
            /* A header names every column: no field empty or a number. A first row whose time is
             * empty or garbled (",0.1,...", "n.5,0.1,...") used to be taken for a header and
             * dropped silently; it is a data row with a bad field. */
            for (k2 = 0; k2 < n && k2 < IMU_CSV_MAX_FIELDS; k2++) {
                named += f[k2][0] != '\0' && imu_csv_number(f[k2], &d) == 1;
            }
            if (named == n) {
                if (n != 7 && n != 8) {
                    snprintf(
                        msg, msg_len,
                        "%s line %ld: the header has %d columns; expected 7 (time, gyro x y z, "
                        "accel x y z) or 8 (and temperature)",
                        name, line, n);
                    return fail(t, INC_ERR_FORMAT);
                }
                t->cols = n;
                cols_line = line;
                continue;
            }
        }
        if (t->cols == 0) {
            if (n != 7 && n != 8) {
                snprintf(msg, msg_len,
                         "%s line %ld: %d fields; expected 7 (time, gyro x y z, accel x y z) or 8 "
                         "(and temperature)",
                         name, line, n);
                return fail(t, INC_ERR_FORMAT);
            }
            t->cols = n;
            cols_line = line;
        }
        if (n != t->cols) {
            snprintf(msg, msg_len, "%s line %ld: %d%s fields; expected %d as on line %ld", name,
                     line, n > IMU_CSV_MAX_FIELDS ? IMU_CSV_MAX_FIELDS : n,
                     n > IMU_CSV_MAX_FIELDS ? " or more" : "", t->cols, cols_line);
            return fail(t, INC_ERR_FORMAT);
        }
        for (k = 0; k < n; k++) {
            const int e = imu_csv_number(f[k], &r.v[k]);
            if (e != 0) {
                snprintf(msg, msg_len, "%s line %ld: field %d (%s) '%s' is %s", name, line, k + 1,
                         col_names[k], f[k], e == 1 ? "not a number" : "NaN or infinite");
                return fail(t, INC_ERR_FORMAT);
            }
        }
        /* The tool turns time into uint64 ns: a negative or huge time was undefined behaviour
         * there (a double outside the target's range converted to an integer). */
        if (!(r.v[0] >= 0.0 && r.v[0] <= IMU_CSV_TIME_MAX_S)) {
            snprintf(msg, msg_len, "%s line %ld: time %.9g s outside 0..%.0e s", name, line, r.v[0],
                     IMU_CSV_TIME_MAX_S);
            return fail(t, INC_ERR_FORMAT);
        }
        if (t->n > 0 && !(r.v[0] > t->rows[t->n - 1].v[0])) {
            snprintf(msg, msg_len, "%s line %ld: time %.9g s does not increase (line %ld: %.9g s)",
                     name, line, r.v[0], t->rows[t->n - 1].line, t->rows[t->n - 1].v[0]);
            return fail(t, INC_ERR_FORMAT);
        }
        r.line = line;
        if (t->n == t->cap) {
            size_t cap = t->cap ? 2u * t->cap : 1024u;
            struct imu_csv_row *nr = realloc(t->rows, cap * sizeof(*nr));
            if (nr == NULL) {
                snprintf(msg, msg_len, "out of memory");
                return fail(t, INC_ERR_NO_SPACE);
            }
            t->rows = nr;
            t->cap = cap;
        }
        t->rows[t->n++] = r;
    }
    if (t->n < 2u) {
        snprintf(msg, msg_len, "%s: %zu data rows; at least 2 are needed", name, t->n);
        return fail(t, INC_ERR_FORMAT);
    }
    return INC_OK;
}

void imu_csv_free(struct imu_csv_table *t)
{
    if (t != NULL) {
        free(t->rows);
        t->rows = NULL;
        t->n = t->cap = 0;
    }
}

/* ---- named columns ---------------------------------------------------------------------- */

static int named_fail(struct imu_csv_cols *t, int err)
{
    imu_csv_cols_free(t);
    return err;
}

int imu_csv_read_named(FILE *in, const char *name, const struct imu_csv_spec *spec, int nspec,
                       struct imu_csv_cols *t, char *msg, size_t msg_len)
{
    char buf[IMU_CSV_MAX_LINE + 1];
    char *f[IMU_CSV_NAMED_MAX_FIELDS + 1];
    int map[IMU_CSV_NAMED_MAX_COLS]; /* spec index -> field index, -1 absent */
    long line = 0;
    int fields = 0, i, got, time_col = -1;
    if (in == NULL || name == NULL || spec == NULL || t == NULL || msg == NULL || msg_len == 0) {
        return INC_ERR_NULL;
    }
    memset(t, 0, sizeof(*t));
    msg[0] = '\0';
    if (nspec < 1 || nspec > IMU_CSV_NAMED_MAX_COLS) return INC_ERR_INVAL;
    for (i = 0; i < nspec; i++) {
        map[i] = -1;
        if (spec[i].name == NULL) return INC_ERR_NULL;
        if ((spec[i].flags & IMU_CSV_TIME) != 0u) {
            if (time_col >= 0) return INC_ERR_INVAL;
            time_col = i;
        }
    }
    t->ncols = nspec;
    while ((got = sim_read_line(in, buf, sizeof buf)) != SIM_LINE_EOF) {
        char *s;
        int n;
        double row[IMU_CSV_NAMED_MAX_COLS];
        line++;
        if (got == SIM_LINE_TOO_LONG) {
            snprintf(msg, msg_len, "%s line %ld: longer than %d characters", name, line,
                     IMU_CSV_MAX_LINE);
            return named_fail(t, INC_ERR_FORMAT);
        }
        if (got == SIM_LINE_NUL) {
            snprintf(msg, msg_len, "%s line %ld: NUL byte in the line", name, line);
            return named_fail(t, INC_ERR_FORMAT);
        }
        if (got == SIM_LINE_IO) {
            snprintf(msg, msg_len, "%s: read error", name);
            return named_fail(t, INC_ERR_IO);
        }
        s = trim(buf);
        if (*s == '\0' || *s == '#') continue;
        n = split(s, f, IMU_CSV_NAMED_MAX_FIELDS);
        if (fields == 0) {
            /* The header: every wanted column found once by name; others are ignored. */
            int k;
            if (n > IMU_CSV_NAMED_MAX_FIELDS) {
                snprintf(msg, msg_len, "%s line %ld: more than %d columns", name, line,
                         IMU_CSV_NAMED_MAX_FIELDS);
                return named_fail(t, INC_ERR_FORMAT);
            }
            for (k = 0; k < n; k++) {
                for (i = 0; i < nspec; i++) {
                    if (strcmp(f[k], spec[i].name) != 0) continue;
                    if (map[i] >= 0) {
                        snprintf(msg, msg_len, "%s line %ld: column '%s' appears twice", name, line,
                                 spec[i].name);
                        return named_fail(t, INC_ERR_FORMAT);
                    }
                    map[i] = k;
                }
            }
            for (i = 0; i < nspec; i++) {
                t->present[i] = map[i] >= 0;
                if (map[i] < 0 && (spec[i].flags & IMU_CSV_OPTIONAL) == 0u) {
                    snprintf(msg, msg_len,
                             "%s line %ld: the header has no column '%s' (it needs at least: ",
                             name, line, spec[i].name);
                    for (k = 0; k < nspec; k++) {
                        if ((spec[k].flags & IMU_CSV_OPTIONAL) != 0u) continue;
                        size_t len = strlen(msg);
                        if (len + 2 < msg_len)
                            snprintf(msg + len, msg_len - len, "%s%s", spec[k].name,
                                     k + 1 < nspec ? "," : ")");
                    }
                    return named_fail(t, INC_ERR_FORMAT);
                }
            }
            fields = n;
            continue;
        }
        if (n != fields) {
            snprintf(msg, msg_len, "%s line %ld: %d%s fields; the header has %d", name, line,
                     n > IMU_CSV_NAMED_MAX_FIELDS ? IMU_CSV_NAMED_MAX_FIELDS : n,
                     n > IMU_CSV_NAMED_MAX_FIELDS ? " or more" : "", fields);
            return named_fail(t, INC_ERR_FORMAT);
        }
        for (i = 0; i < nspec; i++) {
            int e;
            if (map[i] < 0) {
                row[i] = NAN;
                continue;
            }
            e = imu_csv_number(f[map[i]], &row[i]);
            if (e == 2 && (spec[i].flags & IMU_CSV_NAN_OK) != 0u && isnan(row[i])) continue;
            if (e != 0) {
                snprintf(msg, msg_len, "%s line %ld: column '%s' field '%s' is %s", name, line,
                         spec[i].name, f[map[i]],
                         e == 1 ? "not a number"
                                : ((spec[i].flags & IMU_CSV_NAN_OK) != 0u ? "infinite"
                                                                          : "NaN or infinite"));
                return named_fail(t, INC_ERR_FORMAT);
            }
        }
        if (time_col >= 0) {
            const double tv = row[time_col];
            if (!(tv >= 0.0 && tv <= IMU_CSV_TIME_MAX_S)) {
                snprintf(msg, msg_len, "%s line %ld: time %.9g s outside 0..%.0e s", name, line, tv,
                         IMU_CSV_TIME_MAX_S);
                return named_fail(t, INC_ERR_FORMAT);
            }
            if (t->n > 0 && !(tv > t->v[(t->n - 1) * (size_t)nspec + (size_t)time_col])) {
                snprintf(msg, msg_len, "%s line %ld: time %.9g s does not increase (line %ld)",
                         name, line, tv, t->line[t->n - 1]);
                return named_fail(t, INC_ERR_FORMAT);
            }
        }
        if (t->n == t->cap) {
            size_t cap = t->cap ? 2u * t->cap : 4096u;
            double *nv = realloc(t->v, cap * (size_t)nspec * sizeof(*nv));
            long *nl;
            if (nv == NULL) {
                snprintf(msg, msg_len, "out of memory");
                return named_fail(t, INC_ERR_NO_SPACE);
            }
            t->v = nv;
            nl = realloc(t->line, cap * sizeof(*nl));
            if (nl == NULL) {
                snprintf(msg, msg_len, "out of memory");
                return named_fail(t, INC_ERR_NO_SPACE);
            }
            t->line = nl;
            t->cap = cap;
        }
        memcpy(&t->v[t->n * (size_t)nspec], row, (size_t)nspec * sizeof(double));
        t->line[t->n] = line;
        t->n++;
    }
    if (fields == 0) {
        snprintf(msg, msg_len, "%s: no header line", name);
        return named_fail(t, INC_ERR_FORMAT);
    }
    if (t->n < 1u) {
        snprintf(msg, msg_len, "%s: no data rows", name);
        return named_fail(t, INC_ERR_FORMAT);
    }
    return INC_OK;
}

void imu_csv_cols_free(struct imu_csv_cols *t)
{
    if (t != NULL) {
        free(t->v);
        free(t->line);
        t->v = NULL;
        t->line = NULL;
        t->n = t->cap = 0;
    }
}
