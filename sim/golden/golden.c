/* golden.c - see sim/golden.h. */
#include "inclino/sim/golden.h"

#include <stdio.h>
#include <string.h>

static struct trace_rec rec; /* one recording at a time; large, kept off the stack (QEMU) */

bool sim_golden_regenerate(int argc, char **argv)
{
    return argc > 1 && strcmp(argv[1], "--regenerate") == 0;
}

int sim_golden_record(const struct sim_golden *g, struct sim_board *board, sim_golden_seq seq,
                      void *ctx)
{
    unsigned i;
    int err, cerr;
    if (g == NULL || board == NULL || seq == NULL) {
        return INC_ERR_NULL;
    }
    err = trace_rec_open(&rec, g->path, &board->spi.bus, &board->hal);
    if (err != INC_OK) {
        return err;
    }
    for (i = 0; i < SIM_GOLDEN_COMMENTS && g->comment[i] != NULL; i++) {
        cerr = trace_rec_comment(&rec, g->comment[i]);
        if (err == INC_OK) {
            err = cerr;
        }
    }
    seq(ctx, &rec.bus, &rec.hal);
    cerr = trace_rec_close(&rec);
    if (err == INC_OK) {
        err = cerr;
    }
    if (board->log.total != 0u) {
        printf("recording %s: violation log:\n", g->path);
        sim_violation_log_print(&board->log, stdout);
        if (err == INC_OK) {
            err = INC_ERR_TIMING;
        }
    }
    return err;
}

int sim_golden_replay(const struct sim_golden *g, struct trace_replay *rp, sim_golden_seq seq,
                      void *ctx)
{
    int err;
    if (g == NULL || rp == NULL || seq == NULL) {
        return INC_ERR_NULL;
    }
    err = trace_replay_open(rp, g->path);
    if (err != INC_OK) {
        printf("cannot open %s: %s\n", g->path, trace_replay_message(rp));
        return err;
    }
    seq(ctx, &rp->bus, &rp->hal);
    err = trace_replay_finish(rp);
    if (err != INC_OK) {
        printf("replay of %s: %s\n", g->path, trace_replay_message(rp));
    }
    return err;
}
