/*
 * sca3000.h - driver for the Murata/VTI SCA3000 3-axis accelerometer (variants D01, E02, E04,
 * E05) on an SPI bus (spi.h: devices and frames, never pins).
 *
 * Units and formats
 *   - Acceleration counts: 13-bit two's complement, -4096..4095, one count = the variant's LSB:
 *     D01 750 ug, E02 1000 ug, E04 2000 ug, E05 6250 ug (docs/sensor-facts.md §1.1: the Linux scales
 *     7357/9810/19620/61313 um/s^2 are 0.75/1/2/6.25 mg x 9.81).
 *   - Ring-buffer values (11-bit mode) are returned in the same 13-bit count units (the 11-bit
 *     value x 4), so one conversion serves both.
 *   - Temperature (D01 only): 9-bit unsigned counts 0..511.
 *   - Conversions give Q16.16 g and Q16.16 degC (int32_t, value = q / 65536).
 *
 * Bus protocol (docs/sensor-facts.md §1.2). 8-bit frames, MSB first, SPI mode 3 (mode 0 accepted: the fact
 * sheet leaves the mode unconfirmed, both shift on the falling and sample on the rising edge).
 * Command byte = address << 2, | 0x02 for a write. A write is [cmd][data] in one CS period; a
 * read is [cmd] followed by n data bytes in the same CS period, the address decrementing after
 * each byte (X_LSB wraps to Z_MSB; BUF_DATA stays put).
 *
 * Integrity. Every fallible call returns 0 or a negative enum inc_err; outputs are written only
 * on success. The driver treats the bus as untrusted:
 *   - REVID 0x00 or 0xFF at init is a bus fault (MISO stuck low/high or no device):
 *     INC_ERR_BUS; any other unexpected REVID is INC_ERR_ID (sca3000_revid() tells the value);
 *   - an acceleration word with any of bits[2:0] set cannot come from the part (they read 0):
 *     INC_ERR_BUS;
 *   - a data read whose bytes are all 0x00 or all 0xFF is confirmed by reading REVID again;
 *     if REVID is not the one found at init the read fails with INC_ERR_BUS;
 *   - STATUS 0xFF is a bus fault; where 0x00 is the plausible "nothing" answer (the public
 *     STATUS check, BUF_COUNT, INT_STATUS, a failed unlock) REVID is read to confirm the bus;
 *   - after every data read, and after every write sequence, STATUS is read: bit0 (the part saw
 *     a corrupt SPI frame) or bit1 (EEPROM checksum error) fail the call with INC_ERR_DEVICE;
 *     sca3000_last_status() gives the STATUS byte;
 *   - each register write is read back where the register is readable (INC_ERR_DEVICE when the
 *     part did not take it).
 * Protected bits (MODE 0x28, INT_MASK 0x1C, MD_CTRL 0xC0, OUT_CTRL 0xE0) are always preserved by
 * read-modify-write; reserved addresses are never written.
 *
 * State is caller-allocated (struct sca3000); no heap. Not re-entrant per device.
 */
#ifndef INCLINO_SCA3000_H
#define INCLINO_SCA3000_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "inclino/error.h"
#include "inclino/hal.h"
#include "inclino/sensor.h"
#include "inclino/spi.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- variants ------------------------------------------------------------------------------ */

enum sca3000_variant {
    SCA3000_D01 = 0,
    SCA3000_E02 = 1,
    SCA3000_E04 = 2,
    SCA3000_E05 = 3,
    SCA3000_E01 = 4, /* named so that a caller can ask for it: no source describes it, so
                          sca3000_init() rejects it with INC_ERR_UNSUPPORTED */
};

/* ---- registers: the addresses, MODE bits and protected-bit masks are private to the driver
 * (drivers/sca3000/sca3000_regs.h; the white-box tests of tests/sca3000 include it). What a
 * caller passes or gets back is here: STATUS and INT_STATUS bits, indirect register selectors,
 * ring axes. ----------------------------------------------------------------------------------- */

