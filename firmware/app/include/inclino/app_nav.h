/*
 * app_nav.h - the navigation mode of the application ([KF-SCA3000]'s set-up: an SCA3000
 * accelerometer and an ADIS16255 yaw gyro on one bit-banged SPI bus, a GPS receiver on a UART),
 * module inclino_app, prefix app_nav_. docs/navigation.md.
 *
 * Two levels:
 *   - the processing (app_nav_gyro, app_nav_accel, app_nav_uart, app_nav_cycle): what happens
 *     to each gyro sample, each accelerometer sample, each chunk of UART bytes and each 13 ms
 *     cycle, on numbers alone (the simulated drives feed it directly);
 *   - the bus (app_nav_bus_init, app_nav_bus_poll): the two drivers on one struct spi_bus, each
 *     part with its own SPI mode and timing (ADIS16255: mode 3, 16-bit frames, 2 MHz, 30 us
 *     stall; SCA3000: mode 0, 8-bit frames, 500 kHz, 10 us stall: the bit-banged engine moves
 *     SCLK to the other idle level between them), each read at its own rate (ADIS16255 on its
 *     data-ready line at 256 SPS, SCA3000 paced by its output rate, 125 Hz on the E02), and the
 *     13 ms cycle. Scheduling: one loop, earliest deadline first over three deadlines (next gyro
 *     sample, next accelerometer sample, next cycle); a read that falls due while another is on
 *     the bus waits for it (reads are 0.1..0.2 ms, the periods 3.9, 8 and 13 ms: nothing is
 *     missed). Bus time is counted per part (app_nav_bus.bus_ns_*).
 *
 * Per gyro sample: rate -> nav_gyro (offset from the gate, averaging, heading). Per accel sample:
 * the stillness gate (still) on (gyro 0, 0, z; accel x, y, z) at the accelerometer's rate; a
 * window at rest while standing (speed below APP_NAV_REST_SPEED_Q16) hands the mean gyro rate
 * and the mean forward specific force of the stop's still windows so far to nav_gyro_offset
 * and nav_accel_rest; the forward axis is summed for the cycle's mean. Per UART chunk: the NMEA
 * parser; an RMC with a fix becomes nav_fix, valid at its arrival time minus the receiver's
 * latency (cfg.gps_latency_ns). Per cycle: nav_step with the cycle's mean forward acceleration.
 */
#ifndef INCLINO_APP_NAV_H
#define INCLINO_APP_NAV_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/adis16255.h"
#include "inclino/error.h"
#include "inclino/fx.h"
#include "inclino/gps_nmea.h"
#include "inclino/nav.h"
#include "inclino/sca3000.h"
#include "inclino/still.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Standing: below this speed (Q16 m/s, 0.3 m/s) a still window may set the gyro offset. */
#define APP_NAV_REST_SPEED_Q16 (FX_Q16_ONE * 3 / 10)
/* The offset is the mean of up to this many still windows of one stop. */
#define APP_NAV_REST_WINDOWS 64u

struct app_nav_cfg {
    struct nav_cfg nav;
    struct still_cfg still; /* units: gyro Q16 deg/s, accel Q16 g */
    uint64_t gps_latency_ns;
};

/* The defaults for an SCA3000 of lsb_ug micro-g per count: Q = 20 counts ([KF-SCA3000]), the
 * nav defaults, a 1 s stillness window at 125 Hz (2 windows), latency 80 ms. */
struct app_nav_cfg app_nav_default_cfg(uint32_t lsb_ug);

struct app_nav_stats {
    uint32_t gyro_samples, accel_samples, cycles;
    uint32_t nmea_sentences, nmea_errors, fixes, fixes_refused;
    uint32_t offsets; /* stillness windows that set the offset */
    int nmea_last_error;
    enum nmea_why nmea_last_why;
};

struct app_nav {
    struct app_nav_cfg cfg;
    struct nav nav;
    struct still still;
    struct nmea_parser nmea;
    fx_q16_t gyro_last;
    int64_t acc_sum;
    uint32_t acc_n;
    fx_q16_t acc_last;
    int64_t rest_gyro_sum, rest_acc_sum; /* window means of the current stop */
    uint32_t rest_n;
    struct app_nav_stats stats;
    bool ready;
};

int app_nav_init(struct app_nav *a, const struct app_nav_cfg *cfg);
/* One gyro sample (Q16 deg/s, yaw, left positive), dt since the previous one. */
int app_nav_gyro(struct app_nav *a, fx_q16_t rate_dps, uint32_t dt_ns);
/* One accelerometer sample (Q16 g, x forward, y left, z up). */
int app_nav_accel(struct app_nav *a, const fx_q16_t acc_g[3]);
/* UART bytes that arrived at t_arrival_ns on the nav clock (the sum of the cycle lengths given to
 * app_nav_cycle since init; app_nav_bus_uart converts from the HAL clock). Returns the fixes
 * used (>= 0). */
int app_nav_uart(struct app_nav *a, const char *data, size_t len, uint64_t t_arrival_ns);
/* The 13 ms cycle. */
int app_nav_cycle(struct app_nav *a, uint32_t dt_ns, struct nav_out *out);

/* ---- the bus ----------------------------------------------------------------------------- */

struct app_nav_bus {
    struct app_nav *nav;
    struct adis16255 gyro;
    struct sca3000 acc;
    const struct hal *hal;
    enum sca3000_variant acc_variant;
    uint64_t next_acc_ns, next_cycle_ns, last_gyro_ns, last_cycle_ns;
    uint64_t t_start_ns; /* HAL time of nav clock 0 */
    uint32_t acc_period_ns, cycle_ns;
    /* bus time (ns the reads took, CS fall to return) */
    uint64_t bus_ns_gyro, bus_ns_acc;
    uint32_t reads_gyro, reads_acc, errors_gyro, errors_acc, missed_gyro;
    int last_error;
};

struct app_nav_bus_cfg {
    const struct spi_bus *bus;
    const struct hal *hal;
    hal_pin_t gyro_cs, gyro_dr, acc_cs;
    enum sca3000_variant acc_variant;
    uint32_t cycle_ns;
};

/* Bring both parts up on the one bus (ADIS16255: 256 SPS, +-80 deg/s, data-ready on DIO0;
 * SCA3000 normal mode, SPI mode 0). Returns 0 or the drivers' error. */
int app_nav_bus_init(struct app_nav_bus *b, struct app_nav *nav, const struct app_nav_bus_cfg *c);
/* UART bytes that arrived now (HAL clock): app_nav_uart on the nav clock. */
int app_nav_bus_uart(struct app_nav_bus *b, const char *data, size_t len);
/* Run the scheduler until the hal clock reaches until_ns; every completed cycle's output goes to
 * *out (the last one). Returns the cycles completed or a negative error. */
int app_nav_bus_run(struct app_nav_bus *b, uint64_t until_ns, struct nav_out *out);

#ifdef __cplusplus
}
#endif

#endif
