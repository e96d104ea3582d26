/*
 * trace_line.h - the line reader shared by the trace reader (trace.c) and the VCD converter
 * (trace_vcd.c); private to sim/trace.
 *
 * fgets cannot tell a NUL byte inside a line from the end of the string, so a line such as
 * "miso=A\0 5C3" used to be read as "miso=A" (docs/traces.md, "Mutation sweep"). This reader
 * counts the bytes itself.
 */
#ifndef INCLINO_SIM_TRACE_LINE_H
#define INCLINO_SIM_TRACE_LINE_H

#include <stddef.h>
#include <stdio.h>

#define TRACE_LINE_OK 1
#define TRACE_LINE_EOF 0
#define TRACE_LINE_TOO_LONG (-1) /* more than cap - 1 characters before the newline */
#define TRACE_LINE_NUL (-2)      /* a NUL byte in the line */
#define TRACE_LINE_IO (-3)       /* read error */

/*
 * Read one line of f into buf (cap >= 2): the characters before the '\n' (which is consumed, not
 * stored), NUL-terminated. A last line without '\n' is a line. Returns TRACE_LINE_OK,
 * TRACE_LINE_EOF (nothing left), or one of the errors above; after TOO_LONG or NUL the rest of
 * the line has been consumed.
 */
int trace_read_line(FILE *f, char *buf, size_t cap);

#endif
