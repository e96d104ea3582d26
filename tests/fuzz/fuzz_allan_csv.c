/*
 * Mutation sweep of the Allan tool's CSV reader (sim_allan_read_csv, tools/allan,
 * docs/noise-and-allan.md), plain host build and ASan+UBSan.
 *
 * Seeds: the example of tests/allan (header, comment, blank line, time column, scale 2), a
 * 40-row comma file with a header and a time column at 100 Hz, a 30-row ';' file with the time
 * in the last column and a negative scale, and a 30-row blank/tab separated file without header
 * or time column. Every case is read from memory (fmemopen) with the seed's column options.
 *
 * Two independent checks per case:
 * - a reference reader written here from the documented rules (allan.h) decides accept/refuse;
 *   the reader must agree: on success every sample equals the read column of its data line,
 *   re-read with strtod and multiplied by the scale (so a NUL, a cut or a merged field cannot
 *   pass unseen), the count is the number of data lines, samples are finite, and with a time
 *   column dt is the mean step, > 0 and finite, every step within 1 % of it; on refusal the
 *   reader names the same line.
 * - the certainly broken cases, derived from the mutation alone, must be refused: NaN/inf/empty
 *   in a read field, a read field cut or missing, 'n'/0xFF in a read field, a NUL byte anywhere,
 *   a line over the limit, a time changed by more than half a step, a duplicated data row or a
 *   deleted middle data row (with a time column), a value overflowing after the scale. Where the
 *   mutation pins the line (field, byte, cut, NUL), the refusal must name exactly that line.
 */
#include "fuzz_mut.h"
#include "inclino/error.h"
#include "inclino/sim/allan.h"
#include "unit.h"

#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct seed_opts {
    const char *label;
    unsigned col;
    int time_col;
    double scale;
};

/* ---- reference reader (from the documented rules, not from allan_io.c) ---------------------- */

#define REF_MAX_FIELDS 64

struct ref_line {
    char text[SIM_ALLAN_CSV_LINE_MAX + 2];
    size_t len;
    bool nul, too_long;
};

/* Line l (1-based) of text: its bytes without the '\n', then trailing blanks and '\r' cut. */
static void ref_get_line(const char *text, size_t len, size_t l, struct ref_line *out)
{
    size_t e, s = fuzz_line_span(text, len, l - 1u, &e), i;
    if (e > s && text[e - 1] == '\n') e--;
    out->nul = false;
    out->too_long = e - s > SIM_ALLAN_CSV_LINE_MAX;
    for (i = s; i < e; i++)
        out->nul = out->nul || text[i] == '\0';
    out->len = out->too_long ? 0 : e - s;
    memcpy(out->text, text + s, out->len);
    while (out->len > 0 && (out->text[out->len - 1] == ' ' || out->text[out->len - 1] == '\t' ||
                            out->text[out->len - 1] == '\r')) {
        out->len--;
    }
    out->text[out->len] = '\0';
}

static bool ref_skip(const char *s)
{
    while (*s != '\0' && isspace((unsigned char)*s))
        s++;
    return *s == '\0' || *s == '#';
}

/* Fields: a run of blanks/tabs separates; ',' or ';' ends a field (so ",," holds an empty one);
 * nothing after the last separator is no field. Writes start/length pairs. */
static size_t ref_fields(const char *s, size_t *fs, size_t *fl)
{
    size_t n = 0, p = 0;
    for (;;) {
        size_t st;
        while (s[p] == ' ' || s[p] == '\t')
            p++;
        if (s[p] == '\0' || n == REF_MAX_FIELDS) return n;
        st = p;
        while (s[p] != '\0' && strchr(",; \t", s[p]) == NULL)
            p++;
        fs[n] = st;
        fl[n++] = p - st;
        while (s[p] == ' ' || s[p] == '\t')
            p++;
        if (s[p] == ',' || s[p] == ';') p++;
    }
}

