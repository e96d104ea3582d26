/*
 * adis16255.h - driver for the Analog Devices ADIS16250/ADIS16255 single-axis gyroscope
 * (module inclino_adis16255, prefix adis16255_). See docs/drivers-adis16255.md.
 *
 * The part talks the shared ADIS register protocol (adis.h): SPI mode 3, 16-bit frames, CS
 * toggled with a stall between frames, pipelined reads (the reply comes in the next frame),
 * byte-wise writes (0x80 | address). It has no PROD_ID register: identity is checked by
 * plausibility (reserved bits, supply reading, write/read-back of the configuration).
 *
 * Outputs (docs/sensor-facts.md §2.3, ADIS16250/55 Rev B p. 12): GYRO_OUT 14-bit two's complement,
 * TEMP_OUT 12-bit two's complement (0 = 25 °C), SUPPLY_OUT 12-bit binary, ANGL_OUT 14-bit.
 * Every output word carries ND (bit 15, new data since the last read) and EA (bit 14, error or
 * alarm: see STATUS). A sample whose ND is clear is reported stale (INC_ERR_STALE); a sample
 * with EA set makes the driver read and decode STATUS and return INC_ERR_DEVICE. Neither is ever
 * marked valid.
 *
 * Facts marked [U] in docs/sensor-facts.md are named constants here with the safe value; every one is
 * listed in docs/unconfirmed-facts.md.
 *
 * Units: physical values are Q16.16 fixed point (int32_t, 1.0 = 65536) in °/s, °C, V and °.
 */
#ifndef INCLINO_ADIS16255_H
#define INCLINO_ADIS16255_H

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

/* Register addresses, MSC_CTRL and COMMAND bits: private to the driver (drivers/adis16255/
 * adis16255_regs.h); the white-box tests of tests/adis16255 include it. */

/* Output register widths. */
#define ADIS16255_GYRO_BITS 14u
#define ADIS16255_TEMP_BITS 12u
#define ADIS16255_SUPPLY_BITS 12u
#define ADIS16255_ANGL_BITS 14u
#define ADIS16255_GYRO_OFF_BITS 12u
#define ADIS16255_GYRO_SCALE_UNITY 0x0800u

/* SMPL_PRD (§2.4): TS = TB * (NS + 1). */
#define ADIS16255_SMPL_PRD_TB 0x80u /* 0: TB = 1.953 ms, 1: TB = 60.54 ms */
#define ADIS16255_SMPL_PRD_NS_MASK 0x7Fu
#define ADIS16255_TB_FAST_US 1953u       /* time base, bit 7 = 0 (A4) */
#define ADIS16255_TB_SLOW_US 60540u      /* time base, bit 7 = 1 (A4) */
#define ADIS16255_SMPL_PRD_DEFAULT 0x01u /* 256 SPS, factory default (A4) */
#define ADIS16255_FAST_NS_MAX 7u         /* NS <= 7 with TB = 0: >= 64 SPS, SCLK <= 2.5 MHz */

/*
 * SENS_AVG [U] layout (by analogy with the ADIS1636x, docs/sensor-facts.md §2.3): bits 10..8 range code
 * (one bit set: 001 = ±80, 010 = ±160, 100 = ±320 °/s), bits 2..0 filter M (2^M taps). Other
 * bits zero.
 */
#define ADIS16255_SENS_AVG_RANGE_SHIFT 8u
#define ADIS16255_SENS_AVG_RANGE_MASK 0x0700u
#define ADIS16255_SENS_AVG_FILTER_MASK 0x0007u
#define ADIS16255_FILTER_M_MAX 6u /* [U] code 7 invalid, as on the ADIS1636x */
/* [U] narrower ranges need more filtering on the ADIS1636x (±150: M >= 2, ±75: M >= 4); the
 * driver imposes the same on the ±160 and ±80 ranges: the safe side if the part shares it. */
#define ADIS16255_FILTER_M_MIN_160 2u
#define ADIS16255_FILTER_M_MIN_80 4u

