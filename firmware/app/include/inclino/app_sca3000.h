/*
 * app_sca3000.h - sensor adapter of the EPB application for the SCA3000 driver
 * (module inclino_app; the interface is inclino/app_sensor.h).
 */
#ifndef INCLINO_APP_SCA3000_H
#define INCLINO_APP_SCA3000_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/app_sensor.h"
#include "inclino/hal.h"
#include "inclino/sca3000.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- SCA3000 ------------------------------------------------------------------------------ */

/*
 * The SCA3000 has no data-ready output (docs/sensor-facts.md §1.6), so the adapter paces its reads at the
 * part's output data rate (sca3000_odr_mhz): each read waits until one output period after the
 * previous one (hal_delay_until; the first waits one period too, so that no sample from before the
 * adapter started is used) and then reads X, Y, Z (and the temperature on the D01). A read
 * that comes more than one period late reports the periods lost in `missed`.
 * Saturation: a count at -4096 or 4095. Identity: family SCA3000, product = the variant code
 * (CALREC_SCA3000_D01 ...), revision = REVID read at init.
 */
struct app_sca3000 {
    struct sca3000 *dev; /* initialised driver, normal measurement mode */
    const struct hal *hal;
    uint32_t period_ns; /* output period of the current mode, ns (rounded up) */
    uint64_t next_ns;   /* earliest time of the next read */
    bool started;
    uint32_t reads;
};

/* INC_ERR_NULL; INC_ERR_STATE when the driver is not ready or its mode has no output rate. */
int app_sca3000_sensor(struct app_sca3000 *ad, struct sca3000 *dev, const struct hal *hal,
                       struct app_sensor *out);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_APP_SCA3000_H */
