/*
 * lf_e2e.c - libFuzzer entry for the E2E receiver and the CAN unpackers (firmware/services/e2e,
 * firmware/app/can): target `e2e` of tests/fuzz/CMakeLists.txt (the fuzz preset; docs/fuzzing.md).
 * Seeds: tests/fuzz/corpus/e2e/ (docs/can.md).
 *
 * The input is a script of records; the first byte of each selects:
 *   op % 4 == 0  a frame for the speed receiver: id (2 bytes, little endian, masked to 11 bits),
 *                dlc (1 byte, any value), 8 data bytes
 *   op % 4 == 1  a receive cycle without a frame
 *   op % 4 == 2  a raw Profile 1 check with a configuration from the next 5 bytes (data ID 2,
 *                len, max delta, sync init; out-of-range ones must be refused) and 8 data bytes
 *   op % 4 == 3  the three output unpackers on 8 data bytes with the id from the op's high bits
 * Invariants (abort on violation): every call returns its documented codes; the check state
 * stays in range; a usable status implies a correct CRC and a counter <= 14; a valid vehicle
 * input has |speed| <= 200 m/s and came from a usable frame at most timeout cycles old.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "inclino/can_frames.h"
#include "inclino/e2e.h"

#define REQ(c)       \
    do {             \
        if (!(c)) {  \
            abort(); \
        }            \
    } while (0)

static bool status_known(uint8_t s)
{
    return s == E2E_P01_OK || s == E2E_P01_NONEWDATA || s == E2E_P01_WRONGCRC ||
           s == E2E_P01_SYNC || s == E2E_P01_INITIAL || s == E2E_P01_REPEATED ||
           s == E2E_P01_OKSOMELOST || s == E2E_P01_WRONGSEQUENCE;
}

static void state_in_range(const struct e2e_p01_cfg *c, const struct e2e_p01_check_state *st)
{
    REQ(st->last_valid_counter <= E2E_P01_COUNTER_MAX);
    REQ(st->max_delta_counter <= E2E_P01_COUNTER_MAX);
    REQ(st->no_new_or_repeated <= E2E_P01_COUNTER_MAX);
    REQ(st->sync_counter <= c->sync_counter_init);
    REQ(status_known(st->status));
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    struct can_speed_rx rx;
    struct e2e_p01_check_state raw;
    struct e2e_p01_cfg raw_cfg = {0x1234u, 8u, 2u, 3u, 2u};
    REQ(can_speed_rx_init(&rx, 3u) == INC_OK);
    REQ(e2e_p01_check_init(&raw) == INC_OK);
    uint32_t cycles_since_usable = UINT32_MAX;
    size_t i = 0;
    while (i < size) {
        uint8_t op = data[i++];
        switch (op % 4u) {
        case 0: {
            if (size - i < 11u) {
                return 0;
            }
            struct can_frame f;
            f.id = ((uint32_t)data[i] | ((uint32_t)data[i + 1] << 8)) & 0x7FFu;
            f.dlc = data[i + 2];
            memcpy(f.data, &data[i + 3], 8u);
            i += 11u;
            uint32_t usable_before = rx.usable;
            struct app_vehicle v;
            REQ(can_speed_rx_cycle(&rx, &f, &v) == INC_OK);
            state_in_range(can_e2e_cfg(CAN_ID_SPEED), &rx.e2e);
            if (rx.usable != usable_before) {
                /* accepted: right id and length, correct CRC, usable status, both valid bits */
                REQ(f.id == CAN_ID_SPEED && f.dlc == 8u);
                REQ(e2e_p01_usable(rx.e2e.status));
                REQ(f.data[0] == e2e_p01_crc(can_e2e_cfg(CAN_ID_SPEED), f.data));
                REQ((f.data[1] & 0x0Fu) <= E2E_P01_COUNTER_MAX);
                REQ((f.data[1] & 0x30u) == 0x30u);
                cycles_since_usable = 0;
            } else if (cycles_since_usable != UINT32_MAX) {
                cycles_since_usable++;
            }
            if (v.valid) {
                REQ(cycles_since_usable <= rx.timeout_cycles);
                REQ(v.speed_mps <= 200 * 65536 && v.speed_mps >= -200 * 65536);
            }
            break;
        }
        case 1: {
            struct app_vehicle v;
            REQ(can_speed_rx_cycle(&rx, NULL, &v) == INC_OK);
            if (cycles_since_usable != UINT32_MAX) {
                cycles_since_usable++;
            }
            if (v.valid) {
                REQ(cycles_since_usable <= rx.timeout_cycles);
            }
            REQ(rx.e2e.status == E2E_P01_NONEWDATA);
            break;
        }
        case 2: {
            if (size - i < 13u) {
                return 0;
            }
            struct e2e_p01_cfg c = {(uint16_t)(data[i] | (data[i + 1] << 8)), data[i + 2],
                                    data[i + 3], 3u, data[i + 4]};
            uint8_t fr[8];
            memcpy(fr, &data[i + 5], 8u);
            i += 13u;
            if (e2e_p01_cfg_check(&c) != INC_OK) {
                REQ(e2e_p01_check(&c, &raw, fr, 8u, true) == INC_ERR_INVAL);
                break;
            }
            if (c.len > 8u) {
                c.len = 8u;
            }
            if (c.sync_counter_init != raw_cfg.sync_counter_init) {
                REQ(e2e_p01_check_init(&raw) == INC_OK); /* a new configuration, a new state */
            }
            raw_cfg = c;
            REQ(e2e_p01_check(&raw_cfg, &raw, fr, 8u, true) == INC_OK);
            state_in_range(&raw_cfg, &raw);
            if (e2e_p01_usable(raw.status) || raw.status == E2E_P01_INITIAL ||
                raw.status == E2E_P01_REPEATED || raw.status == E2E_P01_SYNC) {
                REQ(raw_cfg.len == 8u);
                REQ(fr[0] == e2e_p01_crc(&raw_cfg, fr));
                REQ((fr[1] & 0x0Fu) <= E2E_P01_COUNTER_MAX);
            }
            break;
        }
        default: {
            if (size - i < 8u) {
                return 0;
            }
            struct can_frame f;
            f.id = CAN_ID_SLOPE + ((op >> 2) % 4u); /* 0x310..0x313 */
            f.dlc = (op & 0x80u) ? 8u : (uint8_t)((op >> 4) & 7u);
            memcpy(f.data, &data[i], 8u);
            i += 8u;
            struct can_slope_sig s;
            struct can_att_sig a;
            struct can_status_sig st;
            int r1 = can_unpack_slope(&f, &s);
            int r2 = can_unpack_attitude(&f, &a);
            int r3 = can_unpack_status(&f, &st);
            REQ(r1 == (f.id == CAN_ID_SLOPE && f.dlc == 8u ? INC_OK : INC_ERR_INVAL));
            REQ(r2 == (f.id == CAN_ID_ATTITUDE && f.dlc == 8u ? INC_OK : INC_ERR_INVAL));
            REQ(r3 == (f.id == CAN_ID_STATUS && f.dlc == 8u ? INC_OK : INC_ERR_INVAL));
            if (r1 == INC_OK) {
                REQ(s.mode <= 1u);
                REQ(s.valid == ((f.data[1] & 0x10u) != 0u));
            }
            if (r3 == INC_OK) {
                REQ(st.fault == ((uint32_t)f.data[2] | ((uint32_t)f.data[3] << 8) |
                                 ((uint32_t)f.data[4] << 16) | ((uint32_t)f.data[5] << 24)));
            }
            break;
        }
        }
    }
    return 0;
}
