/*
 * sim/faultmx.h - the fault matrix of the EPB path (module inclino_sim_faultmx, prefix fmx_).
 *
 * One case = one fault of enum fmx_fault, with an amplitude and an onset, injected into the EPB
 * rig (sim/epb_rig.h) through the simulated-part interface (sim/part.h) or, for the record
 * faults, into the simulated flash before the power-up. The rig runs a parked measurement of
 * `blocks` estimates (app_step, as epb_demo does) after the ECU wakes up; the fault comes on
 * onset_s seconds after the first sample of the measurement. Each estimate is compared with
 * the true slope: an estimate marked valid whose |error| exceeds its own bound is
 * "valid-but-wrong". The verdict of a case:
 *   detected  the power-up refused the part or the record (init status != 0, or the record not
 *             loaded), or an estimate ending after the onset is not valid, or reads fail;
 *   latency   samples from the onset to the end of the first estimate not valid (0 when the
 *             power-up refused), UINT32_MAX when never;
 *   harmless  not detected and no valid-but-wrong estimate.
 *
 * The set-up (fmx_setup) holds the calibrated flash image the end of line left (taken once by
 * fmx_capture after an end of line on the rig), so cases run independently of each other and in
 * any order. Plain C (sim/ rules), deterministic for a given setup and case.
 */
#ifndef INCLINO_SIM_FAULTMX_H
#define INCLINO_SIM_FAULTMX_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/app.h"
#include "inclino/calrec.h"
#include "inclino/sim/calpart.h"
#include "inclino/sim/epb_rig.h"

#ifdef __cplusplus
extern "C" {
#endif

enum fmx_fault {
    FMX_NONE = 0,      /* no fault: the false-alarm reference */
    FMX_STUCK_OUTPUT,  /* slope-axis accelerometer output constant at amp g */
    FMX_FROZEN,        /* the sensing element repeats its last value (all channels) */
    FMX_BIAS_ACC,      /* slope-axis accelerometer bias step of amp g */
    FMX_BIAS_GYRO,     /* pitch-rate (y) gyro bias step of amp deg/s */
    FMX_NOISE_BURST,   /* + amp g x N(0,1) on the accelerometers for 1 s */
    FMX_SATURATION,    /* slope-axis accelerometer at amp g (beyond its range) */
    FMX_DRIFT,         /* slope-axis accelerometer bias ramp of amp g/s */
    FMX_MISO_HIGH,     /* MISO stuck high from the onset */
    FMX_MISO_LOW,      /* MISO stuck low from the onset */
    FMX_BIT_FLIP,      /* bit `bit` of every MISO word flipped during one read */
    FMX_CORRUPT_FRAME, /* every MISO word XOR 0x0101 from the onset */
    FMX_MISSED_DR,     /* no data-ready for amp s from the onset */
    FMX_DEVICE_ERROR,  /* the part's error flag from the onset */
    FMX_WRONG_ID,      /* the part identifies as another one at the power-up (reset) */
    FMX_STUCK_BIT,     /* data bit `bit` of the slope-axis register reads 1 from the onset */
    FMX_REC_TORN,      /* the record's last program unit not written (power loss) */
    FMX_REC_CORRUPT,   /* one bit of the stored record flipped */
    FMX_REC_OFFSET,    /* the station wrote a record (correct CRC) whose slope-axis offset is off
                          by amp g; the end-of-line verification (app_eol_verify) runs on it */
    FMX_REC_FOREIGN,   /* records bound to another part in both slots, correct CRC (ADIS: serial
                          + 1; SCA3000, which has no serial: revision + 1) */
    FMX_SUPPLY,        /* supply at amp V from the onset */
    FMX_TEMP_STUCK,    /* temperature reads amp degC from the onset (the car is at another) */
    FMX_TEMP_RANGE,    /* temperature reads amp degC (outside the part's range) */
    FMX_EXTRA_DR,      /* a spurious data-ready pulse halfway through every period from the
                          onset (no new sample behind it) */
    FMX_FAULTS
};

struct fmx_case {
    enum fmx_fault fault;
    double amp;            /* the fault's amplitude (unit of the fault above) */
    double onset_s;        /* after the first sample of the measurement */
    uint8_t bit;           /* FMX_BIT_FLIP, FMX_STUCK_BIT */
    double slope_step_deg; /* the true slope changes by this 1 s after the onset (0: never), e.g.
                              the car lifted or towed while the output is frozen */
};

struct fmx_setup {
    enum epb_rig_part part;
    struct sim_calpart_params type; /* the part's errors */
    uint64_t seed;
    struct app_cfg cfg;         /* with the budget the end of line derived */
    struct epb_rig_vehicle veh; /* the parked car */
    uint32_t blocks;            /* estimates per case */
    bool eol_verify;            /* the station verifies the record (app_eol_verify) */
    bool temp_ref;              /* a second temperature source is fitted (the ECU's board
                                      sensor, reading the car's temperature) */
    struct calrec rec;          /* the good record (as saved) */
    uint8_t flash[2048];        /* the flash image after the end of line */
};

struct fmx_result {
    int init_status;   /* epb_rig_power_up's status */
    int cal_status;    /* the application's calstore status (0: calibrated) */
    int inject_status; /* sim_part_inject's status (INC_ERR_UNSUPPORTED: not modelled) */
    int eol_status;    /* FMX_NONE, FMX_REC_OFFSET: the end-of-line verification's status
                           (INC_ERR_RANGE: the station rejected the unit); else 0 */
    double eol_dev_g;  /* its largest deviation over the six faces */
    bool detected;
    uint32_t latency;   /* samples, see above */
    uint32_t estimates; /* estimates ending after the onset */
    uint32_t valid;     /* of those, marked valid */
    uint32_t valid_wrong;
    uint32_t read_errors;
    uint32_t fault_word; /* OR of app flags | slope flags << 16 over the estimates after onset */
    double max_err_deg;  /* largest |error| of a valid estimate after the onset */
    double bound_deg;    /* the bound of that estimate (or of the last one) */
    double true_deg;
};

/* Name of a fault ("frozen", ...; "?" out of range). */
const char *fmx_fault_name(enum fmx_fault f);

/* After an end of line on the rig (the record saved by app_eol_save): keep its flash image and
 * the record in s (the other fields are the caller's). */
void fmx_capture(const struct epb_rig *r, const struct calrec *rec, struct fmx_setup *s);

/* Tolerance of the end-of-line verification: the calibrated faces within 5 mg of +-1 g (the
 * good record's residuals and the 1 s face noise stay below 3 mg on the simulated parts). */
#define FMX_EOL_VERIFY_TOL_G 0.005

/* Run one case on the process's rig (epb_rig_instance()). 0, or a set-up error of the rig. */
int fmx_run(const struct fmx_setup *s, const struct fmx_case *c, struct fmx_result *out);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_SIM_FAULTMX_H */
