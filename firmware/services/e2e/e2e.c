/* e2e.c - CRC-8 SAE J1850 and AUTOSAR E2E Profile 1 (variant 1A); see inclino/e2e.h. */
#include "inclino/e2e.h"

uint8_t e2e_crc8_j1850(const uint8_t *data, size_t len, uint8_t start, bool first)
{
    /* the library's convention: the register starts at 0xFF on the first call, otherwise at the
     * previous result with its final XOR undone */
    uint8_t crc = first ? (uint8_t)E2E_CRC8_J1850_INIT : (uint8_t)(start ^ E2E_CRC8_J1850_XOR);
    if (data == NULL) {
        return (uint8_t)(crc ^ E2E_CRC8_J1850_XOR);
    }
    for (size_t i = 0; i < len; i++) {
        crc ^= data[i];
        for (unsigned b = 0; b < 8u; b++) {
            if ((crc & 0x80u) != 0u) {
                crc = (uint8_t)((uint8_t)(crc << 1) ^ E2E_CRC8_J1850_POLY);
            } else {
                crc = (uint8_t)(crc << 1);
            }
        }
    }
    return (uint8_t)(crc ^ E2E_CRC8_J1850_XOR);
}

int e2e_p01_cfg_check(const struct e2e_p01_cfg *cfg)
{
    if (cfg == NULL) {
        return INC_ERR_NULL;
    }
    if (cfg->len < E2E_P01_LEN_MIN || cfg->len > E2E_P01_LEN_MAX ||
        cfg->max_delta_counter_init < 1u || cfg->max_delta_counter_init > E2E_P01_COUNTER_MAX ||
        cfg->max_no_new_or_repeated > E2E_P01_COUNTER_MAX ||
        cfg->sync_counter_init > E2E_P01_COUNTER_MAX) {
        return INC_ERR_INVAL;
    }
    return INC_OK;
}

int e2e_p01_protect_init(struct e2e_p01_protect_state *st)
{
    if (st == NULL) {
        return INC_ERR_NULL;
    }
    st->counter = 0;
    return INC_OK;
}

uint8_t e2e_p01_crc(const struct e2e_p01_cfg *cfg, const uint8_t *frame)
{
    const uint8_t id[2] = {(uint8_t)(cfg->data_id & 0xFFu), (uint8_t)(cfg->data_id >> 8)};
    /* start value 0xFF with first == false: the register starts at 0x00 */
    uint8_t crc = e2e_crc8_j1850(&id[0], 1u, 0xFFu, false);
    crc = e2e_crc8_j1850(&id[1], 1u, crc, false);
    /* the bytes before the CRC (none: CRCOffset 0), then the bytes after it */
    crc = e2e_crc8_j1850(&frame[E2E_P01_CRC_BYTE + 1u], (size_t)cfg->len - 1u, crc, false);
    return (uint8_t)(crc ^ 0xFFu);
}

int e2e_p01_protect(const struct e2e_p01_cfg *cfg, struct e2e_p01_protect_state *st, uint8_t *frame,
                    size_t len)
{
    if (cfg == NULL || st == NULL || frame == NULL) {
        return INC_ERR_NULL;
    }
    if (e2e_p01_cfg_check(cfg) != INC_OK || len != cfg->len) {
        return INC_ERR_INVAL;
    }
    if (st->counter > E2E_P01_COUNTER_MAX) {
        return INC_ERR_STATE;
    }
    frame[E2E_P01_COUNTER_BYTE] = (uint8_t)((frame[E2E_P01_COUNTER_BYTE] & 0xF0u) |
                                            (st->counter & E2E_P01_COUNTER_MASK));
    frame[E2E_P01_CRC_BYTE] = e2e_p01_crc(cfg, frame);
    st->counter = (uint8_t)((st->counter + 1u) % (E2E_P01_COUNTER_MAX + 1u));
    return INC_OK;
}

int e2e_p01_check_init(struct e2e_p01_check_state *st)
{
    if (st == NULL) {
        return INC_ERR_NULL;
    }
    st->last_valid_counter = 0;
    st->max_delta_counter = 0;
    st->wait_for_first_data = true;
    st->lost_data = 0;
    st->no_new_or_repeated = 0;
    st->sync_counter = 0;
    st->status = E2E_P01_NONEWDATA;
    return INC_OK;
}

/* After an in-sequence frame (OK or OKSOMELOST): resynchronisation after too many cycles
 * without new data, or its count-down. */
