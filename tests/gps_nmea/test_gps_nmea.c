/*
 * NMEA 0183 parser (drivers/gps_nmea): decoded values of real-looking RMC/GGA/VTG sentences from
 * several talkers, the fixed-point conversions against exact rational math, empty fields, every
 * refusal reason with one sentence that provokes it (and nothing decoded), a sentence split at
 * every byte, overlong lines, noise between sentences. Runs on every target (QEMU too).
 */
#include "inclino/gps_nmea.h"
#include "unit.h"

#include <stdio.h>
#include <string.h>

/* "$" body "*hh\r\n" with the right checksum. */
static size_t mk(char *out, size_t cap, const char *body)
{
    size_t n = strlen(body);
    int k = snprintf(out, cap, "$%s*%02X\r\n", body, (unsigned)nmea_checksum(body, n));
    return (size_t)k;
}

static int parse(const char *body, struct nmea_msg *m, enum nmea_why *why)
{
    char buf[256];
    size_t n = mk(buf, sizeof buf, body);
    return nmea_parse_line(buf, n, m, why);
}

static void test_rmc(void)
{
    struct nmea_msg m;
    enum nmea_why w;
    CHECK_OK(parse("GPRMC,123519.25,A,4807.038,N,01131.000,E,022.4,084.4,230394,003.1,W", &m, &w));
    CHECK_EQ_INT(w, NMEA_OK);
    CHECK_EQ_INT(m.type, NMEA_RMC);
    CHECK(strcmp(m.talker, "GP") == 0);
    CHECK_EQ_INT(m.time.hour, 12);
    CHECK_EQ_INT(m.time.min, 35);
    CHECK_EQ_INT(m.time.sec, 19);
    CHECK_EQ_INT(m.time.ms, 250);
    CHECK_EQ_INT(m.status, 'A');
    /* 48 deg 07.038' = 48.1173 deg exactly; 11 deg 31.000' = 11.516666.. -> 115166667 */
    CHECK_EQ_INT(m.lat_e7, 481173000);
    CHECK_EQ_INT(m.lon_e7, 115166667);
    /* 22.4 kn = 22400 mkn * 1852 / 3600 = 11523.55 -> 11524 mm/s */
    CHECK_EQ_INT(m.speed_mmps, 11524);
    CHECK_EQ_INT(m.course_cdeg, 8440);
    CHECK_EQ_INT(m.date.day, 23);
    CHECK_EQ_INT(m.date.month, 3);
    CHECK_EQ_INT(m.date.year, 2094);
    CHECK(nmea_msg_has_fix(&m));
    CHECK(!(m.has & NMEA_HAS_MODE));
    /* NMEA 2.3 mode field, GN talker, south/west, 7 decimals of minutes */
    CHECK_OK(parse("GNRMC,000000.00,A,3351.1234567,S,15112.7654321,W,0.000,,010124,,,D", &m, &w));
    CHECK(strcmp(m.talker, "GN") == 0);
    CHECK_EQ_INT(m.mode, 'D');
    /* 33 + 51.1234567/60 = 33.852057611.. -> 338520576 */
    CHECK_EQ_INT(m.lat_e7, -338520576);
    /* 151 + 12.7654321/60 = 151.21275720.. -> 1512127572 */
    CHECK_EQ_INT(m.lon_e7, -1512127572);
    CHECK_EQ_INT(m.speed_mmps, 0);
    CHECK(!(m.has & NMEA_HAS_COURSE));
    CHECK_EQ_INT(m.date.year, 2024);
    /* NMEA 4.1: navigational status field */
    CHECK_OK(
        parse("GLRMC,235960,A,8959.9999999,N,17959.9999999,E,1.5,359.99,311299,,,A,V", &m, &w));
    CHECK_EQ_INT(m.time.sec, 60);
    CHECK_EQ_INT(m.lat_e7, 899999999 + 1); /* 89.99999999833 -> 900000000 */
    CHECK_EQ_INT(m.lon_e7, 1800000000);
    CHECK_EQ_INT(m.course_cdeg, 35999);
    /* no fix yet: everything empty, status V */
    CHECK_OK(parse("GPRMC,,V,,,,,,,,,,N", &m, &w));
    CHECK_EQ_INT(m.has, NMEA_HAS_STATUS | NMEA_HAS_MODE);
    CHECK(!nmea_msg_has_fix(&m));
    CHECK_EQ_INT(m.lat_e7, 0);
    /* status A but mode N: not a fix */
    CHECK_OK(parse("GPRMC,120000,A,4807.038,N,01131.000,E,,,230394,,,N", &m, &w));
    CHECK(!nmea_msg_has_fix(&m));
    CHECK_OK(parse("GPRMC,120000,V,4807.038,N,01131.000,E,,,230394,,", &m, &w));
    CHECK(!nmea_msg_has_fix(&m));
    CHECK(m.has & NMEA_HAS_POS);
    /* course 360.00 reads as 0 */
    CHECK_OK(parse("GPRMC,120000,A,4807.038,N,01131.000,E,1,360.00,230394,,", &m, &w));
    CHECK_EQ_INT(m.course_cdeg, 0);
}

