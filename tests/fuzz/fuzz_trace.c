/*
 * Mutation sweep of the trace reader (trace_parse_next, trace_replay_open's header check) and of
 * the VCD converter (trace_from_vcd), under the plain host build and ASan+UBSan.
 *
 * Trace: every golden trace of the repository is the seed of the fuzz_mut.h mutation set. Each
 * case is parsed to its end with trace_parse_next and, independently, by ref_parse() below: a
 * strict reading of docs/traces.md written for this test. The two must agree on every record
 * (kind, time, pin, bits, words, line) and on where and whether the file is refused; on top of
 * that, mutations that certainly break the format (NUL, 0xFF or 'n' inside a record line, an
 * extra field, a record cut before its last value, a NaN/overflow/sign token in a field, a line
 * longer than the reader's buffer) must be refused, naming the line.
 *
 * VCD: a capture written with sim/vcd.h's conventions is mutated the same way. A conversion that
 * succeeds must write a trace that parses back completely, with exactly the number of records
 * it returned, each of the options' frame size and CS pin, 1..256 words, times not decreasing;
 * truncation before $enddefinitions, a missing wire and non-numeric or overflowing timestamps
 * must be refused.
 */
#include "fuzz_mut.h"
#include "inclino/sim/trace.h"
#include "unit.h"

#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef GOLDEN_ROOT
#error "GOLDEN_ROOT must be defined (the tests/ directory)"
#endif

static const char *const seeds[] = {
    GOLDEN_ROOT "/trace/golden/loopback_driver.trace",
    GOLDEN_ROOT "/sca3000/golden/d01_init_read.trace",
    GOLDEN_ROOT "/sca3000/golden/e04_init_read.trace",
    GOLDEN_ROOT "/sca3000/golden/e05_ring.trace",
    GOLDEN_ROOT "/adis_imu/golden/adis16364.trace",
    GOLDEN_ROOT "/adis_imu/golden/adis16405.trace",
    GOLDEN_ROOT "/adis16255/golden/adis16255_init_read.trace",
    GOLDEN_ROOT "/adis16255/golden/adis16255_commands.trace",
};
#define N_SEEDS (sizeof seeds / sizeof seeds[0])

/* The reader's line limit: 4095 characters before the newline (buffer of 4096). */
#define REF_LINE_MAX 4095u

/* ------------------------------------------------------------------ reference reader */

static int ref_blank(char c)
{
    return c == ' ' || c == '\t';
}

/* At least one blank, then key, then decimal digits (no sign) <= max. */
static const char *ref_num(const char *p, const char *key, unsigned long long max,
                           unsigned long long *out)
{
    unsigned long long v = 0;
    const size_t kl = strlen(key);
    int digits = 0;
    if (!ref_blank(*p)) return NULL;
    while (ref_blank(*p))
        p++;
    if (strncmp(p, key, kl) != 0) return NULL;
    p += kl;
    while (*p >= '0' && *p <= '9') {
        const unsigned d = (unsigned)(*p - '0');
        if (v > (UINT64_MAX - d) / 10u) return NULL; /* does not fit 64 bits */
        v = v * 10u + d;
        p++;
        digits++;
    }
    if (digits == 0 || v > max) return NULL;
    *out = v;
    return p;
}

