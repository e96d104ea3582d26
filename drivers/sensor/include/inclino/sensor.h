/*
 * sensor.h - the one sensor interface of Inclino (module inclino_sensor, prefix sensor_).
 *
 * Every sensor driver (drivers/adis_imu, drivers/adis16255, drivers/sca3000) exports a const
 * struct sensor_ops; the application and the services reach a part only through a struct sensor
 * (ops + the driver's instance). A replay or a test fills the same struct from recorded data.
 * Freestanding C11, no heap: instances are caller-allocated.
 *
 * Units: a sample is in physical units, Q16.16 (inclino/fx.h): acceleration in g scaled with the
 * part's NOMINAL sensitivity (what the calibration record corrects), angular rate in deg/s,
 * temperature in degC, supply in V. The drivers' conversions are exact to 0.5 LSB of Q16.
 *
 * Errors (inclino/error.h): every op returns 0 or a negative code and never a plausible value
 * together with an error: on error a sample is not to be used, and sensor_read and sensor_next
 * zero it (no SENSOR_S_HAVE_* flag set); the other ops zero their output themselves.
 */
#ifndef INCLINO_SENSOR_H
#define INCLINO_SENSOR_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/error.h"
#include "inclino/fx.h"
#include "inclino/hal.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- A sample ----------------------------------------------------------------------------- */

/* What a sample holds (struct sensor_sample.flags). */
#define SENSOR_S_HAVE_ACCEL 0x0001u /* accel_g is measured */
#define SENSOR_S_HAVE_GYRO 0x0002u  /* gyro_dps is measured (else 0: an accelerometer-only part) */
#define SENSOR_S_HAVE_TEMP 0x0004u  /* temp_c is measured (else 0: no temperature output) */
#define SENSOR_S_ACCEL_SAT_X \
    0x0010u                         /* accel axis x at the end of its output range; y, z: << 1, 2 */
#define SENSOR_S_GYRO_SAT_X 0x0080u /* gyro axis x at the end of its output range; y, z: << 1, 2 */
#define SENSOR_S_ACCEL_SAT (SENSOR_S_ACCEL_SAT_X * 7u) /* any accelerometer axis saturated */
#define SENSOR_S_GYRO_SAT (SENSOR_S_GYRO_SAT_X * 7u)   /* any gyro axis saturated */

struct sensor_sample {
    fx_q16_t accel_g[3];  /* g, Q16, nominal sensitivity, sensor frame x y z */
    fx_q16_t gyro_dps[3]; /* deg/s, Q16 (0 without SENSOR_S_HAVE_GYRO) */
    fx_q16_t temp_c;      /* degC, Q16 (0 without SENSOR_S_HAVE_TEMP) */
    uint32_t flags;       /* SENSOR_S_* */
    uint32_t missed;      /* samples of the part lost before this one (missed data-ready) */
    uint64_t t_ns;        /* HAL time of the read */
};

/* ---- What the part is --------------------------------------------------------------------- */

/* Sensor families (the calibration record's binding table uses the same numbers). */
enum sensor_family {
    SENSOR_FAMILY_NONE = 0,
    SENSOR_FAMILY_SCA3000 = 1,
    SENSOR_FAMILY_ADIS1625X = 2,
    SENSOR_FAMILY_ADIS163XX = 3, /* ADIS1636x and ADIS1640x */
};

/* The identity a calibration record is bound to; fields a part does not have are 0. */
struct sensor_identity {
    uint32_t family;   /* enum sensor_family */
    uint32_t product;  /* e.g. 16405, 3000 */
    uint32_t revision; /* REVID where the part has one */
    uint32_t serial;
    uint32_t lot_id1;
    uint32_t lot_id2;
};

/* The configured measurement ranges and rate (for saturation handling and filters). */
struct sensor_info {
    fx_q16_t accel_fs_g;  /* full scale of each accelerometer axis, g (0: none) */
    fx_q16_t gyro_fs_dps; /* full scale of each gyro axis, deg/s (0: none) */
    uint32_t rate_mhz;    /* output data rate, milli-samples per second */
};

/* ---- Diagnostics -------------------------------------------------------------------------- */

#define SENSOR_D_SUPPLY 0x0001u    /* supply out of range */
#define SENSOR_D_SELF_TEST 0x0002u /* self-test failed */
#define SENSOR_D_OVERRANGE 0x0004u /* an output exceeded its range */
#define SENSOR_D_BUS 0x0008u       /* the part saw a bad SPI transfer */
#define SENSOR_D_MEMORY 0x0010u    /* flash/EEPROM update or checksum failure */
#define SENSOR_D_ALARM 0x0020u     /* a user alarm is active */
#define SENSOR_D_OTHER 0x8000u     /* another error bit the part defines */

struct sensor_diag {
    uint32_t flags;    /* SENSOR_D_*; 0 when the part reports nothing */
    uint32_t raw;      /* the part's own status word(s), for logs */
    fx_q16_t supply_v; /* measured supply, V Q16 (0 where the part has no supply output) */
};

