/*
 * The FTFC driver through its register model: the partition policy, the command sequence with
 * each error flag mapped to its error, address checks before anything is launched, command
 * time in simulated time; then the calibration store on it: a record written at end of line
 * survives a power cycle, and a power cut at every program/erase step of a save (nothing done,
 * torn, done) leaves the previous record valid.
 */
#include "fixture.h"
#include "inclino/calstore_ftfc.h"
#include "inclino/s32k_ftfc.h"
#include "inclino/s32k_mmio.h"
#include "inclino/sim/s32k_bus.h"
#include "inclino/sim/s32k_ftfc.h"
#include "unit.h"

#include <stdio.h>
#include <string.h>

#define ACCESS_NS 25u /* virtual time one register access costs (the bus hook) */

static struct sim_clock clk;
static struct sim_s32k_ftfc model;
static struct s32k_ftfc drv;
static struct calstore store;
static struct calstore_config scfg;

static void charge(void *ctx)
{
    (void)ctx;
    sim_clock_advance_to(&clk, clk.now_ns + ACCESS_NS);
}

static int model_up(enum s32k_ftfc_part part, uint8_t depart, uint32_t erase_ns,
                    uint32_t program_ns, bool map_fcfg1)
{
    struct sim_s32k_ftfc_cfg mc;
    sim_clock_init(&clk);
    s32k_bus_reset();
    s32k_bus_set_hook(charge, NULL);
    mc.part = part;
    mc.depart = depart;
    mc.clk = &clk;
    mc.erase_ns = erase_ns;
    mc.program_ns = program_ns;
    mc.map_fcfg1 = map_fcfg1;
    return sim_s32k_ftfc_init(&model, &mc);
}

static int drv_up(enum s32k_ftfc_part part, uint32_t poll_limit)
{
    struct s32k_ftfc_cfg c;
    c.part = part;
    c.ftfc_base = S32K_FTFC_BASE;
    c.fcfg1_addr = S32K_SIM_FCFG1;
    c.dflash_base = S32K_DFLASH_BASE;
    c.poll_limit = poll_limit;
    return s32k_ftfc_init(&drv, &c);
}

static void bus_clean(void)
{
    CHECK_EQ_INT(s32k_bus_stats()->unmapped_reads, 0);
    CHECK_EQ_INT(s32k_bus_stats()->unmapped_writes, 0);
    CHECK_EQ_INT(model.stats.locked_writes, 0);
    CHECK_EQ_INT(model.stats.read_collisions, 0);
    CHECK_EQ_INT(model.stats.array_writes, 0);
}

/* ------------------------------------------------------------------ partition policy */

static void test_partition_policy(void)
{
    REQUIRE(model_up(S32K_FTFC_S32K144, 0xF, 0, 0, true) == 0);
    CHECK_ERR(drv_up(S32K_FTFC_S32K144, 0), INC_ERR_STATE); /* never partitioned: refused */
    CHECK_ERR(s32k_ftfc_erase_sector(&drv, 0), INC_ERR_STATE);
    CHECK_EQ_INT(model.stats.launches, 0);
    REQUIRE(model_up(S32K_FTFC_S32K144, 0x1, 0, 0, true) == 0);
    CHECK_ERR(drv_up(S32K_FTFC_S32K144, 0), INC_ERR_UNSUPPORTED); /* reserved code */
    REQUIRE(model_up(S32K_FTFC_S32K144, 0x4, 0, 0, true) == 0);
    CHECK_ERR(drv_up(S32K_FTFC_S32K144, 0), INC_ERR_UNSUPPORTED); /* all EEPROM backup */
    REQUIRE(model_up(S32K_FTFC_S32K144, 0x0, 0, 0, true) == 0);
    CHECK_OK(drv_up(S32K_FTFC_S32K144, 0));
    CHECK_EQ_INT(drv.dflash_size, 65536);
    REQUIRE(model_up(S32K_FTFC_S32K144, 0x3, 0, 0, true) == 0);
    CHECK_OK(drv_up(S32K_FTFC_S32K144, 0));
    CHECK_EQ_INT(drv.dflash_size, 32768);
    REQUIRE(model_up(S32K_FTFC_S32K116, 0x0, 0, 0, true) == 0);
    CHECK_OK(drv_up(S32K_FTFC_S32K116, 0));
    CHECK_EQ_INT(drv.dflash_size, 32768);
    CHECK_EQ_INT(s32k_ftfc_dflash_size(S32K_FTFC_S32K116, 0x9), 8192);
    CHECK_EQ_INT(s32k_ftfc_dflash_size(S32K_FTFC_S32K144, 0xA), 16384);
    CHECK_EQ_INT(s32k_ftfc_dflash_size(S32K_FTFC_S32K116, 0xC), 0);
    CHECK_ERR(s32k_ftfc_init(NULL, NULL), INC_ERR_NULL);
}

