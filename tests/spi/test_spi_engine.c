/*
 * The bit-banged SPI engine against the loopback part on the simulated board: every mode and
 * frame size, CS held and toggled, exact bus timing, argument errors.
 */
#include "inclino/sim/board.h"
#include "inclino/sim/loopback.h"
#include "inclino/spi.h"
#include "unit.h"

#include <string.h>

static struct sim_board board;
static struct sim_loopback part;
static struct spi_dev dev;

/* Limits of the test part: 2 MHz, 100 ns setup/hold, 1 us stall, 40 ns output delay. */
static const struct sim_spi_timing part_timing = {
    .min_period_ns = 500,
    .min_half_ns = 200,
    .min_cs_setup_ns = 100,
    .min_cs_hold_ns = 100,
    .min_stall_ns = 1000,
    .mosi_setup_ns = 20,
    .miso_delay_ns = 40,
};

static const struct spi_timing master_timing = {
    .sclk_period_ns = 500,
    .cs_setup_ns = 100,
    .cs_hold_ns = 100,
    .stall_ns = 1000,
    .gap_ns = 0,
};

/* CS edges, recorded by a pin listener, to measure bus time. */
static uint64_t cs_fall[64], cs_rise[64];
static unsigned n_fall, n_rise;
static struct sim_pin_listener cs_listener;

static void on_cs(void *arg, unsigned pin, bool level, uint64_t t)
{
    (void)arg;
    (void)pin;
    if (!level && n_fall < 64u) cs_fall[n_fall++] = t;
    if (level && n_rise < 64u) cs_rise[n_rise++] = t;
}

static int setup(uint8_t part_mode, uint8_t master_mode, uint8_t bits, uint16_t first)
{
    struct sim_loopback_cfg lc;
    struct spi_dev_cfg dc;
    int err = sim_board_init(&board);
    if (err) return err;
    memset(&lc, 0, sizeof(lc));
    lc.bus = &board.bus;
    lc.cs = SIM_BOARD_CS(0);
    lc.sclk = SIM_BOARD_SCLK;
    lc.mosi = SIM_BOARD_MOSI;
    lc.miso = SIM_BOARD_MISO;
    lc.mode = part_mode;
    lc.bits = bits;
    lc.timing = part_timing;
    lc.first = first;
    lc.log = &board.log;
    err = sim_loopback_init(&part, &lc);
    if (err) return err;
    dc.cs = SIM_BOARD_CS(0);
    dc.mode = master_mode;
    dc.bits = bits;
    dc.timing = master_timing;
    err = spi_dev_init(&dev, &board.spi.bus, &dc);
    if (err) return err;
    n_fall = n_rise = 0;
    cs_listener.fn = on_cs;
    cs_listener.arg = NULL;
    cs_listener.mask = SIM_PIN_MASK(SIM_BOARD_CS(0));
    return sim_pinbus_listen(&board.bus, &cs_listener);
}

/* Words that exercise every bit position and both levels at the ends. */
static const uint16_t words16[] = {0xA5C3, 0x0001, 0x8000, 0xFFFF, 0x0000, 0x3E00, 0x7FFE, 0x1234};
static const uint16_t words8[] = {0xA5, 0x01, 0x80, 0xFF, 0x00, 0x3E, 0x7E, 0x12};
#define NWORDS 8u

static void check_loopback(uint8_t mode, uint8_t bits, enum spi_cs_policy cs)
{
    const uint16_t *w = bits == 16u ? words16 : words8;
    const uint16_t first = bits == 16u ? 0x5AA5u : 0x5Au;
    uint16_t rx[NWORDS];
    unsigned i;
    REQUIRE(setup(mode, mode, bits, first) == 0);
    CHECK_OK(spi_transfer(&dev, w, rx, NWORDS, cs));
    /* The part answers each word with the previous one. */
    CHECK_EQ_HEX(rx[0], first);
    for (i = 1; i < NWORDS; i++) {
        CHECK_EQ_HEX(rx[i], w[i - 1]);
    }
    CHECK_EQ_INT(part.received, NWORDS);
    for (i = 0; i < NWORDS; i++) {
        CHECK_EQ_HEX(part.rx_log[i], w[i]);
    }
    CHECK_EQ_INT(board.log.total, 0);
    CHECK_EQ_INT(n_fall, cs == SPI_CS_TOGGLE ? NWORDS : 1u);
    CHECK_EQ_INT(n_rise, n_fall);
    CHECK_EQ_INT(part.frames_ended, n_fall);
}

