/*
 * mini_libc.c - the rv32 test board's C-library shim; see include/stdio.h.
 *
 * Output goes to QEMU's console through RISC-V semihosting (SYS_WRITE0), one buffered line at a
 * time. exit() ends QEMU through SYS_EXIT: QEMU 7.2 on riscv32 maps "application exit" to status
 * 0 and every other reason to 1 (SYS_EXIT_EXTENDED with a status is not honoured there), so a
 * failing rv32 test exits 1 whatever its failure count.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/*
 * Both streams go to the semihosting console; fd only tells them apart. The suppression: cppcheck
 * replaces this shim's <stdio.h> with its own model of the standard one, so it does not see that
 * FILE is this struct and that fflush reads fd.
 */
struct rv32_file {
    /* cppcheck-suppress unusedStructMember */
    int fd;
};
static struct rv32_file rv32_stdout = {1};
static struct rv32_file rv32_stderr = {2};
FILE *const stdout = &rv32_stdout;
FILE *const stderr = &rv32_stderr;

long rv32_semihost(long op, const void *arg);
void rv32_exit_hooks(void);
__attribute__((noreturn)) void rv32_exit_now(int status);

/*
 * The RISC-V semihosting trap is "ebreak" between two marker instructions, uncompressed and in
 * this exact order (RISC-V semihosting spec, "Semihosting trap instruction sequence").
 */
long rv32_semihost(long op, const void *arg)
{
    register long a0 __asm("a0") = op;
    register const void *a1 __asm("a1") = arg;
    __asm volatile(".option push\n\t"
                   ".option norvc\n\t"
                   ".balign 16\n\t"
                   "slli zero, zero, 0x1f\n\t"
                   "ebreak\n\t"
                   "srai zero, zero, 7\n\t"
                   ".option pop"
                   : "+r"(a0)
                   : "r"(a1)
                   : "memory");
    return a0;
}

#define SEMIHOST_SYS_WRITE0 0x04
#define SEMIHOST_SYS_EXIT 0x18
#define SEMIHOST_ADP_APPLICATION_EXIT 0x20026
#define SEMIHOST_ADP_RUNTIME_ERROR 0x20023

static char rv32_line[128];
static size_t rv32_len;

int fflush(FILE *f)
{
    if (f != NULL && f->fd != 1 && f->fd != 2) {
        return -1; /* EOF: not a stream of ours */
    }
    if (rv32_len > 0u) {
        rv32_line[rv32_len] = '\0';
        (void)rv32_semihost(SEMIHOST_SYS_WRITE0, rv32_line);
        rv32_len = 0u;
    }
    return 0;
}

int putchar(int c)
{
    rv32_line[rv32_len++] = (char)c;
    if (c == '\n' || rv32_len == sizeof(rv32_line) - 1u) {
        (void)fflush(stdout);
    }
    return (unsigned char)c;
}

int puts(const char *s)
{
    while (*s != '\0') {
        (void)putchar(*s++);
    }
    (void)putchar('\n');
    return 0;
}

size_t strlen(const char *s)
{
    size_t n = 0u;
    while (s[n] != '\0') {
        n++;
    }
    return n;
}

int strcmp(const char *a, const char *b)
{
    while (*a != '\0' && *a == *b) {
        a++;
        b++;
    }
    return (int)(unsigned char)*a - (int)(unsigned char)*b;
}

int strncmp(const char *a, const char *b, size_t n)
{
    for (; n > 0u; n--, a++, b++) {
        if (*a != *b || *a == '\0') {
            return (int)(unsigned char)*a - (int)(unsigned char)*b;
        }
    }
    return 0;
}

/* Print digits of v in base (10 or 16) with padding; returns characters written. */
static int rv32_put_uint(unsigned long long v, unsigned base, int upper, int width, char pad,
                         int left, int negative)
{
    char buf[24];
    int n = 0;
    int total;
    int i;
    const char *digits = upper ? "0123456789ABCDEF" : "0123456789abcdef";
    do {
        buf[n++] = digits[v % base];
        v /= base;
    } while (v != 0u);
    total = n + (negative ? 1 : 0);
    if (negative && pad == '0') {
        (void)putchar('-');
    }
    for (i = total; !left && i < width; i++) {
        (void)putchar(pad);
    }
    if (negative && pad != '0') {
        (void)putchar('-');
    }
    while (n > 0) {
        (void)putchar(buf[--n]);
    }
    for (i = total; left && i < width; i++) {
        (void)putchar(' ');
    }
    return total > width ? total : width;
}

