/*
 * mem.c - memcpy, memset, memmove, memcmp for the freestanding images (see rt.h).
 *
 * Byte loops on purpose: the firmware copies small structs (tens of bytes), so a word-at-a-time
 * version would cost flash (the M0+ budget is 64 KiB) for no measurable gain. The module is
 * compiled with -fno-tree-loop-distribute-patterns (cmake/inclino.cmake), without which gcc
 * would turn these very loops back into calls to memcpy/memset: infinite recursion.
 *
 * INC_RT_NAME lets tests/hal_rt (test hal_rt_mem, through tests/hal_rt/mem_renamed.c) compile
 * this file as rt_memcpy, rt_memset, rt_memmove and rt_memcmp, so the same code is tested on the
 * host, under QEMU on Cortex-M and on rv32, next to the C library's own functions.
 */
#include <stddef.h>
#include <stdint.h>

#ifndef INC_RT_NAME
#define INC_RT_NAME(name) name
#endif

void *INC_RT_NAME(memcpy)(void *restrict dst, const void *restrict src, size_t n);
void *INC_RT_NAME(memset)(void *dst, int c, size_t n);
void *INC_RT_NAME(memmove)(void *dst, const void *src, size_t n);
int INC_RT_NAME(memcmp)(const void *a, const void *b, size_t n);

void *INC_RT_NAME(memcpy)(void *restrict dst, const void *restrict src, size_t n)
{
    unsigned char *d = dst;
    const unsigned char *s = src;
    while (n-- > 0u) {
        *d++ = *s++;
    }
    return dst;
}

void *INC_RT_NAME(memset)(void *dst, int c, size_t n)
{
    unsigned char *d = dst;
    while (n-- > 0u) {
        *d++ = (unsigned char)c;
    }
    return dst;
}

void *INC_RT_NAME(memmove)(void *dst, const void *src, size_t n)
{
    unsigned char *d = dst;
    const unsigned char *s = src;
    /* Relational comparison of unrelated pointers is undefined in C; compare addresses. */
    if ((uintptr_t)d <= (uintptr_t)s || (uintptr_t)d >= (uintptr_t)s + n) {
        while (n-- > 0u) {
            *d++ = *s++;
        }
    } else {
        /* dst overlaps the tail of src: copy backwards. */
        d += n;
        s += n;
        while (n-- > 0u) {
            *--d = *--s;
        }
    }
    return dst;
}

int INC_RT_NAME(memcmp)(const void *a, const void *b, size_t n)
{
    const unsigned char *p = a;
    const unsigned char *q = b;
    for (; n > 0u; n--, p++, q++) {
        if (*p != *q) {
            return (int)*p - (int)*q;
        }
    }
    return 0;
}