static void test_all_modes_and_sizes_cs_toggle(void)
{
    uint8_t mode;
    for (mode = 0; mode < 4u; mode++) {
        check_loopback(mode, 16, SPI_CS_TOGGLE);
        check_loopback(mode, 8, SPI_CS_TOGGLE);
    }
}

static void test_all_modes_and_sizes_cs_held(void)
{
    uint8_t mode;
    for (mode = 0; mode < 4u; mode++) {
        check_loopback(mode, 16, SPI_CS_HOLD);
        check_loopback(mode, 8, SPI_CS_HOLD);
        CHECK_EQ_INT(part.last_frame_words, NWORDS);
    }
}

/* A part that senses mode 0 or 3 from SCLK at CS fall works with a mode 0 and a mode 3 master. */
static void test_auto_mode_part(void)
{
    uint16_t rx[2];
    const uint16_t tx[2] = {0xBEEF, 0x0F0F};
    REQUIRE(setup(SIM_SPI_MODE_AUTO_0_3, SPI_MODE_0, 16, 0x1111) == 0);
    CHECK_OK(spi_transfer(&dev, tx, rx, 2, SPI_CS_TOGGLE));
    CHECK_EQ_HEX(rx[0], 0x1111);
    CHECK_EQ_HEX(rx[1], 0xBEEF);
    dev.cfg.mode = SPI_MODE_3;
    CHECK_OK(spi_transfer(&dev, tx, rx, 2, SPI_CS_TOGGLE));
    CHECK_EQ_HEX(rx[0], 0x0F0F);
    CHECK_EQ_HEX(rx[1], 0xBEEF);
    CHECK_EQ_INT(board.log.total, 0);
}

/* Bus time: exact to the ns, and within 1.05 x of bits*P + setup + hold + stall. */
static void test_bus_time(void)
{
    const uint64_t P = master_timing.sclk_period_ns, S = master_timing.cs_setup_ns;
    const uint64_t H = master_timing.cs_hold_ns, T = master_timing.stall_ns;
    const uint64_t h2 = P - P / 2u;
    uint16_t tx[NWORDS];
    unsigned i;
    REQUIRE(setup(SPI_MODE_3, SPI_MODE_3, 16, 0) == 0);
    memcpy(tx, words16, sizeof(tx));
    CHECK_OK(spi_transfer(&dev, tx, NULL, NWORDS, SPI_CS_TOGGLE));
    REQUIRE(n_fall == NWORDS && n_rise == NWORDS);
    for (i = 0; i < NWORDS; i++) {
        /* CS low: setup + 16 periods - the half before the first leading edge + hold. */
        CHECK_EQ_INT(cs_rise[i] - cs_fall[i], S + 16u * P - h2 + H);
        if (i > 0) {
            uint64_t frame = cs_fall[i] - cs_fall[i - 1];
            uint64_t ideal = 16u * P + S + H + T;
            CHECK_EQ_INT(cs_fall[i] - cs_rise[i - 1], T);
            CHECK(frame * 100u <= ideal * 105u);
            CHECK(frame <= ideal);
        }
    }
    /* The stall is also kept between separate transfers. */
    CHECK_OK(spi_xfer1(&dev, 0x1234, NULL));
    CHECK_EQ_INT(cs_fall[NWORDS] - cs_rise[NWORDS - 1], T);
    /* A device initialised again on the same CS still gets the stall. */
    {
        struct spi_dev again;
        REQUIRE(spi_dev_init(&again, &board.spi.bus, &dev.cfg) == 0);
        CHECK_OK(spi_xfer1(&again, 0x4321, NULL));
        CHECK_EQ_INT(cs_fall[NWORDS + 1] - cs_rise[NWORDS], T);
        dev = again;
    }
    /* Held CS: frames follow each other after max(gap, half period). */
    n_fall = n_rise = 0;
    board.clk.now_ns += 100000u;
    CHECK_OK(spi_transfer(&dev, tx, NULL, 4, SPI_CS_HOLD));
    REQUIRE(n_fall == 1 && n_rise == 1);
    CHECK_EQ_INT(cs_rise[0] - cs_fall[0], S + 4u * 16u * P - h2 + H);
    CHECK_EQ_INT(board.log.total, 0);
}

