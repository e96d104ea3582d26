/*
 * The NMEA 0183 parser (drivers/gps_nmea) under the deterministic mutation sweep (fuzz_mut.h) of
 * the committed corpus tests/fuzz/corpus/nmea. Every mutated stream, fed whole and in reads of 1
 * and 5 bytes, keeps the invariants of nmea_check.h, gives the same sentences however it is cut,
 * and - outside the FUZZ_RANDOM and FUZZ_TOKEN families, whose changes can cancel in the XOR
 * checksum (three random bytes; "00" replaced by "" keeps the XOR) - never decodes a sentence that
 * is not one of the seed's own: a changed byte inside a sentence is always refused (checksum,
 * framing or field reason), never passed on as another value.
 */
#include "fuzz_mut.h"
#include "nmea_check.h"
#include "unit.h"

#include <stdio.h>
#include <stdlib.h>

#ifndef NMEA_CORPUS
#error "NMEA_CORPUS must be defined (tests/fuzz/corpus/nmea)"
#endif

#define CAP 64u

static const char *const seeds[] = {"rmc_gga_vtg.nmea", "no_fix.nmea", "gn_multi.nmea",
                                    "split_noise.nmea"};

static void sweep(const char *name)
{
    static struct nmea_msg base[CAP], a[CAP], b[CAP];
    struct fuzz_case c = {NULL, 0, FUZZ_END, 0, 0};
    char path[512];
    size_t len = 0, n_base = 0, na, nb, i, j;
    unsigned long k, cases = 0, decoded = 0;
    char *seed;
    snprintf(path, sizeof path, "%s/%s", NMEA_CORPUS, name);
    seed = fuzz_read_file(path, &len);
    REQUIRE(seed != NULL);
    CHECK_EQ_INT(nmea_check_stream(seed, len, len, base, CAP, &n_base), 0);
    CHECK(n_base >= 2u);
    for (k = 0; fuzz_mutate(seed, len, k, UNIT_SIZE(1u, 3u), UNIT_SIZE(300u, 60u), &c) != FUZZ_END;
         k++) {
        const size_t chunks[2] = {1u, 5u};
        unsigned bad = nmea_check_stream(c.data, c.len, c.len ? c.len : 1u, a, CAP, &na);
        cases++;
        for (j = 0; j < 2u; j++) {
            bad += nmea_check_stream(c.data, c.len, chunks[j], b, CAP, &nb);
            if (nb != na) bad++;
            for (i = 0; i < na && i < nb && i < CAP; i++)
                if (!nmea_msg_equal(&a[i], &b[i])) bad++;
        }
        if (c.family != FUZZ_RANDOM && c.family != FUZZ_TOKEN) {
            for (i = 0; i < na && i < CAP; i++) {
                bool found = false;
                for (j = 0; j < n_base; j++)
                    found = found || nmea_msg_equal(&a[i], &base[j]);
                if (!found) bad++;
            }
        }
        decoded += na;
        if (bad != 0u)
            printf("  %s case %lu (%s at %u, arg %u): %u violations\n", name, k,
                   fuzz_family_name(c.family), (unsigned)c.where, c.arg, bad);
        CHECK_EQ_INT(bad, 0);
    }
    printf("  %s: %lu cases, %lu sentences decoded\n", name, cases, decoded);
    CHECK(cases > 100u);
    fuzz_case_free(&c);
    free(seed);
}

static void test_sweep(void)
{
    size_t i;
    for (i = 0; i < sizeof seeds / sizeof seeds[0]; i++)
        sweep(seeds[i]);
}

int main(void)
{
    UNIT_RUN(test_sweep);
    return unit_report();
}
