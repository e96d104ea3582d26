/*
 * app_adis.h - sensor adapter of the EPB application for the ADIS1636x/1640x driver
 * (module inclino_app; the interface is inclino/app_sensor.h).
 */
#ifndef INCLINO_APP_ADIS_H
#define INCLINO_APP_ADIS_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/app_sensor.h"
#include "inclino/adis_imu.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- ADIS1636x / ADIS1640x ---------------------------------------------------------------- */

/*
 * Reads through adis_imu_wait_dr (the part's data-ready line; timeout: three sample periods)
 * and a burst read. An ND-clear (stale) burst is read once more after the next data-ready.
 * Temperature: TEMP_OUT (1640x) or the mean of the three gyro temperatures (1636x), rounded.
 * Saturation: any gyro or accelerometer count at the end of the 14-bit range.
 * Identity: family ADIS163XX, product = PROD_ID (e.g. 16405), serial and lot ids read from the
 * part on the 1636x (SERIAL_NUM, LOT_ID1/2), 0 on the 1640x (they have none).
 */
struct app_adis {
    struct adis_imu *imu; /* initialised driver with data-ready configured */
    uint32_t reads, stale_retries;
};

/* Fill *out with an adapter over imu (imu must have passed adis_imu_init with a dr_pin).
 * INC_ERR_NULL; INC_ERR_STATE when the driver is not ready or data-ready is not configured. */
int app_adis_sensor(struct app_adis *ad, struct adis_imu *imu, struct app_sensor *out);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_APP_ADIS_H */
