/* lf_imu_csv.c - libFuzzer target: imu_replay's CSV readers (tools/lib/imu_csv). The first byte
 * chooses the reader: even, the positional imu_csv_read; odd, imu_csv_read_named with the
 * BROAD/vehicle_sim layout (time, optional and NaN-allowed columns). Properties: on success
 * every value is finite (NaN only in NaN-allowed columns), time lies in [0,
 * IMU_CSV_TIME_MAX_S] and increases strictly; on error no rows are kept and the message is set. */
#include "inclino/error.h"
#include "inclino/sim/imu_csv.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static void positional(FILE *f)
{
    struct imu_csv_table t = {NULL, 0, 0, 0};
    char msg[256] = "";
    size_t i;
    int c;
    const int err = imu_csv_read(f, "fuzz", &t, msg, sizeof msg);
    if (err != INC_OK) {
        if (t.rows != NULL || t.n != 0u || msg[0] == '\0') abort();
        return;
    }
    if (t.n < 2u || (t.cols != 7 && t.cols != 8)) abort();
    for (i = 0; i < t.n; i++) {
        for (c = 0; c < t.cols; c++) {
            if (!isfinite(t.rows[i].v[c])) abort();
        }
        if (t.rows[i].v[0] < 0.0 || t.rows[i].v[0] > IMU_CSV_TIME_MAX_S) abort();
        if (i > 0u && !(t.rows[i].v[0] > t.rows[i - 1u].v[0])) abort();
    }
    imu_csv_free(&t);
}

static void named(FILE *f)
{
    static const struct imu_csv_spec spec[] = {{"t_s", IMU_CSV_TIME},
                                               {"acc_x_g", 0u},
                                               {"acc_y_g", 0u},
                                               {"truth_qw", IMU_CSV_NAN_OK},
                                               {"temp_c", IMU_CSV_OPTIONAL},
                                               {"speed_mps", IMU_CSV_OPTIONAL | IMU_CSV_NAN_OK}};
    const int nspec = (int)(sizeof spec / sizeof spec[0]);
    struct imu_csv_cols t;
    char msg[256] = "";
    size_t i;
    int c, err;
    t.v = NULL;
    t.line = NULL;
    t.n = t.cap = 0;
    err = imu_csv_read_named(f, "fuzz", spec, nspec, &t, msg, sizeof msg);
    if (err != INC_OK) {
        if (t.v != NULL || t.n != 0u || msg[0] == '\0') abort();
        return;
    }
    if (t.n < 1u || t.ncols != nspec) abort();
    for (i = 0; i < t.n; i++) {
        const double ts = imu_csv_at(&t, i, 0);
        for (c = 0; c < nspec; c++) {
            const double v = imu_csv_at(&t, i, c);
            if (isinf(v)) abort();
            if (isnan(v) && (spec[c].flags & IMU_CSV_NAN_OK) == 0u && t.present[c]) abort();
        }
        if (!(ts >= 0.0 && ts <= IMU_CSV_TIME_MAX_S)) abort();
        if (i > 0u && !(ts > imu_csv_at(&t, i - 1u, 0))) abort();
    }
    imu_csv_cols_free(&t);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    FILE *f;
    if (size < 2) return 0;
    f = fmemopen((void *)(data + 1), size - 1u, "r");
    if (f == NULL) return 0;
    if (data[0] & 1u)
        named(f);
    else
        positional(f);
    fclose(f);
    return 0;
}