/* ------------------------------------------------------------------ commands and errors */

static void test_erase_program_read(void)
{
    static const uint8_t ph[16] = {1,    2,    3,    4,    5,    6,    7,    8,
                                   0x10, 0x20, 0x30, 0x40, 0x50, 0x60, 0x70, 0x80};
    uint8_t buf[16];
    uint64_t t0;
    REQUIRE(model_up(S32K_FTFC_S32K144, 0x0, 0, 0, true) == 0);
    REQUIRE(drv_up(S32K_FTFC_S32K144, 0) == 0);

    /* Program two phrases at the end of the D-flash; read them back at odd offsets. */
    t0 = clk.now_ns;
    CHECK_OK(s32k_ftfc_program(&drv, 65536u - 16u, ph, 16u));
    CHECK(clk.now_ns - t0 >= 2u * SIM_FTFC_PROGRAM_NS_DEFAULT);
    CHECK_EQ_INT(model.stats.phrases, 2);
    CHECK(memcmp(&model.mem[65536u - 16u], ph, 16u) == 0); /* byte order of FCCOB4..B */
    CHECK_OK(s32k_ftfc_read(&drv, 65536u - 15u, buf, 15u));
    CHECK(memcmp(buf, &ph[1], 15u) == 0);

    /* A phrase programmed twice without erase: MGSTAT0 -> INC_ERR_IO, cells unchanged. */
    CHECK_ERR(s32k_ftfc_program(&drv, 65536u - 16u, ph, 8u), INC_ERR_IO);
    CHECK_EQ_INT(model.stats.reprograms, 1);
    CHECK_EQ_INT(drv.stats.mgstat0, 1);
    CHECK((drv.stats.last_fstat & S32K_FTFC_FSTAT_MGSTAT0) != 0u);

    /* Erase: the sector reads 0xFF again, after the erase time. */
    t0 = clk.now_ns;
    CHECK_OK(s32k_ftfc_erase_sector(&drv, 65536u - 2048u));
    CHECK(clk.now_ns - t0 >= SIM_FTFC_ERASE_NS_DEFAULT);
    CHECK_OK(s32k_ftfc_read(&drv, 65536u - 16u, buf, 16u));
    CHECK_EQ_HEX(buf[0], 0xFF);
    CHECK_EQ_HEX(buf[15], 0xFF);
    CHECK_OK(s32k_ftfc_program(&drv, 65536u - 16u, ph, 8u)); /* erased: fine again */

    /* Address checks in the driver: nothing is launched. */
    {
        const uint32_t launches = model.stats.launches;
        CHECK_ERR(s32k_ftfc_program(&drv, 4u, ph, 8u), INC_ERR_INVAL);     /* misaligned */
        CHECK_ERR(s32k_ftfc_program(&drv, 0u, ph, 12u), INC_ERR_INVAL);    /* not whole phrases */
        CHECK_ERR(s32k_ftfc_program(&drv, 65536u, ph, 8u), INC_ERR_INVAL); /* past the end */
        CHECK_ERR(s32k_ftfc_erase_sector(&drv, 1024u), INC_ERR_INVAL);
        CHECK_ERR(s32k_ftfc_erase_sector(&drv, 65536u), INC_ERR_INVAL);
        CHECK_ERR(s32k_ftfc_read(&drv, 65530u, buf, 8u), INC_ERR_INVAL);
        CHECK_ERR(s32k_ftfc_program(&drv, 0u, NULL, 8u), INC_ERR_NULL);
        CHECK_EQ_INT(model.stats.launches, launches);
    }

    /* FPVIOL: the last eighth of the D-flash protected (FDPROT bit 7 = 0). */
    s32k_mmio_write8(S32K_FTFC_BASE + S32K_FTFC_FDPROT, 0x7Fu);
    CHECK_ERR(s32k_ftfc_erase_sector(&drv, 65536u - 2048u), INC_ERR_STATE);
    CHECK_EQ_INT(drv.stats.fpviol, 1);
    CHECK_OK(s32k_ftfc_erase_sector(&drv, 0u)); /* elsewhere fine */
    bus_clean();
}

/* ACCERR: the driver believes in 64 KiB (a SIM model says DEPART 0), the controller has
 * 32 KiB (DEPART 3): the controller refuses, the driver returns INC_ERR_INVAL. */