/* An odd period splits into P/2 after the leading edge and the rest before it. */
static void test_odd_period(void)
{
    struct spi_timing t = master_timing;
    uint16_t rx[3];
    const uint16_t tx[3] = {0x8001, 0x4002, 0x2004};
    REQUIRE(setup(SPI_MODE_3, SPI_MODE_3, 16, 0x0F0F) == 0);
    t.sclk_period_ns = 1001;
    CHECK_OK(spi_dev_set_timing(&dev, &t));
    CHECK_OK(spi_transfer(&dev, tx, rx, 3, SPI_CS_HOLD));
    CHECK_EQ_HEX(rx[0], 0x0F0F);
    CHECK_EQ_HEX(rx[1], 0x8001);
    CHECK_EQ_HEX(rx[2], 0x4002);
    CHECK_EQ_INT(cs_rise[0] - cs_fall[0], 100u + 48u * 1001u - 501u + 100u);
}

/* A port's fast path as struct spi_bitbang_fast documents it, written on the HAL (a real port
 * inlines its pins; the S32K1 boards' s32k_board_bb_frame): counts its frames. */
static unsigned fast_frames;

static void fast_wait(uint32_t ns)
{
    if (ns != 0u) {
        hal_delay_ns(&board.hal, ns);
    }
}

static uint16_t fast_frame(void *ctx, const struct spi_bitbang_frame *fr, bool *mosi_out)
{
    bool mosi = fr->mosi_level;
    uint16_t in = 0;
    unsigned b = fr->bits;
    (void)ctx;
    fast_frames++;
    while (b-- > 0u) {
        const bool out = ((fr->word >> b) & 1u) != 0u;
        const uint32_t before = b == fr->bits - 1u ? fr->lead_ns : fr->h2_ns;
        if (!fr->cpha) {
            if (out != mosi) {
                hal_pin_write(&board.hal, SIM_BOARD_MOSI, out);
                mosi = out;
            }
            fast_wait(before);
            in = (uint16_t)((in << 1) | (hal_pin_read(&board.hal, SIM_BOARD_MISO) ? 1u : 0u));
            hal_pin_write(&board.hal, SIM_BOARD_SCLK, !fr->idle);
            fast_wait(fr->h1_ns);
            hal_pin_write(&board.hal, SIM_BOARD_SCLK, fr->idle);
        } else {
            fast_wait(before);
            hal_pin_write(&board.hal, SIM_BOARD_SCLK, !fr->idle);
            if (out != mosi) {
                hal_pin_write(&board.hal, SIM_BOARD_MOSI, out);
                mosi = out;
            }
            fast_wait(fr->h1_ns);
            in = (uint16_t)((in << 1) | (hal_pin_read(&board.hal, SIM_BOARD_MISO) ? 1u : 0u));
            hal_pin_write(&board.hal, SIM_BOARD_SCLK, fr->idle);
        }
    }
    *mosi_out = mosi;
    return in;
}

/* The engine of spi_bitbang_init_fast (no per-bit loop of its own): every mode and size, CS
 * held and toggled, through the fast path, with the loopback's answers and no timing
 * violation; set_fast(NULL) cannot take its fast path away; its argument errors. */