static void check_sync(const struct e2e_p01_cfg *cfg, struct e2e_p01_check_state *st)
{
    if (st->no_new_or_repeated <= cfg->max_no_new_or_repeated) {
        st->no_new_or_repeated = 0;
        if (st->sync_counter > 0u) {
            st->sync_counter--;
            st->status = E2E_P01_SYNC;
        }
    } else {
        st->no_new_or_repeated = 0;
        st->sync_counter = cfg->sync_counter_init;
        st->status = E2E_P01_SYNC;
    }
}

static void check_counter(const struct e2e_p01_cfg *cfg, struct e2e_p01_check_state *st,
                          uint8_t counter)
{
    uint8_t delta;
    if (counter >= st->last_valid_counter) {
        delta = (uint8_t)(counter - st->last_valid_counter);
    } else {
        delta = (uint8_t)(E2E_P01_COUNTER_MAX + 1u + counter - st->last_valid_counter);
    }
    if (delta == 0u) {
        if (st->no_new_or_repeated < E2E_P01_COUNTER_MAX) {
            st->no_new_or_repeated++;
        }
        st->status = E2E_P01_REPEATED;
    } else if (delta <= st->max_delta_counter) {
        st->max_delta_counter = cfg->max_delta_counter_init;
        st->last_valid_counter = counter;
        st->lost_data = (uint8_t)(delta - 1u);
        st->status = delta == 1u ? E2E_P01_OK : E2E_P01_OKSOMELOST;
        check_sync(cfg, st);
    } else {
        st->no_new_or_repeated = 0;
        st->sync_counter = cfg->sync_counter_init;
        if (st->sync_counter > 0u) {
            st->max_delta_counter = cfg->max_delta_counter_init;
            st->last_valid_counter = counter;
        }
        st->status = E2E_P01_WRONGSEQUENCE;
    }
}

int e2e_p01_check(const struct e2e_p01_cfg *cfg, struct e2e_p01_check_state *st,
                  const uint8_t *frame, size_t len, bool new_data)
{
    if (cfg == NULL || st == NULL || (new_data && frame == NULL)) {
        return INC_ERR_NULL;
    }
    if (e2e_p01_cfg_check(cfg) != INC_OK) {
        return INC_ERR_INVAL;
    }
    if (st->last_valid_counter > E2E_P01_COUNTER_MAX ||
        st->max_delta_counter > E2E_P01_COUNTER_MAX ||
        st->no_new_or_repeated > E2E_P01_COUNTER_MAX || st->sync_counter > cfg->sync_counter_init) {
        (void)e2e_p01_check_init(st);
        st->status = E2E_P01_WRONGCRC;
        return INC_ERR_STATE;
    }
    if (st->max_delta_counter < E2E_P01_COUNTER_MAX) {
        st->max_delta_counter++;
    }
    if (!new_data) {
        if (st->no_new_or_repeated < E2E_P01_COUNTER_MAX) {
            st->no_new_or_repeated++;
        }
        st->status = E2E_P01_NONEWDATA;
        return INC_OK;
    }
    if (len != cfg->len) {
        st->status = E2E_P01_WRONGCRC;
        return INC_OK;
    }
    uint8_t counter = (uint8_t)(frame[E2E_P01_COUNTER_BYTE] & E2E_P01_COUNTER_MASK);
    if (counter > E2E_P01_COUNTER_MAX || frame[E2E_P01_CRC_BYTE] != e2e_p01_crc(cfg, frame)) {
        st->status = E2E_P01_WRONGCRC;
        return INC_OK;
    }
    if (st->wait_for_first_data) {
        st->wait_for_first_data = false;
        st->max_delta_counter = cfg->max_delta_counter_init;
        st->last_valid_counter = counter;
        st->status = E2E_P01_INITIAL;
        return INC_OK;
    }
    check_counter(cfg, st, counter);
    return INC_OK;
}

bool e2e_p01_usable(uint8_t status)
{
    return status == E2E_P01_OK || status == E2E_P01_OKSOMELOST;
}

const char *e2e_p01_status_name(uint8_t status)
{
    switch (status) {
    case E2E_P01_OK: return "OK";
    case E2E_P01_NONEWDATA: return "NONEWDATA";
    case E2E_P01_WRONGCRC: return "WRONGCRC";
    case E2E_P01_SYNC: return "SYNC";
    case E2E_P01_INITIAL: return "INITIAL";
    case E2E_P01_REPEATED: return "REPEATED";
    case E2E_P01_OKSOMELOST: return "OKSOMELOST";
    case E2E_P01_WRONGSEQUENCE: return "WRONGSEQUENCE";
    default: return "?";
    }
}
