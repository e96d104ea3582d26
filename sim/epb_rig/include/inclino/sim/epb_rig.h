/*
 * sim/epb_rig.h - the EPB demo's rig (module inclino_epb_rig, prefix epb_rig_): one simulated
 * board with one inertial part (ADIS1636x/1640x or SCA3000 pin-level model) carrying the errors
 * calibration removes (sim/calpart.h), an emulated NOR flash for the calibration store, the real
 * drivers (as a struct sensor, inclino/sensor.h) and the EPB application (inclino/app.h) on top, and the physics
 * the part feels:
 *
 *   STATION  the end-of-line station: the part lies on one of its six faces (enum cal_face) in a
 *            chamber at a set temperature (the soak itself is not simulated in time: the chamber
 *            is taken as settled).
 *   VEHICLE  the part in a parked car (x forward, y left, z up): slope (nose up positive) and
 *            cross slope, engine idling, small random bumps (passengers, doors), optionally the
 *            car driving off. The model is documented in docs/epb-demo.md ("Vibration model"):
 *              engine   sinusoids at engine orders 0.5, 1, 2, 4 of the idle speed (750 rpm: 2nd
 *                       order 25 Hz dominant for a four-cylinder), amplitudes in g per axis and a
 *                       small angular rate, phases drawn from the seed;
 *              bumps    Poisson arrivals; each a damped body-bounce oscillation (1.4 Hz, zeta
 *                       0.3) in z and in pitch (the true attitude rocks, the gyro sees the rate);
 *              driving  from drive_off_s: a longitudinal acceleration ramp, squat, road noise.
 *
 * Plain C (sim/ rules): also builds for the QEMU tests; doubles are simulation only.
 * Deterministic for a given seed.
 */
#ifndef INCLINO_SIM_EPB_RIG_H
#define INCLINO_SIM_EPB_RIG_H

#include <stdbool.h>
#include <stdint.h>

#include <stdio.h>

#include "inclino/app.h"
#include "inclino/calstore.h"
#include "inclino/sim/calpart.h"
#include "inclino/sim/pinbus.h"
#include "inclino/sim/vcd.h"