/* STATUS (§2.3). */
#define ADIS16255_STATUS_SUPPLY_LOW 0x0001u  /* supply < 4.75 V */
#define ADIS16255_STATUS_SUPPLY_HIGH 0x0002u /* supply > 5.25 V */
#define ADIS16255_STATUS_FLASH_FAIL 0x0004u  /* flash update failed */
#define ADIS16255_STATUS_SPI_FAIL 0x0008u    /* SPI communication failure */
#define ADIS16255_STATUS_OVERRANGE 0x0010u   /* gyro over range */
#define ADIS16255_STATUS_SELF_TEST 0x0020u   /* self-test error */
#define ADIS16255_STATUS_FLASH_CRC 0x0040u   /* flash checksum (ADIS16260 headers only) */
#define ADIS16255_STATUS_ALARM1 0x0100u
#define ADIS16255_STATUS_ALARM2 0x0200u
#define ADIS16255_STATUS_DEFINED 0x037Fu /* any other bit set: not a STATUS word (bus fault) */

/* ------------------------------------------------------------------ timing (§2.2) */
/*
 * SCLK: <= 2.5 MHz at >= 64 SPS, <= 1 MHz below (A4, confirmed). The driver keeps a margin
 * (a bit-banged port only ever runs slower than asked, never faster).
 */
#define ADIS16255_SCLK_FAST_HZ 2000000u
#define ADIS16255_SCLK_SLOW_HZ 800000u
/* [U] tSTALL: staging driver 9 us, Linux adis16260 30 us: the longer one. */
#define ADIS16255_STALL_NS 30000u
/* [U] below 64 SPS the part runs in its low-power mode; the ADIS1640x needs 75 us there
 * (recollection): used for this part too. */
#define ADIS16255_STALL_SLOW_NS 75000u
/* [U] CS setup/hold: not found; 500 ns, ten times the ADIS16400's 48.8 ns (recollection). */
#define ADIS16255_CS_SETUP_NS 500u
#define ADIS16255_CS_HOLD_NS 500u

/* ------------------------------------------------------------------ command times [U] */
/* No source gives this family's command durations; long waits, named and listed. */
#define ADIS16255_RESET_MS 220u             /* Linux adis16260 reset/sw-reset timeout */
#define ADIS16255_FLASH_UPDATE_MS 200u      /* 2 x the 100 ms the OPTEC ADIS16405 code waits */
#define ADIS16255_FACTORY_RESTORE_MS 100u   /* 2 x the 50 ms of ADI's ADIS16364 example */
#define ADIS16255_AUTONULL_MS 100u          /* 2 x ADI's 50 ms, plus 2 x the filter window */
#define ADIS16255_SELF_TEST_MS 35u          /* first look (staging ADIS16255 driver waits 35 ms) */
#define ADIS16255_SELF_TEST_TIMEOUT_MS 220u /* give up (Linux adis16260 self_test_ms) */
#define ADIS16255_POLL_MS 5u                /* poll interval while waiting for the part */
/* The part still busy (garbage answers) after a command's wait, or busy before a command for
 * a reason the driver did not cause: poll this long before INC_ERR_BUSY. */
#define ADIS16255_BUSY_TIMEOUT_MS 1000u
/* Data-ready wait: default timeout = 2 sample periods + this margin. */
#define ADIS16255_DR_MARGIN_US 1000u

/* Identity plausibility: SUPPLY_OUT must read 4.0 .. 6.0 V (spec 4.75 .. 5.25 V). */
#define ADIS16255_SUPPLY_PLAUSIBLE_MIN_MV 4000u
#define ADIS16255_SUPPLY_PLAUSIBLE_MAX_MV 6000u

/* ------------------------------------------------------------------ types */

/* Measurement range; the value is the SENS_AVG range code and the multiple of 5/273 °/s. */
enum adis16255_range {
    ADIS16255_RANGE_80 = 1,  /* ±80 °/s, 5/273 °/s per LSB (0.01832) */
    ADIS16255_RANGE_160 = 2, /* ±160 °/s, 10/273 (0.03663) */
    ADIS16255_RANGE_320 = 4, /* ±320 °/s, 20/273 (0.07326, datasheet) */
};

