/* gps_nmea.c - NMEA 0183 RMC/GGA/VTG parser (inclino/gps_nmea.h). */
#include "inclino/gps_nmea.h"

struct field {
    const char *s;
    size_t n;
};

static void msg_clear(struct nmea_msg *m)
{
    m->type = NMEA_NONE;
    m->talker[0] = '\0';
    m->talker[1] = '\0';
    m->talker[2] = '\0';
    m->has = 0u;
    m->time.hour = 0u;
    m->time.min = 0u;
    m->time.sec = 0u;
    m->time.ms = 0u;
    m->date.day = 0u;
    m->date.month = 0u;
    m->date.year = 0u;
    m->lat_e7 = 0;
    m->lon_e7 = 0;
    m->speed_mmps = 0u;
    m->speed_kmh_mmps = 0u;
    m->course_cdeg = 0u;
    m->status = '\0';
    m->mode = '\0';
    m->quality = 0u;
    m->sats = 0u;
    m->hdop_c = 0u;
    m->alt_mm = 0;
}

uint8_t nmea_checksum(const char *s, size_t n)
{
    uint8_t x = 0u;
    size_t i;
    for (i = 0; i < n; i++)
        x ^= (uint8_t)s[i];
    return x;
}

static bool is_digit(char c)
{
    return c >= '0' && c <= '9';
}

static int hex_val(char c)
{
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    return -1;
}

/* n digits of s as an unsigned number (n <= 9). */
static bool digits(const char *s, size_t n, uint32_t *out)
{
    uint32_t v = 0u;
    size_t i;
    if (n == 0u || n > 9u) return false;
    for (i = 0; i < n; i++) {
        if (!is_digit(s[i])) return false;
        v = v * 10u + (uint32_t)(s[i] - '0');
    }
    *out = v;
    return true;
}

/*
 * Unsigned decimal "iii.fff" -> value * 10^frac, rounded half up at the first unused decimal.
 * Integer part: 1..max_int digits (at least one digit overall; ".5" and "5." are accepted).
 * Result <= (10^9 - 1) * 10^frac + ..., kept in uint64.
 */
static bool udec(const char *s, size_t n, unsigned max_int, unsigned frac, uint64_t *out)
{
    size_t i = 0;
    unsigned ni = 0, nf = 0;
    uint64_t v = 0u;
    bool any = false, round_up = false;
    while (i < n && is_digit(s[i])) {
        if (++ni > max_int) return false;
        v = v * 10u + (uint64_t)(s[i] - '0');
        i++;
        any = true;
    }
    if (i < n) {
        if (s[i] != '.') return false;
        i++;
        while (i < n) {
            if (!is_digit(s[i])) return false;
            if (nf < frac)
                v = v * 10u + (uint64_t)(s[i] - '0');
            else if (nf == frac)
                round_up = s[i] >= '5';
            if (nf <= frac) /* later digits are checked but change nothing */
                nf++;
            i++;
            any = true;
        }
    }
    if (!any) return false;
    if (nf > frac) nf = frac;
    while (nf < frac) {
        v *= 10u;
        nf++;
    }
    *out = v + (round_up ? 1u : 0u);
    return true;
}

/* Signed decimal: optional '-' then udec. */
static bool sdec(const char *s, size_t n, unsigned max_int, unsigned frac, int64_t *out)
{
    uint64_t u;
    bool neg = false;
    if (n > 0u && s[0] == '-') {
        neg = true;
        s++;
        n--;
    }
    if (!udec(s, n, max_int, frac, &u)) return false;
    *out = neg ? -(int64_t)u : (int64_t)u;
    return true;
}

static bool one_char(struct field f, char a, char b)
{
    return f.n == 1u && (f.s[0] == a || f.s[0] == b);
}

