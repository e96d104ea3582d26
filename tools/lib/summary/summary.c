/* summary.c - see tool_summary.h. */
#include "inclino/tool_summary.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#define SUMMARY_MAX_KEYS 64
#define SUMMARY_KEY_LEN 32
#define SUMMARY_VALUE_LEN 96

static char summary_tool[SUMMARY_KEY_LEN] = "?";
static char summary_keys[SUMMARY_MAX_KEYS][SUMMARY_KEY_LEN];
static char summary_values[SUMMARY_MAX_KEYS][SUMMARY_VALUE_LEN];
static int summary_n;

/* src copied into dst[size] (size >= 2), white space and '=' replaced by '_', "" by "-". */
static void copy_clean(char *dst, size_t size, const char *src)
{
    size_t i, n = strlen(src);
    if (n > size - 1u) n = size - 1u;
    for (i = 0; i < n; i++) {
        const char c = src[i];
        dst[i] = (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '=') ? '_' : c;
    }
    dst[n] = '\0';
    if (n == 0u) {
        dst[0] = '-';
        dst[1] = '\0';
    }
}

void tool_summary_begin(const char *tool)
{
    copy_clean(summary_tool, sizeof summary_tool, tool != NULL ? tool : "?");
    summary_n = 0;
}

void tool_summary_add(const char *key, const char *fmt, ...)
{
    char value[SUMMARY_VALUE_LEN];
    char k[SUMMARY_KEY_LEN];
    va_list ap;
    int i;
    if (key == NULL || fmt == NULL) return;
    va_start(ap, fmt);
    (void)vsnprintf(value, sizeof value, fmt, ap);
    va_end(ap);
    copy_clean(k, sizeof k, key);
    for (i = 0; i < summary_n; i++) {
        if (strcmp(summary_keys[i], k) == 0) break;
    }
    if (i == summary_n) {
        if (summary_n == SUMMARY_MAX_KEYS) return;
        summary_n++;
        memcpy(summary_keys[i], k, sizeof k);
    }
    copy_clean(summary_values[i], sizeof summary_values[i], value);
}

int tool_summary_end(const char *status, int exit_status)
{
    char st[SUMMARY_KEY_LEN];
    int i;
    copy_clean(st, sizeof st, status != NULL ? status : "?");
    fflush(stderr);
    printf("summary: tool=%s status=%s", summary_tool, st);
    for (i = 0; i < summary_n; i++) {
        printf(" %s=%s", summary_keys[i], summary_values[i]);
    }
    printf("\n");
    summary_n = 0;
    /* A report that did not reach stdout (a full disk, a closed pipe) is a failed run. */
    if (fflush(stdout) != 0 || ferror(stdout)) {
        (void)fprintf(stderr, "%s: write error on standard output\n", summary_tool);
        return exit_status != 0 ? exit_status : 1;
    }
    return exit_status;
}

int tool_summary_error(const char *error, int exit_status)
{
    tool_summary_add("error", "%s", error != NULL ? error : "?");
    return tool_summary_end("error", exit_status);
}
