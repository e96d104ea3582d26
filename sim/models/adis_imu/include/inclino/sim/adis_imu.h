/*
 * sim/adis_imu.h - simulated ADIS1636x (16360/62/64/65) and ADIS1640x (16400/16405) IMU.
 *
 * Written from docs/sensor-facts.md §3 and [ADI-IMU-QS], not from the driver. The SPI
 * protocol (pipelined reads, byte writes, busy -> garbage, burst <= 1 MHz) is the shared core
 * (sim/adis_core.h); this model is the part behind it:
 *
 *   - register file with per-variant defaults and a flash copy: GLOB_CMD[3] stores the writable
 *     registers and counts FLASH_CNT; power-on and software reset load them back;
 *   - internal sampling in virtual time at fS = 1638.4 / (NS + 1) SPS (31 x slower with
 *     SMPL_PRD[7]); each sample takes the physical input (physics hook or the static input),
 *     passes it through the error-model hook, runs the Bartlett filter of SENS_AVG (two cascaded
 *     N-tap moving averages, N = 2^M) on gyros and accelerometers, adds the user offsets,
 *     saturates at the rated range, quantises (14-bit, 12-bit) and sets ND on every output;
 *   - a data-ready pulse on DIO1 or DIO2 (MSC_CTRL) after each sample, not while busy;
 *   - DIAG_STAT: supply low/high from the supply input, over-range on saturation, SPI
 *     communication failure after a dropped frame, self-test results; cleared on read [U];
 *     EA = DIAG_STAT != 0 when an output word is read;
 *   - SCLK/stall limits of normal or low-power mode following SMPL_PRD[7:0] (<= 0x09: normal);
 *   - GLOB_CMD: autonull (offset -= filtered output, in 0.0125 deg/s LSB, 13-bit, saturating),
 *     precision autonull (mean of 30 s of 819.2 SPS samples, then the same), flash update,
 *     factory restore (offsets cleared), software reset (registers from flash), each busy for its
 *     time; MSC_CTRL[10] internal self-test (busy, then clears itself).
 * Unconfirmed choices are named constants in adis_imu.c and listed in docs/unconfirmed-facts.md;
 * the behaviour is described in docs/drivers-adis-imu.md.
 */
#ifndef INCLINO_SIM_ADIS_IMU_H
#define INCLINO_SIM_ADIS_IMU_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/sim/adis_core.h"
#include "inclino/sim/inertial.h"
#include "inclino/sim/part.h"

