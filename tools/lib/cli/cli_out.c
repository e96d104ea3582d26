/* cli_out.c - the safe output writer of tool_cli.h. */
#define _POSIX_C_SOURCE 200809L
#include "inclino/tool_cli.h"

#include "inclino/error.h"

#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

static void out_reset(struct cli_out *o)
{
    o->f = NULL;
    o->is_stdout = 0;
    o->path[0] = '\0';
    o->tmp[0] = '\0';
}

static const char *kind_of(mode_t m)
{
    if (S_ISLNK(m)) return "a symbolic link";
    if (S_ISFIFO(m)) return "a FIFO";
    if (S_ISCHR(m)) return "a character device";
    if (S_ISBLK(m)) return "a block device";
    if (S_ISDIR(m)) return "a directory";
    if (S_ISSOCK(m)) return "a socket";
    return "not a regular file";
}

/* The target must not exist, or be a regular file (not reached through a symlink). */
static int check_target(const char *opt, const char *path, struct stat *st, int *exists)
{
    *exists = 0;
    if (lstat(path, st) != 0) {
        if (errno == ENOENT) return INC_OK;
        cli_error("%s: cannot examine '%s': %s", opt, path, strerror(errno));
        return INC_ERR_IO;
    }
    if (!S_ISREG(st->st_mode)) {
        cli_error("%s: '%s' is %s; refusing to replace it (the output must be a regular file or "
                  "a new path)",
                  opt, path, kind_of(st->st_mode));
        return INC_ERR_IO;
    }
    *exists = 1;
    return INC_OK;
}

int cli_out_open(struct cli_out *o, const char *opt, const char *path, const char *const *inputs,
                 size_t n_inputs)
{
    struct stat st;
    int exists = 0, rc, fd;
    size_t len;
    const char *slash, *base;
    mode_t mask, mode;
    if (o == NULL) return INC_ERR_NULL;
    out_reset(o);
    if (opt == NULL) opt = "output";
    if (path == NULL || path[0] == '\0') {
        cli_error("%s: empty output path", opt);
        return INC_ERR_INVAL;
    }
    if (strcmp(path, "-") == 0) {
        o->f = stdout;
        o->is_stdout = 1;
        (void)snprintf(o->path, sizeof o->path, "-");
        return INC_OK;
    }
    len = strlen(path);
    if (len + 16u > sizeof o->path) {
        cli_error("%s: output path too long", opt);
        return INC_ERR_INVAL;
    }
    rc = check_target(opt, path, &st, &exists);
    if (rc != INC_OK) return rc;
    if (exists) {
        size_t i;
        for (i = 0; i < n_inputs; i++) {
            struct stat in;
            if (inputs == NULL || inputs[i] == NULL || strcmp(inputs[i], "-") == 0) continue;
            if (stat(inputs[i], &in) != 0) continue;
            if (in.st_dev == st.st_dev && in.st_ino == st.st_ino) {
                cli_error("%s: '%s' is the same file as the input '%s'; refusing to overwrite "
                          "an input",
                          opt, path, inputs[i]);
                return INC_ERR_INVAL;
            }
        }
    }
    /* The temporary file: <dir>/.<base>.XXXXXX, in the target's directory so rename is atomic. */
    slash = strrchr(path, '/');
    base = slash != NULL ? slash + 1 : path;
    if (base[0] == '\0') {
        cli_error("%s: '%s' names a directory, not a file", opt, path);
        return INC_ERR_INVAL;
    }
    (void)snprintf(o->tmp, sizeof o->tmp, "%.*s.%s.XXXXXX", (int)(base - path), path, base);
    fd = mkstemp(o->tmp);
    if (fd < 0) {
        cli_error("%s: cannot create a temporary file beside '%s': %s", opt, path, strerror(errno));
        o->tmp[0] = '\0';
        return INC_ERR_IO;
    }
    mask = umask(0);
    (void)umask(mask);
    mode = exists ? (st.st_mode & 07777) : (mode_t)(0666 & ~mask);
    if (fchmod(fd, mode) != 0) {
        cli_error("%s: cannot set the mode of '%s': %s", opt, o->tmp, strerror(errno));
        (void)close(fd);
        (void)unlink(o->tmp);
        o->tmp[0] = '\0';
        return INC_ERR_IO;
    }
    o->f = fdopen(fd, "w");
    if (o->f == NULL) {
        cli_error("%s: cannot open '%s': %s", opt, o->tmp, strerror(errno));
        (void)close(fd);
        (void)unlink(o->tmp);
        o->tmp[0] = '\0';
        return INC_ERR_IO;
    }
    (void)snprintf(o->path, sizeof o->path, "%s", path);
    return INC_OK;
}

int cli_stdout_check(void)
{
    const int flush_failed = fflush(stdout) != 0;
    const int err = errno;
    if (flush_failed || ferror(stdout)) {
        cli_error("write error on standard output: %s",
                  flush_failed ? strerror(err) : "the stream reports an error");
        return INC_ERR_IO;
    }
    return INC_OK;
}

int cli_out_close(struct cli_out *o)
{
    const char *stage = NULL;
    int err = 0, exists = 0, rc;
    struct stat st;
    if (o == NULL || o->f == NULL) return INC_OK;
    if (o->is_stdout) {
        rc = cli_stdout_check();
        out_reset(o);
        return rc;
    }
    if (ferror(o->f)) {
        stage = "write";
        err = EIO;
    }
    if (fflush(o->f) != 0 && stage == NULL) {
        stage = "write";
        err = errno;
    }
    if (stage == NULL && fsync(fileno(o->f)) != 0) {
        stage = "fsync";
        err = errno;
    }
    if (fclose(o->f) != 0 && stage == NULL) {
        stage = "close";
        err = errno;
    }
    o->f = NULL;
    if (stage != NULL) {
        cli_error("%s error on '%s': %s; nothing written", stage, o->path, strerror(err));
        (void)unlink(o->tmp);
        out_reset(o);
        return INC_ERR_IO;
    }
    /* Checked again: the target may have been replaced by something else meanwhile. */
    rc = check_target("output", o->path, &st, &exists);
    if (rc != INC_OK) {
        (void)unlink(o->tmp);
        out_reset(o);
        return rc;
    }
    if (rename(o->tmp, o->path) != 0) {
        cli_error("cannot rename '%s' to '%s': %s", o->tmp, o->path, strerror(errno));
        (void)unlink(o->tmp);
        out_reset(o);
        return INC_ERR_IO;
    }
    out_reset(o);
    return INC_OK;
}

void cli_out_discard(struct cli_out *o)
{
    if (o == NULL || o->f == NULL) return;
    if (o->is_stdout) {
        (void)fflush(stdout);
    } else {
        (void)fclose(o->f);
        (void)unlink(o->tmp);
    }
    out_reset(o);
}
