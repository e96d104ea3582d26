/*
 * Averaging filters (firmware/signal/avg): rejected lengths, exact outputs against brute-force
 * references written independently (integer rounding ties away from zero), exact kernels from
 * impulse responses, no overflow at the extremes of int32 and at the longest lengths, and the
 * noise law: on white noise the output rms is sigma * sqrt(sum h^2) (1/sqrt(N) for N-sample
 * averages) within 5 %.
 *
 * Runs on the host and under QEMU. Where UNIT_REDUCED (QEMU, sanitizers) the long-noise runs use fewer samples (QEMU is
 * about 30 times slower); the tolerances stay the same (5 %), still 4.3 sigma of the estimate.
 */
#include "inclino/avg.h"
#include "inclino/sim/inertial.h"
#include "unit.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#if UNIT_REDUCED
#define NOISE_K 2500u /* independent outputs per rms estimate: rel. sd 1.4 % */
#else
#define NOISE_K 7200u /* rel. sd 0.83 % */
#endif

/* Reference rounding: round(num / den), den > 0, ties away from zero, from the definition. */
static int64_t ref_div(int64_t num, int64_t den)
{
    const int64_t mag = num < 0 ? -num : num;
    const int64_t q = (2 * mag + den) / (2 * den);
    return num < 0 ? -q : q;
}

/* Deterministic test signals. */
static struct sim_rng rng;

static int32_t rnd_full(void)
{
    return (int32_t)sim_rng_u32(&rng);
}

/* White noise, integer only: sum of four uniform 12-bit values, centred: mean 0, variance
 * 4 (4096^2 - 1) / 12 exactly. */
#define NOISE_VAR (4.0 * (4096.0 * 4096.0 - 1.0) / 12.0)
static int32_t noise(void)
{
    int32_t s = 0;
    int i;
    for (i = 0; i < 4; i++) {
        s += (int32_t)(sim_rng_u32(&rng) >> 20);
    }
    return s - 8190;
}

