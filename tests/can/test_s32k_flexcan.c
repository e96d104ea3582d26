/* The S32K1 FlexCAN driver (_sim build) against the register model. */
#include "inclino/s32k_flexcan.h"
#include "inclino/s32k_mmio.h"
#include "inclino/sim/s32k_bus.h"
#include "inclino/sim/s32k_flexcan_model.h"
#include "unit.h"

#include <stdio.h>
#include <string.h>

static struct s32k_flexcan_model model;
static struct s32k_flexcan dev;
static char logbuf[4096];
static FILE *logf_;

static void setup(void)
{
    s32k_bus_reset();
    memset(logbuf, 0, sizeof logbuf);
    logf_ = fmemopen(logbuf, sizeof logbuf, "w");
    REQUIRE(logf_ != NULL);
    setvbuf(logf_, NULL, _IONBF, 0);
    REQUIRE(s32k_flexcan_model_init(&model, S32K_CAN0_BASE, 32u, logf_, "can0") == INC_OK);
    struct s32k_flexcan_cfg cfg;
    s32k_flexcan_cfg_default(&cfg, 0x1A0u);
    CHECK_OK(s32k_flexcan_init(&dev, &cfg));
}

static void teardown(void)
{
    fclose(logf_);
    logf_ = NULL;
}

static void test_init_sequence(void)
{
    setup();
    /* running, not frozen, configured as documented, no refused write, no stray access */
    CHECK_EQ_HEX(model.mcr & (S32K_FLEXCAN_MCR_MDIS | S32K_FLEXCAN_MCR_FRZACK |
                              S32K_FLEXCAN_MCR_NOTRDY | S32K_FLEXCAN_MCR_HALT),
                 0u);
    CHECK_EQ_HEX(model.mcr & S32K_FLEXCAN_MCR_MAXMB_MASK, 31u);
    CHECK(model.mcr & S32K_FLEXCAN_MCR_SRXDIS);
    CHECK_EQ_HEX(model.ctrl1, 0x00690006u); /* PRESDIV 0, RJW 1, PSEG1 5, PSEG2 1, PROPSEG 6 */
    CHECK_EQ_HEX(model.ctrl1 & S32K_FLEXCAN_CTRL1_CLKSRC, 0u);
    /* 1 + (PROPSEG+1) + (PSEG1+1) + (PSEG2+1) = 16 tq of 125 ns: 500 kbit/s, sample at 14/16 */
    unsigned tq = 1u + 7u + 6u + 2u;
    CHECK_EQ_INT(tq, S32K_FLEXCAN_TQ_PER_BIT);
    CHECK_EQ_INT(S32K_FLEXCAN_CLK_HZ / (1u * tq), S32K_FLEXCAN_BITRATE);
    CHECK_EQ_INT(model.stats.config_violations, 0);
    CHECK_EQ_INT(s32k_bus_stats()->unmapped_reads + s32k_bus_stats()->unmapped_writes, 0);
    CHECK_EQ_HEX(model.ram[8 * 4 + 1], 0x1A0u << 18);
    CHECK_EQ_HEX(model.ram[8 * 4] >> 24, S32K_FLEXCAN_CODE_RX_EMPTY);
    CHECK_OK(s32k_flexcan_error_state(&dev));
    /* bad configurations */
    struct s32k_flexcan_cfg cfg;
    s32k_flexcan_cfg_default(&cfg, 0x1A0u);
    cfg.rx_mb = 10u; /* inside the Tx buffers */
    CHECK_ERR(s32k_flexcan_init(&dev, &cfg), INC_ERR_INVAL);
    s32k_flexcan_cfg_default(&cfg, 0x800u);
    CHECK_ERR(s32k_flexcan_init(&dev, &cfg), INC_ERR_INVAL);
    s32k_flexcan_cfg_default(&cfg, 0x1A0u);
    cfg.clk_hz = 40000000u;
    CHECK_ERR(s32k_flexcan_init(&dev, &cfg), INC_ERR_UNSUPPORTED);
    CHECK_ERR(s32k_flexcan_send(&dev, 0x310u, NULL, 0u), INC_ERR_STATE);
    teardown();
}

static void test_send_writes_candump(void)
{
    setup();
    const uint8_t d[8] = {0x00, 0x11, 0x22, 0x33, 0x44, 0x55, 0x66, 0x77};
    s32k_flexcan_model_set_time_ns(&model, 1234567000ull);
    CHECK_OK(s32k_flexcan_send(&dev, 0x123u, d, 8u));
    CHECK_OK(s32k_flexcan_send(&dev, 0x7FFu, d, 2u));
    CHECK_OK(s32k_flexcan_send(&dev, 0x001u, NULL, 0u));
    /* 108 bits = 216 us; 3 bits (6 us) of interframe space; then 60 bits, 44 bits */
    const char *want = "(0000000001.234783) can0 123#0011223344556677\n"
                       "(0000000001.234909) can0 7FF#0011\n"
                       "(0000000001.235003) can0 001#\n";
    CHECK(strcmp(logbuf, want) == 0);
    if (strcmp(logbuf, want) != 0) {
        printf("log:\n%s", logbuf);
    }
    CHECK_EQ_INT(model.stats.tx_frames, 3);
    CHECK_ERR(s32k_flexcan_send(&dev, 0x800u, d, 8u), INC_ERR_INVAL);
    CHECK_ERR(s32k_flexcan_send(&dev, 0x100u, d, 9u), INC_ERR_INVAL);
    CHECK_ERR(s32k_flexcan_send(&dev, 0x100u, NULL, 1u), INC_ERR_NULL);
    teardown();
}