/* Which identity check failed at init (adis16255.id_check). */
enum adis16255_id_check {
    ADIS16255_ID_OK = 0,
    ADIS16255_ID_STUCK_HIGH,    /* every word 0xFFFF: no device or MISO stuck at 1 */
    ADIS16255_ID_STUCK_LOW,     /* every word 0x0000: MISO stuck at 0 */
    ADIS16255_ID_SUPPLY,        /* SUPPLY_OUT outside 4.0 .. 6.0 V */
    ADIS16255_ID_RESERVED_BITS, /* a reserved bit set in GYRO_SCALE/SMPL_PRD/MSC_CTRL/STATUS */
    ADIS16255_ID_SENS_AVG,      /* SENS_AVG not a valid range code + filter */
    ADIS16255_ID_READBACK,      /* the configuration written did not read back */
};

/* STATUS, decoded. raw keeps the register word. */
struct adis16255_status {
    uint16_t raw;
    bool supply_low;
    bool supply_high;
    bool flash_update_fail;
    bool spi_fail;
    bool overrange;
    bool self_test_fail;
    bool flash_checksum;
    bool alarm1;
    bool alarm2;
};

struct adis16255_cfg {
    const struct spi_bus *bus;
    const struct hal *hal;
    hal_pin_t cs;
    hal_pin_t dr_pin; /* MCU pin wired to the part's data-ready DIO; HAL_PIN_NONE:
                                     not wired (adis16255_wait_sample unavailable) */
    uint8_t smpl_prd; /* SMPL_PRD: bit 7 time base, bits 6..0 NS */
    enum adis16255_range range;
    uint8_t filter_m; /* 0..ADIS16255_FILTER_M_MAX: 2^M taps */
    bool dr_enable;   /* MSC_CTRL data-ready output on */
    bool dr_active_high;
    uint8_t dr_line;        /* 0 = DIO0, 1 = DIO1 */
    bool reset_at_init;     /* software reset first (waits ADIS16255_RESET_MS) */
    bool self_test_at_init; /* run adis16255_self_test() at the end of init */
};

/* Sample flags. */
#define ADIS16255_SAMPLE_GYRO_NEW 0x01u /* ND of GYRO_OUT */
#define ADIS16255_SAMPLE_TEMP_NEW 0x02u /* ND of TEMP_OUT */
#define ADIS16255_SAMPLE_ALARM 0x04u    /* EA seen; status holds STATUS */
#define ADIS16255_SAMPLE_OVERRUN \
    0x08u /* wait_sample: more than one data-ready edge since the
                                            previous sample (samples were skipped) */

/*
 * One gyro + temperature sample. valid is true only when both words had ND set, neither had EA
 * set and the words were plausible; otherwise rate/temp are 0 and the error says why. The raw
 * words are kept for diagnosis in every case.
 */
struct adis16255_sample {
    bool valid;
    uint8_t flags;
    int32_t rate_dps_q16;           /* Q16.16 °/s */
    int32_t temp_c_q16;             /* Q16.16 °C */
    uint16_t gyro_word;             /* GYRO_OUT as read (ND, EA, data) */
    uint16_t temp_word;             /* TEMP_OUT as read */
    struct adis16255_status status; /* decoded STATUS when EA was seen, else zero */
    uint64_t t_ns;                  /* hal time of the read */
};

/* Driver state: caller-allocated (static), one per part. Fields are read-only to the caller. */
struct adis16255 {
    struct adis16255_cfg cfg;
    struct spi_dev spi;
    uint16_t smpl_prd; /* configuration written to the part (read-back checked) */
    uint16_t sens_avg;
    uint16_t msc_ctrl;
    bool fast;              /* SCLK/stall for >= 64 SPS in use */
    uint64_t busy_until_ns; /* the part is busy with a command the driver issued */
    struct sensor_dr dr;    /* data-ready edges seen and consumed (wait_sample) */
    bool dr_attached;
    bool ready;
    enum adis16255_id_check id_check; /* the identity check that failed at init */
    struct adis16255_status status;   /* the last STATUS read (EA, self-test, init) */
    uint32_t bus_errors;              /* calls that ended in INC_ERR_BUS */
    uint32_t sensor_missed;           /* sensor ops: samples lost since the last one handed out */
    /* the chained SENS_AVG check of adis16255_read_sample: tail_mark is spi.transfers after the
     * last sample read, whose trailing frame read SENS_AVG; tail_fails counts mismatches */
    bool tail_valid;
    uint32_t tail_mark;
    uint32_t tail_fails;
};