/* 1: a finite number read whole; 0: a number that is not finite; -1: not a number. */
static int ref_number(const char *s, size_t len, double *v)
{
    char buf[SIM_ALLAN_CSV_FIELD_MAX + 1];
    char *end;
    if (len == 0 || len > SIM_ALLAN_CSV_FIELD_MAX) return -1;
    memcpy(buf, s, len);
    buf[len] = '\0';
    *v = strtod(buf, &end);
    if (*end != '\0') return -1;
    return isfinite(*v) ? 1 : 0;
}

struct ref_result {
    bool ok;
    size_t bad_line, n;
    double *y, *t, dt;
    size_t *line;
};

static void ref_read(const char *text, size_t len, const struct seed_opts *o, struct ref_result *r)
{
    static struct ref_line ln;
    const size_t lines = fuzz_count_lines(text, len);
    size_t l, fs[REF_MAX_FIELDS], fl[REF_MAX_FIELDS];
    bool first = true;
    r->ok = false;
    r->n = 0;
    r->bad_line = 0;
    r->y = calloc(lines + 1u, sizeof(double));
    r->t = calloc(lines + 1u, sizeof(double));
    r->line = calloc(lines + 1u, sizeof(size_t));
    if (r->y == NULL || r->t == NULL || r->line == NULL) exit(2);
    for (l = 1; l <= lines; l++) {
        size_t nf;
        double v = 0.0, t = 0.0;
        ref_get_line(text, len, l, &ln);
        if (ln.nul || ln.too_long) {
            r->bad_line = l;
            return;
        }
        if (ref_skip(ln.text)) continue;
        nf = ref_fields(ln.text, fs, fl);
        if (first) {
            size_t names = 0, k;
            first = false;
            for (k = 0; k < nf; k++)
                names += ref_number(ln.text + fs[k], fl[k], &v) < 0 && fl[k] > 0;
            if (names == nf) continue; /* the header */
        }
        if (o->col >= nf || ref_number(ln.text + fs[o->col], fl[o->col], &v) != 1 ||
            (o->time_col >= 0 &&
             ((size_t)o->time_col >= nf ||
              ref_number(ln.text + fs[o->time_col], fl[o->time_col], &t) != 1)) ||
            !isfinite(v * o->scale)) {
            r->bad_line = l;
            return;
        }
        r->y[r->n] = v * o->scale;
        r->t[r->n] = t;
        r->line[r->n++] = l;
    }
    if (r->n == 0 || (o->time_col >= 0 && r->n < 2u)) {
        r->bad_line = lines;
        return;
    }
    if (o->time_col >= 0) {
        const double step = (r->t[r->n - 1] - r->t[0]) / (double)(r->n - 1u);
        const bool step_ok = isfinite(step) && step > 0.0;
        size_t worst = 0;
        double worst_dev = 0.0;
        for (l = 1; l < r->n; l++) {
            const double d = r->t[l] - r->t[l - 1];
            if (!step_ok && (!(d > 0.0) || !isfinite(d))) {
                r->bad_line = r->line[l];
                return;
            }
            if (step_ok && fabs(d - step) > 0.01 * step && fabs(d - step) > worst_dev) {
                worst_dev = fabs(d - step);
                worst = l;
            }
        }
        if (!step_ok || worst != 0) {
            r->bad_line = r->line[step_ok ? worst : r->n - 1];
            return;
        }
        r->dt = step;
    }
    r->ok = true;
}

static void ref_free(struct ref_result *r)
{
    free(r->y);
    free(r->t);
    free(r->line);
}

/* ---- the certainly broken cases, from the mutation and the seed ----------------------------- */

/* The field of the seed's line holding offset pos: line (1-based), field index, start, length;
 * false when pos is not on a data row of the seed or not inside a field. */
struct seed_info {
    const char *seed;
    size_t len, lines, first_data, last_data, data_rows;
    double step; /* the seed's time step (0 without a time column) */
};

