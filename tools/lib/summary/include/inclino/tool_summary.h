/*
 * tool_summary.h - the machine-readable summary line of the end-to-end tools
 * (docs/tool-summary.md).
 *
 * Every tool ends its run, success or failure, with exactly one line on stdout:
 *
 *     summary: tool=<name> status=<ok|fail|error> key=value key=value ...
 *
 * Keys are lower case [a-z0-9_]; a value never contains white space or '=' (tool_summary_add
 * replaces them with '_'), and an empty value is written as '-'. Error codes are written by
 * name (inc_err_name: error=ERR_FORMAT), other refusals with a short word (error=usage). Tests
 * assert on these keys (cmake/scripts/tool_summary.cmake), not on the prose around them.
 */
#ifndef INCLINO_TOOL_SUMMARY_H
#define INCLINO_TOOL_SUMMARY_H

#ifdef __cplusplus
extern "C" {
#endif

/* Starts a summary for `tool`, dropping any pending one. */
void tool_summary_begin(const char *tool);
/* Appends key=value, value formatted with printf's rules. A key added twice keeps the last
 * value. */
void tool_summary_add(const char *key, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
/* Prints the line (status first, after tool) to stdout and flushes; status is "ok", "fail" or
 * "error". Returns exit_status, so that `return tool_summary_end("ok", 0);` ends main; when
 * stdout has a write error (a full disk: everything the tool printed is suspect) it says so on
 * stderr and returns exit_status, or 1 when that was 0. */
int tool_summary_end(const char *status, int exit_status);
/* Shorthand for a run that stops on an error: error=<error>, then tool_summary_end("error",
 * exit_status). */
int tool_summary_error(const char *error, int exit_status);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_TOOL_SUMMARY_H */
