/*
 * adis_imu.h - driver for the Analog Devices six-axis iSensor IMUs ADIS16360/16362/16364/16365
 * (ADIS1636x) and ADIS16400/16405 (ADIS1640x).
 *
 * The driver talks to the part through the shared ADIS register protocol (inclino/adis.h) on one
 * struct spi_dev that it owns and re-times itself: SCLK <= 2 MHz in normal mode, <= 300 kHz in
 * low-power mode (the mode follows SMPL_PRD), <= 1 MHz for burst reads, with the stall between
 * frames of the current mode. Data-ready comes through the HAL (irq_attach + irq_wait). State is
 * caller-allocated (struct adis_imu), the configuration is a const struct, every fallible
 * function returns 0 or a negative enum inc_err code.
 *
 * Facts come from docs/sensor-facts.md §3-4 and [ADI-IMU-QS]; values the fact sheet marks
 * unconfirmed are named constants below tagged [U] and listed in docs/unconfirmed-facts.md.
 * docs/drivers-adis-imu.md describes the API, the protocol and the simulated part.
 *
 * Output words (docs/sensor-facts.md §3.3): bit 15 ND (new data since the register was last read), bit 14
 * EA (an error or alarm flag is set in DIAG_STAT), data in bits 13..0 (14-bit) or 11..0 (12-bit).
 * The driver never hands out a value silently: EA -> INC_ERR_DEVICE with DIAG_STAT read and kept,
 * ND clear -> the channel is stale (INC_ERR_STALE), a reply that cannot come from a live part
 * (all words 0x0000 or all 0xFFFF: no device, MISO stuck) -> INC_ERR_BUS.
 *
 * Blocking: a command (GLOB_CMD, self-test, reset) makes the part busy for its execution time,
 * during which it ignores the bus. The driver remembers until when; every later call waits that
 * deadline out before it touches the bus, so a request made while the part is busy is delayed,
 * never lost. adis_imu_busy() lets a caller avoid the wait.
 */
#ifndef INCLINO_ADIS_IMU_H
#define INCLINO_ADIS_IMU_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "inclino/adis.h"
#include "inclino/error.h"
#include "inclino/hal.h"
#include "inclino/sensor.h"
#include "inclino/spi.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------------------------------------
 * Variants
 * ------------------------------------------------------------------------------------------- */

enum adis_imu_variant {
    ADIS_IMU_ADIS16360 = 0,
    ADIS_IMU_ADIS16362 = 1,
    ADIS_IMU_ADIS16364 = 2,
    ADIS_IMU_ADIS16365 = 3,
    ADIS_IMU_ADIS16400 = 4,
    ADIS_IMU_ADIS16405 = 5,
    ADIS_IMU_VARIANT_COUNT = 6,
    ADIS_IMU_ANY = 0xFE,     /* config only: accept any known PROD_ID */
    ADIS_IMU_UNKNOWN = 0xFF, /* a PROD_ID that names none of the parts above */
};

enum adis_imu_family {
    ADIS_IMU_FAMILY_1636X = 0, /* three per-gyro temperatures, AUX_ADC at 0x16, 11-word burst */
    ADIS_IMU_FAMILY_1640X = 1, /* magnetometer, TEMP_OUT at 0x16, AUX_ADC at 0x18, 12-word burst */
};

/* PROD_ID = the part number in decimal (docs/sensor-facts.md §3.5). */
#define ADIS_IMU_PROD_ID_16360 0x3FE8u
#define ADIS_IMU_PROD_ID_16362 0x3FEAu
#define ADIS_IMU_PROD_ID_16364 0x3FECu
#define ADIS_IMU_PROD_ID_16365 0x3FEDu
#define ADIS_IMU_PROD_ID_16400 0x4010u
#define ADIS_IMU_PROD_ID_16405 0x4015u

struct adis_imu_variant_info {
    const char *name; /* "ADIS16405" */
    uint16_t prod_id;
    uint8_t family;            /* enum adis_imu_family */
    uint8_t burst_words;       /* output words after the burst command: 11 or 12 */
    uint16_t accel_lsb_ug;     /* XACCL_OUT LSB in micro-g: 3333, 333 or 1000 */
    uint16_t accel_off_lsb_ug; /* XACCL_OFF LSB in micro-g [U]: taken = the output LSB */
    uint8_t supply_bits;       /* SUPPLY_OUT width: 12 (1636x) or 14 (1640x [U]) */
    uint16_t reset_ms;         /* driver wait after a software reset */
    uint16_t self_test_ms;     /* driver wait after starting the internal self-test */
};