static void test_init_rejects(void)
{
    struct avg_block b;
    struct avg_moving m;
    struct avg_cascade c;
    struct avg_bartlett bt;
    static int32_t line[16];
    static int64_t lines[64];
    int32_t y = 0;
    uint32_t cnt = 0;
    bool f = false, r = false;
    CHECK_ERR(avg_block_init(&b, 0), INC_ERR_INVAL);
    CHECK_ERR(avg_block_push(&b, 1, &y, &f), INC_ERR_STATE); /* failed init: refuses */
    CHECK_ERR(avg_block_init(&b, 0x80000001u), INC_ERR_OVERFLOW);
    CHECK_ERR(avg_block_init(&b, UINT32_MAX), INC_ERR_OVERFLOW);
    CHECK_OK(avg_block_init(&b, 0x80000000u));
    CHECK_OK(avg_block_init(&b, 1u << 17));
    CHECK_ERR(avg_block_init(NULL, 4), INC_ERR_NULL);
    CHECK_ERR(avg_block_partial(&b, &y, &cnt), INC_ERR_STATE); /* empty */

    CHECK_ERR(avg_moving_init(&m, line, 16, 0), INC_ERR_INVAL);
    CHECK_ERR(avg_moving_push(&m, 1, &y, &f), INC_ERR_STATE);
    CHECK_ERR(avg_moving_init(&m, line, 16, 17), INC_ERR_INVAL);
    CHECK_ERR(avg_moving_init(&m, line, UINT32_MAX, 0x80000001u), INC_ERR_OVERFLOW);
    CHECK_ERR(avg_moving_init(&m, NULL, 16, 4), INC_ERR_NULL);
    CHECK_OK(avg_moving_init(&m, line, 16, 16));

    CHECK_ERR(avg_cascade_init(&c, lines, 64, 4, 0), INC_ERR_INVAL);
    CHECK_ERR(avg_cascade_push(&c, 1, &y, &f), INC_ERR_STATE);
    CHECK_ERR(avg_cascade_init(&c, lines, 64, 4, 5), INC_ERR_INVAL);
    CHECK_ERR(avg_cascade_init(&c, lines, 64, 0, 2), INC_ERR_INVAL);
    CHECK_ERR(avg_cascade_init(&c, lines, 64, 17, 4), INC_ERR_INVAL);     /* 68 > 64 entries */
    CHECK_ERR(avg_cascade_init(&c, lines, 64, 216, 4), INC_ERR_OVERFLOW); /* 216^4 > 2^31 */
    CHECK_ERR(avg_cascade_init(&c, lines, 64, 46341, 2), INC_ERR_OVERFLOW);
    CHECK_ERR(avg_cascade_init(&c, lines, 64, 1291, 3), INC_ERR_OVERFLOW);
    CHECK_ERR(avg_cascade_init(&c, lines, 64, UINT32_MAX, 4), INC_ERR_OVERFLOW);
    CHECK_ERR(avg_cascade_init(&c, NULL, 64, 4, 2), INC_ERR_NULL);
    CHECK_OK(avg_cascade_init(&c, lines, 64, 16, 4));
    CHECK_EQ_INT(avg_cascade_taps(&c), 61);

    CHECK_ERR(avg_bartlett_init(&bt, 7, 2), INC_ERR_INVAL); /* SENS_AVG code 7: not valid */
    CHECK_ERR(avg_bartlett_push(&bt, 1, &y, &r, &f), INC_ERR_STATE);
    CHECK_ERR(avg_bartlett_init(&bt, 4, 0), INC_ERR_INVAL);
    CHECK_ERR(avg_bartlett_init(&bt, 4, 17), INC_ERR_INVAL); /* d > N = 16 would alias */
    CHECK_OK(avg_bartlett_init(&bt, 4, 16));
    CHECK_OK(avg_bartlett_init(&bt, 0, 1));
    CHECK_ERR(avg_bartlett_init(&bt, 0, 2), INC_ERR_INVAL);
}

static void test_block_exact(void)
{
    struct avg_block b;
    int32_t mean = 0;
    bool done = false;
    uint32_t i, cnt = 0;
    /* ties away from zero, odd symmetry */
    REQUIRE(avg_block_init(&b, 2) == INC_OK);
    CHECK_OK(avg_block_push(&b, 1, &mean, &done));
    CHECK(!done);
    CHECK_OK(avg_block_push(&b, 2, &mean, &done));
    CHECK(done);
    CHECK_EQ_INT(mean, 2);
    CHECK_OK(avg_block_push(&b, -1, &mean, &done));
    CHECK_OK(avg_block_push(&b, -2, &mean, &done));
    CHECK_EQ_INT(mean, -2);
    CHECK_OK(avg_block_push(&b, -1, &mean, &done));
    CHECK_OK(avg_block_push(&b, 2, &mean, &done));
    CHECK_EQ_INT(mean, 1);
    /* 2^17 samples at the int32 extremes: no overflow, exact */
    REQUIRE(avg_block_init(&b, 1u << 17) == INC_OK);
    for (i = 0; i < (1u << 17); i++) {
        CHECK_OK(avg_block_push(&b, INT32_MAX, &mean, &done));
    }
    CHECK(done);
    CHECK_EQ_INT(mean, INT32_MAX);
    for (i = 0; i < (1u << 17); i++) {
        CHECK_OK(avg_block_push(&b, INT32_MIN, &mean, &done));
    }
    CHECK_EQ_INT(mean, INT32_MIN);
    /* [ADI-IMU-QS]'s manual calibration length, random full-range samples, against the reference */
    {
        int64_t sum = 0;
        sim_rng_seed(&rng, 1);
        REQUIRE(avg_block_init(&b, 82000) == INC_OK);
        for (i = 0; i < 82000u; i++) {
            const int32_t x = rnd_full();
            sum += x;
            CHECK_OK(avg_block_push(&b, x, &mean, &done));
            if (i == 40000u) {
                int32_t pm = 0;
                CHECK_OK(avg_block_partial(&b, &pm, &cnt));
                CHECK_EQ_INT(cnt, 40001);
                CHECK_EQ_INT(pm, ref_div(sum, 40001));
            }
        }
        CHECK(done);
        CHECK_EQ_INT(mean, ref_div(sum, 82000));
    }
    /* partial and restart */
    REQUIRE(avg_block_init(&b, 10) == INC_OK);
    CHECK_OK(avg_block_push(&b, 7, &mean, &done));
    CHECK_OK(avg_block_push(&b, 8, &mean, &done));
    CHECK_OK(avg_block_partial(&b, &mean, &cnt));
    CHECK_EQ_INT(mean, 8); /* 7.5 -> 8 */
    CHECK_EQ_INT(cnt, 2);
    avg_block_restart(&b);
    CHECK_ERR(avg_block_partial(&b, &mean, &cnt), INC_ERR_STATE);
}

