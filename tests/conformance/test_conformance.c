/*
 * Conformance of every driver/model pair (docs/sim.md, "The conformance suite").
 *
 * Each pair is the driver's public API (drivers/<part>/include) on the standard board with its
 * model behind the part interface (sim/bench.h, sim/part.h):
 *   adis16255  ADIS16255 driver + ADIS16255 model
 *   adis_imu   ADIS1636x/1640x driver + model (ADIS16405; the sweep also ADIS16364)
 *   sca3000    SCA3000 driver + model (E05; the sweep also D01 and E04)
 *
 * 1. Sweeps: every output channel is driven across its range through the part's physical
 *    input; each value the driver returns is compared with the exact conversion of the register
 *    counts it read, an integer rational computed here from the datasheet scale, within the
 *    bound the driver states (0.5 LSB of Q16.16: |got x den - num| x 2 <= den, exactly).
 * 2. One fault matrix: every fault of sim/part.h on every pair, with the error the driver's
 *    header promises for it. A fault of the bus or the identity is injected before init and
 *    init's result is the observation; every other fault is injected after a clean init and the
 *    observation is "wait for new data, read one sample". A result other than the expected one
 *    fails, unless the cell records it as a known deviation (a driver bug or a limit of the
 *    part, listed in docs/sim.md): then it is printed as such, and the cell fails once the
 *    driver is fixed, so that the table is kept true. Every error result must also leave no
 *    plausible value behind (the error convention, base/error/include/inclino/error.h).
 */
#include "inclino/adis16255.h"
#include "inclino/adis_imu.h"
#include "inclino/sca3000.h"
#include "adis16255_regs.h"
#include "adis_imu_regs.h"
#include "inclino/sim/bench.h"
#include "sca3000_regs.h"
#include "unit.h"

#include <stdio.h>
#include <string.h>

#ifdef CONFORMANCE_LPSPI
#include "inclino/sim/s32k_lpspi_rig.h"
#endif

static struct sim_bench bench;

/* The SPI engine under test: the board's bit-banged engine, or (test conformance_lpspi) the
 * S32K1 LPSPI engine through its register model on the same pins. Same drivers, same models,
 * same expectations. */
#ifdef CONFORMANCE_LPSPI
static struct sim_lpspi_rig rig;
#define ENGINE_NAME "lpspi"
#else
#define ENGINE_NAME "bitbang"
#endif

static int bench_init(void)
{
    int err = sim_bench_init(&bench);
#ifdef CONFORMANCE_LPSPI
    if (err == INC_OK) {
        err = sim_lpspi_rig_init(&rig, &bench.board, 0);
    }
#endif
    return err;
}

static const struct spi_bus *conf_bus(void)
{
#ifdef CONFORMANCE_LPSPI
    return &rig.engine.bus;
#else
    return &bench.board.spi.bus;
#endif
}
static struct adis16255 g16;
static struct adis16255_cfg g16c;
static struct adis_imu imu;
static struct adis_imu_cfg imuc;
static struct sca3000 sca;
static struct sca3000_cfg scac;

/* ------------------------------------------------------------------ exact comparison */

struct sweep_stat {
    const char *what;
    unsigned checked, bad;
    int32_t lo, hi; /* register counts seen */
};

static void stat_init(struct sweep_stat *st, const char *what)
{
    memset(st, 0, sizeof(*st));
    st->what = what;
    st->lo = INT32_MAX;
    st->hi = INT32_MIN;
}

/* got (Q16.16) against the exact value num / den (x 65536 already in num): within 0.5 LSB. */
static void check_rat(struct sweep_stat *st, int32_t counts, int32_t got, int64_t num, int64_t den)
{
    int64_t d = (int64_t)got * den - num;
    if (d < 0) {
        d = -d;
    }
    st->checked++;
    if (counts < st->lo) {
        st->lo = counts;
    }
    if (counts > st->hi) {
        st->hi = counts;
    }
    if (2 * d > den) {
        if (st->bad < 5u) {
            printf("  %s: counts %ld -> %ld, exact %.6f (x 2^-16)\n", st->what, (long)counts,
                   (long)got, (double)num / (double)den);
        }
        st->bad++;
    }
}

