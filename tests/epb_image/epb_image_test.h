/*
 * epb_image_test.h - what the EPB image's loop tests share (tests/epb_image): the part they put
 * on the rig and the board the image runs on there.
 */
#ifndef INCLINO_EPB_IMAGE_TEST_H
#define INCLINO_EPB_IMAGE_TEST_H

#include "epb_image.h"
#include "inclino/sim/calpart.h"
#include "inclino/sim/epb_rig_state.h"

/* An ideal part but for offsets of 20 / -10 / 15 mg (x / y / z), gains of 1.02 (x) and 0.99 (z),
 * and 2 mg of noise: uncorrected, the x offset alone is 1.1 deg of slope. */
void epb_test_part(struct sim_calpart_params *p);

/* The image's board on the rig: the rig's HAL and bit-banged SPI, the part on CS 0 with data
 * ready on DR 0, hook after each result, the calibration store on store. */
void epb_test_board(struct epb_image_board *b, struct epb_rig *rig, void (*hook)(void),
                    const struct calstore_config *store);

#endif
