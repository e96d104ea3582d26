/*
 * SCA3000 golden traces (docs/traces.md): the driver's init and read sequences, recorded from the
 * model, are replayed to the driver without any model or board. The replay checks every MOSI
 * word and the CS-period shape; this test also checks the values the driver decodes from the
 * recorded MISO words, and that a changed driver behaviour is caught.
 *
 *   test_sca3000_golden               replay the traces in tests/sca3000/golden (CTest: host, QEMU)
 *   test_sca3000_golden --regenerate  record them again from the model (review the diff: the
 *                                     trace is the driver's bus contract)
 */
#include "fixture.h"
#include "inclino/sim/golden.h"

#include <stdio.h>
#include <string.h>

#ifndef GOLDEN_DIR
#error "GOLDEN_DIR must be defined"
#endif

static struct trace_replay rp;

struct results {
    int err;
    uint8_t revid;
    int16_t xyz[3];
    int16_t xyz2[3];
    uint16_t temp;
    size_t ring_n;
    int16_t ring[SCA3000_RING_CAPACITY];
    uint8_t int_status;
};
static struct results got;

#define TRY(expr)                \
    do {                         \
        r->err = (expr);         \
        if (r->err != 0) return; \
    } while (0)

/* D01: init, one full sample (X/Y/Z + temperature), option 1 (bypass), X/Y/Z again. */
static void seq_d01(struct results *r)
{
    struct sca3000_sample s;
    TRY(sca3000_init(&fx.dev, &fx.cfg));
    r->revid = sca3000_revid(&fx.dev);
    hal_delay_ms(fx.cfg.hal, 11);
    TRY(sca3000_read_sample(&fx.dev, &s));
    memcpy(r->xyz, s.xyz, sizeof(r->xyz));
    r->temp = s.temp_raw;
    TRY(sca3000_set_mode(&fx.dev, SCA3000_MODE_OPTION1));
    hal_delay_ms(fx.cfg.hal, 5);
    TRY(sca3000_read_accel(&fx.dev, r->xyz2));
}

/* E04: init, X/Y/Z, option 2 (wide, 400 Hz), X/Y/Z. */
static void seq_e04(struct results *r)
{
    TRY(sca3000_init(&fx.dev, &fx.cfg));
    r->revid = sca3000_revid(&fx.dev);
    hal_delay_ms(fx.cfg.hal, 11);
    TRY(sca3000_read_accel(&fx.dev, r->xyz));
    TRY(sca3000_set_mode(&fx.dev, SCA3000_MODE_OPTION2));
    hal_delay_ms(fx.cfg.hal, 3);
    TRY(sca3000_read_accel(&fx.dev, r->xyz2));
}

/* E05 ring buffer: X/Y/Z at ODR/2, INT on 1/2 full (active high), wait for it, read it all. */
static void seq_e05_ring(struct results *r)
{
    TRY(sca3000_init(&fx.dev, &fx.cfg));
    r->revid = sca3000_revid(&fx.dev);
    TRY(sca3000_ring_config(&fx.dev, SCA3000_OUT_CTRL_X | SCA3000_OUT_CTRL_Y | SCA3000_OUT_CTRL_Z,
                            2));
    TRY(sca3000_int_config(&fx.dev, SCA3000_INT_RING_1_2, true));
    TRY(sca3000_ring_enable(&fx.dev, true));
    TRY(sca3000_wait_int(&fx.dev, hal_now_ns(fx.cfg.hal) + 1000000000u));
    TRY(sca3000_int_status(&fx.dev, &r->int_status));
    TRY(sca3000_ring_read(&fx.dev, r->ring, SCA3000_RING_CAPACITY, &r->ring_n));
    TRY(sca3000_ring_enable(&fx.dev, false));
}

struct golden {
    struct sim_golden g;
    enum sim_sca3000_variant variant;
    void (*seq)(struct results *r);
};

#define COMMENTS                                                                  \
    {                                                                             \
        "SCA3000 driver against the model (tests/sca3000/test_sca3000_golden.c)", \
            "input: 0.5, -0.25, 1.0 g, 25 degC; SCLK 500 kHz, mode 3", NULL       \
    }