/* hhmmss[.sss] */
static enum nmea_why parse_time(struct field f, struct nmea_msg *m)
{
    uint32_t hh, mm, ss;
    uint64_t ms = 0u;
    if (f.n == 0u) return NMEA_OK;
    if (f.n < 6u || !digits(f.s, 2u, &hh) || !digits(f.s + 2, 2u, &mm) || !digits(f.s + 4, 2u, &ss))
        return NMEA_E_TIME;
    if (f.n > 6u) {
        /* ".sss": a decimal point and 1..9 digits, 3 used (truncated: a time tag, not a value) */
        size_t i, nf = f.n - 7u;
        if (f.s[6] != '.' || nf == 0u || nf > 9u) return NMEA_E_TIME;
        for (i = 0; i < 3u; i++) {
            char c = i < nf ? f.s[7 + i] : '0';
            if (!is_digit(c)) return NMEA_E_TIME;
            ms = ms * 10u + (uint64_t)(c - '0');
        }
        for (i = 3u; i < nf; i++)
            if (!is_digit(f.s[7 + i])) return NMEA_E_TIME;
    }
    if (hh > 23u || mm > 59u || ss > 60u) return NMEA_E_TIME;
    m->time.hour = (uint8_t)hh;
    m->time.min = (uint8_t)mm;
    m->time.sec = (uint8_t)ss;
    m->time.ms = (uint16_t)ms;
    m->has |= NMEA_HAS_TIME;
    return NMEA_OK;
}

static enum nmea_why parse_date(struct field f, struct nmea_msg *m)
{
    uint32_t dd, mo, yy;
    if (f.n == 0u) return NMEA_OK;
    if (f.n != 6u || !digits(f.s, 2u, &dd) || !digits(f.s + 2, 2u, &mo) ||
        !digits(f.s + 4, 2u, &yy))
        return NMEA_E_DATE;
    if (dd < 1u || dd > 31u || mo < 1u || mo > 12u) return NMEA_E_DATE;
    m->date.day = (uint8_t)dd;
    m->date.month = (uint8_t)mo;
    m->date.year = (uint16_t)(2000u + yy);
    m->has |= NMEA_HAS_DATE;
    return NMEA_OK;
}

/* (d)ddmm.mmmm -> 1e-7 deg, deg_digits 2 or 3, limit in whole degrees. */
static bool parse_angle(struct field f, unsigned deg_digits, uint32_t limit_deg, uint32_t *e7)
{
    uint32_t deg;
    uint64_t min_e7, v;
    size_t rest;
    if (f.n < deg_digits + 2u || !digits(f.s, deg_digits, &deg)) return false;
    rest = f.n - deg_digits;
    /* minutes: exactly two integer digits */
    if (!is_digit(f.s[deg_digits]) || !is_digit(f.s[deg_digits + 1u]) ||
        (rest > 2u && f.s[deg_digits + 2u] != '.'))
        return false;
    if (rest > 13u) /* "mm." + at most 10 decimals */
        return false;
    if (!udec(f.s + deg_digits, rest, 2u, 7u, &min_e7)) return false;
    if (min_e7 >= 600000000u) /* 60 minutes (also 59.99999995 rounding up to 60) */
        return false;
    v = (uint64_t)deg * 10000000u + (min_e7 + 30u) / 60u;
    if (v > (uint64_t)limit_deg * 10000000u) return false;
    *e7 = (uint32_t)v;
    return true;
}

static enum nmea_why parse_pos(const struct field *f, struct nmea_msg *m)
{
    /* f[0] lat, f[1] N/S, f[2] lon, f[3] E/W */
    uint32_t lat, lon;
    bool any = f[0].n || f[1].n || f[2].n || f[3].n;
    if (!any) return NMEA_OK;
    if (f[0].n && !parse_angle(f[0], 2u, 90u, &lat)) return NMEA_E_LAT;
    if (f[1].n && !one_char(f[1], 'N', 'S')) return NMEA_E_NS;
    if (f[2].n && !parse_angle(f[2], 3u, 180u, &lon)) return NMEA_E_LON;
    if (f[3].n && !one_char(f[3], 'E', 'W')) return NMEA_E_EW;
    if (!f[0].n || !f[1].n || !f[2].n || !f[3].n) return NMEA_E_POS_PARTIAL;
    m->lat_e7 = f[1].s[0] == 'S' ? -(int32_t)lat : (int32_t)lat;
    m->lon_e7 = f[3].s[0] == 'W' ? -(int32_t)lon : (int32_t)lon;
    m->has |= NMEA_HAS_POS;
    return NMEA_OK;
}

/* knots (or km/h) with 3 decimals used -> mm/s. num/den: 1852/3.6 = 4630/9 per knot... per
 * milli-knot: 1852 mm per 3.6 s = 514.444 mm/s per knot = 0.514444 mm/s per milli-knot. */
