/*
 * e2e.h - end-to-end protection of small frames, AUTOSAR E2E Profile 1 (module inclino_e2e,
 * prefix e2e_). docs/can.md; [AUTOSAR-E2E], [AUTOSAR-CRC].
 *
 * CRC: CRC-8 SAE J1850 as the AUTOSAR CRC library computes it (Crc_CalculateCRC8): polynomial
 * 0x1D, initial value 0xFF, input and result not reflected, final XOR 0xFF; check ("123456789")
 * 0x4B, magic check 0xC4. e2e_crc8_j1850 has the library's calling convention: with first ==
 * false the start value is the previous call's result (its final XOR is undone first), so a
 * CRC over several pieces equals the CRC over their concatenation.
 *
 * Profile 1, variant 1A, with this fixed layout of a frame of len bytes (2..30):
 *   byte 0        the CRC (CRCOffset 0)
 *   byte 1 [3:0]  the counter 0..14 (CounterOffset 8); 15 is never sent
 *   the rest      the protected data (byte 1 [7:4] included)
 * Data ID mode BOTH (E2E_P01_DATAID_BOTH): both bytes of the 16-bit data ID enter the CRC,
 * low byte first, and are never sent. The CRC is the J1850 polynomial over
 *   data_id low, data_id high, bytes 1 .. len-1
 * computed as the profile does: Crc_CalculateCRC8 with start value 0xFF and first == false on
 * the ID (effective start 0x00), chained over the data, and the result XORed with 0xFF (so the
 * effective final XOR is 0x00).
 *
 * Sender: e2e_p01_protect writes the counter and the CRC, then increments the counter (14 -> 0).
 * Receiver: e2e_p01_check, called once per expected reception (the receive cycle), with
 * new_data telling whether a frame arrived. It follows the profile's check state machine:
 *   - MaxDeltaCounter grows by 1 at every call (saturating at 14): a receiver that saw nothing
 *     for k cycles accepts a counter jump of up to max_delta_counter_init + k;
 *   - no frame: NONEWDATA (NoNewOrRepeatedDataCounter + 1, saturating at 14);
 *   - CRC mismatch: WRONGCRC (nothing else changes); a frame of the wrong length and a counter
 *     of 15 are also reported as WRONGCRC (unconfirmed-facts.md: the profile treats them as an
 *     input error; here bus input always yields a status);
 *   - first correct frame: INITIAL (the counter is taken, nothing is accepted yet);
 *   - delta = received - last valid counter (mod 15): 0: REPEATED; 1: OK; 2..MaxDeltaCounter:
 *     OKSOMELOST (lost_data = delta - 1); beyond: WRONGSEQUENCE (resynchronisation starts: the
 *     counter is taken when sync_counter_init > 0, and sync_counter_init more in-sequence frames
 *     are reported SYNC);
 *   - after more than max_no_new_or_repeated NONEWDATA/REPEATED cycles, the next in-sequence
 *     frames are SYNC for sync_counter_init frames.
 * e2e_p01_usable() is the application's rule: only OK and OKSOMELOST deliver data.
 *
 * Freestanding C11, integer only, no heap. Not re-entrant per state.
 */
#ifndef INCLINO_E2E_H
#define INCLINO_E2E_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "inclino/error.h"