/* Every value within its bound, and the counts seen span [lo, hi]. */
static void stat_done(const struct sweep_stat *st, int32_t lo, int32_t hi)
{
    printf("  %-22s %5u values, counts %6ld .. %6ld, %u outside 0.5 LSB\n", st->what, st->checked,
           (long)st->lo, (long)st->hi, st->bad);
    CHECK_EQ_INT(st->bad, 0);
    CHECK(st->checked > 0u);
    CHECK(st->lo <= lo);
    CHECK(st->hi >= hi);
}

/* i-th of n evenly spread points of [lo, hi] (both ends included). */
static int32_t point(unsigned i, unsigned n, int32_t lo, int32_t hi)
{
    return (int32_t)(lo + ((int64_t)hi - lo) * (int64_t)i / (int64_t)(n - 1u));
}

static void no_violations(void)
{
    if (bench.board.log.total != 0u) {
        sim_violation_log_print(&bench.board.log, stdout);
    }
    CHECK_EQ_INT(bench.board.log.total, 0);
}

/* ------------------------------------------------------------------ the pairs */

static void a16_cfg(void)
{
    memset(&g16c, 0, sizeof(g16c));
    g16c.bus = conf_bus();
    g16c.hal = &bench.board.hal;
    g16c.cs = SIM_BOARD_CS(0);
    g16c.dr_pin = SIM_BOARD_DR(0);
    g16c.smpl_prd = 0x01;
    g16c.range = ADIS16255_RANGE_320;
    g16c.filter_m = 2;
    g16c.dr_enable = true;
    g16c.dr_active_high = true;
    g16c.dr_line = 0;
}

static int a16_setup(void)
{
    struct sim_adis16255_cfg mc;
    struct sim_inertial_input in;
    int err = bench_init();
    if (err != INC_OK) {
        return err;
    }
    sim_bench_adis16255_cfg(&bench.board, 0, &mc);
    err = sim_bench_add_adis16255(&bench, &mc);
    sim_inertial_at_rest(&in);
    in.rate_dps[2] = 10.0;
    in.temp_c = 30.0;
    sim_part_set_input(&bench.part, &in);
    a16_cfg();
    return err;
}

static int a16_init(void)
{
    return adis16255_init(&g16, &g16c);
}

static int a16_read(bool *value_with_error)
{
    struct adis16255_sample s;
    int err;
    memset(&s, 0x5A, sizeof(s));
    err = adis16255_wait_sample(&g16, 0, &s);
    *value_with_error = err != INC_OK && (s.valid || s.rate_dps_q16 != 0 || s.temp_c_q16 != 0);
    return err;
}

static void imu_cfg(enum sim_adis_imu_variant v)
{
    memset(&imuc, 0, sizeof(imuc));
    imuc.hal = &bench.board.hal;
    imuc.bus = conf_bus();
    imuc.cs = SIM_BOARD_CS(0);
    imuc.variant = (uint8_t)v; /* same order in both enums */
    imuc.dr_pin = SIM_BOARD_DR(0);
    imuc.dr_line = ADIS_IMU_DR_DIO1;
}

static int imu_setup_variant(enum sim_adis_imu_variant v)
{
    struct sim_adis_imu_cfg mc;
    int err = bench_init();
    if (err != INC_OK) {
        return err;
    }
    sim_bench_adis_imu_cfg(&bench.board, 0, v, &mc);
    err = sim_bench_add_adis_imu(&bench, &mc);
    /* The driver does not wait for power-on: its caller does (adis_imu.h). */
    hal_delay_ms(&bench.board.hal, ADIS_IMU_STARTUP_MS);
    imu_cfg(v);
    return err;
}

static int imu_setup(void)
{
    return imu_setup_variant(SIM_ADIS16405);
}

static int imu_init(void)
{
    return adis_imu_init(&imu, &imuc);
}

static int imu_read(bool *value_with_error)
{
    struct adis_imu_sample s;
    int err = adis_imu_wait_ready(&imu, 0, NULL);
    memset(&s, 0, sizeof(s));
    if (err == INC_OK) {
        err = adis_imu_read_sample(&imu, &s);
    }
    *value_with_error = err != INC_OK && s.valid != 0u;
    return err;
}