/* Table entry of a variant; NULL for ADIS_IMU_ANY, ADIS_IMU_UNKNOWN or anything out of range. */
const struct adis_imu_variant_info *adis_imu_variant_info(enum adis_imu_variant v);
/* The variant whose PROD_ID is id, or ADIS_IMU_UNKNOWN. */
enum adis_imu_variant adis_imu_variant_from_prod_id(uint16_t id);
/* "ADIS16405", ..., "unknown" (never NULL). */
const char *adis_imu_variant_name(enum adis_imu_variant v);

/* ---------------------------------------------------------------------------------------------
 * Register map: the addresses and the MSC_CTRL bits are the driver's business and live in its
 * private adis_imu_regs.h (drivers/adis_imu, not on the include path of callers). A caller that
 * reads a register by address (adis_imu_read_reg) names it through adis_imu_reg_map() /
 * adis_imu_reg_find() below, or is a white-box test that includes the private header.
 * ------------------------------------------------------------------------------------------- */


/* Access of a register. */
enum adis_imu_reg_access {
    ADIS_IMU_RO = 1, /* read-only */
    ADIS_IMU_RW = 3, /* read-write (byte writes) */
    ADIS_IMU_WO = 2, /* write-only (GLOB_CMD) */
};

struct adis_imu_reg_desc {
    const char *name; /* datasheet name */
    uint8_t addr;     /* even address */
    uint8_t bits;     /* data width (field below ND/EA for outputs) */
    uint8_t access;   /* enum adis_imu_reg_access */
    bool is_output;   /* carries ND (bit 15) and EA (bit 14) */
    bool is_signed;   /* two's complement data */
};

/* The register map of a family: *count entries in address order. NULL for a bad family. */
const struct adis_imu_reg_desc *adis_imu_reg_map(enum adis_imu_family f, size_t *count);
/* The entry of one address (even), or NULL when the family has no register there. */
const struct adis_imu_reg_desc *adis_imu_reg_find(enum adis_imu_family f, uint8_t addr);


/* GLOB_CMD bits (docs/sensor-facts.md §3.4); enum adis_imu_cmd values are these bits. */
enum adis_imu_cmd {
    ADIS_IMU_CMD_AUTONULL = 0x01,
    ADIS_IMU_CMD_FACTORY_RESTORE = 0x02,
    ADIS_IMU_CMD_AUX_DAC_LATCH = 0x04,
    ADIS_IMU_CMD_FLASH_UPDATE = 0x08,
    ADIS_IMU_CMD_PRECISION_AUTONULL = 0x10,
    ADIS_IMU_CMD_SW_RESET = 0x80,
};

/* DIAG_STAT bits (docs/sensor-facts.md §3.4). Every bit except 7 is an error or alarm (EA). */
#define ADIS_IMU_DIAG_SUPPLY_LOW 0x0001u   /* supply < 4.75 V */
#define ADIS_IMU_DIAG_SUPPLY_HIGH 0x0002u  /* supply > 5.25 V */
#define ADIS_IMU_DIAG_FLASH_UPDATE 0x0004u /* flash update failed */
#define ADIS_IMU_DIAG_SPI_FAIL 0x0008u     /* SPI communication failure */
#define ADIS_IMU_DIAG_OVERRANGE 0x0010u    /* a sensor is over its range */
#define ADIS_IMU_DIAG_SELF_TEST 0x0020u    /* self-test error */
#define ADIS_IMU_DIAG_FLASH_CHECKSUM 0x0040u
#define ADIS_IMU_DIAG_UNUSED 0x0080u /* always 0 on a live part: set -> bus fault */
#define ADIS_IMU_DIAG_ALARM1 0x0100u
#define ADIS_IMU_DIAG_ALARM2 0x0200u
#define ADIS_IMU_DIAG_ZGYRO_ST 0x0400u /* self-test failure of one sensor */
#define ADIS_IMU_DIAG_YGYRO_ST 0x0800u
#define ADIS_IMU_DIAG_XGYRO_ST 0x1000u
#define ADIS_IMU_DIAG_XACCL_ST 0x2000u
#define ADIS_IMU_DIAG_YACCL_ST 0x4000u
#define ADIS_IMU_DIAG_ZACCL_ST 0x8000u
#define ADIS_IMU_DIAG_ERRORS 0xFF7Fu
#define ADIS_IMU_DIAG_SELF_TEST_BITS 0xFC20u /* bit 5 and the per-sensor bits 10..15 */

