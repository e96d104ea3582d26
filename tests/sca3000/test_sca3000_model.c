/*
 * The SCA3000 model on its own, driven by raw SPI frames (no driver): command byte, decrementing
 * reads with the X_LSB -> Z_MSB wrap, modes 0 and 3 sensed at CS fall, writes only as
 * [cmd][data], the STATUS frame-error bit (set by a corrupt frame, cleared by reading STATUS),
 * the three-frame unlock, indirect registers, reserved-register lock-up, the ring buffer FIFO
 * port with BUF_COUNT and INT_STATUS, the INT line, output data rates per variant and mode, and
 * the timing limits enforced through the slave framework.
 */
#include "fixture.h"

#include <string.h>

static struct spi_dev raw;

static int raw_setup(uint8_t mode, uint32_t period, uint32_t stall)
{
    struct spi_dev_cfg dc;
    dc.cs = FX_CS;
    dc.mode = mode;
    dc.bits = 8;
    dc.timing.sclk_period_ns = period;
    dc.timing.cs_setup_ns = 1000;
    dc.timing.cs_hold_ns = 1000;
    dc.timing.stall_ns = stall;
    dc.timing.gap_ns = 0;
    return spi_dev_init(&raw, &fx.board.spi.bus, &dc);
}

static int setup(enum sim_sca3000_variant v, uint8_t mode)
{
    int err = fx_setup_part(v, 0);
    return err != 0 ? err : raw_setup(mode, 2000, 10000);
}

/* Read n bytes from addr in one CS period. */
static void rd(uint8_t addr, uint8_t *out, size_t n)
{
    uint16_t tx[16] = {0}, rx[16];
    size_t i;
    tx[0] = (uint16_t)(addr << 2);
    CHECK_OK(spi_transfer(&raw, tx, rx, n + 1u, SPI_CS_HOLD));
    CHECK_EQ_HEX(rx[0], 0x00); /* the part shifts 0x00 during the command byte */
    for (i = 0; i < n; i++) {
        out[i] = (uint8_t)rx[i + 1u];
    }
}

static uint8_t rd1(uint8_t addr)
{
    uint8_t v = 0xEE;
    rd(addr, &v, 1);
    return v;
}

static void wr(uint8_t addr, uint8_t v)
{
    const uint16_t tx[2] = {(uint16_t)((addr << 2) | 2u), v};
    CHECK_OK(spi_transfer(&raw, tx, NULL, 2, SPI_CS_HOLD));
}

static void test_decrementing_reads_both_modes(void)
{
    static const uint8_t from_x[6] = {0x14, 0xD8, 0x29, 0xA8, 0xF5, 0x98}; /* X, Z, Y */
    static const uint8_t from_y[6] = {0xF5, 0x98, 0x14, 0xD8, 0x29, 0xA8}; /* Y, X, Z */
    static const uint8_t from_z[8] = {0x29, 0xA8, 0xF5, 0x98, 0x14, 0xD8, 0x29, 0xA8};
    uint8_t mode;
    for (mode = 0; mode <= 3u; mode = (uint8_t)(mode + 3u)) {
        uint8_t b[8];
        REQUIRE(setup(SIM_SCA3000_D01, mode) == 0);
        /* D01, 0.75 mg/LSB: 0.5 g -> 667 (0x14D8 = 667 << 3), -0.25 g -> -333 (0xF598),
         * 1 g -> 1333 (0x29A8). */
        fx_input(0.5, -0.25, 1.0, 25.0);
        fx_wait_ns(4000000);
        CHECK_EQ_HEX(rd1(0x00), SIM_SCA3000_REVID_DEFAULT);
        rd(0x05, b, 6);
        CHECK(memcmp(b, from_x, 6) == 0);
        rd(0x07, b, 6);
        CHECK(memcmp(b, from_y, 6) == 0);
        rd(0x09, b, 8);
        CHECK(memcmp(b, from_z, 8) == 0);
        /* Temperature 25 degC: 25 * 1.8 + 214.6 = 259.6 -> 260 in bits[13:5] = 0x2080. */
        rd(0x13, b, 2);
        CHECK_EQ_HEX(b[0], 0x20);
        CHECK_EQ_HEX(b[1], 0x80);
        CHECK_EQ_HEX(rd1(0x14), SIM_SCA3000_MODE_DEFAULT);
        CHECK_EQ_HEX(rd1(0x02), 0x00);
        CHECK_EQ_INT(fx.part.corrupt_frames, 0);
        CHECK_NO_VIOLATIONS();
    }
}

