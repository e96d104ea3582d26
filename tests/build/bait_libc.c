/*
 * Deliberately breaks the freestanding rules, for the self-test of the no-libc check only: it is
 * never part of a module or an image. It references malloc and printf; the check must report
 * both.
 */
#include <stddef.h>

void *malloc(size_t size);
int printf(const char *fmt, ...);
void *bait_libc_alloc(size_t n);

void *bait_libc_alloc(size_t n)
{
    (void)printf("%u\n", (unsigned)n);
    return malloc(n);
}