static uint32_t fake_fcfg1(void *ctx, uint32_t off, unsigned width)
{
    (void)ctx;
    (void)off;
    (void)width;
    return 0u; /* DEPART 0 */
}

static void fake_write(void *ctx, uint32_t off, uint32_t v, unsigned width)
{
    (void)ctx;
    (void)off;
    (void)v;
    (void)width;
}

static const struct s32k_bus_region_ops fake_ops = {fake_fcfg1, fake_write};

static void test_accerr_and_timeouts(void)
{
    static const uint8_t ph[8] = {0};
    REQUIRE(model_up(S32K_FTFC_S32K144, 0x3, 0, 0, false) == 0);
    REQUIRE(s32k_bus_map(S32K_SIM_FCFG1, 4u, &fake_ops, NULL) == 0);
    REQUIRE(drv_up(S32K_FTFC_S32K144, 0) == 0);
    CHECK_EQ_INT(drv.dflash_size, 65536);
    CHECK_ERR(s32k_ftfc_erase_sector(&drv, 40960u), INC_ERR_INVAL);
    CHECK_EQ_INT(drv.stats.accerr, 1);
    CHECK((drv.stats.last_fstat & S32K_FTFC_FSTAT_ACCERR) != 0u);
    /* The next command clears ACCERR (write 1) and works. */
    CHECK_OK(s32k_ftfc_program(&drv, 0u, ph, 8u));

    /* A command slower than the poll limit: INC_ERR_TIMEOUT; the next one finds CCIF = 0
     * (INC_ERR_BUSY) until the controller is done. */
    REQUIRE(model_up(S32K_FTFC_S32K144, 0x0, 50000000u, 0, true) == 0);
    REQUIRE(drv_up(S32K_FTFC_S32K144, 4000u) == 0); /* 100 us of polling */
    CHECK_ERR(s32k_ftfc_erase_sector(&drv, 0u), INC_ERR_TIMEOUT);
    CHECK_ERR(s32k_ftfc_program(&drv, 2048u, ph, 8u), INC_ERR_BUSY);
    sim_clock_advance_to(&clk, clk.now_ns + 50000000u);
    CHECK_OK(s32k_ftfc_program(&drv, 2048u, ph, 8u));
    CHECK_EQ_INT(model.stats.locked_writes, 0); /* FCCOB never written while busy */
}

/* ------------------------------------------------------------------ the calibration store */

static int store_up(void)
{
    int err = drv_up(S32K_FTFC_S32K144, 0);
    if (err == INC_OK) {
        err = calstore_ftfc_config(&drv, 30u, &scfg); /* the last two sectors */
    }
    if (err == INC_OK) {
        err = calstore_init(&store, &scfg);
    }
    return err;
}

static void test_record_survives_power_cycle(void)
{
    struct calrec rec, out;
    struct calstore_info info;
    REQUIRE(model_up(S32K_FTFC_S32K144, 0x0, 0, 0, true) == 0);
    REQUIRE(store_up() == 0);
    CHECK_EQ_INT(scfg.slot_addr[0], 30u * 2048u);
    CHECK_EQ_INT(scfg.prog_size, 8);
    fix_record(&rec);
    CHECK_OK(calstore_save(&store, &rec, &info)); /* end of line */
    CHECK_EQ_INT(model.stats.reprograms, 0);
    /* Power cycle: registers reset, a fresh driver and store; the array keeps its bits. */
    sim_s32k_ftfc_power_on(&model);
    memset(&drv, 0, sizeof(drv));
    memset(&store, 0, sizeof(store));
    REQUIRE(store_up() == 0);
    CHECK_OK(calstore_load(&store, &rec.binding, &out, &info));
    rec.valid = true;
    CHECK(fix_record_equal(&out, &rec));
    CHECK_EQ_INT(info.seq, 1);
    /* Too few sectors for two slots. */
    CHECK_ERR(calstore_ftfc_config(&drv, 31u, &scfg), INC_ERR_NO_SPACE);
    bus_clean();
}

#define WRITES 3
#define TORN_SEEDS 2u

static uint8_t before[S32K144_FLEXNVM_SIZE];