static void test_writes_and_frame_error(void)
{
    const uint16_t three[3] = {(0x14 << 2) | 2u, 0x09, 0x00};
    const uint16_t bad_cmd[2] = {(0x14 << 2) | 1u, 0x00};
    REQUIRE(setup(SIM_SCA3000_E04, 3) == 0);
    /* A write that is not exactly [cmd][data] is a corrupt frame and is not applied. */
    CHECK_OK(spi_transfer(&raw, three, NULL, 3, SPI_CS_HOLD));
    CHECK_EQ_HEX(fx.part.mode, SIM_SCA3000_MODE_DEFAULT);
    CHECK_EQ_HEX(rd1(0x02), 0x01); /* frame error reported ... */
    CHECK_EQ_HEX(rd1(0x02), 0x00); /* ... and cleared by the read */
    /* A command byte with bit0 set is corrupt too. */
    CHECK_OK(spi_transfer(&raw, bad_cmd, NULL, 2, SPI_CS_HOLD));
    CHECK_EQ_HEX(rd1(0x02), 0x01);
    CHECK_EQ_INT(sim_violation_count(&fx.board.log, SIM_VIOL_PROTOCOL), 2);
    /* A good write is applied at CS rise. */
    wr(0x14, 0x09);
    CHECK_EQ_HEX(rd1(0x14), 0x09);
    CHECK_EQ_HEX(rd1(0x02), 0x00);
    /* A write to a read-only register is ignored and logged, without lock-up. */
    wr(0x00, 0x12);
    CHECK_EQ_HEX(rd1(0x00), SIM_SCA3000_REVID_DEFAULT);
    CHECK_EQ_INT(sim_violation_count(&fx.board.log, SIM_VIOL_PROTOCOL), 3);
    CHECK(!fx.part.locked_up);
    /* Option 2 exists on the E04 (wide, 400 Hz) ... */
    wr(0x14, 0x0A);
    CHECK_EQ_INT(sim_sca3000_odr_mhz(&fx.part), 400000);
    /* ... not on the E02: refused. */
    REQUIRE(setup(SIM_SCA3000_E02, 3) == 0);
    wr(0x14, 0x0A);
    CHECK_EQ_HEX(rd1(0x14), SIM_SCA3000_MODE_DEFAULT);
    CHECK_EQ_INT(sim_violation_count(&fx.board.log, SIM_VIOL_PROTOCOL), 1);
}

static void test_unlock_and_indirect(void)
{
    const uint16_t one_frame[6] = {(0x1E << 2) | 2u, 0x00, (0x1E << 2) | 2u, 0x50,
                                   (0x1E << 2) | 2u, 0xA0};
    REQUIRE(setup(SIM_SCA3000_D01, 3) == 0);
    CHECK_EQ_HEX(rd1(0x02) & 0x20, 0x00); /* locked after power-up */
    /* Locked: CTRL_SEL/CTRL_DATA do nothing. */
    wr(0x18, 0x0B);
    CHECK_EQ_HEX(rd1(0x22), 0x00);
    /* The sequence in one CS period does not unlock (and is a corrupt frame). */
    CHECK_OK(spi_transfer(&raw, one_frame, NULL, 6, SPI_CS_HOLD));
    CHECK_EQ_HEX(rd1(0x02), 0x01);
    /* Another frame between the writes restarts the sequence. */
    wr(0x1E, 0x00);
    wr(0x1E, 0x50);
    (void)rd1(0x00);
    wr(0x1E, 0xA0);
    CHECK_EQ_HEX(rd1(0x02), 0x00);
    /* Three consecutive CS periods unlock. */
    wr(0x1E, 0x00);
    wr(0x1E, 0x50);
    wr(0x1E, 0xA0);
    CHECK_EQ_HEX(rd1(0x02), 0x20);
    wr(0x18, 0x0B);
    CHECK_EQ_HEX(rd1(0x22), SIM_SCA3000_OUT_CTRL_DEFAULT);
    wr(0x18, 0x02);
    CHECK_EQ_HEX(rd1(0x22), SIM_SCA3000_MD_CTRL_DEFAULT);
    wr(0x22, 0x45); /* protected bits kept: accepted */
    CHECK_EQ_HEX(fx.part.ind[2], 0x45);
    wr(0x18, 0x01); /* I2C_DISABLE exists on the D01 */
    wr(0x22, 0x01);
    CHECK_EQ_HEX(rd1(0x22), 0x01);
    /* Any UNLOCK write relocks. */
    wr(0x1E, 0x00);
    CHECK_EQ_HEX(rd1(0x02), 0x00);
    CHECK(!fx.part.locked_up);
    CHECK_EQ_INT(sim_violation_count(&fx.board.log, SIM_VIOL_PROTOCOL), 1); /* the 6-byte frame */
}

