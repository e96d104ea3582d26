/* The CAN frames of the application (inclino/can_frames.h). */
#include "inclino/can_frames.h"
#include "unit.h"

#include <string.h>

#define Q16(x) ((fx_q16_t)((x)*65536.0 + ((x) >= 0 ? 0.5 : -0.5)))

static void check_e2e_ok(const struct can_frame *f)
{
    const struct e2e_p01_cfg *c = can_e2e_cfg(f->id);
    REQUIRE(c != NULL);
    CHECK_EQ_HEX(f->data[0], e2e_p01_crc(c, f->data));
    CHECK(f->dlc == 8u);
}

static void test_data_ids_never_collide(void)
{
    /* two frames' data IDs masquerade iff their XOR is a multiple of x^8+x^4+x^3+x^2+1 */
    static const uint32_t ids[] = {CAN_ID_SLOPE, CAN_ID_ATTITUDE, CAN_ID_STATUS, CAN_ID_SPEED};
    for (size_t a = 0; a < 4; a++) {
        for (size_t b = 0; b < 4; b++) {
            if (a == b) {
                continue;
            }
            struct can_frame f;
            memset(&f, 0, sizeof f);
            f.id = ids[a];
            f.dlc = 8;
            f.data[2] = (uint8_t)(a * 37u + b);
            const struct e2e_p01_cfg *ca = can_e2e_cfg(ids[a]), *cb = can_e2e_cfg(ids[b]);
            /* for every counter and a sweep of payloads, the CRCs differ */
            for (unsigned k = 0; k < 15u * 64u; k++) {
                f.data[1] = (uint8_t)(k % 15u);
                f.data[3] = (uint8_t)(k / 15u);
                CHECK(e2e_p01_crc(ca, f.data) != e2e_p01_crc(cb, f.data));
            }
        }
    }
    CHECK(can_e2e_cfg(0x123u) == NULL);
}

static void test_slope_scaling_and_roundtrip(void)
{
    struct can_tx tx;
    CHECK_OK(can_tx_init(&tx));
    struct slope_result s;
    memset(&s, 0, sizeof s);
    s.valid = true;
    for (int i = -3000; i <= 3000; i += 7) {
        s.slope_deg = i * 655 + 13;  /* about -30 .. 30 deg */
        s.grade_pct = i * 3001 - 77; /* about -137 .. 137 % */
        s.bound_deg = (i + 3000) * 17 + 1;
        struct can_frame f;
        struct can_slope_sig sig, back;
        bool sat = true;
        CHECK_OK(can_pack_slope(&tx, &s, APP_MODE_PARKED, &f, &sig, &sat));
        CHECK(!sat);
        CHECK_EQ_HEX(f.id, CAN_ID_SLOPE);
        check_e2e_ok(&f);
        CHECK_OK(can_unpack_slope(&f, &back));
        CHECK(back.valid);
        CHECK_EQ_INT(back.mode, 0);
        CHECK_EQ_INT(back.slope, sig.slope);
        CHECK_EQ_INT(back.grade, sig.grade);
        CHECK_EQ_INT(back.bound, sig.bound);
        /* |value - raw / 100| <= 0.5 LSB; the bound is never below the computed one */
        double v = s.slope_deg / 65536.0, r = back.slope / 100.0;
        CHECK_NEAR(v, r, 0.005 + 1e-9);
        CHECK_NEAR(s.grade_pct / 65536.0, back.grade / 100.0, 0.005 + 1e-9);
        double b = s.bound_deg / 65536.0, rb = back.bound / 1000.0;
        CHECK(rb >= b);
        CHECK(rb - b < 0.001);
    }
    /* exact ties: 0.005 deg rounds away from zero */
    s.slope_deg = 65536 / 200 + 0; /* 327/65536 = 0.00499 deg: rounds to 0 */
    struct can_frame f;
    struct can_slope_sig sig;
    CHECK_OK(can_pack_slope(&tx, &s, 0, &f, &sig, NULL));
    CHECK_EQ_INT(sig.slope, 0);
    s.slope_deg = Q16(-1.0);
    CHECK_OK(can_pack_slope(&tx, &s, 0, &f, &sig, NULL));
    CHECK_EQ_INT(sig.slope, -100);
    /* beyond the field: saturated and never valid */
    s.grade_pct = Q16(400.0);
    bool sat = false;
    CHECK_OK(can_pack_slope(&tx, &s, 0, &f, &sig, &sat));
    CHECK(sat);
    CHECK_EQ_INT(sig.grade, INT16_MAX);
    CHECK(!sig.valid);
    CHECK_EQ_HEX(f.data[1] & CAN_B1_VALID, 0u);
    s.grade_pct = 0;
    s.bound_deg = Q16(70.0);
    CHECK_OK(can_pack_slope(&tx, &s, 0, &f, &sig, &sat));
    CHECK(sat && !sig.valid && sig.bound == UINT16_MAX);
    s.bound_deg = -1;
    CHECK_OK(can_pack_slope(&tx, &s, 0, &f, &sig, &sat));
    CHECK(sat && !sig.valid);
    /* an invalid estimate stays invalid */
    s.bound_deg = Q16(0.5);
    s.valid = false;
    CHECK_OK(can_pack_slope(&tx, &s, 0, &f, &sig, &sat));
    CHECK(!sat && !sig.valid);
}

