/*
 * app_sensor.h - the sensor seen by the EPB application: one small ops struct (read the next
 * sample, report the part's identity) plus a context pointer (module inclino_app, prefix app_).
 * The adapters that fill it from the drivers: inclino/app_adis.h (ADIS1636x/1640x) and
 * inclino/app_sca3000.h (SCA3000); a replay fills it from recorded data (tools/imu_replay).
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

#include "inclino/calrec.h"
#include "inclino/error.h"
#include "inclino/fx.h"

#ifdef __cplusplus
extern "C" {
#endif

/* What a sample holds (struct app_sample.flags). */
#define APP_S_HAVE_GYRO 0x01u /* gyro_dps is measured (else 0: an accelerometer-only part) */
#define APP_S_HAVE_TEMP 0x02u /* temp_c is measured (else 0: a part without a temperature output) */
#define APP_S_ACCEL_SAT 0x04u /* an accelerometer axis is at the end of its output range */
#define APP_S_GYRO_SAT 0x08u  /* a gyro axis is at the end of its output range */

struct app_sample {
    fx_q16_t accel_g[3];  /* g, Q16, nominal sensitivity, sensor frame x y z */
    fx_q16_t gyro_dps[3]; /* deg/s, Q16 (0 without APP_S_HAVE_GYRO) */
    fx_q16_t temp_c;      /* degC, Q16 (0 without APP_S_HAVE_TEMP) */
    uint32_t flags;       /* APP_S_* */
    uint32_t missed;      /* samples of the part lost before this one (missed data-ready) */
    uint64_t t_ns;        /* HAL time of the read */
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

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_APP_SENSOR_H */