static int hexval(char c)
{
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

static const char *ref_words(const char *p, const char *key, unsigned bits, uint16_t *w,
                             unsigned *n)
{
    const size_t kl = strlen(key);
    unsigned k = 0;
    if (!ref_blank(*p)) return NULL;
    while (ref_blank(*p))
        p++;
    if (strncmp(p, key, kl) != 0) return NULL;
    p += kl;
    for (;;) {
        unsigned v = 0, d = 0;
        while (hexval(*p) >= 0) {
            if (++d > 4u) return NULL;
            v = v * 16u + (unsigned)hexval(*p++);
        }
        if (d == 0 || k == TRACE_MAX_WORDS || v > (bits == 8u ? 0xFFu : 0xFFFFu)) return NULL;
        w[k++] = (uint16_t)v;
        if (*p != ',') break;
        p++;
    }
    *n = k;
    return p;
}

/* One line (no '\n', NUL-free) -> 1 record, 0 skipped, -1 malformed. */
static int ref_line(const char *s, struct trace_record *r)
{
    const char *p = s;
    unsigned long long v;
    unsigned n2 = 0;
    while (ref_blank(*p))
        p++;
    if (*p == '#') return 0;
    {
        const char *q = p;
        while (ref_blank(*q) || *q == '\r')
            q++;
        if (*q == '\0') return 0;
    }
    memset(r, 0, sizeof(*r));
    if (p[0] == 'I' && p[1] == ' ') {
        r->kind = TRACE_IRQ;
        if ((p = ref_num(p + 1, "t=", UINT64_MAX, &v)) == NULL) return -1;
        r->t_ns = v;
        if ((p = ref_num(p, "pin=", 0xFFFEu, &v)) == NULL) return -1;
        r->pin = (unsigned)v;
    } else if (p[0] == 'F' && p[1] == ' ') {
        r->kind = TRACE_PERIOD;
        if ((p = ref_num(p + 1, "t=", UINT64_MAX, &v)) == NULL) return -1;
        r->t_ns = v;
        if ((p = ref_num(p, "cs=", 0xFFFEu, &v)) == NULL) return -1;
        r->pin = (unsigned)v;
        if ((p = ref_num(p, "bits=", 16u, &v)) == NULL || (v != 8u && v != 16u)) return -1;
        r->bits = (unsigned)v;
        if ((p = ref_words(p, "mosi=", r->bits, r->mosi, &r->n)) == NULL) return -1;
        if ((p = ref_words(p, "miso=", r->bits, r->miso, &n2)) == NULL || n2 != r->n) return -1;
    } else {
        return -1;
    }
    while (ref_blank(*p) || *p == '\r')
        p++;
    return *p == '\0' ? 1 : -1;
}

#define MAX_RECS 4096u

struct parsed {
    struct trace_record *rec; /* MAX_RECS */
    unsigned n;
    int status;    /* 0 = the whole file read, INC_ERR_FORMAT = refused */
    unsigned line; /* the line refused */
};

static void ref_parse(const char *d, size_t len, struct parsed *out)
{
    size_t i = 0;
    unsigned line = 0;
    static char buf[8192];
    out->n = 0;
    out->status = 0;
    while (i < len) {
        size_t j = i, l = 0;
        int r;
        bool nul = false;
        line++;
        while (j < len && d[j] != '\n') {
            nul = nul || d[j] == '\0';
            if (l < sizeof buf - 1u) buf[l++] = d[j];
            j++;
        }
        buf[l] = '\0';
        if (nul || j - i > REF_LINE_MAX) {
            out->status = INC_ERR_FORMAT;
            out->line = line;
            return;
        }
        r = ref_line(buf, &out->rec[out->n]);
        if (r < 0) {
            out->status = INC_ERR_FORMAT;
            out->line = line;
            return;
        }
        if (r == 1) {
            out->rec[out->n].line = line;
            if (out->n + 1u < MAX_RECS) out->n++;
        }
        i = j + 1u;
    }
}

static void dut_parse(const char *d, size_t len, struct parsed *out, char *msg, size_t msg_len)
{
    FILE *f = fmemopen((void *)(uintptr_t)d, len, "r");
    unsigned line = 0;
    int r;
    out->n = 0;
    out->status = 0;
    msg[0] = '\0';
    if (len == 0) return; /* fmemopen of 0 bytes is not portable; an empty file has no records */
    if (f == NULL) {
        out->status = INC_ERR_IO;
        return;
    }
    while ((r = trace_parse_next(f, &line, &out->rec[out->n], msg, msg_len)) == 1) {
        if (out->n + 1u < MAX_RECS) out->n++;
    }
    if (r < 0) {
        out->status = r;
        out->line = line;
    }
    fclose(f);
}

static bool same_record(const struct trace_record *a, const struct trace_record *b)
{
    if (a->kind != b->kind || a->t_ns != b->t_ns || a->pin != b->pin || a->line != b->line)
        return false;
    if (a->kind == TRACE_IRQ) return true;
    return a->bits == b->bits && a->n == b->n &&
           memcmp(a->mosi, b->mosi, a->n * sizeof(uint16_t)) == 0 &&
           memcmp(a->miso, b->miso, a->n * sizeof(uint16_t)) == 0;
}

/* Is byte offset pos of text inside a record line (F or I)? *eq: offset of that line's last '='. */
static bool on_record_line(const char *text, size_t len, size_t pos, size_t *start, size_t *last_eq)
{
    size_t s = pos, e = pos;
    while (s > 0 && text[s - 1] != '\n')
        s--;
    while (e < len && text[e] != '\n')
        e++;
    *start = s;
    *last_eq = s;
    for (size_t i = s; i < e; i++) {
        if (text[i] == '=') *last_eq = i;
    }
    return (text[s] == 'F' || text[s] == 'I') && s + 1 < len && text[s + 1] == ' ';
}

static unsigned n_cases, n_accepted, n_must_fail;
static struct parsed dut, ref;

static void report(const char *seed, unsigned long k, const struct fuzz_case *c, const char *what)
{
    unit_fail(__FILE__, __LINE__, "%s case %lu (%s at %zu, arg %u): %s", seed, k,
              fuzz_family_name(c->family), c->where, c->arg, what);
}

/* Must this case be refused, whatever else the reference says? */
static bool must_fail(const char *s, size_t len, const struct fuzz_case *c)
{
    size_t start, eq;
    switch (c->family) {
    case FUZZ_BYTE:
        if ((unsigned char)s[c->where] == fuzz_bytes[c->arg]) return false; /* no change */
        if (c->arg == 0u || fuzz_bytes[c->arg] == 0xFFu || fuzz_bytes[c->arg] == 'n') {
            return on_record_line(s, len, c->where, &start, &eq);
        }
        return false;
    case FUZZ_TRUNC:
        return c->where > 0 && on_record_line(s, len, c->where - 1u, &start, &eq) &&
               c->where > start && c->where <= eq + 1u;
    case FUZZ_TOKEN:
        return strcmp(fuzz_tokens[c->arg], "010") != 0 &&
               on_record_line(s, len, c->where, &start, &eq);
    case FUZZ_EXTRA: {
        size_t e;
        const size_t ls = fuzz_line_span(s, len, c->where, &e);
        return ls < len && on_record_line(s, len, ls, &start, &eq);
    }
    case FUZZ_LONG: return true;
    default: return false;
    }
}

static void test_trace_sweep(void)
{
    static char msg[TRACE_MSG_LEN];
    struct fuzz_case c = {NULL, 0, FUZZ_END, 0, 0};
    unsigned si;
    dut.rec = calloc(MAX_RECS, sizeof(struct trace_record));
    ref.rec = calloc(MAX_RECS, sizeof(struct trace_record));
    REQUIRE(dut.rec != NULL && ref.rec != NULL);
    for (si = 0; si < N_SEEDS; si++) {
        size_t len = 0, stride;
        char *seed = fuzz_read_file(seeds[si], &len);
        unsigned long k;
        REQUIRE(seed != NULL);
        /* The seed itself: read whole by both, every record accepted. */
        dut_parse(seed, len, &dut, msg, sizeof msg);
        ref_parse(seed, len, &ref);
        CHECK_EQ_INT(dut.status, 0);
        CHECK_EQ_INT(ref.status, 0);
        CHECK(dut.n > 0 && dut.n == ref.n);
        stride = UNIT_SIZE(len / 300u, len / 150u);
        if (stride == 0) stride = 1;
        for (k = 0; fuzz_mutate(seed, len, k, stride, UNIT_SIZE(200u, 40u), &c) != FUZZ_END; k++) {
            unsigned i;
            bool agree = true;
            n_cases++;
            dut_parse(c.data, c.len, &dut, msg, sizeof msg);
            ref_parse(c.data, c.len, &ref);
            if (dut.status != INC_OK && dut.status != INC_ERR_FORMAT) {
                report(seeds[si], k, &c, "neither success nor INC_ERR_FORMAT");
                continue;
            }
            if (dut.status != ref.status || dut.n != ref.n ||
                (dut.status != 0 && dut.line != ref.line)) {
                agree = false;
            }
            for (i = 0; agree && i < dut.n; i++)
                agree = same_record(&dut.rec[i], &ref.rec[i]);
            if (!agree) {
                char what[400];
                snprintf(
                    what, sizeof what,
                    "reader %s (%u records, line %u, '%s'), reference %s (%u records, line %u)",
                    dut.status ? "refused" : "accepted", dut.n, dut.status ? dut.line : 0u, msg,
                    ref.status ? "refuses" : "accepts", ref.n, ref.status ? ref.line : 0u);
                report(seeds[si], k, &c, what);
            }
            unit_checks++;
            if (dut.status != 0) {
                char want[32];
                snprintf(want, sizeof want, "trace line %u:", dut.line);
                unit_checks++;
                if (strncmp(msg, want, strlen(want)) != 0)
                    report(seeds[si], k, &c, "message does not name the line");
            } else {
                n_accepted++;
            }
            if (must_fail(seed, len, &c)) {
                n_must_fail++;
                unit_checks++;
                if (dut.status == 0)
                    report(seeds[si], k, &c, "a certainly broken file was accepted");
            }
        }
        free(seed);
    }
    fuzz_case_free(&c);
    printf("trace: %u cases, %u accepted, %u that must be refused\n", n_cases, n_accepted,
           n_must_fail);
    CHECK(n_cases > UNIT_SIZE(30000u, 15000u));
    CHECK(n_must_fail > n_cases / 10u);
    CHECK(n_accepted > n_cases / 10u);
}

/* Named regression inputs (each once silently accepted; see docs/traces.md). */
static void test_trace_regressions(void)
{
    static const char *const bad[] = {
        "F t=18446744073709551616 cs=4 bits=16 mosi=5600 miso=A5C3\n", /* t overflows 64 bits */
        "F t=99999999999999999999 cs=4 bits=16 mosi=5600 miso=A5C3\n",
        "F t=500009cs=4 bits=16 mosi=5600 miso=A5C3\n", /* no blank between fields */
        "F t=5 cs=4 bits=16mosi=5600 miso=A5C3\n",
        "F t=5 cs=4 bits=16 mosi=0x12 miso=A5C3\n", /* C hex prefix in a word */
        "I t=5pin=7\n",
        "F t=5 cs=4 bits=16 mosi=5600 miso=A\0"
        "5C3", /* NUL cuts the last line */
    };
    static const size_t bad_len[] = {0, 0, 0, 0, 0, 0, 46};
    static char msg[TRACE_MSG_LEN];
    struct trace_record *r = calloc(1, sizeof(*r));
    unsigned i;
    REQUIRE(r != NULL);
    for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        const size_t len = bad_len[i] ? bad_len[i] : strlen(bad[i]);
        FILE *f = fmemopen((void *)(uintptr_t)bad[i], len, "r");
        unsigned line = 0;
        REQUIRE(f != NULL);
        msg[0] = '\0';
        CHECK_ERR(trace_parse_next(f, &line, r, msg, sizeof msg), INC_ERR_FORMAT);
        CHECK(strncmp(msg, "trace line 1:", 13) == 0);
        fclose(f);
    }
    free(r);
}

