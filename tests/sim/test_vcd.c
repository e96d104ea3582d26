/*
 * VCD content: the words in the waveform file are the words sent and received. The file is read
 * back by a small VCD parser and SPI decoder written here, independent of the writer (the
 * host-only test sim_vcd_sigrok checks the same with sigrok's own decoder).
 */
#include "inclino/sim/bench.h"
#include "inclino/sim/loopback.h"
#include "inclino/sim/vcd.h"
#include "inclino/spi.h"
#include "unit.h"

#include <stdio.h>
#include <string.h>

static struct sim_board board;
static struct sim_loopback part;
static struct sim_vcd vcd;

struct decoded {
    unsigned n;
    uint16_t mosi[32], miso[32];
    unsigned frames;  /* CS periods */
    unsigned partial; /* CS rose mid-word */
    unsigned vars;
    unsigned long long last_t;
    int time_backwards;
};

/* Decode SPI from a VCD: sample MOSI/MISO on the mode's sampling edge while cs0 is low. */
static int decode_vcd(const char *path, unsigned mode, unsigned bits, struct decoded *d)
{
    char line[256];
    char id_sclk = 0, id_mosi = 0, id_miso = 0, id_cs = 0;
    int sclk = -1, mosi = -1, miso = -1, cs = -1;
    unsigned nb = 0;
    uint16_t wi = 0, wo = 0;
    int in_defs = 1;
    const int cpol = (int)(mode >> 1), cpha = (int)(mode & 1u);
    FILE *f = fopen(path, "r");
    memset(d, 0, sizeof(*d));
    if (f == NULL) {
        return -1;
    }
    while (fgets(line, sizeof(line), f) != NULL) {
        char id;
        if (in_defs) {
            char name[32];
            if (sscanf(line, "$var wire 1 %c %31s $end", &id, name) == 2) {
                d->vars++;
                if (strcmp(name, "sclk") == 0) id_sclk = id;
                if (strcmp(name, "mosi") == 0) id_mosi = id;
                if (strcmp(name, "miso") == 0) id_miso = id;
                if (strcmp(name, "cs0") == 0) id_cs = id;
            }
            if (strncmp(line, "$enddefinitions", 15) == 0) in_defs = 0;
            continue;
        }
        if (line[0] == '#') {
            unsigned long long t = 0;
            if (sscanf(line + 1, "%llu", &t) != 1) {
                fclose(f);
                return -1;
            }
            if (t < d->last_t) d->time_backwards = 1;
            d->last_t = t;
            continue;
        }
        if ((line[0] != '0' && line[0] != '1') || line[1] == '\0') {
            continue; /* $dumpvars / $end */
        }
        id = line[1];
        {
            const int v = line[0] - '0';
            if (id == id_cs) {
                if (v == 0 && cs == 1) {
                    d->frames++;
                    nb = 0;
                    wi = wo = 0;
                } else if (v == 1 && cs == 0 && nb != 0) {
                    d->partial++;
                }
                cs = v;
            } else if (id == id_mosi) {
                mosi = v;
            } else if (id == id_miso) {
                miso = v;
            } else if (id == id_sclk) {
                const int leading = v != cpol;
                const int sampling = cpha ? !leading : leading;
                if (cs == 0 && sampling && sclk != -1 && v != sclk) {
                    wi = (uint16_t)((wi << 1) | (mosi == 1));
                    wo = (uint16_t)((wo << 1) | (miso == 1));
                    if (++nb == bits) {
                        if (d->n < 32u) {
                            d->mosi[d->n] = wi;
                            d->miso[d->n] = wo;
                        }
                        d->n++;
                        nb = 0;
                        wi = wo = 0;
                    }
                }
                sclk = v;
            }
        }
    }
    fclose(f);
    return (id_sclk && id_mosi && id_miso && id_cs) ? 0 : -1;
}

