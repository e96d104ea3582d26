/* fuzz_mut.c - the deterministic mutation set (see fuzz_mut.h). */
#include "fuzz_mut.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "unit.h"

const unsigned char fuzz_bytes[FUZZ_N_BYTES] = {0x00, '\n', ',', '-', '9',
                                                0xFF, ' ',  '.', 'e', 'n'};
const char *const fuzz_tokens[FUZZ_N_TOKENS] = {
    "1e308",
    "-1e308",
    "99999999999999999999",
    "-2147483649",
    "18446744073709551616",
    "nan",
    "inf",
    "-inf",
    "",
    "-0",
    "0x10",
    "010",
    "1e-400",
    "+5",
};

#define FUZZ_LONG_RUN 5000u

static int tok_char(char c)
{
    return (c >= '0' && c <= '9') || (c >= 'A' && c <= 'F') || (c >= 'a' && c <= 'f') || c == '.' ||
           c == '+' || c == '-';
}

/* The t-th number token (every stride-th one); returns its start, *tlen its length; len if none. */
static size_t nth_token(const char *s, size_t len, size_t t, size_t stride, size_t *tlen,
                        size_t *count)
{
    size_t i = 0, found = 0, res = len;
    while (i < len) {
        size_t j = i, digits = 0;
        if (!tok_char(s[i]) || (i > 0 && tok_char(s[i - 1]))) {
            i++;
            continue;
        }
        while (j < len && tok_char(s[j])) {
            digits += (s[j] >= '0' && s[j] <= '9');
            j++;
        }
        if (digits > 0) {
            if (found % stride == 0 && found / stride == t && res == len) {
                res = i;
                *tlen = j - i;
            }
            found++;
        }
        i = j;
    }
    if (count != NULL) *count = (found + stride - 1) / stride;
    return res;
}

size_t fuzz_count_lines(const char *text, size_t len)
{
    size_t i, n = 0;
    for (i = 0; i < len; i++)
        n += text[i] == '\n';
    return n + (len > 0 && text[len - 1] != '\n');
}

size_t fuzz_line_span(const char *text, size_t len, size_t line, size_t *end)
{
    size_t i = 0, l = 0, start;
    while (l < line && i < len) {
        if (text[i++] == '\n') l++;
    }
    start = l == line ? i : len;
    i = start;
    while (i < len && text[i] != '\n')
        i++;
    *end = i < len ? i + 1 : len;
    return start;
}

static void put(struct fuzz_case *c, const char *a, size_t na, const char *b, size_t nb,
                const char *d, size_t nd)
{
    free(c->data);
    c->data = malloc(na + nb + nd + 1u);
    if (c->data == NULL) {
        fprintf(stderr, "fuzz_mut: out of memory\n");
        exit(2);
    }
    memcpy(c->data, a, na);
    memcpy(c->data + na, b, nb);
    memcpy(c->data + na + nb, d, nd);
    c->len = na + nb + nd;
    c->data[c->len] = '\0';
}

