/* line.c - the byte-counting line reader (see inclino/sim/line.h). */
#include "inclino/sim/line.h"

int sim_read_line(FILE *f, char *buf, size_t cap)
{
    size_t n = 0;
    int c, err = SIM_LINE_OK;
    while ((c = getc(f)) != EOF && c != '\n') {
        if (c == '\0') {
            err = SIM_LINE_NUL;
        } else if (n + 1u >= cap) {
            err = err == SIM_LINE_OK ? SIM_LINE_TOO_LONG : err;
        } else {
            buf[n++] = (char)c;
        }
    }
    buf[n] = '\0';
    if (c == EOF && ferror(f)) {
        return SIM_LINE_IO;
    }
    if (c == EOF && n == 0u && err == SIM_LINE_OK) {
        return SIM_LINE_EOF;
    }
    return err;
}