/* DIAG_STAT decoded, one flag per bit. */
struct adis_imu_diag {
    bool supply_low, supply_high, flash_update_fail, spi_fail, overrange, self_test_fail,
        flash_checksum, alarm1, alarm2;
    bool gyro_st_fail[3];  /* x, y, z */
    bool accel_st_fail[3]; /* x, y, z */
    bool any;              /* any error bit */
};
void adis_imu_diag_decode(uint16_t diag, struct adis_imu_diag *out);
/* Name of DIAG_STAT bit 0..15 ("supply < 4.75 V", ..., "unused"), "" for bit > 15. */
const char *adis_imu_diag_bit_name(unsigned bit);

/* ---------------------------------------------------------------------------------------------
 * Timing (docs/sensor-facts.md §3.1, §3.4). Periods in ns, waits in ms. [U] = unconfirmed, safe side.
 * ------------------------------------------------------------------------------------------- */
#define ADIS_IMU_SCLK_PERIOD_NORMAL_NS 500u     /* <= 2 MHz while SMPL_PRD[7:0] <= 0x09 */
#define ADIS_IMU_SCLK_PERIOD_LOW_POWER_NS 3334u /* <= 300 kHz otherwise: ceil(1e9 / 300 kHz) */
#define ADIS_IMU_SCLK_PERIOD_BURST_NS 1000u     /* <= 1 MHz during a burst read */
/* [U] tSTALL: recollection 9 us (normal) / 75 us (low power); the OPTEC driver's 9 us works on
 * ADIS16405 hardware. The driver adds margin; Linux's flat 50 us is a driver choice, not a spec
 * (it would even be short of 75 us in low-power mode). */
#define ADIS_IMU_STALL_NORMAL_NS 10000u
#define ADIS_IMU_STALL_LOW_POWER_NS 80000u
/* [U] tCS recollection ~48.8 ns; CS setup and hold are taken at 100 ns. */
#define ADIS_IMU_CS_SETUP_NS 100u
#define ADIS_IMU_CS_HOLD_NS 100u
/* Burst words are separated by one SCLK period (docs/sensor-facts.md §3.1, B10-B12). */
#define ADIS_IMU_BURST_GAP_NS ADIS_IMU_SCLK_PERIOD_BURST_NS
/* SMPL_PRD[7:0] above this selects low-power mode (time-base bit 7 included). */
#define ADIS_IMU_SMPL_PRD_NORMAL_MAX 0x09u

/* Waits after commands (driver side; the part ignores the bus meanwhile). */
#define ADIS_IMU_AUTONULL_MS 50u              /* [U] ADI example's wait, no datasheet figure */
#define ADIS_IMU_FACTORY_RESTORE_MS 50u       /* [U] ADI example's wait */
#define ADIS_IMU_FLASH_UPDATE_MS 100u         /* [U] OPTEC's wait after the update */
#define ADIS_IMU_PRECISION_AUTONULL_MS 30000u /* [ADI-IMU-QS] and the ADI example: 30 s */
#define ADIS_IMU_AUX_DAC_LATCH_MS 0u
/* Power-on to first access: Linux STARTUP_DELAY 290 ms, the longest of 220/290 ms (ADIS16405)
 * and 180/250 ms (ADIS16367). The driver does not wait it (it cannot know when power came);
 * callers do, before adis_imu_init(). */
#define ADIS_IMU_STARTUP_MS 290u
/* Self-test: after the variant's self_test_ms, MSC_CTRL[10] is polled this often, this long. */
#define ADIS_IMU_SELF_TEST_POLL_MS 2u
#define ADIS_IMU_SELF_TEST_POLLS 10u

/* ---------------------------------------------------------------------------------------------
 * Sample rate (SMPL_PRD) and filter/range (SENS_AVG)
 * ------------------------------------------------------------------------------------------- */
#define ADIS_IMU_SMPL_PRD_TIMEBASE 0x80u /* bit 7: time base 31 x 0.6104 ms instead of 0.6104 */
#define ADIS_IMU_SMPL_PRD_NS_MASK 0x7Fu
#define ADIS_IMU_SMPL_PRD_DEFAULT 0x01u /* 819.2 SPS */

/*
 * Sample period in ns (rounded to nearest) for SMPL_PRD[7:0] = smpl_prd:
 * (NS + 1) x tB, tB = 1/1638.4 s = 610351.5625 ns, or 31 x that with bit 7 set (the Linux rate
 * constants 1638.404 and 52.851 SPS, docs/sensor-facts.md §3.4). 0x01 -> 1220703 ns (819.2 SPS).
 */