#ifdef __cplusplus
extern "C" {
#endif

#define E2E_CRC8_J1850_POLY 0x1Du
#define E2E_CRC8_J1850_INIT 0xFFu
#define E2E_CRC8_J1850_XOR 0xFFu
#define E2E_CRC8_J1850_CHECK 0x4Bu /* CRC of the ASCII bytes "123456789" */
#define E2E_CRC8_J1850_MAGIC 0xC4u /* CRC over data followed by its CRC */

/* Profile 1 limits. */
#define E2E_P01_COUNTER_MAX 14u /* the counter runs 0..14 and wraps to 0 */
#define E2E_P01_LEN_MIN 2u      /* CRC byte and counter byte */
#define E2E_P01_LEN_MAX 30u     /* DataLength <= 240 bits */
#define E2E_P01_CRC_BYTE 0u     /* CRCOffset 0 */
#define E2E_P01_COUNTER_BYTE 1u /* CounterOffset 8: low nibble of byte 1 */
#define E2E_P01_COUNTER_MASK 0x0Fu

/*
 * CRC-8 SAE J1850 over len bytes (AUTOSAR Crc_CalculateCRC8): first == true starts from 0xFF
 * (start is ignored); first == false continues from start, the result of a previous call.
 * data may be NULL only when len == 0 (the result is then start, or 0x00 for first).
 */
uint8_t e2e_crc8_j1850(const uint8_t *data, size_t len, uint8_t start, bool first);

/* The receiver's status of one check (the profile's E2E_P01CheckStatusType values). */
enum e2e_p01_status {
    E2E_P01_OK = 0x00,
    E2E_P01_NONEWDATA = 0x01,
    E2E_P01_WRONGCRC = 0x02,
    E2E_P01_SYNC = 0x03,
    E2E_P01_INITIAL = 0x04,
    E2E_P01_REPEATED = 0x08,
    E2E_P01_OKSOMELOST = 0x20,
    E2E_P01_WRONGSEQUENCE = 0x40,
};

struct e2e_p01_cfg {
    uint16_t data_id;               /* system-unique; both bytes enter the CRC */
    uint8_t len;                    /* frame length in bytes, E2E_P01_LEN_MIN..E2E_P01_LEN_MAX */
    uint8_t max_delta_counter_init; /* largest accepted counter jump after a reception, 1..14 */
    uint8_t max_no_new_or_repeated; /* NONEWDATA/REPEATED cycles tolerated, 0..14 */
    uint8_t sync_counter_init;      /* in-sequence frames needed to resynchronise, 0..14 */
};

struct e2e_p01_protect_state {
    uint8_t counter; /* the next counter to send, 0..14 */
};

struct e2e_p01_check_state {
    uint8_t last_valid_counter;
    uint8_t max_delta_counter;
    bool wait_for_first_data;
    uint8_t lost_data; /* frames lost before the last OK/OKSOMELOST one */
    uint8_t no_new_or_repeated;
    uint8_t sync_counter;
    uint8_t status; /* enum e2e_p01_status of the last check */
};

/* 0, INC_ERR_NULL, INC_ERR_INVAL (a field outside its range). */
int e2e_p01_cfg_check(const struct e2e_p01_cfg *cfg);

/* Counter 0. INC_ERR_NULL. */
int e2e_p01_protect_init(struct e2e_p01_protect_state *st);

/* The Profile 1 CRC of frame (cfg->len bytes, byte 0 not read) for cfg's data ID. */
uint8_t e2e_p01_crc(const struct e2e_p01_cfg *cfg, const uint8_t *frame);

/*
 * Write the counter into the low nibble of frame[1] (its high nibble is kept), the CRC into
 * frame[0], and advance the counter. len must be cfg->len. 0, INC_ERR_NULL, INC_ERR_INVAL (cfg,
 * len), INC_ERR_STATE (a counter > 14 in st; nothing written).
 */
int e2e_p01_protect(const struct e2e_p01_cfg *cfg, struct e2e_p01_protect_state *st, uint8_t *frame,
                    size_t len);

/* Waiting for the first frame, status NONEWDATA. INC_ERR_NULL. */
int e2e_p01_check_init(struct e2e_p01_check_state *st);

/*
 * One receive cycle: new_data == false means no frame arrived (frame may then be NULL, len is
 * not used). Sets st->status (enum e2e_p01_status) and returns 0; INC_ERR_NULL (cfg, st, or
 * frame with new_data), INC_ERR_INVAL (cfg), INC_ERR_STATE (a state whose fields are out of
 * range: st is then re-initialised and the status is WRONGCRC).
 */
int e2e_p01_check(const struct e2e_p01_cfg *cfg, struct e2e_p01_check_state *st,
                  const uint8_t *frame, size_t len, bool new_data);

/* True for the statuses whose data the application may use: OK and OKSOMELOST. */
bool e2e_p01_usable(uint8_t status);

/* A short name of a status ("OK", "WRONGCRC", ...; "?" for others). */
const char *e2e_p01_status_name(uint8_t status);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_E2E_H */
