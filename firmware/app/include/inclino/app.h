/*
 * app.h - the EPB application: what the firmware image runs on top of the HAL.
 *
 * For now only the start-up contract: the image's main() brings up its HAL port and hands the
 * struct hal over; the EPB pipeline (sensors, calibration, averaging, tilt) grows here.
 */
#ifndef INCLINO_APP_H
#define INCLINO_APP_H

#include "inclino/hal.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Validate the HAL and start the application. Returns 0 or INC_ERR_NULL (hal incomplete). */
int app_init(const struct hal *hal);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_APP_H */