static const struct golden goldens[] = {
    {{GOLDEN_DIR "/d01_init_read.trace", COMMENTS}, SIM_SCA3000_D01, seq_d01},
    {{GOLDEN_DIR "/e04_init_read.trace", COMMENTS}, SIM_SCA3000_E04, seq_e04},
    {{GOLDEN_DIR "/e05_ring.trace", COMMENTS}, SIM_SCA3000_E05, seq_e05_ring},
};

/* A sequence on the bus and HAL of the harness: the driver configured as on the board, with
 * them instead. */
static void seq(void *ctx, const struct spi_bus *bus, const struct hal *hal)
{
    const struct golden *g = ctx;
    fx.cfg.bus = bus;
    fx.cfg.hal = hal;
    memset(&got, 0, sizeof(got));
    g->seq(&got);
}

static int record(const struct golden *g)
{
    int err = fx_setup_part(g->variant, 0);
    if (err != 0) {
        return err;
    }
    fx_input(0.5, -0.25, 1.0, 25.0);
    err = sim_golden_record(&g->g, &fx.board, seq, (void *)g);
    if (got.err != 0 || err != 0) {
        printf("recording %s failed: %s\n", g->g.path, inc_err_name(got.err != 0 ? got.err : err));
        return -1;
    }
    printf("recorded %s\n", g->g.path);
    return 0;
}

/* Replay a golden trace to the driver configured as on the board (no model behind it). */
static int replay(const struct golden *g, uint8_t expected_revid)
{
    if (fx_setup_part(g->variant, 0) != 0) {
        return -100;
    }
    fx.cfg.expected_revid = expected_revid;
    return sim_golden_replay(&g->g, &rp, seq, (void *)g);
}

static void test_replay_d01(void)
{
    CHECK_OK(replay(&goldens[0], 0));
    CHECK_OK(got.err);
    CHECK_EQ_HEX(got.revid, SCA3000_REVID_DEFAULT);
    CHECK_EQ_INT(got.xyz[0], 667);
    CHECK_EQ_INT(got.xyz[1], -333);
    CHECK_EQ_INT(got.xyz[2], 1333);
    CHECK_EQ_INT(got.temp, 260);
    CHECK_EQ_INT(got.xyz2[2], 1333);
}

static void test_replay_e04(void)
{
    CHECK_OK(replay(&goldens[1], 0));
    CHECK_OK(got.err);
    CHECK_EQ_INT(got.xyz[0], 250);
    CHECK_EQ_INT(got.xyz[1], -125);
    CHECK_EQ_INT(got.xyz[2], 500);
    CHECK_EQ_INT(got.xyz2[0], 250);
}

static void test_replay_e05_ring(void)
{
    size_t i;
    CHECK_OK(replay(&goldens[2], 0));
    CHECK_OK(got.err);
    CHECK_EQ_HEX(got.int_status, SCA3000_INT_RING_1_2);
    CHECK_EQ_INT(got.ring_n, 96);
    /* E05: 80, -40, 160 counts -> 11-bit 20, -10, 40 -> x4 = 80, -40, 160. */
    for (i = 0; i + 2u < got.ring_n; i += 3u) {
        CHECK_EQ_INT(got.ring[i], 80);
        CHECK_EQ_INT(got.ring[i + 1u], -40);
        CHECK_EQ_INT(got.ring[i + 2u], 160);
    }
}

/* A driver that behaves differently is caught: one expecting another REVID stops after the
 * REVID read, and the replay reports the unconsumed rest of the trace. */
static void test_changed_driver_is_caught(void)
{
    CHECK(replay(&goldens[0], 0x33) != 0);
    CHECK_ERR(got.err, INC_ERR_ID);
    CHECK(strlen(trace_replay_message(&rp)) > 0u);
}

int main(int argc, char **argv)
{
    if (sim_golden_regenerate(argc, argv)) {
        unsigned i;
        for (i = 0; i < sizeof(goldens) / sizeof(goldens[0]); i++) {
            if (record(&goldens[i]) != 0) {
                return 1;
            }
        }
        return 0;
    }
    UNIT_RUN(test_replay_d01);
    UNIT_RUN(test_replay_e04);
    UNIT_RUN(test_replay_e05_ring);
    UNIT_RUN(test_changed_driver_is_caught);
    return unit_report();
}