static enum sca3000_variant sca_variant(enum sim_sca3000_variant v)
{
    switch (v) {
    case SIM_SCA3000_D01: return SCA3000_D01;
    case SIM_SCA3000_E02: return SCA3000_E02;
    case SIM_SCA3000_E04: return SCA3000_E04;
    default: return SCA3000_E05;
    }
}

static int sca_setup_variant(enum sim_sca3000_variant v)
{
    struct sim_sca3000_cfg mc;
    int err = bench_init();
    if (err != INC_OK) {
        return err;
    }
    sim_bench_sca3000_cfg(&bench.board, 0, v, &mc);
    err = sim_bench_add_sca3000(&bench, &mc);
    memset(&scac, 0, sizeof(scac));
    scac.bus = conf_bus();
    scac.cs = SIM_BOARD_CS(0);
    scac.spi_mode0 = false; /* mode 3; the driver builds its own 8-bit frames and timing */
    scac.variant = sca_variant(v);
    scac.hal = &bench.board.hal;
    scac.int_pin = SIM_BOARD_DR(0);
    return err;
}

static int sca_setup(void)
{
    struct sim_inertial_input in;
    int err = sca_setup_variant(SIM_SCA3000_E05);
    sim_inertial_at_rest(&in);
    in.accel_g[0] = 0.5;
    sim_part_set_input(&bench.part, &in);
    return err;
}

/* Init, and the data path a driver waits on: the ring buffer with INT at half full (the part
 * has no data-ready output). */
static int sca_init(void)
{
    int err = sca3000_init(&sca, &scac);
    if (err == INC_OK) {
        err = sca3000_ring_config(&sca,
                                  SCA3000_OUT_CTRL_X | SCA3000_OUT_CTRL_Y | SCA3000_OUT_CTRL_Z, 1);
    }
    if (err == INC_OK) {
        err = sca3000_int_config(&sca, SCA3000_INT_RING_1_2, true);
    }
    if (err == INC_OK) {
        err = sca3000_ring_enable(&sca, true);
    }
    return err;
}

static int sca_read(bool *value_with_error)
{
    struct sca3000_sample s, before;
    int err = sca3000_wait_int(&sca, hal_now_ns(&bench.board.hal) + 1000000000u);
    memset(&s, 0x5A, sizeof(s));
    before = s;
    if (err == INC_OK) {
        err = sca3000_read_sample(&sca, &s);
    }
    *value_with_error = err != INC_OK && memcmp(&s, &before, sizeof(s)) != 0;
    return err;
}

struct pair {
    const char *name;
    int (*setup)(void);
    int (*init)(void);
    int (*read)(bool *value_with_error);
    uint8_t stuck_addr, stuck_bit; /* a data bit of the first output register */
};

enum { P_ADIS16255, P_ADIS_IMU, P_SCA3000, PAIRS };

static const struct pair pairs[PAIRS] = {
    {"adis16255", a16_setup, a16_init, a16_read, ADIS16255_REG_GYRO_OUT, 0},
    {"adis_imu", imu_setup, imu_init, imu_read, ADIS_IMU_REG_XGYRO_OUT, 0},
    {"sca3000", sca_setup, sca_init, sca_read, SCA3000_REG_X_LSB, 3},
};

/* ------------------------------------------------------------------ sweeps */

/* Each point: the new input, one sample period for it to reach the registers, then the
 * driver's own wait and read. */
