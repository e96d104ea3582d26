/*
 * fixture.h - the simulated board with one ADIS1636x/1640x model and the driver, shared by the
 * tests in this directory. One global fixture (large structs stay off the stack under QEMU).
 *
 * Wiring: SPI on the board's sclk/mosi/miso and cs0; the part's DIO1 on dr0, DIO2 on dr1. The
 * driver's default config: the variant of the part, data-ready on dr0 (DIO1, active high).
 */
#ifndef ADIS_IMU_TEST_FIXTURE_H
#define ADIS_IMU_TEST_FIXTURE_H

#include "inclino/adis_imu.h"
#include "inclino/sim/adis_imu.h"
#include "inclino/sim/board.h"

struct fx {
    struct sim_board board;
    struct sim_adis_imu part;
    struct sim_adis_imu_cfg part_cfg;
    struct adis_imu imu;
    struct adis_imu_cfg cfg;
};

extern struct fx fx;

/* Board + model (power-on busy, then the driver's start-up wait), default driver config. */
void fx_setup(enum sim_adis_imu_variant v);
/* Same, but the model is configured by the caller's edits to fx.part_cfg after fx_prepare()
 * and started with fx_start(). */
void fx_prepare(enum sim_adis_imu_variant v);
void fx_start(void);
/* adis_imu_init(&fx.imu, &fx.cfg). */
int fx_init(void);
/* Total violations logged; prints the log when there are any (so a failing test shows them). */
unsigned fx_violations(void);
/* Advance virtual time. */
void fx_wait_ms(uint32_t ms);
/* Set the static input of the part and let its Bartlett filter settle (2 x 64 samples). */
void fx_set_input_settled(const struct sim_inertial_input *in);

#endif
