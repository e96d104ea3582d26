/*
 * sim/bench.h - the standard simulated board with parts wired to it, the way every test does it
 * (module inclino_sim_bench, layer sim).
 *
 * Slot n of the board (sim/board.h) is chip select csN and data-ready line drN (a part with a
 * second data-ready output drives dr(N+1) with it when N < 3). The firmware's SPI engine is the
 * board's bit-banged master: a driver gets &board.spi.bus and &board.hal.
 *
 * Two levels:
 *   - sim_bench_<part>_cfg(): a model configuration with the standard wiring (bus, csN, sclk,
 *     mosi, miso, drN, the board's violation log) and the tests' defaults; change what a test
 *     needs, then call the model's own init. Tests that keep their model in their own fixture
 *     use these.
 *   - struct sim_bench: a board and one part behind the part interface (sim/part.h), for code
 *     that treats every part alike (tests/conformance).
 */
#ifndef INCLINO_SIM_BENCH_H
#define INCLINO_SIM_BENCH_H

#include "inclino/sim/adis16255.h"
#include "inclino/sim/adis_imu.h"
#include "inclino/sim/board.h"
#include "inclino/sim/loopback.h"
#include "inclino/sim/part.h"
#include "inclino/sim/sca3000.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ADIS16255 on slot: DIO0 -> drN, DIO1 -> dr(N+1) (or not wired), rate about z, seed 16255,
 * ENDURANCE 0x0010, the model's default durations. */
void sim_bench_adis16255_cfg(struct sim_board *b, unsigned slot, struct sim_adis16255_cfg *c);
/* ADIS1636x/1640x variant v on slot: DIO1 -> drN, DIO2 -> dr(N+1) (or none), seed 1234 + v,
 * busy for its start-up time after init (the real part). */
void sim_bench_adis_imu_cfg(struct sim_board *b, unsigned slot, enum sim_adis_imu_variant v,
                            struct sim_adis_imu_cfg *c);
/* SCA3000 variant v on slot: INT -> drN, default REVID, timing and range. */
void sim_bench_sca3000_cfg(struct sim_board *b, unsigned slot, enum sim_sca3000_variant v,
                           struct sim_sca3000_cfg *c);
/* Loopback part on slot (mode 3, 16-bit, no timing limits: the caller sets them). */
void sim_bench_loopback_cfg(struct sim_board *b, unsigned slot, struct sim_loopback_cfg *c);

enum sim_bench_kind {
    SIM_BENCH_NONE = 0,
    SIM_BENCH_ADIS16255,
    SIM_BENCH_ADIS_IMU,
    SIM_BENCH_SCA3000,
};

struct sim_bench {
    struct sim_board board;
    struct sim_part part; /* the part on slot 0, once added */
    enum sim_bench_kind kind;
    union {
        struct sim_adis16255 adis16255;
        struct sim_adis_imu adis_imu;
        struct sim_sca3000 sca3000;
    } m;
};

/* A fresh board and no part. Returns 0 or the board's error. */
int sim_bench_init(struct sim_bench *b);
/* Initialise the model from *c (from sim_bench_<part>_cfg(&b->board, 0, ...), edited or not)
 * and bind it to b->part. Returns 0 or the model's error. */
int sim_bench_add_adis16255(struct sim_bench *b, const struct sim_adis16255_cfg *c);
int sim_bench_add_adis_imu(struct sim_bench *b, const struct sim_adis_imu_cfg *c);
int sim_bench_add_sca3000(struct sim_bench *b, const struct sim_sca3000_cfg *c);

/* Let virtual time pass (the parts sample on the way). */
void sim_bench_wait_ns(struct sim_bench *b, uint64_t ns);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_SIM_BENCH_H */
