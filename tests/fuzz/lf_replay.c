/*
 * lf_replay.c - runs a libFuzzer target's entry function over files, without libFuzzer: the
 * corpus of tests/fuzz/corpus/<name>/ as a regression test in the gcc and ASan + UBSan host
 * builds (fuzz_corpus_<name>), and the way to reproduce a crash without clang
 * (docs/fuzzing.md):
 *
 *     lf_replay_<name> FILE|DIR ...
 *
 * Every regular file named, and every regular file directly inside a named directory, is read
 * whole and passed once. Exit status 0 when every file ran (the target aborts on a broken
 * property; a sanitizer stops the program on a report); 1 when a file cannot be read or nothing
 * was run.
 */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static int run_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    unsigned char *buf = NULL;
    size_t len = 0, cap = 0;
    if (f == NULL) {
        fprintf(stderr, "lf_replay: cannot open %s\n", path);
        return -1;
    }
    for (;;) {
        size_t got;
        if (len == cap) {
            unsigned char *nb;
            cap = cap != 0 ? cap * 2u : 4096u;
            nb = realloc(buf, cap);
            if (nb == NULL) {
                free(buf);
                fclose(f);
                return -1;
            }
            buf = nb;
        }
        got = fread(buf + len, 1, cap - len, f);
        len += got;
        if (got == 0) break;
    }
    if (ferror(f)) {
        fprintf(stderr, "lf_replay: read error on %s\n", path);
        free(buf);
        fclose(f);
        return -1;
    }
    fclose(f);
    (void)LLVMFuzzerTestOneInput(buf, len);
    free(buf);
    return 0;
}

int main(int argc, char **argv)
{
    unsigned long files = 0;
    int i;
    for (i = 1; i < argc; i++) {
        struct stat st;
        if (stat(argv[i], &st) != 0) {
            fprintf(stderr, "lf_replay: cannot stat %s\n", argv[i]);
            return 1;
        }
        if (S_ISDIR(st.st_mode)) {
            struct dirent **names = NULL;
            const int n = scandir(argv[i], &names, NULL, alphasort);
            int k;
            if (n < 0) {
                fprintf(stderr, "lf_replay: cannot list %s\n", argv[i]);
                return 1;
            }
            for (k = 0; k < n; k++) {
                char path[4096];
                struct stat fs;
                (void)snprintf(path, sizeof path, "%s/%s", argv[i], names[k]->d_name);
                if (names[k]->d_name[0] != '.' && stat(path, &fs) == 0 && S_ISREG(fs.st_mode)) {
                    if (run_file(path) != 0) return 1;
                    files++;
                }
                free(names[k]);
            }
            free(names);
        } else {
            if (run_file(argv[i]) != 0) return 1;
            files++;
        }
    }
    printf("lf_replay: %lu files run\n", files);
    return files > 0u ? 0 : 1;
}
