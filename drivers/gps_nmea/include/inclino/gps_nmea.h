/*
 * gps_nmea.h - NMEA 0183 sentence parser for a GPS/GNSS receiver on a UART (module
 * inclino_gps_nmea, prefix nmea_). Freestanding C11, integer only, fixed memory (the parser
 * state holds one line buffer), no heap. docs/navigation.md, "NMEA input".
 *
 * Input is a byte stream as a UART gives it, in reads of any size: a sentence may be split
 * across reads, and bytes outside a sentence (line noise, binary protocols) are skipped and
 * counted. A sentence is '$', an address field (two-letter talker + three-letter formatter),
 * comma-separated fields, '*', two hex digits of checksum (XOR of every byte between '$' and
 * '*'), then CR LF (a lone LF is accepted too). The checksum is required: a sentence without one
 * is refused (NMEA_E_NO_CHECKSUM).
 *
 * Sentences decoded: RMC, GGA, VTG, from any talker (GP, GN, GL, GA, GB, BD, GQ, ... : any two
 * upper-case letters; the talker is reported). Any other well-formed sentence (GSA, GSV, a
 * proprietary $P...) is reported as NMEA_E_TYPE / INC_ERR_UNSUPPORTED, not as malformed.
 *
 * Every malformed sentence gets one distinct reason (enum nmea_why, nmea_why_name) and an error
 * code of the project's enum; the first problem found wins, in this order: framing (length,
 * characters, checksum), address, field count, then the fields left to right.
 *
 * Empty fields are allowed wherever a receiver leaves them empty (no fix yet): the value is then
 * absent (its NMEA_HAS_* bit clear), never a zero passed off as data. A field that is present
 * must be well formed and in range.
 *
 * FORMATS AND RANGES (all integer):
 *   latitude   int32 1e-7 degrees, -900 000 000 .. +900 000 000 (north positive).
 *   longitude  int32 1e-7 degrees, -1 800 000 000 .. +1 800 000 000 (east positive).
 *              From ddmm.mmmm / dddmm.mmmm (exactly 2 / 3 degree digits, minutes < 60, 0..10
 *              decimals of minutes; decimals beyond the 7th are dropped after rounding at the
 *              8th). Rounding: minutes to 1e-7 min (half up), then degrees = dd + min / 60
 *              rounded to nearest 1e-7 deg (half up). |error| <= 0.51e-7 deg (< 6 mm).
 *   speed      uint32 mm/s, from knots (RMC, VTG) with 0..3 decimals used (further decimals
 *              rounded at the 4th): round(knots * 1852 / 3.6) exactly in integers, |error| <=
 *              0.5 mm/s + 0.26 mm/s (the knot rounding); range 0 .. 9999.999 kn (5144 m/s).
 *              VTG's km/h field is decoded too (0 .. 99999.999 km/h, mm/s, same rounding).
 *   course     uint16 centidegrees 0 .. 35999 (true course over ground; 360.00 reads as 0),
 *              2 decimals used (rounded at the 3rd).
 *   time       hh mm ss and milliseconds (0..3 decimals used, further ones dropped), hh < 24,
 *              mm < 60, ss <= 60 (a leap second).
 *   date       dd 1..31, mm 1..12, yy -> 2000 + yy (this century's reading of a 2-digit year).
 *   hdop       uint16 centi-units, 0 .. 99.99; altitude and geoid separation int32 mm,
 *              -99 999.999 .. +99 999.999 m, unit field must be 'M'.
 *   satellites 0 .. 99.  GGA quality 0 .. 8.  RMC status 'A' or 'V'.  Mode indicator (RMC, VTG
 *              NMEA 2.3+): A D E F M N P R S (absent on NMEA 2.0 receivers).
 *
 * A FIX (nmea_msg_has_fix): RMC with status 'A', mode not 'N' (when present) and a position;
 * GGA with quality 1..5 or 8 (not 0 invalid, not 6 estimated/dead reckoning, not 7 manual) and
 * a position. VTG never carries a position.
 */
