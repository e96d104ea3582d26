/* trace_vcd.c - logic-analyser capture (VCD) to trace (see sim/trace.h, docs/traces.md). */
#include "inclino/sim/trace.h"

#include <ctype.h>
#include <stdlib.h>
#include <string.h>

#include "inclino/sim/line.h"

#define VCD_ID_MAX 16

/* what, and " at t=<ns> ns" when at_t is not UINT64_MAX. */
static int vfail(char *msg, size_t len, const char *what, unsigned long long at_t)
{
    if (msg != NULL && len > 0) {
        if (at_t != UINT64_MAX) {
            snprintf(msg, len, "%s at t=%llu ns", what, at_t);
        } else {
            snprintf(msg, len, "%s", what);
        }
    }
    return INC_ERR_FORMAT;
}

/* "VCD line N: what" */
static int lfail(char *msg, size_t len, unsigned line, const char *what)
{
    if (msg != NULL && len > 0) {
        snprintf(msg, len, "VCD line %u: %s", line, what);
    }
    return INC_ERR_FORMAT;
}

/*
 * Timescale "1 ns", "10ns", "1 us", "100 ps" ... -> numerator/denominator to ns. The number is
 * 1..1000 in decimal digits (IEEE 1364 allows 1, 10, 100); a sign, another unit or a number that
 * would overflow the scale is refused rather than wrapped.
 */
static int parse_timescale(const char *s, unsigned long long *mul, unsigned long long *div)
{
    unsigned long long n = 0;
    unsigned digits = 0;
    while (isdigit((unsigned char)*s) && digits < 5u) {
        n = n * 10u + (unsigned)(*s++ - '0');
        digits++;
    }
    if (digits == 0 || isdigit((unsigned char)*s) || n == 0 || n > 1000u) {
        return -1;
    }
    while (*s == ' ')
        s++;
    *mul = n;
    *div = 1;
    if (strncmp(s, "fs", 2) == 0)
        *div = 1000000;
    else if (strncmp(s, "ps", 2) == 0)
        *div = 1000;
    else if (strncmp(s, "ns", 2) == 0)
        *div = 1;
    else if (strncmp(s, "us", 2) == 0)
        *mul = n * 1000ull;
    else if (strncmp(s, "ms", 2) == 0)
        *mul = n * 1000000ull;
    else if (s[0] == 's')
        *mul = n * 1000000000ull;
    else
        return -1;
    return 0;
}

/* "#<decimal>" (p after the '#'), trailing blanks allowed, scaled to ns without overflow. */
static int parse_time(const char *p, unsigned long long mul, unsigned long long div,
                      unsigned long long *t)
{
    unsigned long long v = 0;
    if (!isdigit((unsigned char)*p)) {
        return -1;
    }
    while (isdigit((unsigned char)*p)) {
        const unsigned d = (unsigned)(*p++ - '0');
        if (v > (UINT64_MAX - d) / 10u) {
            return -1;
        }
        v = v * 10u + d;
    }
    while (*p == ' ' || *p == '\t' || *p == '\r')
        p++;
    if (*p != '\0' || v > (UINT64_MAX - 1u) / mul) {
        return -1; /* UINT64_MAX itself is vfail's "no time" */
    }
    *t = v * mul / div;
    return 0;
}