static void test_receive_filter_and_overrun(void)
{
    setup();
    uint16_t id;
    uint8_t d[8], dlc;
    bool ovr = true;
    CHECK_ERR(s32k_flexcan_receive(&dev, &id, d, &dlc, &ovr), INC_ERR_STALE);
    const uint8_t a[8] = {1, 2, 3, 4, 5, 6, 7, 8};
    CHECK_ERR(s32k_flexcan_model_inject(&model, 0x1A1u, a, 8u), INC_ERR_BUSY); /* filtered */
    CHECK_OK(s32k_flexcan_model_inject(&model, 0x1A0u, a, 8u));
    CHECK_OK(s32k_flexcan_receive(&dev, &id, d, &dlc, &ovr));
    CHECK_EQ_HEX(id, 0x1A0u);
    CHECK_EQ_INT(dlc, 8);
    CHECK(memcmp(d, a, 8u) == 0);
    CHECK(!ovr);
    CHECK_ERR(s32k_flexcan_receive(&dev, &id, d, &dlc, &ovr), INC_ERR_STALE);
    /* two frames before a read: the second overwrites the first */
    const uint8_t b[3] = {9, 9, 9};
    CHECK_OK(s32k_flexcan_model_inject(&model, 0x1A0u, a, 8u));
    CHECK_OK(s32k_flexcan_model_inject(&model, 0x1A0u, b, 3u));
    CHECK_OK(s32k_flexcan_receive(&dev, &id, d, &dlc, &ovr));
    CHECK(ovr);
    CHECK_EQ_INT(dlc, 3);
    CHECK_EQ_INT(d[0], 9);
    CHECK_EQ_INT(d[3], 0);
    CHECK_EQ_INT(dev.overruns, 1);
    CHECK_EQ_INT(model.stats.rx_dropped, 1);
    teardown();
}

static void test_bus_errors(void)
{
    setup();
    const uint8_t d[8] = {0};
    /* no acknowledge: ACKERR, the buffers stay pending until all are busy, error passive */
    s32k_flexcan_model_set_no_ack(&model, true);
    for (unsigned i = 0; i < 4u; i++) {
        CHECK_OK(s32k_flexcan_send(&dev, 0x310u, d, 8u));
    }
    CHECK_ERR(s32k_flexcan_send(&dev, 0x310u, d, 8u), INC_ERR_BUSY);
    CHECK(dev.last_esr1 & S32K_FLEXCAN_ESR1_ACKERR); /* kept from the reads in send */
    CHECK_ERR(s32k_flexcan_error_state(&dev), INC_ERR_TIMEOUT);
    for (unsigned i = 0; i < 20u; i++) {
        s32k_flexcan_model_set_time_ns(&model, 1000000ull * (i + 1u));
    }
    CHECK_ERR(s32k_flexcan_error_state(&dev), INC_ERR_DEVICE); /* TEC >= 128 */
    CHECK_EQ_INT(model.stats.tx_frames, 0);
    CHECK(strlen(logbuf) == 0u);
    /* acknowledged again: the pending frames leave */
    s32k_flexcan_model_set_no_ack(&model, false);
    s32k_flexcan_model_set_time_ns(&model, 100000000ull);
    CHECK_EQ_INT(model.stats.tx_frames, 4);
    CHECK_OK(s32k_flexcan_send(&dev, 0x310u, d, 8u));
    /* bus off: refused, nothing sent or received */
    s32k_flexcan_model_set_bus_off(&model, true);
    CHECK_ERR(s32k_flexcan_send(&dev, 0x310u, d, 8u), INC_ERR_BUS);
    CHECK_ERR(s32k_flexcan_error_state(&dev), INC_ERR_BUS);
    uint16_t id;
    uint8_t r[8], dlc;
    CHECK_ERR(s32k_flexcan_model_inject(&model, 0x1A0u, d, 8u), INC_ERR_BUS);
    CHECK_ERR(s32k_flexcan_receive(&dev, &id, r, &dlc, NULL), INC_ERR_BUS);
    s32k_flexcan_model_set_bus_off(&model, false);
    CHECK_OK(s32k_flexcan_error_state(&dev));
    CHECK_OK(s32k_flexcan_send(&dev, 0x310u, d, 8u));
    CHECK_EQ_INT(model.stats.tx_frames, 6);
    teardown();
}

static void test_config_refused_while_running(void)
{
    setup();
    /* the model refuses what the hardware refuses: the driver never does it */
    uint32_t before = model.ctrl1;
    s32k_mmio_write32(S32K_CAN0_BASE + S32K_FLEXCAN_CTRL1, 0u);
    CHECK_EQ_HEX(model.ctrl1, before);
    CHECK_EQ_INT(model.stats.config_violations, 1);
    teardown();
}

int main(int argc, char **argv)
{
    unit_args(argc, argv);
    UNIT_RUN(test_init_sequence);
    UNIT_RUN(test_send_writes_candump);
    UNIT_RUN(test_receive_filter_and_overrun);
    UNIT_RUN(test_bus_errors);
    UNIT_RUN(test_config_refused_while_running);
    return unit_report();
}