static void test_gga_vtg(void)
{
    struct nmea_msg m;
    enum nmea_why w;
    CHECK_OK(parse("GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,", &m, &w));
    CHECK_EQ_INT(m.type, NMEA_GGA);
    CHECK_EQ_INT(m.quality, 1);
    CHECK_EQ_INT(m.sats, 8);
    CHECK_EQ_INT(m.hdop_c, 90);
    CHECK_EQ_INT(m.alt_mm, 545400);
    CHECK(nmea_msg_has_fix(&m));
    CHECK_OK(
        parse("GAGGA,123519,4807.038,N,01131.000,E,6,08,0.9,-12.25,M,46.9,M,2.0,0031", &m, &w));
    CHECK(strcmp(m.talker, "GA") == 0);
    CHECK_EQ_INT(m.alt_mm, -12250);
    CHECK(!nmea_msg_has_fix(&m)); /* quality 6: the receiver's own dead reckoning */
    CHECK_OK(parse("GPGGA,,,,,,0,,,,,,,,", &m, &w));
    CHECK_EQ_INT(m.has, NMEA_HAS_QUALITY);
    CHECK(!nmea_msg_has_fix(&m));
    CHECK_OK(parse("BDGGA,010203.5,0000.0000,N,00000.0000,E,4,12,1.0,0,M,0,M,,", &m, &w));
    CHECK(nmea_msg_has_fix(&m));
    CHECK_EQ_INT(m.time.ms, 500);
    CHECK_OK(parse("GPVTG,054.7,T,034.4,M,005.5,N,010.2,K", &m, &w));
    CHECK_EQ_INT(m.type, NMEA_VTG);
    CHECK_EQ_INT(m.course_cdeg, 5470);
    /* 5.5 kn = 5500 * 1852 / 3600 = 2829.44 -> 2829 */
    CHECK_EQ_INT(m.speed_mmps, 2829);
    /* 10.2 km/h = 10200 * 1000 / 3600 = 2833.33 -> 2833 */
    CHECK_EQ_INT(m.speed_kmh_mmps, 2833);
    CHECK(!nmea_msg_has_fix(&m));
    CHECK_OK(parse("GNVTG,,T,,M,0.012,N,0.022,K,A", &m, &w));
    CHECK_EQ_INT(m.mode, 'A');
    CHECK_EQ_INT(m.speed_mmps, 6); /* 12 * 1852 / 3600 = 6.17 */
    CHECK(!(m.has & NMEA_HAS_COURSE));
    /* a speed with more decimals than used: rounded at the 4th */
    CHECK_OK(parse("GNVTG,,T,,M,1.0005,N,,K,A", &m, &w));
    CHECK_EQ_INT(m.speed_mmps, 515); /* 1001 mkn -> 514.96 */
}

/* The coordinate conversion against exact rational math over a sweep of minutes. */
static void test_angle_bound(void)
{
    struct nmea_msg m;
    enum nmea_why w;
    char body[128];
    unsigned long i, n = UNIT_SIZE(20000ul, 1000ul);
    for (i = 0; i < n; i++) {
        /* minutes e7 in 0 .. 59.9999999 */
        unsigned long min_e7 = (i * 2654435761ul) % 600000000ul;
        unsigned deg = (unsigned)(i % 90u);
        long long exact_num, got;
        snprintf(body, sizeof body,
                 "GPGGA,000000,%02u%02lu.%07lu,N,%03u%02lu.%07lu,W,1,5,1,0,M,0,M,,", deg,
                 min_e7 / 10000000ul, min_e7 % 10000000ul, deg * 2u, min_e7 / 10000000ul,
                 min_e7 % 10000000ul);
        REQUIRE(parse(body, &m, &w) == INC_OK);
        /* exact: deg + min_e7 / 60 / 1e7 deg; in 1e-7 deg * 60: */
        exact_num = (long long)deg * 600000000ll + (long long)min_e7;
        got = (long long)m.lat_e7 * 60ll;
        CHECK(got - exact_num <= 30 && exact_num - got <= 30); /* <= 0.5e-7 deg */
        got = -(long long)m.lon_e7 * 60ll;
        exact_num += (long long)deg * 600000000ll;
        CHECK(got - exact_num <= 30 && exact_num - got <= 30);
    }
}