int trace_from_vcd(FILE *vcd, FILE *out, const struct trace_vcd_opts *o, char *msg, size_t msg_len)
{
    static struct trace_record r; /* 1 KiB: kept off the stack */
    char line[512];
    unsigned lineno = 0;
    int got;
    char id_sclk[VCD_ID_MAX] = "", id_mosi[VCD_ID_MAX] = "", id_miso[VCD_ID_MAX] = "",
         id_cs[VCD_ID_MAX] = "";
    int sclk = -1, mosi = 0, miso = 0, cs = 1;
    unsigned long long t = 0, mul = 1, div = 1;
    unsigned nb = 0, records = 0;
    uint16_t wi = 0, wo = 0;
    int in_defs = 1, in_timescale = 0;
    int cpol, cpha;
    if (vcd == NULL || out == NULL || o == NULL || o->sclk == NULL || o->mosi == NULL ||
        o->miso == NULL || o->cs == NULL) {
        return INC_ERR_NULL;
    }
    if (o->mode > 3u || (o->bits != 8u && o->bits != 16u) || o->cs_pin > TRACE_PIN_MAX) {
        return INC_ERR_INVAL;
    }
    cpol = (int)(o->mode >> 1);
    cpha = (int)(o->mode & 1u);
    if (fprintf(out, "# inclino-trace 1\n# converted from a VCD capture (mode %u, %u-bit)\n",
                o->mode, o->bits) < 0) {
        return INC_ERR_IO;
    }
    while ((got = sim_read_line(vcd, line, sizeof(line))) != SIM_LINE_EOF) {
        char *p = line;
        lineno++;
        if (got == SIM_LINE_TOO_LONG) {
            return lfail(msg, msg_len, lineno, "line longer than 511 characters");
        }
        if (got == SIM_LINE_NUL) {
            return lfail(msg, msg_len, lineno, "NUL byte in the line");
        }
        if (got == SIM_LINE_IO) {
            lfail(msg, msg_len, lineno, "read error");
            return INC_ERR_IO;
        }
        while (*p == ' ' || *p == '\t')
            p++;
        if (in_defs) {
            char id[VCD_ID_MAX], name[64];
            unsigned width;
            if (in_timescale || strncmp(p, "$timescale", 10) == 0) {
                char *q = in_timescale ? p : p + 10;
                while (*q == ' ')
                    q++;
                if (*q != '\0' && *q != '\r' && strncmp(q, "$end", 4) != 0) {
                    if (parse_timescale(q, &mul, &div) != 0) {
                        return lfail(msg, msg_len, lineno, "unsupported $timescale");
                    }
                    in_timescale = 0;
                } else {
                    in_timescale = 1;
                }
                if (strstr(q, "$end") != NULL) in_timescale = 0;
            } else if (sscanf(p, "$var %*s %u %15s %63s", &width, id, name) == 3) {
                char *bracket = strchr(name, '[');
                if (bracket != NULL) *bracket = '\0';
                if (width == 1u) {
                    if (strcmp(name, o->sclk) == 0) strcpy(id_sclk, id);
                    if (strcmp(name, o->mosi) == 0) strcpy(id_mosi, id);
                    if (strcmp(name, o->miso) == 0) strcpy(id_miso, id);
                    if (strcmp(name, o->cs) == 0) strcpy(id_cs, id);
                }
            } else if (strncmp(p, "$enddefinitions", 15) == 0) {
                in_defs = 0;
                if (!id_sclk[0] || !id_mosi[0] || !id_miso[0] || !id_cs[0]) {
                    return vfail(msg, msg_len, "VCD: a wire named in the options is missing",
                                 UINT64_MAX);
                }
            }
            continue;
        }
        if (p[0] == '#') {
            /* A timestamp that is not a plain decimal, overflows, or runs backwards is a broken
             * capture: strtoull used to read "#abc" as 0 and "#-5" as a huge time. */
            unsigned long long nt;
            if (parse_time(p + 1, mul, div, &nt) != 0) {
                return lfail(msg, msg_len, lineno,
                             "bad timestamp (decimal digits within 64 bits expected)");
            }
            if (nt < t) {
                return lfail(msg, msg_len, lineno, "timestamp goes backwards");
            }
            t = nt;
            continue;
        }
        if (p[0] == '0' || p[0] == '1' || p[0] == 'x' || p[0] == 'z' || p[0] == 'X' ||
            p[0] == 'Z') {
            const int v = p[0] == '1';
            char *id = p + 1;
            id[strcspn(id, " \r\n")] = '\0';
            if (strcmp(id, id_cs) == 0) {
                if (v == 0 && cs == 1) {
                    memset(&r, 0, sizeof(r));
                    r.kind = TRACE_PERIOD;
                    r.t_ns = t;
                    r.pin = o->cs_pin;
                    r.bits = o->bits;
                    nb = 0;
                    wi = wo = 0;
                } else if (v == 1 && cs == 0) {
                    if (nb != 0) {
                        return vfail(msg, msg_len, "VCD: CS rose mid-word", t);
                    }
                    if (r.n > 0) {
                        if (trace_write_record(out, &r) != INC_OK) return INC_ERR_IO;
                        records++;
                    }
                }
                cs = v;
            } else if (strcmp(id, id_mosi) == 0) {
                mosi = v;
            } else if (strcmp(id, id_miso) == 0) {
                miso = v;
            } else if (strcmp(id, id_sclk) == 0) {
                const int leading = v != cpol;
                const int sampling = cpha ? !leading : leading;
                if (cs == 0 && sclk != -1 && v != sclk && sampling) {
                    wi = (uint16_t)((wi << 1) | (unsigned)mosi);
                    wo = (uint16_t)((wo << 1) | (unsigned)miso);
                    if (++nb == o->bits) {
                        if (r.n == TRACE_MAX_WORDS) {
                            return vfail(msg, msg_len, "VCD: too many words in one CS period", t);
                        }
                        r.mosi[r.n] = wi;
                        r.miso[r.n] = wo;
                        r.n++;
                        nb = 0;
                        wi = wo = 0;
                    }
                }
                sclk = v;
            }
        }
    }
    if (in_defs) {
        return vfail(msg, msg_len, "VCD: no $enddefinitions", UINT64_MAX);
    }
    if (cs == 0) { /* the capture ended inside a CS period: keep its words, refuse half a word */
        if (nb != 0) {
            return vfail(msg, msg_len, "VCD: capture ends mid-word", t);
        }
        if (r.n > 0) {
            if (trace_write_record(out, &r) != INC_OK) return INC_ERR_IO;
            records++;
        }
    }
    return (int)records;
}