static void test_sweep_adis16255(void)
{
    const unsigned n = UNIT_SIZE(8735u, 601u); /* host: every gyro count */
    struct sweep_stat sg, st, ss;
    struct sim_inertial_input in;
    struct adis16255_sample s;
    unsigned i;
    REQUIRE(a16_setup() == INC_OK);
    g16c.filter_m = 0; /* one tap: each sample is the input */
    REQUIRE(adis16255_init(&g16, &g16c) == INC_OK);
    stat_init(&sg, "adis16255 gyro");
    stat_init(&st, "adis16255 temp");
    stat_init(&ss, "adis16255 supply");
    sim_inertial_at_rest(&in);
    for (i = 0; i < n; i++) {
        /* ±320 °/s = ±4368 counts of 20/273 °/s (the end itself is the over-range limit);
         * TEMP_OUT's whole 12-bit code range; the supply's specified 4.75 .. 5.25 V (outside it
         * the part flags EA). */
        const int32_t kg = point(i, n, -4367, 4367);
        const int32_t kt = point(n - 1u - i, n, -2048, 2047);
        const int32_t ks = point(i, n, 2594, 2866);
        int32_t v;
        int err;
        in.rate_dps[2] = (double)kg * 20.0 / 273.0;
        in.temp_c = 25.0 + (double)kt * 0.1453;
        in.supply_v = (double)ks * 1.8315e-3;
        sim_part_set_input(&bench.part, &in);
        hal_delay_ns(&bench.board.hal, adis16255_sample_period_us(0x01) * 1000u);
        err = adis16255_wait_sample(&g16, 0, &s);
        if (err != INC_OK) {
            printf("  sample %u: %s\n", i, inc_err_name(err));
            CHECK_OK(err);
            break;
        }
        v = (int32_t)(((uint32_t)s.gyro_word & 0x3FFFu) ^ 0x2000u) - 0x2000;
        check_rat(&sg, v, s.rate_dps_q16, (int64_t)v * 4 * 327680, 273);
        v = (int32_t)(((uint32_t)s.temp_word & 0x0FFFu) ^ 0x0800u) - 0x0800;
        check_rat(&st, v, s.temp_c_q16, ((int64_t)250000 + 1453 * (int64_t)v) * 65536, 10000);
        {
            int32_t sv = 0;
            const uint16_t word = sim_part_peek(&bench.part, ADIS16255_REG_SUPPLY_OUT);
            CHECK_OK(adis16255_read_supply(&g16, &sv));
            v = (int32_t)(word & 0x0FFFu);
            check_rat(&ss, v, sv, (int64_t)v * 18315 * 65536, 10000000);
        }
    }
    stat_done(&sg, -4367, 4367);
    stat_done(&st, -2048, 2047);
    stat_done(&ss, 2594, 2866);
    no_violations();
}

struct imu_range {
    enum sim_adis_imu_variant v;
    int32_t accel;              /* rated range in counts (docs/drivers-adis-imu.md): 18 g / 5 g */
    int64_t temp_num, temp_den; /* degC per LSB = num / den */
};