struct bad {
    const char *body; /* checksum added by mk, unless raw */
    enum nmea_why why;
};

static const struct bad bad_bodies[] = {
    {"GPRMC,1235,A,4807.038,N,01131.000,E,022.4,084.4,230394,003.1,W", NMEA_E_TIME},
    {"GPRMC,253519,A,4807.038,N,01131.000,E,022.4,084.4,230394,003.1,W", NMEA_E_TIME},
    {"GPRMC,123519.,A,4807.038,N,01131.000,E,022.4,084.4,230394,003.1,W", NMEA_E_TIME},
    {"GPRMC,12a519,A,4807.038,N,01131.000,E,022.4,084.4,230394,003.1,W", NMEA_E_TIME},
    {"GPRMC,123519,X,4807.038,N,01131.000,E,022.4,084.4,230394,003.1,W", NMEA_E_STATUS},
    {"GPRMC,123519,A,9107.038,N,01131.000,E,022.4,084.4,230394,003.1,W", NMEA_E_LAT},
    {"GPRMC,123519,A,4860.000,N,01131.000,E,022.4,084.4,230394,003.1,W", NMEA_E_LAT},
    {"GPRMC,123519,A,807.038,N,01131.000,E,022.4,084.4,230394,003.1,W", NMEA_E_LAT},
    {"GPRMC,123519,A,4807.0-8,N,01131.000,E,022.4,084.4,230394,003.1,W", NMEA_E_LAT},
    {"GPRMC,123519,A,4807.038,X,01131.000,E,022.4,084.4,230394,003.1,W", NMEA_E_NS},
    {"GPRMC,123519,A,4807.038,N,18131.000,E,022.4,084.4,230394,003.1,W", NMEA_E_LON},
    {"GPRMC,123519,A,4807.038,N,1131.000,E,022.4,084.4,230394,003.1,W", NMEA_E_LON},
    {"GPRMC,123519,A,4807.038,N,01131.000,Q,022.4,084.4,230394,003.1,W", NMEA_E_EW},
    {"GPRMC,123519,A,4807.038,N,,E,022.4,084.4,230394,003.1,W", NMEA_E_POS_PARTIAL},
    {"GPRMC,123519,A,4807.038,,01131.000,E,022.4,084.4,230394,003.1,W", NMEA_E_POS_PARTIAL},
    {"GPRMC,123519,A,4807.038,N,01131.000,E,-22.4,084.4,230394,003.1,W", NMEA_E_SPEED},
    {"GPRMC,123519,A,4807.038,N,01131.000,E,99999.0,084.4,230394,003.1,W", NMEA_E_SPEED},
    {"GPRMC,123519,A,4807.038,N,01131.000,E,1e3,084.4,230394,003.1,W", NMEA_E_SPEED},
    {"GPRMC,123519,A,4807.038,N,01131.000,E,22.4,360.01,230394,003.1,W", NMEA_E_COURSE},
    {"GPRMC,123519,A,4807.038,N,01131.000,E,22.4,.,230394,003.1,W", NMEA_E_COURSE},
    {"GPRMC,123519,A,4807.038,N,01131.000,E,22.4,84.4,320394,003.1,W", NMEA_E_DATE},
    {"GPRMC,123519,A,4807.038,N,01131.000,E,22.4,84.4,231394,003.1,W", NMEA_E_DATE},
    {"GPRMC,123519,A,4807.038,N,01131.000,E,22.4,84.4,23039,003.1,W", NMEA_E_DATE},
    {"GPRMC,123519,A,4807.038,N,01131.000,E,22.4,84.4,230394,x,W", NMEA_E_MAGVAR},
    {"GPRMC,123519,A,4807.038,N,01131.000,E,22.4,84.4,230394,3.1,N", NMEA_E_MAGVAR},
    {"GPRMC,123519,A,4807.038,N,01131.000,E,22.4,84.4,230394,3.1,W,Z", NMEA_E_MODE},
    {"GPRMC,123519,A,4807.038,N,01131.000,E,22.4,84.4,230394,3.1,W,AA", NMEA_E_MODE},
    {"GPRMC,123519,A,4807.038,N,01131.000,E,22.4,84.4,230394,3.1", NMEA_E_FIELD_COUNT},
    {"GPRMC,123519,A,4807.038,N,01131.000,E,22.4,84.4,230394,3.1,W,A,V,1", NMEA_E_FIELD_COUNT},
    {"GPGGA,123519,4807.038,N,01131.000,E,9,08,0.9,545.4,M,46.9,M,,", NMEA_E_QUALITY},
    {"GPGGA,123519,4807.038,N,01131.000,E,1,108,0.9,545.4,M,46.9,M,,", NMEA_E_SATS},
    {"GPGGA,123519,4807.038,N,01131.000,E,1,08,100.0,545.4,M,46.9,M,,", NMEA_E_HDOP},
    {"GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4.1,M,46.9,M,,", NMEA_E_ALT},
    {"GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,F,46.9,M,,", NMEA_E_UNIT},
    {"GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,x,", NMEA_E_AGE},
    {"GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,", NMEA_OK},
    {"GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,", NMEA_E_FIELD_COUNT},
    {"GPVTG,054.7,T,034.4,M,005.5,N,010.2,X", NMEA_E_UNIT},
    {"GPVTG,054.7,T,034.4,M,005.5,N,010.2", NMEA_E_FIELD_COUNT},
    {"GPVTG,054.7,T,034.4,M,005.5,N,1000000,K", NMEA_E_SPEED},
    {"GPGSA,A,3,04,05,,09,12,,,24,,,,,2.5,1.3,2.1", NMEA_E_TYPE},
    {"PGRME,15.0,M,45.0,M,25.0,M", NMEA_E_TYPE},
    {"GPRM,123519,A", NMEA_E_ADDRESS},
    {"gprmc,123519,A", NMEA_E_ADDRESS},
    {"G1RMC,123519,A", NMEA_E_ADDRESS},
};