/* ---- The ops table a driver exports ------------------------------------------------------- */

struct sensor_ops {
    /* Bring the part up with the driver's own configuration (struct <driver>_cfg). */
    int (*init)(void *dev, const void *cfg);
    /* Wait until the part has a new sample (data-ready edge, or the output period where the
     * part has no data-ready line), at most timeout_ns; 0: the driver's default (a few sample
     * periods). INC_ERR_TIMEOUT when none came. Samples the part made since the last one
     * handed out are reported in the next sample's `missed`. */
    int (*wait_ready)(void *dev, uint32_t timeout_ns);
    /* Read the newest sample. INC_ERR_STALE when the part had no new data. */
    int (*read)(void *dev, struct sensor_sample *out);
    /* Read the part's status. A part that reports an error makes this return 0 with flags set
     * (the read itself worked); INC_ERR_BUS etc. when the status could not be read. */
    int (*read_diag)(void *dev, struct sensor_diag *out);
    /* Run the part's self-test; INC_ERR_DEVICE when it fails (out says why). */
    int (*self_test)(void *dev, struct sensor_diag *out);
    /* The part's identity (what init found, and where the part has them its serial number and
     * lot ids, read on this call). INC_ERR_STATE before a successful init. */
    int (*identity)(void *dev, struct sensor_identity *out);
    /* The configured ranges and rate. INC_ERR_STATE before a successful init. */
    int (*info)(void *dev, struct sensor_info *out);
};

struct sensor {
    const struct sensor_ops *ops;
    void *dev; /* the driver's instance (struct adis_imu, struct sca3000, ...) */
};

/* Call wrappers: INC_ERR_NULL for a NULL sensor, ops, op or output, else what the op returns.
 * (identity and info are sensor_get_identity / sensor_get_info: in C++ a function may not share
 * its name with a struct.) */
int sensor_init(const struct sensor *s, const void *cfg);
int sensor_wait_ready(const struct sensor *s, uint32_t timeout_ns);
int sensor_read(const struct sensor *s, struct sensor_sample *out);
int sensor_read_diag(const struct sensor *s, struct sensor_diag *out);
int sensor_self_test(const struct sensor *s, struct sensor_diag *out);
int sensor_get_identity(const struct sensor *s, struct sensor_identity *out);
int sensor_get_info(const struct sensor *s, struct sensor_info *out);

/* The safe states of the three outputs, which every op writes on error: a zero sample with no
 * SENSOR_S_HAVE_* flag, an identity of family SENSOR_FAMILY_NONE, a diagnosis with no flag.
 * NULL is ignored. */
void sensor_sample_clear(struct sensor_sample *out);
void sensor_identity_clear(struct sensor_identity *out);
void sensor_diag_clear(struct sensor_diag *out);

/* Wait for the next sample and read it; a stale read (INC_ERR_STALE) is retried once after the
 * next wait. On any error *out is zeroed. INC_ERR_NULL for a NULL out, before any wait. */
int sensor_next(const struct sensor *s, uint32_t timeout_ns, struct sensor_sample *out);

/* ---- Data-ready edges ------------------------------------------------------------------ */

/*
 * Data-ready edges, counted in interrupt context and consumed by the driver: the one data-ready
 * helper of every driver (ADIS16255 and ADIS1636x/1640x data-ready, the SCA3000's INT line). The part pulses its data-ready line once per sample; the interrupt handler
 * only increments `count`, so an edge is never lost and edges the driver did not wait for are
 * counted (a missed sample is reported, not hidden). Unsigned wrap-around is harmless: only
 * count - taken is used.
 */
struct sensor_dr {
    volatile uint32_t count; /* edges seen (written in interrupt context only) */
    uint32_t taken;          /* count when the driver last consumed the edges */
};

/* Zero both counters (no interrupt may be attached yet). */
void sensor_dr_reset(struct sensor_dr *dr);

/* The interrupt handler to pass to hal_irq_attach, with arg = the struct sensor_dr. */
void sensor_dr_isr(void *arg);

/* Forget the edges seen so far (taken = count, in a critical section). */
void sensor_dr_sync(const struct hal *hal, struct sensor_dr *dr);

/*
 * Wait until at least one edge has come since the last consumption, or until the HAL clock
 * reaches deadline_ns. On an edge: consumes all pending edges, *pending (may be NULL) = their
 * number (>= 1; > 1 means samples were missed), INC_OK. At the deadline with no edge:
 * *pending = 0, INC_ERR_TIMEOUT. An edge that arrives exactly at the deadline is taken. Between
 * checks it sleeps in hal_irq_wait, which may return at any attached interrupt (another part's
 * too): it looks again either way.
 */
int sensor_dr_wait(const struct hal *hal, struct sensor_dr *dr, uint64_t deadline_ns,
                   uint32_t *pending);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_SENSOR_H */
