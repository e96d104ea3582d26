/*
 * Golden traces of the ADIS1636x/1640x driver (docs/traces.md): its init and read sequences,
 * recorded from the simulated part and committed under tests/adis_imu/golden/, are replayed to
 * the driver without any model. The replay checks every MOSI word the driver sends; the test
 * checks the values the driver makes of the recorded MISO words.
 *
 * Scenario (one per family, ADIS16405 and ADIS16364): init with data-ready on DIO1; wait for
 * data-ready; burst read; wait; pipelined read of every channel; wait; pipelined read of gyros,
 * accelerometers and temperature; a gyro offset write and read-back; a switch to low-power mode
 * and a burst read there.
 *
 * Regenerate after an intended change of the driver's traffic (then review the diff):
 *   build/host/tests/adis_imu/test_adis_imu_golden --regenerate
 */
#include "fixture.h"
#include "inclino/sim/golden.h"
#include "unit.h"

#include <stdio.h>
#include <string.h>

#ifndef GOLDEN_DIR
#error "GOLDEN_DIR must be defined"
#endif

struct result {
    int err[9];
    struct adis_imu_sample s[4];
    int32_t offset;
};

static struct adis_imu imu;
static struct trace_replay rp;
static struct result live, replayed;

static void run_scenario(const struct spi_bus *bus, const struct hal *hal,
                         enum sim_adis_imu_variant v, struct result *r)
{
    struct adis_imu_cfg c;
    memset(&c, 0, sizeof(c));
    memset(r, 0, sizeof(*r));
    c.hal = hal;
    c.bus = bus;
    c.cs = SIM_BOARD_CS(0);
    c.variant = (uint8_t)v;
    c.dr_pin = SIM_BOARD_DR(0);
    c.dr_line = ADIS_IMU_DR_DIO1;
    r->err[0] = adis_imu_init(&imu, &c);
    if (r->err[0] != INC_OK) {
        return;
    }
    r->err[1] = adis_imu_wait_ready(&imu, 0, NULL);
    r->err[2] = adis_imu_read_sample(&imu, &r->s[0]);
    r->err[3] = adis_imu_wait_ready(&imu, 0, NULL);
    r->err[4] = adis_imu_read_channels(&imu, ADIS_IMU_CH_ALL, &r->s[1]);
    (void)adis_imu_wait_ready(&imu, 0, NULL);
    r->err[5] = adis_imu_read_channels(
        &imu, ADIS_IMU_CH_GYROS | ADIS_IMU_CH_ACCELS | ADIS_IMU_CH_TEMPS, &r->s[2]);
    r->err[6] = adis_imu_set_gyro_offset(&imu, 2, -1236); /* -15.45 deg/s */
    if (r->err[6] == INC_OK) {
        r->err[6] = adis_imu_get_gyro_offset(&imu, 2, &r->offset);
    }
    r->err[7] = adis_imu_set_sample_period(&imu, 0x0A);
    (void)adis_imu_dr_flush(&imu); /* a sample taken with the offset */
    (void)adis_imu_wait_ready(&imu, 0, NULL);
    r->err[8] = adis_imu_read_sample(&imu, &r->s[3]);
}

static void golden_path(enum sim_adis_imu_variant v, char *buf, size_t len)
{
    snprintf(buf, len, "%s/%s.trace", GOLDEN_DIR, v == SIM_ADIS16405 ? "adis16405" : "adis16364");
}

/* The scenario of variant v as a golden sequence. */
struct run {
    enum sim_adis_imu_variant v;
    struct result *r;
};

static void seq(void *ctx, const struct spi_bus *bus, const struct hal *hal)
{
    const struct run *run = ctx;
    run_scenario(bus, hal, run->v, run->r);
}

/* The standard input of the driver test (10, -20.5, 123.45 deg/s ...), on the live part. */
static void live_part(enum sim_adis_imu_variant v)
{
    struct sim_inertial_input in;
    sim_inertial_at_rest(&in);
    in.rate_dps[0] = 10.0;
    in.rate_dps[1] = -20.5;
    in.rate_dps[2] = 123.45;
    in.accel_g[0] = 0.5;
    in.accel_g[1] = -0.25;
    in.accel_g[2] = 0.98;
    in.temp_c = 40.0;
    fx_prepare(v);
    fx.part_cfg.seed = 99;
    fx_start();
    sim_adis_imu_set_input(&fx.part, &in);
    sim_adis_imu_set_magn(&fx.part, 0.25, -0.1, 0.5);
    sim_adis_imu_set_aux(&fx.part, 1.5);
    fx_set_input_settled(&in);
}

/* Record the scenario from the live part to path. */
static int record(enum sim_adis_imu_variant v, const char *path, struct result *r)
{
    struct sim_golden g = {path,
                           {v == SIM_ADIS16405
                                ? "ADIS16405 (sim): init, burst, register reads, offset, low power"
                                : "ADIS16364 (sim): init, burst, register reads, offset, low power",
                            NULL}};
    struct run run = {v, r};
    live_part(v);
    return sim_golden_record(&g, &fx.board, seq, &run);
}