static void test_init_fast(void)
{
    static const struct spi_bitbang_fast fast = {fast_frame, NULL};
    static const struct spi_bitbang_fast no_frame = {NULL, NULL};
    struct spi_bitbang_cfg bc;
    struct spi_dev_cfg dc;
    uint8_t mode;
    unsigned p;
    for (mode = 0; mode < 4u; mode++) {
        for (p = 0; p < 4u; p++) {
            const uint8_t bits = p < 2u ? 16u : 8u;
            const enum spi_cs_policy cs = (p & 1u) != 0u ? SPI_CS_HOLD : SPI_CS_TOGGLE;
            REQUIRE(setup(mode, mode, bits, bits == 16u ? 0x5AA5u : 0x5Au) == 0);
            bc = board.spi.cfg;
            dc = dev.cfg;
            REQUIRE(spi_bitbang_init_fast(&board.spi, &bc, &fast) == INC_OK);
            spi_bitbang_set_fast(&board.spi, NULL); /* ignored: no per-bit path */
            REQUIRE(spi_dev_init(&dev, &board.spi.bus, &dc) == INC_OK);
            n_fall = n_rise = 0;
            fast_frames = 0;
            {
                const uint16_t *w = bits == 16u ? words16 : words8;
                uint16_t rx[NWORDS];
                unsigned i;
                CHECK_OK(spi_transfer(&dev, w, rx, NWORDS, cs));
                CHECK_EQ_INT(fast_frames, NWORDS);
                CHECK_EQ_HEX(rx[0], bits == 16u ? 0x5AA5u : 0x5Au);
                for (i = 1; i < NWORDS; i++) {
                    CHECK_EQ_HEX(rx[i], w[i - 1]);
                }
                CHECK_EQ_INT(board.log.total, 0);
                CHECK_EQ_INT(n_fall, cs == SPI_CS_TOGGLE ? NWORDS : 1u);
            }
        }
    }
    bc = board.spi.cfg;
    CHECK_ERR(spi_bitbang_init_fast(&board.spi, &bc, NULL), INC_ERR_NULL);
    CHECK_ERR(spi_bitbang_init_fast(&board.spi, &bc, &no_frame), INC_ERR_NULL);
    CHECK_ERR(spi_bitbang_init_fast(NULL, &bc, &fast), INC_ERR_NULL);
    CHECK_ERR(spi_bitbang_init_fast(&board.spi, NULL, &fast), INC_ERR_NULL);
    bc.miso = bc.mosi;
    CHECK_ERR(spi_bitbang_init_fast(&board.spi, &bc, &fast), INC_ERR_INVAL);
}

static void test_tx_null_sends_zeros(void)
{
    uint16_t rx[2];
    REQUIRE(setup(SPI_MODE_0, SPI_MODE_0, 16, 0xCAFE) == 0);
    CHECK_OK(spi_transfer(&dev, NULL, rx, 2, SPI_CS_HOLD));
    CHECK_EQ_HEX(rx[0], 0xCAFE);
    CHECK_EQ_HEX(rx[1], 0x0000);
    CHECK_EQ_HEX(part.rx_log[0], 0);
}