#ifndef INCLINO_GPS_NMEA_H
#define INCLINO_GPS_NMEA_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "inclino/error.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Longest sentence kept, '$' to the last checksum digit. The standard allows 82 characters
 * including CR LF (80 without them); this leaves 2 more for receivers that run slightly over. */
#define NMEA_MAX_CHARS 82u
#define NMEA_MAX_FIELDS 24u /* fields after the address, more -> NMEA_E_FIELD_COUNT */

enum nmea_type {
    NMEA_NONE = 0,
    NMEA_RMC = 1,
    NMEA_GGA = 2,
    NMEA_VTG = 3,
};

/* The reason a sentence was refused. Each has exactly one error code (nmea_why_err). */
enum nmea_why {
    NMEA_OK = 0,
    NMEA_E_TOO_LONG,       /* more than NMEA_MAX_CHARS before the end (INC_ERR_NO_SPACE) */
    NMEA_E_TRUNCATED,      /* a new '$' came before the end of the sentence (INC_ERR_FORMAT) */
    NMEA_E_CHAR,           /* a byte that is not printable ASCII inside the sentence (FORMAT) */
    NMEA_E_NO_START,       /* nmea_parse_line: the line does not start with '$' (FORMAT) */
    NMEA_E_NO_CHECKSUM,    /* no '*' (FORMAT) */
    NMEA_E_CHECKSUM_FIELD, /* '*' not followed by exactly two hex digits (FORMAT) */
    NMEA_E_CHECKSUM,       /* checksum mismatch (INC_ERR_CRC) */
    NMEA_E_ADDRESS,        /* address field not 5 upper-case letters/digits (FORMAT) */
    NMEA_E_TYPE,           /* well formed but not RMC/GGA/VTG (INC_ERR_UNSUPPORTED) */
    NMEA_E_FIELD_COUNT,    /* too few or too many fields for the sentence (FORMAT) */
    NMEA_E_TIME,           /* time field malformed or out of range (FORMAT) */
    NMEA_E_DATE,           /* date field malformed or out of range (FORMAT) */
    NMEA_E_STATUS,         /* RMC status not 'A'/'V' (FORMAT) */
    NMEA_E_LAT,            /* latitude malformed or > 90 deg (FORMAT) */
    NMEA_E_NS,             /* N/S indicator not 'N'/'S' (FORMAT) */
    NMEA_E_LON,            /* longitude malformed or > 180 deg (FORMAT) */
    NMEA_E_EW,             /* E/W indicator not 'E'/'W' (FORMAT) */
    NMEA_E_POS_PARTIAL, /* latitude without longitude or a value without its hemisphere (FORMAT) */
    NMEA_E_SPEED,       /* speed malformed or out of range (FORMAT) */
    NMEA_E_COURSE,      /* course malformed or > 360 deg (FORMAT) */
    NMEA_E_MAGVAR,      /* magnetic variation or its E/W malformed (FORMAT) */
    NMEA_E_MODE,        /* mode indicator not one of A D E F M N P R S (FORMAT) */
    NMEA_E_QUALITY,     /* GGA quality not 0..8 (FORMAT) */
    NMEA_E_SATS,        /* satellites not 0..99 (FORMAT) */
    NMEA_E_HDOP,        /* HDOP malformed or > 99.99 (FORMAT) */
    NMEA_E_ALT,         /* altitude / geoid separation malformed or out of range (FORMAT) */
    NMEA_E_UNIT,        /* a unit letter field (M, T, N, K) not what the sentence needs (FORMAT) */
    NMEA_E_AGE,         /* GGA differential age or station id malformed (FORMAT) */
    NMEA_WHY_COUNT
};