/* ------------------------------------------------------------------ pure functions */

/*
 * GYRO_OUT word -> rate in Q16.16 °/s. The 14-bit two's complement count n (ND/EA ignored) is
 * scaled by the range's LSB, 5/273 * range °/s (±320: 20/273 = 0.0732600 = 320 °/s / 4368 LSB,
 * the datasheet's 0.07326). Output = round(n * range * 327680 / 273), computed exactly in
 * 32-bit integers; ties cannot occur (273 is odd), so the error against exact math is
 * <= 0.5 LSB of Q16.16 (7.6e-6 °/s). Range ±600.1 °/s (±320), no saturation needed.
 * Returns 0, INC_ERR_NULL, or INC_ERR_INVAL (range not 1, 2 or 4; *dps_q16 = 0).
 */
int adis16255_gyro_dps_from_word(uint16_t word, enum adis16255_range range, int32_t *dps_q16);

/*
 * TEMP_OUT word -> Q16.16 °C: 25 + n * 0.1453, n the 12-bit two's complement count.
 * Exact rational math (0.1453 * 65536 = 9522 + 238/625), rounded to nearest (625 is odd: no
 * ties); error <= 0.5 LSB of Q16.16. Range -272.6 .. +322.4 °C. Total function.
 */
int32_t adis16255_temp_c_from_word(uint16_t word);

/*
 * SUPPLY_OUT word -> Q16.16 V: n * 1.8315 mV, n the 12-bit unsigned count. Exact
 * (1.8315e-3 * 65536 = 120 + 2280/78125), rounded to nearest (no ties); error <= 0.5 LSB of
 * Q16.16. Range 0 .. 7.5 V. Total function.
 */
int32_t adis16255_supply_v_from_word(uint16_t word);

/*
 * ANGL_OUT word -> Q16.16 °: n * 10/273 ° (0.03663 °/LSB, the Linux ADIS16260 value [U] for this
 * part), n the 14-bit count taken as unsigned [U] (the angle wraps modulo 16384 counts =
 * 600.1°; use differences modulo 2^14 for relative angles). round(n * 655360 / 273), no ties,
 * error <= 0.5 LSB of Q16.16. Range 0 .. 600.1 °. Total function.
 */
int32_t adis16255_angle_deg_from_word(uint16_t word);

/*
 * GYRO_OFF [U] format: 12-bit two's complement (Linux), LSB 5/273 °/s (0.01832, the ±80 range
 * LSB, independent of the range setting) [U]; full scale -37.51 .. +37.49 °/s.
 * adis16255_gyro_off_word_from_dps: rate offset (Q16.16 °/s, any int32) -> register word
 * (low 12 bits, two's complement), rounded to nearest, ties away from zero; values outside the
 * 12-bit range saturate to -2048/+2047 and *saturated = true. Error <= 0.5 LSB (0.00916 °/s)
 * when not saturated. Returns 0 or INC_ERR_NULL.
 */
int adis16255_gyro_off_word_from_dps(int32_t dps_q16, uint16_t *word, bool *saturated);
/* GYRO_OFF word -> Q16.16 °/s (exact to <= 0.5 LSB of Q16.16, no ties). Total function. */
int32_t adis16255_gyro_off_dps_from_word(uint16_t word);

/* Sample period in us for a SMPL_PRD value: TB * (NS + 1), TB = 1953 or 60540 us. */
uint32_t adis16255_sample_period_us(uint8_t smpl_prd);
/* True when SMPL_PRD gives >= 64 SPS (TB = 0, NS <= 7): SCLK may run up to 2.5 MHz. */
bool adis16255_sclk_fast_allowed(uint8_t smpl_prd);

/* SENS_AVG word for a range and filter; INC_ERR_INVAL for a bad range, M > 6, or a filter below
 * the range's [U] minimum. Returns 0 or an error; *word untouched on error. */
int adis16255_sens_avg_encode(enum adis16255_range range, uint8_t filter_m, uint16_t *word);

/*
 * Decode a STATUS word into *out (raw always set). Returns 0, INC_ERR_NULL, or INC_ERR_BUS when
 * a bit outside ADIS16255_STATUS_DEFINED is set (not a STATUS word: e.g. MISO stuck at 1).
 */