static bool seed_is_data_line(const struct seed_info *si, size_t l)
{
    static struct ref_line ln;
    ref_get_line(si->seed, si->len, l, &ln);
    return l >= si->first_data && l <= si->last_data && !ref_skip(ln.text);
}

/* The line (1-based) of offset pos, and the index of the field that holds or starts at pos
 * (SIZE_MAX between fields); *fstart / *fend: that field's offsets in the seed. */
static size_t seed_field_at(const struct seed_info *si, size_t pos, size_t *field, size_t *fstart,
                            size_t *fend)
{
    static struct ref_line ln;
    size_t l = 1, s = 0, i, nf, fs[REF_MAX_FIELDS], fl[REF_MAX_FIELDS];
    for (i = 0; i < pos && i < si->len; i++) {
        if (si->seed[i] == '\n') {
            l++;
            s = i + 1u;
        }
    }
    ref_get_line(si->seed, si->len, l, &ln);
    nf = ref_fields(ln.text, fs, fl);
    *field = SIZE_MAX;
    for (i = 0; i < nf; i++) {
        if (pos >= s + fs[i] && pos < s + fs[i] + fl[i]) {
            *field = i;
            *fstart = s + fs[i];
            *fend = s + fs[i] + fl[i];
        }
    }
    return l;
}

static bool is_read(const struct seed_opts *o, size_t field)
{
    return field == o->col || (o->time_col >= 0 && field == (size_t)o->time_col);
}

/* 0: not certainly broken; else the line the refusal must name, or SIZE_MAX (refused, line not
 * pinned by the mutation alone). */
static size_t must_fail(const struct seed_info *si, const struct seed_opts *o,
                        const struct fuzz_case *c)
{
    const size_t last_read = o->time_col >= 0 && (size_t)o->time_col > o->col ? (size_t)o->time_col
                                                                              : o->col;
    size_t f, fs, fe, l, e;
    switch (c->family) {
    case FUZZ_BYTE: {
        const unsigned char b = fuzz_bytes[c->arg];
        if ((unsigned char)si->seed[c->where] == b) return 0;
        l = seed_field_at(si, c->where, &f, &fs, &fe);
        if (b == 0u) return l; /* a NUL anywhere */
        return (b == 0xFFu || b == 'n') && seed_is_data_line(si, l) && f != SIZE_MAX &&
                       is_read(o, f)
                   ? l
                   : 0;
    }
    case FUZZ_TRUNC: {
        size_t ls;
        bool content = false;
        if (c->where == 0 || si->seed[c->where - 1u] == '\n') return 0;
        l = seed_field_at(si, c->where - 1u, &f, &fs, &fe);
        if (!seed_is_data_line(si, l)) return 0;
        ls = fuzz_line_span(si->seed, si->len, l - 1u, &e);
        for (size_t p = ls; p < c->where; p++)
            content = content || !isspace((unsigned char)si->seed[p]);
        if (!content) return 0; /* only blanks left: a blank line */
        /* the last read field gone or cut to nothing */
        {
            size_t lf, lfs, lfe, p;
            for (p = ls; p < e; p++) {
                (void)seed_field_at(si, p, &lf, &lfs, &lfe);
                if (lf == last_read) break;
            }
            if (c->where <= p) return l;
        }
        /* a number cut after its sign or its exponent letter */
        if (f != SIZE_MAX && is_read(o, f) && strchr("eE+-", si->seed[c->where - 1u]) != NULL)
            return l;
        return 0;
    }
    case FUZZ_TOKEN: {
        const char *t = fuzz_tokens[c->arg];
        double nv;
        l = seed_field_at(si, c->where, &f, &fs, &fe);
        if (!seed_is_data_line(si, l) || f == SIZE_MAX || !is_read(o, f)) return 0;
        if (strcmp(t, "nan") == 0 || strcmp(t, "inf") == 0 || strcmp(t, "-inf") == 0 ||
            t[0] == '\0')
            return l;
        nv = strtod(t, NULL);
        if (f == o->col && !isfinite(nv * o->scale)) return l;
        if (o->time_col >= 0 && f == (size_t)o->time_col) {
            const double ov = strtod(si->seed + fs, NULL);
            if (fabs(nv - ov) > 0.5 * si->step) return SIZE_MAX;
        }
        return 0;
    }
    case FUZZ_DUPLINE: /* a zero step: the copy is the step farthest from the mean */
        return o->time_col >= 0 && seed_is_data_line(si, c->where + 1u) ? c->where + 2u : 0;
    case FUZZ_DELLINE: /* a double step into the row after the deleted one (>= 3 rows left) */
        if (o->time_col < 0 || si->data_rows < 4u || !seed_is_data_line(si, c->where + 1u) ||
            c->where + 1u <= si->first_data || c->where + 1u >= si->last_data) {
            return 0;
        }
        for (l = c->where + 2u; !seed_is_data_line(si, l); l++) {
        }
        return l - 1u;
    case FUZZ_LONG: return c->where + 1u;
    default: return 0;
    }
}

