/* lf_allan_csv.c - libFuzzer target: the allan tool's CSV reader (tools/lib/allan,
 * sim_allan_read_csv), then the Allan deviation of what it read. The first byte chooses the
 * value column (0..3), the time column (none or 0) and the scale (1, -1e300, 1e-300).
 * Properties: on success every value is finite, n >= 1, dt > 0 and finite with a time column;
 * sim_allan_compute gives finite points or refuses (never inf or NaN); on error the bad line is
 * named (>= 1). */
#include "inclino/error.h"
#include "inclino/sim/allan.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const double scales[4] = {1.0, -1e300, 1e-300, 65536.0};
    static struct sim_allan_point pts[256];
    double *y = NULL, dt = 0.0;
    size_t n = 0, bad = 0, i, count = 0;
    const unsigned col = size > 0 ? (data[0] & 3u) : 0u;
    const int time_col = (size > 0 && (data[0] & 4u)) ? 0 : -1;
    const double scale = scales[size > 0 ? (data[0] >> 3) & 3u : 0u];
    FILE *f;
    int err;
    if (size < 2) return 0;
    f = fmemopen((void *)(data + 1), size - 1u, "r");
    if (f == NULL) return 0;
    err = sim_allan_read_csv(f, col, time_col, scale, &y, &n, &dt, &bad);
    fclose(f);
    if (err != INC_OK) {
        if (err == INC_ERR_FORMAT && bad < 1u) abort();
        return 0;
    }
    if (y == NULL || n < 1u) abort();
    for (i = 0; i < n; i++) {
        if (!isfinite(y[i])) abort();
    }
    if (time_col >= 0 && !(dt > 0.0 && isfinite(dt))) abort();
    if (time_col < 0) dt = 1.0;
    err = sim_allan_compute(y, n, dt, NULL, pts, sizeof pts / sizeof pts[0], &count);
    if (err == INC_OK || err == INC_ERR_NO_SPACE) {
        for (i = 0; i < count; i++) {
            if (!isfinite(pts[i].adev) || !isfinite(pts[i].err) || !(pts[i].adev >= 0.0)) abort();
        }
    } else if (count != 0u) {
        abort();
    }
    free(y);
    return 0;
}