#define SCA3000_STATUS_UNLOCKED 0x20u /* bit5: 1 = indirect registers unlocked (Linux reading) */
#define SCA3000_STATUS_EEPROM 0x02u   /* bit1: EEPROM checksum error */
#define SCA3000_STATUS_FRAME 0x01u    /* bit0: the part saw a corrupt SPI frame */

#define SCA3000_INT_RING_3_4 0x80u /* INT_STATUS / INT_MASK: ring 3/4 full */
#define SCA3000_INT_RING_1_2 0x40u /* ring 1/2 full */
#define SCA3000_INT_FREE_FALL 0x08u
#define SCA3000_INT_MOTION_Y 0x04u
#define SCA3000_INT_MOTION_X 0x02u
#define SCA3000_INT_MOTION_Z 0x01u

/* ---- indirect registers (CTRL_SEL values, docs/sensor-facts.md §1.5) ----------------------------------- */

#define SCA3000_IND_I2C_DISABLE 0x01u /* D01 only */
#define SCA3000_IND_MD_CTRL 0x02u
#define SCA3000_IND_MD_Y_TH 0x03u
#define SCA3000_IND_MD_X_TH 0x04u
#define SCA3000_IND_MD_Z_TH 0x05u
#define SCA3000_IND_OUT_CTRL 0x0Bu

#define SCA3000_OUT_CTRL_X 0x10u
#define SCA3000_OUT_CTRL_Y 0x08u
#define SCA3000_OUT_CTRL_Z 0x04u


/* ---- SPI timing (all [U] in docs/sensor-facts.md; safe values, see docs/unconfirmed-facts.md) --------- */

/* SCLK period: 2000 ns = 500 kHz. No readable source gives the maximum; the only field value is
 * an ATmega driver at 4 MHz (docs/sensor-facts.md S9). 8x slower than that. */
#define SCA3000_SCLK_PERIOD_NS 2000u
/* CS falling edge -> first SCLK edge, and last SCLK edge -> CS rising edge. */
#define SCA3000_CS_SETUP_NS 1000u
#define SCA3000_CS_HOLD_NS 1000u
/* CS high between two CS periods (the unlock sequence needs three separate periods). */
#define SCA3000_STALL_NS 10000u

/* The spi_timing the driver uses, with the values above (gap between bytes of one period: none). */
#define SCA3000_SPI_TIMING_INIT                                                               \
    {                                                                                         \
        SCA3000_SCLK_PERIOD_NS, SCA3000_CS_SETUP_NS, SCA3000_CS_HOLD_NS, SCA3000_STALL_NS, 0u \
    }

/* REVID the driver expects when the config gives 0. The real value is not known ([U]); a
 * board that reads another value fails init with INC_ERR_ID and sca3000_revid() names it. */
#define SCA3000_REVID_DEFAULT 0x52u

/* Longest read in one CS period (bytes after the command); bounds stack use. */
#define SCA3000_MAX_BURST 64u

/* Ring buffer capacity in values (64 time points x 3 axes). */
#define SCA3000_RING_CAPACITY 192u

/* ---- configuration and state ---------------------------------------------------------------- */

enum sca3000_mode {
    SCA3000_MODE_NORMAL = 0,
    SCA3000_MODE_OPTION1 = 1, /* D01: low-pass bypassed; E02/E04/E05: narrow band, ODR halved */
    SCA3000_MODE_OPTION2 = 2, /* E04/E05 only: wide band, 400 Hz */
    SCA3000_MODE_MOTION = 3,  /* motion detection: acceleration reads fail with INC_ERR_STATE */
};

struct sca3000_cfg {
    const struct spi_bus *bus;
    hal_pin_t cs;   /* chip select (active low) */
    bool spi_mode0; /* false: SPI mode 3; true: mode 0, which the part takes too. The
                               driver builds the rest of its spi_dev_cfg itself (8-bit frames,
                               SCA3000_SPI_TIMING_INIT), as the ADIS drivers do */
    enum sca3000_variant variant;
    uint8_t expected_revid; /* 0: SCA3000_REVID_DEFAULT; 0xFF is not allowed */
    const struct hal *hal;  /* for the INT line; may be NULL when int_pin is HAL_PIN_NONE */
    hal_pin_t int_pin;      /* the part's INT output, or HAL_PIN_NONE */
};

