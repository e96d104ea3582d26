/*
 * test_hal_rt_mem.c - the run-time's memcpy, memset, memmove and memcmp (hal/rt/mem.c), compiled
 * under other names (mem_renamed.c), against a reference written here with indices: every length
 * 0..MAXN at every source and destination offset 0..7, overlapping moves in both directions, and
 * memcmp's sign at every position of the first difference. Bytes outside the destination range
 * must not change. Runs on the host, under QEMU on Cortex-M and on rv32.
 */
#include "unit.h"

#include <stddef.h>
#include <stdint.h>

void *rt_memcpy(void *restrict dst, const void *restrict src, size_t n);
void *rt_memset(void *dst, int c, size_t n);
void *rt_memmove(void *dst, const void *src, size_t n);
int rt_memcmp(const void *a, const void *b, size_t n);

#define MAXN 40
#define OFFS 8
#define BUF (MAXN + 2 * OFFS + 8)

static unsigned char src[BUF], dst[BUF], ref[BUF];

static void fill(unsigned char *b, uint32_t seed)
{
    size_t i;
    uint32_t s = seed;
    for (i = 0; i < BUF; i++) {
        b[i] = (unsigned char)unit_rand32(&s);
    }
}

static int same(const unsigned char *a, const unsigned char *b)
{
    size_t i;
    for (i = 0; i < BUF; i++) {
        if (a[i] != b[i]) return 0;
    }
    return 1;
}

static void test_memcpy(void)
{
    size_t n, so, d0;
    unsigned bad = 0, badret = 0;
    for (n = 0; n <= MAXN; n++) {
        for (so = 0; so < OFFS; so++) {
            for (d0 = 0; d0 < OFFS; d0++) {
                size_t i;
                fill(src, 0x1234u + (uint32_t)n);
                fill(dst, 0x9876u + (uint32_t)so);
                fill(ref, 0x9876u + (uint32_t)so);
                for (i = 0; i < n; i++) {
                    ref[d0 + i] = src[so + i];
                }
                if (rt_memcpy(dst + d0, src + so, n) != dst + d0) badret++;
                if (!same(dst, ref)) bad++;
            }
        }
    }
    CHECK_EQ_INT(bad, 0);
    CHECK_EQ_INT(badret, 0);
}

static void test_memset(void)
{
    static const int values[] = {0, 1, 0x7F, 0x80, 0xFF, -1, 0x1A5, -200};
    size_t n, d0, v;
    unsigned bad = 0, badret = 0;
    for (v = 0; v < sizeof values / sizeof values[0]; v++) {
        for (n = 0; n <= MAXN; n++) {
            for (d0 = 0; d0 < OFFS; d0++) {
                size_t i;
                fill(dst, 0x5555u + (uint32_t)n);
                fill(ref, 0x5555u + (uint32_t)n);
                for (i = 0; i < n; i++) {
                    ref[d0 + i] = (unsigned char)values[v]; /* converted to unsigned char */
                }
                if (rt_memset(dst + d0, values[v], n) != dst + d0) badret++;
                if (!same(dst, ref)) bad++;
            }
        }
    }
    CHECK_EQ_INT(bad, 0);
    CHECK_EQ_INT(badret, 0);
}

/* memmove within one buffer, source and destination anywhere in [0, 2 * OFFS), so every overlap
 * (forward, backward, equal, disjoint) occurs. */
static void test_memmove(void)
{
    size_t n, so, d0;
    unsigned bad = 0, badret = 0;
    unsigned char tmp[BUF];
    for (n = 0; n <= MAXN; n++) {
        for (so = 0; so < 2 * OFFS; so++) {
            for (d0 = 0; d0 < 2 * OFFS; d0++) {
                size_t i;
                fill(dst, 0xABCDu + (uint32_t)(n * 31u + so));
                fill(ref, 0xABCDu + (uint32_t)(n * 31u + so));
                for (i = 0; i < n; i++) {
                    tmp[i] = ref[so + i];
                }
                for (i = 0; i < n; i++) {
                    ref[d0 + i] = tmp[i];
                }
                if (rt_memmove(dst + d0, dst + so, n) != dst + d0) badret++;
                if (!same(dst, ref)) bad++;
            }
        }
    }
    CHECK_EQ_INT(bad, 0);
    CHECK_EQ_INT(badret, 0);
}

static int sign(int v)
{
    return (v > 0) - (v < 0);
}

static void test_memcmp(void)
{
    size_t n, at;
    unsigned bad = 0;
    CHECK_EQ_INT(rt_memcmp(src, dst, 0), 0);
    for (n = 1; n <= MAXN; n++) {
        fill(src, 0x3141u + (uint32_t)n);
        rt_memcpy(dst, src, BUF);
        if (rt_memcmp(src, dst, n) != 0) bad++;
        for (at = 0; at < n; at++) {
            const unsigned char keep = dst[at];
            /* a larger byte in b, then a smaller one, then the bytes 0x00 against 0xFF: the
             * comparison is of unsigned chars */
            dst[at] = (unsigned char)(keep + 1u);
            if (sign(rt_memcmp(src, dst, n)) != (keep == 0xFFu ? 1 : -1)) bad++;
            if (sign(rt_memcmp(dst, src, n)) != (keep == 0xFFu ? -1 : 1)) bad++;
            /* a difference after the first n bytes is not seen */
            if (at + 1u < n && rt_memcmp(src, dst, at) != 0) bad++;
            dst[at] = keep;
        }
    }
    src[0] = 0x00;
    dst[0] = 0xFF;
    CHECK(rt_memcmp(src, dst, 1) < 0);
    CHECK(rt_memcmp(dst, src, 1) > 0);
    CHECK_EQ_INT(rt_memcmp(dst, src, 1), 0xFF);
    CHECK_EQ_INT(bad, 0);
}

int main(void)
{
    UNIT_RUN(test_memcpy);
    UNIT_RUN(test_memset);
    UNIT_RUN(test_memmove);
    UNIT_RUN(test_memcmp);
    return unit_report();
}