static void test_power_cut_every_step(void)
{
    struct calrec recs[WRITES], out, want;
    struct calstore_info info;
    unsigned cases = 0, bad = 0, new_seen = 0;
    int k;
    REQUIRE(model_up(S32K_FTFC_S32K144, 0x0, 100000u, 10000u, true) == 0);
    REQUIRE(store_up() == 0);
    for (k = 0; k < WRITES; k++) {
        fix_record_variant(&recs[k], k);
    }
    for (k = 0; k < WRITES; k++) {
        uint32_t steps, n, s0;
        memcpy(before, model.mem, sizeof(before));
        s0 = sim_s32k_ftfc_steps(&model);
        REQUIRE(calstore_save(&store, &recs[k], NULL) == 0);
        steps = sim_s32k_ftfc_steps(&model) - s0;
        for (n = 1; n <= steps; n++) {
            unsigned mode_i;
            for (mode_i = 0; mode_i < 2u + TORN_SEEDS; mode_i++) {
                const enum simflash_cut_mode mode = mode_i == 0u
                                                        ? SIMFLASH_CUT_BEFORE
                                                        : (mode_i == 1u ? SIMFLASH_CUT_AFTER
                                                                        : SIMFLASH_CUT_TORN);
                const uint32_t kept = scfg.slot_addr[(unsigned)(k + 1) % 2u];
                int err;
                cases++;
                memcpy(model.mem, before, sizeof(before));
                sim_s32k_ftfc_power_on(&model);
                REQUIRE(store_up() == 0);
                sim_s32k_ftfc_cut_power_at(&model, n, mode, mode_i);
                err = calstore_save(&store, &recs[k], NULL);
                if (err != INC_ERR_IO || sim_s32k_ftfc_powered(&model)) {
                    if (bad < 5u) {
                        printf("  k %d step %u mode %u: save %s, powered %d\n", k, (unsigned)n,
                               mode_i, inc_err_name(err), sim_s32k_ftfc_powered(&model));
                    }
                    bad++;
                }
                sim_s32k_ftfc_power_on(&model); /* reboot */
                REQUIRE(store_up() == 0);
                if (k > 0 && memcmp(&model.mem[kept], &before[kept], scfg.slot_size) != 0) {
                    printf("  k %d step %u mode %u: kept slot touched\n", k, (unsigned)n, mode_i);
                    bad++; /* the slot of the previous record was touched */
                }
                err = calstore_load(&store, &recs[k].binding, &out, &info);
                want = recs[k];
                want.valid = true;
                if (err == INC_OK && fix_record_equal(&out, &want)) {
                    /* the new record: only once the commit step happened */
                    if (n != steps || mode == SIMFLASH_CUT_BEFORE) {
                        bad++;
                    }
                    new_seen++;
                } else if (k == 0) {
                    /* never calibrated, or a torn first image: uncalibrated, safe default */
                    if ((err != INC_ERR_NOT_CALIBRATED && err != INC_ERR_CRC) ||
                        !fix_record_is_default(&out)) {
                        bad++;
                    }
                } else {
                    want = recs[k - 1];
                    want.valid = true;
                    if (err != INC_OK || !fix_record_equal(&out, &want) ||
                        (n == steps && mode == SIMFLASH_CUT_AFTER)) {
                        if (bad < 8u) {
                            printf("  k %d step %u mode %u: load %s seq %u\n", k, (unsigned)n,
                                   mode_i, inc_err_name(err), (unsigned)info.seq);
                        }
                        bad++;
                    }
                }
            }
        }
        /* Leave the completed save in place for the next k. */
        memcpy(model.mem, before, sizeof(before));
        sim_s32k_ftfc_power_on(&model);
        REQUIRE(store_up() == 0);
        REQUIRE(calstore_save(&store, &recs[k], NULL) == 0);
        printf("  save %d: %u program/erase steps\n", k, (unsigned)steps);
    }
    printf("  %u power-cut cases, %u bad, new record visible in %u\n", cases, bad, new_seen);
    CHECK(cases > 0u);
    CHECK_EQ_INT(bad, 0);
    CHECK(new_seen >= (unsigned)WRITES); /* AFTER at the commit step shows the new record */
    CHECK_EQ_INT(model.stats.reprograms, 0);
}

/* ------------------------------------------------------------------ the station's data-flash image */

/* The file the station's probe programs (calstation dflash, docs/calibration.md 4.6), written
 * over a D-flash that holds an older pair of records, then a power cycle: on both parts the
 * images' store (calstore_ftfc_config at CALSTORE_FTFC_IMAGE_SECTOR) loads the record of
 * record.bin, from slot 0 with sequence number 1; a part of another serial number gets
 * INC_ERR_MISMATCH; an on-device save afterwards goes to slot 1 with sequence number 2. */
static const char *dflash_path, *record_path;

