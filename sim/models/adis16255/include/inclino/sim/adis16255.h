/*
 * sim/adis16255.h - register-level model of the ADIS16250/ADIS16255 gyroscope on the simulated
 * board, on top of the shared ADIS protocol core (sim/adis_core.h).
 *
 * Written from docs/sensor-facts.md §2 and the datasheet pages it cites (ADIS16250/55 Rev B pp. 11, 12,
 * 15), not from the driver. Where a fact is [U] the model takes a stated choice (listed in
 * docs/drivers-adis16255.md, "Model"); time constants of the part are in struct
 * sim_adis16255_times and can be changed by a test.
 *
 * Behaviour:
 *   - register file with defaults (ENDURANCE = cfg.endurance, GYRO_SCALE 0x0800, SMPL_PRD
 *     0x0001, SENS_AVG 0x0402, MSC_CTRL 0x0006) and a non-volatile copy (flash) of GYRO_OFF,
 *     GYRO_SCALE, ALM_*, MSC_CTRL, SMPL_PRD and SENS_AVG;
 *   - every sample period TS = TB * (NS + 1) (TB 1.953 / 60.54 ms) in virtual time: physical
 *     input (physics hook or static input) -> error-model hook -> self-test stimulus -> moving
 *     average over 2^M samples (SENS_AVG[2:0]) -> GYRO_SCALE/2048 and GYRO_OFF -> range clamp
 *     (overrange bit) -> quantisation; TEMP_OUT, SUPPLY_OUT, ANGL_OUT (integral of the rate);
 *     ND set on every output; a data-ready pulse on the DIO line MSC_CTRL selects;
 *   - ND clears when the register is read; EA = STATUS != 0; STATUS: supply bits follow the
 *     supply input, overrange / SPI failure (a frame dropped for a timing rule) / flash failure
 *     latch until STATUS is read, the self-test error stays until a passing self-test;
 *   - SCLK <= 2.5 MHz (stall 30 us) at >= 64 SPS, <= 1 MHz (stall 75 us) below;
 *   - COMMAND: autonull (busy for 2^M samples + autonull_extra_ns, then GYRO_OFF -= the mean
 *     output over those samples), factory restore (GYRO_OFF = 0, GYRO_SCALE = 0x0800), flash
 *     update (flash copy, ENDURANCE + 1), software reset (registers from flash, outputs cleared,
 *     sampling restarts); while busy the core answers garbage and reports SIM_VIOL_BUSY;
 *   - MSC_CTRL bit 10 runs the internal self-test for self_test_ns: the output shifts by
 *     SIM_ADIS16255_ST_DPS, the bit then clears itself and STATUS bit 5 tells pass/fail.
 */
#ifndef INCLINO_SIM_ADIS16255_H
#define INCLINO_SIM_ADIS16255_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/sim/adis_core.h"
#include "inclino/sim/inertial.h"
#include "inclino/sim/part.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SIM_ADIS16255_REGS 32u        /* 16-bit registers 0x00..0x3E */
#define SIM_ADIS16255_HIST 64u        /* 2^6 taps, the largest filter */
#define SIM_ADIS16255_ST_DPS 25.0     /* [U] self-test output shift, °/s */
#define SIM_ADIS16255_MAN_ST_DPS 25.0 /* [U] manual self-test (MSC_CTRL bits 8/9) shift */

/* Durations of the part; a zero field takes the default in brackets. */
struct sim_adis16255_times {
    uint64_t reset_ns;           /* software reset busy time [100 ms] */
    uint64_t flash_update_ns;    /* [50 ms] */
    uint64_t factory_restore_ns; /* [30 ms] */
    uint64_t autonull_extra_ns;  /* on top of 2^M sample periods [10 ms] */
    uint64_t self_test_ns;       /* internal self-test [30 ms] */
    uint64_t dr_pulse_ns;        /* data-ready pulse width [50 us] */
};

struct sim_adis16255_cfg {
    const char *name;       /* for violation reports ("adis16255" when NULL) */
    struct sim_pinbus *bus; /* its clock drives the sampling */
    unsigned cs, sclk, mosi, miso;
    int dio0, dio1; /* board pins wired to DIO0/DIO1, -1 = not wired */
    unsigned axis;  /* rate axis sensed: 0 x, 1 y, 2 z */
    struct sim_violation_log *log;
    uint64_t seed;      /* garbage while busy / after broken frames */
    uint16_t endurance; /* flash write count at start */
    struct sim_adis16255_times times;
};