/* trace_replay_open: the first line must be the header exactly (trailing blanks allowed). */
static void test_trace_header(void)
{
    static struct trace_replay rp;
    static const struct {
        const char *text;
        int want;
    } cases[] = {
        {"# inclino-trace 1\nF t=0 cs=4 bits=16 mosi=1 miso=2\n", INC_OK},
        {"# inclino-trace 1\r\nF t=0 cs=4 bits=16 mosi=1 miso=2\n", INC_OK},
        {"# inclino-trace 1  \nF t=0 cs=4 bits=16 mosi=1 miso=2\n", INC_OK},
        {"# inclino-trace 12\nF t=0 cs=4 bits=16 mosi=1 miso=2\n", INC_ERR_FORMAT},
        {"# inclino-trace 1.5\n", INC_ERR_FORMAT},
        {"# inclino-trace\n", INC_ERR_FORMAT},
        {"", INC_ERR_FORMAT},
        {"# inclino-trace 1 and a comment longer than the header buffer of sixty-four characters\n",
         INC_ERR_FORMAT},
        {"F t=0 cs=4 bits=16 mosi=1 miso=2\n", INC_ERR_FORMAT},
        {"# inclino-trace 1\nF t=0 cs=4 bits=16 mosi=1 miso=2 3\n", INC_ERR_FORMAT},
    };
    unsigned i;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        FILE *f = fopen("fuzz_header.trace", "wb");
        int err;
        REQUIRE(f != NULL);
        fputs(cases[i].text, f);
        fclose(f);
        err = trace_replay_open(&rp, "fuzz_header.trace");
        if (err != cases[i].want) {
            unit_fail(__FILE__, __LINE__, "header case %u: %d, want %d (%s)", i, err, cases[i].want,
                      trace_replay_message(&rp));
        }
        unit_checks++;
        if (err == INC_OK) {
            CHECK(rp.have_next && rp.next.kind == TRACE_PERIOD && rp.next.line == 2u);
        } else {
            CHECK(strstr(trace_replay_message(&rp), "line") != NULL);
        }
        trace_replay_finish(&rp);
    }
    remove("fuzz_header.trace");
}

