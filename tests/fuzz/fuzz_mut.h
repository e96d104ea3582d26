/*
 * fuzz_mut.h - the deterministic mutation set of the parser sweep (tests/fuzz, docs/traces.md
 * "Mutation sweep").
 *
 * A seed text is turned into a numbered list of mutated texts: case k of a seed is always the
 * same bytes (no clock, no global random state), so a failure report "seed S case k" reproduces
 * exactly. fuzz_mutate() fills *out with case k and returns its family, or FUZZ_END past the last
 * case. The families:
 *   FUZZ_TRUNC   the first i bytes, every i (every stride-th i for long seeds)
 *   FUZZ_BYTE    one byte replaced by each of the interesting bytes (0, '\n', ',', '-', '9', 0xFF,
 *                ' ', '.', 'e', 'n')
 *   FUZZ_DELLINE one line deleted;  FUZZ_DUPLINE one line duplicated
 *   FUZZ_TOKEN   one number (a run of [0-9A-Fa-f.+-]) replaced by each of fuzz_tokens[]: huge,
 *                NaN/inf, empty, signs, hex and octal spellings
 *   FUZZ_EXTRA   ",1" / " 1" appended to one line (an extra field)
 *   FUZZ_CRLF    every "\n" written "\r\n";   FUZZ_NOEOL the final newline removed
 *   FUZZ_LONG    a 5000-character run inserted at the start of one line (longer than every
 *                fixed line buffer of the parsers)
 *   FUZZ_RANDOM  three bytes at seeded (xorshift32) positions set to seeded values
 * Positions are byte offsets into the seed; `where` in the result says which one (or the line).
 */
#ifndef INCLINO_FUZZ_MUT_H
#define INCLINO_FUZZ_MUT_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

enum fuzz_family {
    FUZZ_END = 0,
    FUZZ_TRUNC,
    FUZZ_BYTE,
    FUZZ_DELLINE,
    FUZZ_DUPLINE,
    FUZZ_TOKEN,
    FUZZ_EXTRA,
    FUZZ_CRLF,
    FUZZ_NOEOL,
    FUZZ_LONG,
    FUZZ_RANDOM,
};

#define FUZZ_N_BYTES 10u
#define FUZZ_N_TOKENS 14u
extern const unsigned char fuzz_bytes[FUZZ_N_BYTES];
extern const char *const fuzz_tokens[FUZZ_N_TOKENS];

struct fuzz_case {
    char *data; /* malloc'd, NUL-terminated for convenience (len excludes it) */
    size_t len;
    enum fuzz_family family;
    size_t where; /* byte offset (TRUNC, BYTE, TOKEN start, LONG) or line index */
    unsigned arg; /* index into fuzz_bytes / fuzz_tokens, or the random case number */
};

/*
 * Case k of seed (len bytes). stride >= 1 thins the per-position families (TRUNC, BYTE: every
 * stride-th position, starting at k-dependent offsets so every position class is still hit);
 * n_random is the number of FUZZ_RANDOM cases. Returns the family (FUZZ_END after the last).
 * out->data is freed and replaced on every call; fuzz_case_free() at the end.
 */
enum fuzz_family fuzz_mutate(const char *seed, size_t len, unsigned long k, size_t stride,
                             unsigned n_random, struct fuzz_case *out);
void fuzz_case_free(struct fuzz_case *c);
const char *fuzz_family_name(enum fuzz_family f);

/* Start of line `line` (0-based) of text, or len when it has fewer lines; *end: after its '\n'. */
size_t fuzz_line_span(const char *text, size_t len, size_t line, size_t *end);
size_t fuzz_count_lines(const char *text, size_t len);

/* A whole file into a malloc'd buffer (NUL-terminated); NULL on failure. */
char *fuzz_read_file(const char *path, size_t *len);

#ifdef __cplusplus
}
#endif
#endif
