/*
 * sim/faultmx_drive.h - the fault matrix of the driving (ESC) attitude output (module
 * inclino_sim_faultmx, prefix fmxd_). docs/safety.md, "The driving matrix".
 *
 * One case: a sim/vehicle scenario (seed, the ADIS16405-class IMU at 819.2 SPS with a residual
 * accelerometer bias of 1 mg, the part after end-of-line calibration), the application in ESC
 * mode (app_esc_step over app_step, as tools/can_run runs it), the vehicle speed through the
 * E2E-protected speed frame every 16 samples and the application's receiver
 * (can_speed_rx_cycle, timeout 5 frames), and optionally an SCA3000-D01-class accelerometer
 * beside the IMU (250 SPS, sample and hold, 0.75 mg LSB, 5 mg rms noise, +-3 g, 1 mg residual
 * bias) for the two-sensor cross-check. The fault is injected at the sample level from onset_s:
 * into the IMU's sample, the speed frames, the second accelerometer, or as the read error the
 * driver returns (INC_ERR_BUS: what the ADIS driver reports for a stuck MISO, a corrupted frame,
 * its error flag or a wrong identity, independent of the mode).
 *
 * Every DRIVING output (the attitude: roll, pitch, bound, valid) after the onset is compared
 * with the truth (sim/vehicle's quaternion): its error is the largest of |roll error|,
 * |pitch error| and the inclination error (the angle between the true and estimated "up").
 * Host simulation code (double precision).
 */
#ifndef INCLINO_SIM_FAULTMX_DRIVE_H
#define INCLINO_SIM_FAULTMX_DRIVE_H

#include <stdbool.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

enum fmxd_fault {
    FMXD_NONE = 0,
    FMXD_STUCK_ACC,    /* one accelerometer axis (axis) keeps its value at the onset */
    FMXD_STUCK_GYRO,   /* one gyro axis keeps its value at the onset */
    FMXD_FROZEN,       /* the whole sample (gyro, accel, temperature) repeats */
    FMXD_BIAS_ACC,     /* accelerometer axis + amp g */
    FMXD_BIAS_GYRO,    /* gyro axis + amp deg/s */
    FMXD_NOISE_BURST,  /* + N(0, amp g) on the three accelerometer axes for 1 s */
    FMXD_SATURATION,   /* the accelerometer axis at its range (18 g, flagged saturated) */
    FMXD_DRIFT_ACC,    /* accelerometer axis + amp g/s x (t - onset) */
    FMXD_DRIFT_GYRO,   /* gyro axis + amp deg/s per s x (t - onset) */
    FMXD_SPEED_LOST,   /* no speed frame from the onset on (the receiver times out) */
    FMXD_SPEED_FROZEN, /* the same speed frame again and again (counter too: E2E REPEATED) */
    FMXD_SPEED_STUCK,  /* the sender's speed value stuck at its onset value, E2E intact */
    FMXD_AUX_BIAS,     /* the second accelerometer's axis + amp g (two-sensor disagreement) */
    FMXD_READ_ERROR,   /* the IMU driver returns INC_ERR_BUS for amp s (a bus fault) */
    FMXD_FAULTS
};

const char *fmxd_fault_name(enum fmxd_fault f);

struct fmxd_case {
    enum fmxd_fault fault;
    const char *scenario; /* a sim/vehicle preset name */
    double amp;
    double onset_s; /* from the start of the scenario (5 s at rest first) */
    unsigned axis;  /* 0 x, 1 y, 2 z */
};

struct fmxd_setup {
    uint64_t seed;
    bool diagnostics; /* app_esc_diag_default (false: the driving diagnostics off) */
    bool aux;         /* the second accelerometer fitted */
};

struct fmxd_result {
    int modelled;         /* 1 (every case is) */
    bool detected;        /* a read error, or an output after the onset not valid with a fault
                              bit (APP_ESC_D_*, ATT_FAULT_*) */
    uint32_t latency;     /* samples from the onset to the detection (UINT32_MAX: none) */
    uint32_t outputs;     /* DRIVING outputs after the onset */
    uint32_t valid;       /* of them valid */
    uint32_t valid_wrong; /* valid with error > bound */
    uint32_t read_errors;
    uint32_t diag_word;    /* OR of APP_ESC_D_* over the outputs after the onset */
    uint32_t att_word;     /* OR of ATT_FAULT_* */
    uint8_t false_diag;    /* latched APP_ESC_D_FLAT/VEH/XCHK bits set before the onset */
    double max_err_deg;    /* largest error of a valid output after the onset */
    double bound_deg;      /* its bound */
    double max_veh_ratio;  /* largest vehicle-check level / threshold seen (diagnostics on) */
    double max_xchk_g;     /* largest cross-check level seen, g */
    uint32_t valid_before; /* DRIVING outputs valid before the onset */
    double max_bound_deg;  /* largest bound of a valid output after the onset */
    uint32_t valid_b[3];   /* valid outputs after the onset with bound <= 2, 5, 10 deg */
};

/* Run one case. 0, or an error of the simulation or the application. */
int fmxd_run(const struct fmxd_setup *s, const struct fmxd_case *c, struct fmxd_result *out);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_SIM_FAULTMX_DRIVE_H */