struct sca3000 {
    struct spi_dev spi;
    enum sca3000_variant variant;
    uint8_t expected_revid;
    const struct hal *hal;
    hal_pin_t int_pin;
    bool ready;       /* init succeeded */
    uint8_t revid;    /* REVID read at the last init (also when it failed) */
    uint8_t status;   /* STATUS byte of the last check */
    uint8_t mode_reg; /* MODE as last written and verified */
    uint8_t int_mask; /* INT_MASK as last written and verified */
    bool int_armed;   /* sca3000_int_config() done */
    bool int_active_high;
    struct sensor_dr int_edges; /* INT edges, counted by sensor_dr_isr (inclino/sensor.h) */
    /* output pacing (sca3000_wait_ready) */
    uint64_t next_ns;     /* earliest time of the next sample */
    uint64_t sample_ns;   /* time of the sample the last wait ended at */
    uint32_t pace_missed; /* output periods lost before that sample */
    bool pace_started;    /* the first wait has been made since init / the last mode change */
    /* statistics */
    uint32_t bus_errors, frame_errors, revid_confirms;
};

/* One sample set. temp_valid is false on variants without a temperature output. */
struct sca3000_sample {
    int16_t xyz[3];    /* counts, 13-bit */
    uint16_t temp_raw; /* 9-bit counts (D01) */
    bool temp_valid;
};

/* ---- device API ----------------------------------------------------------------------------- */

/*
 * Bind, check and set up the part: REVID (bus fault or identity), STATUS (EEPROM checksum,
 * frame error), acknowledge INT_STATUS, MODE <- normal measurement, ring off, free-fall off
 * (protected bits kept), INT_MASK read. Errors: INC_ERR_NULL, INC_ERR_INVAL (config),
 * INC_ERR_UNSUPPORTED (E01), INC_ERR_BUS, INC_ERR_ID, INC_ERR_DEVICE, or the bus's own error.
 * The part's power-up time is the caller's business (not known, [U]). Calling init again
 * (re-binding the device) forgets when CS last rose: leave SCA3000_STALL_NS after any earlier
 * traffic to the part.
 */
int sca3000_init(struct sca3000 *dev, const struct sca3000_cfg *cfg);

/* REVID read by the last init (the value found, also when init failed with INC_ERR_ID). */
uint8_t sca3000_revid(const struct sca3000 *dev);
/* STATUS byte of the last check (frame error, EEPROM, unlocked). */
uint8_t sca3000_last_status(const struct sca3000 *dev);

/* Read n (1..SCA3000_MAX_BURST) bytes from addr in one CS period (decrementing address). Raw:
 * no plausibility or STATUS check. addr must be readable (not a reserved or write-only one). */
int sca3000_read_burst(struct sca3000 *dev, uint8_t addr, uint8_t *buf, size_t n);
/* One register, raw (as sca3000_read_burst with n = 1). */
int sca3000_read_reg(struct sca3000 *dev, uint8_t addr, uint8_t *val);

/* Read STATUS and check it (see Integrity); a STATUS of 0x00 is confirmed with REVID (a MISO
 * stuck low reads 0x00 too). *status (may be NULL) gets the byte also when the result is
 * INC_ERR_DEVICE. */
int sca3000_read_diag(struct sca3000 *dev, uint8_t *status);

/* Select the measurement mode (MODE[1:0], read-modify-write, verified). INC_ERR_UNSUPPORTED
 * for option 2 on the D01 and E02. */
int sca3000_set_mode(struct sca3000 *dev, enum sca3000_mode mode);
enum sca3000_mode sca3000_get_mode(const struct sca3000 *dev);
/* Output data rate of the current mode in mHz (docs/sensor-facts.md §1.6; 0 in motion detection). */
uint32_t sca3000_odr_mhz(const struct sca3000 *dev);
/* The output period of the current mode in ns, rounded up (never shorter than the part's):
 * ceil(1e12 / sca3000_odr_mhz); 0 in motion detection or before init. */
uint32_t sca3000_period_ns(const struct sca3000 *dev);

