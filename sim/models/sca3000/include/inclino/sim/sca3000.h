/*
 * sim/sca3000.h - register-level model of the Murata/VTI SCA3000 3-axis accelerometer
 * (variants D01, E02, E04, E05), behind the pin-level SPI slave of sim/spi_slave.h.
 *
 * Written from docs/sensor-facts.md section 1 (and its sources), not from the driver.
 * Every behaviour the fact sheet leaves open is a stated assumption here and in
 * docs/drivers-sca3000.md ("The model"); the main ones:
 *
 * SPI. 8-bit words, MSB first. Modes 0 and 3 are both accepted: the part senses SCLK's level when
 *   CS falls (SIM_SPI_MODE_AUTO_0_3). Both modes shift MISO on SCLK's falling edge and sample MOSI
 *   on its rising edge, which is what VTI's TN15 describes for the sister parts. Timing limits
 *   (SIM_SCA3000_TIMING_*) are the assumed datasheet limits; the slave framework enforces them.
 * Frame. Byte 0 is the command: bits[7:2] address, bit1 = 1 write, bit0 must be 0. During the
 *   command byte the part shifts out 0x00. A read returns the addressed register on byte 1 and
 *   then auto-decrements: X_LSB (0x04) wraps to Z_MSB (0x09); BUF_DATA (0x0F) does not move
 *   (every further byte comes from the ring, MSB then LSB of each 16-bit sample); 0x00 wraps to
 *   0x3F. The output registers (X/Y/Z, TEMP, BUF_COUNT) are latched when CS falls, so one CS
 *   period reads one coherent sample set. A read's side effect (STATUS frame-error clear,
 *   INT_STATUS acknowledge, a ring sample leaving the buffer) happens only when its byte has been
 *   clocked out completely. A write is exactly [cmd][data] and takes effect at the CS rising
 *   edge, only if the frame was clean.
 * Frame error. A frame is corrupt when the slave framework saw any timing violation in it, or
 *   it ends in a partial byte, or the command has bit0 set, or a write frame is not exactly two
 *   bytes. A corrupt frame sets STATUS bit0; reading STATUS clears it (clear-on-read, assumed:
 *   the fact sheet only says "previous frame was corrupt").
 * Unlock. UNLOCK (0x1E) must be written 0x00, 0x50, 0xA0 in three consecutive CS periods; any
 *   other frame in between, or another value, restarts the sequence. While unlocked STATUS bit5
 *   reads 1 (the Linux driver's reading of the bit). CTRL_SEL/CTRL_DATA writes are ignored and
 *   CTRL_DATA reads 0 while locked. Any write to UNLOCK relocks first.
 * Lock-up. The fact sheet warns that touching reserved registers can lock the part up. The model
 *   locks up (answers 0x00 to everything, ignores writes, stops sampling, logs a protocol
 *   violation) on a write to a reserved address, on a write that changes protected bits (MODE
 *   0x28, INT_MASK 0x1C, MD_CTRL 0xC0) and on an OUT_CTRL write that clears any of bits[7:5]
 *   ("the device will not function"). sim_sca3000_power_cycle() recovers.
 * Measurement. Samples at the output data rate of the variant and MODE[1:0] (docs/sensor-facts.md §1.6) in
 *   virtual time: physics hook (or the static input) -> error-model hook -> scale (mg/LSB 0.75,
 *   1, 2, 6.25) -> saturation at the range (default: the 13-bit code range; sim cfg range_g) ->
 *   13-bit two's complement in bits[15:3]. Temperature (D01 only; 0 on the others): 9 bits in
 *   bits[13:5], counts = T * 1.8 + 214.6 (the Linux offset/scale, [U]). Motion-detection mode
 *   (MODE[1:0] = 11) freezes X/Y/Z at 0; motion and free-fall events are not modelled.
 *   MODE[1:0] = 10 on D01/E02 (no option 2) is refused (write ignored, protocol violation).
 * Ring buffer. MODE bit7 enables it (emptied when enabled); every 1st/2nd/4th sample
 *   (OUT_CTRL[1:0]) the enabled axes (OUT_CTRL bits 4..2 = X, Y, Z) are stored as 11-bit values
 *   in bits[15:5] (the 13-bit count floor-divided by 4). 192 values; when full the oldest is
 *   overwritten. BUF_COUNT = values stored. INT_STATUS bit6/bit7 are set when the count reaches
 *   96 / 144 (re-evaluated at every stored sample) and cleared by reading INT_STATUS. 8-bit ring
 *   mode is not modelled (logged).
 * Interrupt line. There is no data-ready output in any source: the model has none. Its INT
 *   output (on int_pin) is active while INT_STATUS & INT_MASK & 0xC0 != 0, polarity INT_MASK
 *   bit0 (1 = active high).
 */
