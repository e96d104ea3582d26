/*
 * allan_io.c - CSV input and CSV / SVG / gnuplot output of Allan curves (see sim/allan.h).
 *
 * The SVG is written directly (no plotting library), so the plot needs nothing beyond a browser;
 * the gnuplot script is for those who have gnuplot (Debian: gnuplot-nox).
 */
#include "inclino/sim/allan.h"

#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "inclino/error.h"
#include "inclino/sim/line.h"

/*
 * The CSV reader. Found by the mutation sweep (tests/fuzz/fuzz_allan_csv.c, docs/traces.md), each
 * kept there as a named regression input: with fgets a NUL byte in an unterminated last line cut
 * it silently ("2,3\0 9" read as 2,3); a '\r' inside a line ended it ("1\r5" read as 1); a first
 * data row whose value was NaN or garbled ("0,nan", "2..5;-15;100") was taken for a header and
 * dropped; a value overflowing after the scale was stored as infinity; times whose span overflows
 * (-1e308, 0, 1e308) gave an infinite dt that passed the uniformity test (inf - inf is NaN, and a
 * NaN comparison is false); a non-uniform time named the file's last line instead of the step.
 */

/* Cut trailing blanks and '\r' (CRLF) off a line read by sim_read_line. */
static void trim_end(char *s)
{
    size_t n = strlen(s);
    while (n > 0u && (s[n - 1u] == ' ' || s[n - 1u] == '\t' || s[n - 1u] == '\r')) {
        n--;
    }
    s[n] = '\0';
}

/* The next field of a line from *p: blanks before it skipped; it ends at ',' ';' blank or the
 * end; then one separator is consumed (a run of blanks counts as one, ',' / ';' each end one
 * field, so ",," holds an empty field). Returns false when the line has no more fields. */
static bool next_field(const char **p, const char **start, size_t *len)
{
    const char *q = *p;
    while (*q == ' ' || *q == '\t') {
        q++;
    }
    if (*q == '\0') {
        return false;
    }
    *start = q;
    while (*q != '\0' && *q != ',' && *q != ';' && *q != ' ' && *q != '\t') {
        q++;
    }
    *len = (size_t)(q - *start);
    while (*q == ' ' || *q == '\t') {
        q++;
    }
    if (*q == ',' || *q == ';') {
        q++;
    }
    *p = q;
    return true;
}

/* 1: a finite number read whole; 0: a number that is not finite (NaN, inf, overflow);
 * -1: not a number (empty, longer than SIM_ALLAN_CSV_FIELD_MAX, or text after the number). */
static int number(const char *s, size_t len, double *v)
{
    char buf[SIM_ALLAN_CSV_FIELD_MAX + 1];
    char *end;
    if (len == 0u || len > SIM_ALLAN_CSV_FIELD_MAX) {
        return -1;
    }
    memcpy(buf, s, len);
    buf[len] = '\0';
    *v = strtod(buf, &end);
    if (*end != '\0') {
        return -1;
    }
    return isfinite(*v) ? 1 : 0;
}

/* Field idx (0-based) of line as a finite double: 1, or 0 when missing or not such a number. */
static int field(const char *line, unsigned idx, double *v)
{
    const char *p = line, *start = NULL;
    size_t len = 0;
    unsigned i;
    for (i = 0; i <= idx; i++) {
        if (!next_field(&p, &start, &len)) {
            return 0;
        }
    }
    return number(start, len, v) == 1;
}

/* A header names every column: each field non-empty and not a number (NaN and inf count as
 * numbers), so a first data row with one bad field is a bad row, not a header. */
static bool is_header(const char *line)
{
    const char *p = line, *start = NULL;
    size_t len = 0;
    double v;
    while (next_field(&p, &start, &len)) {
        if (len == 0u || number(start, len, &v) >= 0) {
            return false;
        }
    }
    return true;
}

static bool blank_or_comment(const char *line)
{
    const char *p = line;
    while (*p != '\0' && isspace((unsigned char)*p)) {
        p++;
    }
    return *p == '\0' || *p == '#';
}

struct time_sample {
    double t;
    size_t line;
};