/* ------------------------------------------------------------------ VCD */

/* A capture as sim/vcd.h writes one: 1 ns, mode 3, 16-bit, two CS periods (1 word, 2 words). */
static size_t make_vcd(char *out, size_t cap)
{
    size_t n = 0;
    uint64_t t = 100;
    const uint16_t words[3] = {0x5600, 0xA5C3, 0x0FF0};
    unsigned w, b, period;
    n += (size_t)snprintf(
        out + n, cap - n,
        "$timescale 1 ns $end\n$scope module board $end\n$var wire 1 ! sclk $end\n"
        "$var wire 1 \" mosi $end\n$var wire 1 # miso $end\n$var wire 1 $ cs1 $end\n"
        "$upscope $end\n$enddefinitions $end\n#0\n$dumpvars\n1!\n0\"\n0#\n1$\n$end\n");
    for (period = 0, w = 0; period < 2u; period++) {
        const unsigned nw = period == 0 ? 1u : 2u;
        unsigned i;
        n += (size_t)snprintf(out + n, cap - n, "#%llu\n0$\n", (unsigned long long)t);
        t += 500;
        for (i = 0; i < nw; i++, w++) {
            for (b = 0; b < 16u; b++) {
                const unsigned bit = (words[w] >> (15u - b)) & 1u;
                /* mode 3: data changes on the falling edge, sampled on the rising edge */
                n += (size_t)snprintf(out + n, cap - n, "#%llu\n0!\n%u\"\n%u#\n#%llu\n1!\n",
                                      (unsigned long long)t, bit, bit ^ 1u,
                                      (unsigned long long)(t + 250));
                t += 500;
            }
        }
        n += (size_t)snprintf(out + n, cap - n, "#%llu\n1$\n", (unsigned long long)t);
        t += 2000;
    }
    return n;
}