static void test_lock_up(void)
{
    REQUIRE(setup(SIM_SCA3000_E05, 0) == 0);
    wr(0x01, 0x00); /* reserved address */
    CHECK(fx.part.locked_up);
    CHECK_EQ_HEX(rd1(0x00), 0x00); /* answers nothing any more */
    CHECK_EQ_INT(sim_violation_count(&fx.board.log, SIM_VIOL_PROTOCOL), 1);
    sim_sca3000_power_cycle(&fx.part);
    CHECK_EQ_HEX(rd1(0x00), SIM_SCA3000_REVID_DEFAULT);
    wr(0x14, 0x00); /* clears MODE bit3 (reserved) */
    CHECK(fx.part.locked_up);
    sim_sca3000_power_cycle(&fx.part);
    wr(0x21, 0x00); /* clears INT_MASK protected bits */
    CHECK(fx.part.locked_up);
    sim_sca3000_power_cycle(&fx.part);
    wr(0x1E, 0x00);
    wr(0x1E, 0x50);
    wr(0x1E, 0xA0);
    wr(0x18, 0x0B);
    wr(0x22, 0x1C); /* OUT_CTRL without bits 7..5 */
    CHECK(fx.part.locked_up);
    CHECK_EQ_INT(sim_violation_count(&fx.board.log, SIM_VIOL_PROTOCOL), 4);
}

static void test_timing_limits(void)
{
    uint8_t id;
    REQUIRE(setup(SIM_SCA3000_D01, 3) == 0);
    /* 1 MHz is faster than the part's 500 kHz: edges are missed, the byte misaligns, the
     * violation is logged and the part flags the frame. */
    REQUIRE(raw_setup(3, 1000, 10000) == 0);
    id = rd1(0x00);
    CHECK(id != SIM_SCA3000_REVID_DEFAULT);
    CHECK(sim_violation_count(&fx.board.log, SIM_VIOL_SCLK_FAST) > 0u);
    CHECK(fx.part.frame_error);
    REQUIRE(raw_setup(3, 2000, 10000) == 0);
    CHECK_EQ_HEX(rd1(0x02), 0x01);
    /* CS high for 2 us instead of 10 us between two periods. */
    sim_violation_log_init(&fx.board.log);
    REQUIRE(raw_setup(3, 2000, 2000) == 0);
    (void)rd1(0x00);
    (void)rd1(0x00);
    CHECK(sim_violation_count(&fx.board.log, SIM_VIOL_STALL) > 0u);
    REQUIRE(raw_setup(3, 2000, 10000) == 0);
    CHECK_EQ_HEX(rd1(0x02), 0x01);
}

