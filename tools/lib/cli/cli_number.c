/* cli_number.c - strict option parsing and the messages of tool_cli.h. */
#include "inclino/tool_cli.h"

#include "inclino/error.h"

#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

static char cli_program[64] = "inclino";
static char cli_message[600];
static int cli_quiet;

void cli_set_program(const char *name)
{
    const char *slash;
    if (name == NULL || name[0] == '\0') return;
    slash = strrchr(name, '/');
    if (slash != NULL && slash[1] != '\0') name = slash + 1;
    (void)snprintf(cli_program, sizeof cli_program, "%s", name);
}

void cli_set_quiet(int quiet)
{
    cli_quiet = quiet;
}

const char *cli_last_error(void)
{
    return cli_message;
}

void cli_error(const char *fmt, ...)
{
    char body[448];
    va_list ap;
    va_start(ap, fmt);
    (void)vsnprintf(body, sizeof body, fmt, ap);
    va_end(ap);
    (void)snprintf(cli_message, sizeof cli_message, "%s: %s", cli_program, body);
    if (!cli_quiet) {
        (void)fprintf(stderr, "%s\n", cli_message);
        (void)fflush(stderr);
    }
}

/* The value as printed in a message: at most 40 characters, so a huge argument stays readable. */
static const char *shown(const char *text, char *buf, size_t size)
{
    size_t n = strlen(text);
    if (n < 41u) return text;
    (void)snprintf(buf, size, "%.37s...", text);
    return buf;
}

/* Digits only, at least one; the magnitude into *mag, 0 on success, -1 when it does not fit
 * in uint64_t. */
static int digits_u64(const char *s, uint64_t *mag)
{
    uint64_t v = 0;
    for (; *s != '\0'; s++) {
        const uint64_t d = (uint64_t)(*s - '0');
        if (v > (UINT64_MAX - d) / 10u) return -1;
        v = v * 10u + d;
    }
    *mag = v;
    return 0;
}

static int all_digits(const char *s)
{
    if (*s == '\0') return 0;
    for (; *s != '\0'; s++) {
        if (*s < '0' || *s > '9') return 0;
    }
    return 1;
}

int cli_parse_u64(const char *opt, const char *text, uint64_t min, uint64_t max, uint64_t *out)
{
    char buf[48];
    uint64_t v;
    if (opt == NULL) opt = "value";
    if (text == NULL || out == NULL) {
        cli_error("%s: no value given", opt);
        return INC_ERR_INVAL;
    }
    if (!all_digits(text)) {
        cli_error("%s: '%s' is not a decimal integer (accepted: an integer in %llu..%llu)", opt,
                  shown(text, buf, sizeof buf), (unsigned long long)min, (unsigned long long)max);
        return INC_ERR_INVAL;
    }
    if (digits_u64(text, &v) != 0 || v < min || v > max) {
        cli_error("%s: '%s' is out of range (accepted: an integer in %llu..%llu)", opt,
                  shown(text, buf, sizeof buf), (unsigned long long)min, (unsigned long long)max);
        return INC_ERR_RANGE;
    }
    *out = v;
    return INC_OK;
}

int cli_parse_i64(const char *opt, const char *text, int64_t min, int64_t max, int64_t *out)
{
    char buf[48];
    const char *digits;
    uint64_t mag;
    int64_t v;
    int neg;
    if (opt == NULL) opt = "value";
    if (text == NULL || out == NULL) {
        cli_error("%s: no value given", opt);
        return INC_ERR_INVAL;
    }
    neg = text[0] == '-';
    digits = neg ? text + 1 : text;
    if (!all_digits(digits)) {
        cli_error("%s: '%s' is not a decimal integer (accepted: an integer in %lld..%lld)", opt,
                  shown(text, buf, sizeof buf), (long long)min, (long long)max);
        return INC_ERR_INVAL;
    }
    if (digits_u64(digits, &mag) != 0) goto range;
    if (neg) {
        if (mag > (uint64_t)INT64_MAX + 1u) goto range;
        v = mag == (uint64_t)INT64_MAX + 1u ? INT64_MIN : -(int64_t)mag;
    } else {
        if (mag > (uint64_t)INT64_MAX) goto range;
        v = (int64_t)mag;
    }
    if (v < min || v > max) goto range;
    *out = v;
    return INC_OK;
range:
    cli_error("%s: '%s' is out of range (accepted: an integer in %lld..%lld)", opt,
              shown(text, buf, sizeof buf), (long long)min, (long long)max);
    return INC_ERR_RANGE;
}