/* The time rule (allan.h): 0 when uniform (*dt_s = the mean step), else the line to name. */
static size_t check_time(const struct time_sample *ts, size_t cnt, double *dt_s)
{
    const double step = (ts[cnt - 1u].t - ts[0].t) / (double)(cnt - 1u);
    size_t k, worst = 0;
    double worst_dev = 0.0;
    if (!(isfinite(step) && step > 0.0)) {
        /* time not increasing (or its span overflows): the first step that is not a finite
         * increase, else the last sample */
        for (k = 1; k < cnt; k++) {
            const double d = ts[k].t - ts[k - 1u].t;
            if (!(d > 0.0) || !isfinite(d)) {
                return ts[k].line;
            }
        }
        return ts[cnt - 1u].line;
    }
    for (k = 1; k < cnt; k++) {
        const double dev = fabs((ts[k].t - ts[k - 1u].t) - step);
        if (dev > 0.01 * step && dev > worst_dev) {
            worst_dev = dev;
            worst = k;
        }
    }
    if (worst != 0u) {
        return ts[worst].line; /* the step farthest from the mean: the jump, the gap, the copy */
    }
    *dt_s = step;
    return 0;
}

int sim_allan_read_csv(FILE *f, unsigned col, int time_col, double scale, double **y, size_t *n,
                       double *dt_s, size_t *bad_line)
{
    char line[SIM_ALLAN_CSV_LINE_MAX + 1];
    double *buf = NULL;
    struct time_sample *tbuf = NULL;
    size_t cap = 0, cnt = 0, lineno = 0;
    bool first = true;
    int err = INC_OK, got;
    if (f == NULL || y == NULL || n == NULL || dt_s == NULL || bad_line == NULL) {
        return INC_ERR_NULL;
    }
    *y = NULL;
    *n = 0;
    *bad_line = 0;
    while ((got = sim_read_line(f, line, sizeof(line))) != SIM_LINE_EOF) {
        double v, t = 0.0;
        lineno++;
        if (got != SIM_LINE_OK) {
            err = got == SIM_LINE_IO ? INC_ERR_IO
                                     : INC_ERR_FORMAT; /* too long, NUL byte, read error */
            break;
        }
        trim_end(line);
        if (blank_or_comment(line)) {
            continue;
        }
        if (first) {
            first = false;
            if (is_header(line)) {
                continue;
            }
        }
        if (field(line, col, &v) != 1 ||
            (time_col >= 0 && field(line, (unsigned)time_col, &t) != 1) || !isfinite(v * scale)) {
            err = INC_ERR_FORMAT;
            break;
        }
        if (cnt == cap) {
            const size_t ncap = cap == 0u ? 4096u : cap * 2u;
            double *nb = realloc(buf, ncap * sizeof(*nb));
            struct time_sample *nt = time_col >= 0 ? realloc(tbuf, ncap * sizeof(*nt)) : NULL;
            if (nb != NULL) {
                buf = nb;
            }
            if (nt != NULL) {
                tbuf = nt;
            }
            if (nb == NULL || (time_col >= 0 && nt == NULL)) {
                err = INC_ERR_NO_SPACE;
                break;
            }
            cap = ncap;
        }
        buf[cnt] = v * scale;
        if (time_col >= 0) {
            tbuf[cnt].t = t;
            tbuf[cnt].line = lineno;
        }
        cnt++;
    }
    if (err == INC_OK && (cnt == 0u || (time_col >= 0 && cnt < 2u))) {
        err = INC_ERR_FORMAT; /* no data: *bad_line = the last line */
    }
    if (err == INC_OK && time_col >= 0) {
        const size_t at = check_time(tbuf, cnt, dt_s);
        if (at != 0u) {
            lineno = at;
            err = INC_ERR_FORMAT;
        }
    }
    free(tbuf);
    if (err != INC_OK) {
        free(buf);
        *bad_line = lineno;
        return err;
    }
    *y = buf;
    *n = cnt;
    return INC_OK;
}

int sim_allan_write_csv(FILE *f, const struct sim_allan_point *pts, size_t count,
                        const double *theory)
{
    size_t i;
    if (f == NULL || pts == NULL) {
        return INC_ERR_NULL;
    }
    fprintf(f, theory != NULL ? "tau_s,adev,err,theory\n" : "tau_s,adev,err\n");
    for (i = 0; i < count; i++) {
        if (theory != NULL) {
            fprintf(f, "%.9g,%.9g,%.9g,%.9g\n", pts[i].tau_s, pts[i].adev, pts[i].err, theory[i]);
        } else {
            fprintf(f, "%.9g,%.9g,%.9g\n", pts[i].tau_s, pts[i].adev, pts[i].err);
        }
    }
    return ferror(f) ? INC_ERR_IO : INC_OK;
}

/* ---- SVG ------------------------------------------------------------------------------------ */

