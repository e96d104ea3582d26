/*
 * nmea_check.h - the invariants every NMEA parse result must keep, whatever the input (shared by
 * the mutation sweep fuzz_nmea.c and the libFuzzer entry lf_nmea.c).
 *
 * nmea_check_stream() feeds data to a fresh parser in reads of `chunk` bytes and checks:
 *   - every call consumes what it says and ends in 1, 0 or a negative code, the code being
 *     exactly nmea_why_err(p.why) with a reason other than NMEA_OK;
 *   - a refused sentence leaves a cleared message (nothing decoded, type NMEA_NONE);
 *   - every decoded value is inside its documented range, and only what `has` says is set;
 *   - the statistics add up (sentences + errors = results; skipped <= bytes).
 * Returns the number of violated invariants (0 = fine); *n_ok gets the decoded sentences and
 * ok[] (up to cap) their messages.
 */
#ifndef INCLINO_NMEA_CHECK_H
#define INCLINO_NMEA_CHECK_H

#include "inclino/gps_nmea.h"

#include <stddef.h>

static inline unsigned nmea_check_msg(const struct nmea_msg *m)
{
    unsigned bad = 0;
    if (m->type != NMEA_RMC && m->type != NMEA_GGA && m->type != NMEA_VTG) bad++;
    if (m->talker[0] < 'A' || m->talker[0] > 'Z' || m->talker[1] < 'A' || m->talker[1] > 'Z' ||
        m->talker[2] != '\0')
        bad++;
    if (m->lat_e7 < -900000000 || m->lat_e7 > 900000000 || m->lon_e7 < -1800000000 ||
        m->lon_e7 > 1800000000)
        bad++;
    if (!(m->has & NMEA_HAS_POS) && (m->lat_e7 != 0 || m->lon_e7 != 0)) bad++;
    if (m->course_cdeg > 35999u || m->speed_mmps > 5144445u || m->speed_kmh_mmps > 27777778u) bad++;
    if (!(m->has & NMEA_HAS_SPEED) && m->speed_mmps != 0u) bad++;
    if (m->time.hour > 23u || m->time.min > 59u || m->time.sec > 60u || m->time.ms > 999u) bad++;
    if ((m->has & NMEA_HAS_DATE) &&
        (m->date.day < 1u || m->date.day > 31u || m->date.month < 1u || m->date.month > 12u ||
         m->date.year < 2000u || m->date.year > 2099u))
        bad++;
    if (m->quality > 8u || m->sats > 99u || m->hdop_c > 9999u) bad++;
    if (m->alt_mm < -99999999 || m->alt_mm > 99999999) bad++;
    if (m->type == NMEA_RMC && (m->has & NMEA_HAS_STATUS) && m->status != 'A' && m->status != 'V')
        bad++;
    if (m->type == NMEA_VTG && nmea_msg_has_fix(m)) bad++;
    return bad;
}

/* Field-wise equality (no memcmp: padding bytes are not part of the value). */
static inline int nmea_msg_equal(const struct nmea_msg *a, const struct nmea_msg *b)
{
    return a->type == b->type && a->talker[0] == b->talker[0] && a->talker[1] == b->talker[1] &&
           a->has == b->has && a->time.hour == b->time.hour && a->time.min == b->time.min &&
           a->time.sec == b->time.sec && a->time.ms == b->time.ms && a->date.day == b->date.day &&
           a->date.month == b->date.month && a->date.year == b->date.year &&
           a->lat_e7 == b->lat_e7 && a->lon_e7 == b->lon_e7 && a->speed_mmps == b->speed_mmps &&
           a->speed_kmh_mmps == b->speed_kmh_mmps && a->course_cdeg == b->course_cdeg &&
           a->status == b->status && a->mode == b->mode && a->quality == b->quality &&
           a->sats == b->sats && a->hdop_c == b->hdop_c && a->alt_mm == b->alt_mm;
}

static inline unsigned nmea_check_stream(const char *data, size_t len, size_t chunk,
                                         struct nmea_msg *ok, size_t cap, size_t *n_ok)
{
    struct nmea_parser p;
    struct nmea_msg m;
    static const struct nmea_msg zero; /* cleared message */
    unsigned bad = 0;
    size_t off = 0, results = 0;
    *n_ok = 0;
    if (chunk == 0u) chunk = 1u;
    if (nmea_init(&p) != INC_OK) return 1u;
    while (off < len) {
        size_t end = off + chunk < len ? off + chunk : len;
        while (off < end) {
            size_t used = 0;
            int rc = nmea_feed(&p, data + off, end - off, &used, &m);
            if (used > end - off) return bad + 1u;
            off += used;
            if (rc == 1) {
                results++;
                bad += nmea_check_msg(&m);
                if (*n_ok < cap) ok[*n_ok] = m;
                (*n_ok)++;
            } else if (rc < 0) {
                results++;
                if (p.why == NMEA_OK || rc != nmea_why_err(p.why)) bad++;
                if (!nmea_msg_equal(&m, &zero)) bad++;
            } else if (rc != 0 || off != end) {
                return bad + 1u; /* 0 must mean: all consumed */
            }
            if (used == 0u && rc >= 0) return bad + 1u; /* no progress */
        }
    }
    if (p.stats.sentences + p.stats.errors != results || p.stats.skipped > len) bad++;
    return bad;
}

#endif
