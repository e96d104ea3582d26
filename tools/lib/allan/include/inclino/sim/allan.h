/*
 * sim/allan.h - overlapping Allan deviation of a rate record, the usual read-offs (angle random
 * walk at tau = 1 s, bias instability = minimum / 0.664), CSV input and SVG / gnuplot output.
 * Module inclino_sim_allan (hosted C; host tool `allan`, docs/noise-and-allan.md).
 *
 * Definitions (IEEE Std 952-1997 annex C, IEEE Std 1554): for rate samples y[0..n-1] taken every
 * dt, the angle theta[k] = dt * sum_{j<k} y[j] (k = 0..n) and, for a cluster of m samples
 * (tau = m dt), the overlapping Allan variance is
 *     AVAR(tau) = sum_{k=0}^{n-2m} (theta[k+2m] - 2 theta[k+m] + theta[k])^2
 *                 / (2 tau^2 (n - 2m + 1)).
 * Units: the deviation has the unit of y (e.g. deg/s); ARW = ADEV(1 s) in unit*sqrt(s) =
 * unit/sqrt(Hz) (deg/s/sqrt(Hz) = deg/sqrt(s); x 60 gives deg/sqrt(h)).
 */
#ifndef INCLINO_SIM_ALLAN_H
#define INCLINO_SIM_ALLAN_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

#define SIM_ALLAN_BI_FACTOR 0.664 /* flicker floor = 0.664 B (sqrt(2 ln 2 / pi)) */

struct sim_allan_point {
    double tau_s; /* averaging time m * dt, s */
    double adev;  /* overlapping Allan deviation, unit of y */
    double err;   /* rough 1-sigma uncertainty: adev / sqrt(2 (n/m - 1)) (white-noise EDF) */
    uint64_t m;   /* cluster size, samples */
};

struct sim_allan_opts {
    unsigned per_decade; /* tau points per decade (log grid of m), 1..100; 0 -> 10 */
    double min_clusters; /* largest m is n / min_clusters (>= 2); 0 -> 10 */
};

/*
 * Overlapping Allan deviation of y[0..n-1] (interval dt_s > 0) on a logarithmic grid of m from 1
 * to n / min_clusters (duplicates removed). Writes up to max_pts points (ascending tau) and
 * *count. Returns 0; INC_ERR_NULL; INC_ERR_INVAL (n < 4, dt <= 0, bad opts, non-finite sample);
 * INC_ERR_NO_SPACE (more grid points than max_pts: the first max_pts are written);
 * INC_ERR_RANGE (no m fits: record too short; or a result that is not a finite double - the
 * record is scaled by a power of two (exact) so that finite samples as large as DBL_MAX or as
 * small as DBL_MIN give finite results, but an ADEV above DBL_MAX, or a dt_s so large that the
 * integral overflows, is refused, never written as inf; *count is then 0). Allocates n + 1
 * doubles for the duration.
 */
int sim_allan_compute(const double *y, size_t n, double dt_s, const struct sim_allan_opts *opts,
                      struct sim_allan_point *pts, size_t max_pts, size_t *count);

/* The overlapping Allan deviation at one cluster size m (1 <= m <= (n - 1) / 2); negative on
 * bad arguments or a result that is not finite. */
double sim_allan_at(const double *y, size_t n, double dt_s, uint64_t m);

struct sim_allan_readoff {
    double arw;              /* ADEV at tau = 1 s (log-log interpolation), unit*sqrt(s) */
    bool arw_valid;          /* false: 1 s is outside the curve */
    double adev_min;         /* smallest ADEV on the curve */
    double tau_min_s;        /* where */
    double bias_instability; /* adev_min / 0.664 */
    bool min_interior;       /* false: the minimum is the last qualifying point (curve still
                                falling, so the bias instability is only an upper bound) or the
                                first point */
};

/*
 * Read-offs of a computed curve (count >= 1). The minimum is searched only among points whose
 * rough relative uncertainty err / adev is at most max_rel_err (0 -> SIM_ALLAN_MIN_REL_ERR):
 * the last points of a curve rest on a handful of clusters, and the smallest of several noisy
 * values would read the floor low. Returns 0, INC_ERR_NULL, or INC_ERR_INVAL (count == 0,
 * max_rel_err < 0, or no point qualifies).
 */
#define SIM_ALLAN_MIN_REL_ERR 0.05 /* n / m >= 201 */
int sim_allan_readoff(const struct sim_allan_point *pts, size_t count, double max_rel_err,
                      struct sim_allan_readoff *r);

/* ADEV at tau_s by log-log interpolation of the curve; negative when outside it. */
double sim_allan_interp(const struct sim_allan_point *pts, size_t count, double tau_s);

/*
 * Read one numeric column of a CSV/whitespace table. Lines: at most SIM_ALLAN_CSV_LINE_MAX
 * characters, no NUL byte; trailing blanks and '\r' (CRLF) ignored; blank lines and lines whose
 * first non-blank is '#' skipped. Fields: separated by ',' or ';' (each ends one field, so ",,"
 * holds an empty one) or a run of blanks/tabs; nothing after the last separator is no field. The
 * first content line is a header when every field is a name (non-empty, not a number); any other
 * line is a data row. col is 0-based; the read fields (col and, with time_col >= 0, the time) must
 * be finite numbers read whole by strtod (at most SIM_ALLAN_CSV_FIELD_MAX characters); other
 * fields are not looked at. Each value is multiplied by scale and must stay finite. With
 * time_col >= 0 the interval comes from that column (seconds): at least 2 rows, the mean step
 * (last - first) / (n - 1) finite and > 0, every step within 1 % of it; *dt_s = the mean step.
 * On success *y is malloc'ed (caller frees), *n >= 1, *dt_s is set when time_col >= 0.
 * Errors: INC_ERR_NULL; INC_ERR_FORMAT with *bad_line = the 1-based line: a line too long or
 * holding a NUL, a bad or missing read field, a value overflowing after the scale; for a
 * non-uniform time the line whose step from the previous row is farthest from the mean (time not
 * increasing: the first row not after its predecessor); no data rows: the last line.
 * INC_ERR_NO_SPACE (out of memory), INC_ERR_IO (read error).
 */
#define SIM_ALLAN_CSV_LINE_MAX 4095u /* characters per line, the '\n' not counted */
#define SIM_ALLAN_CSV_FIELD_MAX 127u /* characters of a read field */
int sim_allan_read_csv(FILE *f, unsigned col, int time_col, double scale, double **y, size_t *n,
                       double *dt_s, size_t *bad_line);

/* The curve as CSV: "tau_s,adev,err[,theory]" (theory may be NULL: column omitted). */
int sim_allan_write_csv(FILE *f, const struct sim_allan_point *pts, size_t count,
                        const double *theory);

/*
 * A self-contained log-log SVG plot: the measured curve with error bars, an optional theory curve
 * (theory[i] at pts[i].tau_s; NULL for none), the read-offs as marks and text. unit labels the
 * y axis ("deg/s"). Returns 0, INC_ERR_NULL, INC_ERR_INVAL (no positive point) or INC_ERR_IO.
 */
int sim_allan_write_svg(FILE *f, const struct sim_allan_point *pts, size_t count,
                        const double *theory, const struct sim_allan_readoff *r, const char *title,
                        const char *unit);

/* A gnuplot script that plots data_csv (written by sim_allan_write_csv) to a PNG png_path. */
int sim_allan_write_gnuplot(FILE *f, const char *data_csv, const char *png_path, bool has_theory,
                            const char *title, const char *unit);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_SIM_ALLAN_H */