/* Moving average against a brute-force mean of the last min(n, W) inputs. */
static void check_moving(uint32_t w, uint32_t n, bool extremes)
{
    static int32_t line[64], hist[4096];
    struct avg_moving m;
    uint32_t i, j, bad = 0;
    REQUIRE(w <= 64u && n <= 4096u);
    REQUIRE(avg_moving_init(&m, line, 64, w) == INC_OK);
    for (i = 0; i < n; i++) {
        int32_t y = 0;
        bool full = false;
        int64_t sum = 0;
        const uint32_t k = i + 1u < w ? i + 1u : w;
        hist[i] = extremes ? ((i / 3u) % 2u ? INT32_MIN : INT32_MAX) : rnd_full();
        CHECK_OK(avg_moving_push(&m, hist[i], &y, &full));
        for (j = 0; j < k; j++) {
            sum += hist[i - j];
        }
        if (y != ref_div(sum, k) || full != (k == w)) {
            bad++;
        }
    }
    CHECK_EQ_INT(bad, 0);
}

static void test_moving_exact(void)
{
    static int32_t line[8];
    struct avg_moving m;
    int32_t y = 0;
    bool full = true;
    uint32_t i;
    sim_rng_seed(&rng, 2);
    check_moving(1, 100, false);
    check_moving(16, 4096, false); /* power of two: shift path */
    check_moving(13, 4096, false); /* division path */
    check_moving(64, 4096, true);
    check_moving(7, 1000, true);
    /* warm-up and restart; the running sum never drifts over a long run */
    REQUIRE(avg_moving_init(&m, line, 8, 3) == INC_OK);
    CHECK_OK(avg_moving_push(&m, 3, &y, &full));
    CHECK_EQ_INT(y, 3);
    CHECK(!full);
    CHECK_OK(avg_moving_push(&m, 4, &y, &full));
    CHECK_EQ_INT(y, 4); /* 3.5 */
    for (i = 0; i < 200000u; i++) {
        CHECK_OK(avg_moving_push(&m, (int32_t)(i % 1000u) - 500, &y, &full));
    }
    CHECK(full);
    /* the last three inputs: 497, 498, 499 */
    CHECK_EQ_INT(y, 498);
    avg_moving_restart(&m);
    CHECK_OK(avg_moving_push(&m, -5, &y, &full));
    CHECK_EQ_INT(y, -5);
    CHECK(!full);
}

/* h_P: the P-fold convolution of W ones (length P (W - 1) + 1). */
static uint32_t kernel(uint32_t w, unsigned p, int64_t *h)
{
    uint32_t len = w, i, j;
    unsigned k;
    for (i = 0; i < w; i++) {
        h[i] = 1;
    }
    for (k = 1; k < p; k++) {
        int64_t t[1024] = {0};
        const uint32_t nl = len + w - 1u;
        for (i = 0; i < nl; i++) {
            for (j = 0; j < w; j++) {
                if (i >= j && i - j < len) {
                    t[i] += h[i - j];
                }
            }
        }
        memcpy(h, t, nl * sizeof(*h));
        len = nl;
    }
    return len;
}

