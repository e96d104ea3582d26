/*
 * fixture.h - the ADIS16255 driver on the standard simulated board with the ADIS16255 model on
 * cs0, DIO0 -> dr0 and DIO1 -> dr1. Shared by the tests of tests/adis16255.
 */
#ifndef TESTS_ADIS16255_FIXTURE_H
#define TESTS_ADIS16255_FIXTURE_H

#include <stdbool.h>
#include <stdio.h>

#include "inclino/adis16255.h"
#include "inclino/sim/adis16255.h"
#include "inclino/sim/board.h"
#include "unit.h"

struct fx {
    struct sim_board board;
    struct sim_adis16255 part;
    struct adis16255 drv;
    struct adis16255_cfg cfg;
    bool has_part;
};

extern struct fx fx;

/* Fresh board; the part when with_part (else nothing answers on cs0); cfg = fx_default_cfg. */
void fx_setup(bool with_part);
/* Same, with the part's durations replaced by *times (NULL: defaults). */
void fx_setup_times(bool with_part, const struct sim_adis16255_times *times);
/* 256 SPS, ±320 °/s, 4 taps, data-ready on DIO0 -> dr0 active high; no reset, no self-test. */
void fx_default_cfg(struct adis16255_cfg *cfg);
/* A static physical input: rate about z, temperature, supply. */
void fx_input(double rate_dps, double temp_c, double supply_v);
/* Let virtual time pass. */
void fx_wait_ms(uint32_t ms);

/* Every normal test ends with this: a driver that broke a timing rule shows the log. */
#define CHECK_NO_VIOLATIONS()                               \
    do {                                                    \
        if (fx.board.log.total != 0u) {                     \
            printf("violation log:\n");                     \
            sim_violation_log_print(&fx.board.log, stdout); \
        }                                                   \
        CHECK_EQ_INT(fx.board.log.total, 0);                \
    } while (0)

#endif /* TESTS_ADIS16255_FIXTURE_H */