static const struct trace_vcd_opts vopts = {"sclk", "mosi", "miso", "cs1", 3, 16, 7};

/* Convert; on success check the output thoroughly. Returns the converter's result. */
static int convert_and_check(const char *d, size_t len, const char *label, unsigned long k,
                             char *msg, size_t msg_len, unsigned *records_out)
{
    static struct trace_record r;
    FILE *in = len ? fmemopen((void *)(uintptr_t)d, len, "r") : tmpfile();
    FILE *out = tmpfile();
    int n;
    msg[0] = '\0';
    if (in == NULL || out == NULL) {
        unit_fail(__FILE__, __LINE__, "cannot open memory/temp files");
        return INC_ERR_IO;
    }
    n = trace_from_vcd(in, out, &vopts, msg, msg_len);
    fclose(in);
    if (n >= 0) {
        unsigned line = 0, got = 0;
        uint64_t last_t = 0;
        int pr;
        char pmsg[TRACE_MSG_LEN];
        rewind(out);
        while ((pr = trace_parse_next(out, &line, &r, pmsg, sizeof pmsg)) == 1) {
            got++;
            if (r.kind != TRACE_PERIOD || r.bits != vopts.bits || r.pin != vopts.cs_pin ||
                r.n < 1u || r.n > TRACE_MAX_WORDS || r.t_ns < last_t) {
                unit_fail(__FILE__, __LINE__,
                          "%s case %lu: record %u inconsistent (kind %d bits %u pin %u n %u "
                          "t %llu after %llu)",
                          label, k, got, (int)r.kind, r.bits, r.pin, r.n,
                          (unsigned long long)r.t_ns, (unsigned long long)last_t);
            }
            last_t = r.t_ns;
        }
        unit_checks++;
        if (pr != 0 || got != (unsigned)n) {
            unit_fail(__FILE__, __LINE__,
                      "%s case %lu: returned %d records, the output parses to %u (%d %s)", label, k,
                      n, got, pr, pr ? pmsg : "");
        }
        *records_out = got;
    } else if (n != INC_ERR_FORMAT) {
        unit_fail(__FILE__, __LINE__,
                  "%s case %lu: result %d is neither a count nor INC_ERR_FORMAT", label, k, n);
    } else {
        unit_checks++;
        if (msg[0] == '\0')
            unit_fail(__FILE__, __LINE__, "%s case %lu: refused without a message", label, k);
    }
    fclose(out);
    return n;
}