/* ---- the sweep ----------------------------------------------------------------------------- */

static unsigned n_cases, n_ok, n_must, n_pinned;

static int read_buf(const char *d, size_t len, const struct seed_opts *o, double **y, size_t *n,
                    double *dt, size_t *bad)
{
    FILE *f = len ? fmemopen((void *)(uintptr_t)d, len, "r") : tmpfile();
    int err;
    if (f == NULL) return INC_ERR_IO;
    err = sim_allan_read_csv(f, o->col, o->time_col, o->scale, y, n, dt, bad);
    fclose(f);
    return err;
}

static void case_fail(int line, const struct seed_opts *o, unsigned long k,
                      const struct fuzz_case *c, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 5, 6)))
#endif
    ;
static void case_fail(int line, const struct seed_opts *o, unsigned long k,
                      const struct fuzz_case *c, const char *fmt, ...)
{
    char what[400];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    unit_fail(__FILE__, line, "%s case %lu (%s at %zu, arg %u): %s", o->label, k,
              fuzz_family_name(c->family), c->where, c->arg, what);
}
#define FAILC(...) case_fail(__LINE__, o, k, c, __VA_ARGS__)

static void check_case(const struct seed_info *si, const struct seed_opts *o, unsigned long k,
                       const struct fuzz_case *c)
{
    struct ref_result ref;
    static double sentinel;
    double *y = &sentinel, dt = -7.0;
    size_t n = 99, bad = 0, want;
    const int err = read_buf(c->data, c->len, o, &y, &n, &dt, &bad);
    ref_read(c->data, c->len, o, &ref);
    n_cases++;
    unit_checks++;
    if (err == INC_OK) {
        bool same = ref.ok && n == ref.n && y != NULL &&
                    (o->time_col < 0 ? dt == -7.0 : dt == ref.dt);
        n_ok++;
        for (size_t i = 0; same && i < n; i++)
            same = y[i] == ref.y[i] && isfinite(y[i]);
        if (o->time_col >= 0 && same) same = isfinite(dt) && dt > 0.0;
        if (!same) {
            FAILC("accepted (%zu samples, dt %g); the reference %s (%zu samples, line %zu)", n, dt,
                  ref.ok ? "accepts" : "refuses", ref.n, ref.bad_line);
        }
        free(y);
    } else if (err != INC_ERR_FORMAT || y != NULL || n != 0 || ref.ok || bad != ref.bad_line) {
        FAILC("error %d, line %zu, y %s; the reference %s at line %zu", err, bad,
              y == NULL ? "NULL" : "set", ref.ok ? "accepts" : "refuses", ref.bad_line);
    }
    want = must_fail(si, o, c);
    if (want != 0) {
        n_must++;
        unit_checks++;
        if (err == INC_OK) {
            FAILC("a certainly broken file was accepted");
        } else if (want != SIZE_MAX) {
            n_pinned++;
            if (bad != want) FAILC("refused naming line %zu, want line %zu", bad, want);
        } else if (bad < 1u || bad > fuzz_count_lines(c->data, c->len)) {
            FAILC("refused naming line %zu, not a line of the file", bad);
        }
    }
    ref_free(&ref);
}