static void run_case(unsigned mode, unsigned bits, enum spi_cs_policy cs)
{
    static const uint16_t w16[] = {0x3E00, 0x5600, 0x8001, 0xFFFF, 0x0000, 0x1234};
    static const uint16_t w8[] = {0x3E, 0x56, 0x81, 0xFF, 0x00, 0x12};
    const uint16_t *tx = bits == 16u ? w16 : w8;
    const char *path = "test_vcd_out.vcd";
    struct sim_loopback_cfg lc;
    struct spi_dev dev;
    struct spi_dev_cfg dc;
    struct decoded d;
    uint16_t rx[6];
    unsigned i;

    REQUIRE(sim_board_init(&board) == 0);
    sim_bench_loopback_cfg(&board, 0, &lc);
    lc.mode = (uint8_t)mode;
    lc.bits = (uint8_t)bits;
    lc.timing.min_period_ns = 500;
    lc.timing.miso_delay_ns = 60;
    lc.first = (uint16_t)(bits == 16u ? 0xA5C3u : 0xA5u);
    REQUIRE(sim_loopback_init(&part, &lc) == 0);
    dc.cs = SIM_BOARD_CS(0);
    dc.mode = (uint8_t)mode;
    dc.bits = (uint8_t)bits;
    dc.timing.sclk_period_ns = 500;
    dc.timing.cs_setup_ns = 100;
    dc.timing.cs_hold_ns = 100;
    dc.timing.stall_ns = 9000;
    dc.timing.gap_ns = 0;
    REQUIRE(spi_dev_init(&dev, &board.spi.bus, &dc) == 0);

    REQUIRE(sim_vcd_open(&vcd, path, &board.bus, SIM_BOARD_SPI_MASK) == 0);
    hal_delay_ns(&board.hal, 1000);
    CHECK_OK(spi_transfer(&dev, tx, rx, 6, cs));
    CHECK_OK(sim_vcd_close(&vcd));
    CHECK(vcd.changes > 6u * bits);

    REQUIRE(decode_vcd(path, mode, bits, &d) == 0);
    CHECK_EQ_INT(d.vars, 7); /* sclk mosi miso cs0..cs3 */
    CHECK_EQ_INT(d.n, 6);
    CHECK_EQ_INT(d.frames, cs == SPI_CS_TOGGLE ? 6 : 1);
    CHECK_EQ_INT(d.partial, 0);
    CHECK(!d.time_backwards);
    CHECK_EQ_INT(d.last_t, board.clk.now_ns + 1000u);
    for (i = 0; i < 6u; i++) {
        CHECK_EQ_HEX(d.mosi[i], tx[i]);
        CHECK_EQ_HEX(d.miso[i], rx[i]);
    }
    CHECK_EQ_HEX(d.miso[0], lc.first);
    remove(path);
}

static void test_vcd_words_every_mode(void)
{
    unsigned mode;
    for (mode = 0; mode < 4u; mode++) {
        run_case(mode, 16, SPI_CS_TOGGLE);
        run_case(mode, 8, SPI_CS_HOLD);
    }
}

static void test_vcd_errors(void)
{
    REQUIRE(sim_board_init(&board) == 0);
    CHECK_ERR(sim_vcd_open(NULL, "x.vcd", &board.bus, 1), INC_ERR_NULL);
    CHECK_ERR(sim_vcd_open(&vcd, NULL, &board.bus, 1), INC_ERR_NULL);
    CHECK_ERR(sim_vcd_open(&vcd, "x.vcd", &board.bus, SIM_PIN_MASK(31)), INC_ERR_INVAL);
    CHECK_ERR(sim_vcd_open(&vcd, "no/such/dir/x.vcd", &board.bus, 1), INC_ERR_IO);
    CHECK_ERR(sim_vcd_close(NULL), INC_ERR_NULL);
}

int main(void)
{
    UNIT_RUN(test_vcd_words_every_mode);
    UNIT_RUN(test_vcd_errors);
    return unit_report();
}
