/*
 * lpspi_bench - simulated bus time of the sensor reads through each SPI engine.
 *
 * For the bit-banged engine and for LPSPI (engine + register model, 48 MHz functional clock) on
 * the standard board: an ADIS16405 burst read (adis_imu_read_sample) and an SCA3000-E05 sample
 * read (sca3000_read_sample), READS times after a warm-up. Per read: "call" = virtual time from
 * the call to its return (stalls, polling, software included), "cs" = first CS fall to last CS
 * rise inside the call. Prints a table and one summary line (docs/tool-summary.md).
 */
#include "inclino/adis_imu.h"
#include "inclino/sca3000.h"
#include "inclino/sim/bench.h"
#include "inclino/sim/s32k_lpspi_rig.h"
#include "inclino/tool_summary.h"

#include <stdio.h>
#include <string.h>

#define READS 16u

static struct sim_bench bench;
static struct sim_lpspi_rig rig;
static struct adis_imu imu;
static struct sca3000 sca;

static uint64_t first_fall, last_rise;
static bool fell;
static struct sim_pin_listener cs_listener;

static void on_cs(void *arg, unsigned pin, bool level, uint64_t t)
{
    (void)arg;
    (void)pin;
    if (!level && !fell) {
        first_fall = t;
        fell = true;
    }
    if (level) {
        last_rise = t;
    }
}

static int board(bool lpspi, const struct spi_bus **bus)
{
    int err = sim_bench_init(&bench);
    if (err == INC_OK && lpspi) {
        err = sim_lpspi_rig_init(&rig, &bench.board, 0);
    }
    *bus = lpspi ? &rig.engine.bus : &bench.board.spi.bus;
    cs_listener.fn = on_cs;
    cs_listener.arg = NULL;
    cs_listener.mask = SIM_PIN_MASK(SIM_BOARD_CS(0));
    if (err == INC_OK) {
        err = sim_pinbus_listen(&bench.board.bus, &cs_listener);
    }
    return err;
}

struct result {
    uint64_t call_ns, cs_ns; /* sums over READS */
    unsigned violations;
};

static int bench_adis(bool lpspi, struct result *r)
{
    struct sim_adis_imu_cfg mc;
    struct adis_imu_cfg c;
    struct adis_imu_sample s;
    const struct spi_bus *bus;
    unsigned i;
    int err = board(lpspi, &bus);
    if (err != INC_OK) {
        return err;
    }
    sim_bench_adis_imu_cfg(&bench.board, 0, SIM_ADIS16405, &mc);
    err = sim_bench_add_adis_imu(&bench, &mc);
    if (err != INC_OK) {
        return err;
    }
    hal_delay_ms(&bench.board.hal, ADIS_IMU_STARTUP_MS);
    memset(&c, 0, sizeof(c));
    c.hal = &bench.board.hal;
    c.bus = bus;
    c.cs = SIM_BOARD_CS(0);
    c.variant = ADIS_IMU_ADIS16405;
    c.dr_pin = SIM_BOARD_DR(0);
    c.dr_line = ADIS_IMU_DR_DIO1;
    err = adis_imu_init(&imu, &c);
    for (i = 0; err == INC_OK && i <= READS; i++) {
        uint64_t t0;
        err = adis_imu_wait_ready(&imu, 0, NULL);
        if (err != INC_OK) {
            break;
        }
        fell = false;
        t0 = bench.board.clk.now_ns;
        err = adis_imu_read_sample(&imu, &s);
        if (i > 0u) { /* the first read is the warm-up */
            r->call_ns += bench.board.clk.now_ns - t0;
            r->cs_ns += last_rise - first_fall;
        }
    }
    r->violations = bench.board.log.total;
    return err;
}

static int bench_sca(bool lpspi, struct result *r)
{
    struct sim_sca3000_cfg mc;
    struct sca3000_cfg c;
    struct sca3000_sample s;
    const struct spi_bus *bus;
    unsigned i;
    int err = board(lpspi, &bus);
    if (err != INC_OK) {
        return err;
    }
    sim_bench_sca3000_cfg(&bench.board, 0, SIM_SCA3000_E05, &mc);
    err = sim_bench_add_sca3000(&bench, &mc);
    if (err != INC_OK) {
        return err;
    }
    memset(&c, 0, sizeof(c));
    c.bus = bus;
    c.cs = SIM_BOARD_CS(0);
    c.spi_mode0 = false;
    c.variant = SCA3000_E05;
    c.hal = &bench.board.hal;
    c.int_pin = SIM_BOARD_DR(0);
    err = sca3000_init(&sca, &c);
    for (i = 0; err == INC_OK && i <= READS; i++) {
        uint64_t t0;
        hal_delay_ns(&bench.board.hal, 2000000u); /* a new sample */
        fell = false;
        t0 = bench.board.clk.now_ns;
        err = sca3000_read_sample(&sca, &s);
        if (i > 0u) {
            r->call_ns += bench.board.clk.now_ns - t0;
            r->cs_ns += last_rise - first_fall;
        }
    }
    r->violations = bench.board.log.total;
    return err;
}

int main(void)
{
    struct result ab = {0}, al = {0}, sb = {0}, sl = {0};
    int err;
    tool_summary_begin("lpspi_bench");
    err = bench_adis(false, &ab);
    if (err == INC_OK) {
        err = bench_adis(true, &al);
    }
    if (err == INC_OK) {
        err = bench_sca(false, &sb);
    }
    if (err == INC_OK) {
        err = bench_sca(true, &sl);
    }
    if (err != INC_OK) {
        return tool_summary_error(inc_err_name(err), 1);
    }
    printf("| read | engine | call ns | CS first fall -> last rise ns | violations |\n");
    printf("|---|---|---:|---:|---:|\n");
    printf("| ADIS16405 burst | bit-banged | %llu | %llu | %u |\n",
           (unsigned long long)(ab.call_ns / READS), (unsigned long long)(ab.cs_ns / READS),
           ab.violations);
    printf("| ADIS16405 burst | LPSPI | %llu | %llu | %u |\n",
           (unsigned long long)(al.call_ns / READS), (unsigned long long)(al.cs_ns / READS),
           al.violations);
    printf("| SCA3000 sample | bit-banged | %llu | %llu | %u |\n",
           (unsigned long long)(sb.call_ns / READS), (unsigned long long)(sb.cs_ns / READS),
           sb.violations);
    printf("| SCA3000 sample | LPSPI | %llu | %llu | %u |\n",
           (unsigned long long)(sl.call_ns / READS), (unsigned long long)(sl.cs_ns / READS),
           sl.violations);
    tool_summary_add("adis_burst_bitbang_ns", "%llu", (unsigned long long)(ab.call_ns / READS));
    tool_summary_add("adis_burst_lpspi_ns", "%llu", (unsigned long long)(al.call_ns / READS));
    tool_summary_add("sca_read_bitbang_ns", "%llu", (unsigned long long)(sb.call_ns / READS));
    tool_summary_add("sca_read_lpspi_ns", "%llu", (unsigned long long)(sl.call_ns / READS));
    tool_summary_add("violations", "%u",
                     ab.violations + al.violations + sb.violations + sl.violations);
    return tool_summary_end("ok", 0);
}