uint32_t adis_imu_sample_period_ns(uint8_t smpl_prd);
/* Sample rate in milli-samples/s, rounded to nearest: 0x01 -> 819200, 0x09 -> 163840. */
uint32_t adis_imu_sample_rate_msps(uint8_t smpl_prd);
/* True when SMPL_PRD puts the part in low-power mode (SCLK <= 300 kHz). */
bool adis_imu_smpl_prd_is_low_power(uint8_t smpl_prd);

/* Gyro range, SENS_AVG[10:8] [U encoding: 100 = 300, 010 = 150, 001 = 75 deg/s]. */
enum adis_imu_range {
    ADIS_IMU_RANGE_75 = 1,
    ADIS_IMU_RANGE_150 = 2,
    ADIS_IMU_RANGE_300 = 4,
};
#define ADIS_IMU_SENS_AVG_M_MASK 0x0007u
#define ADIS_IMU_SENS_AVG_M_MAX 6u /* N = 2^M taps per Bartlett stage, M <= 6 */
#define ADIS_IMU_SENS_AVG_RANGE_SHIFT 8u
#define ADIS_IMU_SENS_AVG_DEFAULT 0x0402u
/* [U] recollection: +-150 needs M >= 2, +-75 needs M >= 4; the driver refuses less. */
#define ADIS_IMU_RANGE_150_MIN_M 2u
#define ADIS_IMU_RANGE_75_MIN_M 4u

/* ---------------------------------------------------------------------------------------------
 * Raw -> physical (pure, integer only). One naming grammar in every driver:
 * <driver>_<quantity>_<unit>_from_<input>; a total function returns the value, a fallible one
 * returns 0 or a negative enum inc_err and writes the value through its last pointer (0 on error,
 * never a plausible value with an error). Every physical result is Q16.16 in int32_t (value x
 * 65536), computed as the exact rational and rounded to nearest, ties away from zero: the error
 * against exact math is <= 0.5 LSB of Q16.16 (2^-17) over the whole input range stated; nothing
 * saturates inside it. Inputs are counts (already sign-extended/masked), e.g. from
 * struct adis_imu_sample.counts.
 * ------------------------------------------------------------------------------------------- */
/* Gyro, deg/s. counts in [-8192, 8191]; LSB 0.05 (300), 0.025 (150), 0.0125 (75) deg/s.
 * Max |result| 409.6 deg/s. INC_ERR_NULL; INC_ERR_INVAL for a range other than the three. */
int adis_imu_gyro_dps_from_counts(int32_t counts, enum adis_imu_range range, int32_t *dps_q16);
/* Accelerometer, g. counts in [-8192, 8191]; lsb_ug from the variant (3333, 333, 1000) or any
 * 1..100000 (else INC_ERR_INVAL). INC_ERR_NULL. */
int adis_imu_accel_g_from_counts(int32_t counts, uint32_t lsb_ug, int32_t *g_q16);
/* Temperature, deg C: 25 + counts x 0.136 (1636x) or x 0.14 (1640x). counts in [-2048, 2047].
 * INC_ERR_NULL; INC_ERR_INVAL for another family. */
int adis_imu_temp_c_from_counts(int32_t counts, enum adis_imu_family f, int32_t *c_q16);
/* Supply, V: counts x 2.418 mV. counts in [0, 16383]. Total. */
int32_t adis_imu_supply_v_from_counts(int32_t counts);
/* Magnetometer, gauss: counts x 0.5 mgauss. counts in [-8192, 8191]. Total. */
int32_t adis_imu_magn_gauss_from_counts(int32_t counts);
/* AUX_ADC, V: counts x 805.8 uV. counts in [0, 4095]. Total. */
int32_t adis_imu_aux_v_from_counts(int32_t counts);

/*
 * User offsets. XGYRO_OFF: 13-bit two's complement [-4096, 4095] at 0.0125 deg/s (= 1/80 deg/s)
 * per LSB [U width: [ADI-IMU-QS] says 14-bit; docs/sensor-facts.md and ADI's example 13; 13 is used]. The
 * offset LSB is taken as independent of the gyro range [U].
 *
 * adis_imu_gyro_off_counts_from_dps: counts = round(dps x 80), ties away from zero, saturated
 * to [-4096, 4095]; *saturated (may be NULL) is set when the input was outside that range
 * (beyond -51.2 / +51.19375 deg/s after rounding). Input: any int32 Q16.16. Total.
 * adis_imu_gyro_off_dps_from_counts: counts x 0.0125 in Q16.16 (exact rounding as above); counts
 * outside the 13-bit range are saturated first. Total.
 */