static bool speed_mmps(struct field f, unsigned max_int, uint32_t num, uint32_t den, uint32_t *out)
{
    uint64_t milli;
    if (!udec(f.s, f.n, max_int, 3u, &milli)) return false;
    /* milli <= 1e8 (+1); * num (<= 1852) < 2^38 */
    *out = (uint32_t)((milli * num + den / 2u) / den);
    return true;
}

static enum nmea_why parse_knots(struct field f, struct nmea_msg *m)
{
    /* mm/s = milli-knots * 1852 / 3600 */
    if (f.n == 0u) return NMEA_OK;
    if (!speed_mmps(f, 4u, 1852u, 3600u, &m->speed_mmps)) return NMEA_E_SPEED;
    m->has |= NMEA_HAS_SPEED;
    return NMEA_OK;
}

static enum nmea_why parse_course(struct field f, struct nmea_msg *m)
{
    uint64_t c;
    if (f.n == 0u) return NMEA_OK;
    if (!udec(f.s, f.n, 3u, 2u, &c) || c > 36000u) return NMEA_E_COURSE;
    m->course_cdeg = (uint16_t)(c == 36000u ? 0u : c);
    m->has |= NMEA_HAS_COURSE;
    return NMEA_OK;
}

static enum nmea_why parse_mode(struct field f, struct nmea_msg *m)
{
    static const char modes[] = "ADEFMNPRS";
    size_t i;
    if (f.n == 0u) return NMEA_OK;
    if (f.n != 1u) return NMEA_E_MODE;
    for (i = 0; modes[i] != '\0'; i++) {
        if (f.s[0] == modes[i]) {
            m->mode = f.s[0];
            m->has |= NMEA_HAS_MODE;
            return NMEA_OK;
        }
    }
    return NMEA_E_MODE;
}

static enum nmea_why parse_rmc(const struct field *f, size_t nf, struct nmea_msg *m)
{
    enum nmea_why w;
    uint64_t mv;
    /* 1 time 2 status 3 lat 4 NS 5 lon 6 EW 7 speed 8 course 9 date 10 magvar 11 EW
     * [12 mode (2.3)] [13 navigational status (4.1)] */
    if (nf < 12u || nf > 14u) return NMEA_E_FIELD_COUNT;
    if ((w = parse_time(f[1], m)) != NMEA_OK) return w;
    if (f[2].n) {
        if (!one_char(f[2], 'A', 'V')) return NMEA_E_STATUS;
        m->status = f[2].s[0];
        m->has |= NMEA_HAS_STATUS;
    }
    if ((w = parse_pos(&f[3], m)) != NMEA_OK) return w;
    if ((w = parse_knots(f[7], m)) != NMEA_OK) return w;
    if ((w = parse_course(f[8], m)) != NMEA_OK) return w;
    if ((w = parse_date(f[9], m)) != NMEA_OK) return w;
    if (f[10].n && (!udec(f[10].s, f[10].n, 3u, 1u, &mv) || mv > 1800u)) return NMEA_E_MAGVAR;
    if (f[11].n && !one_char(f[11], 'E', 'W')) return NMEA_E_MAGVAR;
    if (nf >= 13u && (w = parse_mode(f[12], m)) != NMEA_OK) return w;
    if (nf == 14u && f[13].n && !(f[13].n == 1u && f[13].s[0] >= 'A' && f[13].s[0] <= 'Z'))
        return NMEA_E_MODE;
    return NMEA_OK;
}

