/*
 * s32k116evb.c - the S32K116EVB (S32K116, Cortex-M0+, FIRC 48 MHz) as the low-cost EPB board.
 * Pins and mux numbers: S32K116 IO signal table of [S32K1XXRM] and the board's user guide
 * [S32K116EVB-UG]; what is not confirmed is listed in docs/unconfirmed-facts.md ("S32K1
 * boards"). Wiring: docs/boards.md.
 */
#include "inclino/s32k_board.h"
#include "inclino/s32k_gpio.h"

const struct s32k_board_desc s32k_board_s32k116evb = {
    "s32k116evb",
    S32K_PART_116,
    S32K_CLOCK_FIRC_48,
    {
        S32K_PIN(1, 2), /* sclk    PTB2  LPSPI0_SCK  (ALT3) */
        S32K_PIN(1, 4), /* mosi    PTB4  LPSPI0_SOUT (ALT3) */
        S32K_PIN(1, 3), /* miso    PTB3  LPSPI0_SIN  (ALT3) */
        S32K_PIN(1, 5), /* cs_imu  PTB5  GPIO */
        S32K_PIN(3, 3), /* cs_acc  PTD3  GPIO */
        S32K_PIN(4, 2), /* dr_imu  PTE2  GPIO + IRQC (shared PORT vector 9) */
        S32K_PIN(4, 6), /* dr_acc  PTE6  GPIO + IRQC */
        S32K_PIN(4, 8), /* rst_imu PTE8  GPIO */
        S32K_PIN(4, 5), /* can_tx  PTE5  CAN0_TX (ALT5) */
        S32K_PIN(4, 4), /* can_rx  PTE4  CAN0_RX (ALT5) */
        3u,             /* LPSPI0 mux */
        5u,             /* CAN0 mux */
        1u, /* cs_imu LPSPI0 PCS: PTB5 ALT3 = LPSPI0_PCS1 as on the S32K144 (unconfirmed for the 48-pin S32K116) */
        S32K_BOARD_NO_PCS, /* cs_acc: no LPSPI0 PCS */
    },
};
