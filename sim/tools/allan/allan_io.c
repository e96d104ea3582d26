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

#define LINE_MAX_CHARS 4096

/* Field idx (0-based) of line as a double. Returns 1 on success, 0 when the field is missing,
 * -1 when it is present but not a number. */
static int field(const char *line, unsigned idx, double *v)
{
    const char *p = line;
    unsigned i = 0;
    for (;;) {
        const char *start;
        while (*p == ' ' || *p == '\t') {
            p++;
        }
        start = p;
        while (*p != '\0' && *p != ',' && *p != ';' && *p != ' ' && *p != '\t' && *p != '\r' &&
               *p != '\n') {
            p++;
        }
        if (p == start && (*p == '\0' || *p == '\r' || *p == '\n')) {
            return 0;
        }
        if (i == idx) {
            char buf[128];
            char *end;
            size_t len = (size_t)(p - start);
            if (len == 0u || len >= sizeof(buf)) {
                return -1;
            }
            memcpy(buf, start, len);
            buf[len] = '\0';
            *v = strtod(buf, &end);
            return (*end == '\0' && isfinite(*v)) ? 1 : -1;
        }
        i++;
        /* one separator (a run of blanks counts as one; ',' / ';' each end one field) */
        while (*p == ' ' || *p == '\t') {
            p++;
        }
        if (*p == ',' || *p == ';') {
            p++;
        }
    }
}

static bool blank_or_comment(const char *line)
{
    const char *p = line;
    while (*p != '\0' && isspace((unsigned char)*p)) {
        p++;
    }
    return *p == '\0' || *p == '#';
}

int sim_allan_read_csv(FILE *f, unsigned col, int time_col, double scale, double **y, size_t *n,
                       double *dt_s, size_t *bad_line)
{
    char line[LINE_MAX_CHARS];
    double *buf = NULL, *tbuf = NULL;
    size_t cap = 0, cnt = 0, lineno = 0;
    bool first = true;
    int err = INC_OK;
    if (f == NULL || y == NULL || n == NULL || dt_s == NULL || bad_line == NULL) {
        return INC_ERR_NULL;
    }
    *y = NULL;
    *n = 0;
    *bad_line = 0;
    while (fgets(line, sizeof(line), f) != NULL) {
        double v, t = 0.0;
        int fv, ft = 1;
        lineno++;
        if (strchr(line, '\n') == NULL && !feof(f)) {
            err = INC_ERR_FORMAT; /* line too long */
            break;
        }
        if (blank_or_comment(line)) {
            continue;
        }
        fv = field(line, col, &v);
        if (time_col >= 0) {
            ft = field(line, (unsigned)time_col, &t);
        }
        if (fv != 1 || ft != 1) {
            if (first && fv != 0 && (time_col < 0 || ft != 0)) {
                first = false; /* a header line */
                continue;
            }
            err = INC_ERR_FORMAT;
            break;
        }
        first = false;
        if (cnt == cap) {
            const size_t ncap = cap == 0u ? 4096u : cap * 2u;
            double *nb = realloc(buf, ncap * sizeof(*nb));
            double *nt = time_col >= 0 ? realloc(tbuf, ncap * sizeof(*nt)) : NULL;
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
            tbuf[cnt] = t;
        }
        cnt++;
    }
    if (err == INC_OK && ferror(f)) {
        err = INC_ERR_IO;
    }
    if (err == INC_OK && cnt == 0u) {
        err = INC_ERR_FORMAT;
    }
    if (err == INC_OK && time_col >= 0) {
        if (cnt < 2u) {
            err = INC_ERR_FORMAT;
        } else {
            const double step = (tbuf[cnt - 1u] - tbuf[0]) / (double)(cnt - 1u);
            size_t k;
            if (!(step > 0.0)) {
                err = INC_ERR_FORMAT;
            }
            for (k = 1; err == INC_OK && k < cnt; k++) {
                if (fabs((tbuf[k] - tbuf[k - 1u]) - step) > 0.01 * step) {
                    err = INC_ERR_FORMAT;
                }
            }
            if (err == INC_OK) {
                *dt_s = step;
            }
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
            vmin = fmin(vmin, pts[i].adev - pts[i].err > 0.0 ? pts[i].adev - pts[i].err
                                                              : pts[i].adev);
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
    fprintf(f, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" "
               "font-family=\"sans-serif\" font-size=\"12\">\n", SVG_W, SVG_H);
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
    fprintf(f, "<text transform=\"translate(22 %.1f) rotate(-90)\" text-anchor=\"middle\">"
               "Allan deviation (", (SVG_T + SVG_H - SVG_B) / 2.0);
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
            fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#1f77b4\"/>\n",
                    x, py(&fr, pts[i].adev - pts[i].err), x, py(&fr, pts[i].adev + pts[i].err));
        }
    }
    if (r != NULL) {
        double ty = SVG_T + 18.0;
        if (r->arw_valid) {
            fprintf(f, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"5\" fill=\"none\" stroke=\"black\"/>\n",
                    px(&fr, 1.0), py(&fr, r->arw));
            fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"end\">ARW (tau = 1 s): %.4g %s"
                       "*sqrt(s) = %.4g %s*sqrt(h)/s</text>\n", SVG_W - SVG_R - 8.0, ty, r->arw,
                    unit != NULL ? unit : "", r->arw * 60.0, unit != NULL ? unit : "");
            ty += 16.0;
        }
        fprintf(f, "<rect x=\"%.1f\" y=\"%.1f\" width=\"8\" height=\"8\" fill=\"black\"/>\n",
                px(&fr, r->tau_min_s) - 4.0, py(&fr, r->adev_min) - 4.0);
        fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"end\">minimum %.4g %s at %.4g s; "
                   "bias instability (min / 0.664): %.4g %s%s</text>\n", SVG_W - SVG_R - 8.0, ty,
                r->adev_min, unit != NULL ? unit : "", r->tau_min_s, r->bias_instability,
                unit != NULL ? unit : "", r->min_interior ? "" : " (minimum at the curve's end)");
        ty += 16.0;
        if (theory != NULL) {
            fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"end\" fill=\"#d62728\">dashed: "
                       "configured model (analytic)</text>\n", SVG_W - SVG_R - 8.0, ty);
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
    fprintf(f, "# gnuplot script written by the allan tool (Debian: apt-get install gnuplot-nox)\n"
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