static size_t read_file(const char *path, uint8_t *buf, size_t cap)
{
    FILE *f = fopen(path, "rb");
    size_t n = 0;
    if (f != NULL) {
        n = fread(buf, 1, cap, f);
        if (fgetc(f) != EOF) {
            n = cap + 1u; /* larger than expected */
        }
        fclose(f);
    }
    return n;
}

static void test_station_dflash_image(void)
{
    static uint8_t img[2u * S32K_DFLASH_SECTOR + 1u], rec_img[CALREC_IMAGE_SIZE + 1u];
    static uint8_t a[CALREC_IMAGE_SIZE], b[CALREC_IMAGE_SIZE];
    static const enum s32k_ftfc_part parts[2] = {S32K_FTFC_S32K116, S32K_FTFC_S32K144};
    struct calrec want, out, old;
    struct calrec_binding other;
    struct calstore_info info;
    uint32_t seq = 0u;
    unsigned p;
    const uint32_t off = CALSTORE_FTFC_IMAGE_SECTOR * S32K_DFLASH_SECTOR;
    REQUIRE(read_file(dflash_path, img, sizeof img) == 2u * S32K_DFLASH_SECTOR);
    REQUIRE(read_file(record_path, rec_img, sizeof rec_img) == CALREC_IMAGE_SIZE);
    memset(&want, 0, sizeof want);
    /* the record file decoded against the binding it carries */
    REQUIRE(calrec_image_binding(rec_img, CALREC_IMAGE_SIZE, &other) == INC_OK);
    REQUIRE(calrec_decode(rec_img, CALREC_IMAGE_SIZE, &other, &want, &seq) == INC_OK);
    for (p = 0; p < 2u; p++) {
        REQUIRE(model_up(parts[p], 0x0, 0, 0, true) == 0);
        REQUIRE(drv_up(parts[p], 0) == 0);
        REQUIRE(calstore_ftfc_config(&drv, CALSTORE_FTFC_IMAGE_SECTOR, &scfg) == 0);
        REQUIRE(calstore_init(&store, &scfg) == 0);
        /* an earlier calibration: two saves, the newer (seq 2) in slot 1 */
        fix_record(&old);
        old.binding = want.binding;
        REQUIRE(calstore_save(&store, &old, NULL) == 0);
        REQUIRE(calstore_save(&store, &old, &info) == 0);
        CHECK_EQ_INT(info.used_slot, 1);
        /* the probe: both sectors erased and programmed with the file's bytes */
        memcpy(&model.mem[off], img, 2u * S32K_DFLASH_SECTOR);
        sim_s32k_ftfc_power_on(&model);
        memset(&drv, 0, sizeof drv);
        memset(&store, 0, sizeof store);
        REQUIRE(drv_up(parts[p], 0) == 0);
        REQUIRE(calstore_ftfc_config(&drv, CALSTORE_FTFC_IMAGE_SECTOR, &scfg) == 0);
        REQUIRE(calstore_init(&store, &scfg) == 0);
        CHECK_OK(calstore_load(&store, &want.binding, &out, &info));
        CHECK_EQ_INT(info.used_slot, 0);
        CHECK_EQ_INT(info.seq, 1);
        CHECK_EQ_INT(calrec_encode(&want, 1u, a, sizeof a), 0);
        CHECK_EQ_INT(calrec_encode(&out, 1u, b, sizeof b), 0);
        CHECK(memcmp(a, b, sizeof a) == 0);
        other = want.binding;
        other.serial ^= 1u;
        CHECK_ERR(calstore_load(&store, &other, &out, NULL), INC_ERR_MISMATCH);
        CHECK_OK(calstore_save(&store, &want, &info)); /* a later on-device save */
        CHECK_EQ_INT(info.used_slot, 1);
        CHECK_EQ_INT(info.seq, 2);
        CHECK_EQ_INT(model.stats.reprograms, 0);
        bus_clean();
    }
}

int main(int argc, char **argv)
{
    if (argc == 3) { /* test ftfc_dflash: the files of tests/ftfc/dflash.cmake */
        dflash_path = argv[1];
        record_path = argv[2];
        UNIT_RUN(test_station_dflash_image);
        return unit_report();
    }
    if (argc > 1) { /* (argc is 0 under semihosting) */
        fprintf(stderr, "usage: test_ftfc [DFLASH.bin RECORD.bin]\n");
        return 2;
    }
    UNIT_RUN(test_partition_policy);
    UNIT_RUN(test_erase_program_read);
    UNIT_RUN(test_accerr_and_timeouts);
    UNIT_RUN(test_record_survives_power_cycle);
    UNIT_RUN(test_power_cut_every_step);
    return unit_report();
}
