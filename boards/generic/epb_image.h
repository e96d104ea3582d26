/*
 * epb_image.h - the part of the inclino_epb firmware image shared by every target: board
 * wiring placeholders, the flash seam, and the EPB main loop on top of a HAL (epb_image.c).
 * Each target's main() brings up its HAL and calls epb_image_run().
 */
#ifndef INCLINO_EPB_IMAGE_H
#define INCLINO_EPB_IMAGE_H

#include "inclino/hal.h"

/* Run the EPB application on hal; never returns. */
void epb_image_run(const struct hal *hal);

#endif /* INCLINO_EPB_IMAGE_H */