static void sweep_imu(const struct imu_range *r)
{
    const unsigned n = UNIT_SIZE(16384u, 601u); /* host: every count of every channel */
    const bool f40 = r->v == SIM_ADIS16405 || r->v == SIM_ADIS16400;
    struct sweep_stat sg[3], sa[3], sm[3], st, ss, sx;
    struct sim_inertial_input in;
    struct adis_imu_sample s;
    struct adis_imu_phys ph;
    uint32_t lsb_ug;
    unsigned i, j;
    REQUIRE(imu_setup_variant(r->v) == INC_OK);
    REQUIRE(adis_imu_init(&imu, &imuc) == INC_OK);
    REQUIRE(adis_imu_set_filter(&imu, 0, ADIS_IMU_RANGE_300) == INC_OK); /* one tap */
    lsb_ug = imu.info->accel_lsb_ug;
    for (j = 0; j < 3u; j++) {
        stat_init(&sg[j], "adis_imu gyro");
        stat_init(&sa[j], "adis_imu accel");
        stat_init(&sm[j], "adis_imu magn");
    }
    stat_init(&st, "adis_imu temp");
    stat_init(&ss, "adis_imu supply");
    stat_init(&sx, "adis_imu aux");
    sim_inertial_at_rest(&in);
    for (i = 0; i < n; i++) {
        /* Gyros ±300 °/s = ±6000 counts of 0.05 (x up, y down, z up from the middle), the
         * accelerometers' rated range, the magnetometers' 14-bit range, the temperature's
         * 12-bit range, the supply's specified 4.75 .. 5.25 V, AUX_ADC's 12-bit range. */
        int32_t kg[3], ka[3], km[3];
        const int32_t kt = point(i, n, -2048, 2047);
        const int32_t ks = point(n - 1u - i, n, 1965, 2171);
        const int32_t kx = point(i, n, 0, 4095);
        int err;
        kg[0] = point(i, n, -6000, 6000);
        kg[1] = point(n - 1u - i, n, -6000, 6000);
        kg[2] = point((i + n / 2u) % n, n, -6000, 6000);
        ka[0] = point(i, n, -r->accel, r->accel);
        ka[1] = point(n - 1u - i, n, -r->accel, r->accel);
        ka[2] = point((i + n / 2u) % n, n, -r->accel, r->accel);
        km[0] = point(i, n, -8192, 8191);
        km[1] = point(n - 1u - i, n, -8192, 8191);
        km[2] = point((i + n / 2u) % n, n, -8192, 8191);
        for (j = 0; j < 3u; j++) {
            in.rate_dps[j] = (double)kg[j] * 0.05;
            in.accel_g[j] = (double)ka[j] * (double)lsb_ug * 1e-6;
        }
        in.temp_c = 25.0 + (double)kt * (double)r->temp_num / (double)r->temp_den;
        in.supply_v = (double)ks * 2.418e-3;
        sim_part_set_input(&bench.part, &in);
        sim_adis_imu_set_magn(&bench.m.adis_imu, km[0] * 0.0005, km[1] * 0.0005, km[2] * 0.0005);
        sim_adis_imu_set_aux(&bench.m.adis_imu, kx * 805.8e-6);
        hal_delay_ns(&bench.board.hal, adis_imu_current_period_ns(&imu));
        (void)adis_imu_dr_flush(&imu);
        err = adis_imu_wait_ready(&imu, 0, NULL);
        if (err == INC_OK) {
            err = adis_imu_read_sample(&imu, &s);
        }
        if (err == INC_OK) {
            err = adis_imu_to_phys(&imu, &s, &ph);
        }
        if (err != INC_OK) {
            printf("  sample %u: %s\n", i, inc_err_name(err));
            CHECK_OK(err);
            break;
        }
        for (j = 0; j < 3u; j++) {
            int32_t c = s.counts[ADIS_IMU_CH_GYRO_X + j];
            check_rat(&sg[j], c, ph.gyro_dps[j], (int64_t)c * 65536, 20);
            c = s.counts[ADIS_IMU_CH_ACCEL_X + j];
            check_rat(&sa[j], c, ph.accel_g[j], (int64_t)c * lsb_ug * 65536, 1000000);
            if (f40) {
                c = s.counts[ADIS_IMU_CH_MAGN_X + j];
                check_rat(&sm[j], c, ph.magn_gauss[j], (int64_t)c * 5 * 65536, 10000);
            }
        }
        check_rat(&st, s.counts[ADIS_IMU_CH_TEMP0], ph.temp_c[0],
                  (25 * r->temp_den + r->temp_num * s.counts[ADIS_IMU_CH_TEMP0]) * 65536,
                  r->temp_den);
        check_rat(&ss, s.counts[ADIS_IMU_CH_SUPPLY], ph.supply_v,
                  (int64_t)s.counts[ADIS_IMU_CH_SUPPLY] * 2418 * 65536, 1000000);
        check_rat(&sx, s.counts[ADIS_IMU_CH_AUX], ph.aux_v,
                  (int64_t)s.counts[ADIS_IMU_CH_AUX] * 8058 * 65536, 10000000);
    }
    for (j = 0; j < 3u; j++) {
        stat_done(&sg[j], -6000, 6000);
        stat_done(&sa[j], -r->accel, r->accel);
        if (f40) {
            stat_done(&sm[j], -8192, 8191);
        }
    }
    stat_done(&st, -2048, 2047);
    stat_done(&ss, 1965, 2171);
    stat_done(&sx, 0, 4095);
    no_violations();
}

static void test_sweep_adis_imu(void)
{
    static const struct imu_range r16405 = {SIM_ADIS16405, 5400, 14, 100};
    static const struct imu_range r16364 = {SIM_ADIS16364, 5000, 136, 1000};
    sweep_imu(&r16405);
    sweep_imu(&r16364);
}

