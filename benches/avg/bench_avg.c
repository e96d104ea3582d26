/*
 * Host benchmark driver for callgrind instruction counts of the averaging filters and the
 * stillness detector (benches/avg/bench_avg.sh). `bench_avg <case>` runs BENCH_N samples through
 * one filter; callgrind counts only the named push function, so the count per call is the cost
 * per sample. Not a test: it checks nothing (the tests are test_avg / test_still).
 */
#include <stdio.h>
#include <string.h>

#include "inclino/avg.h"
#include "inclino/still.h"
#include "bench_avg_cfg.h"

#define BENCH_N 100000u

static uint32_t lcg = 12345u;
static int32_t next(void)
{
    lcg = lcg * 1664525u + 1013904223u;
    return (int32_t)(lcg >> 18) - 8192; /* 14-bit counts */
}

static volatile int32_t sink;

int main(int argc, char **argv)
{
    static int32_t line[1024];
    static int64_t lines[4 * 64];
    static struct avg_bartlett bt;
    struct avg_block b;
    struct avg_moving m;
    struct avg_cascade c;
    struct still s;
    struct still_thermal th;
    const char *k = argc > 1 ? argv[1] : "";
    uint32_t i;
    int32_t y = 0;
    bool f = false, r = false;
    if (strcmp(k, "block") == 0) {
        (void)avg_block_init(&b, 1024);
        for (i = 0; i < BENCH_N; i++) {
            (void)avg_block_push(&b, next(), &y, &f);
        }
    } else if (strcmp(k, "moving64") == 0 || strcmp(k, "moving50") == 0) {
        (void)avg_moving_init(&m, line, 1024, k[6] == '6' ? 64u : 50u);
        for (i = 0; i < BENCH_N; i++) {
            (void)avg_moving_push(&m, next(), &y, &f);
        }
    } else if (strcmp(k, "cascade16x4") == 0 || strcmp(k, "cascade10x2") == 0) {
        if (k[7] == '1' && k[8] == '6') {
            (void)avg_cascade_init(&c, lines, 4 * 64, 16, 4);
        } else {
            (void)avg_cascade_init(&c, lines, 4 * 64, 10, 2);
        }
        for (i = 0; i < BENCH_N; i++) {
            (void)avg_cascade_push(&c, next(), &y, &f);
        }
    } else if (strcmp(k, "bartlett6d1") == 0 || strcmp(k, "bartlett4d16") == 0) {
        if (k[8] == '6') {
            (void)avg_bartlett_init(&bt, 6, 1);
        } else {
            (void)avg_bartlett_init(&bt, 4, 16);
        }
        for (i = 0; i < BENCH_N; i++) {
            (void)avg_bartlett_push(&bt, next(), &y, &r, &f);
        }
    } else if (strcmp(k, "still") == 0) {
        struct still_cfg cfg;
        bench_still_cfg(&cfg);
        (void)still_init(&s, &cfg);
        for (i = 0; i < BENCH_N; i++) {
            const int32_t g[3] = {next() >> 6, next() >> 6, next() >> 6};
            const int32_t a[3] = {next() >> 8, next() >> 8, 1000 + (next() >> 8)};
            (void)still_push(&s, g, a, &f);
        }
    } else if (strcmp(k, "thermal") == 0) {
        (void)still_thermal_init(&th, &bench_thermal_cfg);
        for (i = 0; i < BENCH_N; i++) {
            (void)still_thermal_push(&th, next() >> 10, &f);
        }
    } else {
        fprintf(stderr, "usage: bench_avg block|moving64|moving50|cascade16x4|cascade10x2|"
                        "bartlett6d1|bartlett4d16|still|thermal\n");
        return 1;
    }
    sink = y;
    return 0;
}
