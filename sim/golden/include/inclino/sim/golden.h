/*
 * sim/golden.h - the golden-trace harness every driver test shares (module inclino_sim_golden,
 * layer sim; docs/traces.md, "Golden traces").
 *
 * A golden case is a driver sequence (a callback that runs the driver on the bus and HAL it is
 * given) and the committed trace of it. Recording runs the sequence against the simulated board
 * through a trace recorder; replaying runs it against the trace alone (no board, no model): the
 * replay checks every MOSI word and CS period, the test checks what the driver made of the MISO
 * words. A test's main() passes --regenerate to record instead of replaying.
 */
#ifndef INCLINO_SIM_GOLDEN_H
#define INCLINO_SIM_GOLDEN_H

#include <stdbool.h>

#include "inclino/hal.h"
#include "inclino/sim/board.h"
#include "inclino/sim/trace.h"
#include "inclino/spi.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SIM_GOLDEN_COMMENTS 4u

/* A driver sequence on bus/hal; its results go wherever ctx says. */
typedef void (*sim_golden_seq)(void *ctx, const struct spi_bus *bus, const struct hal *hal);

struct sim_golden {
    const char *path;                         /* the trace file */
    const char *comment[SIM_GOLDEN_COMMENTS]; /* '#' lines of a recording, NULL ends */
};

/* True when the test was started with --regenerate (record the traces instead). */
bool sim_golden_regenerate(int argc, char **argv);

/*
 * Record: run seq against the live board (the caller set up the board and its part) through a
 * recorder writing g->path, with g's comments. Returns 0, the recorder's error, or
 * INC_ERR_TIMING when the board's violation log is not empty (then printed): a golden trace is
 * always a clean run.
 */
int sim_golden_record(const struct sim_golden *g, struct sim_board *board, sim_golden_seq seq,
                      void *ctx);

/*
 * Replay: run seq against the trace g->path in *rp (caller-owned, so a test can read
 * trace_replay_message() afterwards). Returns trace_replay_finish()'s result (the first
 * divergence, or a driver that stopped early), or the open error; a failure is printed with
 * the replay's message.
 */
int sim_golden_replay(const struct sim_golden *g, struct trace_replay *rp, sim_golden_seq seq,
                      void *ctx);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_SIM_GOLDEN_H */
