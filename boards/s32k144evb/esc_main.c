/*
 * esc_main.c - the S32K144EVB ESC image: the ADIS IMU at 819.2 samples/s on the bit-banged
 * engine, the parked/driving application (inclino/app_esc.h: EPB blocks while parked, the
 * attitude estimator on every sample while driving), its outputs as CAN frames on FlexCAN0
 * (INC_Slope / INC_Attitude / INC_Status, AUTOSAR E2E Profile 1: docs/can.md, inclino.dbc) and
 * the vehicle speed frame (VEH_Speed, E2E checked by can_speed_rx) as the estimator's aiding,
 * with the driving diagnostics on (app_esc_diag_default: flat line, vehicle-level check).
 * The calibration record is on the FTFC data flash (boards/s32k1/s32k_image.c); the vectors are
 * in isr.c. docs/boards.md, "The ESC image".
 */
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "inclino/adis_imu.h"
#include "inclino/app.h"
#include "inclino/app_esc.h"
#include "inclino/calstore.h"
#include "inclino/can_frames.h"
#include "inclino/hal.h"
#include "inclino/s32k_flexcan.h"
#include "inclino/s32k_scg.h"
#include "inclino/s32k_wdog.h"
#include "inclino/sensor.h"
#include "epb_image.h"
#include "s32k_image.h"

/* The speed mailbox is read every ESC_SPEED_EVERY samples (19.5 ms at 819.2 SPS: the sender's
 * 20 ms period), and the speed counts as lost after ESC_SPEED_TIMEOUT such cycles without a
 * usable frame (inclino/can_frames.h). */
#define ESC_SPEED_EVERY 16u
#define ESC_SPEED_TIMEOUT 5u
#define ESC_RETRY_MS 100u

/* What a debugger (or a test bench) reads: outputs sent, frames that could not be queued, the
 * last error of the main loop. */
volatile uint32_t esc_out_count;
volatile uint32_t esc_tx_errors;
volatile int32_t esc_status;

static struct adis_imu imu;
static struct sensor sensor = {&adis_imu_sensor_ops, &imu};
static struct calstore store;
static struct app app;
static struct app_esc esc;
static struct s32k_flexcan can;
static struct can_tx tx;
static struct can_speed_rx srx;

/* The steps not inlined into main (link-time optimisation: main would then hold every step's
 * locals at once, and Reset_Handler's start-up area before the FCF would take main). */
static S32K1_STEP int up(void)
{
    const struct s32k_board *b = &s32k_image_board;
    struct epb_image_board eb;
    struct s32k_flexcan_cfg cc;
    static struct app_cfg acfg;
    static struct app_esc_cfg ecfg;
    const uint32_t rate = adis_imu_sample_rate_msps(ADIS_IMU_SMPL_PRD_DEFAULT);
    int err;
    eb.hal = &b->hal;
    eb.spi = b->spi;
    eb.cs = b->desc->pins.cs_imu;
    eb.dr = b->desc->pins.dr_imu;
    eb.per_result = NULL;
    eb.store = NULL;
    err = epb_image_adis_up(&imu, &eb);
    if (err == INC_OK) {
        err = calstore_init(&store, s32k_image_store(&s32k_board_s32k144evb));
    }
    if (err == INC_OK) {
        err = app_cfg_default(&acfg, rate);
    }
    if (err == INC_OK) {
        err = app_init(&app, &acfg, &sensor, &store);
    }
    if (err == INC_OK) {
        err = app_esc_cfg_default(&ecfg, rate);
    }
    if (err == INC_OK) {
        /* the flat-line and vehicle-level checks (no second accelerometer on this board:
         * the cross-check never runs) */
        err = app_esc_diag_default(&ecfg);
    }
    if (err == INC_OK) {
        err = app_esc_init(&esc, &ecfg);
    }
    if (err == INC_OK) {
        err = s32k_pcc_enable(S32K_PCC_FLEXCAN0, 0u);
    }
    if (err == INC_OK) {
        s32k_flexcan_cfg_default(&cc, CAN_ID_SPEED);
        err = s32k_flexcan_init(&can, &cc);
    }
    if (err == INC_OK) {
        err = can_tx_init(&tx);
    }
    if (err == INC_OK) {
        err = can_speed_rx_init(&srx, ESC_SPEED_TIMEOUT);
    }
    return err;
}

/* One speed cycle: the mailbox (or nothing) through the E2E receiver into *veh. */
static void speed_cycle(struct app_vehicle *veh)
{
    struct can_frame f;
    uint16_t id = 0u;
    uint8_t dlc = 0u;
    bool ovr = false;
    const int r = s32k_flexcan_receive(&can, &id, f.data, &dlc, &ovr);
    f.id = id;
    f.dlc = dlc;
    (void)can_speed_rx_cycle(&srx, r == INC_OK ? &f : NULL, veh);
}

/* Run until an error the loop cannot go on from; returns it. */
static S32K1_STEP int run(void)
{
    struct app_vehicle veh = {false, 0, 0};
    uint32_t n = 0u;
    for (;;) {
        struct sensor_sample s;
        struct app_esc_output out;
        struct can_frame fr[2];
        size_t nf = 0u, k;
        bool have = false;
        const int rerr = sensor_next(&sensor, 0u, &s);
        int err;
        if (++n >= ESC_SPEED_EVERY) {
            n = 0u;
            speed_cycle(&veh);
        }
        err = app_esc_step(&esc, &app, &s, rerr, &veh, &out, &have);
        if (err != INC_OK) {
            return err;
        }
        if (!have) {
            continue;
        }
        err = can_pack_output(&tx, &out, veh.valid, fr, &nf);
        if (err != INC_OK) {
            return err;
        }
        for (k = 0u; k < nf; k++) {
            if (s32k_flexcan_send(&can, (uint16_t)fr[k].id, fr[k].data, fr[k].dlc) != INC_OK) {
                esc_tx_errors = esc_tx_errors + 1u;
            }
        }
        esc_out_count = esc_out_count + 1u;
        s32k_wdog_refresh();
    }
}

S32K1_STEP int main(void)
{
    s32k_image_bringup(&s32k_board_s32k144evb);
    for (;;) {
        int err = up();
        if (err == INC_OK) {
            err = run();
        }
        esc_status = err;
        hal_delay_ms(&s32k_image_board.hal, ESC_RETRY_MS);
    }
}