static void sweep(const struct seed_opts *o, const char *seed, size_t len)
{
    struct fuzz_case c = {NULL, 0, FUZZ_END, 0, 0};
    struct seed_info si;
    struct ref_result ref;
    double *y = NULL, dt = 0.0;
    size_t n = 0, bad = 0, stride = UNIT_SIZE(1u, 2u), l;
    unsigned long k;
    /* the seed itself: accepted, and the reference agrees */
    REQUIRE(read_buf(seed, len, o, &y, &n, &dt, &bad) == INC_OK);
    ref_read(seed, len, o, &ref);
    REQUIRE(ref.ok && ref.n == n && n >= 3u);
    si.seed = seed;
    si.len = len;
    si.lines = fuzz_count_lines(seed, len);
    si.first_data = ref.line[0];
    si.last_data = ref.line[n - 1u];
    si.data_rows = n;
    si.step = o->time_col >= 0 ? dt : 0.0;
    for (l = 0; l < n; l++)
        CHECK(y[l] == ref.y[l]);
    ref_free(&ref);
    free(y);
    for (k = 0; fuzz_mutate(seed, len, k, stride, UNIT_SIZE(400u, 80u), &c) != FUZZ_END; k++) {
        check_case(&si, o, k, &c);
    }
    fuzz_case_free(&c);
}

static void test_sweep(void)
{
    static const struct seed_opts o_example = {"tests/allan example", 1, 0, 2.0};
    static const struct seed_opts o_comma = {"comma 100 Hz", 1, 0, 1.0};
    static const struct seed_opts o_semi = {"semicolon time last", 0, 2, -0.5};
    static const struct seed_opts o_blank = {"blanks no time", 1, -1, 1.0};
    static const char example[] =
        "# gyro log\ntime_s,gyro_x,gyro_y\n0.0,1.5,9\n0.5,-2.0,9\n\n1.0,0.25,9\n";
    static char comma[4096], semi[4096], blank[4096];
    size_t nc = 0, ns = 0, nb = 0;
    unsigned i;
    nc += (size_t)snprintf(comma, sizeof comma, "time_s,rate_dps,temp_c\n");
    for (i = 0; i < 40u; i++) {
        nc += (size_t)snprintf(comma + nc, sizeof comma - nc, "%s%.2f,%.4g,%d.%u\n",
                               i == 20u ? "# restart\n\n" : "", 0.01 * i,
                               (i % 3u ? 1.0 : -1.0) * (0.01 + 0.0137 * i) * (i % 7u ? 1.0 : 1e-3),
                               20 + (int)(i % 4u), i % 10u);
    }
    for (i = 0; i < 30u; i++) {
        ns += (size_t)snprintf(semi + ns, sizeof semi - ns, "%.3e;%d;%.1f\n",
                               (i % 2u ? -1.0 : 1.0) * 0.25 * (i + 1u), (int)i - 15,
                               100.0 + 0.5 * i);
    }
    for (i = 0; i < 30u; i++) {
        nb += (size_t)snprintf(blank + nb, sizeof blank - nb, "%s%u%s%+.3f\n", i % 4u ? "" : "  ",
                               i, i % 3u ? "\t" : "   ", 0.125 * ((int)i - 11));
    }
    sweep(&o_example, example, sizeof example - 1u);
    sweep(&o_comma, comma, nc);
    sweep(&o_semi, semi, ns);
    sweep(&o_blank, blank, nb);
    printf("allan csv: %u cases, %u accepted, %u that must be refused (%u at a pinned line)\n",
           n_cases, n_ok, n_must, n_pinned);
    CHECK(n_cases > UNIT_SIZE(20000u, 9000u));
    CHECK(n_must > n_cases / 10u);
    CHECK(n_ok > n_cases / 10u);
}