/*
 * Wait until the part has a new sample. The SCA3000 has no data-ready output in direct
 * measurement mode (its INT line serves the ring buffer), so the output data rate paces the
 * reads: each wait ends one output period after the previous one (hal_delay_until). The first
 * wait after init or a mode change waits one period too, so that no sample from before is used.
 * A wait that comes more than one period late returns at once and reports the periods lost in
 * *missed (may be NULL). timeout_ns 0: no limit (the wait is at most one period); else
 * INC_ERR_TIMEOUT when the next sample is due later than timeout_ns from now (waited that long,
 * the pacing kept). INC_ERR_STATE before init, without a HAL, or in motion detection.
 */
int sca3000_wait_ready(struct sca3000 *dev, uint32_t timeout_ns, uint32_t *missed);

/* X, Y, Z counts in one CS period (X_MSB down, wrapping to Z), then STATUS checked.
 * INC_ERR_STATE in motion-detection mode (no acceleration output). */
int sca3000_read_accel(struct sca3000 *dev, int16_t xyz[3]);
/* Temperature counts (D01; INC_ERR_UNSUPPORTED on the others), then STATUS checked. */
int sca3000_read_temp(struct sca3000 *dev, uint16_t *raw9);
/* Acceleration and (D01) temperature. */
int sca3000_read_sample(struct sca3000 *dev, struct sca3000_sample *s);

/* Unlock the indirect registers when STATUS says they are locked (UNLOCK 0x00, 0x50, 0xA0 in
 * three CS periods), then confirm with STATUS bit5. */
int sca3000_unlock(struct sca3000 *dev);
/* Read / write an indirect register through CTRL_SEL and CTRL_DATA (unlocking first). Writes
 * keep the register's protected bits as read and are verified; sel must be one of
 * SCA3000_IND_* (I2C_DISABLE on the D01 only): INC_ERR_INVAL otherwise. */
int sca3000_ind_read(struct sca3000 *dev, uint8_t sel, uint8_t *val);
int sca3000_ind_write(struct sca3000 *dev, uint8_t sel, uint8_t val);

/* Ring buffer input: axes (SCA3000_OUT_CTRL_X|Y|Z, at least one) and the rate divider
 * (1, 2 or 4). OUT_CTRL read-modify-write keeping bits[7:5]. */
int sca3000_ring_config(struct sca3000 *dev, uint8_t axes, unsigned divider);
/* Enable (11-bit mode) or disable the ring buffer (MODE bit7, read-modify-write). */
int sca3000_ring_enable(struct sca3000 *dev, bool on);
/* Values stored in the ring (BUF_COUNT; INC_ERR_BUS when above the capacity; a count of 0 is
 * confirmed with REVID). */
int sca3000_ring_count(struct sca3000 *dev, unsigned *count);
/*
 * Read up to cap values (BUF_COUNT tells how many there are), in the part's order (the enabled
 * axes X, Y, Z of each time point), as 13-bit-unit counts. *n = values read. STATUS is checked
 * after the reads.
 */
int sca3000_ring_read(struct sca3000 *dev, int16_t *values, size_t cap, size_t *n);

/* INT output: which INT_STATUS sources drive it (SCA3000_INT_RING_*), and its polarity.
 * INT_MASK read-modify-write keeping bits[4:2]. With an int_pin, the driver's callback is
 * attached on the active edge. */
int sca3000_int_config(struct sca3000 *dev, uint8_t sources, bool active_high);
/* Read INT_STATUS (this acknowledges the events); 0x00 and 0xFF are confirmed with REVID. */
int sca3000_int_status(struct sca3000 *dev, uint8_t *status);
/* Wait until the INT line is (or becomes) active, or deadline_ns passes (INC_ERR_TIMEOUT).
 * INC_ERR_STATE without an int_pin or before sca3000_int_config(). */
int sca3000_wait_int(struct sca3000 *dev, uint64_t deadline_ns);

/* ---- pure conversions (no device) ------------------------------------------------------------ */