static enum nmea_why parse_gga(const struct field *f, size_t nf, struct nmea_msg *m)
{
    enum nmea_why w;
    uint32_t v;
    uint64_t u;
    int64_t s;
    /* 1 time 2 lat 3 NS 4 lon 5 EW 6 quality 7 sats 8 hdop 9 alt 10 M 11 sep 12 M 13 age
     * 14 station */
    if (nf != 15u) return NMEA_E_FIELD_COUNT;
    if ((w = parse_time(f[1], m)) != NMEA_OK) return w;
    if ((w = parse_pos(&f[2], m)) != NMEA_OK) return w;
    if (f[6].n) {
        if (f[6].n != 1u || !digits(f[6].s, 1u, &v) || v > 8u) return NMEA_E_QUALITY;
        m->quality = (uint8_t)v;
        m->has |= NMEA_HAS_QUALITY;
    }
    if (f[7].n) {
        if (f[7].n > 2u || !digits(f[7].s, f[7].n, &v)) return NMEA_E_SATS;
        m->sats = (uint8_t)v;
        m->has |= NMEA_HAS_SATS;
    }
    if (f[8].n) {
        if (!udec(f[8].s, f[8].n, 2u, 2u, &u)) return NMEA_E_HDOP;
        if (u > 9999u) return NMEA_E_HDOP;
        m->hdop_c = (uint16_t)u;
        m->has |= NMEA_HAS_HDOP;
    }
    if (f[9].n) {
        if (!sdec(f[9].s, f[9].n, 5u, 3u, &s)) return NMEA_E_ALT;
        m->alt_mm = (int32_t)s; /* |s| < 1e8 */
        m->has |= NMEA_HAS_ALT;
    }
    if ((f[9].n && !one_char(f[10], 'M', 'M')) ||
        (!f[9].n && f[10].n && !one_char(f[10], 'M', 'M')))
        return NMEA_E_UNIT;
    if (f[11].n && !sdec(f[11].s, f[11].n, 5u, 3u, &s)) return NMEA_E_ALT;
    if ((f[11].n && !one_char(f[12], 'M', 'M')) ||
        (!f[11].n && f[12].n && !one_char(f[12], 'M', 'M')))
        return NMEA_E_UNIT;
    if (f[13].n && !udec(f[13].s, f[13].n, 4u, 1u, &u)) return NMEA_E_AGE;
    if (f[14].n && (f[14].n > 4u || !digits(f[14].s, f[14].n, &v) || v > 1023u)) return NMEA_E_AGE;
    return NMEA_OK;
}

static enum nmea_why parse_vtg(const struct field *f, size_t nf, struct nmea_msg *m)
{
    enum nmea_why w;
    uint64_t u;
    /* 1 course T 2 'T' 3 course M 4 'M' 5 knots 6 'N' 7 km/h 8 'K' [9 mode] */
    if (nf != 9u && nf != 10u) return NMEA_E_FIELD_COUNT;
    if ((w = parse_course(f[1], m)) != NMEA_OK) return w;
    if (f[3].n && (!udec(f[3].s, f[3].n, 3u, 2u, &u) || u > 36000u)) return NMEA_E_COURSE;
    if ((f[2].n && !one_char(f[2], 'T', 'T')) || (f[4].n && !one_char(f[4], 'M', 'M')) ||
        (f[6].n && !one_char(f[6], 'N', 'N')) || (f[8].n && !one_char(f[8], 'K', 'K')))
        return NMEA_E_UNIT;
    if ((w = parse_knots(f[5], m)) != NMEA_OK) return w;
    if (f[7].n) {
        /* mm/s = milli-km/h * 1000 / 3600 */
        if (!speed_mmps(f[7], 5u, 1000u, 3600u, &m->speed_kmh_mmps)) return NMEA_E_SPEED;
        m->has |= NMEA_HAS_SPEED_KMH;
    }
    if (nf == 10u && (w = parse_mode(f[9], m)) != NMEA_OK) return w;
    return NMEA_OK;
}

static bool same3(const char *s, const char *t)
{
    return s[0] == t[0] && s[1] == t[1] && s[2] == t[2];
}