static void test_errors(void)
{
    struct spi_dev d2;
    struct spi_dev_cfg dc;
    struct spi_bitbang bb;
    struct spi_bitbang_cfg bc;
    struct spi_timing t = master_timing;
    uint16_t w = 0x100;
    REQUIRE(setup(SPI_MODE_0, SPI_MODE_0, 8, 0) == 0);

    /* Transfers */
    CHECK_ERR(spi_transfer(NULL, &w, NULL, 1, SPI_CS_HOLD), INC_ERR_NULL);
    CHECK_ERR(spi_transfer(&dev, &w, NULL, 0, SPI_CS_HOLD), INC_ERR_INVAL);
    CHECK_ERR(spi_transfer(&dev, &w, NULL, SPI_MAX_FRAMES + 1u, SPI_CS_HOLD), INC_ERR_INVAL);
    CHECK_ERR(spi_transfer(&dev, &w, NULL, 1, (enum spi_cs_policy)7), INC_ERR_INVAL);
    CHECK_ERR(spi_transfer(&dev, &w, NULL, 1, SPI_CS_HOLD), INC_ERR_INVAL); /* 9 bits in 8 */
    CHECK_EQ_INT(part.received, 0); /* nothing reached the bus */
    CHECK_EQ_INT(n_fall, 0);

    /* Device configuration */
    dc.cs = SIM_BOARD_CS(1);
    dc.mode = SPI_MODE_3;
    dc.bits = 16;
    dc.timing = master_timing;
    CHECK_ERR(spi_dev_init(NULL, &board.spi.bus, &dc), INC_ERR_NULL);
    CHECK_ERR(spi_dev_init(&d2, NULL, &dc), INC_ERR_NULL);
    CHECK_ERR(spi_dev_init(&d2, &board.spi.bus, NULL), INC_ERR_NULL);
    dc.bits = 12;
    CHECK_ERR(spi_dev_init(&d2, &board.spi.bus, &dc), INC_ERR_INVAL);
    CHECK_ERR(spi_transfer(&d2, &w, NULL, 1, SPI_CS_HOLD), INC_ERR_STATE); /* failed init */
    dc.bits = 16;
    dc.mode = 4;
    CHECK_ERR(spi_dev_init(&d2, &board.spi.bus, &dc), INC_ERR_INVAL);
    dc.mode = SPI_MODE_3;
    dc.cs = HAL_PIN_NONE;
    CHECK_ERR(spi_dev_init(&d2, &board.spi.bus, &dc), INC_ERR_INVAL);
    dc.cs = SIM_BOARD_SCLK; /* CS on the clock pin */
    CHECK_ERR(spi_dev_init(&d2, &board.spi.bus, &dc), INC_ERR_INVAL);
    dc.cs = SIM_BOARD_CS(1);
    dc.timing.sclk_period_ns = 1;
    CHECK_ERR(spi_dev_init(&d2, &board.spi.bus, &dc), INC_ERR_INVAL);
    t.sclk_period_ns = 0;
    CHECK_ERR(spi_dev_set_timing(&dev, &t), INC_ERR_INVAL);
    CHECK_ERR(spi_dev_set_timing(&dev, NULL), INC_ERR_NULL);
    CHECK_ERR(spi_dev_set_timing(NULL, &master_timing), INC_ERR_NULL);
    CHECK_EQ_INT(dev.cfg.timing.sclk_period_ns, master_timing.sclk_period_ns); /* unchanged */

    /* Engine configuration */
    bc.hal = &board.hal;
    bc.sclk = SIM_BOARD_SCLK;
    bc.mosi = SIM_BOARD_MOSI;
    bc.miso = SIM_BOARD_MOSI;
    CHECK_ERR(spi_bitbang_init(&bb, &bc), INC_ERR_INVAL);
    bc.miso = HAL_PIN_NONE;
    CHECK_ERR(spi_bitbang_init(&bb, &bc), INC_ERR_INVAL);
    bc.miso = SIM_BOARD_MISO;
    bc.hal = NULL;
    CHECK_ERR(spi_bitbang_init(&bb, &bc), INC_ERR_NULL);
    CHECK_ERR(spi_bitbang_init(&bb, NULL), INC_ERR_NULL);
    CHECK_ERR(spi_bitbang_init(NULL, &bc), INC_ERR_NULL);

    CHECK_EQ_INT(spi_period_for_hz(2000000), 500);
    CHECK_EQ_INT(spi_period_for_hz(300000), 3334);
    CHECK_EQ_INT(spi_period_for_hz(0), 0);
}

int main(void)
{
    UNIT_RUN(test_all_modes_and_sizes_cs_toggle);
    UNIT_RUN(test_all_modes_and_sizes_cs_held);
    UNIT_RUN(test_auto_mode_part);
    UNIT_RUN(test_bus_time);
    UNIT_RUN(test_odd_period);
    UNIT_RUN(test_tx_null_sends_zeros);
    UNIT_RUN(test_errors);
    UNIT_RUN(test_init_fast);
    return unit_report();
}
