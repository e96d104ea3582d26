/*
 * The exhaustive power-cut test. For a sequence of saves (into empty flash, then the 2nd, 3rd,
 * 4th save, so each slot is hit both fresh and holding an old record), power is cut at EVERY
 * program/erase step of the save, in every cut mode (nothing done / torn with several seeds /
 * done), then the board "reboots" and:
 *   - the load returns the complete old record (or "not calibrated" before the first save),
 *     and nothing else for any cut before the last step; at the last step (the commit) old or
 *     new, and new when the commit completed;
 *   - the slot holding the old record is bit-for-bit untouched;
 *   - the next save succeeds and a load returns it with the next sequence number;
 *   - no program unit was ever programmed twice without an erase.
 * The geometry is chosen at compile time (POWERCUT_GEOMETRY) so that each runs as its own
 * test, in parallel and under QEMU. The step and case counts are printed (docs/benchmarks.md).
 */
#include <stdio.h>
#include <string.h>

#include "fixture.h"
#include "unit.h"

#ifndef POWERCUT_GEOMETRY
#define POWERCUT_GEOMETRY 0
#endif

/* name, page, prog, pages per slot, reprogram policy */
static const struct fix_geometry geometries[] = {
    {"1KiB page, 8 B unit (ECC flash)", 1024u, 8u, 1u, SIMFLASH_REPROGRAM_ERROR},
    {"256 B page, 4 B unit, 3 pages/slot", 256u, 4u, 3u, SIMFLASH_REPROGRAM_AND},
    {"1KiB page, 2 B unit (STM32F1-like)", 1024u, 2u, 1u, SIMFLASH_REPROGRAM_ERROR},
    {"512 B page, 1 B unit (serial NOR)", 512u, 1u, 2u, SIMFLASH_REPROGRAM_AND},
    {"1KiB page, 32 B unit", 1024u, 32u, 1u, SIMFLASH_REPROGRAM_ERROR},
};

#define WRITES 4
#define TORN_SEEDS 3u

static const struct fix_geometry *geo = &geometries[POWERCUT_GEOMETRY];
static uint8_t mem[FIX_FLASH_MAX];
static uint8_t before[FIX_FLASH_MAX]; /* flash image before the save under test */
static struct fix_store fs;
static struct calrec recs[WRITES];

static unsigned cases, bad_load, bad_keep, bad_recover, bad_rc, new_early, reprograms;

static void restore(const uint8_t *image)
{
    simflash_power_on(&fs.flash);
    simflash_poke(&fs.flash, 0, image, fs.size);
}

/* One case: from `before`, cut at step n in mode/seed while saving recs[k]. */
static void one_case(int k, uint32_t n, uint32_t steps, enum simflash_cut_mode mode, uint32_t seed)
{
    struct calrec out, want;
    struct calstore_info info;
    uint32_t keep_addr, old_seq = (uint32_t)k;    /* seq of recs[k-1] is k */
    unsigned kept_slot = (unsigned)((k + 1) % 2); /* recs[k-1] lives in slot (k-1)%2 */
    int err;

    cases++;
    restore(before);
    simflash_cut_power_at(&fs.flash, n, mode, seed);
    err = calstore_save(&fs.store, &recs[k], NULL);
    if (err != INC_ERR_IO || simflash_powered(&fs.flash)) {
        bad_rc++;
    }
    simflash_power_on(&fs.flash); /* reboot */

    /* The old record's slot is untouched. */
    keep_addr = fs.cfg.slot_addr[kept_slot];
    if (k > 0 && memcmp(&mem[keep_addr], &before[keep_addr], fs.cfg.slot_size) != 0) {
        bad_keep++;
    }

    err = calstore_load(&fs.store, &recs[k].binding, &out, &info);
    want = recs[k];
    want.valid = true;
    if (err == INC_OK && fix_record_equal(&out, &want) && info.seq == old_seq + 1u) {
        /* The new record is visible: only allowed once its commit step has happened. */
        if (n != steps || mode == SIMFLASH_CUT_BEFORE) {
            new_early++;
        }
    } else if (k == 0) {
        if ((err != INC_ERR_NOT_CALIBRATED && err != INC_ERR_CRC) || !fix_record_is_default(&out)) {
            bad_load++;
        }
    } else {
        want = recs[k - 1];
        want.valid = true;
        if (err != INC_OK || !fix_record_equal(&out, &want) || info.seq != old_seq) {
            bad_load++;
        }
    }
    if (n == steps && mode == SIMFLASH_CUT_AFTER && !(err == INC_OK && info.seq == old_seq + 1u)) {
        bad_load++; /* commit completed: the new record must be the one loaded */
    }

    /* Recovery: the next save works and is loaded. */
    err = calstore_save(&fs.store, &recs[k], &info);
    {
        uint32_t seq = info.seq;
        int err2 = calstore_load(&fs.store, &recs[k].binding, &out, &info);
        want = recs[k];
        want.valid = true;
        if (err != INC_OK || err2 != INC_OK || !fix_record_equal(&out, &want) || info.seq != seq ||
            !calstore_seq_newer(seq, old_seq)) {
            bad_recover++;
        }
    }
    reprograms += simflash_get_stats(&fs.flash)->reprograms;
    simflash_reset_stats(&fs.flash);
}

