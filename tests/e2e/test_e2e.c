/* E2E Profile 1 and CRC-8 SAE J1850 (inclino/e2e.h). */
#include "inclino/e2e.h"
#include "unit.h"

#include <string.h>

/* Reference: the J1850 polynomial as long division of the message bit string, MSB first, with an
 * explicit initial register and final XOR (written independently of e2e.c's loop). */
static uint8_t ref_crc8(const uint8_t *d, size_t n, uint8_t init, uint8_t xorout)
{
    uint16_t reg = init;
    for (size_t i = 0; i < n; i++) {
        for (int b = 7; b >= 0; b--) {
            unsigned in = ((unsigned)d[i] >> b) & 1u;
            unsigned top = ((reg >> 7) & 1u) ^ in;
            reg = (uint16_t)((reg << 1) & 0xFFu);
            if (top) {
                reg ^= 0x1Du;
            }
        }
    }
    return (uint8_t)(reg ^ xorout);
}

static const struct e2e_p01_cfg cfg_ex = {
    .data_id = 0x0123u,
    .len = 8u,
    .max_delta_counter_init = 2u,
    .max_no_new_or_repeated = 3u,
    .sync_counter_init = 2u,
};

static void test_crc_published_values(void)
{
    /* AUTOSAR CRC library, CRC-8 SAE J1850: check and magic check, and its table of results */
    const uint8_t check[] = "123456789";
    CHECK_EQ_HEX(e2e_crc8_j1850(check, 9u, 0u, true), 0x4Bu);
    uint8_t m[10];
    memcpy(m, check, 9u);
    m[9] = 0x4Bu;
    /* the register after data and its CRC, before the final XOR */
    CHECK_EQ_HEX(e2e_crc8_j1850(m, 10u, 0u, true) ^ 0xFFu, E2E_CRC8_J1850_MAGIC);
    static const struct {
        uint8_t d[9];
        size_t n;
        uint8_t crc;
    } v[] = {
        {{0x00, 0x00, 0x00, 0x00}, 4, 0x59},
        {{0xF2, 0x01, 0x83}, 3, 0x37},
        {{0x0F, 0xAA, 0x00, 0x55}, 4, 0x79},
        {{0x00, 0xFF, 0x55, 0x11}, 4, 0xB8},
        {{0x33, 0x22, 0x55, 0xAA, 0xBB, 0xCC, 0xDD, 0xEE, 0xFF}, 9, 0xCB},
        {{0x92, 0x6B, 0x55}, 3, 0x8C},
        {{0xFF, 0xFF, 0xFF, 0xFF}, 4, 0x74},
    };
    for (size_t i = 0; i < sizeof v / sizeof v[0]; i++) {
        CHECK_EQ_HEX(e2e_crc8_j1850(v[i].d, v[i].n, 0u, true), v[i].crc);
        CHECK_EQ_HEX(ref_crc8(v[i].d, v[i].n, 0xFFu, 0xFFu), v[i].crc);
        /* chained in two pieces: the same result */
        uint8_t c = e2e_crc8_j1850(v[i].d, 1u, 0u, true);
        CHECK_EQ_HEX(e2e_crc8_j1850(v[i].d + 1, v[i].n - 1u, c, false), v[i].crc);
    }
    CHECK_EQ_HEX(e2e_crc8_j1850(NULL, 0u, 0u, true), 0x00u);
    CHECK_EQ_HEX(e2e_crc8_j1850(NULL, 0u, 0x5Au, false), 0x5Au);
}

static void test_p01_crc_is_the_profile_formula(void)
{
    /* Profile 1, DATAID_BOTH: J1850 polynomial, effective start 0x00 and final XOR 0x00, over
     * data ID low, data ID high, then bytes 1..7. Values computed independently (Python). */
    uint8_t f[8] = {0, 0x10, 0x11, 0x22, 0x33, 0x44, 0x55, 0x66};
    static const struct {
        uint8_t cnt, crc;
    } ex[] = {{0, 0xDD}, {1, 0x80}, {14, 0xDC}};
    for (size_t i = 0; i < 3; i++) {
        f[1] = ex[i].cnt;
        f[0] = 0;
        CHECK_EQ_HEX(e2e_p01_crc(&cfg_ex, f), ex[i].crc);
    }
    for (unsigned id = 0; id < 65536u; id += 257u) {
        struct e2e_p01_cfg c = cfg_ex;
        c.data_id = (uint16_t)id;
        uint8_t msg[9] = {(uint8_t)(id & 0xFFu), (uint8_t)(id >> 8)};
        memcpy(&msg[2], &f[1], 7u);
        CHECK_EQ_HEX(e2e_p01_crc(&c, f), ref_crc8(msg, 9u, 0x00u, 0x00u));
    }
}

