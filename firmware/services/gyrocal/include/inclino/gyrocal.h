/*
 * gyrocal.h - gyro bias calibration of the ADIS1636x/1640x (module inclino_gyrocal, prefix
 * gyrocal_), on top of the driver (inclino/adis_imu.h, its public functions only).
 * Freestanding C11, integer only, caller-allocated state. The three options of [ADI-IMU-QS]
 * ("optimising bias accuracy"):
 *
 *   AUTONULL   SMPL_PRD = 0x01, SENS_AVG M = 6 (64 taps per stage; range kept), 200 ms for the
 *              taps to fill, GLOB_CMD[0]: the part writes minus its output into XGYRO_OFF..
 *              Equivalent averaging time about 0.15 s; [ADI-IMU-QS]: about 0.08 deg/s.
 *   PRECISION  GLOB_CMD[4]: the part averages 30 s at its own settings and writes the offsets.
 *              [ADI-IMU-QS]: about 0.008 deg/s.
 *   MANUAL     SMPL_PRD = 0x01; wait for thermal settling (TEMP_OUT); average manual_samples
 *              ([ADI-IMU-QS]: 82 000, about 100 s at 819.2 SPS) of each gyro; offset = old - round(80 x
 *              mean deg/s), 13-bit two's complement (docs/sensor-facts.md §3.4; [ADI-IMU-QS] says 14-bit, see
 *              docs/gyro-calibration.md), saturating; write; GLOB_CMD[3] flash update (bit 3 =
 *              DIN 0xBE08; [ADI-IMU-QS] prints 0xBE04, which is bit 2, the AUX DAC latch).
 *              Also a processor-side correction at 1/320 deg/s ([ADI-IMU-QS]: the x320 variant for
 *              a 16-bit correction added to the output in the processor): the full correction
 *              (manual_to_register false: registers untouched) or the remainder the 0.0125 deg/s
 *              register cannot take (true). [ADI-IMU-QS]: about 0.006 deg/s.
 *
 * Gating: every mode REFUSES to start (nothing written) unless the stillness detector says
 * AT_REST and the thermal detector says SETTLED (MANUAL first waits up to settle_timeout_ms for
 * settling); feed them with gyrocal_feed() or gyrocal_monitor() beforehand. A mode ABORTS, and
 * puts the old offsets back, when the detectors see motion or a temperature change during it,
 * or when the verification after it fails. Saturation of an offset at the register limits is
 * not an abort: the saturated value is written (the best the register can do), the axis is
 * flagged and the call returns INC_ERR_RANGE.
 *
 * Residual estimate (1 sigma, per axis, deg/s Q16.16): sqrt(a^2 + q^2/12), with a the part's
 * Allan deviation at the mode's averaging time (cfg.adev_q16, [ADI-IMU-QS]'s figures by default) -
 * for MANUAL the larger of that and the measured standard error of the mean - and q the
 * resolution of the correction (0.0125 deg/s register, 1/320 deg/s processor-side).
 *
 * Verification (cfg.verify_samples > 0): after a mode, that many samples of the corrected
 * output; per axis |mean| must be <= verify_sigmas x sqrt(s^2/V + r^2) (s the samples' sd, r the
 * residual estimate). It catches what the part cannot report: motion during the 30 s precision
 * autonull, when the part is busy and no sample can be read.
 *
 * Units: detectors run on raw output counts (gyro at the range in force, accel at the variant's
 * LSB, TEMP_OUT counts); results are register counts, 1/320 deg/s units and Q16.16 deg/s.
 */
#ifndef INCLINO_GYROCAL_H
#define INCLINO_GYROCAL_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/adis_imu.h"
#include "inclino/error.h"
#include "inclino/still.h"

