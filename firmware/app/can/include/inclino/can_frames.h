/*
 * can_frames.h - the application's CAN frames (module inclino_can, prefix can_). docs/can.md;
 * firmware/app/can/inclino.dbc describes the same frames and signals.
 *
 * Classic CAN, 11-bit identifiers, 8 data bytes, every multi-byte signal little endian (Intel),
 * every frame protected with AUTOSAR E2E Profile 1, variant 1A (inclino/e2e.h): byte 0 the CRC,
 * byte 1 [3:0] the counter, a 16-bit data ID per frame in the CRC.
 *
 *   0x310 INC_Slope     (tx, each EPB estimate)   data ID 0x1310
 *     byte 1 bit 4 SlopeValid, bit 5 SlopeMode (0 parked, 1 driving)
 *     bytes 2-3 Slope      int16  0.01 deg   (-327.68 .. 327.67)
 *     bytes 4-5 Grade      int16  0.01 %
 *     bytes 6-7 SlopeBound uint16 0.001 deg  (0 .. 65.535)
 *   0x311 INC_Attitude  (tx, each ESC output)     data ID 0x1311
 *     byte 1 bit 4 AttValid, bit 5 AttMode
 *     bytes 2-3 Roll       int16  0.01 deg
 *     bytes 4-5 Pitch      int16  0.01 deg
 *     bytes 6-7 AttBound   uint16 0.001 deg
 *   0x312 INC_Status    (tx, with each of the two) data ID 0x1312
 *     byte 1 bit 4 Mode, bit 5 SpeedInputOk
 *     bytes 2-5 FaultWord  uint32 (bits 0-7 APP_F_*, 8-15 SLOPE_F_*, 16-23 ATT_FAULT_*,
 *               24 CAN_FAULT_SPEED_INPUT, 25 CAN_FAULT_SCALING)
 *     bytes 6-7 GradeBound uint16 0.01 %     (0 .. 655.35)
 *   0x1A0 VEH_Speed     (rx, the vehicle's speed and yaw rate) data ID 0x11A0
 *     byte 1 bit 4 SpeedValid, bit 5 YawRateValid
 *     bytes 2-3 VehSpeed   int16  0.01 m/s   (|.| <= 200 accepted)
 *     bytes 4-5 YawRate    int16  0.01 deg/s
 *     bytes 6-7 reserved (sent 0, not checked)
 * Unused bits are sent 0.
 *
 * Scaling (Q16.16 in, raw out): values round(v * scale / 2^16), ties away from zero, |error|
 * <= 0.5 LSB; bounds ceil(v * scale / 2^16), so a sent bound is never below the computed one
 * (error in [0, 1) LSB). A value or bound that does not fit its field is sent saturated, its
 * frame's valid bit cleared and CAN_FAULT_SCALING set in the fault word: a clipped value is never
 * marked valid. Unpacking multiplies back exactly (raw * 2^16 / scale, rounded to nearest Q16).
 *
 * Freestanding C11, integer only, no heap.
 */
#ifndef INCLINO_CAN_FRAMES_H
#define INCLINO_CAN_FRAMES_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "inclino/app.h"
#include "inclino/app_esc.h"
#include "inclino/e2e.h"
#include "inclino/error.h"
#include "inclino/fx.h"

