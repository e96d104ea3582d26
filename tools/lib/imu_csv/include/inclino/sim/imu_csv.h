/*
 * imu_csv.h - the recorded-IMU CSV reader of the imu_replay tool (docs/imu-replay.md), as a
 * library so that it can be tested on buffers (tests/fuzz) and not only through the tool.
 *
 * Input: lines starting with '#' and blank lines are skipped; an optional header line (every
 * field a name: non-empty and not a number); then rows of 7 or 8 comma-separated numbers:
 *   time (s), gyro x, y, z (deg/s), accel x, y, z (g) [, temperature (degC)]
 * Every field is a finite decimal number; time is in [0, IMU_CSV_TIME_MAX_S] and increases
 * strictly; every row has the column count of the first row (or of the header).
 */
#ifndef INCLINO_IMU_CSV_H
#define INCLINO_IMU_CSV_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

#define IMU_CSV_MAX_LINE 1024 /* characters per line, the newline not counted */
#define IMU_CSV_MAX_FIELDS 16
/* Largest time, s: the tool converts time to uint64 ns (limit 1.8e10 s); 1e10 s keeps a margin
 * and still takes Unix-epoch time stamps. */
#define IMU_CSV_TIME_MAX_S 1.0e10

struct imu_csv_row {
    double v[8]; /* time s, gyro x y z deg/s, accel x y z g, [temp degC] */
    long line;   /* 1-based line in the file */
};

struct imu_csv_table {
    struct imu_csv_row *rows; /* malloc'd; imu_csv_free() */
    size_t n, cap;
    int cols; /* 7 or 8 */
};

/*
 * Read the whole CSV from in. name is used in messages ("<name> line 5: ..."). Returns INC_OK
 * with t filled (at least 2 rows); INC_ERR_FORMAT for bad input (msg names the line and the
 * problem, docs/imu-replay.md); INC_ERR_IO for a read error; INC_ERR_NO_SPACE when memory runs
 * out; INC_ERR_NULL. On any error t holds no rows (n = 0, rows = NULL).
 */
int imu_csv_read(FILE *in, const char *name, struct imu_csv_table *t, char *msg, size_t msg_len);

/* One field: 0 when s is a finite number (in *out), 1 when it is not a number, 2 for NaN or inf. */
int imu_csv_number(const char *s, double *out);

/* Release the rows of t (t itself is the caller's). */
void imu_csv_free(struct imu_csv_table *t);

/* ---- Named columns (the BROAD benchmark's layout and other CSVs with a header) ------------
 *
 * The first line that is not blank or a '#' comment is the header: comma-separated column
 * names. Every wanted column (struct imu_csv_spec) is found by its exact name, once; columns
 * not asked for are ignored (their fields are not checked, but every row must have as many
 * fields as the header). Each wanted field is a finite decimal number; IMU_CSV_NAN_OK also
 * takes "nan" (any case strtod reads as NaN), which is stored as NaN; a missing
 * IMU_CSV_OPTIONAL column reads as NaN in every row and present[i] is false. The IMU_CSV_TIME
 * column (at most one) must lie in [0, IMU_CSV_TIME_MAX_S] and increase strictly.
 */
#define IMU_CSV_NAMED_MAX_FIELDS 64 /* columns in the header */
#define IMU_CSV_NAMED_MAX_COLS 24   /* columns asked for */
#define IMU_CSV_OPTIONAL 0x1u       /* the column may be absent */
#define IMU_CSV_NAN_OK 0x2u         /* "nan" is a value (e.g. truth lost by the optical system) */
#define IMU_CSV_TIME 0x4u           /* the time column: in range, strictly increasing */

struct imu_csv_spec {
    const char *name;
    unsigned flags; /* IMU_CSV_* */
};

struct imu_csv_cols {
    double *v;  /* n rows x ncols values, row-major, in the order of the spec (malloc'd) */
    long *line; /* 1-based file line of each row */
    size_t n, cap;
    int ncols;
    bool present[IMU_CSV_NAMED_MAX_COLS]; /* the column was in the header */
};

/* Read a CSV with a header from in. Returns INC_OK (at least one row); INC_ERR_FORMAT (msg names
 * the line and the problem); INC_ERR_IO; INC_ERR_NO_SPACE; INC_ERR_NULL; INC_ERR_INVAL (nspec
 * outside 1..IMU_CSV_NAMED_MAX_COLS, two time columns). On error t holds no rows. */
int imu_csv_read_named(FILE *in, const char *name, const struct imu_csv_spec *spec, int nspec,
                       struct imu_csv_cols *t, char *msg, size_t msg_len);

/* Value of column c in row r (no checks). */
static inline double imu_csv_at(const struct imu_csv_cols *t, size_t r, int c)
{
    return t->v[r * (size_t)t->ncols + (size_t)c];
}

void imu_csv_cols_free(struct imu_csv_cols *t);

/* Open path for reading: "-" is standard input; a gzip file (magic bytes 1f 8b) is decompressed
 * on the fly (zlib), anything else is read as it is. NULL with errno set when it cannot be
 * opened. Close with fclose. */
FILE *imu_csv_open(const char *path);

#ifdef __cplusplus
}
#endif

#endif