#define ADIS_IMU_GYRO_OFF_BITS 13u
#define ADIS_IMU_GYRO_OFF_MIN (-4096)
#define ADIS_IMU_GYRO_OFF_MAX 4095
#define ADIS_IMU_GYRO_OFF_PER_DPS 80 /* offset LSB per deg/s (1 / 0.0125) */
int16_t adis_imu_gyro_off_counts_from_dps(int32_t dps_q16, bool *saturated);
int32_t adis_imu_gyro_off_dps_from_counts(int32_t counts);

/*
 * XACCL_OFF: 12-bit two's complement [-2048, 2047], LSB lsb_ug micro-g [U: the variant's output
 * LSB; ADI's example uses 1 mg on the ADIS16364]. From g Q16.16: round(g / lsb), ties away from
 * zero, saturated, *saturated (may be NULL) set when clipped. Both are fallible: lsb_ug must be
 * 1..100000 (else INC_ERR_INVAL, *counts / *g_q16 = 0); INC_ERR_NULL.
 */
#define ADIS_IMU_ACCEL_OFF_BITS 12u
#define ADIS_IMU_ACCEL_OFF_MIN (-2048)
#define ADIS_IMU_ACCEL_OFF_MAX 2047
int adis_imu_accel_off_counts_from_g(int32_t g_q16, uint32_t lsb_ug, int16_t *counts,
                                     bool *saturated);
int adis_imu_accel_off_g_from_counts(int32_t counts, uint32_t lsb_ug, int32_t *g_q16);

/* ---------------------------------------------------------------------------------------------
 * Samples
 * ------------------------------------------------------------------------------------------- */
enum adis_imu_chan {
    ADIS_IMU_CH_SUPPLY = 0,
    ADIS_IMU_CH_GYRO_X,
    ADIS_IMU_CH_GYRO_Y,
    ADIS_IMU_CH_GYRO_Z,
    ADIS_IMU_CH_ACCEL_X,
    ADIS_IMU_CH_ACCEL_Y,
    ADIS_IMU_CH_ACCEL_Z,
    ADIS_IMU_CH_MAGN_X,
    ADIS_IMU_CH_MAGN_Y,
    ADIS_IMU_CH_MAGN_Z, /* 1640x only */
    ADIS_IMU_CH_TEMP0,  /* 1636x XTEMP_OUT, 1640x TEMP_OUT */
    ADIS_IMU_CH_TEMP1,  /* 1636x YTEMP_OUT */
    ADIS_IMU_CH_TEMP2,  /* 1636x ZTEMP_OUT */
    ADIS_IMU_CH_AUX,
    ADIS_IMU_CH_COUNT
};
#define ADIS_IMU_CH(c) (1u << (unsigned)(c))
#define ADIS_IMU_CH_GYROS                                                \
    (ADIS_IMU_CH(ADIS_IMU_CH_GYRO_X) | ADIS_IMU_CH(ADIS_IMU_CH_GYRO_Y) | \
     ADIS_IMU_CH(ADIS_IMU_CH_GYRO_Z))
#define ADIS_IMU_CH_ACCELS                                                 \
    (ADIS_IMU_CH(ADIS_IMU_CH_ACCEL_X) | ADIS_IMU_CH(ADIS_IMU_CH_ACCEL_Y) | \
     ADIS_IMU_CH(ADIS_IMU_CH_ACCEL_Z))
#define ADIS_IMU_CH_MAGNS                                                \
    (ADIS_IMU_CH(ADIS_IMU_CH_MAGN_X) | ADIS_IMU_CH(ADIS_IMU_CH_MAGN_Y) | \
     ADIS_IMU_CH(ADIS_IMU_CH_MAGN_Z))
#define ADIS_IMU_CH_TEMPS                                              \
    (ADIS_IMU_CH(ADIS_IMU_CH_TEMP0) | ADIS_IMU_CH(ADIS_IMU_CH_TEMP1) | \
     ADIS_IMU_CH(ADIS_IMU_CH_TEMP2))
#define ADIS_IMU_CH_ALL ((1u << (unsigned)ADIS_IMU_CH_COUNT) - 1u)

/*
 * One read of output registers. Channels the part does not have, or that were not asked for,
 * are absent (bit clear in `present`). Only channels in `valid` may be used.
 */
struct adis_imu_sample {
    uint16_t raw[ADIS_IMU_CH_COUNT];   /* register words as read, ND/EA included */
    int32_t counts[ADIS_IMU_CH_COUNT]; /* data field: sign-extended or masked per its width */
    uint16_t present;                  /* channels read */
    uint16_t valid;                    /* read, ND set, no EA, no bus fault */
    uint16_t stale;                    /* read with ND clear (no new data since last read) */
    uint16_t diag;                     /* DIAG_STAT read because EA was set (else 0) */
    uint8_t gyro_range;                /* enum adis_imu_range in force when it was read */
    uint64_t t_ns;                     /* HAL time when the read began */
};

