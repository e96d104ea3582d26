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

#ifdef __cplusplus
}
#endif

#endif
