/*
 * The navigation mode on its bus: an ADIS16255 (slot 0, data-ready DIO0 -> dr0) and an
 * SCA3000-E02 (slot 1) on the one bit-banged SPI bus of the simulated board, brought up and read
 * by app_nav_bus (each part with its own SPI mode and timing, each at its own rate, the 13 ms
 * cycle), with static inputs: a 10 deg/s turn and 0.1 g forward. Asserts:
 *   - no timing violation reported by either model (SCLK, setup, hold, stall, contention);
 *   - every gyro sample read (256 SPS), every accelerometer sample (125 Hz), every cycle;
 *   - the readings reach the dead reckoning (the heading turns at 10 deg/s once a fix is in);
 *   - the bus time per 13 ms cycle of each part, against the physical bound of the same reads
 *     (bits x SCLK period + CS setup + hold per CS period + the stalls between the periods of
 *     one read), printed for docs/benchmarks.md: within 1.25 x the bound.
 * Host only (the simulated board).
 */
#include "inclino/app_nav.h"
#include "inclino/sim/bench.h"
#include "unit.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static struct sim_board board;
static struct sim_adis16255 gyro_m;
static struct sim_sca3000 acc_m;
static struct app_nav an;
static struct app_nav_bus bus;

static void test_bus(void)
{
    struct sim_adis16255_cfg gc;
    struct sim_sca3000_cfg ac;
    struct sim_inertial_input in;
    struct app_nav_cfg cfg = app_nav_default_cfg(1000u);
    struct app_nav_bus_cfg bc;
    struct nav_out o;
    struct nav_fix_in f = {481000000, 115000000, 15000u, 9000u, true, true, 0u};
    uint64_t t0, t1;
    unsigned i, viol = 0;
    int cycles;
    double per_cycle_gyro, per_cycle_acc, bound_gyro, bound_acc, h0, h1;
    REQUIRE(sim_board_init(&board) == 0);
    sim_bench_adis16255_cfg(&board, 0, &gc);
    gc.dio1 = -1;
    REQUIRE(sim_adis16255_init(&gyro_m, &gc) == 0);
    sim_bench_sca3000_cfg(&board, 1, SIM_SCA3000_E02, &ac);
    REQUIRE(sim_sca3000_init(&acc_m, &ac) == 0);
    memset(&in, 0, sizeof in);
    in.rate_dps[2] = 10.0;
    in.accel_g[0] = 0.1;
    in.accel_g[2] = 1.0;
    in.temp_c = 25.0;
    in.supply_v = 5.0;
    sim_adis16255_set_input(&gyro_m, &in);
    sim_sca3000_set_input(&acc_m, &in);
    REQUIRE(app_nav_init(&an, &cfg) == INC_OK);
    bc.bus = &board.spi.bus;
    bc.hal = &board.hal;
    bc.gyro_cs = SIM_BOARD_CS(0);
    bc.gyro_dr = SIM_BOARD_DR(0);
    bc.acc_cs = SIM_BOARD_CS(1);
    bc.acc_variant = SCA3000_E02;
    bc.cycle_ns = 13000000u;
    REQUIRE(app_nav_bus_init(&bus, &an, &bc) == INC_OK);
    /* a fix so that the heading is known, then 2.6 s (200 cycles) */
    f.t_valid_ns = hal_now_ns(&board.hal);
    REQUIRE(nav_fix(&an.nav, &f) == 1);
    t0 = hal_now_ns(&board.hal);
    cycles = app_nav_bus_run(&bus, t0 + 13000000ull, &o);
    CHECK_EQ_INT(cycles, 1);
    h0 = o.heading_deg / 65536.0;
    bus.bus_ns_gyro = bus.bus_ns_acc = 0u;
    bus.reads_gyro = bus.reads_acc = 0u;
    t0 = hal_now_ns(&board.hal);
    cycles = app_nav_bus_run(&bus, t0 + 200ull * 13000000ull, &o);
    t1 = hal_now_ns(&board.hal);
    h1 = o.heading_deg / 65536.0;
    CHECK_EQ_INT(cycles, 200);
    for (i = 0; i < SIM_VIOL_KIND_COUNT; i++)
        viol += sim_violation_count(&board.log, (enum sim_violation_kind)i);
    if (viol != 0u) sim_violation_log_print(&board.log, stdout);
    CHECK_EQ_INT(viol, 0);
    CHECK_EQ_INT(bus.errors_gyro, 0);
    CHECK_EQ_INT(bus.errors_acc, 0);
    CHECK_EQ_INT(bus.missed_gyro, 0);
    /* 2.6 s: 256 SPS -> 665.6 samples, 125 Hz -> 325 */
    CHECK(bus.reads_gyro >= 664u && bus.reads_gyro <= 667u);
    CHECK(bus.reads_acc >= 324u && bus.reads_acc <= 326u);
    /* the turn reached the heading: 10 deg/s x 2.6 s (the offset is not learned: it turns) */
    CHECK_NEAR(h1 - h0, 26.0, 0.5);
    /* a fix through the UART on the HAL clock: parsed and aligned with the nav clock (the
     * reference point again, 39 m behind the track: judged against the history, refused as a
     * jump - not as a time outside the ring) */
    {
        static const char rmc[] =
            "$GPRMC,120000.00,A,4806.0000,N,01130.0000,E,29.158,090.00,010124,,,A*";
        char line[128];
        unsigned x = 0;
        size_t j;
        const uint32_t before = an.stats.fixes;
        for (j = 1; rmc[j] != '*'; j++)
            x ^= (unsigned char)rmc[j];
        snprintf(line, sizeof line, "%s%02X\r\n", rmc, x);
        CHECK(app_nav_bus_uart(&bus, line, strlen(line)) >= 0);
        CHECK_EQ_INT(an.stats.nmea_sentences, 1);
        CHECK_EQ_INT(an.stats.fixes, before);
        CHECK_EQ_INT(an.stats.fixes_refused, 1);
        CHECK_EQ_INT(an.nav.jumps, 1); /* the gate, not INC_ERR_RANGE */
    }
    (void)t1;
    /* bus time per cycle and the physical bound of the same reads:
     * ADIS16255 read_sample: 3 frames of 16 bits at 500 ns (2 MHz), setup + hold 500 + 500 ns
     * each, 2 stalls of 30 us between them (the third frame's stall is idle bus time after the
     * read, not part of it);
     * SCA3000 read_accel: one CS period of 7 bytes (command + X, Y, Z) at 2000 ns, setup + hold
     * 1000 + 1000 ns, then STATUS (2 bytes) after a 10 us stall. */
    bound_gyro = 3.0 * (16 * 500.0 + 500.0 + 500.0) + 2.0 * 30000.0;
    bound_acc = (56 * 2000.0 + 2000.0) + 10000.0 + (16 * 2000.0 + 2000.0);
    per_cycle_gyro = (double)bus.bus_ns_gyro / cycles;
    per_cycle_acc = (double)bus.bus_ns_acc / cycles;
    printf("| ADIS16255 | 256 SPS | %.1f | %.0f | %.0f | %.3f | %.0f |\n",
           (double)bus.reads_gyro / cycles, (double)bus.bus_ns_gyro / bus.reads_gyro, bound_gyro,
           (double)bus.bus_ns_gyro / bus.reads_gyro / bound_gyro, per_cycle_gyro);
    printf("| SCA3000-E02 | 125 Hz | %.2f | %.0f | %.0f | %.3f | %.0f |\n",
           (double)bus.reads_acc / cycles, (double)bus.bus_ns_acc / bus.reads_acc, bound_acc,
           (double)bus.bus_ns_acc / bus.reads_acc / bound_acc, per_cycle_acc);
    printf("| both | | | | | | %.0f ns per 13 ms cycle = %.2f %% of the bus |\n",
           per_cycle_gyro + per_cycle_acc, 100.0 * (per_cycle_gyro + per_cycle_acc) / 13e6);
    CHECK((double)bus.bus_ns_gyro / bus.reads_gyro >= bound_gyro * 0.95);
    CHECK((double)bus.bus_ns_gyro / bus.reads_gyro <= bound_gyro * 1.25);
    CHECK((double)bus.bus_ns_acc / bus.reads_acc >= bound_acc * 0.95);
    CHECK((double)bus.bus_ns_acc / bus.reads_acc <= bound_acc * 1.25);
    CHECK(per_cycle_gyro + per_cycle_acc < 0.1 * 13e6);
}

int main(void)
{
    UNIT_RUN(test_bus);
    return unit_report();
}
