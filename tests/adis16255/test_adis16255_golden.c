/*
 * Golden traces of the ADIS16255 driver (docs/traces.md): its init and read sequences, and its
 * commands, recorded once from the ADIS16255 model and committed under tests/adis16255/golden.
 * The test replays each trace to the driver with no model behind it and asserts the same
 * results as a live run against the model, exactly; a driver whose bus traffic changes fails at
 * the first diverging frame with the frame index and both words.
 *
 * Regenerate (review the diff: the trace is the driver's bus contract):
 *   build/host/tests/adis16255/test_adis16255_golden --regenerate
 */
#include "fixture.h"

#include "inclino/sim/golden.h"

#include <string.h>

#ifndef GOLDEN_DIR
#error "GOLDEN_DIR must be defined"
#endif

#define INIT_READ GOLDEN_DIR "/adis16255_init_read.trace"
#define COMMANDS GOLDEN_DIR "/adis16255_commands.trace"

static struct trace_replay rp;
static struct adis16255 drv;

struct results {
    int err[16];
    int32_t val[16];
    unsigned n;
};

static void put(struct results *r, int err, int32_t val)
{
    if (r->n < 16u) {
        r->err[r->n] = err;
        r->val[r->n] = val;
        r->n++;
    }
}

/* Results are stored after each call returns (never as arguments of the same call: the order
 * in which C evaluates arguments is unspecified). */

/* Init (reset + self-test), three data-ready samples, a stale read, supply, angle. */
static void seq_init_read(const struct spi_bus *bus, const struct hal *hal,
                          enum adis16255_range range, struct results *r)
{
    struct adis16255_cfg cfg;
    struct adis16255_sample s;
    int32_t q = 0;
    unsigned i;
    int e;
    memset(r, 0, sizeof(*r));
    fx_default_cfg(&cfg);
    cfg.bus = bus;
    cfg.hal = hal;
    cfg.range = range;
    cfg.reset_at_init = true;
    cfg.self_test_at_init = true;
    e = adis16255_init(&drv, &cfg);
    put(r, e, 0);
    if (r->err[0] != INC_OK) {
        return;
    }
    for (i = 0; i < 3u; i++) {
        e = adis16255_wait_sample(&drv, 0, &s);
        put(r, e, s.rate_dps_q16);
        put(r, e, s.temp_c_q16);
    }
    e = adis16255_read_sample(&drv, &s);
    put(r, e, s.rate_dps_q16);
    e = adis16255_read_supply(&drv, &q);
    put(r, e, q);
    e = adis16255_read_angle(&drv, &q);
    put(r, e, q);
}

/* Init, autonull, flash update, offset write, factory restore, self-test, reset, a sample. */
static void seq_commands(const struct spi_bus *bus, const struct hal *hal, struct results *r)
{
    struct adis16255_cfg cfg;
    struct adis16255_sample s;
    int32_t q = 0;
    bool sat = false;
    int e;
    memset(r, 0, sizeof(*r));
    fx_default_cfg(&cfg);
    cfg.bus = bus;
    cfg.hal = hal;
    e = adis16255_init(&drv, &cfg);
    put(r, e, 0);
    if (r->err[0] != INC_OK) {
        return;
    }
    e = adis16255_autonull(&drv);
    put(r, e, 0);
    e = adis16255_get_gyro_offset(&drv, &q);
    put(r, e, q);
    e = adis16255_flash_update(&drv);
    put(r, e, 0);
    e = adis16255_set_gyro_offset(&drv, 3 * 65536, &sat);
    put(r, e, sat);
    e = adis16255_factory_restore(&drv);
    put(r, e, 0);
    e = adis16255_self_test(&drv);
    put(r, e, 0);
    e = adis16255_reset(&drv);
    put(r, e, 0);
    e = adis16255_get_gyro_offset(&drv, &q);
    put(r, e, q);
    e = adis16255_wait_sample(&drv, 0, &s);
    put(r, e, s.rate_dps_q16);
}

/* The physical world of the recordings: 102 °/s (init/read) or a part at rest with a 2 °/s
 * bias (commands: autonull needs the part still), 40 °C, 5 V. */
static void live_setup(int which)
{
    fx_setup(true);
    fx_input(which == 0 ? 102.0 : 2.0, 40.0, 5.0);
}

