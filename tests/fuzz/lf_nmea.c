/*
 * lf_nmea.c - libFuzzer entry for the NMEA 0183 parser (drivers/gps_nmea): target `nmea` of
 * tests/fuzz/CMakeLists.txt (the fuzz preset; docs/fuzzing.md), seeds in tests/fuzz/corpus/nmea.
 * The input is fed whole, then again in reads of 1 and 7 bytes (the first input byte picks a
 * third read size): the decoded sentences must be the same however the stream is cut, and every
 * result must keep the invariants of nmea_check.h. A violation aborts (a finding).
 */
#include "nmea_check.h"

#include <stdint.h>
#include <stdlib.h>

#define LF_CAP 64u

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static struct nmea_msg a[LF_CAP], b[LF_CAP];
    size_t na = 0, nb = 0, i, k;
    const size_t chunks[3] = {1u, 7u, size > 0u ? (size_t)(data[0] % 97u) + 1u : 1u};
    const char *s = (const char *)data;
    if (nmea_check_stream(s, size, size > 0u ? size : 1u, a, LF_CAP, &na) != 0u) abort();
    for (k = 0; k < 3u; k++) {
        if (nmea_check_stream(s, size, chunks[k], b, LF_CAP, &nb) != 0u || nb != na) abort();
        for (i = 0; i < na && i < LF_CAP; i++)
            if (!nmea_msg_equal(&a[i], &b[i])) abort();
    }
    /* the same bytes as one line through nmea_parse_line */
    {
        struct nmea_msg m;
        enum nmea_why why = NMEA_OK;
        int rc = nmea_parse_line(s, size, &m, &why);
        if (rc != nmea_why_err(why) || (rc == INC_OK && nmea_check_msg(&m) != 0u)) abort();
    }
    return 0;
}