/* A sample in physical units, Q16.16 (see the conversions above); only `valid` channels. */
struct adis_imu_phys {
    int32_t gyro_dps[3];
    int32_t accel_g[3];
    int32_t magn_gauss[3];
    int32_t temp_c[3]; /* 1640x: temp_c[0] only */
    int32_t supply_v;
    int32_t aux_v;
    uint16_t valid; /* copied from the sample */
};

/* ---------------------------------------------------------------------------------------------
 * Driver
 * ------------------------------------------------------------------------------------------- */
enum adis_imu_dr_line {
    ADIS_IMU_DR_DIO1 = 0, /* factory default */
    ADIS_IMU_DR_DIO2 = 1,
};

struct adis_imu_cfg {
    const struct hal *hal;     /* time, delays, data-ready interrupt */
    const struct spi_bus *bus; /* the SPI bus the part is on */
    hal_pin_t cs;              /* chip select (active low) */
    uint8_t variant;           /* enum adis_imu_variant expected, or ADIS_IMU_ANY */
    hal_pin_t dr_pin;          /* host pin wired to the part's DR line; HAL_PIN_NONE: none */
    uint8_t dr_line;           /* enum adis_imu_dr_line: which DIO the part drives */
    bool dr_active_low;        /* false: active high (factory default) */
    bool reset_at_init;        /* software reset (and its wait) before identification */
    bool self_test_at_init;    /* run the internal self-test; a failure fails init */
};

struct adis_imu {
    struct adis_imu_cfg cfg;
    const struct adis_imu_variant_info *info; /* the identified part (NULL until init passed) */
    uint16_t found_id;                        /* PROD_ID read at init (also when it was wrong) */
    uint8_t found_variant; /* enum adis_imu_variant of found_id, or ADIS_IMU_UNKNOWN */
    bool id_known;         /* found_id/found_variant hold what init read */
    bool ready;            /* init passed */
    bool low_power;        /* SCLK/stall limits of low-power mode in force */
    bool resync_pending;   /* a reset was sent: re-read the mode registers first */
    bool dr_enabled;       /* data-ready configured and attached */
    uint8_t dr_line;       /* enum adis_imu_dr_line in force */
    bool dr_active_low;
    uint16_t smpl_prd; /* cached register values */
    uint16_t sens_avg;
    uint16_t msc_ctrl;
    uint16_t last_diag;     /* last DIAG_STAT read (it clears on read [U]) */
    uint16_t init_diag;     /* DIAG_STAT read at init (power-up flags), not an error */
    uint64_t busy_until_ns; /* the part ignores the bus until then; 0 once passed */
    struct sensor_dr dr;    /* data-ready edges seen and consumed (wait_dr) */
    /* statistics */
    uint32_t bursts, reg_reads, bus_errors, device_errors, stale_reads, timeouts;
    uint32_t sensor_missed; /* sensor ops: samples lost since the last sample handed out */
    /* Last: the driver's own fields above stay within the short load/store offsets of Thumb. */
    struct spi_dev spi;
};

/*
 * Bind to the part and identify it. cfg is copied. Sequence: SPI at the low-power limits (safe in
 * either mode); optional software reset; one pipelined read of PROD_ID, SMPL_PRD, SENS_AVG,
 * MSC_CTRL, DIAG_STAT; SCLK/stall to the mode SMPL_PRD selects; data-ready (when dr_pin is set:
 * MSC_CTRL written, interrupt attached); optional self-test.
 * Errors: INC_ERR_NULL / INC_ERR_INVAL (cfg), INC_ERR_BUS (PROD_ID 0x0000 or 0xFFFF: no device,
 * MISO stuck), INC_ERR_ID (another PROD_ID: dev->found_id holds it and dev->found_variant names it
 * when it is a known part), INC_ERR_DEVICE (self-test failed: dev->last_diag), a HAL/bus error.
 * On error dev->ready is false and every other call returns INC_ERR_STATE.
 */
int adis_imu_init(struct adis_imu *dev, const struct adis_imu_cfg *cfg);

/* The part found by init: PROD_ID and its variant (ADIS_IMU_UNKNOWN if none). Either may be
 * NULL. Valid after a successful init and after one that failed with INC_ERR_ID. */
int adis_imu_found(const struct adis_imu *dev, uint16_t *prod_id, enum adis_imu_variant *variant);

