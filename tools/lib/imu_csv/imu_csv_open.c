/* imu_csv_open.c - open a CSV for reading, gzip or plain (see inclino/sim/imu_csv.h). Host
 * only: glibc's fopencookie wraps a zlib stream into a FILE so that every reader takes both. */
#define _GNU_SOURCE
#include "inclino/sim/imu_csv.h"

#include <errno.h>
#include <string.h>
#include <sys/types.h>
#include <zlib.h>

static ssize_t gz_read(void *cookie, char *buf, size_t size)
{
    int n;
    if (size > (size_t)1 << 30) size = (size_t)1 << 30;
    n = gzread((gzFile)cookie, buf, (unsigned)size);
    if (n < 0) {
        errno = EIO;
        return -1;
    }
    return n;
}

static int gz_close(void *cookie)
{
    return gzclose((gzFile)cookie) == Z_OK ? 0 : EOF;
}

FILE *imu_csv_open(const char *path)
{
    static const cookie_io_functions_t gz_io = {gz_read, NULL, NULL, gz_close};
    unsigned char magic[2];
    size_t got;
    FILE *f;
    gzFile z;
    FILE *out;
    if (path == NULL) {
        errno = EINVAL;
        return NULL;
    }
    if (strcmp(path, "-") == 0) {
        /* Standard input may be a pipe: zlib reads it either way (plain text passes through). */
        z = gzdopen(0, "rb");
        if (z == NULL) return NULL;
        out = fopencookie(z, "r", gz_io);
        if (out == NULL) gzclose(z);
        return out;
    }
    f = fopen(path, "rb");
    if (f == NULL) return NULL;
    got = fread(magic, 1, sizeof magic, f);
    if (got == 2u && magic[0] == 0x1fu && magic[1] == 0x8bu) {
        fclose(f);
        z = gzopen(path, "rb");
        if (z == NULL) {
            errno = EIO;
            return NULL;
        }
        out = fopencookie(z, "r", gz_io);
        if (out == NULL) gzclose(z);
        return out;
    }
    if (ferror(f) || fseek(f, 0, SEEK_SET) != 0) {
        fclose(f);
        errno = EIO;
        return NULL;
    }
    return f;
}