/* line[0..len) = "$....*hh", no CR LF. */
static enum nmea_why parse_body(const char *line, size_t len, struct nmea_msg *m)
{
    struct field f[NMEA_MAX_FIELDS + 1u];
    size_t i, star = len, nf = 0, start;
    int h1, h2;
    if (len == 0u || line[0] != '$') return NMEA_E_NO_START;
    if (len > NMEA_MAX_CHARS) return NMEA_E_TOO_LONG;
    for (i = 1; i < len; i++) {
        char c = line[i];
        if ((unsigned char)c < 0x20u || (unsigned char)c > 0x7Eu) return NMEA_E_CHAR;
        if (c == '$') return NMEA_E_TRUNCATED;
        if (c == '*' && star == len) star = i;
    }
    if (star == len) return NMEA_E_NO_CHECKSUM;
    if (len - star != 3u) return NMEA_E_CHECKSUM_FIELD;
    h1 = hex_val(line[star + 1u]);
    h2 = hex_val(line[star + 2u]);
    if (h1 < 0 || h2 < 0) return NMEA_E_CHECKSUM_FIELD;
    if (nmea_checksum(line + 1, star - 1u) != (uint8_t)(h1 * 16 + h2)) return NMEA_E_CHECKSUM;
    /* split "$ADDR,f1,f2,...": f[0] = address */
    start = 1u;
    for (i = 1; i <= star; i++) {
        if (i == star || line[i] == ',') {
            if (nf > NMEA_MAX_FIELDS) return NMEA_E_FIELD_COUNT;
            f[nf].s = line + start;
            f[nf].n = i - start;
            nf++;
            start = i + 1u;
        }
    }
    if (f[0].n != 5u) return NMEA_E_ADDRESS;
    for (i = 0; i < 5u; i++) {
        char c = f[0].s[i];
        if (!((c >= 'A' && c <= 'Z') || (i >= 2u && is_digit(c)))) return NMEA_E_ADDRESS;
    }
    if (f[0].s[0] == 'P') /* proprietary */
        return NMEA_E_TYPE;
    m->talker[0] = f[0].s[0];
    m->talker[1] = f[0].s[1];
    if (same3(f[0].s + 2, "RMC")) {
        m->type = NMEA_RMC;
        return parse_rmc(f, nf, m);
    }
    if (same3(f[0].s + 2, "GGA")) {
        m->type = NMEA_GGA;
        return parse_gga(f, nf, m);
    }
    if (same3(f[0].s + 2, "VTG")) {
        m->type = NMEA_VTG;
        return parse_vtg(f, nf, m);
    }
    return NMEA_E_TYPE;
}

int nmea_parse_line(const char *line, size_t len, struct nmea_msg *msg, enum nmea_why *why)
{
    enum nmea_why w;
    if (msg == NULL || (line == NULL && len > 0u)) {
        if (why != NULL) *why = NMEA_E_NO_START;
        if (msg != NULL) msg_clear(msg);
        return INC_ERR_NULL;
    }
    msg_clear(msg);
    if (len > 0u && line[len - 1u] == '\n') len--;
    if (len > 0u && line[len - 1u] == '\r') len--;
    w = parse_body(line, len, msg);
    if (w != NMEA_OK) msg_clear(msg);
    if (why != NULL) *why = w;
    return nmea_why_err(w);
}

int nmea_init(struct nmea_parser *p)
{
    if (p == NULL) return INC_ERR_NULL;
    p->len = 0u;
    p->in_sentence = false;
    p->overlong = false;
    p->cr = false;
    p->after_cr = false;
    p->why = NMEA_OK;
    p->stats.sentences = 0u;
    p->stats.errors = 0u;
    p->stats.skipped = 0u;
    p->ready = true;
    return INC_OK;
}

static int finish(struct nmea_parser *p, enum nmea_why w, struct nmea_msg *msg)
{
    p->why = w;
    p->in_sentence = false;
    p->overlong = false;
    p->cr = false;
    p->after_cr = false;
    p->len = 0u;
    if (w != NMEA_OK) {
        msg_clear(msg);
        p->stats.errors++;
        return nmea_why_err(w);
    }
    p->stats.sentences++;
    return 1;
}

int nmea_feed(struct nmea_parser *p, const char *data, size_t len, size_t *used,
              struct nmea_msg *msg)
{
    size_t i;
    if (used != NULL) *used = 0u;
    if (p == NULL || msg == NULL || used == NULL || (data == NULL && len > 0u)) return INC_ERR_NULL;
    if (!p->ready) return INC_ERR_STATE;
    for (i = 0; i < len; i++) {
        char c = data[i];
        if (!p->in_sentence) {
            if (c == '$') {
                p->in_sentence = true;
                p->overlong = false;
                p->cr = false;
                p->after_cr = false;
                p->line[0] = c;
                p->len = 1u;
            } else {
                p->stats.skipped++;
            }
            continue;
        }
        if (c == '$') {
            /* the previous sentence never ended: refuse it, keep this byte for the next one */
            *used = i;
            return finish(p, p->overlong ? NMEA_E_TOO_LONG : NMEA_E_TRUNCATED, msg);
        }
        if (c == '\n') {
            enum nmea_why w;
            *used = i + 1u;
            if (p->overlong) return finish(p, NMEA_E_TOO_LONG, msg);
            if (p->after_cr) return finish(p, NMEA_E_CHAR, msg);
            msg_clear(msg);
            w = parse_body(p->line, p->len, msg);
            return finish(p, w, msg);
        }
        if (c == '\r') {
            /* not stored: only LF may follow it */
            if (p->cr) p->after_cr = true;
            p->cr = true;
            continue;
        }
        if (p->cr) p->after_cr = true; /* a byte between CR and LF */
        if (p->overlong || p->after_cr) continue;
        if (p->len >= NMEA_MAX_CHARS) {
            p->overlong = true;
            continue;
        }
        p->line[p->len++] = c;
    }
    *used = len;
    return 0;
}