struct sim_adis16255 {
    struct sim_adis_core core;
    struct sim_adis16255_cfg cfg;
    struct sim_clock *clk;
    int dio_dev;                        /* pin-bus device id driving the DIO pins */
    uint16_t reg[SIM_ADIS16255_REGS];   /* index = address >> 1; outputs hold data bits only */
    uint16_t flash[SIM_ADIS16255_REGS]; /* non-volatile copy */
    uint32_t nd;                        /* ND per register index */
    uint16_t latched;                   /* STATUS bits that latch until STATUS is read */
    uint16_t live;                      /* STATUS bits that follow a condition (supply) */
    bool st_error;                      /* STATUS self-test error */
    struct sim_inertial_input input;    /* static input when no physics hook */
    struct sim_physics physics;
    struct sim_error_model error;
    double hist[SIM_ADIS16255_HIST];
    unsigned hist_len, hist_pos;
    double angle_deg;
    double rate_out_dps; /* last gyro output before quantisation (after offset) */
    bool sampling;       /* false while in reset */
    bool connected;
    bool dr_suppressed; /* test back door: no data-ready pulses */
    bool dr_high;       /* level driven on the active DIO (when driven) */
    uint64_t busy_until;
    bool reset_pending;
    bool autonull_active;
    unsigned autonull_target, autonull_n;
    double autonull_sum;
    bool self_test_active;
    bool self_test_fail; /* test back door: the next self-tests fail */
    int ev_sample, ev_dr_off, ev_cmd, ev_st;
    /* injected faults (sim/part.h, sim_adis16255_part) */
    uint16_t fault_status;      /* STATUS bits held on (device error) */
    struct sim_stuck_bit stuck; /* an injected stuck data bit */
    /* statistics */
    uint32_t samples, commands, dr_pulses, frame_errors;
};

/* Attach the model to the bus (SPI slave on cs/sclk/mosi/miso, DIO pins) and start sampling at
 * the default rate; the input is "at rest" (sim_inertial_at_rest). Returns 0 or an error. */
int sim_adis16255_init(struct sim_adis16255 *m, const struct sim_adis16255_cfg *cfg);

/* Back doors for tests (the physical world and fault injection). */
void sim_adis16255_set_input(struct sim_adis16255 *m, const struct sim_inertial_input *in);
void sim_adis16255_set_physics(struct sim_adis16255 *m,
                               const struct sim_physics *p); /* NULL: static */
void sim_adis16255_set_error_model(struct sim_adis16255 *m,
                                   const struct sim_error_model *e); /* NULL: ideal */
/* Busy (garbage answers) for ns from now, as if a command ran that the driver did not send. */
void sim_adis16255_force_busy(struct sim_adis16255 *m, uint64_t ns);
void sim_adis16255_fail_self_test(struct sim_adis16255 *m, bool fail);
void sim_adis16255_suppress_dr(struct sim_adis16255 *m, bool suppress);
/* The part is gone: SPI slave detached, DIO released, sampling stopped. */
void sim_adis16255_disconnect(struct sim_adis16255 *m);
/* Register contents without side effects (outputs: data bits only); poke sets a register. */
uint16_t sim_adis16255_peek(const struct sim_adis16255 *m, uint8_t addr);
void sim_adis16255_poke(struct sim_adis16255 *m, uint8_t addr, uint16_t value);
uint16_t sim_adis16255_flash(const struct sim_adis16255 *m, uint8_t addr);
/* The STATUS word as it would read now (no clearing). */
uint16_t sim_adis16255_status(const struct sim_adis16255 *m);
/* Current sample period in ns. */
uint64_t sim_adis16255_period_ns(const struct sim_adis16255 *m);
/* LSB of GYRO_OUT for the current range, °/s; LSB of GYRO_OFF, °/s. */
double sim_adis16255_gyro_lsb(const struct sim_adis16255 *m);
#define SIM_ADIS16255_OFF_LSB (80.0 / 4368.0)

/*
 * The part interface (sim/part.h). Faults: wire ones (MISO stuck, corrupt frame), physics ones,
 * and in the model: wrong identity (GYRO_SCALE reads a reserved bit, as another part of the
 * family would: the driver has no PROD_ID to check), busy (sim_adis16255_force_busy), no
 * data-ready (sim_adis16255_suppress_dr), device error (STATUS bits held on, ALARM1 by default:
 * EA in every output word), stuck bit (any register as read over the bus).
 */
struct sim_part;
extern const struct sim_part_ops sim_adis16255_part_ops;
void sim_adis16255_part(struct sim_adis16255 *m, struct sim_part *p);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_SIM_ADIS16255_H */