int vprintf(const char *fmt, va_list ap)
{
    int count = 0;
    for (; *fmt != '\0'; fmt++) {
        int left = 0;
        int width = 0;
        int lng = 0;
        char pad = ' ';
        if (*fmt != '%') {
            (void)putchar(*fmt);
            count++;
            continue;
        }
        fmt++;
        for (; *fmt == '-' || *fmt == '0'; fmt++) {
            if (*fmt == '-') {
                left = 1;
            } else {
                pad = '0';
            }
        }
        for (; *fmt >= '0' && *fmt <= '9'; fmt++) {
            width = width * 10 + (*fmt - '0');
        }
        if (*fmt == '.') { /* precision: accepted, ignored (only the float form uses one) */
            fmt++;
            while (*fmt >= '0' && *fmt <= '9') {
                fmt++;
            }
        }
        for (; *fmt == 'l' || *fmt == 'h' || *fmt == 'z'; fmt++) {
            if (*fmt == 'l' || *fmt == 'z') {
                lng++;
            }
        }
        switch (*fmt) {
        case 'd':
        case 'i': {
            long long v = lng >= 2   ? va_arg(ap, long long)
                          : lng == 1 ? va_arg(ap, long)
                                     : va_arg(ap, int);
            unsigned long long m = v < 0 ? 0u - (unsigned long long)v : (unsigned long long)v;
            count += rv32_put_uint(m, 10u, 0, width, pad, left, v < 0);
            break;
        }
        case 'u':
        case 'x':
        case 'X': {
            unsigned long long v = lng >= 2   ? va_arg(ap, unsigned long long)
                                   : lng == 1 ? va_arg(ap, unsigned long)
                                              : va_arg(ap, unsigned);
            count += rv32_put_uint(v, *fmt == 'u' ? 10u : 16u, *fmt == 'X', width, pad, left, 0);
            break;
        }
        case 'p':
            (void)putchar('0');
            (void)putchar('x');
            count += 2 + rv32_put_uint((uintptr_t)va_arg(ap, void *), 16u, 0, 0, ' ', 0, 0);
            break;
        case 'c':
            (void)putchar(va_arg(ap, int));
            count++;
            break;
        case 's': {
            const char *s = va_arg(ap, const char *);
            if (s == NULL) {
                s = "(null)";
            }
            while (*s != '\0') {
                (void)putchar(*s++);
                count++;
            }
            break;
        }
        case 'f':
        case 'g':
        case 'e': {
            /* Tests only print floats in failure messages: a fixed 6-decimal form will do. */
            double v = va_arg(ap, double);
            int neg = v < 0.0;
            unsigned long long ip;
            unsigned long long frac;
            if (neg) {
                v = -v;
            }
            if (!(v < 1e18)) {
                (void)putchar(neg ? '-' : '+');
                (void)putchar('i');
                (void)putchar('n');
                (void)putchar('f');
                count += 4;
                break;
            }
            ip = (unsigned long long)v;
            frac = (unsigned long long)((v - (double)ip) * 1e6 + 0.5);
            if (frac >= 1000000u) {
                ip++;
                frac -= 1000000u;
            }
            count += rv32_put_uint(ip, 10u, 0, 0, ' ', 0, neg);
            (void)putchar('.');
            count += 1 + rv32_put_uint(frac, 10u, 0, 6, '0', 0, 0);
            break;
        }
        case '%':
            (void)putchar('%');
            count++;
            break;
        default: /* unknown conversion: show it rather than guess its argument */
            (void)putchar('%');
            (void)putchar(*fmt);
            count += 2;
            if (*fmt == '\0') {
                return count;
            }
            break;
        }
    }
    return count;
}

int printf(const char *fmt, ...)
{
    va_list ap;
    int n;
    va_start(ap, fmt);
    n = vprintf(fmt, ap);
    va_end(ap);
    return n;
}

/* Weak: the board replaces it to print the stack report before exiting. */
__attribute__((weak)) void rv32_exit_hooks(void)
{
}

void rv32_exit_now(int status)
{
    (void)fflush(stdout);
    (void)rv32_semihost(SEMIHOST_SYS_EXIT,
                        (const void *)(uintptr_t)(status == 0 ? SEMIHOST_ADP_APPLICATION_EXIT
                                                              : SEMIHOST_ADP_RUNTIME_ERROR));
    for (;;) {
    }
}

void exit(int status)
{
    rv32_exit_hooks();
    rv32_exit_now(status);
}

void abort(void)
{
    rv32_exit_now(1);
}