int adis16255_status_decode(uint16_t raw, struct adis16255_status *out);
/* Name of a STATUS bit (0..15): "supply<4.75V", ..., or "reserved". */
const char *adis16255_status_bit_name(unsigned bit);

/* ------------------------------------------------------------------ device */

/*
 * Bring the part up: validate cfg (INC_ERR_NULL/INC_ERR_INVAL), bind the SPI device (slow SCLK
 * until the sample rate is known), optional software reset, identity plausibility (one
 * pipelined read of SUPPLY_OUT, GYRO_SCALE, SENS_AVG, SMPL_PRD, MSC_CTRL, then STATUS on its
 * own, which clears its latched bits): INC_ERR_BUS for all-ones/all-zeros (no device, MISO
 * stuck), INC_ERR_ID for implausible contents (dev->id_check says which); write SMPL_PRD,
 * SENS_AVG, MSC_CTRL and read them back (INC_ERR_ID on mismatch); select SCLK/stall for the
 * rate; optional self-test (else the pending outputs are discarded); read STATUS again: any bit
 * set -> INC_ERR_DEVICE with dev->status; attach the data-ready interrupt. On error st is not
 * usable (every other call returns INC_ERR_STATE). docs/drivers-adis16255.md, Init.
 */
int adis16255_init(struct adis16255 *dev, const struct adis16255_cfg *cfg);

/*
 * Read GYRO_OUT and TEMP_OUT in one pipelined sequence (3 frames; the third reads SENS_AVG,
 * whose value arrives as the first word of the next sample read). 0 and s->valid = true when
 * both are new and error-free. Otherwise s->valid = false, rate/temp = 0, raw words kept:
 *   INC_ERR_BUSY   the first word of this read, the answer to the previous sample read's
 *                  trailing SENS_AVG command (checked when nothing else went to the part in
 *                  between), is not the SENS_AVG the driver wrote: the part answered garbage
 *                  (busy: it gives no busy flag) or lost its configuration (a reset: its range
 *                  and filter may no longer be the ones the conversion assumes); the sample is
 *                  not used and dev->tail_fails counts it;
 *   INC_ERR_BUS    an all-ones word with a STATUS that is not one (reserved bits), or
 *                  all-zero stale words and SENS_AVG does not read back (MISO stuck/no device);
 *   INC_ERR_DEVICE EA set: STATUS read and decoded into s->status and dev->status;
 *   INC_ERR_STALE  ND clear on either word (no new sample since the last read);
 *   bus errors from the SPI layer.
 */
int adis16255_read_sample(struct adis16255 *dev, struct adis16255_sample *s);

/*
 * Wait for the next data-ready edge (hal_irq_wait), at most timeout_ns (0: 2 sample periods +
 * ADIS16255_DR_MARGIN_US). An edge that came since the previous call counts (none is lost);
 * *missed (may be NULL) = edges beyond one since the last consumed. INC_ERR_TIMEOUT when none
 * came; INC_ERR_STATE when no data-ready pin is configured/enabled.
 */
int adis16255_wait_ready(struct adis16255 *dev, uint32_t timeout_ns, uint32_t *missed);

/*
 * adis16255_wait_ready, then adis16255_read_sample. timeout_us = 0 means 2 sample periods +
 * ADIS16255_DR_MARGIN_US. Timeout -> INC_ERR_TIMEOUT, s->valid = false, nothing read.
 * More than one edge since the previous sample sets ADIS16255_SAMPLE_OVERRUN.
 */
int adis16255_wait_sample(struct adis16255 *dev, uint32_t timeout_us, struct adis16255_sample *s);

/* SUPPLY_OUT (Q16.16 V) / ANGL_OUT (Q16.16 °), with the same ND/EA/bus checks as a sample. On
 * error *out = 0. */
int adis16255_read_supply(struct adis16255 *dev, int32_t *v_q16);
int adis16255_read_angle(struct adis16255 *dev, int32_t *deg_q16);

/* Read and decode STATUS (clears its latched bits on the part [U]). INC_ERR_BUS when it is not
 * a STATUS word. */
