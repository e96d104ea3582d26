/*
 * line.h - one line of a text file, bytes counted (host side). Shared by the readers of the
 * trace (sim/trace), VCD, Allan-deviation CSV (tools/allan) and recorded-IMU CSV
 * (tools/imu_replay) formats.
 *
 * fgets cannot tell a NUL byte inside a line from the end of the string, so a line such as
 * "miso=A\0 5C3" or "1.5\0 7" used to be read cut short (docs/traces.md, "Mutation sweep").
 * This reader counts the bytes itself and reports the NUL.
 */
#ifndef INCLINO_SIM_LINE_H
#define INCLINO_SIM_LINE_H

#include <stddef.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

#define SIM_LINE_OK 1
#define SIM_LINE_EOF 0
#define SIM_LINE_TOO_LONG (-1) /* more than cap - 1 characters before the newline */
#define SIM_LINE_NUL (-2)      /* a NUL byte in the line (reported even if it is also too long) */
#define SIM_LINE_IO (-3)       /* read error */

/*
 * Read one line of f into buf (cap >= 2): the characters before the '\n' (which is consumed, not
 * stored), NUL-terminated, nothing else removed. A last line without '\n' is a line. Returns
 * SIM_LINE_OK, SIM_LINE_EOF (nothing left), or one of the errors above; after TOO_LONG or NUL
 * the rest of the line has been consumed and buf holds its first cap - 1 other characters.
 */
int sim_read_line(FILE *f, char *buf, size_t cap);

#ifdef __cplusplus
}
#endif

#endif