static void test_cascade_kernel(void)
{
    static int64_t lines[4 * 64], h[1024];
    static int32_t hist[2048];
    const uint32_t ws[3] = {5, 4, 1};
    unsigned wi, p;
    for (wi = 0; wi < 3u; wi++) {
        for (p = 1; p <= 4u; p++) {
            struct avg_cascade c;
            const uint32_t w = ws[wi];
            const uint32_t len = kernel(w, p, h);
            int64_t div = 1;
            uint32_t i, j, bad = 0;
            unsigned k;
            int32_t y = 0;
            bool full = true;
            for (k = 0; k < p; k++) {
                div *= w;
            }
            REQUIRE(avg_cascade_init(&c, lines, 4 * 64, w, p) == INC_OK);
            CHECK_EQ_INT(avg_cascade_taps(&c), len);
            /* zeros, then an impulse of W^P: each output is one kernel tap exactly */
            CHECK_OK(avg_cascade_push(&c, 0, &y, &full));
            CHECK_EQ_INT(full, len == 1u);
            CHECK_OK(avg_cascade_push(&c, (int32_t)div, &y, &full));
            CHECK_EQ_INT(y, h[0]);
            for (i = 1; i < len + 3u; i++) {
                CHECK_OK(avg_cascade_push(&c, 0, &y, &full));
                if (y != (i < len ? h[i] : 0)) {
                    bad++;
                }
            }
            CHECK_EQ_INT(bad, 0);
            CHECK(full);
            /* random full-range data against the brute-force convolution (history before the
             * first sample = the first sample) */
            avg_cascade_restart(&c);
            sim_rng_seed(&rng, 3u + p);
            for (i = 0; i < 2048u; i++) {
                int64_t acc = 0;
                hist[i] = rnd_full();
                CHECK_OK(avg_cascade_push(&c, hist[i], &y, &full));
                for (j = 0; j < len; j++) {
                    acc += h[j] * (int64_t)(j <= i ? hist[i - j] : hist[0]);
                }
                if (y != ref_div(acc, div) || full != (i + 1u >= len)) {
                    bad++;
                }
            }
            CHECK_EQ_INT(bad, 0);
        }
    }
}

static void test_cascade_extremes(void)
{
    static int64_t lines[4 * 215];
    struct avg_cascade c;
    int32_t y = 0;
    bool full = false;
    uint32_t i, bad = 0;
    /* the largest P = 4 window (215^4 = 2.137e9), square wave at the extremes (UBSan watches) */
    REQUIRE(avg_cascade_init(&c, lines, 4 * 215, 215, 4) == INC_OK);
    for (i = 0; i < 3000u; i++) {
        const int32_t x = (i / 400u) % 2u ? INT32_MIN : INT32_MAX;
        CHECK_OK(avg_cascade_push(&c, x, &y, &full));
        if (i < 400u && y != INT32_MAX) {
            bad++; /* primed with the first sample: a constant passes unchanged */
        }
    }
    CHECK_EQ_INT(bad, 0);
    for (i = 0; i < 900u; i++) {
        CHECK_OK(avg_cascade_push(&c, INT32_MIN, &y, &full));
    }
    CHECK_EQ_INT(y, INT32_MIN);
    CHECK(full);
}