int nmea_why_err(enum nmea_why why)
{
    switch (why) {
    case NMEA_OK: return INC_OK;
    case NMEA_E_TOO_LONG: return INC_ERR_NO_SPACE;
    case NMEA_E_CHECKSUM: return INC_ERR_CRC;
    case NMEA_E_TYPE: return INC_ERR_UNSUPPORTED;
    case NMEA_E_TRUNCATED:
    case NMEA_E_CHAR:
    case NMEA_E_NO_START:
    case NMEA_E_NO_CHECKSUM:
    case NMEA_E_CHECKSUM_FIELD:
    case NMEA_E_ADDRESS:
    case NMEA_E_FIELD_COUNT:
    case NMEA_E_TIME:
    case NMEA_E_DATE:
    case NMEA_E_STATUS:
    case NMEA_E_LAT:
    case NMEA_E_NS:
    case NMEA_E_LON:
    case NMEA_E_EW:
    case NMEA_E_POS_PARTIAL:
    case NMEA_E_SPEED:
    case NMEA_E_COURSE:
    case NMEA_E_MAGVAR:
    case NMEA_E_MODE:
    case NMEA_E_QUALITY:
    case NMEA_E_SATS:
    case NMEA_E_HDOP:
    case NMEA_E_ALT:
    case NMEA_E_UNIT:
    case NMEA_E_AGE: return INC_ERR_FORMAT;
    case NMEA_WHY_COUNT: break;
    }
    return INC_ERR_INVAL;
}

const char *nmea_why_name(enum nmea_why why)
{
    switch (why) {
    case NMEA_OK: return "ok";
    case NMEA_E_TOO_LONG: return "sentence too long";
    case NMEA_E_TRUNCATED: return "sentence cut off by a new '$'";
    case NMEA_E_CHAR: return "non-printable byte in sentence";
    case NMEA_E_NO_START: return "line does not start with '$'";
    case NMEA_E_NO_CHECKSUM: return "no checksum ('*hh')";
    case NMEA_E_CHECKSUM_FIELD: return "checksum not two hex digits";
    case NMEA_E_CHECKSUM: return "checksum mismatch";
    case NMEA_E_ADDRESS: return "bad address field";
    case NMEA_E_TYPE: return "sentence type not decoded";
    case NMEA_E_FIELD_COUNT: return "wrong number of fields";
    case NMEA_E_TIME: return "bad time";
    case NMEA_E_DATE: return "bad date";
    case NMEA_E_STATUS: return "bad RMC status";
    case NMEA_E_LAT: return "bad latitude";
    case NMEA_E_NS: return "bad N/S indicator";
    case NMEA_E_LON: return "bad longitude";
    case NMEA_E_EW: return "bad E/W indicator";
    case NMEA_E_POS_PARTIAL: return "incomplete position";
    case NMEA_E_SPEED: return "bad speed";
    case NMEA_E_COURSE: return "bad course";
    case NMEA_E_MAGVAR: return "bad magnetic variation";
    case NMEA_E_MODE: return "bad mode indicator";
    case NMEA_E_QUALITY: return "bad GGA fix quality";
    case NMEA_E_SATS: return "bad satellite count";
    case NMEA_E_HDOP: return "bad HDOP";
    case NMEA_E_ALT: return "bad altitude";
    case NMEA_E_UNIT: return "bad unit field";
    case NMEA_E_AGE: return "bad differential age/station";
    case NMEA_WHY_COUNT: break;
    }
    return "unknown";
}

bool nmea_msg_has_fix(const struct nmea_msg *m)
{
    if (m == NULL || (m->has & NMEA_HAS_POS) == 0u) return false;
    if (m->type == NMEA_RMC) return m->status == 'A' && m->mode != 'N';
    if (m->type == NMEA_GGA)
        return (m->has & NMEA_HAS_QUALITY) != 0u &&
               ((m->quality >= 1u && m->quality <= 5u) || m->quality == 8u);
    return false;
}