static void test_bad(void)
{
    struct nmea_msg m;
    enum nmea_why w;
    size_t i;
    bool seen[NMEA_WHY_COUNT] = {false};
    char buf[256];
    for (i = 0; i < sizeof bad_bodies / sizeof bad_bodies[0]; i++) {
        int rc = parse(bad_bodies[i].body, &m, &w);
        if (w != bad_bodies[i].why)
            printf("  case %u: %s -> %s\n", (unsigned)i, bad_bodies[i].body, nmea_why_name(w));
        CHECK_EQ_INT(w, bad_bodies[i].why);
        CHECK_EQ_INT(rc, nmea_why_err(bad_bodies[i].why));
        if (w != NMEA_OK) {
            CHECK_EQ_INT(m.has, 0); /* nothing decoded is left in a refused message */
            CHECK_EQ_INT(m.type, NMEA_NONE);
        }
        seen[w] = true;
    }
    /* framing errors */
    CHECK_ERR(nmea_parse_line("GPRMC,,V,,,,,,,,,*53", 20, &m, &w), INC_ERR_FORMAT);
    CHECK_EQ_INT(w, NMEA_E_NO_START);
    seen[w] = true;
    strcpy(buf, "$GPRMC,,V,,,,,,,,,");
    CHECK_ERR(nmea_parse_line(buf, strlen(buf), &m, &w), INC_ERR_FORMAT);
    CHECK_EQ_INT(w, NMEA_E_NO_CHECKSUM);
    seen[w] = true;
    strcpy(buf, "$GPRMC,,V,,,,,,,,,*5");
    CHECK_ERR(nmea_parse_line(buf, strlen(buf), &m, &w), INC_ERR_FORMAT);
    CHECK_EQ_INT(w, NMEA_E_CHECKSUM_FIELD);
    strcpy(buf, "$GPRMC,,V,,,,,,,,,*5G");
    CHECK_ERR(nmea_parse_line(buf, strlen(buf), &m, &w), INC_ERR_FORMAT);
    CHECK_EQ_INT(w, NMEA_E_CHECKSUM_FIELD);
    strcpy(buf, "$GPRMC,,V,,,,,,,,,*533");
    CHECK_ERR(nmea_parse_line(buf, strlen(buf), &m, &w), INC_ERR_FORMAT);
    CHECK_EQ_INT(w, NMEA_E_CHECKSUM_FIELD);
    seen[w] = true;
    mk(buf, sizeof buf, "GPRMC,,V,,,,,,,,,");
    CHECK_OK(nmea_parse_line(buf, strlen(buf), &m, &w));
    buf[strlen(buf) - 3u] ^= 1; /* last hex digit changed */
    CHECK_ERR(nmea_parse_line(buf, strlen(buf), &m, &w), INC_ERR_CRC);
    CHECK_EQ_INT(w, NMEA_E_CHECKSUM);
    seen[w] = true;
    mk(buf, sizeof buf, "GPRMC,,V,,,,,,,,,");
    buf[8] = '\x01';
    CHECK_ERR(nmea_parse_line(buf, strlen(buf), &m, &w), INC_ERR_FORMAT);
    CHECK_EQ_INT(w, NMEA_E_CHAR);
    seen[w] = true;
    strcpy(buf, "$GPRMC,,V,$GPRMC,,V,,,,,,,,,*53");
    CHECK_ERR(nmea_parse_line(buf, strlen(buf), &m, &w), INC_ERR_FORMAT);
    CHECK_EQ_INT(w, NMEA_E_TRUNCATED);
    seen[w] = true;
    memset(buf, ',', 120);
    memcpy(buf, "$GPRMC", 6);
    buf[120] = '\0';
    CHECK_ERR(nmea_parse_line(buf, 120, &m, &w), INC_ERR_NO_SPACE);
    CHECK_EQ_INT(w, NMEA_E_TOO_LONG);
    seen[w] = true;
    /* every reason is provoked by one of the cases above and has a distinct name */
    for (i = 1; i < NMEA_WHY_COUNT; i++) {
        size_t j;
        if (!seen[i])
            printf("  reason %u (%s) not provoked\n", (unsigned)i, nmea_why_name((enum nmea_why)i));
        CHECK(seen[i]);
        CHECK(nmea_why_err((enum nmea_why)i) < 0);
        for (j = 0; j < i; j++)
            CHECK(strcmp(nmea_why_name((enum nmea_why)i), nmea_why_name((enum nmea_why)j)) != 0);
    }
    CHECK_EQ_INT(nmea_why_err(NMEA_OK), INC_OK);
    CHECK_ERR(nmea_parse_line(NULL, 3, &m, &w), INC_ERR_NULL);
    CHECK_ERR(nmea_parse_line(buf, 3, NULL, &w), INC_ERR_NULL);
    CHECK(!nmea_msg_has_fix(NULL));
}

