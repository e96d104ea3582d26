/*
 * app_sensor.h - the sensor seen by the EPB application: one small ops struct (read the next
 * sample, report the part's identity) plus a context pointer, and the adapters that fill it from
 * the ADIS1636x/1640x and SCA3000 drivers (module inclino_app, prefix app_).
 *
 * A sample is in physical units, Q16.16 (inclino/fx.h): acceleration in g scaled with the part's
 * NOMINAL sensitivity (what the calibration record corrects, inclino/cal.h), angular rate in
 * deg/s, temperature in degC. The drivers' conversions are exact to 0.5 LSB Q16, so an adapter
 * adds no error of its own. Freestanding C11, no heap: adapters are caller-allocated structs.
 */
#ifndef INCLINO_APP_SENSOR_H
#define INCLINO_APP_SENSOR_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/adis_imu.h"
#include "inclino/calrec.h"
#include "inclino/error.h"
#include "inclino/fx.h"
#include "inclino/hal.h"
#include "inclino/sca3000.h"

#ifdef __cplusplus
extern "C" {
#endif

/* What a sample holds (struct app_sample.flags). */
#define APP_S_HAVE_GYRO 0x01u   /* gyro_dps is measured (else 0: an accelerometer-only part) */
#define APP_S_HAVE_TEMP 0x02u   /* temp_c is measured (else 0: a part without a temperature output) */
#define APP_S_ACCEL_SAT 0x04u   /* an accelerometer axis is at the end of its output range */
#define APP_S_GYRO_SAT 0x08u    /* a gyro axis is at the end of its output range */

struct app_sample {
    fx_q16_t accel_g[3];   /* g, Q16, nominal sensitivity, sensor frame x y z */
    fx_q16_t gyro_dps[3];  /* deg/s, Q16 (0 without APP_S_HAVE_GYRO) */
    fx_q16_t temp_c;       /* degC, Q16 (0 without APP_S_HAVE_TEMP) */
    uint32_t flags;        /* APP_S_* */
    uint32_t missed;       /* samples of the part lost before this one (missed data-ready) */
    uint64_t t_ns;         /* HAL time of the read */
};

struct app_sensor_ops {
    /* Wait for the part's next sample (data-ready, or its output rate where the part has no
     * data-ready line) and read it. 0, or the driver's negative code (the sample is not used). */
    int (*read)(void *ctx, struct app_sample *out);
    /* The identity the calibration record must be bound to (calrec.h binding table). */
    int (*identity)(void *ctx, struct calrec_binding *out);
};

struct app_sensor {
    const struct app_sensor_ops *ops;
    void *ctx;
};

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
    struct adis_imu *imu;  /* initialised driver with data-ready configured */
    uint32_t reads, stale_retries;
};

/* Fill *out with an adapter over imu (imu must have passed adis_imu_init with a dr_pin).
 * INC_ERR_NULL; INC_ERR_STATE when the driver is not ready or data-ready is not configured. */
int app_adis_sensor(struct app_adis *ad, struct adis_imu *imu, struct app_sensor *out);

/* ---- SCA3000 ------------------------------------------------------------------------------ */

/*
 * The SCA3000 has no data-ready output (sensors.md 1.6), so the adapter paces its reads at the
 * part's output data rate (sca3000_odr_mhz): each read waits until one output period after the
 * previous one (hal_delay_until) and then reads X, Y, Z (and the temperature on the D01). A read
 * that comes more than one period late reports the periods lost in `missed`.
 * Saturation: a count at -4096 or 4095. Identity: family SCA3000, product = the variant code
 * (CALREC_SCA3000_D01 ...), revision = REVID read at init.
 */
struct app_sca3000 {
    struct sca3000 *dev;   /* initialised driver, normal measurement mode */
    const struct hal *hal;
    uint32_t period_ns;    /* output period of the current mode, ns (rounded up) */
    uint64_t next_ns;      /* earliest time of the next read */
    bool started;
    uint32_t reads;
};

/* INC_ERR_NULL; INC_ERR_STATE when the driver is not ready or its mode has no output rate. */
int app_sca3000_sensor(struct app_sca3000 *ad, struct sca3000 *dev, const struct hal *hal,
                       struct app_sensor *out);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_APP_SENSOR_H */