/* Named regression inputs: each was accepted, or refused naming the wrong line, before the fix
 * (docs/traces.md "Mutation sweep"). */
static void test_regressions(void)
{
    static const struct {
        const char *name;
        const char *text;
        size_t len; /* 0: strlen */
        struct seed_opts o;
        size_t line;
    } cases[] = {
        /* a NUL in the unterminated last line: read as "2,3" */
        {"nul-last-line",
         "0,1\n1,2\n2,3\0"
         "9",
         13,
         {"", 1, 0, 1.0},
         3},
        /* a '\r' inside a line ended it: read as 1 */
        {"cr-mid-line", "0,1\r5\n1,2\n2,3\n", 0, {"", 1, 0, 1.0}, 1},
        /* the first row's value NaN or garbled: taken for a header and dropped */
        {"nan-first-row", "0,nan\n1,2\n2,3\n", 0, {"", 1, 0, 1.0}, 1},
        {"garbled-first-row",
         "2..00e-01;-15;100.0\n-5.000e-01;-14;100.5\n7.500e-01;-13;101.0\n",
         0,
         {"", 0, 2, -0.5},
         1},
        /* 1e308 x scale 2 stored as infinity */
        {"scale-overflow", "0,1e308\n1,1\n2,1\n", 0, {"", 1, 0, 2.0}, 1},
        /* the time span overflows: dt = inf passed (inf - inf is NaN, NaN > x is false) */
        {"time-span-overflow", "-1e308,1\n0,1\n1e308,1\n", 0, {"", 1, 0, 1.0}, 3},
        /* non-uniform time: the file's last line was named, not the step */
        {"time-jump", "0,1\n1,1\n2.5,1\n3,1\n4,1\n", 0, {"", 1, 0, 1.0}, 3},
        {"time-duplicate-row", "0,1\n0.5,2\n0.5,2\n1,4\n1.5,5\n", 0, {"", 1, 0, 1.0}, 3},
    };
    unsigned i;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        double *y = NULL, dt = 0.0;
        size_t n = 0, bad = 0;
        const size_t len = cases[i].len ? cases[i].len : strlen(cases[i].text);
        CHECK_ERR(read_buf(cases[i].text, len, &cases[i].o, &y, &n, &dt, &bad), INC_ERR_FORMAT);
        unit_checks++;
        if (bad != cases[i].line || y != NULL || n != 0u) {
            unit_fail(__FILE__, __LINE__, "%s: line %zu, want %zu", cases[i].name, bad,
                      cases[i].line);
        }
    }
    /* the documented accepted forms still pass: header, CRLF, ';', a text column not read */
    {
        static const char ok[] =
            "t;x;status\r\n0;1.5;OK\r\n# pause\r\n0.5;-2;OK\r\n1;4e-3;late\r\n";
        static const struct seed_opts o = {"", 1, 0, 2.0};
        double *y = NULL, dt = 0.0;
        size_t n = 0, bad = 0;
        CHECK_OK(read_buf(ok, sizeof ok - 1u, &o, &y, &n, &dt, &bad));
        REQUIRE(y != NULL && n == 3u);
        CHECK_NEAR(y[0], 3.0, 0.0);
        CHECK_NEAR(y[1], -4.0, 0.0);
        CHECK_NEAR(y[2], 8e-3, 0.0);
        CHECK_NEAR(dt, 0.5, 0.0);
        free(y);
    }
}

int main(void)
{
    UNIT_RUN(test_regressions);
    UNIT_RUN(test_sweep);
    return unit_report();
}