/* A stream of three sentences with noise, fed in every split position and byte by byte. */
static void test_stream(void)
{
    static char stream[600];
    size_t n = 0, cut, i;
    struct nmea_parser p;
    struct nmea_msg m;
    memcpy(stream, "\x00\xFFgarbage\r\n", 11);
    n = 11;
    n += mk(stream + n, sizeof stream - n,
            "GPRMC,123519,A,4807.038,N,01131.000,E,022.4,084.4,230394,003.1,W");
    n += mk(stream + n, sizeof stream - n,
            "GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,");
    n += (size_t)snprintf(stream + n, sizeof stream - n, "$GPRMC,12"); /* cut off */
    n += mk(stream + n, sizeof stream - n, "GPVTG,054.7,T,034.4,M,005.5,N,010.2,K");
    /* a lone LF ending is accepted */
    n += (size_t)snprintf(stream + n, sizeof stream - n, "$GPVTG,,T,,M,0.0,N,0.0,K*4E\n");
    n += (size_t)snprintf(stream + n, sizeof stream - n, "$GPVTG,,T,,M,0.0,N,0.0,K*4E\rX\n");
    for (cut = 0; cut <= n; cut++) {
        int types[8], errs[8], nt = 0, ne = 0;
        REQUIRE(nmea_init(&p) == INC_OK);
        /* two reads: [0, cut) and [cut, n), each consumed in a loop */
        for (i = 0; i < 2u; i++) {
            const size_t b = i == 0u ? cut : n;
            size_t off = i == 0u ? 0u : cut;
            while (off < b) {
                size_t used = 0;
                int rc = nmea_feed(&p, stream + off, b - off, &used, &m);
                off += used;
                if (rc == 1 && nt < 8)
                    types[nt++] = (int)m.type;
                else if (rc < 0 && ne < 8)
                    errs[ne++] = (int)p.why;
                if (rc == 0) REQUIRE(off == b);
            }
        }
        CHECK_EQ_INT(nt, 4);
        CHECK_EQ_INT(ne, 2);
        if (nt == 4 && ne == 2) {
            CHECK_EQ_INT(types[0], NMEA_RMC);
            CHECK_EQ_INT(types[1], NMEA_GGA);
            CHECK_EQ_INT(types[2], NMEA_VTG);
            CHECK_EQ_INT(types[3], NMEA_VTG);
            CHECK_EQ_INT(errs[0], NMEA_E_TRUNCATED);
            CHECK_EQ_INT(errs[1], NMEA_E_CHAR);
        }
        CHECK_EQ_INT(p.stats.sentences, 4);
        CHECK_EQ_INT(p.stats.errors, 2);
        CHECK_EQ_INT(p.stats.skipped, 11);
    }
    /* byte by byte */
    REQUIRE(nmea_init(&p) == INC_OK);
    for (i = 0; i < n;) {
        size_t used = 0;
        int rc = nmea_feed(&p, stream + i, 1u, &used, &m);
        /* a '$' that ends a cut-off sentence is not consumed: it starts the next one */
        CHECK(used == 1u || (used == 0u && rc < 0 && stream[i] == '$'));
        i += used;
    }
    CHECK_EQ_INT(p.stats.sentences, 4);
    CHECK_EQ_INT(p.stats.errors, 2);
}