/*
 * Burst read (DIN 0x3E00, 11 or 12 words in one CS period at <= 1 MHz; the device timing is
 * switched for the burst and back). Fills every channel of the part. Returns 0 when every
 * channel is valid; INC_ERR_BUS (all words 0x0000 or all 0xFFFF, or DIAG_STAT implausible),
 * INC_ERR_DEVICE (EA set in any word: out->diag holds DIAG_STAT, valid = 0), INC_ERR_STALE
 * (ND clear in some word: those channels are in out->stale and not in out->valid).
 */
int adis_imu_read_sample(struct adis_imu *dev, struct adis_imu_sample *out);

/*
 * The same with pipelined register reads (n registers in n + 1 frames at the mode's SCLK, CS
 * toggled with the stall) for the channels in mask (ADIS_IMU_CH(...) bits; channels the part
 * lacks are ignored). Same errors; INC_ERR_INVAL for an empty mask.
 */
int adis_imu_read_channels(struct adis_imu *dev, uint16_t mask, struct adis_imu_sample *out);

/* Convert the valid channels of a sample to physical units (gyro scale: the range recorded in
 * the sample, i.e. SENS_AVG as it was when the sample was read). */
int adis_imu_to_phys(const struct adis_imu *dev, const struct adis_imu_sample *in,
                     struct adis_imu_phys *out);

/* Read any register of the map (the whole 16-bit word). INC_ERR_INVAL: not in the map or
 * write-only. Reading an output register clears its ND; reading DIAG_STAT clears it [U]. */
int adis_imu_read_reg(struct adis_imu *dev, uint8_t addr, uint16_t *value);
/* Write a read-write register of the map (low byte, then high byte). SMPL_PRD, SENS_AVG,
 * MSC_CTRL and GLOB_CMD have their own functions (they change the driver's state) and are
 * refused here with INC_ERR_INVAL, as are read-only registers. */
int adis_imu_write_reg(struct adis_imu *dev, uint8_t addr, uint16_t value);

/*
 * Write SMPL_PRD[7:0]. The part changes mode with it; the driver waits the longer (low-power)
 * stall once and then uses the new mode's SCLK and stall.
 */
int adis_imu_set_sample_period(struct adis_imu *dev, uint8_t smpl_prd);
/* Sample period in ns of the current SMPL_PRD (for data-ready timeouts). */
uint32_t adis_imu_current_period_ns(const struct adis_imu *dev);

/*
 * Write SENS_AVG: M = log2 of the taps per Bartlett stage (0..6) and the gyro range.
 * INC_ERR_INVAL for M > 6, an unknown range, or a range with fewer taps than it needs [U].
 */
int adis_imu_set_filter(struct adis_imu *dev, unsigned taps_log2, enum adis_imu_range range);
/* The gyro range of the cached SENS_AVG (ADIS_IMU_RANGE_300 when its field is not one of the
 * three codes). */
enum adis_imu_range adis_imu_gyro_range(const struct adis_imu *dev);

/* Read (and so clear [U]) DIAG_STAT. INC_ERR_BUS when bit 7 (unused) is set: not a live part. */
int adis_imu_read_diag(struct adis_imu *dev, uint16_t *diag);

/*
 * GLOB_CMD. adis_imu_command sends one command (one enum adis_imu_cmd) and waits its execution
 * time (table in docs/drivers-adis-imu.md); adis_imu_command_start returns once it is sent, and
 * the next call that needs the bus waits it out. After a software reset the driver re-reads
 * SMPL_PRD, SENS_AVG and MSC_CTRL (flash values) and re-times the bus.
 * INC_ERR_INVAL for a value that is not one command.
 */
int adis_imu_command(struct adis_imu *dev, enum adis_imu_cmd cmd);
int adis_imu_command_start(struct adis_imu *dev, enum adis_imu_cmd cmd);
/* Execution time the driver allows for cmd, in ms (0 for an unknown command). */
uint32_t adis_imu_command_ms(const struct adis_imu *dev, enum adis_imu_cmd cmd);
/* True while a started command is still executing (no bus access needed). */
bool adis_imu_busy(const struct adis_imu *dev);
/* Wait until no command is executing. */
int adis_imu_wait_idle(struct adis_imu *dev);

/*
 * User offsets, in register counts (gyro 13-bit, accel 12-bit; see the conversions above).
 * axis 0..2 = x, y, z. Set: INC_ERR_RANGE when counts is outside the register (nothing is
 * written: saturate first with the conversion functions). Get: sign-extended.
 */
int adis_imu_set_gyro_offset(struct adis_imu *dev, unsigned axis, int32_t counts);
int adis_imu_get_gyro_offset(struct adis_imu *dev, unsigned axis, int32_t *counts);
int adis_imu_set_accel_offset(struct adis_imu *dev, unsigned axis, int32_t counts);
int adis_imu_get_accel_offset(struct adis_imu *dev, unsigned axis, int32_t *counts);

