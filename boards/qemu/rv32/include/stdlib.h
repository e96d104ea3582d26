/* stdlib.h - rv32 test shim (see stdio.h): exit and abort only; no heap. */
#ifndef INCLINO_RV32_STDLIB_H
#define INCLINO_RV32_STDLIB_H

#include <stddef.h>

#define EXIT_SUCCESS 0
#define EXIT_FAILURE 1

__attribute__((noreturn)) void exit(int status);
__attribute__((noreturn)) void abort(void);

#endif /* INCLINO_RV32_STDLIB_H */