static void test_every_cut(void)
{
    uint32_t steps_per_save[WRITES];
    uint32_t expect_steps, n, seed;
    int k;

    REQUIRE(fix_store_init(&fs, mem, sizeof mem, geo) == INC_OK);
    expect_steps = geo->slot_pages + (CALREC_IMAGE_SIZE + geo->prog_size - 1u) / geo->prog_size +
                   (geo->prog_size >= 4u ? 1u : 4u / geo->prog_size);
    for (k = 0; k < WRITES; k++) {
        fix_record_variant(&recs[k], k);
    }
    for (k = 0; k < WRITES; k++) {
        struct calstore_info info;
        uint32_t t0;
        memcpy(before, mem, fs.size);
        /* Reference run: count the steps of this save. */
        t0 = simflash_steps(&fs.flash);
        REQUIRE(calstore_save(&fs.store, &recs[k], &info) == INC_OK);
        steps_per_save[k] = simflash_steps(&fs.flash) - t0;
        CHECK_EQ_INT(steps_per_save[k], expect_steps);
        CHECK_EQ_INT(info.seq, k + 1);
        for (n = 1; n <= steps_per_save[k]; n++) {
            one_case(k, n, steps_per_save[k], SIMFLASH_CUT_BEFORE, 1u);
            one_case(k, n, steps_per_save[k], SIMFLASH_CUT_AFTER, 1u);
            for (seed = 1; seed <= TORN_SEEDS; seed++) {
                one_case(k, n, steps_per_save[k], SIMFLASH_CUT_TORN,
                         n * 7919u + seed * 104729u + (uint32_t)k);
            }
        }
        /* Continue the sequence from the clean state after save k. */
        restore(before);
        REQUIRE(calstore_save(&fs.store, &recs[k], &info) == INC_OK);
        REQUIRE(info.seq == (uint32_t)k + 1u);
    }
    printf("powercut [%s]: %u steps per save (%u erase + %u program units), %u cut cases\n",
           geo->name, (unsigned)steps_per_save[0], (unsigned)geo->slot_pages,
           (unsigned)(steps_per_save[0] - geo->slot_pages), cases);
    CHECK_EQ_INT(cases, WRITES * expect_steps * (2u + TORN_SEEDS));
    CHECK_EQ_INT(bad_rc, 0);
    CHECK_EQ_INT(bad_keep, 0);
    CHECK_EQ_INT(bad_load, 0);
    CHECK_EQ_INT(new_early, 0);
    CHECK_EQ_INT(bad_recover, 0);
    CHECK_EQ_INT(reprograms, 0);
}

#if POWERCUT_GEOMETRY == 4
/*
 * Two cuts in a row on the coarse geometry: the save is cut at step n1, and the recovery save
 * after the reboot is cut again at step n2 (torn). After the second reboot the old record must
 * still be the one loaded (or the new one, only if a commit completed), and a third save works.
 */
static void test_double_cut(void)
{
    static const struct fix_geometry coarse = {"1KiB/32", 1024u, 32u, 1u, SIMFLASH_REPROGRAM_ERROR};
    struct calrec out, want_old, want_new;
    struct calstore_info info;
    uint32_t n1, n2, steps = 1u + 21u + 1u;
    unsigned bad = 0, runs = 0;

    REQUIRE(fix_store_init(&fs, mem, sizeof mem, &coarse) == INC_OK);
    REQUIRE(calstore_save(&fs.store, &recs[0], NULL) == INC_OK);
    REQUIRE(calstore_save(&fs.store, &recs[1], NULL) == INC_OK); /* old = recs[1], seq 2, slot 1 */
    memcpy(before, mem, fs.size);
    want_old = recs[1];
    want_old.valid = true;
    want_new = recs[2];
    want_new.valid = true;
    for (n1 = 1; n1 <= steps; n1++) {
        for (n2 = 1; n2 <= steps; n2++) {
            int err;
            runs++;
            restore(before);
            simflash_cut_power_at(&fs.flash, n1, SIMFLASH_CUT_TORN, n1 * 31u + n2);
            (void)calstore_save(&fs.store, &recs[2], NULL);
            simflash_power_on(&fs.flash);
            simflash_cut_power_at(&fs.flash, n2, SIMFLASH_CUT_TORN, n2 * 17u + n1);
            (void)calstore_save(&fs.store, &recs[2], NULL);
            simflash_power_on(&fs.flash);
            err = calstore_load(&fs.store, &recs[2].binding, &out, &info);
            if (err != INC_OK ||
                !(fix_record_equal(&out, &want_old) || fix_record_equal(&out, &want_new))) {
                bad++;
            } else if (fix_record_equal(&out, &want_new) && n1 != steps && n2 != steps) {
                bad++; /* new visible without any commit step */
            }
            if (calstore_save(&fs.store, &recs[3], NULL) != INC_OK ||
                calstore_load(&fs.store, &recs[3].binding, &out, &info) != INC_OK || !out.valid) {
                bad++;
            }
        }
    }
    printf("powercut double cut: %u cases\n", runs);
    CHECK_EQ_INT(runs, steps * steps);
    CHECK_EQ_INT(bad, 0);
}
#endif

int main(void)
{
    UNIT_RUN(test_every_cut);
#if POWERCUT_GEOMETRY == 4
    UNIT_RUN(test_double_cut); /* once, in the build of the coarsest geometry */
#endif
    return unit_report();
}