#ifdef __cplusplus
extern "C" {
#endif

#define CAN_ID_SLOPE 0x310u
#define CAN_ID_ATTITUDE 0x311u
#define CAN_ID_STATUS 0x312u
#define CAN_ID_SPEED 0x1A0u

#define CAN_DATAID_SLOPE 0x1310u
#define CAN_DATAID_ATTITUDE 0x1311u
#define CAN_DATAID_STATUS 0x1312u
#define CAN_DATAID_SPEED 0x11A0u

#define CAN_DLC 8u

/* Raw units per physical unit. */
#define CAN_SCALE_ANGLE 100u  /* 0.01 deg */
#define CAN_SCALE_GRADE 100u  /* 0.01 % */
#define CAN_SCALE_BOUND 1000u /* 0.001 deg */
#define CAN_SCALE_GBOUND 100u /* 0.01 % */
#define CAN_SCALE_SPEED 100u  /* 0.01 m/s */
#define CAN_SCALE_YAW 100u    /* 0.01 deg/s */

/* byte 1 flag bits (above the counter nibble) */
#define CAN_B1_VALID 0x10u    /* Slope/Att valid; Speed: SpeedValid */
#define CAN_B1_MODE 0x20u     /* Slope/Att: mode driving; Speed: YawRateValid */
#define CAN_B1_ST_MODE 0x10u  /* Status: mode driving */
#define CAN_B1_ST_SPEED 0x20u /* Status: speed input usable */

/* Fault word bits beyond the application's own (bits 24..31). */
#define CAN_FAULT_SPEED_INPUT (1u << 24) /* ESC mode: no usable speed frame within the timeout */
#define CAN_FAULT_SCALING (1u << 25)     /* a value or bound did not fit its field */

/* Speeds beyond this are refused by the receiver (struct app_vehicle's range). */
#define CAN_SPEED_MAX_RAW 20000

struct can_frame {
    uint32_t id; /* 11-bit standard identifier */
    uint8_t dlc; /* 0..8 */
    uint8_t data[8];
};

/* The E2E configuration of a frame of this interface (NULL for another identifier). Every frame:
 * len 8, max_delta_counter_init 2, max_no_new_or_repeated 3, sync_counter_init 2. */
const struct e2e_p01_cfg *can_e2e_cfg(uint32_t id);

/* The sender: one counter per transmitted frame. */
struct can_tx {
    struct e2e_p01_protect_state slope, att, status;
};

int can_tx_init(struct can_tx *tx);

/* The raw signals of the transmitted frames (what the DBC decodes). */
struct can_slope_sig {
    bool valid;
    uint8_t mode;
    int16_t slope;  /* 0.01 deg */
    int16_t grade;  /* 0.01 % */
    uint16_t bound; /* 0.001 deg */
};

struct can_att_sig {
    bool valid;
    uint8_t mode;
    int16_t roll, pitch; /* 0.01 deg */
    uint16_t bound;      /* 0.001 deg */
};

struct can_status_sig {
    uint8_t mode;
    bool speed_ok;
    uint32_t fault;
    uint16_t grade_bound; /* 0.01 % */
};

/* Fault word of an output: app flags, slope flags, attitude fault bits, extra CAN_FAULT_*. */
uint32_t can_fault_word(uint32_t app_flags, uint32_t slope_flags, uint8_t att_fault,
                        uint32_t extra);

/*
 * Pack (scale, then protect) one frame. The _sig forms fill *sig with the raw values sent
 * (NULL allowed); *scaling_fault is set true when a value had to be clipped (NULL allowed).
 * 0, INC_ERR_NULL, or e2e_p01_protect's error.
 */
int can_pack_slope(struct can_tx *tx, const struct slope_result *s, uint8_t mode,
                   struct can_frame *f, struct can_slope_sig *sig, bool *scaling_fault);
int can_pack_attitude(struct can_tx *tx, const struct app_esc_output *o, struct can_frame *f,
                      struct can_att_sig *sig, bool *scaling_fault);
int can_pack_status(struct can_tx *tx, uint8_t mode, bool speed_ok, uint32_t fault,
                    fx_q16_t grade_bound_pct, struct can_frame *f, struct can_status_sig *sig);

/*
 * The frames of one output of the application: PARKED (or the EPB demo): INC_Slope and
 * INC_Status; DRIVING: INC_Attitude and INC_Status. speed_ok tells whether the speed input was
 * usable (it goes into the status frame; its absence into the fault word in DRIVING).
 * frames[2] receives them; *n = 2. 0, INC_ERR_NULL, INC_ERR_INVAL (mode).
 */
int can_pack_output(struct can_tx *tx, const struct app_esc_output *o, bool speed_ok,
                    struct can_frame frames[2], size_t *n);

/* Unpack the raw signals (no E2E check: see can_e2e_cfg / e2e_p01_check). INC_ERR_NULL,
 * INC_ERR_INVAL (another identifier, dlc != 8). */
int can_unpack_slope(const struct can_frame *f, struct can_slope_sig *s);
int can_unpack_attitude(const struct can_frame *f, struct can_att_sig *s);
int can_unpack_status(const struct can_frame *f, struct can_status_sig *s);

/* The sender of the speed frame (the vehicle side; used by the simulation and the tests). */
int can_pack_speed(struct e2e_p01_protect_state *st, bool speed_valid, fx_q16_t speed_mps,
                   bool yaw_valid, fx_q16_t yaw_rate_dps, struct can_frame *f);

/*
 * The receiver of the speed frame, run once per receive cycle (the frame's period). It E2E-checks
 * the frame (NULL: none arrived this cycle), and delivers the vehicle input for the attitude
 * estimator: valid only while the latest usable frame (E2E OK or OKSOMELOST, SpeedValid and
 * YawRateValid set, |speed| <= 200 m/s) is at most timeout_cycles old. Its values are the frame's,
 * converted exactly to Q16 (0.01 m/s = 655.36 Q16, rounded to nearest).
 */
struct can_speed_rx {
    struct e2e_p01_check_state e2e;
    struct app_vehicle last; /* the latest usable values */
    uint32_t age;            /* receive cycles since it */
    uint32_t timeout_cycles; /* >= 1 */
    bool have;
    uint32_t usable, rejected; /* statistics: usable frames, frames not usable */
};

/* 0, INC_ERR_NULL, INC_ERR_INVAL (timeout_cycles 0). */
int can_speed_rx_init(struct can_speed_rx *rx, uint32_t timeout_cycles);

/* One cycle; *out receives the vehicle input (valid false when there is none). 0, INC_ERR_NULL,
 * INC_ERR_STATE (e2e state corrupted: re-initialised, *out invalid). */
int can_speed_rx_cycle(struct can_speed_rx *rx, const struct can_frame *f, struct app_vehicle *out);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_CAN_FRAMES_H */