static void sweep_sca3000(enum sim_sca3000_variant v)
{
    const unsigned n = UNIT_SIZE(8192u, 601u); /* host: every count */
    const bool d01 = v == SIM_SCA3000_D01;
    const enum sca3000_variant dv = sca_variant(v);
    const uint32_t ug = sca3000_ug_per_lsb(dv);
    struct sweep_stat sa[3], st;
    struct sim_inertial_input in;
    struct sca3000_sample s;
    unsigned i, j;
    REQUIRE(sca_setup_variant(v) == INC_OK);
    REQUIRE(sca3000_init(&sca, &scac) == INC_OK);
    for (j = 0; j < 3u; j++) {
        stat_init(&sa[j], "sca3000 accel");
    }
    stat_init(&st, "sca3000 temp");
    sim_inertial_at_rest(&in);
    for (i = 0; i < n; i++) {
        /* The 13-bit code range on each axis; the D01's 9-bit temperature code range. */
        const int32_t kt = point(i, n, 0, 511);
        int32_t k[3];
        int err;
        k[0] = point(i, n, -4096, 4095);
        k[1] = point(n - 1u - i, n, -4096, 4095);
        k[2] = point((i + n / 2u) % n, n, -4096, 4095);
        for (j = 0; j < 3u; j++) {
            in.accel_g[j] = (double)k[j] * (double)ug * 1e-6;
        }
        in.temp_c = ((double)kt - 214.6) / 1.8;
        sim_part_set_input(&bench.part, &in);
        sim_bench_wait_ns(&bench, 1000000000000ull / sim_sca3000_odr_mhz(&bench.m.sca3000) + 1u);
        err = sca3000_read_sample(&sca, &s);
        if (err != INC_OK) {
            printf("  sample %u: %s\n", i, inc_err_name(err));
            CHECK_OK(err);
            break;
        }
        for (j = 0; j < 3u; j++) {
            int32_t g = 0;
            CHECK_OK(sca3000_accel_g_from_counts(s.xyz[j], dv, &g));
            check_rat(&sa[j], s.xyz[j], g, (int64_t)s.xyz[j] * ug * 65536, 1000000);
        }
        if (d01) {
            int32_t c = 0;
            CHECK(s.temp_valid);
            CHECK_OK(sca3000_temp_c_from_counts(s.temp_raw, &c));
            check_rat(&st, s.temp_raw, c, ((int64_t)10 * s.temp_raw - 2146) * 65536, 18);
        }
    }
    for (j = 0; j < 3u; j++) {
        stat_done(&sa[j], -4096, 4095);
    }
    if (d01) {
        stat_done(&st, 0, 511);
    }
    no_violations();
}

static void test_sweep_sca3000(void)
{
    sweep_sca3000(SIM_SCA3000_D01);
    sweep_sca3000(SIM_SCA3000_E04);
    sweep_sca3000(SIM_SCA3000_E05);
}

/* ------------------------------------------------------------------ the fault matrix */

#define NA 1   /* the model cannot show the fault (sim_part_inject: INC_ERR_UNSUPPORTED) */
#define NONE 2 /* no known deviation */

struct cell {
    int expect, alt; /* the driver's documented answer (either) */
    int known;       /* a known deviation: what the driver answers instead (NONE: none) */
    bool known_leak; /* a known deviation: later reads under the fault deliver values */
};

struct row {
    enum sim_fault fault;
    bool at_init; /* injected before init (the observation is init's result) */
    struct cell cell[PAIRS];
};

#define E(a)              \
    {                     \
        a, a, NONE, false \
    }
#define E2(a, b)          \
    {                     \
        a, b, NONE, false \
    }
#define K(a, b, k, leak) \
    {                    \
        a, b, k, leak    \
    }