static void test_overlong(void)
{
    static char stream[2000];
    struct nmea_parser p;
    struct nmea_msg m;
    size_t n = 0, off = 0, len;
    int results[4], k = 0;
    char body[160];
    /* exactly NMEA_MAX_CHARS: accepted; one more: refused */
    memset(body, '0', sizeof body);
    memcpy(body, "GPVTG,,T,,M,", 12);
    len = NMEA_MAX_CHARS - 4u; /* '$' + body + '*hh' = MAX */
    /* make the speed field a long run of decimals "0.000...", then ",N,,K" */
    body[12] = '0';
    body[13] = '.';
    memcpy(body + len - 5u, ",N,,K", 5);
    body[len] = '\0';
    n += mk(stream + n, sizeof stream - n, body);
    body[len - 5u] = '0';
    memcpy(body + len - 4u, ",N,,K", 5);
    body[len + 1u] = '\0';
    n += mk(stream + n, sizeof stream - n, body);
    /* a very long line of junk inside a sentence, then a good sentence */
    stream[n++] = '$';
    memset(stream + n, 'A', 1000);
    n += 1000;
    stream[n++] = '\n';
    n += mk(stream + n, sizeof stream - n, "GPVTG,,T,,M,0.0,N,0.0,K");
    REQUIRE(nmea_init(&p) == INC_OK);
    while (off < n && k < 4) {
        size_t used = 0;
        const int rc = nmea_feed(&p, stream + off, n - off, &used, &m);
        off += used;
        if (rc != 0) results[k++] = rc == 1 ? 1 : (int)p.why;
    }
    CHECK_EQ_INT(k, 4);
    CHECK_EQ_INT(results[0], 1);
    CHECK_EQ_INT(results[1], NMEA_E_TOO_LONG);
    CHECK_EQ_INT(results[2], NMEA_E_TOO_LONG);
    CHECK_EQ_INT(results[3], 1);
    CHECK_ERR(nmea_feed(NULL, stream, 1, &len, &m), INC_ERR_NULL);
    CHECK_ERR(nmea_feed(&p, NULL, 1, &len, &m), INC_ERR_NULL);
    p.ready = false;
    CHECK_ERR(nmea_feed(&p, stream, 1, &len, &m), INC_ERR_STATE);
}

int main(void)
{
    UNIT_RUN(test_rmc);
    UNIT_RUN(test_gga_vtg);
    UNIT_RUN(test_angle_bound);
    UNIT_RUN(test_bad);
    UNIT_RUN(test_stream);
    UNIT_RUN(test_overlong);
    return unit_report();
}