/* What the driver must make of the traffic, worked out from the datasheet scales. */
static void check_result(enum sim_adis_imu_variant v, const struct result *r)
{
    const bool f40 = v == SIM_ADIS16405;
    unsigned i, k;
    for (i = 0; i < 9u; i++) {
        CHECK_EQ_INT(r->err[i], 0);
    }
    for (k = 0; k < 4u; k++) {
        const struct adis_imu_sample *s = &r->s[k];
        CHECK_EQ_INT(s->counts[ADIS_IMU_CH_GYRO_X], 200);
        CHECK_EQ_INT(s->counts[ADIS_IMU_CH_GYRO_Y], -410);
        CHECK_EQ_INT(s->counts[ADIS_IMU_CH_GYRO_Z], k < 3u ? 2469 : 2160); /* 123.45 - 15.45 */
        CHECK_EQ_INT(s->counts[ADIS_IMU_CH_ACCEL_X], f40 ? 150 : 500);
        CHECK_EQ_INT(s->counts[ADIS_IMU_CH_ACCEL_Z], f40 ? 294 : 980);
        CHECK_EQ_INT(s->counts[ADIS_IMU_CH_TEMP0], f40 ? 107 : 110);
        CHECK_EQ_HEX(s->stale, 0);
        CHECK_EQ_HEX(s->valid, s->present);
        if (k != 2u) {
            CHECK_EQ_INT(s->counts[ADIS_IMU_CH_SUPPLY], 2068);
            CHECK_EQ_INT(s->counts[ADIS_IMU_CH_AUX], 1862);
        }
        if (f40 && k != 2u) {
            CHECK_EQ_INT(s->counts[ADIS_IMU_CH_MAGN_Y], -200);
        }
    }
    CHECK_EQ_HEX(r->s[2].present, ADIS_IMU_CH_GYROS | ADIS_IMU_CH_ACCELS |
                                      (f40 ? ADIS_IMU_CH(ADIS_IMU_CH_TEMP0) : ADIS_IMU_CH_TEMPS));
    CHECK_EQ_INT(r->offset, -1236);
}

static void replay(enum sim_adis_imu_variant v, const char *path, struct result *r)
{
    struct sim_golden g = {path, {NULL}};
    struct run run = {v, r};
    CHECK_OK(sim_golden_replay(&g, &rp, seq, &run));
}

/* The committed traces replay to the exact values. */
static void test_golden_replay(void)
{
    static const enum sim_adis_imu_variant vs[2] = {SIM_ADIS16405, SIM_ADIS16364};
    char path[512];
    unsigned i;
    for (i = 0; i < 2u; i++) {
        golden_path(vs[i], path, sizeof(path));
        replay(vs[i], path, &replayed);
        check_result(vs[i], &replayed);
    }
}

/* Today's driver against today's model gives the same values, and its own fresh recording
 * replays (record -> replay round trip). */
static void test_live_and_round_trip(void)
{
    CHECK_OK(record(SIM_ADIS16405, "adis_imu_live.trace", &live));
    check_result(SIM_ADIS16405, &live);
    replay(SIM_ADIS16405, "adis_imu_live.trace", &replayed);
    check_result(SIM_ADIS16405, &replayed);
    CHECK(memcmp(live.s[3].raw, replayed.s[3].raw, sizeof(live.s[3].raw)) == 0);
    remove("adis_imu_live.trace");
}

/* A driver that changes its traffic is caught at the first divergent word. */
static void test_divergence_is_reported(void)
{
    struct adis_imu_cfg c;
    struct adis_imu_sample s;
    char path[512];
    golden_path(SIM_ADIS16405, path, sizeof(path));
    REQUIRE(trace_replay_open(&rp, path) == INC_OK);
    memset(&c, 0, sizeof(c));
    c.hal = &rp.hal;
    c.bus = &rp.bus;
    c.cs = SIM_BOARD_CS(0);
    c.variant = ADIS_IMU_ADIS16405;
    c.dr_pin = SIM_BOARD_DR(0);
    REQUIRE(adis_imu_init(&imu, &c) == INC_OK);
    CHECK_OK(adis_imu_wait_ready(&imu, 0, NULL));
    /* registers instead of the recorded burst: */
    CHECK_ERR(adis_imu_read_channels(&imu, ADIS_IMU_CH_GYROS, &s), INC_ERR_MISMATCH);
    CHECK_ERR(trace_replay_finish(&rp), INC_ERR_MISMATCH);
    printf("expected divergence: %s\n", trace_replay_message(&rp));
    /* frame 7 is the burst: 13 words in one CS period, the driver made a 1-word period */
    CHECK(strstr(trace_replay_message(&rp), "frame 7 ") != NULL);
    CHECK(strstr(trace_replay_message(&rp), "of 13 16-bit words") != NULL);
    CHECK(strstr(trace_replay_message(&rp), "of 1 16-bit words") != NULL);
}

int main(int argc, char **argv)
{
    if (sim_golden_regenerate(argc, argv)) {
        char path[512];
        int err;
        golden_path(SIM_ADIS16405, path, sizeof(path));
        err = record(SIM_ADIS16405, path, &live);
        check_result(SIM_ADIS16405, &live);
        golden_path(SIM_ADIS16364, path, sizeof(path));
        if (err == INC_OK) {
            err = record(SIM_ADIS16364, path, &live);
            check_result(SIM_ADIS16364, &live);
        }
        CHECK_OK(err);
        return unit_report();
    }
    UNIT_RUN(test_golden_replay);
    UNIT_RUN(test_live_and_round_trip);
    UNIT_RUN(test_divergence_is_reported);
    return unit_report();
}
