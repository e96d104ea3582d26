/*
 * s32k_image.h - what the S32K1 board images share (s32k_image.c): the board object, the
 * bring-up, the calibration store on the FTFC data flash, and the EPB image's main loop. Each
 * board folder keeps only what differs: its descriptor and its interrupt vectors (the S32K144
 * has one PORT vector per port, the S32K116 one for all five), which call the bring-up's ISRs
 * on s32k_image_board.
 */
#ifndef INCLINO_S32K_IMAGE_H
#define INCLINO_S32K_IMAGE_H

#include "inclino/calstore.h"
#include "inclino/s32k_board.h"
#include "s32k1_startup.h"

/* The board the image runs on (its ISRs take it). */
extern struct s32k_board s32k_image_board;

/* S32K_IMAGE_LPSPI (a compile definition of the image, default 0): 0 brings the bit-banged engine
 * up (the LPSPI driver is not linked), 1 the LPSPI engine (LPSPI0, sleeping on its interrupt;
 * the bit-banged engine is not linked). */
#ifndef S32K_IMAGE_LPSPI
#define S32K_IMAGE_LPSPI 0
#endif

/* Clocks, pins, the HAL port (watchdog refreshed) and the engine of S32K_IMAGE_LPSPI on
 * s32k_image_board. When it fails it never returns: it stops refreshing, so the
 * watchdog resets the part and the bring-up is tried again. */
void s32k_image_bringup(const struct s32k_board_desc *desc);

/* The calibration store on sectors 0 and 1 of the FTFC data flash; when the part's FlexNVM
 * gives no usable D-flash (never partitioned: docs/boards.md, "Data flash"), the placeholder
 * flash whose every access fails (epb_image_no_flash), so the application runs uncalibrated and
 * says so. Never NULL. */
const struct calstore_config *s32k_image_store(const struct s32k_board_desc *desc);

/*
 * The EPB image: s32k_image_bringup, the store of s32k_image_store, and the EPB application
 * (boards/generic/epb_image.c) with the watchdog refreshed once per result. Never returns.
 */
void s32k_epb_main(const struct s32k_board_desc *desc);

#endif /* INCLINO_S32K_IMAGE_H */
