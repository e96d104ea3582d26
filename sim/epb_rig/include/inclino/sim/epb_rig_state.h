/*
 * sim/epb_rig_state.h - the state of the EPB demo's rig (see sim/epb_rig.h). C only: it holds
 * the drivers' and models' structs by value (caller-allocated, no heap).
 */
#ifndef INCLINO_SIM_EPB_RIG_STATE_H
#define INCLINO_SIM_EPB_RIG_STATE_H

#include "inclino/adis_imu.h"
#include "inclino/sca3000.h"
#include "inclino/sim/adis_imu.h"
#include "inclino/sim/board.h"
#include "inclino/sim/epb_rig.h"
#include "inclino/sim/s32k_core.h"
#include "inclino/sim/s32k_lpit.h"
#include "inclino/sim/s32k_lpspi.h"
#include "inclino/sim/s32k_port_gpio.h"
#include "inclino/sim/sca3000.h"
#include "inclino/s32k_board.h"
#include "inclino/simflash.h"

struct epb_rig_bump {
    double t0; /* start, s (scenario time) */
    double amp_g, pitch_deg;
};

struct epb_rig {
    enum epb_rig_part part;
    const struct epb_rig_part_info *info;
    struct sim_board board;
    struct sim_adis_imu adis;
    struct sim_sca3000 sca;
    struct sim_calpart errors;
    struct sim_error_model em;
    struct sim_physics phys;
    struct simflash flash;
    uint8_t flash_mem[2048];
    /* physics */
    enum epb_rig_mode mode;
    int face;              /* enum cal_face (station), or -1: held at station_dir */
    double station_dir[3]; /* station: the specific force the part feels, g (part frame) */
    double station_temp_c;
    struct epb_rig_vehicle veh;
    uint64_t t0_ns; /* start of the vehicle scenario */
    double phase[EPB_RIG_ORDERS][3];
    struct sim_rng rng; /* bumps and road noise */
    double next_bump_s;
    struct epb_rig_bump bumps[EPB_RIG_BUMPS];
    unsigned bump_count, bump_total;
    double last_pitch_deg; /* true pitch of the last physics sample (base + rocking) */
    /* the MCU board the firmware runs on (epb_rig_set_board) */
    enum epb_rig_board mcu;
    struct sim_s32k_core s32k_core;
    struct sim_s32k_lpit s32k_lpit;
    struct sim_s32k_port_gpio s32k_gpio;
    struct sim_s32k_lpspi s32k_lpspi; /* mapped when the board runs LPSPI */
    struct s32k_board s32k;
    /* firmware side (re-created at every power-up) */
    struct adis_imu imu;
    struct sca3000 sca_dev;
    struct sensor sensor; /* ops of the driver in use, dev = &imu or &sca_dev */
    struct calstore store;
    struct app app;
};

#endif /* INCLINO_SIM_EPB_RIG_STATE_H */
