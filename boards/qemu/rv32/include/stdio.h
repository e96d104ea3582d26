/*
 * stdio.h - the rv32 test board's C-library shim (no C library exists for Debian's
 * riscv64-unknown-elf-gcc). Just enough for tests/support/unit.c and simple tests: printf and
 * vprintf to the semihosting console. Conversions: %d %i %u %x %X %c %s %p %% with the l, ll, z,
 * h, hh modifiers, width, '-' and '0'; %f %g %e print a fixed "[+-]int.frac6" form.
 */
#ifndef INCLINO_RV32_STDIO_H
#define INCLINO_RV32_STDIO_H

#include <stdarg.h>
#include <stddef.h>

typedef struct rv32_file FILE;
extern FILE *const stdout;
extern FILE *const stderr;

int printf(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
int vprintf(const char *fmt, va_list ap) __attribute__((format(printf, 1, 0)));
int fflush(FILE *f);
int putchar(int c);
int puts(const char *s);

#endif /* INCLINO_RV32_STDIO_H */