static void test_vcd_sweep(void)
{
    static char seed[64 * 1024];
    char msg[200];
    struct fuzz_case c = {NULL, 0, FUZZ_END, 0, 0};
    const size_t len = make_vcd(seed, sizeof seed);
    const size_t enddefs = (size_t)(strstr(seed, "$enddefinitions") - seed);
    const size_t stride = UNIT_SIZE(len / 600u, len / 300u) ? UNIT_SIZE(len / 600u, len / 300u)
                                                            : 1u;
    unsigned long k;
    unsigned recs = 0, cases = 0, ok = 0, must = 0;
    static struct trace_record r;
    REQUIRE(len < sizeof seed - 1u);
    /* The seed converts to the two periods it was made of. */
    CHECK_EQ_INT(convert_and_check(seed, len, "vcd seed", 0, msg, sizeof msg, &recs), 2);
    {
        FILE *in = fmemopen(seed, len, "r"), *out = tmpfile();
        unsigned line = 0;
        REQUIRE(in != NULL && out != NULL);
        REQUIRE(trace_from_vcd(in, out, &vopts, msg, sizeof msg) == 2);
        rewind(out);
        REQUIRE(trace_parse_next(out, &line, &r, msg, sizeof msg) == 1);
        CHECK_EQ_INT(r.n, 1);
        CHECK_EQ_HEX(r.mosi[0], 0x5600u);
        CHECK_EQ_HEX(r.miso[0], 0xA9FFu);
        CHECK_EQ_INT(r.t_ns, 100);
        REQUIRE(trace_parse_next(out, &line, &r, msg, sizeof msg) == 1);
        CHECK_EQ_INT(r.n, 2);
        CHECK_EQ_HEX(r.mosi[1], 0x0FF0u);
        CHECK_EQ_HEX(r.miso[1], 0xF00Fu);
        fclose(in);
        fclose(out);
    }
    for (k = 0; fuzz_mutate(seed, len, k, stride, UNIT_SIZE(300u, 60u), &c) != FUZZ_END; k++) {
        bool must_fail = false;
        int n;
        cases++;
        n = convert_and_check(c.data, c.len, "vcd", k, msg, sizeof msg, &recs);
        ok += n >= 0;
        if (c.family == FUZZ_TRUNC && c.where < enddefs + 15u) must_fail = true;
        if (c.family == FUZZ_DELLINE && c.where >= 2u && c.where <= 5u)
            must_fail = true; /* a $var */
        if (c.family == FUZZ_TOKEN && c.where > enddefs && c.where > 0 &&
            c.data[c.where - 1] == '#') {
            /* a timestamp: only a plain decimal passes ("010" is 10: valid where time does not
             * run backwards, which the converter must then notice, see the regressions) */
            must_fail = strcmp(fuzz_tokens[c.arg], "010") != 0;
        }
        if (must_fail) {
            must++;
            unit_checks++;
            if (n >= 0) {
                unit_fail(__FILE__, __LINE__,
                          "vcd case %lu (%s at %zu, arg %u): a broken capture was accepted "
                          "(%d records)",
                          k, fuzz_family_name(c.family), c.where, c.arg, n);
            }
        }
    }
    fuzz_case_free(&c);
    printf("vcd: %u cases, %u converted, %u that must be refused\n", cases, ok, must);
    CHECK(cases > UNIT_SIZE(10000u, 5000u));
    CHECK(must > UNIT_SIZE(80u, 40u));
    CHECK(ok > cases / 4u);
}