#ifdef __cplusplus
extern "C" {
#endif

enum gyrocal_mode {
    GYROCAL_AUTONULL = 0,
    GYROCAL_PRECISION = 1,
    GYROCAL_MANUAL = 2,
    GYROCAL_MODES = 3
};

/* Outcome of a run (also in the result when the return code is not 0). */
enum gyrocal_reason {
    GYROCAL_DONE = 0,
    GYROCAL_SATURATED,       /* done; an offset is at a register limit (INC_ERR_RANGE) */
    GYROCAL_REFUSED_MOVING,  /* not at rest when asked (INC_ERR_MOTION): nothing written */
    GYROCAL_REFUSED_THERMAL, /* temperature not settled (INC_ERR_THERMAL): nothing written */
    GYROCAL_ABORTED_MOTION,  /* motion during the procedure (INC_ERR_MOTION): old offsets back */
    GYROCAL_ABORTED_THERMAL, /* temperature moved during it (INC_ERR_THERMAL): old offsets */
    GYROCAL_ABORTED_VERIFY,  /* corrected output implausible afterwards (INC_ERR_ABORTED) */
    GYROCAL_FAILED_DEVICE,   /* bus or device error (the driver's code); old offsets put back
                                   if the bus still answers */
    GYROCAL_REASONS
};

/* "done", "refused: moving", ... (never NULL). */
const char *gyrocal_reason_text(enum gyrocal_reason r);

/* [ADI-IMU-QS]'s bias accuracies, deg/s Q16.16: autonull 0.08, precision 0.008, manual 0.006. */
#define GYROCAL_ADEV_AUTONULL_Q16 5243 /* 0.08 * 65536 = 5242.9 */
#define GYROCAL_ADEV_PRECISION_Q16 524 /* 0.008 */
#define GYROCAL_ADEV_MANUAL_Q16 393    /* 0.006 */
#define GYROCAL_MANUAL_SAMPLES 82000u  /* [ADI-IMU-QS]: about 100 s at 819.2 SPS */
#define GYROCAL_AUTONULL_M 6u          /* SENS_AVG = 0x06 */
#define GYROCAL_AUTONULL_FILL_MS 200u  /* [ADI-IMU-QS]: 200 ms for the taps to fill */
#define GYROCAL_PROC_PER_DPS 320       /* processor-side correction units per deg/s */

struct gyrocal_cfg {
    struct still_cfg still;           /* in output counts (see gyrocal_default_cfg) */
    struct still_thermal_cfg thermal; /* in TEMP_OUT counts */
    uint32_t settle_timeout_ms;       /* MANUAL: longest wait for settling; 0 = refuse at once */
    uint32_t manual_samples;          /* MANUAL: samples averaged, 2..2^24 */
    bool manual_to_register;          /* MANUAL: write XGYRO_OFF.. (else processor-side only) */
    bool flash_update;                /* MANUAL: GLOB_CMD[3] after writing ([ADI-IMU-QS] step 8) */
    int32_t adev_q16[GYROCAL_MODES];  /* Allan deviation at each mode's averaging time, > 0 */
    uint32_t verify_samples;          /* samples of the verification (0 = none), <= 2^24 */
    uint32_t verify_sigmas;           /* verification limit in sigmas, 1..100 */
};

/*
 * Defaults for a variant and gyro range, from [ADI-IMU-QS] and the fact sheet:
 *  still: 1 s windows (819 samples at 819.2 SPS), 2 in a row; gyro variance for "less than
 *   1 deg/s rms unfiltered" ([ADI-IMU-QS]) plus the 6-sigma margin of a 819-sample estimate; accel
 *   variance for 10 mg rms [U: no accelerometer noise figure in docs/references.md]; |gyro mean| <= 5 deg/s
 *   [U: above any uncalibrated bias]; | |a| - 1 g | <= 100 mg; accel drift <= 3 mg per window;
 *  thermal: 1 s points (819 samples), 30 s window, at most 1 TEMP_OUT LSB of change;
 *  manual: 82 000 samples, to the register, flash update, 15 min settling timeout ([ADI-IMU-QS]: up
 *   to 10 to 15 minutes); adev: [ADI-IMU-QS]'s figures; verification 1638 samples (2 s), 6 sigma.
 * INC_ERR_NULL / INC_ERR_INVAL (no variant info, unknown range).
 */
int gyrocal_default_cfg(struct gyrocal_cfg *cfg, const struct adis_imu_variant_info *vi,
                        enum adis_imu_range range);

/* The processor-side correction, in 1/320 deg/s per axis, to add to the output (after the
 * offset register). valid = false until a MANUAL run set it. */
struct gyrocal_correction {
    int16_t corr[3];
    bool valid;
};

struct gyrocal_result {
    uint8_t mode;                /* enum gyrocal_mode */
    uint8_t reason;              /* enum gyrocal_reason */
    int32_t old_offset[3];       /* XGYRO_OFF.. before, register counts */
    int32_t new_offset[3];       /* after (== old when refused or aborted) */
    bool saturated[3];           /* offset at a register limit */
    int16_t proc_corr[3];        /* processor-side correction in force after, 1/320 deg/s */
    bool proc_saturated[3];      /* it hit the int16 limits */
    int32_t mean_q16[3];         /* MANUAL: mean output over the average, deg/s Q16.16 */
    int32_t residual_q16[3];     /* residual estimate, 1 sigma, deg/s Q16.16 */
    int32_t verify_mean_q16[3];  /* corrected output mean in the verification, deg/s Q16.16 */
    int32_t verify_limit_q16[3]; /* its limit */
    uint32_t samples;            /* MANUAL: samples averaged */
    uint64_t t_avg_start_ns;     /* the span whose average the new offsets represent (HAL time): */
    uint64_t t_avg_end_ns;       /* AUTONULL the 2 x 64 - 1 filter taps before GLOB_CMD[0],
                                     PRECISION the 30 s after GLOB_CMD[4], MANUAL first to last
                                     sample; 0 when the mode did not get that far */
    uint32_t missed;             /* data-ready edges missed while reading */
    uint64_t t_start_ns, t_end_ns;
};

struct gyrocal {
    struct adis_imu *imu;
    struct gyrocal_cfg cfg;
    struct still still;
    struct still_thermal thermal;
    struct gyrocal_correction corr;
    uint32_t fed;    /* samples fed to the detectors */
    uint32_t missed; /* data-ready edges missed (monitoring included) */
    bool ready;
};

/* Bind to an initialised driver. INC_ERR_NULL, INC_ERR_STATE (driver not ready), INC_ERR_INVAL
 * (a configuration field out of range; the detectors' own checks included). */
int gyrocal_init(struct gyrocal *g, struct adis_imu *imu, const struct gyrocal_cfg *cfg);

/* Feed one sample the application read itself (gyro, accel and TEMP0 valid) to the detectors.
 * INC_ERR_STALE when the sample lacks one of those channels (not fed). */
int gyrocal_feed(struct gyrocal *g, const struct adis_imu_sample *s);

/* Read n samples (burst, at each data-ready; without data-ready every sample period) and feed
 * them. Driver errors are returned as they are. */
int gyrocal_monitor(struct gyrocal *g, uint32_t n);

/* Detector verdicts now. */
bool gyrocal_at_rest(const struct gyrocal *g);
bool gyrocal_settled(const struct gyrocal *g);

/*
 * Run one mode; *res (may not be NULL) is filled in every case. Returns 0 (DONE),
 * INC_ERR_RANGE (SATURATED: written and flagged), INC_ERR_MOTION (refused or aborted: moving),
 * INC_ERR_THERMAL (not settled), INC_ERR_ABORTED (verification failed), INC_ERR_STATE /
 * INC_ERR_INVAL (bad call), or the driver's error (FAILED_DEVICE).
 */
int gyrocal_run(struct gyrocal *g, enum gyrocal_mode mode, struct gyrocal_result *res);

/* The processor-side correction in force (a copy; valid false when none). */
struct gyrocal_correction gyrocal_correction_get(const struct gyrocal *g);

/*
 * gyro + corr / 320 deg/s, Q16.16 in and out: corr x 65536 / 320 = corr x 1024 / 5 rounded to
 * nearest (ties away from zero; |error| <= 0.5 LSB Q16 = 7.6e-6 deg/s), added with saturation.
 * Without a valid correction, or for axis > 2, gyro is returned unchanged.
 */
int32_t gyrocal_correct_q16(const struct gyrocal_correction *c, unsigned axis,
                            int32_t gyro_dps_q16);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_GYROCAL_H */