#ifdef __cplusplus
extern "C" {
#endif

enum epb_rig_part {
    EPB_RIG_ADIS16405 = 0,
    EPB_RIG_ADIS16400,
    EPB_RIG_ADIS16364,
    EPB_RIG_ADIS16362,
    EPB_RIG_SCA3000_D01,
    EPB_RIG_SCA3000_E02,
    EPB_RIG_PARTS
};

struct epb_rig_part_info {
    const char *name;    /* "adis16405", "sca3000-d01", ... (command-line name) */
    bool adis;           /* ADIS1636x/1640x (else SCA3000) */
    int sim_variant;     /* enum sim_adis_imu_variant or enum sim_sca3000_variant */
    double acc_lsb_g;    /* accelerometer output LSB, g */
    double gyro_lsb_dps; /* gyro LSB (+-300 deg/s range), deg/s; 0 without gyro */
    double temp_lsb_c;   /* temperature LSB, degC; 0 without temperature output */
    double rate_sps;     /* output rate the firmware runs the part at */
    double range_g;      /* accelerometer output range (saturation), g */
};

/* The table entry of a part (NULL when out of range) and the part of a command-line name. */
const struct epb_rig_part_info *epb_rig_part_get(enum epb_rig_part p);
int epb_rig_part_from_name(const char *name, enum epb_rig_part *out);

enum epb_rig_mode { EPB_RIG_STATION = 0, EPB_RIG_VEHICLE = 1 };

#define EPB_RIG_ORDERS 4 /* engine orders modelled */
#define EPB_RIG_BUMPS 16 /* bumps ringing at once (the oldest is dropped) */

struct epb_rig_order {
    double order;      /* multiple of the crank frequency */
    double amp_g[3];   /* x y z, g */
    double amp_dps[3]; /* angular vibration, deg/s */
};

struct epb_rig_vehicle {
    double slope_deg; /* nose up positive (10 % grade = 5.71 deg) */
    double roll_deg;  /* cross slope, left side up positive */
    double temp_c;    /* die temperature */
    double idle_rpm;  /* 0: engine off */
    struct epb_rig_order orders[EPB_RIG_ORDERS];
    double bump_rate_hz;    /* mean bumps per second (0: none) */
    double bump_amp_g;      /* largest bump, z, g */
    double bump_pitch_deg;  /* largest bump, pitch, deg */
    double bump_freq_hz;    /* body bounce frequency */
    double bump_zeta;       /* its damping ratio */
    double drive_off_s;     /* < 0: parked for good; else the car drives off at this time */
    double drive_accel_g;   /* longitudinal acceleration reached 1 s after drive-off */
    double drive_squat_deg; /* pitch change while accelerating */
    double road_noise_g;    /* rms road vibration while driving (z; x, y at 40 %) */
};

/* The default parked car: 10 % grade, 25 degC, engine idling at 750 rpm (four-cylinder orders
 * 0.5/1/2/4), bumps 0.3 per s of at most 8 mg and 0.02 deg, parked for good. */
void epb_rig_vehicle_default(struct epb_rig_vehicle *v);

/* The rig's state; its definition is in inclino/sim/epb_rig_state.h (C only: the drivers'
 * headers do not compile as C++ under -Wshadow). C++ code uses epb_rig_instance(). */
struct epb_rig;

/*
 * Set up board, part model (errors: NULL = sim_calpart_paper(), [ADI-EPB]/[TEMP-LORENTZ]'s part "A"),
 * flash (erased) and the station physics (face ZP, 25 degC). The part is powered and past its
 * start-up time. 0 or an error of the parts.
 */
int epb_rig_init(struct epb_rig *r, enum epb_rig_part part, const struct sim_calpart_params *errors,
                 uint64_t seed);

/*
 * Power the MCU up (again): fresh driver, adapter, calibration store over the same flash and
 * application instance (app_init with cfg: the record is loaded here). For the ADIS parts the
 * driver runs the part at 819.2 SPS with its own filter off (SENS_AVG M = 0, +-300 deg/s).
 * Returns 0 or the first error (driver init, app_init).
 */
int epb_rig_power_up(struct epb_rig *r, const struct app_cfg *cfg);

/*
 * The MCU board the firmware runs on. EPB_RIG_BOARD_SIM (the default): the simulated board's
 * HAL port (sim/hal_sim) and SPI master. EPB_RIG_BOARD_S32K144: the S32K144EVB through the S32K1
 * port's own code (hal/port/s32k1, boards/s32k1, the _sim build) against the register models
 * of sim/models/s32k1 (core/NVIC, LPIT0 time base, PORT/GPIO wired to the same pin bus); the
 * part model, physics and flash are the same.
 */
enum epb_rig_board { EPB_RIG_BOARD_SIM = 0, EPB_RIG_BOARD_S32K144 = 1 };

/* Choose the board (after epb_rig_init, before the first epb_rig_power_up). 0 or an error of
 * the models or of the board's bring-up. The S32K144 board's SPI engine is the bit-banged one. */
int epb_rig_set_board(struct epb_rig *r, enum epb_rig_board board);

/* The same with the SPI engine chosen: lpspi = true runs the drivers through LPSPI0
 * (drivers/spi_lpspi) against its register model (sim/models/s32k1/lpspi) on the same wires,
 * the part's CS on the PCS the board gives it. EPB_RIG_BOARD_SIM has no LPSPI: INC_ERR_INVAL.
 * A part whose CS is no LPSPI0 PCS on the board (the SCA3000 on PTD3): INC_ERR_UNSUPPORTED. */
int epb_rig_set_board_spi(struct epb_rig *r, enum epb_rig_board board, bool lpspi);

/* The firmware's sample rate for this part, milli-samples/s (for app_cfg_default). */
uint32_t epb_rig_rate_mhz(const struct epb_rig *r);

/* The specific force (g, part frame) on `face` (enum cal_face; out of range: CAL_FACE_ZP). */
void epb_rig_face_dir(int face, double dir[3]);

/* Station physics: the part on `face` (enum cal_face) at temp_c. */
void epb_rig_station(struct epb_rig *r, int face, double temp_c);

/* Station physics: the part held still at temp_c, feeling the specific force dir (g, part
 * frame; a unit vector for a part at rest), e.g. on the station's tilt table during the
 * nonlinearity sweep. */
void epb_rig_station_dir(struct epb_rig *r, const double dir[3], double temp_c);

/* Vehicle physics from now on (scenario time 0 = now): the car parks (or drives, see v). */
void epb_rig_park(struct epb_rig *r, const struct epb_rig_vehicle *v);

/* Let virtual time pass (the part keeps sampling). */
void epb_rig_wait(struct epb_rig *r, double seconds);

/* Scenario time of the vehicle (s since epb_rig_vehicle), and virtual time (s). */
double epb_rig_scenario_s(const struct epb_rig *r);
double epb_rig_now_s(const struct epb_rig *r);

/* Timing/protocol violations seen by the part (sim_violation_log total). */
unsigned epb_rig_violations(const struct epb_rig *r);

/* The process's rig (static storage: no heap), for callers that cannot allocate the struct. */
struct epb_rig *epb_rig_instance(void);

/* Parts of the rig. */
const struct epb_rig_part_info *epb_rig_info(const struct epb_rig *r);
struct app *epb_rig_app(struct epb_rig *r);
const struct sensor *epb_rig_sensor(const struct epb_rig *r);
struct calstore *epb_rig_store(struct epb_rig *r);
struct sim_pinbus *epb_rig_pinbus(struct epb_rig *r);
/* Start a VCD of the SPI pins and the part's data-ready line (sim_vcd_open). */
int epb_rig_vcd_open(struct epb_rig *r, struct sim_vcd *v, const char *path);
/* Print the violation log (when there is any violation). */
void epb_rig_print_violations(const struct epb_rig *r, FILE *out);
/* Bumps begun since epb_rig_park. */
unsigned epb_rig_bump_count(const struct epb_rig *r);

/* The true specific force and rate at scenario time t (what the physics hook gives the part
 * before its errors). */
void epb_rig_truth(struct epb_rig *r, double t_s, double accel_g[3], double rate_dps[3]);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_SIM_EPB_RIG_H */