/* The Bartlett decimator is exactly a two-pass cascade of N = 2^M, read every d-th sample. */
static void test_bartlett(void)
{
    static int64_t lines[2 * 64];
    unsigned m;
    for (m = 0; m <= AVG_BARTLETT_MAX_M; m++) {
        const uint32_t n = 1u << m;
        uint32_t d;
        for (d = 1; d <= n; d = d < 3u ? d + 1u : d * 2u + 1u) {
            static struct avg_bartlett b;
            struct avg_cascade c;
            uint32_t i, outs = 0, bad = 0;
            sim_rng_seed(&rng, 100u + m);
            REQUIRE(avg_bartlett_init(&b, m, d) == INC_OK);
            REQUIRE(avg_cascade_init(&c, lines, 2 * 64, n, 2) == INC_OK);
            for (i = 0; i < 1000u; i++) {
                const int32_t x = rnd_full();
                int32_t yb = 0, yc = 0;
                bool ready = false, fb = false, fc = false;
                CHECK_OK(avg_bartlett_push(&b, x, &yb, &ready, &fb));
                CHECK_OK(avg_cascade_push(&c, x, &yc, &fc));
                if (ready != ((i + 1u) % d == 0u) || fb != fc || (ready && yb != yc)) {
                    bad++;
                }
                outs += ready;
            }
            CHECK_EQ_INT(bad, 0);
            CHECK_EQ_INT(outs, 1000u / d);
        }
    }
    /* triangle taps for M = 2 (N = 4): 1 2 3 4 3 2 1, impulse of N^2 = 16 */
    {
        static struct avg_bartlett b;
        const int32_t tri[9] = {1, 2, 3, 4, 3, 2, 1, 0, 0};
        int32_t y = -1;
        bool ready = false;
        unsigned i;
        REQUIRE(avg_bartlett_init(&b, 2, 1) == INC_OK);
        CHECK_OK(avg_bartlett_push(&b, 0, &y, &ready, NULL));
        CHECK_OK(avg_bartlett_push(&b, 16, &y, &ready, NULL));
        CHECK_EQ_INT(y, 1);
        for (i = 1; i < 9u; i++) {
            CHECK_OK(avg_bartlett_push(&b, 0, &y, &ready, NULL));
            CHECK_EQ_INT(y, tri[i]);
        }
        /* the extremes over the longest filter */
        REQUIRE(avg_bartlett_init(&b, 6, 64) == INC_OK);
        for (i = 0; i < 640u; i++) {
            CHECK_OK(avg_bartlett_push(&b, INT32_MIN, &y, &ready, NULL));
        }
        CHECK_EQ_INT(y, INT32_MIN);
        avg_bartlett_restart(&b);
        for (i = 0; i < 640u; i++) {
            CHECK_OK(
                avg_bartlett_push(&b, (i / 50u) % 2u ? INT32_MIN : INT32_MAX, &y, &ready, NULL));
        }
    }
}

/* ---- noise ------------------------------------------------------------------------------- */

/* rms of the output of one filter on NOISE_K independent outputs (every `stride`-th after the
 * first `skip`), against sigma * sqrt(gain2) (+ 1/12 LSB^2 for the output rounding). */
enum kind { BLOCK, MOVING, CASCADE, BARTLETT };

static double measure(enum kind kd, uint32_t n, unsigned p, uint32_t *stride_out)
{
    static int32_t line[1024];
    static int64_t lines[4 * 256];
    static struct avg_bartlett bt;
    struct avg_block b;
    struct avg_moving mv;
    struct avg_cascade c;
    uint32_t taps = n, got = 0, since = 0;
    double s2 = 0.0;
    int ok;
    switch (kd) {
    case BLOCK: ok = avg_block_init(&b, n); break;
    case MOVING: ok = avg_moving_init(&mv, line, 1024, n); break;
    case CASCADE:
        ok = avg_cascade_init(&c, lines, 4 * 256, n, p);
        taps = avg_cascade_taps(&c);
        break;
    default:
        ok = avg_bartlett_init(&bt, p, 1u << p); /* p = M here, d = N */
        taps = 2u * (1u << p) - 1u;
        break;
    }
    if (ok != INC_OK) {
        return -1.0;
    }
    *stride_out = taps;
    while (got < NOISE_K) {
        const int32_t x = noise();
        int32_t y = 0;
        bool out = false, full = true;
        switch (kd) {
        case BLOCK: (void)avg_block_push(&b, x, &y, &out); break;
        case MOVING:
            (void)avg_moving_push(&mv, x, &y, &full);
            out = true;
            break;
        case CASCADE:
            (void)avg_cascade_push(&c, x, &y, &full);
            out = true;
            break;
        default: (void)avg_bartlett_push(&bt, x, &y, &out, &full); break;
        }
        if (!out || !full) {
            continue;
        }
        /* keep outputs whose windows do not overlap */
        if (kd == MOVING || kd == CASCADE || kd == BARTLETT) {
            since++;
            if (kd == BARTLETT) {
                since += (1u << p) - 1u; /* one output per N inputs */
            }
            if (since < taps) {
                continue;
            }
            since = 0;
        }
        s2 += (double)y * (double)y;
        got++;
    }
    return sqrt(s2 / (double)NOISE_K);
}