static void test_protect_counter_and_layout(void)
{
    struct e2e_p01_protect_state ps;
    CHECK_OK(e2e_p01_protect_init(&ps));
    uint8_t f[8] = {0xEE, 0xAF, 1, 2, 3, 4, 5, 6};
    for (unsigned i = 0; i < 40u; i++) {
        CHECK_OK(e2e_p01_protect(&cfg_ex, &ps, f, 8u));
        CHECK_EQ_HEX(f[1] & 0x0Fu, i % 15u); /* 0..14, 15 is never sent */
        CHECK_EQ_HEX(f[1] & 0xF0u, 0xA0u);   /* the high nibble is data */
        CHECK_EQ_HEX(f[0], e2e_p01_crc(&cfg_ex, f));
        CHECK_EQ_INT(f[2], 1);
    }
    CHECK_ERR(e2e_p01_protect(&cfg_ex, &ps, f, 7u), INC_ERR_INVAL);
    CHECK_ERR(e2e_p01_protect(NULL, &ps, f, 8u), INC_ERR_NULL);
    ps.counter = 15u;
    CHECK_ERR(e2e_p01_protect(&cfg_ex, &ps, f, 8u), INC_ERR_STATE);
    struct e2e_p01_cfg bad = cfg_ex;
    bad.len = 1u;
    CHECK_ERR(e2e_p01_cfg_check(&bad), INC_ERR_INVAL);
    bad = cfg_ex;
    bad.len = 31u;
    CHECK_ERR(e2e_p01_cfg_check(&bad), INC_ERR_INVAL);
    bad = cfg_ex;
    bad.max_delta_counter_init = 0u;
    CHECK_ERR(e2e_p01_cfg_check(&bad), INC_ERR_INVAL);
    bad = cfg_ex;
    bad.sync_counter_init = 15u;
    CHECK_ERR(e2e_p01_cfg_check(&bad), INC_ERR_INVAL);
}

/* A sender and a receiver of cfg_ex. */
struct link {
    struct e2e_p01_protect_state tx;
    struct e2e_p01_check_state rx;
    uint8_t f[8];
};

static void link_init(struct link *l)
{
    CHECK_OK(e2e_p01_protect_init(&l->tx));
    CHECK_OK(e2e_p01_check_init(&l->rx));
    static const uint8_t payload[8] = {0, 0x30, 9, 8, 7, 6, 5, 4};
    memcpy(l->f, payload, 8u);
}

static void link_send(struct link *l)
{
    CHECK_OK(e2e_p01_protect(&cfg_ex, &l->tx, l->f, 8u));
}

static uint8_t link_rx(struct link *l, const uint8_t *f)
{
    CHECK_OK(e2e_p01_check(&cfg_ex, &l->rx, f, 8u, f != NULL));
    return l->rx.status;
}

/* send and receive one frame */
static uint8_t link_step(struct link *l)
{
    link_send(l);
    return link_rx(l, l->f);
}

static void test_check_in_sequence_and_wrap(void)
{
    struct link l;
    link_init(&l);
    CHECK_EQ_INT(l.rx.status, E2E_P01_NONEWDATA);
    CHECK_EQ_INT(link_step(&l), E2E_P01_INITIAL);
    CHECK(!e2e_p01_usable(E2E_P01_INITIAL));
    for (unsigned i = 0; i < 45u; i++) { /* three wraps of the counter */
        CHECK_EQ_INT(link_step(&l), E2E_P01_OK);
        CHECK_EQ_INT(l.rx.lost_data, 0);
    }
    CHECK(e2e_p01_usable(l.rx.status));
}

static void test_check_repetition(void)
{
    struct link l;
    link_init(&l);
    link_step(&l);
    CHECK_EQ_INT(link_step(&l), E2E_P01_OK);
    /* the same frame again: REPEATED, never usable */
    CHECK_EQ_INT(link_rx(&l, l.f), E2E_P01_REPEATED);
    CHECK(!e2e_p01_usable(E2E_P01_REPEATED));
    CHECK_EQ_INT(link_step(&l), E2E_P01_OK); /* 1 repetition <= max_no_new_or_repeated (3) */
    for (unsigned i = 0; i < 4u; i++) {
        CHECK_EQ_INT(link_rx(&l, l.f), E2E_P01_REPEATED);
    }
    /* 4 > 3 cycles without new data: the next in-sequence frames resynchronise */
    CHECK_EQ_INT(link_step(&l), E2E_P01_SYNC);
    CHECK_EQ_INT(link_step(&l), E2E_P01_SYNC);
    CHECK_EQ_INT(link_step(&l), E2E_P01_SYNC);
    CHECK_EQ_INT(link_step(&l), E2E_P01_OK);
}

