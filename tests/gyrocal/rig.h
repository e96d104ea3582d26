/*
 * rig.h - a simulated ADIS1636x/1640x on the standard board, with the seeded error model of
 * sim/noise, a physics hook for motion and temperature scenarios, the driver and gyrocal; shared
 * by the gyrocal tests and the residual-bias benchmark. One instance per process (large).
 *
 * The achieved bias of axis i at any instant is the error model's correlated bias (white noise
 * excluded) plus the part's user offset plus the processor-side correction in force:
 * rig_bias_dps(). Averages of it over spans of virtual time are taken by the error-model wrapper
 * (rig_bias_acc_*), once per internal sample of the part.
 */
#ifndef GYROCAL_TEST_RIG_H
#define GYROCAL_TEST_RIG_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/adis_imu.h"
#include "inclino/gyrocal.h"
#include "inclino/sim/adis_imu.h"
#include "inclino/sim/board.h"
#include "inclino/sim/noise.h"

#define RIG_CMD_LOG 32u

struct rig_motion {
    uint64_t from_ns, to_ns; /* rotation about z during [from, to) */
    double rate_dps;
    double vib_dps; /* vibration amplitude on all gyros at 17 Hz during [from, to) */
};

struct rig_temp {
    double start_c; /* temperature at t0 */
    double rise_c;  /* exponential warm-up: + rise (1 - exp(-(t - t0) / tau)) */
    double tau_s;
    double ramp_c_per_s; /* linear ramp from ramp_from_ns on */
    uint64_t ramp_from_ns;
    uint64_t t0_ns;
};

struct rig {
    struct sim_board board;
    struct sim_adis_imu part;
    struct sim_adis_imu_cfg part_cfg;
    struct sim_noise noise;
    struct sim_error_model err_hook;
    struct sim_physics phys;
    struct spi_bus spy;            /* records GLOB_CMD writes, passes everything on */
    uint16_t cmd_log[RIG_CMD_LOG]; /* DIN words 0xBExx seen, in order */
    unsigned cmd_count;
    struct adis_imu imu;
    struct adis_imu_cfg cfg;
    struct gyrocal gc;
    struct gyrocal_cfg gcfg;
    struct rig_motion motion;
    struct rig_temp temp;
    /* bias accumulation */
    bool acc_on;
    double acc_sum[3];     /* achieved bias: error model + offset register + correction */
    double acc_sum_reg[3]; /* the same without the processor-side correction */
    uint64_t acc_n;
    /* history of the error model's correlated bias (rig_history) */
    bool hist_on;
    size_t hist_n, hist_cap;
    uint64_t *hist_t; /* sample times */
    double *hist_c;   /* 3 cumulative sums per sample */
};

extern struct rig rig;

/* Board, part (variant v, error model ncfg), driver (data-ready on DIO1), gyrocal with gcfg
 * (NULL: gyrocal_default_cfg for the variant at +-300 deg/s). At rest, 25 C, no motion.
 * Returns 0 or the first error. */
int rig_setup(enum sim_adis_imu_variant v, const struct sim_noise_cfg *ncfg,
              const struct gyrocal_cfg *gcfg);
/* Virtual time now, ns. */
uint64_t rig_now(void);
/* Advance virtual time (the part keeps sampling). */
void rig_wait_ms(uint32_t ms);
/* Achieved bias of axis i now: correlated error-model bias + user offset + correction. */
double rig_bias_dps(unsigned axis);
/* Average the achieved bias over the next `seconds` of virtual time (out_reg, may be NULL:
 * without the processor-side correction). */
void rig_bias_mean2(double seconds, double out[3], double out_reg[3]);
void rig_bias_mean(double seconds, double out[3]);
/* Record the error model's correlated bias per internal sample from now on (host benchmark:
 * allocates; rig_setup frees). Returns 0 or -1 (out of memory). */
int rig_history(void);
/* Mean correlated bias (error model only: no offset, no correction) of the samples taken in
 * (t1, t2]; -1 when there are none recorded. */
int rig_bias_window(uint64_t t1, uint64_t t2, double out[3]);
/* GLOB_CMD words seen so far equal to w. */
unsigned rig_cmd_seen(uint16_t w);
/* Violations on the board (printed when any). */
unsigned rig_violations(void);

#endif