enum fuzz_family fuzz_mutate(const char *seed, size_t len, unsigned long k, size_t stride,
                             unsigned n_random, struct fuzz_case *out)
{
    const size_t lines = fuzz_count_lines(seed, len);
    size_t n_pos = (len + stride - 1) / stride, n_tok = 0, tl = 0;
    size_t s, e;
    (void)nth_token(seed, len, (size_t)-1, stride, &tl, &n_tok);
    out->arg = 0;
    /* TRUNC */
    if (k < n_pos) {
        out->where = (size_t)k * stride;
        put(out, seed, out->where, "", 0, "", 0);
        return out->family = FUZZ_TRUNC;
    }
    k -= n_pos;
    /* BYTE: position j*stride + (j % stride), so a strided sweep still visits every column. */
    if (k < n_pos * FUZZ_N_BYTES) {
        const size_t j = (size_t)k / FUZZ_N_BYTES;
        size_t pos = j * stride + j % stride;
        char b;
        if (pos >= len) pos = len - 1u;
        out->where = pos;
        out->arg = (unsigned)(k % FUZZ_N_BYTES);
        b = (char)fuzz_bytes[out->arg];
        put(out, seed, pos, &b, 1, seed + pos + 1, len - pos - 1);
        return out->family = FUZZ_BYTE;
    }
    k -= n_pos * FUZZ_N_BYTES;
    if (k < lines) {
        s = fuzz_line_span(seed, len, (size_t)k, &e);
        out->where = (size_t)k;
        put(out, seed, s, "", 0, seed + e, len - e);
        return out->family = FUZZ_DELLINE;
    }
    k -= lines;
    if (k < lines) {
        s = fuzz_line_span(seed, len, (size_t)k, &e);
        out->where = (size_t)k;
        put(out, seed, e, seed + s, e - s, seed + e, len - e);
        /* a last line without '\n' duplicated: keep the lines apart */
        if (e == len && (len == 0 || seed[len - 1] != '\n')) {
            put(out, seed, e, "\n", 1, seed + s, e - s);
        }
        return out->family = FUZZ_DUPLINE;
    }
    k -= lines;
    if (k < n_tok * FUZZ_N_TOKENS) {
        const char *tok = fuzz_tokens[k % FUZZ_N_TOKENS];
        s = nth_token(seed, len, (size_t)k / FUZZ_N_TOKENS, stride, &tl, NULL);
        out->where = s;
        out->arg = (unsigned)(k % FUZZ_N_TOKENS);
        put(out, seed, s, tok, strlen(tok), seed + s + tl, len - s - tl);
        return out->family = FUZZ_TOKEN;
    }
    k -= n_tok * FUZZ_N_TOKENS;
    if (k < 2u * lines) {
        const size_t line = (size_t)k / 2u;
        s = fuzz_line_span(seed, len, line, &e);
        if (e > s && seed[e - 1] == '\n') e--;
        out->where = line;
        out->arg = (unsigned)(k % 2u);
        put(out, seed, e, k % 2u ? " 1" : ",1", 2, seed + e, len - e);
        return out->family = FUZZ_EXTRA;
    }
    k -= 2u * lines;
    if (k == 0) {
        size_t i, o = 0, nl = 0;
        for (i = 0; i < len; i++)
            nl += seed[i] == '\n';
        put(out, "", 0, "", 0, "", 0);
        free(out->data);
        out->data = malloc(len + nl + 1u);
        if (out->data == NULL) exit(2);
        for (i = 0; i < len; i++) {
            if (seed[i] == '\n') out->data[o++] = '\r';
            out->data[o++] = seed[i];
        }
        out->data[o] = '\0';
        out->len = o;
        out->where = 0;
        return out->family = FUZZ_CRLF;
    }
    k--;
    if (k == 0) {
        const size_t n = len > 0 && seed[len - 1] == '\n' ? len - 1u : len;
        put(out, seed, n, "", 0, "", 0);
        out->where = n;
        return out->family = FUZZ_NOEOL;
    }
    k--;
    if (k < lines) {
        static char run[FUZZ_LONG_RUN];
        const char fill = "x1 ,"[k % 4u];
        memset(run, fill, sizeof run);
        s = fuzz_line_span(seed, len, (size_t)k, &e);
        out->where = (size_t)k;
        out->arg = (unsigned)fill;
        put(out, seed, s, run, sizeof run, seed + s, len - s);
        return out->family = FUZZ_LONG;
    }
    k -= lines;
    if (k < n_random && len > 0) {
        uint32_t st = 0x9E3779B9u ^ (uint32_t)(k * 2654435761u);
        unsigned m;
        put(out, seed, len, "", 0, "", 0);
        for (m = 0; m < 3u; m++) {
            const size_t pos = unit_rand32(&st) % len;
            out->data[pos] = (char)(unit_rand32(&st) & 0xFFu);
        }
        out->where = 0;
        out->arg = (unsigned)k;
        return out->family = FUZZ_RANDOM;
    }
    return out->family = FUZZ_END;
}

void fuzz_case_free(struct fuzz_case *c)
{
    free(c->data);
    c->data = NULL;
    c->len = 0;
}

const char *fuzz_family_name(enum fuzz_family f)
{
    static const char *const names[] = {"end",   "trunc", "byte",  "delline", "dupline", "token",
                                        "extra", "crlf",  "noeol", "long",    "random"};
    return (unsigned)f < sizeof names / sizeof names[0] ? names[f] : "?";
}

char *fuzz_read_file(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    char *buf;
    long n;
    if (f == NULL) return NULL;
    if (fseek(f, 0, SEEK_END) != 0 || (n = ftell(f)) < 0 || fseek(f, 0, SEEK_SET) != 0) {
        fclose(f);
        return NULL;
    }
    buf = malloc((size_t)n + 1u);
    if (buf == NULL || fread(buf, 1, (size_t)n, f) != (size_t)n) {
        free(buf);
        fclose(f);
        return NULL;
    }
    fclose(f);
    buf[n] = '\0';
    *len = (size_t)n;
    return buf;
}