#ifndef INCLINO_SIM_SCA3000_H
#define INCLINO_SIM_SCA3000_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/sim/inertial.h"
#include "inclino/sim/part.h"
#include "inclino/sim/spi_slave.h"

#ifdef __cplusplus
extern "C" {
#endif

enum sim_sca3000_variant {
    SIM_SCA3000_D01 = 0,
    SIM_SCA3000_E02 = 1,
    SIM_SCA3000_E04 = 2,
    SIM_SCA3000_E05 = 3,
};

/* Assumed part limits (no readable datasheet table; see docs/unconfirmed-facts.md). */
#define SIM_SCA3000_TIMING_MIN_PERIOD_NS 2000u /* SCLK <= 500 kHz */
#define SIM_SCA3000_TIMING_MIN_HALF_NS 1000u
#define SIM_SCA3000_TIMING_CS_SETUP_NS 1000u
#define SIM_SCA3000_TIMING_CS_HOLD_NS 1000u
#define SIM_SCA3000_TIMING_STALL_NS 10000u /* CS high between two CS periods */
#define SIM_SCA3000_TIMING_MOSI_SETUP_NS 50u
#define SIM_SCA3000_TIMING_MISO_DELAY_NS 250u /* MISO valid after the falling SCLK edge */

/* REVID the model answers unless configured otherwise (the real value is unknown, [U]). */
#define SIM_SCA3000_REVID_DEFAULT 0x52u

/* Factory content of the protected (reserved) bits, a model assumption: non-zero so that a
 * driver that does not read-modify-write is caught. */
#define SIM_SCA3000_MODE_DEFAULT 0x08u     /* bit3 reserved set, normal mode, ring off */
#define SIM_SCA3000_INT_MASK_DEFAULT 0x14u /* bits 4 and 2 (protected 0x1C) set, active low */
#define SIM_SCA3000_MD_CTRL_DEFAULT 0x40u  /* bit6 (protected 0xC0) set, no axis enabled */
#define SIM_SCA3000_OUT_CTRL_DEFAULT 0xFCu /* bits 7..5 set, X/Y/Z in the ring, no divider */

#define SIM_SCA3000_RING_SIZE 192u
#define SIM_SCA3000_NO_PIN 0xFFFFu

/* Fault injection, the "faulty fake device" (OR of bits). */
#define SIM_SCA3000_FAULT_EEPROM 0x01u /* STATUS bit1: EEPROM checksum error */

struct sim_sca3000_cfg {
    const char *name; /* for violation reports; default "sca3000" */
    struct sim_pinbus *bus;
    unsigned cs, sclk, mosi, miso;
    unsigned int_pin; /* INT output pin, or SIM_SCA3000_NO_PIN */
    enum sim_sca3000_variant variant;
    uint8_t revid;                       /* 0: SIM_SCA3000_REVID_DEFAULT */
    const struct sim_spi_timing *timing; /* NULL: the SIM_SCA3000_TIMING_* limits */
    double range_g;                      /* saturation in g; 0: the 13-bit code range */
    struct sim_violation_log *log;
};

struct sim_sca3000 {
    struct sim_spi_slave slave;
    struct sim_pinbus *bus;
    unsigned int_pin;
    int int_dev; /* pin-bus device id for INT, -1 when none */
    enum sim_sca3000_variant variant;
    const char *name;
    struct sim_violation_log *log;
    double range_g;
    uint8_t revid;

    /* inputs */
    struct sim_inertial_input input; /* static input (used when no physics hook) */
    struct sim_physics physics;      /* .sample NULL: use `input` */
    struct sim_error_model error;    /* .apply NULL: ideal part */

    /* register file */
    uint8_t mode, int_mask, int_status, ctrl_sel;
    uint8_t ind[16]; /* indirect registers by CTRL_SEL value */
    bool frame_error, unlocked, locked_up;
    unsigned unlock_step; /* UNLOCK values accepted in sequence: 0..2 */
    bool unlock_step_this_frame;
    uint8_t faults;
    uint16_t x, y, z, temp; /* output words as the registers hold them */
    int32_t count[3];       /* last 13-bit counts (for tests' diagnostics) */
    bool saturated;         /* last sample hit the range */

    /* ring buffer */
    uint16_t ring[SIM_SCA3000_RING_SIZE];
    unsigned ring_head, ring_count; /* oldest value, values stored */
    unsigned ring_div_phase;
    uint32_t ring_overwritten;

    /* the CS period in progress */
    uint16_t lx, ly, lz, ltemp; /* latched at CS fall */
    uint8_t lcount;             /* BUF_COUNT latched at CS fall */
    bool is_write, bad_cmd;
    uint8_t addr; /* address of the byte being shifted out */
    uint8_t wdata;
    unsigned ring_byte; /* 0: next ring byte is a sample's MSB, 1: its LSB */
    unsigned ring_peek; /* samples consumed in this period */
    bool have_out;      /* a read byte is in the shift register */
    uint8_t out_addr;

    /* sampling */
    int sample_handle; /* pending clock event, 0 none */
    uint64_t sample_period_ns;
    uint64_t samples;

    bool attached;

    /* injected faults (sim/part.h, sim_sca3000_part) */
    bool int_suppressed;        /* the INT line never goes active */
    bool int_extra;             /* a spurious INT pulse halfway through every sample period */
    int int_extra_ev;           /* its pending event (pulse or end), 0 when none */
    uint32_t int_extra_pulses;  /* spurious pulses given */
    bool wrong_id;              /* REVID reads revid + 1 */
    struct sim_stuck_bit stuck; /* an injected stuck data bit */

    /* statistics and diagnostics */
    uint32_t frames, corrupt_frames, writes_applied, protocol_errors;
    const char *last_protocol; /* what the last protocol violation was (static string) */
};

/*
 * Attach the model to the pins and start sampling (first sample at the current virtual time).
 * Returns 0, INC_ERR_NULL, INC_ERR_INVAL (variant, pins) or an error of the slave framework.
 */
int sim_sca3000_init(struct sim_sca3000 *m, const struct sim_sca3000_cfg *cfg);

/* The static physical input (used at every sample while no physics hook is installed). */
void sim_sca3000_set_input(struct sim_sca3000 *m, const struct sim_inertial_input *in);
/* Install (or with NULL remove) the physics and error-model hooks. */
void sim_sca3000_set_physics(struct sim_sca3000 *m, const struct sim_physics *p);
void sim_sca3000_set_error_model(struct sim_sca3000 *m, const struct sim_error_model *e);

/* Set the injected faults (SIM_SCA3000_FAULT_*). */
void sim_sca3000_set_faults(struct sim_sca3000 *m, uint8_t faults);

/* Power cycle: registers back to their defaults, locked, lock-up cleared, ring emptied. */
void sim_sca3000_power_cycle(struct sim_sca3000 *m);

/* Output data rate of the current mode in mHz (0 in motion-detection mode). */
uint32_t sim_sca3000_odr_mhz(const struct sim_sca3000 *m);

/* Disconnect from the bus (MISO released, no more sampling): "no device" at run time. */
void sim_sca3000_detach(struct sim_sca3000 *m);

/*
 * The part interface (sim/part.h). Faults: wire ones (MISO stuck, corrupt frame), physics ones,
 * and in the model: wrong identity (REVID + 1), no data-ready (the INT line never goes
 * active: the part has no data-ready output, INT is what a driver waits on), device error
 * (STATUS bit1, the EEPROM checksum error of SIM_SCA3000_FAULT_EEPROM), stuck bit (any
 * register byte as read over the bus). Busy is unsupported: the part has no busy state.
 * peek/poke address the 8-bit direct registers (peek: as latched for the current CS period).
 */
struct sim_part;
extern const struct sim_part_ops sim_sca3000_part_ops;
void sim_sca3000_part(struct sim_sca3000 *m, struct sim_part *p);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_SIM_SCA3000_H */
