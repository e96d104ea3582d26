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

static int split(char *line, char **f)
{
    int n = 0;
    char *p = line;
    for (;;) {
        char *c = strchr(p, ',');
        if (n == IMU_CSV_MAX_FIELDS) return n + 1;
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
        n = split(s, f);
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