#ifdef __cplusplus
extern "C" {
#endif

enum sim_adis_imu_variant {
    SIM_ADIS16360 = 0,
    SIM_ADIS16362 = 1,
    SIM_ADIS16364 = 2,
    SIM_ADIS16365 = 3,
    SIM_ADIS16400 = 4,
    SIM_ADIS16405 = 5,
    SIM_ADIS_IMU_VARIANTS = 6,
};

#define SIM_ADIS_IMU_NO_PIN 0xFFFFu
#define SIM_ADIS_IMU_REGS 48u    /* 16-bit registers at byte addresses 0x00..0x5F */
#define SIM_ADIS_IMU_HIST 128u   /* Bartlett history (2 x 64 taps) */
#define SIM_ADIS_IMU_FILTERED 6u /* gyro x, y, z, accel x, y, z */

struct sim_adis_imu_cfg {
    enum sim_adis_imu_variant variant;
    struct sim_pinbus *bus;
    unsigned cs, sclk, mosi, miso; /* SPI pins */
    unsigned dio1, dio2;           /* pins DIO1/DIO2 drive, or SIM_ADIS_IMU_NO_PIN */
    struct sim_violation_log *log;
    const struct sim_physics *physics;   /* NULL: the static input (sim_adis_imu_set_input) */
    const struct sim_error_model *error; /* NULL: an ideal part */
    uint64_t seed;                       /* garbage words of the core */
    bool power_on_busy;                  /* busy for the start-up time after init (real part) */
    bool burst_bug;                      /* ADIS16405 burst bug, docs/sensor-facts.md §3.6; off */
    const char *name;                    /* for violation reports; NULL: the part's name */
};

/* One Bartlett channel: raw history x, first-stage history y1, running sums. */
struct sim_adis_imu_filter {
    double x[SIM_ADIS_IMU_HIST];
    double y1[SIM_ADIS_IMU_HIST];
    double s1, s2;
};

struct sim_adis_imu {
    struct sim_adis_core core;
    struct sim_adis_imu_cfg cfg;
    const char *name;
    struct sim_clock *clk;
    int dr_dev;                        /* pin-bus device id of the DIO lines */
    uint16_t reg[SIM_ADIS_IMU_REGS];   /* register file (outputs without ND/EA) */
    uint16_t flash[SIM_ADIS_IMU_REGS]; /* flash copy of the writable registers */
    uint64_t nd;                       /* ND per register index (bit i = reg[i]) */
    uint16_t diag;                     /* DIAG_STAT latch */
    bool low_power;
    /* sampling */
    struct sim_inertial_input input; /* static input */
    double magn_gauss[3];            /* magnetometer input (1640x), not in the error model */
    double aux_v;                    /* AUX_ADC input */
    uint64_t next_sample_16;         /* time of the next sample in 1/16 ns */
    int sample_ev;
    uint64_t period_16; /* current sample period in 1/16 ns */
    uint32_t hist_idx;
    unsigned taps; /* N of the Bartlett filter in force */
    struct sim_adis_imu_filter filt[SIM_ADIS_IMU_FILTERED];
    double filtered[SIM_ADIS_IMU_FILTERED]; /* filter outputs of the last sample (deg/s, g) */
    /* data-ready */
    unsigned dr_pin; /* pin in use, or SIM_ADIS_IMU_NO_PIN */
    bool dr_active_high;
    int dr_off_ev;
    /* commands */
    uint64_t busy_until;
    int busy_ev;
    bool prec_active; /* precision autonull is averaging */
    double prec_sum[3];
    uint32_t prec_n;
    bool self_test_active;
    uint16_t self_test_fail; /* DIAG bits the next self-test reports */
    uint32_t bursts_served;
    /* hooks installed by sim_adis_imu_set_physics / _set_error_model (cfg points here) */
    struct sim_physics physics_hook;
    struct sim_error_model error_hook;
    /* injected faults (sim/part.h, sim_adis_imu_part) */
    bool dr_suppressed;         /* no data-ready pulses */
    bool dr_extra;              /* a spurious pulse halfway through every sample period */
    int dr_extra_ev;            /* its pending event, 0 when none */
    uint32_t dr_extra_pulses;   /* spurious pulses given */
    uint16_t fault_diag;        /* DIAG_STAT bits held on (device error) */
    uint16_t true_prod_id;      /* PROD_ID while a wrong identity is shown */
    struct sim_stuck_bit stuck; /* an injected stuck data bit */
    /* statistics */
    uint64_t samples;
    uint32_t dr_pulses, commands, flash_writes, spi_failures, protocol_errors;
};

int sim_adis_imu_init(struct sim_adis_imu *m, const struct sim_adis_imu_cfg *cfg);

/* Static physical input (used when no physics hook is set). */
void sim_adis_imu_set_input(struct sim_adis_imu *m, const struct sim_inertial_input *in);
/* Install (or with NULL remove) the physics and error-model hooks at run time: the same as
 * cfg.physics / cfg.error at init (the hook is copied into the model). */
void sim_adis_imu_set_physics(struct sim_adis_imu *m, const struct sim_physics *p);
void sim_adis_imu_set_error_model(struct sim_adis_imu *m, const struct sim_error_model *e);
/* Magnetic field in gauss (1640x), and the AUX_ADC input in volts. */
void sim_adis_imu_set_magn(struct sim_adis_imu *m, double x, double y, double z);
void sim_adis_imu_set_aux(struct sim_adis_imu *m, double volts);
/* DIAG_STAT bits the next internal self-test sets (0: pass). Bit 5 is added when non-zero. */
void sim_adis_imu_set_self_test_fail(struct sim_adis_imu *m, uint16_t diag_bits);
/* Set DIAG_STAT bits (fault injection: alarms, flash checksum...). */
void sim_adis_imu_raise_diag(struct sim_adis_imu *m, uint16_t diag_bits);

/* Back door: a register as stored (no ND/EA, no read side effects). addr even. */
uint16_t sim_adis_imu_peek(const struct sim_adis_imu *m, uint8_t addr);
/* Back door write of a whole register with the side effects of a bus write (mode change...). */
void sim_adis_imu_poke(struct sim_adis_imu *m, uint8_t addr, uint16_t value);

/*
 * The gyro output of axis 0..2 before quantisation, in deg/s: the filtered sensor value plus
 * the user offset (what the part would report with infinite resolution). Tests and the bias
 * benchmark of issue 5 read the achieved bias here.
 */
double sim_adis_imu_gyro_dps(const struct sim_adis_imu *m, unsigned axis);
/* The user offset of gyro axis 0..2 in deg/s (register x 0.0125). */
double sim_adis_imu_gyro_offset_dps(const struct sim_adis_imu *m, unsigned axis);
/* True while a command keeps the part busy. */
bool sim_adis_imu_is_busy(const struct sim_adis_imu *m);
/* Output rate in force, in SPS. */
double sim_adis_imu_rate_sps(const struct sim_adis_imu *m);

/*
 * The part interface (sim/part.h). Faults: wire ones (MISO stuck, corrupt frame), physics ones,
 * and in the model: wrong identity (PROD_ID + 1, a part number none of the variants has), busy
 * (for arg.duration_ns, no command behind it), no data-ready, device error (DIAG_STAT bits held
 * on, 0x0040 by default: EA in every output word), stuck bit (any register as read over the
 * bus, burst words included).
 */
struct sim_part;
extern const struct sim_part_ops sim_adis_imu_part_ops;
void sim_adis_imu_part(struct sim_adis_imu *m, struct sim_part *p);

/* Model constants the tests need (all [U] unless noted; see adis_imu.c). */
#define SIM_ADIS_IMU_STALL_NORMAL_NS 9000u
#define SIM_ADIS_IMU_STALL_LOW_POWER_NS 75000u
#define SIM_ADIS_IMU_DR_PULSE_NS 20000u
#define SIM_ADIS_IMU_AUTONULL_MS 50u
#define SIM_ADIS_IMU_FACTORY_RESTORE_MS 50u
#define SIM_ADIS_IMU_FLASH_UPDATE_MS 100u
#define SIM_ADIS_IMU_PRECISION_AUTONULL_MS 30000u /* [ADI-IMU-QS] */
#define SIM_ADIS_IMU_SELF_TEST_MS 12u

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_SIM_ADIS_IMU_H */