static const struct sim_golden goldens[2] = {
    {INIT_READ,
     {"ADIS16255 driver: init and read sequence", "model: 102 dps, 40 C, 5.0 V",
      "regenerate: test_adis16255_golden --regenerate", NULL}},
    {COMMANDS,
     {"ADIS16255 driver: commands", "model: at rest, 2 dps bias, 40 C, 5.0 V",
      "regenerate: test_adis16255_golden --regenerate", NULL}},
};

/* One sequence of the golden cases, with the range it configures. */
struct run {
    int which;
    enum adis16255_range range;
    struct results *r;
};

static void seq(void *ctx, const struct spi_bus *bus, const struct hal *hal)
{
    const struct run *run = ctx;
    if (run->which == 0) {
        seq_init_read(bus, hal, run->range, run->r);
    } else {
        seq_commands(bus, hal, run->r);
    }
}

static void run_live(int which, struct results *r, bool record)
{
    struct run run = {which, ADIS16255_RANGE_320, r};
    live_setup(which);
    if (record) {
        CHECK_OK(sim_golden_record(&goldens[which], &fx.board, seq, &run));
    } else {
        seq(&run, &fx.board.spi.bus, &fx.board.hal);
    }
    CHECK_NO_VIOLATIONS();
}

static int replay(int which, enum adis16255_range range, struct results *r)
{
    struct run run = {which, range, r};
    return sim_golden_replay(&goldens[which], &rp, seq, &run);
}

static void check_same(const struct results *a, const struct results *b)
{
    unsigned i;
    CHECK_EQ_INT(a->n, b->n);
    for (i = 0; i < a->n && i < b->n; i++) {
        CHECK_EQ_INT(a->err[i], b->err[i]);
        CHECK_EQ_INT(a->val[i], b->val[i]);
    }
}

static void test_init_read(void)
{
    static const int err[10] = {0, 0, 0, 0, 0, 0, 0, INC_ERR_STALE, 0, 0};
    struct results live, again;
    unsigned i;
    run_live(0, &live, false);
    /* The live results themselves: 102 °/s -> 1392 counts -> 101.978 °/s; 40 °C -> 103. */
    REQUIRE(live.n == 10u);
    for (i = 0; i < 10u; i++) {
        CHECK_EQ_INT(live.err[i], err[i]);
    }
    CHECK_EQ_INT(live.val[1], 6683232);
    CHECK_EQ_INT(live.val[2], 2619205);
    CHECK_EQ_INT(live.val[5], 6683232);
    CHECK_EQ_INT(live.val[8], 327680);
    CHECK_OK(replay(0, ADIS16255_RANGE_320, &again));
    check_same(&live, &again);
}

static void test_commands(void)
{
    struct results live, again;
    unsigned i;
    run_live(1, &live, false);
    REQUIRE(live.n == 10u);
    for (i = 0; i < 10u; i++) {
        CHECK_EQ_INT(live.err[i], 0);
    }
    CHECK_EQ_INT(live.val[2], adis16255_gyro_off_dps_from_word(0xF93)); /* -109: the 2 °/s bias */
    CHECK_EQ_INT(live.val[8], adis16255_gyro_off_dps_from_word(0xF93)); /* from flash after reset */
    CHECK_EQ_INT(live.val[9], 0);                                       /* bias nulled */
    CHECK_OK(replay(1, ADIS16255_RANGE_320, &again));
    check_same(&live, &again);
}

/* A driver configured differently (±160 °/s) sends another SENS_AVG: the replay stops there,
 * naming the frame and both words; the driver gets INC_ERR_MISMATCH and is not initialised. */
static void test_divergence(void)
{
    struct results r;
    CHECK_ERR(replay(0, ADIS16255_RANGE_160, &r), INC_ERR_MISMATCH);
    CHECK_EQ_INT(r.n, 1);
    CHECK_EQ_INT(r.err[0], INC_ERR_MISMATCH);
    CHECK(!drv.ready);
    printf("expected divergence: %s\n", trace_replay_message(&rp));
    CHECK(strstr(trace_replay_message(&rp), "expected MOSI B904, driver sent B902") != NULL);
}

int main(int argc, char **argv)
{
    if (sim_golden_regenerate(argc, argv)) {
        struct results r;
        run_live(0, &r, true);
        run_live(1, &r, true);
        return unit_report();
    }
    UNIT_RUN(test_init_read);
    UNIT_RUN(test_commands);
    UNIT_RUN(test_divergence);
    return unit_report();
}