static const struct row matrix[] = {
    {SIM_FAULT_MISO_STUCK_HIGH, true, {E(INC_ERR_BUS), E(INC_ERR_BUS), E(INC_ERR_BUS)}},
    {SIM_FAULT_MISO_STUCK_LOW, true, {E(INC_ERR_BUS), E(INC_ERR_BUS), E(INC_ERR_BUS)}},
    {SIM_FAULT_WRONG_ID, true, {E(INC_ERR_ID), E(INC_ERR_ID), E(INC_ERR_ID)}},
    /* ADIS16255: the busy part answers garbage and its data-ready keeps coming; the driver's
     * chained SENS_AVG word (the first word of each read answers the previous read's trailing
     * SENS_AVG command) tells garbage from samples: INC_ERR_BUSY (docs/drivers-adis16255.md). */
    {SIM_FAULT_BUSY,
     false,
     {E2(INC_ERR_BUSY, INC_ERR_TIMEOUT), E2(INC_ERR_BUSY, INC_ERR_TIMEOUT), E(NA)}},
    {SIM_FAULT_NO_DATA_READY, false, {E(INC_ERR_TIMEOUT), E(INC_ERR_TIMEOUT), E(INC_ERR_TIMEOUT)}},
    /* A spurious data-ready pulse halfway through each period: no new sample behind it; the
     * driver must not deliver the old sample again as new (not modelled on the ADIS16255). */
    {SIM_FAULT_EXTRA_DATA_READY, false, {E(NA), E(INC_OK), E(INC_OK)}},
    /* The ADIS protocol has no check word: a flipped data bit is a plausible value. The
     * ADIS16255's chained SENS_AVG word is corrupted with the rest (every word XOR 0x0101):
     * the read is refused as garbage (INC_ERR_BUSY); the ADIS IMU burst has no such word. */
    {SIM_FAULT_CORRUPT_FRAME,
     false,
     {E2(INC_ERR_BUSY, INC_ERR_BUS), K(INC_ERR_BUS, INC_ERR_CRC, INC_OK, true),
      E2(INC_ERR_BUS, INC_ERR_CRC)}},
    {SIM_FAULT_DEVICE_ERROR, false, {E(INC_ERR_DEVICE), E(INC_ERR_DEVICE), E(INC_ERR_DEVICE)}},
    /* Value faults: one sample cannot show them to a driver (a plausibility check above the
     * driver can); the driver must still deliver the sample. */
    {SIM_FAULT_FROZEN_OUTPUT, false, {E(INC_OK), E(INC_OK), E(INC_OK)}},
    {SIM_FAULT_STUCK_BIT, false, {E(INC_OK), E(INC_OK), E(INC_OK)}},
    {SIM_FAULT_BIAS_JUMP, false, {E(INC_OK), E(INC_OK), E(INC_OK)}},
    {SIM_FAULT_NOISE_BURST, false, {E(INC_OK), E(INC_OK), E(INC_OK)}},
    /* Saturation: the ADIS parts flag over-range (EA); the SCA3000 has no such flag. */
    {SIM_FAULT_SATURATION, false, {E(INC_ERR_DEVICE), E(INC_ERR_DEVICE), E(INC_OK)}},
};

static const char *res_name(int r)
{
    return r == NA ? "n/a" : (r == NONE ? "-" : inc_err_name(r));
}

#define MATRIX_READS 16u

static void test_fault_matrix(void)
{
    unsigned i, p, k;
    printf("  %-16s %-10s %-26s %-10s %-5s %s\n", "fault", "pair", "expected", "observed", "leak",
           "verdict");
    for (i = 0; i < sizeof(matrix) / sizeof(matrix[0]); i++) {
        const struct row *row = &matrix[i];
        for (p = 0; p < (unsigned)PAIRS; p++) {
            const struct pair *pr = &pairs[p];
            const struct cell *c = &row->cell[p];
            struct sim_fault_arg arg = sim_fault_default(row->fault);
            bool vwe = false, ok, leak = false;
            unsigned leaks = 0;
            const char *verdict;
            char expected[40], reads[16];
            int obs, inj;
            REQUIRE(pr->setup() == INC_OK);
            if (row->fault == SIM_FAULT_STUCK_BIT) {
                arg.addr = pr->stuck_addr;
                arg.bit = pr->stuck_bit;
            }
            if (row->at_init) {
                inj = sim_part_inject(&bench.part, row->fault, &arg);
                obs = inj == INC_OK ? pr->init() : NA;
            } else {
                REQUIRE(pr->init() == INC_OK);
                inj = sim_part_inject(&bench.part, row->fault, &arg);
                obs = inj == INC_OK ? pr->read(&vwe) : NA;
                /* A fault the driver must report is reported on every read, not only the
                 * first: reads that deliver a value under it are leaks. */
                for (k = 1; inj == INC_OK && c->expect != INC_OK && k < MATRIX_READS; k++) {
                    bool v = false;
                    if (pr->read(&v) == INC_OK) {
                        leaks++;
                    }
                    vwe = vwe || v;
                }
            }
            if (inj != INC_OK) {
                CHECK_ERR(inj, INC_ERR_UNSUPPORTED);
            }
            leak = leaks != 0u || (c->expect != INC_OK && obs == INC_OK);
            if (c->expect == c->alt) {
                snprintf(expected, sizeof(expected), "%s", res_name(c->expect));
            } else {
                snprintf(expected, sizeof(expected), "%s or %s", res_name(c->expect),
                         res_name(c->alt));
            }
            ok = (obs == c->expect || obs == c->alt) && !leak && !vwe;
            if (ok) {
                verdict = "ok";
            } else if (obs == c->known && leak == c->known_leak && !vwe) {
                verdict = "KNOWN DEVIATION (docs/sim.md)";
            } else {
                verdict = vwe ? "FAIL (a value with the error)" : "FAIL";
                unit_fail(__FILE__, __LINE__, "fault matrix: %s on %s", sim_fault_name(row->fault),
                          pr->name);
            }
            if (row->at_init || c->expect == INC_OK) {
                snprintf(reads, sizeof(reads), "-");
            } else {
                snprintf(reads, sizeof(reads), "%u/%u", leaks, MATRIX_READS - 1u);
            }
            printf("  %-16s %-10s %-26s %-10s %-5s %s\n", sim_fault_name(row->fault), pr->name,
                   expected, res_name(obs), reads, verdict);
        }
    }
}