#define SVG_W 760.0
#define SVG_H 500.0
#define SVG_L 90.0
#define SVG_R 20.0
#define SVG_T 40.0
#define SVG_B 60.0

struct frame {
    double x0, x1, y0, y1; /* log10 ranges */
};

static double px(const struct frame *fr, double tau)
{
    return SVG_L + (log10(tau) - fr->x0) / (fr->x1 - fr->x0) * (SVG_W - SVG_L - SVG_R);
}

static double py(const struct frame *fr, double v)
{
    return SVG_H - SVG_B - (log10(v) - fr->y0) / (fr->y1 - fr->y0) * (SVG_H - SVG_T - SVG_B);
}

static void xml_text(FILE *f, const char *s)
{
    for (; s != NULL && *s != '\0'; s++) {
        switch (*s) {
        case '&': fputs("&amp;", f); break;
        case '<': fputs("&lt;", f); break;
        case '>': fputs("&gt;", f); break;
        case '"': fputs("&quot;", f); break;
        default: fputc(*s, f); break;
        }
    }
}

int sim_allan_write_svg(FILE *f, const struct sim_allan_point *pts, size_t count,
                        const double *theory, const struct sim_allan_readoff *r, const char *title,
                        const char *unit)
{
    struct frame fr;
    double vmin = INFINITY, vmax = 0.0, tmin = INFINITY, tmax = 0.0;
    size_t i;
    int d;
    bool pen;
    if (f == NULL || pts == NULL) {
        return INC_ERR_NULL;
    }
    for (i = 0; i < count; i++) {
        if (pts[i].adev > 0.0 && pts[i].tau_s > 0.0) {
            vmin = fmin(vmin,
                        pts[i].adev - pts[i].err > 0.0 ? pts[i].adev - pts[i].err : pts[i].adev);
            vmax = fmax(vmax, pts[i].adev + pts[i].err);
            tmin = fmin(tmin, pts[i].tau_s);
            tmax = fmax(tmax, pts[i].tau_s);
        }
        if (theory != NULL && theory[i] > 0.0) {
            vmin = fmin(vmin, theory[i]);
            vmax = fmax(vmax, theory[i]);
        }
    }
    if (!(vmax > 0.0) || !isfinite(vmin) || !isfinite(tmin)) {
        return INC_ERR_INVAL;
    }
    fr.x0 = floor(log10(tmin));
    fr.x1 = ceil(log10(tmax));
    fr.y0 = floor(log10(vmin));
    fr.y1 = ceil(log10(vmax));
    if (fr.x1 <= fr.x0) {
        fr.x1 = fr.x0 + 1.0;
    }
    if (fr.y1 <= fr.y0) {
        fr.y1 = fr.y0 + 1.0;
    }
    fprintf(f,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" "
            "font-family=\"sans-serif\" font-size=\"12\">\n",
            SVG_W, SVG_H);
    fprintf(f, "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n");
    /* grid: decades solid, 2..9 light */
    for (d = (int)fr.x0; d <= (int)fr.x1; d++) {
        int k;
        for (k = 1; k <= 9 && (k == 1 || d < (int)fr.x1); k++) {
            const double x = px(&fr, (double)k * pow(10.0, d));
            fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\"/>\n", x,
                    SVG_T, x, SVG_H - SVG_B, k == 1 ? "#999" : "#e4e4e4");
        }
        fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\">1e%d</text>\n",
                px(&fr, pow(10.0, d)), SVG_H - SVG_B + 18.0, d);
    }
    for (d = (int)fr.y0; d <= (int)fr.y1; d++) {
        int k;
        for (k = 1; k <= 9 && (k == 1 || d < (int)fr.y1); k++) {
            const double y = py(&fr, (double)k * pow(10.0, d));
            fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\"/>\n",
                    SVG_L, y, SVG_W - SVG_R, y, k == 1 ? "#999" : "#e4e4e4");
        }
        fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"end\">1e%d</text>\n", SVG_L - 6.0,
                py(&fr, pow(10.0, d)) + 4.0, d);
    }
    fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\">averaging time tau (s)</text>\n",
            (SVG_L + SVG_W - SVG_R) / 2.0, SVG_H - 15.0);
    fprintf(f,
            "<text transform=\"translate(22 %.1f) rotate(-90)\" text-anchor=\"middle\">"
            "Allan deviation (",
            (SVG_T + SVG_H - SVG_B) / 2.0);
    xml_text(f, unit != NULL ? unit : "unit");
    fprintf(f, ")</text>\n<text x=\"%.1f\" y=\"24\" text-anchor=\"middle\" font-size=\"15\">",
            (SVG_L + SVG_W - SVG_R) / 2.0);
    xml_text(f, title != NULL ? title : "Allan deviation");
    fprintf(f, "</text>\n");
    /* theory */
    if (theory != NULL) {
        pen = false;
        fprintf(f, "<path fill=\"none\" stroke=\"#d62728\" stroke-dasharray=\"6 4\" d=\"");
        for (i = 0; i < count; i++) {
            if (theory[i] > 0.0) {
                fprintf(f, "%c%.1f %.1f ", pen ? 'L' : 'M', px(&fr, pts[i].tau_s),
                        py(&fr, theory[i]));
                pen = true;
            }
        }
        fprintf(f, "\"/>\n");
    }
    /* measured, with error bars */
    pen = false;
    fprintf(f, "<path fill=\"none\" stroke=\"#1f77b4\" stroke-width=\"2\" d=\"");
    for (i = 0; i < count; i++) {
        if (pts[i].adev > 0.0) {
            fprintf(f, "%c%.1f %.1f ", pen ? 'L' : 'M', px(&fr, pts[i].tau_s),
                    py(&fr, pts[i].adev));
            pen = true;
        }
    }
    fprintf(f, "\"/>\n");
    for (i = 0; i < count; i++) {
        if (pts[i].adev > 0.0 && pts[i].adev - pts[i].err > 0.0) {
            const double x = px(&fr, pts[i].tau_s);
            fprintf(f,
                    "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#1f77b4\"/>\n",
                    x, py(&fr, pts[i].adev - pts[i].err), x, py(&fr, pts[i].adev + pts[i].err));
        }
    }
    if (r != NULL) {
        double ty = SVG_T + 18.0;
        if (r->arw_valid) {
            fprintf(f, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"5\" fill=\"none\" stroke=\"black\"/>\n",
                    px(&fr, 1.0), py(&fr, r->arw));
            fprintf(f,
                    "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"end\">ARW (tau = 1 s): %.4g %s"
                    "*sqrt(s) = %.4g %s*sqrt(h)/s</text>\n",
                    SVG_W - SVG_R - 8.0, ty, r->arw, unit != NULL ? unit : "", r->arw * 60.0,
                    unit != NULL ? unit : "");
            ty += 16.0;
        }
        fprintf(f, "<rect x=\"%.1f\" y=\"%.1f\" width=\"8\" height=\"8\" fill=\"black\"/>\n",
                px(&fr, r->tau_min_s) - 4.0, py(&fr, r->adev_min) - 4.0);
        fprintf(f,
                "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"end\">minimum %.4g %s at %.4g s; "
                "bias instability (min / 0.664): %.4g %s%s</text>\n",
                SVG_W - SVG_R - 8.0, ty, r->adev_min, unit != NULL ? unit : "", r->tau_min_s,
                r->bias_instability, unit != NULL ? unit : "",
                r->min_interior ? "" : " (minimum at the curve's end)");
        ty += 16.0;
        if (theory != NULL) {
            fprintf(f,
                    "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"end\" fill=\"#d62728\">dashed: "
                    "configured model (analytic)</text>\n",
                    SVG_W - SVG_R - 8.0, ty);
        }
    }
    fprintf(f, "</svg>\n");
    return ferror(f) ? INC_ERR_IO : INC_OK;
}

int sim_allan_write_gnuplot(FILE *f, const char *data_csv, const char *png_path, bool has_theory,
                            const char *title, const char *unit)
{
    if (f == NULL || data_csv == NULL || png_path == NULL) {
        return INC_ERR_NULL;
    }
    fprintf(f,
            "# gnuplot script written by the allan tool (Debian: apt-get install gnuplot-nox)\n"
            "set terminal pngcairo size 900,600\nset output '%s'\n"
            "set datafile separator ','\nset logscale xy\nset grid xtics ytics mxtics mytics\n"
            "set xlabel 'averaging time tau (s)'\nset ylabel 'Allan deviation (%s)'\n"
            "set title '%s'\n"
            "plot '%s' every ::1 using 1:2:3 with yerrorlines title 'overlapping ADEV'",
            png_path, unit != NULL ? unit : "", title != NULL ? title : "Allan deviation",
            data_csv);
    if (has_theory) {
        fprintf(f, ", '' every ::1 using 1:4 with lines dt 2 title 'model (analytic)'");
    }
    fprintf(f, "\n");
    return ferror(f) ? INC_ERR_IO : INC_OK;
}