static void test_check_loss(void)
{
    struct link l;
    link_init(&l);
    link_step(&l);
    link_step(&l);
    /* one frame lost on the bus (the receiver still checks that cycle: NONEWDATA) */
    link_send(&l);
    CHECK_EQ_INT(link_rx(&l, NULL), E2E_P01_NONEWDATA);
    CHECK_EQ_INT(link_step(&l), E2E_P01_OKSOMELOST);
    CHECK_EQ_INT(l.rx.lost_data, 1);
    CHECK(e2e_p01_usable(E2E_P01_OKSOMELOST));
    /* one lost without a check in between: delta 2 <= max_delta_counter_init (2) */
    link_send(&l);
    CHECK_EQ_INT(link_step(&l), E2E_P01_OKSOMELOST);
    CHECK_EQ_INT(l.rx.lost_data, 1);
    CHECK_EQ_INT(link_step(&l), E2E_P01_OK);
    /* three lost, the receiver unaware: delta 4 > 2: WRONGSEQUENCE, then resynchronisation */
    link_send(&l);
    link_send(&l);
    link_send(&l);
    CHECK_EQ_INT(link_step(&l), E2E_P01_WRONGSEQUENCE);
    CHECK(!e2e_p01_usable(E2E_P01_WRONGSEQUENCE));
    CHECK_EQ_INT(link_step(&l), E2E_P01_SYNC);
    CHECK_EQ_INT(link_step(&l), E2E_P01_SYNC);
    CHECK_EQ_INT(link_step(&l), E2E_P01_OK);
    /* 14 lost: delta 0 mod 15 looks like a repetition, which is never usable */
    for (unsigned i = 0; i < 14u; i++) {
        link_send(&l);
    }
    CHECK_EQ_INT(link_step(&l), E2E_P01_REPEATED);
}

static void test_check_delay(void)
{
    struct link l;
    link_init(&l);
    link_step(&l);
    link_step(&l);
    /* a frame one cycle late: NONEWDATA, then it arrives in sequence */
    link_send(&l);
    CHECK_EQ_INT(link_rx(&l, NULL), E2E_P01_NONEWDATA);
    CHECK_EQ_INT(link_rx(&l, l.f), E2E_P01_OK);
    /* an old frame delivered after newer ones (out of order): never usable */
    uint8_t old[8];
    link_send(&l);
    memcpy(old, l.f, 8u);
    link_rx(&l, l.f);
    CHECK_EQ_INT(link_step(&l), E2E_P01_OK);
    CHECK_EQ_INT(link_step(&l), E2E_P01_OK);
    CHECK_EQ_INT(link_rx(&l, old), E2E_P01_WRONGSEQUENCE);
    /* the stream goes on (a jump of 3 from the old counter, within the grown MaxDeltaCounter):
     * it resynchronises over sync_counter_init frames */
    CHECK_EQ_INT(link_step(&l), E2E_P01_SYNC);
    CHECK_EQ_INT(link_step(&l), E2E_P01_SYNC);
    CHECK_EQ_INT(link_step(&l), E2E_P01_OK);
    /* a long silence: the accepted jump grows with the cycles without data */
    for (unsigned i = 0; i < 5u; i++) {
        link_send(&l);
        CHECK_EQ_INT(link_rx(&l, NULL), E2E_P01_NONEWDATA);
    }
    CHECK_EQ_INT(link_step(&l), E2E_P01_SYNC); /* 6 > 3 cycles without new data */
}

static void test_check_every_single_bit_flip(void)
{
    struct link l;
    link_init(&l);
    link_step(&l);
    link_step(&l);
    link_send(&l);
    unsigned detected = 0;
    for (unsigned bit = 0; bit < 64u; bit++) {
        struct e2e_p01_check_state saved = l.rx;
        uint8_t f[8];
        memcpy(f, l.f, 8u);
        f[bit / 8u] ^= (uint8_t)(1u << (bit % 8u));
        if (link_rx(&l, f) == E2E_P01_WRONGCRC) {
            detected++;
        }
        /* a WRONGCRC frame changes nothing but the status and the cycle count */
        CHECK_EQ_INT(l.rx.last_valid_counter, saved.last_valid_counter);
        l.rx = saved;
    }
    CHECK_EQ_INT(detected, 64);
    CHECK_EQ_INT(link_rx(&l, l.f), E2E_P01_OK);
    /* every double bit flip too (the J1850 polynomial's Hamming distance is >= 3 here) */
    unsigned d2 = 0, n2 = 0;
    for (unsigned a = 0; a < 64u; a++) {
        for (unsigned b = a + 1u; b < 64u; b++) {
            struct e2e_p01_check_state saved = l.rx;
            uint8_t f[8];
            memcpy(f, l.f, 8u);
            f[a / 8u] ^= (uint8_t)(1u << (a % 8u));
            f[b / 8u] ^= (uint8_t)(1u << (b % 8u));
            n2++;
            if (link_rx(&l, f) == E2E_P01_WRONGCRC) {
                d2++;
            }
            l.rx = saved;
        }
    }
    CHECK_EQ_INT(d2, n2);
    /* a frame of the wrong length */
    CHECK_OK(e2e_p01_check(&cfg_ex, &l.rx, l.f, 7u, true));
    CHECK_EQ_INT(l.rx.status, E2E_P01_WRONGCRC);
}