/*
 * Data-ready: enable (MSC_CTRL[2]) on the given DIO line with the given polarity, attach the
 * interrupt on cfg.dr_pin (edge = the active edge); or disable and detach. INC_ERR_STATE when
 * cfg.dr_pin is HAL_PIN_NONE and enable is requested.
 */
int adis_imu_dr_config(struct adis_imu *dev, bool enable, enum adis_imu_dr_line line,
                       bool active_low);
/*
 * Wait for the next data-ready edge (one that came since the last one consumed counts at once).
 * timeout_ns 0 = three sample periods. INC_ERR_TIMEOUT when none came in time (missed
 * data-ready); INC_ERR_STATE when data-ready is not configured. *missed (may be NULL) = edges
 * beyond one since the last consumed (samples the caller did not read).
 */
int adis_imu_wait_ready(struct adis_imu *dev, uint32_t timeout_ns, uint32_t *missed);
/* Forget data-ready edges not yet consumed (e.g. after a setting changed, to wait for a sample
 * taken with it). No bus access. */
int adis_imu_dr_flush(struct adis_imu *dev);

/*
 * Internal self-test: set MSC_CTRL[10], wait the variant's self-test time, poll until the bit
 * clears (ADIS_IMU_SELF_TEST_POLLS x ADIS_IMU_SELF_TEST_POLL_MS, else INC_ERR_TIMEOUT), read
 * DIAG_STAT into *diag (may be NULL). INC_ERR_DEVICE when a self-test bit is set.
 */
int adis_imu_self_test(struct adis_imu *dev, uint16_t *diag);

/* ---------------------------------------------------------------------------------------------
 * Settings in force and the sensor interface
 * ------------------------------------------------------------------------------------------- */

/* The driver's cached settings (no bus access). */
struct adis_imu_settings {
    uint8_t smpl_prd;  /* SMPL_PRD[7:0] */
    uint16_t sens_avg; /* SENS_AVG as written or read (range code and M) */
    uint8_t taps_log2; /* SENS_AVG M */
    uint8_t range;     /* enum adis_imu_range of adis_imu_gyro_range() */
    bool dr_enabled;   /* data-ready configured and attached */
};
/* INC_ERR_NULL; INC_ERR_STATE before a successful init (*out zeroed). */
int adis_imu_get_settings(const struct adis_imu *dev, struct adis_imu_settings *out);
/* The HAL the driver was initialised with (NULL before init or for NULL). */
const struct hal *adis_imu_hal(const struct adis_imu *dev);

/*
 * The part's identity for struct sensor_identity: family SENSOR_FAMILY_ADIS163XX, product =
 * PROD_ID in decimal (e.g. 16405), revision 0, and on the 1636x SERIAL_NUM, LOT_ID1 and LOT_ID2
 * read from the part (the 1640x has none: 0). INC_ERR_NULL, INC_ERR_STATE, a bus error.
 */
int adis_imu_read_identity(struct adis_imu *dev, struct sensor_identity *out);

/*
 * The driver as a struct sensor (inclino/sensor.h); dev = struct adis_imu, cfg of init =
 * struct adis_imu_cfg.
 *   wait_ready  adis_imu_wait_ready (timeout 0: three sample periods); the edges missed are
 *               kept and reported in the next sample's `missed`.
 *   read        one burst (adis_imu_read_sample); a stale burst counts as a missed sample.
 *               Accel (variant LSB), gyro (range in force) and temperature: TEMP_OUT on the
 *               1640x, the mean of the three gyro temperatures on the 1636x (rounded, ties away
 *               from zero). Saturation per axis: a count at -8192 or 8191 (14-bit ends).
 *   read_diag   DIAG_STAT mapped to SENSOR_D_*, raw = DIAG_STAT, supply_v = SUPPLY_OUT (that
 *               read clears SUPPLY_OUT's ND: a burst in the same sample period is then stale,
 *               and sensor_next takes the next sample).
 *   self_test   adis_imu_self_test; INC_ERR_DEVICE with the failing bits in out.
 *   identity    adis_imu_read_identity.
 *   info        accel full scale 8192 x LSB, gyro full scale 300/150/75 deg/s (range in force),
 *               rate from SMPL_PRD.
 * It needs data-ready configured (cfg.dr_pin): wait_ready returns INC_ERR_STATE otherwise.
 */
extern const struct sensor_ops adis_imu_sensor_ops;

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_ADIS_IMU_H */