/*
 * Decode a direct acceleration word (MSB << 8 | LSB): 13-bit two's complement in bits[15:3].
 * INC_ERR_BUS when bits[2:0] are not 0 (not a word the part sends; e.g. MISO stuck high).
 * *count in -4096..4095.
 */
int sca3000_accel_counts_from_word(uint16_t word, int16_t *count);
/* Decode an 11-bit ring word (bits[15:5], bits[4:0] ignored) into 13-bit-unit counts: the
 * 11-bit value x 4, -4096..4092. Always succeeds. */
int16_t sca3000_ring_counts_from_word(uint16_t word);
/* Decode the temperature word (TEMP_MSB << 8 | TEMP_LSB): 9 bits in bits[13:5], 0..511. */
uint16_t sca3000_temp_counts_from_word(uint16_t word);

/* The variant codes of struct sensor_identity.product (the part has no product-id register);
 * the calibration record's CALREC_SCA3000_* are the same numbers. */
#define SCA3000_PRODUCT_D01 0x0D01u
#define SCA3000_PRODUCT_E02 0x0E02u
#define SCA3000_PRODUCT_E04 0x0E04u
#define SCA3000_PRODUCT_E05 0x0E05u

/* LSB of the variant in ug (750, 1000, 2000, 6250); 0 for E01 or an invalid variant. */
uint32_t sca3000_ug_per_lsb(enum sca3000_variant v);

/*
 * counts (13-bit units, -4096..4095) -> micro-g, exact: counts x ug_per_lsb.
 * INC_ERR_INVAL for a bad variant, INC_ERR_RANGE for counts outside -4096..4095.
 */
int sca3000_accel_ug_from_counts(int32_t counts, enum sca3000_variant v, int32_t *ug);

/*
 * counts -> Q16.16 g: counts x ug_per_lsb x 65536 / 1e6, rounded to the nearest Q16.16 step,
 * ties away from zero. Inputs -4096..4095 (else INC_ERR_RANGE); output |g| <= 25.6 g
 * (E05), no saturation needed. Maximum error against exact math: 0.5 LSB of Q16.16
 * (7.63e-6 g). Bit-identical on every target (64-bit integer math, no shifts of negatives).
 */
int sca3000_accel_g_from_counts(int32_t counts, enum sca3000_variant v, int32_t *g_q16);

/*
 * 9-bit temperature counts (0..511, else INC_ERR_RANGE) -> Q16.16 degC:
 * T = (raw - 214.6) / 1.8 = (10 raw - 2146) / 18, rounded to the nearest Q16.16 step, ties away
 * from zero; range -119.22..+164.67 degC, max error 0.5 LSB of Q16.16 (7.63e-6 degC).
 * The formula is the Linux driver's (offset -214.6 LSB, 0.555556 degC/LSB); the datasheet
 * value is UNCONFIRMED (docs/sensor-facts.md §1.4, docs/unconfirmed-facts.md).
 */
int sca3000_temp_c_from_counts(int32_t raw9, int32_t *c_q16);

/*
 * The driver as a struct sensor (inclino/sensor.h); dev = struct sca3000, cfg of init =
 * struct sca3000_cfg. An accelerometer with a temperature output on the D01 only.
 *   wait_ready  sca3000_wait_ready (output-rate pacing, see there).
 *   read        sca3000_read_sample: X, Y, Z in one CS period (and TEMP on the D01); t_ns = the
 *               time the last wait ended at, missed = the periods it found lost. Saturation per
 *               axis: a count at -4096 or 4095 (13-bit ends).
 *   read_diag   STATUS (sca3000_read_diag): frame error -> SENSOR_D_BUS, EEPROM checksum ->
 *               SENSOR_D_MEMORY (returned as 0 with the flags: the read worked); no supply.
 *   self_test   INC_ERR_UNSUPPORTED: no source describes a self-test for the part.
 *   identity    family SENSOR_FAMILY_SCA3000, product SCA3000_PRODUCT_*, revision = REVID.
 *   info        accel full scale 4096 x the variant's LSB (3.072, 4.096, 8.192, 25.6 g),
 *               rate = sca3000_odr_mhz.
 */
extern const struct sensor_ops sca3000_sensor_ops;

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_SCA3000_H */