/* A spurious data-ready pulse halfway through every period reaches the ADIS IMU's driver, which
 * reads on it, finds ND clear (no new sample behind it) and does not hand the old sample out
 * again: 16 samples, each with a new time stamp one period after the last. */
static void test_extra_data_ready(void)
{
    struct sim_fault_arg arg = sim_fault_default(SIM_FAULT_EXTRA_DATA_READY);
    struct adis_imu_sample s;
    uint64_t last = 0;
    unsigned k, fresh = 0;
    REQUIRE(imu_setup() == INC_OK);
    REQUIRE(imu_init() == INC_OK);
    CHECK_OK(sim_part_inject(&bench.part, SIM_FAULT_EXTRA_DATA_READY, &arg));
    for (k = 0; k < 16u; k++) {
        int err = adis_imu_wait_ready(&imu, 0, NULL);
        if (err == INC_OK) {
            err = adis_imu_read_sample(&imu, &s);
        }
        if (err == INC_ERR_STALE) { /* the spurious edge: the next one is the sample */
            err = adis_imu_wait_ready(&imu, 0, NULL);
            if (err == INC_OK) {
                err = adis_imu_read_sample(&imu, &s);
            }
        }
        CHECK_OK(err);
        if (err == INC_OK && s.t_ns > last) {
            fresh++;
            last = s.t_ns;
        }
    }
    CHECK_EQ_INT((int)fresh, 16);
    CHECK(bench.m.adis_imu.dr_extra_pulses >= 15u);
    CHECK(imu.stale_reads >= 10u); /* it did read on the spurious edges */
    sim_part_clear_all(&bench.part);
    no_violations();
}

/* Faults clear: a part whose faults are all cleared serves the driver normally again. */
static void test_faults_clear(void)
{
    unsigned p, f;
    bool vwe = false;
    for (p = 0; p < (unsigned)PAIRS; p++) {
        REQUIRE(pairs[p].setup() == INC_OK);
        for (f = 0; f < (unsigned)SIM_FAULT_COUNT; f++) {
            struct sim_fault_arg arg = sim_fault_default((enum sim_fault)f);
            arg.addr = pairs[p].stuck_addr;
            arg.bit = pairs[p].stuck_bit;
            (void)sim_part_inject(&bench.part, (enum sim_fault)f, &arg);
        }
        sim_part_clear_all(&bench.part);
        CHECK_EQ_INT(bench.part.active, 0);
        CHECK_OK(pairs[p].init());
        CHECK_OK(pairs[p].read(&vwe));
        CHECK(!vwe);
        no_violations();
    }
}

int main(void)
{
    printf("engine: %s\n", ENGINE_NAME);
    UNIT_RUN(test_sweep_adis16255);
    UNIT_RUN(test_sweep_adis_imu);
    UNIT_RUN(test_sweep_sca3000);
    UNIT_RUN(test_fault_matrix);
    UNIT_RUN(test_extra_data_ready);
    UNIT_RUN(test_faults_clear);
    return unit_report();
}