int adis16255_read_diag(struct adis16255 *dev, struct adis16255_status *out);

/* Change SMPL_PRD (and the SCLK/stall that follow from it); read-back checked. */
int adis16255_set_sample_period(struct adis16255 *dev, uint8_t smpl_prd);
/* Change range and filter (SENS_AVG); read-back checked. */
int adis16255_set_sens_avg(struct adis16255 *dev, enum adis16255_range range, uint8_t filter_m);

/*
 * Write GYRO_OFF from a rate offset (Q16.16 °/s), saturating to the 12-bit range;
 * *saturated (may be NULL) tells whether it did. Read-back checked (INC_ERR_ID on mismatch).
 */
int adis16255_set_gyro_offset(struct adis16255 *dev, int32_t dps_q16, bool *saturated);
int adis16255_get_gyro_offset(struct adis16255 *dev, int32_t *dps_q16);

/*
 * COMMAND, each blocking until the part is done. Before the command the driver waits out any
 * busy time it knows of and checks that the part answers (SENS_AVG reads back); while it does
 * not, it polls every ADIS16255_POLL_MS up to ADIS16255_BUSY_TIMEOUT_MS and then returns
 * INC_ERR_BUSY without sending the command (retry later: the request is not lost silently).
 * After the command's wait it polls the same way until the part answers again.
 *   autonull: wait ADIS16255_AUTONULL_MS + 2 filter windows (2^M sample periods each);
 *   factory restore: ADIS16255_FACTORY_RESTORE_MS, then GYRO_OFF = 0 and GYRO_SCALE = 0x0800
 *     are checked (INC_ERR_DEVICE if not);
 *   flash update: ADIS16255_FLASH_UPDATE_MS, then ENDURANCE must have grown by exactly 1 and
 *     STATUS must not flag a flash failure (INC_ERR_DEVICE otherwise);
 *   reset: ADIS16255_RESET_MS, then the driver's configuration is written again (the part
 *     reloads its flash copy) and read back.
 */
int adis16255_autonull(struct adis16255 *dev);
int adis16255_factory_restore(struct adis16255 *dev);
int adis16255_flash_update(struct adis16255 *dev);
int adis16255_reset(struct adis16255 *dev);

/*
 * Internal self-test: set MSC_CTRL bit 10, wait ADIS16255_SELF_TEST_MS, poll until the bit
 * clears (INC_ERR_TIMEOUT after ADIS16255_SELF_TEST_TIMEOUT_MS), read STATUS: self-test error
 * -> INC_ERR_DEVICE with dev->status. Outputs during the test are not valid; the driver
 * discards the sample flags (reads GYRO_OUT/TEMP_OUT once) before returning.
 */
int adis16255_self_test(struct adis16255 *dev);

/* The default data-ready timeout for the configured rate, in us. */
uint32_t adis16255_dr_timeout_us(const struct adis16255 *dev);

/*
 * The driver as a struct sensor (inclino/sensor.h); dev = struct adis16255, cfg of init =
 * struct adis16255_cfg. The part is a single-axis gyro: its rate is gyro_dps[2], the sensor
 * frame's z axis (the axis normal to the package top, docs/drivers-adis16255.md, "Sensor
 * interface"); x and y are 0 and there is no accelerometer (no SENSOR_S_HAVE_ACCEL).
 *   wait_ready  adis16255_wait_ready; edges missed are reported in the next sample's `missed`.
 *   read        adis16255_read_sample: rate and TEMP_OUT; a stale sample counts as missed.
 *               Saturation: GYRO_OUT at -8192 or 8191 sets SENSOR_S_GYRO_SAT_X << 2.
 *   read_diag   STATUS mapped to SENSOR_D_*, raw = STATUS, supply_v = SUPPLY_OUT.
 *   self_test   adis16255_self_test.
 *   identity    family SENSOR_FAMILY_ADIS1625X, product 16255 (the part has no ID register: the
 *               ADIS16250 cannot be told apart and is bound as 16255 too), the rest 0.
 *   info        gyro full scale 80/160/320 deg/s from the configured range, no accelerometer,
 *               rate from SMPL_PRD.
 */
extern const struct sensor_ops adis16255_sensor_ops;

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_ADIS16255_H */