static void test_check_masquerade(void)
{
    /* a frame correctly protected by a sender with another data ID is rejected. The CRC is
     * linear: another ID passes iff (id ^ other) * x^56 is a multiple of the polynomial, i.e.
     * for exactly 255 of the 65535 other IDs; every other one is WRONGCRC. */
    struct link l;
    link_init(&l);
    link_step(&l);
    link_step(&l);
    unsigned accepted = 0;
    for (unsigned id = 0; id < 65536u; id++) {
        if (id == cfg_ex.data_id) {
            continue;
        }
        struct e2e_p01_cfg other = cfg_ex;
        other.data_id = (uint16_t)id;
        struct e2e_p01_protect_state ps = {.counter = l.tx.counter};
        uint8_t f[8];
        memcpy(f, l.f, 8u);
        CHECK_OK(e2e_p01_protect(&other, &ps, f, 8u));
        struct e2e_p01_check_state saved = l.rx;
        if (link_rx(&l, f) != E2E_P01_WRONGCRC) {
            accepted++;
        }
        l.rx = saved;
    }
    CHECK_EQ_INT(accepted, 255);
    /* the IDs next to it (one or two bits away) are all rejected */
    for (unsigned b = 0; b < 16u; b++) {
        struct e2e_p01_cfg other = cfg_ex;
        other.data_id = (uint16_t)(cfg_ex.data_id ^ (1u << b));
        struct e2e_p01_protect_state ps = {.counter = l.tx.counter};
        uint8_t f[8];
        memcpy(f, l.f, 8u);
        CHECK_OK(e2e_p01_protect(&other, &ps, f, 8u));
        struct e2e_p01_check_state saved = l.rx;
        CHECK_EQ_INT(link_rx(&l, f), E2E_P01_WRONGCRC);
        l.rx = saved;
    }
}

static void test_check_bad_arguments_and_state(void)
{
    struct e2e_p01_check_state st;
    uint8_t f[8] = {0};
    CHECK_ERR(e2e_p01_check_init(NULL), INC_ERR_NULL);
    CHECK_OK(e2e_p01_check_init(&st));
    CHECK_ERR(e2e_p01_check(NULL, &st, f, 8u, true), INC_ERR_NULL);
    CHECK_ERR(e2e_p01_check(&cfg_ex, NULL, f, 8u, true), INC_ERR_NULL);
    CHECK_ERR(e2e_p01_check(&cfg_ex, &st, NULL, 8u, true), INC_ERR_NULL);
    CHECK_OK(e2e_p01_check(&cfg_ex, &st, NULL, 0u, false));
    CHECK_EQ_INT(st.status, E2E_P01_NONEWDATA);
    struct e2e_p01_cfg bad = cfg_ex;
    bad.len = 0u;
    CHECK_ERR(e2e_p01_check(&bad, &st, f, 8u, true), INC_ERR_INVAL);
    st.last_valid_counter = 15u; /* a corrupted state */
    CHECK_ERR(e2e_p01_check(&cfg_ex, &st, f, 8u, true), INC_ERR_STATE);
    CHECK_EQ_INT(st.status, E2E_P01_WRONGCRC);
    CHECK(st.wait_for_first_data);
    /* counter 15 with a matching CRC: never accepted */
    f[1] = 0x0Fu;
    f[0] = e2e_p01_crc(&cfg_ex, f);
    CHECK_OK(e2e_p01_check(&cfg_ex, &st, f, 8u, true));
    CHECK_EQ_INT(st.status, E2E_P01_WRONGCRC);
    CHECK(e2e_p01_status_name(E2E_P01_OKSOMELOST)[0] == 'O');
    CHECK(e2e_p01_status_name(0x77u)[0] == '?');
}

int main(int argc, char **argv)
{
    unit_args(argc, argv);
    UNIT_RUN(test_crc_published_values);
    UNIT_RUN(test_p01_crc_is_the_profile_formula);
    UNIT_RUN(test_protect_counter_and_layout);
    UNIT_RUN(test_check_in_sequence_and_wrap);
    UNIT_RUN(test_check_repetition);
    UNIT_RUN(test_check_loss);
    UNIT_RUN(test_check_delay);
    UNIT_RUN(test_check_every_single_bit_flip);
    UNIT_RUN(test_check_masquerade);
    UNIT_RUN(test_check_bad_arguments_and_state);
    return unit_report();
}