/* Which optional values a message carries. */
#define NMEA_HAS_TIME 0x0001u
#define NMEA_HAS_DATE 0x0002u
#define NMEA_HAS_POS 0x0004u
#define NMEA_HAS_SPEED 0x0008u
#define NMEA_HAS_COURSE 0x0010u
#define NMEA_HAS_MODE 0x0020u
#define NMEA_HAS_QUALITY 0x0040u
#define NMEA_HAS_SATS 0x0080u
#define NMEA_HAS_HDOP 0x0100u
#define NMEA_HAS_ALT 0x0200u
#define NMEA_HAS_STATUS 0x0400u
#define NMEA_HAS_SPEED_KMH 0x0800u

struct nmea_time {
    uint8_t hour, min, sec;
    uint16_t ms;
};

struct nmea_date {
    uint8_t day, month;
    uint16_t year;
};

struct nmea_msg {
    enum nmea_type type;
    char talker[3]; /* "GP", "GN", ... NUL-terminated */
    uint16_t has;   /* NMEA_HAS_* */
    struct nmea_time time;
    struct nmea_date date;
    int32_t lat_e7, lon_e7;  /* 1e-7 deg */
    uint32_t speed_mmps;     /* over ground, from knots */
    uint32_t speed_kmh_mmps; /* VTG's km/h field, as mm/s */
    uint16_t course_cdeg;    /* true course over ground, 0..35999 */
    char status;             /* RMC: 'A' or 'V' */
    char mode;               /* mode indicator, 0 when absent */
    uint8_t quality;         /* GGA */
    uint8_t sats;            /* GGA */
    uint16_t hdop_c;         /* GGA, 1/100 */
    int32_t alt_mm;          /* GGA altitude above mean sea level */
};

struct nmea_stats {
    uint32_t sentences; /* decoded */
    uint32_t errors;    /* refused (any reason, NMEA_E_TYPE included) */
    uint32_t skipped;   /* bytes outside a sentence */
};

/* Stream parser state. Caller-allocated; about NMEA_MAX_CHARS + 16 bytes. */
struct nmea_parser {
    char line[NMEA_MAX_CHARS];
    uint16_t len;
    bool in_sentence;
    bool overlong; /* the current sentence overflowed: discard until its end */
    bool cr;       /* a CR was seen in the current sentence */
    bool after_cr; /* something other than LF followed it (NMEA_E_CHAR at the end) */
    bool ready;
    enum nmea_why why; /* reason of the last refused sentence */
    struct nmea_stats stats;
};

/* A parser with an empty line. Returns 0 or INC_ERR_NULL. */
int nmea_init(struct nmea_parser *p);

/*
 * Feed len bytes (len 0 allowed). Bytes are consumed until one sentence ends (decoded or
 * refused) or the input is used up; *used (required) = bytes consumed. Call again with the rest.
 * Returns 1 (a sentence decoded into *msg), 0 (input used up, no sentence ended), or a negative
 * error for a refused sentence (p->why says why; *msg is cleared). INC_ERR_NULL for a NULL
 * p/msg/used or NULL data with len > 0; INC_ERR_STATE before init.
 */
int nmea_feed(struct nmea_parser *p, const char *data, size_t len, size_t *used,
              struct nmea_msg *msg);

/*
 * Parse one complete sentence "$...*hh" (CR LF optional at the end, nothing else after it).
 * Returns 0 with *msg filled, or a negative error with *why (may be NULL) set and *msg cleared.
 */
int nmea_parse_line(const char *line, size_t len, struct nmea_msg *msg, enum nmea_why *why);

/* The error code of a reason (INC_OK for NMEA_OK), and its name ("checksum mismatch", ...). */
int nmea_why_err(enum nmea_why why);
const char *nmea_why_name(enum nmea_why why);

/* True when the message carries a usable position fix (see A FIX above). */
bool nmea_msg_has_fix(const struct nmea_msg *m);

/* XOR checksum of n bytes (the bytes between '$' and '*'). */
uint8_t nmea_checksum(const char *s, size_t n);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_GPS_NMEA_H */