static double gain2(uint32_t w, unsigned p)
{
    static int64_t h[1024];
    const uint32_t len = kernel(w, p, h);
    double s = 0.0, d = 1.0;
    uint32_t i;
    unsigned k;
    for (k = 0; k < p; k++) {
        d *= w;
    }
    for (i = 0; i < len; i++) {
        s += (double)h[i] * (double)h[i];
    }
    return s / (d * d);
}

static void test_noise_law(void)
{
#if UNIT_REDUCED
    const uint32_t ns[] = {4, 16, 64};
#else
    const uint32_t ns[] = {4, 16, 64, 256, 1024};
#endif
    const double sigma = sqrt(NOISE_VAR);
    unsigned i, p;
    uint32_t stride;
    sim_rng_seed(&rng, 77);
    for (i = 0; i < sizeof(ns) / sizeof(ns[0]); i++) {
        const double want = sqrt(NOISE_VAR / ns[i] + 1.0 / 12.0);
        const double rb = measure(BLOCK, ns[i], 0, &stride);
        const double rm = measure(MOVING, ns[i], 0, &stride);
        printf("  N %4u: block rms %.2f, moving rms %.2f, sigma/sqrt(N) %.2f\n", (unsigned)ns[i],
               rb, rm, sigma / sqrt((double)ns[i]));
        CHECK_NEAR(rb, want, 0.05 * want);
        CHECK_NEAR(rm, want, 0.05 * want);
    }
    /* cascades of W = 8, 1..4 passes: rms = sigma sqrt(sum h^2) */
    for (p = 1; p <= 4u; p++) {
        const double want = sqrt(NOISE_VAR * gain2(8, p) + 1.0 / 12.0);
        const double r = measure(CASCADE, 8, p, &stride);
        printf("  cascade W 8 P %u: rms %.2f, want %.2f (N_eq %.1f)\n", p, r, want,
               1.0 / gain2(8, p));
        CHECK_NEAR(r, want, 0.05 * want);
    }
    /* Bartlett M = 3, 5: rms = sigma sqrt((2N^2 + 1) / (3N^3)) */
    for (p = 3; p <= 5u; p += 2u) {
        const double nn = (double)(1u << p);
        const double g = (2.0 * nn * nn + 1.0) / (3.0 * nn * nn * nn);
        const double want = sqrt(NOISE_VAR * g + 1.0 / 12.0);
        const double r = measure(BARTLETT, 0, p, &stride);
        CHECK_NEAR(g, gain2(1u << p, 2), 1e-12);
        printf("  Bartlett M %u: rms %.2f, want %.2f\n", p, r, want);
        CHECK_NEAR(r, want, 0.05 * want);
    }
}

int main(void)
{
    UNIT_RUN(test_init_rejects);
    UNIT_RUN(test_block_exact);
    UNIT_RUN(test_moving_exact);
    UNIT_RUN(test_cascade_kernel);
    UNIT_RUN(test_cascade_extremes);
    UNIT_RUN(test_bartlett);
    UNIT_RUN(test_noise_law);
    return unit_report();
}