static void test_ring_fifo_and_int(void)
{
    uint8_t b[4];
    unsigned i;
    REQUIRE(setup(SIM_SCA3000_D01, 3) == 0);
    fx_input(0.5, -0.25, 1.0, 25.0);
    fx_wait_ns(4000000);
    CHECK(sim_pinbus_read(&fx.board.bus, FX_INT)); /* active low, inactive = high */
    wr(0x21, SIM_SCA3000_INT_MASK_DEFAULT | 0x40); /* ring 1/2 full drives INT */
    wr(0x14, SIM_SCA3000_MODE_DEFAULT | 0x80);     /* ring on */
    CHECK_EQ_HEX(rd1(0x15), 0);
    fx_wait_ns(40000000); /* 10 samples at 250 Hz */
    CHECK_EQ_INT(rd1(0x15), 30);
    /* FIFO port: two values, X then Y: floor(667/4) = 166 -> 0x14C0, floor(-333/4) = -84 ->
     * 0xF580. The address does not move on. */
    rd(0x0F, b, 4);
    CHECK_EQ_HEX(b[0], 0x14);
    CHECK_EQ_HEX(b[1], 0xC0);
    CHECK_EQ_HEX(b[2], 0xF5);
    CHECK_EQ_HEX(b[3], 0x80);
    CHECK_EQ_INT(rd1(0x15), 28);
    /* Half a value read (MSB only): nothing leaves the ring. */
    rd(0x0F, b, 1);
    CHECK_EQ_INT(rd1(0x15), 28);
    rd(0x0F, b, 2); /* Z: floor(1333/4) = 333 -> 0x29A0 */
    CHECK_EQ_HEX(b[0], 0x29);
    CHECK_EQ_HEX(b[1], 0xA0);
    CHECK_EQ_INT(rd1(0x15), 27);
    CHECK(sim_pinbus_read(&fx.board.bus, FX_INT));
    for (i = 0; i < 30u && rd1(0x15) < 96u; i++) {
        fx_wait_ns(4000000);
    }
    CHECK_EQ_INT(rd1(0x15), 96);
    CHECK(!sim_pinbus_read(&fx.board.bus, FX_INT)); /* INT active */
    CHECK_EQ_HEX(rd1(0x16), 0x40);                  /* acknowledges */
    CHECK(sim_pinbus_read(&fx.board.bus, FX_INT));
    CHECK_EQ_HEX(rd1(0x16), 0x00);
    /* Full: the oldest values are overwritten, BUF_COUNT stays at 192. */
    fx_wait_ns(400000000);
    CHECK_EQ_INT(rd1(0x15), 192);
    CHECK(fx.part.ring_overwritten > 0u);
    CHECK_EQ_HEX(rd1(0x16), 0xC0);
    CHECK_NO_VIOLATIONS();
}

static void test_output_data_rates(void)
{
    /* mHz per variant and MODE[1:0] (docs/sensor-facts.md §1.6). */
    static const uint32_t want[4][3] = {
        {250000, 250000, 0}, {125000, 62500, 0}, {100000, 50000, 400000}, {200000, 50000, 400000}};
    unsigned v, m;
    for (v = 0; v < 4u; v++) {
        for (m = 0; m < 3u; m++) {
            uint64_t before;
            if (want[v][m] == 0u) {
                continue;
            }
            REQUIRE(setup((enum sim_sca3000_variant)v, 3) == 0);
            wr(0x14, (uint8_t)(SIM_SCA3000_MODE_DEFAULT | m));
            CHECK_EQ_INT(sim_sca3000_odr_mhz(&fx.part), want[v][m]);
            before = fx.part.samples;
            fx_wait_ns(2000000000ull); /* 2 s */
            CHECK_EQ_INT(fx.part.samples - before, want[v][m] / 500u);
            CHECK_NO_VIOLATIONS();
        }
    }
    /* Motion detection: no acceleration output. */
    REQUIRE(setup(SIM_SCA3000_E04, 3) == 0);
    fx_input(0.5, 0.5, 0.5, 25.0);
    fx_wait_ns(20000000);
    CHECK(fx.part.x != 0u);
    wr(0x14, SIM_SCA3000_MODE_DEFAULT | 3u);
    fx_wait_ns(20000000);
    CHECK_EQ_HEX(fx.part.x, 0);
    CHECK_EQ_INT(sim_sca3000_odr_mhz(&fx.part), 0);
}

int main(void)
{
    UNIT_RUN(test_decrementing_reads_both_modes);
    UNIT_RUN(test_writes_and_frame_error);
    UNIT_RUN(test_unlock_and_indirect);
    UNIT_RUN(test_lock_up);
    UNIT_RUN(test_timing_limits);
    UNIT_RUN(test_ring_fifo_and_int);
    UNIT_RUN(test_output_data_rates);
    return unit_report();
}