/* Named VCD regression inputs (each once converted silently). */
static void test_vcd_regressions(void)
{
    static const char *const head =
        "$timescale 1 ns $end\n$var wire 1 ! sclk $end\n$var wire 1 \" mosi $end\n$var wire 1 # miso $end\n"
        "$var wire 1 $ cs1 $end\n$enddefinitions $end\n";
    static const char *const bodies[] = {
        "#abc\n1!\n",                  /* a timestamp that is not a number */
        "#-5\n1!\n",                   /* a negative timestamp */
        "#99999999999999999999\n1!\n", /* overflows 64 bits */
        "#100\n1!\n#50\n0!\n",         /* time runs backwards */
        "#\n1!\n",                     /* empty timestamp */
    };
    static const char *const scales[] = {
        "$timescale -1 ns $end\n", "$timescale 99999999999 s $end\n", "$timescale 1 ks $end\n"};
    char text[1024], msg[200];
    unsigned i, recs;
    for (i = 0; i < sizeof bodies / sizeof bodies[0]; i++) {
        snprintf(text, sizeof text, "%s%s", head, bodies[i]);
        CHECK_ERR(
            convert_and_check(text, strlen(text), "vcd regression", i, msg, sizeof msg, &recs),
            INC_ERR_FORMAT);
        CHECK(strstr(msg, "timestamp") != NULL);
    }
    for (i = 0; i < sizeof scales / sizeof scales[0]; i++) {
        snprintf(text, sizeof text, "%s%s#1\n", scales[i], head + strlen("$timescale 1 ns $end\n"));
        CHECK_ERR(convert_and_check(text, strlen(text), "vcd timescale", i, msg, sizeof msg, &recs),
                  INC_ERR_FORMAT);
        CHECK(strstr(msg, "timescale") != NULL);
    }
}

int main(void)
{
    UNIT_RUN(test_trace_regressions);
    UNIT_RUN(test_trace_header);
    UNIT_RUN(test_trace_sweep);
    UNIT_RUN(test_vcd_regressions);
    UNIT_RUN(test_vcd_sweep);
    return unit_report();
}