static void test_output_frames(void)
{
    struct can_tx tx;
    CHECK_OK(can_tx_init(&tx));
    struct app_esc_output o;
    memset(&o, 0, sizeof o);
    o.mode = APP_MODE_DRIVING;
    o.valid = true;
    o.roll_deg = Q16(-3.256);
    o.pitch_deg = Q16(12.5);
    o.bound_deg = Q16(0.75);
    o.att_fault = 0x02u;
    struct can_frame fr[2];
    size_t n = 0;
    CHECK_OK(can_pack_output(&tx, &o, false, fr, &n));
    REQUIRE(n == 2u);
    CHECK_EQ_HEX(fr[0].id, CAN_ID_ATTITUDE);
    CHECK_EQ_HEX(fr[1].id, CAN_ID_STATUS);
    check_e2e_ok(&fr[0]);
    check_e2e_ok(&fr[1]);
    struct can_att_sig a;
    CHECK_OK(can_unpack_attitude(&fr[0], &a));
    CHECK(a.valid);
    CHECK_EQ_INT(a.mode, 1);
    CHECK_EQ_INT(a.roll, -326);
    CHECK_EQ_INT(a.pitch, 1250);
    CHECK_EQ_INT(a.bound, 750);
    struct can_status_sig st;
    CHECK_OK(can_unpack_status(&fr[1], &st));
    CHECK_EQ_INT(st.mode, 1);
    CHECK(!st.speed_ok);
    CHECK_EQ_HEX(st.fault, (0x02u << 16) | CAN_FAULT_SPEED_INPUT);
    /* parked: the EPB estimate and its flags */
    o.mode = APP_MODE_PARKED;
    o.epb.valid = false;
    o.epb.flags = APP_F_NOT_CALIBRATED;
    o.epb.slope.flags = SLOPE_F_NOT_CALIBRATED;
    o.epb.slope.slope_deg = Q16(4.0);
    o.epb.slope.bound_pct = Q16(1.234);
    CHECK_OK(can_pack_output(&tx, &o, true, fr, &n));
    CHECK_EQ_HEX(fr[0].id, CAN_ID_SLOPE);
    CHECK_OK(can_unpack_status(&fr[1], &st));
    CHECK_EQ_HEX(st.fault, APP_F_NOT_CALIBRATED | (SLOPE_F_NOT_CALIBRATED << 8));
    CHECK_EQ_INT(st.grade_bound, 124); /* ceil(123.4) */
    CHECK(st.speed_ok);
    /* counters advance per frame */
    CHECK_EQ_INT(fr[0].data[1] & 0x0Fu, 0);
    CHECK_EQ_INT(fr[1].data[1] & 0x0Fu, 1);
    o.mode = 7;
    CHECK_ERR(can_pack_output(&tx, &o, true, fr, &n), INC_ERR_INVAL);
    CHECK_ERR(can_unpack_slope(&fr[1], NULL), INC_ERR_INVAL);
    struct can_slope_sig ss;
    CHECK_ERR(can_unpack_slope(&fr[1], &ss), INC_ERR_INVAL);
    CHECK_ERR(can_unpack_slope(NULL, &ss), INC_ERR_NULL);
}

