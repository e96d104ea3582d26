/*
 * tool_cli.h - the command-line layer of the host tools: strict number parsing and a safe output
 * writer (docs/tool-summary.md, "Failing loudly").
 *
 * Numbers. An option's value is accepted only when the whole field is a decimal number inside
 * the range the caller states:
 *   - integers: an optional '-' (signed parsers only), then one or more digits 0-9, nothing
 *     else: no leading '+', no white space, no "0x", no trailing characters. Leading zeros are
 *     decimal ("010" is ten, never octal eight). A value that does not fit the type or lies
 *     outside [min, max] is refused; nothing wraps.
 *   - doubles: an optional '-', digits with at most one '.', an optional exponent (e/E, optional
 *     sign, digits); no hex floats, no white space, no '+' in front. "nan", "inf" and "-inf"
 *     (any case) are refused unless CLI_ALLOW_NONFINITE is given; a decimal value that overflows
 *     the double range (1e999) or underflows to a denormal or zero (1e-400) is refused, never
 *     rounded to inf or 0. A finite value must lie inside [min, max].
 * On a refusal the parser leaves *out untouched, writes one message to stderr that names the
 * program, the option and the accepted range, e.g.
 *     kf_bench: --n: '0' is out of range (accepted: an integer in 1..100000)
 * keeps the same text for cli_last_error(), and returns INC_ERR_INVAL (not a number) or
 * INC_ERR_RANGE (a number outside the range).
 *
 * Output. cli_out_open(path) prepares a file the tool writes through `o.f` with stdio:
 *   - "-" is stdout (o.f == stdout); cli_out_close flushes it and checks ferror/fflush.
 *   - any other path: refused when it exists and is not a regular file (a FIFO, a symlink - even
 *     to a regular file -, a device, a directory), or when it is the same file (st_dev and
 *     st_ino) as one of the inputs given; otherwise a temporary file is created in the target's
 *     directory (".NAME.XXXXXX", mode 0666 less the umask, or the existing file's mode).
 *     cli_out_close checks every stage - the stream's error flag, fflush, fsync, fclose - and
 *     only then renames the temporary file over the target; on any failure the temporary file
 *     is removed, the target is left as it was, and an error naming the path is returned
 *     (INC_ERR_IO). A full disk (ENOSPC, e.g. /dev/full as stdout) is such a failure.
 *   - cli_out_discard drops the temporary file (a run that fails half-way leaves no output).
 * Refusals at open return INC_ERR_INVAL (same file as an input, empty path) or INC_ERR_IO (not a
 * regular file, cannot create); all messages go to stderr and to cli_last_error().
 */
#ifndef INCLINO_TOOL_CLI_H
#define INCLINO_TOOL_CLI_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The program name in messages ("inclino" until set). */
void cli_set_program(const char *name);
/* When quiet, messages are only kept for cli_last_error() (the unit tests). */
void cli_set_quiet(int quiet);
/* The last refusal's message (without the trailing newline), "" when none. */
const char *cli_last_error(void);
/* Reports a refusal the caller found itself: "<program>: <message>" to stderr and
 * cli_last_error(); printf format. */
void cli_error(const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;

/* Integers: the whole of `text` a decimal number within [min, max] (see above). `opt` names the
 * option in the message ("--n", "COUNT"). */
int cli_parse_u64(const char *opt, const char *text, uint64_t min, uint64_t max, uint64_t *out);
int cli_parse_i64(const char *opt, const char *text, int64_t min, int64_t max, int64_t *out);
int cli_parse_u32(const char *opt, const char *text, uint32_t min, uint32_t max, uint32_t *out);
int cli_parse_int(const char *opt, const char *text, int min, int max, int *out);

#define CLI_ALLOW_NONFINITE 1u /* cli_parse_double: "nan", "inf", "-inf" accepted as such */

/* A decimal floating-point number within [min, max] (see above). */
int cli_parse_double(const char *opt, const char *text, double min, double max, unsigned flags,
                     double *out);

/* Returns argv[*i + 1] and advances *i when it exists; otherwise reports "<opt> needs a value"
 * and returns NULL. For loops of the form `for (i = 1; i < argc; i++)`. */
const char *cli_value(int argc, char **argv, int *i);

#define CLI_PATH_MAX 4096

struct cli_out {
    FILE *f;       /* write through this; NULL when not open */
    int is_stdout; /* "-" */
    char path[CLI_PATH_MAX];
    char tmp[CLI_PATH_MAX];
};

/* Opens `path` for writing as described above. `inputs` (n_inputs paths, NULL entries and "-"
 * skipped) are the files the run reads; the output may not be any of them. `opt` names the
 * option in messages ("--out"). On failure o->f is NULL. */
int cli_out_open(struct cli_out *o, const char *opt, const char *path, const char *const *inputs,
                 size_t n_inputs);
/* Checks and commits (see above); o->f is NULL afterwards. Closing a struct that is not open
 * returns 0. */
int cli_out_close(struct cli_out *o);
/* Drops the output: stdout is flushed, a temporary file closed and removed. */
void cli_out_discard(struct cli_out *o);

/* Flushes stdout and checks its error flag: 0, or INC_ERR_IO with a message. For tools whose
 * report on stdout is their output. */
int cli_stdout_check(void);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_TOOL_CLI_H */