int cli_parse_u32(const char *opt, const char *text, uint32_t min, uint32_t max, uint32_t *out)
{
    uint64_t v;
    const int rc = cli_parse_u64(opt, text, min, max, &v);
    if (rc == INC_OK && out != NULL) *out = (uint32_t)v;
    return rc;
}

int cli_parse_int(const char *opt, const char *text, int min, int max, int *out)
{
    int64_t v;
    const int rc = cli_parse_i64(opt, text, min, max, &v);
    if (rc == INC_OK && out != NULL) *out = (int)v;
    return rc;
}

/* -?digits[.digits][(e|E)[+-]digits], at least one digit in the mantissa. */
static int decimal_syntax(const char *s)
{
    int mant = 0;
    if (*s == '-') s++;
    while (*s >= '0' && *s <= '9') {
        s++;
        mant++;
    }
    if (*s == '.') {
        s++;
        while (*s >= '0' && *s <= '9') {
            s++;
            mant++;
        }
    }
    if (mant == 0) return 0;
    if (*s == 'e' || *s == 'E') {
        int exp = 0;
        s++;
        if (*s == '+' || *s == '-') s++;
        while (*s >= '0' && *s <= '9') {
            s++;
            exp++;
        }
        if (exp == 0) return 0;
    }
    return *s == '\0';
}

/* Case-insensitive equality with a lower-case word. */
static int same_word(const char *s, const char *word)
{
    for (; *s != '\0' && *word != '\0'; s++, word++) {
        const char c = (*s >= 'A' && *s <= 'Z') ? (char)(*s - 'A' + 'a') : *s;
        if (c != *word) return 0;
    }
    return *s == '\0' && *word == '\0';
}

/* Only zeros in the mantissa (so 0 is an exact result, not an underflow). */
static int zero_mantissa(const char *s)
{
    for (; *s != '\0' && *s != 'e' && *s != 'E'; s++) {
        if (*s >= '1' && *s <= '9') return 0;
    }
    return 1;
}

int cli_parse_double(const char *opt, const char *text, double min, double max, unsigned flags,
                     double *out)
{
    char buf[48];
    double v;
    char *end = NULL;
    const int nonfinite = (flags & CLI_ALLOW_NONFINITE) != 0u;
    const char *extra = nonfinite ? ", or nan/inf/-inf" : "";
    if (opt == NULL) opt = "value";
    if (text == NULL || out == NULL) {
        cli_error("%s: no value given", opt);
        return INC_ERR_INVAL;
    }
    if (same_word(text, "nan") || same_word(text, "inf") || same_word(text, "-inf") ||
        same_word(text, "infinity") || same_word(text, "-infinity")) {
        if (!nonfinite) {
            cli_error("%s: '%s' is not a finite number (accepted: a decimal number in %.9g..%.9g)",
                      opt, text, min, max);
            return INC_ERR_RANGE;
        }
        *out = same_word(text, "nan") ? (double)NAN
                                      : (text[0] == '-' ? -(double)INFINITY : (double)INFINITY);
        return INC_OK;
    }
    if (!decimal_syntax(text)) {
        cli_error("%s: '%s' is not a decimal number (accepted: a decimal number in %.9g..%.9g%s)",
                  opt, shown(text, buf, sizeof buf), min, max, extra);
        return INC_ERR_INVAL;
    }
    errno = 0;
    v = strtod(text, &end);
    if (end == NULL || *end != '\0' || !isfinite(v) || (errno == ERANGE) ||
        (v == 0.0 && !zero_mantissa(text)) || (v != 0.0 && fabs(v) < DBL_MIN) || v < min ||
        v > max) {
        cli_error("%s: '%s' is out of range (accepted: a decimal number in %.9g..%.9g%s)", opt,
                  shown(text, buf, sizeof buf), min, max, extra);
        return INC_ERR_RANGE;
    }
    *out = v;
    return INC_OK;
}

const char *cli_value(int argc, char **argv, int *i)
{
    if (argv == NULL || i == NULL) return NULL;
    if (*i + 1 >= argc || argv[*i + 1] == NULL) {
        cli_error("%s needs a value", (*i < argc && argv[*i] != NULL) ? argv[*i] : "option");
        return NULL;
    }
    *i += 1;
    return argv[*i];
}