static void test_speed_receiver(void)
{
    struct e2e_p01_protect_state tx = {0};
    struct can_speed_rx rx;
    struct app_vehicle v;
    struct can_frame f;
    CHECK_ERR(can_speed_rx_init(&rx, 0u), INC_ERR_INVAL);
    CHECK_OK(can_speed_rx_init(&rx, 3u));
    /* the first frame is INITIAL: not yet used */
    CHECK_OK(can_pack_speed(&tx, true, Q16(13.89), true, Q16(-2.5), &f));
    CHECK_OK(can_speed_rx_cycle(&rx, &f, &v));
    CHECK_EQ_INT(rx.e2e.status, E2E_P01_INITIAL);
    CHECK(!v.valid);
    CHECK_OK(can_pack_speed(&tx, true, Q16(13.89), true, Q16(-2.5), &f));
    CHECK_OK(can_speed_rx_cycle(&rx, &f, &v));
    CHECK(v.valid);
    CHECK_EQ_INT(v.speed_mps, (1389 * 65536 + 50) / 100);
    CHECK_EQ_INT(v.yaw_rate_dps, -((250 * 65536 + 50) / 100));
    /* no frame: held for timeout_cycles, then invalid */
    for (unsigned i = 0; i < 3u; i++) {
        CHECK_OK(can_speed_rx_cycle(&rx, NULL, &v));
        CHECK(v.valid);
    }
    CHECK_OK(can_speed_rx_cycle(&rx, NULL, &v));
    CHECK(!v.valid);
    /* a corrupted frame is never used */
    CHECK_OK(can_speed_rx_init(&rx, 3u));
    for (unsigned i = 0; i < 3u; i++) {
        CHECK_OK(can_pack_speed(&tx, true, Q16(5.0), true, 0, &f));
        CHECK_OK(can_speed_rx_cycle(&rx, &f, &v));
    }
    CHECK(v.valid);
    CHECK_OK(can_pack_speed(&tx, true, Q16(50.0), true, 0, &f));
    f.data[3] ^= 0x40u;
    CHECK_OK(can_speed_rx_cycle(&rx, &f, &v));
    CHECK_EQ_INT(rx.e2e.status, E2E_P01_WRONGCRC);
    CHECK(v.valid); /* the last good value, within its timeout */
    CHECK_EQ_INT(v.speed_mps, Q16(5.0));
    /* SpeedValid clear, or beyond 200 m/s: not used */
    CHECK_OK(can_pack_speed(&tx, false, Q16(7.0), true, 0, &f));
    CHECK_OK(can_speed_rx_cycle(&rx, &f, &v));
    CHECK_EQ_INT(v.speed_mps, Q16(5.0));
    CHECK_OK(can_pack_speed(&tx, true, Q16(250.0), true, 0, &f));
    CHECK_OK(can_speed_rx_cycle(&rx, &f, &v));
    CHECK_EQ_INT(v.speed_mps, Q16(5.0));
    CHECK_EQ_INT(rx.rejected, 4); /* the INITIAL one, the corrupted one and these two */
    /* another data ID (the slope frame's identifier in the speed's place): rejected */
    struct can_tx otx;
    CHECK_OK(can_tx_init(&otx));
    struct slope_result s;
    memset(&s, 0, sizeof s);
    CHECK_OK(can_pack_slope(&otx, &s, 0, &f, NULL, NULL));
    f.id = CAN_ID_SPEED;
    CHECK_OK(can_speed_rx_cycle(&rx, &f, &v));
    CHECK_EQ_INT(rx.e2e.status, E2E_P01_WRONGCRC);
    CHECK_ERR(can_speed_rx_cycle(NULL, &f, &v), INC_ERR_NULL);
}

/* Deterministic bad input: every byte value at every position, every dlc and identifier the
 * receiver might see, through the speed receiver and the unpackers; the invariants hold. */
static void test_bad_input_sweep(void)
{
    struct can_speed_rx rx;
    CHECK_OK(can_speed_rx_init(&rx, 2u));
    uint32_t seed = 12345u;
    unsigned valid_out = 0;
    for (unsigned it = 0; it < UNIT_SIZE(200000u, 20000u); it++) {
        struct can_frame f;
        seed = seed * 1103515245u + 12345u;
        f.id = (seed >> 8) % 4u == 0u ? CAN_ID_SPEED : (seed >> 12) & 0x7FFu;
        f.dlc = (uint8_t)((seed >> 20) % 16u);
        for (unsigned i = 0; i < 8u; i++) {
            seed = seed * 1103515245u + 12345u;
            f.data[i] = (uint8_t)(seed >> 16);
        }
        struct app_vehicle v;
        int rc = can_speed_rx_cycle(&rx, (it % 5u) == 0u ? NULL : &f, &v);
        CHECK(rc == INC_OK);
        if (v.valid) {
            valid_out++;
            CHECK(v.speed_mps <= Q16(200.0) && v.speed_mps >= -Q16(200.0));
        }
        struct can_slope_sig s;
        rc = can_unpack_slope(&f, &s);
        CHECK(rc == INC_OK || rc == INC_ERR_INVAL);
        CHECK(rc != INC_OK || (f.id == CAN_ID_SLOPE && f.dlc == 8u));
    }
    /* random frames practically never pass (CRC 1/256, then the counter and both valid bits) */
    CHECK(rx.usable < 60u);
    (void)valid_out;
}

int main(int argc, char **argv)
{
    unit_args(argc, argv);
    UNIT_RUN(test_data_ids_never_collide);
    UNIT_RUN(test_slope_scaling_and_roundtrip);
    UNIT_RUN(test_output_frames);
    UNIT_RUN(test_speed_receiver);
    UNIT_RUN(test_bad_input_sweep);
    return unit_report();
}
