/* Two-slot store: missing, corrupt (every bit), wrong version, wrong sensor, out of range,
 * status priority, sequence wrap-around, driver failures and read-back verification, and
 * argument checking. Power cuts are in test_powercut.c. */
#include <string.h>

#include "fixture.h"
#include "inclino/crc32.h"
#include "unit.h"

static uint8_t mem[FIX_FLASH_MAX];
/* Geometry of most cases: 1 KiB pages, 8-byte program unit (ECC-style), one page per slot. */
static const struct fix_geometry g8 = {"1k/8", 1024u, 8u, 1u, SIMFLASH_REPROGRAM_ERROR};
static const struct fix_geometry g1 = {"256/1", 256u, 1u, 3u, SIMFLASH_REPROGRAM_AND};

static struct fix_store fs;

static void setup(const struct fix_geometry *g)
{
    int err = fix_store_init(&fs, mem, sizeof mem, g);
    CHECK_OK(err);
}

static void test_missing(void)
{
    struct calrec_binding b;
    struct calrec out;
    struct calstore_info info;

    setup(&g8);
    fix_binding(&b);
    memset(&out, 0x5A, sizeof out);
    CHECK_ERR(calstore_load(&fs.store, &b, &out, &info), INC_ERR_NOT_CALIBRATED);
    CHECK(fix_record_is_default(&out));
    CHECK_EQ_INT(info.used_slot, -1);
    CHECK_EQ_INT(info.slot[0].status, INC_ERR_NOT_CALIBRATED);
    CHECK_EQ_INT(info.slot[1].status, INC_ERR_NOT_CALIBRATED);
    CHECK(!info.slot[0].intact);
    CHECK_EQ_INT(simflash_steps(&fs.flash), 0); /* a load never programs or erases */
}

static void test_save_load_alternates(const struct fix_geometry *g)
{
    struct calrec r, out;
    struct calstore_info info;
    const struct simflash_stats *st = simflash_get_stats(&fs.flash);
    uint32_t body_units, commit_units, pages;
    int k;

    setup(g);
    pages = g->slot_pages;
    body_units = (CALREC_IMAGE_SIZE + g->prog_size - 1u) / g->prog_size;
    commit_units = g->prog_size >= 4u ? 1u : 4u / g->prog_size;
    for (k = 0; k < 5; k++) {
        fix_record_variant(&r, k);
        simflash_reset_stats(&fs.flash);
        CHECK_OK(calstore_save(&fs.store, &r, &info));
        CHECK_EQ_INT(info.used_slot, k % 2);
        CHECK_EQ_INT(info.seq, k + 1);
        /* Exact flash work of one save: erase the slot, program image + commit in 2 calls. */
        CHECK_EQ_INT(st->erases, pages);
        CHECK_EQ_INT(st->prog_calls, 2);
        CHECK_EQ_INT(st->prog_units, body_units + commit_units);
        CHECK_EQ_INT(st->reprograms, 0);
        CHECK_OK(calstore_load(&fs.store, &r.binding, &out, &info));
        r.valid = true;
        CHECK(fix_record_equal(&out, &r));
        CHECK_EQ_INT(info.used_slot, k % 2);
        CHECK_EQ_INT(info.seq, k + 1);
        if (k > 0) {
            CHECK_EQ_INT(info.slot[(k + 1) % 2].status, INC_OK); /* the previous one is kept */
            CHECK_EQ_INT(info.slot[(k + 1) % 2].seq, k);
        }
    }
}

static void test_save_load_8(void)
{
    test_save_load_alternates(&g8);
}
static void test_save_load_1(void)
{
    test_save_load_alternates(&g1);
}

/* Reads of a load and a save with both slots intact (the figures of docs/benchmarks.md):
 * judging an intact slot reads the header, the commit unit, the CRC-covered bytes (streamed),
 * the stored CRC and the image; a save then reads the image back in 32-byte pieces and the
 * commit unit. */
static void test_steady_state_reads(const struct fix_geometry *g)
{
    struct calrec r, out;
    const struct simflash_stats *st = simflash_get_stats(&fs.flash);
    uint32_t body = ((CALREC_IMAGE_SIZE + g->prog_size - 1u) / g->prog_size) * g->prog_size;
    uint32_t clen = g->prog_size > 4u ? g->prog_size : 4u;
    uint32_t judge = 16u + clen + (CALREC_IMAGE_SIZE - 4u) + 4u + CALREC_IMAGE_SIZE;

    setup(g);
    fix_record(&r);
    REQUIRE(calstore_save(&fs.store, &r, NULL) == INC_OK);
    REQUIRE(calstore_save(&fs.store, &r, NULL) == INC_OK);
    simflash_reset_stats(&fs.flash);
    CHECK_OK(calstore_load(&fs.store, &r.binding, &out, NULL));
    CHECK_EQ_INT(st->read_calls, 11);
    CHECK_EQ_INT(st->read_bytes, 2u * judge + CALREC_IMAGE_SIZE);
    simflash_reset_stats(&fs.flash);
    CHECK_OK(calstore_save(&fs.store, &r, NULL));
    CHECK_EQ_INT(st->read_calls, 10u + (body + 31u) / 32u + 1u);
    CHECK_EQ_INT(st->read_bytes, 2u * judge + body + clen);
    CHECK_EQ_INT(st->erases, g->slot_pages);
    CHECK_EQ_INT(st->prog_units, body / g->prog_size + (clen + g->prog_size - 1u) / g->prog_size);
}

static void test_reads_8(void)
{
    test_steady_state_reads(&g8);
}
static void test_reads_1(void)
{
    test_steady_state_reads(&g1);
}

/* Every single-bit flip in a stored record (image, padding-free area and commit unit). */
static void test_corrupt_every_bit(void)
{
    struct calrec r1, r2, out;
    struct calstore_info info;
    uint32_t addr, end = CALREC_IMAGE_SIZE + 8u; /* image + commit unit at 656 (prog 8) */
    unsigned bit, bad_single = 0, bad_pair = 0;

    setup(&g8);
    fix_record_variant(&r1, 1);
    fix_record_variant(&r2, 2);
    REQUIRE(calstore_save(&fs.store, &r1, NULL) == INC_OK); /* slot 0, seq 1 */
    /* Only one record: every flip must give "corrupt" and the safe default. */
    for (addr = 0; addr < end; addr++) {
        for (bit = 0; bit < 8u; bit++) {
            int err;
            simflash_flip_bit(&fs.flash, addr, bit);
            err = calstore_load(&fs.store, &r1.binding, &out, &info);
            if (err != INC_ERR_CRC || !fix_record_is_default(&out) || info.slot[0].intact) {
                bad_single++;
            }
            simflash_flip_bit(&fs.flash, addr, bit);
        }
    }
    CHECK_EQ_INT(bad_single, 0);

    /* Two records: flipping any bit of the newer one falls back to the older, never to a
     * corrupted newer one. */
    REQUIRE(calstore_save(&fs.store, &r2, NULL) == INC_OK); /* slot 1, seq 2 */
    r1.valid = true;
    for (addr = 0; addr < end; addr++) {
        for (bit = 0; bit < 8u; bit++) {
            int err;
            simflash_flip_bit(&fs.flash, fs.cfg.slot_addr[1] + addr, bit);
            err = calstore_load(&fs.store, &r1.binding, &out, &info);
            if (err != INC_OK || !fix_record_equal(&out, &r1) || info.used_slot != 0 ||
                info.slot[1].status != INC_ERR_CRC) {
                bad_pair++;
            }
            simflash_flip_bit(&fs.flash, fs.cfg.slot_addr[1] + addr, bit);
        }
    }
    CHECK_EQ_INT(bad_pair, 0);
    CHECK_OK(calstore_load(&fs.store, &r1.binding, &out, &info));
    CHECK_EQ_INT(info.used_slot, 1);
}

static void test_wrong_version(void)
{
    struct calrec r, out;
    struct calstore_info info;
    uint8_t img[CALREC_IMAGE_SIZE + 64];

    setup(&g8);
    fix_record(&r);
    REQUIRE(calrec_encode(&r, 5u, img, sizeof img) == INC_OK);
    calrec_put_le32(&img[CALREC_OFF_VERSION], 1u); /* a record of the previous format */
    fix_reseal(img);
    REQUIRE(fix_put_image(&fs, 0, img, CALREC_IMAGE_SIZE) == INC_OK);
    CHECK_ERR(calstore_load(&fs.store, &r.binding, &out, &info), INC_ERR_VERSION);
    CHECK(fix_record_is_default(&out));
    CHECK(info.slot[0].intact);
    CHECK_EQ_INT(info.slot[0].seq, 5);

    /* A longer (future) record, intact: still "wrong version", and its sequence number counts:
     * the next save keeps it and writes seq 10 + 1 into the other slot. */
    setup(&g8);
    memset(img, 0x11, sizeof img);
    REQUIRE(calrec_encode(&r, 10u, img, sizeof img) == INC_OK);
    calrec_put_le32(&img[CALREC_OFF_VERSION], 7u);
    calrec_put_le32(&img[CALREC_OFF_LENGTH], CALREC_IMAGE_SIZE + 64u);
    calrec_put_le32(&img[CALREC_IMAGE_SIZE + 60u], 0u);
    {
        uint32_t crc = crc32_update(0, img, CALREC_IMAGE_SIZE + 60u);
        calrec_put_le32(&img[CALREC_IMAGE_SIZE + 60u], crc);
    }
    REQUIRE(fix_put_image(&fs, 1, img, CALREC_IMAGE_SIZE + 64u) == INC_OK);
    CHECK_ERR(calstore_load(&fs.store, &r.binding, &out, &info), INC_ERR_VERSION);
    CHECK(info.slot[1].intact);
    CHECK_EQ_INT(info.slot[1].status, INC_ERR_VERSION);
    CHECK_OK(calstore_save(&fs.store, &r, &info));
    CHECK_EQ_INT(info.used_slot, 0);
    CHECK_EQ_INT(info.seq, 11);
    CHECK_OK(calstore_load(&fs.store, &r.binding, &out, &info));
    CHECK_EQ_INT(info.used_slot, 0);
}

static void test_wrong_sensor(void)
{
    struct calrec r, other, out;
    struct calrec_binding e;
    struct calstore_info info;
    unsigned field;

    for (field = 0; field < 5u; field++) {
        setup(&g8);
        fix_record(&r);
        REQUIRE(calstore_save(&fs.store, &r, NULL) == INC_OK);
        fix_binding(&e);
        switch (field) {
        case 0: e.product = 16362u; break; /* another PROD_ID */
        case 1: e.serial = 0x1233u; break; /* same type, another unit */
        case 2: e.lot_id1 = 0x0001u; break;
        case 3: e.lot_id2 = 0x0001u; break;
        default:
            e.family = CALREC_FAMILY_SCA3000;
            e.product = CALREC_SCA3000_E04;
            e.revision = 0x31u;
            e.serial = 0;
            e.lot_id1 = 0;
            e.lot_id2 = 0;
            break; /* other part, REVID */
        }
        CHECK_ERR(calstore_load(&fs.store, &e, &out, &info), INC_ERR_MISMATCH);
        CHECK(fix_record_is_default(&out));
    }

    /* SCA3000 records bound by REVID: another revision of the same variant is refused. */
    setup(&g8);
    fix_record(&r);
    memset(&r.binding, 0, sizeof r.binding);
    r.binding.family = CALREC_FAMILY_SCA3000;
    r.binding.product = CALREC_SCA3000_D01;
    r.binding.revision = 0x21u;
    REQUIRE(calstore_save(&fs.store, &r, NULL) == INC_OK);
    e = r.binding;
    e.revision = 0x22u;
    CHECK_ERR(calstore_load(&fs.store, &e, &out, NULL), INC_ERR_MISMATCH);
    CHECK_OK(calstore_load(&fs.store, &r.binding, &out, NULL));

    /* Slot 1 newer but for another sensor: the older record of this sensor is used. */
    setup(&g8);
    fix_record(&r);
    fix_record(&other);
    other.binding.serial = 0x9999u;
    REQUIRE(fix_put_record(&fs, 0, &r, 4u) == INC_OK);
    REQUIRE(fix_put_record(&fs, 1, &other, 5u) == INC_OK);
    CHECK_OK(calstore_load(&fs.store, &r.binding, &out, &info));
    CHECK_EQ_INT(info.used_slot, 0);
    CHECK_EQ_INT(info.slot[1].status, INC_ERR_MISMATCH);
    /* Saving for this sensor overwrites the foreign slot, above both sequence numbers. */
    CHECK_OK(calstore_save(&fs.store, &r, &info));
    CHECK_EQ_INT(info.used_slot, 1);
    CHECK_EQ_INT(info.seq, 5);
}

static void test_out_of_range(void)
{
    struct calrec r, out;
    struct calstore_info info;
    uint8_t img[CALREC_IMAGE_SIZE];

    setup(&g8);
    fix_record(&r);
    r.acc_gain[2] = -CALREC_Q30_ONE; /* +1 g and -1 g swapped */
    CHECK_ERR(calstore_save(&fs.store, &r, &info), INC_ERR_RANGE);
    CHECK_EQ_INT(info.used_slot, -1);
    CHECK_EQ_INT(simflash_steps(&fs.flash), 0);                 /* nothing written */
    CHECK_EQ_INT(simflash_get_stats(&fs.flash)->read_calls, 0); /* not even looked */
    calrec_set_default(&r);
    CHECK_ERR(calstore_save(&fs.store, &r, &info), INC_ERR_INVAL); /* unbound default */
    CHECK_EQ_INT(simflash_steps(&fs.flash), 0);

    /* A sealed, committed record with an out-of-range coefficient (e.g. from a buggy tool). */
    fix_record(&r);
    REQUIRE(calrec_encode(&r, 3u, img, sizeof img) == INC_OK);
    calrec_put_le32(&img[CALREC_OFF_GYRO_OFFSET], (uint32_t)(CALREC_LIM_GYRO_OFFSET + 1));
    fix_reseal(img);
    REQUIRE(fix_put_image(&fs, 0, img, sizeof img) == INC_OK);
    CHECK_ERR(calstore_load(&fs.store, &r.binding, &out, &info), INC_ERR_RANGE);
    CHECK(fix_record_is_default(&out));
    CHECK(info.slot[0].intact);
    CHECK_EQ_INT(info.slot[0].status, INC_ERR_RANGE);
}

static void test_status_priority(void)
{
    struct calrec r, out;
    struct calrec_binding e;
    uint8_t junk[64];

    /* Garbage in one slot, nothing in the other: corrupt. */
    setup(&g8);
    fix_binding(&e);
    memset(junk, 0x42, sizeof junk);
    simflash_poke(&fs.flash, 0, junk, sizeof junk);
    CHECK_ERR(calstore_load(&fs.store, &e, &out, NULL), INC_ERR_CRC);
    /* Garbage only beyond the header of an otherwise erased slot still is not "empty". */
    setup(&g8);
    simflash_poke(&fs.flash, fs.cfg.slot_addr[1] + 600u, junk, 1);
    CHECK_ERR(calstore_load(&fs.store, &e, &out, NULL), INC_ERR_CRC);
    /* An intact record of another sensor beats garbage as the reported reason. */
    setup(&g8);
    fix_record(&r);
    r.binding.serial = 7u;
    fix_put_record(&fs, 1, &r, 9u);
    simflash_poke(&fs.flash, 0, junk, sizeof junk);
    CHECK_ERR(calstore_load(&fs.store, &e, &out, NULL), INC_ERR_MISMATCH);
    CHECK(fix_record_is_default(&out));
}

static void test_seq_newer(void)
{
    CHECK(calstore_seq_newer(2u, 1u));
    CHECK(!calstore_seq_newer(1u, 2u));
    CHECK(!calstore_seq_newer(5u, 5u));
    CHECK(calstore_seq_newer(0u, 0xFFFFFFFFu));
    CHECK(!calstore_seq_newer(0xFFFFFFFFu, 0u));
    CHECK(calstore_seq_newer(0x7FFFFFFFu, 0u));
    CHECK(!calstore_seq_newer(0x80000000u, 0u)); /* exactly half the circle: neither */
    CHECK(!calstore_seq_newer(0u, 0x80000000u));
    CHECK(calstore_seq_newer(0x80000000u, 1u));
}

static void test_seq_wraparound(void)
{
    struct calrec ra, rb, out;
    struct calstore_info info;
    int k;

    /* 0xFFFFFFFF in slot 0, 0 in slot 1: slot 1 is newer; and mirrored. */
    setup(&g8);
    fix_record_variant(&ra, 1);
    fix_record_variant(&rb, 2);
    fix_put_record(&fs, 0, &ra, 0xFFFFFFFFu);
    fix_put_record(&fs, 1, &rb, 0u);
    CHECK_OK(calstore_load(&fs.store, &rb.binding, &out, &info));
    CHECK_EQ_INT(info.used_slot, 1);
    rb.valid = true;
    CHECK(fix_record_equal(&out, &rb));
    setup(&g8);
    fix_put_record(&fs, 1, &ra, 0xFFFFFFFFu);
    fix_put_record(&fs, 0, &rb, 0u);
    CHECK_OK(calstore_load(&fs.store, &rb.binding, &out, &info));
    CHECK_EQ_INT(info.used_slot, 0);

    /* Saving across the wrap: FFFFFFFE -> FFFFFFFF -> 0 -> 1, always loading the newest. */
    setup(&g8);
    fix_put_record(&fs, 0, &ra, 0xFFFFFFFEu);
    for (k = 0; k < 3; k++) {
        struct calrec r;
        fix_record_variant(&r, 10 + k);
        CHECK_OK(calstore_save(&fs.store, &r, &info));
        CHECK_EQ_HEX(info.seq, 0xFFFFFFFFu + (uint32_t)k);
        CHECK_EQ_INT(info.used_slot, (k + 1) % 2);
        CHECK_OK(calstore_load(&fs.store, &r.binding, &out, &info));
        r.valid = true;
        CHECK(fix_record_equal(&out, &r));
    }

    /* Equal or half-circle-apart numbers (never written by the store): slot 0 wins, and the
     * next save overwrites slot 1 with slot 0's number + 1. */
    setup(&g8);
    fix_put_record(&fs, 0, &ra, 100u);
    fix_put_record(&fs, 1, &rb, 100u);
    CHECK_OK(calstore_load(&fs.store, &ra.binding, &out, &info));
    CHECK_EQ_INT(info.used_slot, 0);
    setup(&g8);
    fix_put_record(&fs, 0, &ra, 5u);
    fix_put_record(&fs, 1, &rb, 5u + 0x80000000u);
    CHECK_OK(calstore_load(&fs.store, &ra.binding, &out, &info));
    CHECK_EQ_INT(info.used_slot, 0);
    CHECK_OK(calstore_save(&fs.store, &rb, &info));
    CHECK_EQ_INT(info.used_slot, 1);
    CHECK_EQ_INT(info.seq, 6);
}

static void test_driver_failures(void)
{
    struct calrec r1, r2, out;
    struct calstore_info info;
    unsigned n;

    fix_record_variant(&r1, 1);
    fix_record_variant(&r2, 2);
    r1.valid = true;

    /* Any failing read during a load: the error, and the safe default. */
    for (n = 1; n <= 8u; n++) {
        setup(&g8);
        REQUIRE(calstore_save(&fs.store, &r1, NULL) == INC_OK);
        simflash_fail_op(&fs.flash, SIMFLASH_OP_READ, n);
        {
            int err = calstore_load(&fs.store, &r1.binding, &out, &info);
            if (err != INC_OK) {
                CHECK_ERR(err, INC_ERR_IO);
                CHECK(fix_record_is_default(&out));
            } else {
                CHECK(fix_record_equal(&out, &r1)); /* n beyond the number of reads */
            }
        }
    }
    /* Failing program / erase / read-back during a save: error, and the old record stays. */
    for (n = 0; n < 4u; n++) {
        setup(&g8);
        REQUIRE(calstore_save(&fs.store, &r1, NULL) == INC_OK);
        switch (n) {
        case 0: simflash_fail_op(&fs.flash, SIMFLASH_OP_ERASE, 1); break;
        case 1: simflash_fail_op(&fs.flash, SIMFLASH_OP_PROGRAM, 1); break;
        case 2: simflash_fail_op(&fs.flash, SIMFLASH_OP_PROGRAM, 2); break; /* the commit */
        default: simflash_fail_op(&fs.flash, SIMFLASH_OP_READ, 12); break;
        }
        CHECK_ERR(calstore_save(&fs.store, &r2, &info), INC_ERR_IO);
        CHECK_OK(calstore_load(&fs.store, &r1.binding, &out, &info));
        CHECK(fix_record_equal(&out, &r1));
        CHECK_EQ_INT(info.used_slot, 0);
    }
}

/* A cell that does not program while the driver reports success: the read-back before the
 * commit catches it, nothing is committed, the old record stays. */
static void test_readback_verification(void)
{
    struct calrec r1, r2, out;
    struct calstore_info info;
    static const uint32_t where[] = {0u, 17u, 300u, 651u, 655u, 656u, 663u};
    unsigned i;
    uint8_t commit[8];

    fix_record_variant(&r1, 1);
    fix_record_variant(&r2, 2);
    r1.valid = true;
    for (i = 0; i < sizeof where / sizeof where[0]; i++) {
        setup(&g8);
        REQUIRE(calstore_save(&fs.store, &r1, NULL) == INC_OK);
        simflash_set_stuck(&fs.flash, fs.cfg.slot_addr[1] + where[i], 0xFFu);
        CHECK_ERR(calstore_save(&fs.store, &r2, &info), INC_ERR_IO);
        simflash_peek(&fs.flash, fs.cfg.slot_addr[1] + 656u, commit, sizeof commit);
        if (where[i] < 656u) {
            CHECK_EQ_HEX(commit[0] & commit[7], 0xFFu); /* never committed */
        }
        CHECK_OK(calstore_load(&fs.store, &r1.binding, &out, &info));
        CHECK(fix_record_equal(&out, &r1));
        CHECK_EQ_INT(info.slot[1].status, INC_ERR_CRC);
    }
}

static int dummy_read(void *ctx, uint32_t a, uint8_t *b, uint32_t l)
{
    (void)ctx;
    (void)a;
    (void)b;
    (void)l;
    return 0;
}
static int dummy_prog(void *ctx, uint32_t a, const uint8_t *b, uint32_t l)
{
    (void)ctx;
    (void)a;
    (void)b;
    (void)l;
    return 0;
}
static int dummy_erase(void *ctx, uint32_t a)
{
    (void)ctx;
    (void)a;
    return 0;
}

static void test_init_arguments(void)
{
    static const struct calstore_flash_ops ok_ops = {dummy_read, dummy_prog, dummy_erase};
    static const struct calstore_flash_ops no_read = {NULL, dummy_prog, dummy_erase};
    static const struct calstore_flash_ops no_prog = {dummy_read, NULL, dummy_erase};
    static const struct calstore_flash_ops no_erase = {dummy_read, dummy_prog, NULL};
    struct calstore st;
    struct calstore_config c, base;

    memset(&base, 0, sizeof base);
    base.ops = &ok_ops;
    base.page_size = 1024u;
    base.prog_size = 8u;
    base.erased_value = 0xFFu;
    base.slot_addr[0] = 0x08007800u;
    base.slot_addr[1] = 0x08007C00u;
    base.slot_size = 1024u;
    CHECK_OK(calstore_init(&st, &base));
    CHECK_ERR(calstore_init(NULL, &base), INC_ERR_NULL);
    CHECK_ERR(calstore_init(&st, NULL), INC_ERR_NULL);
    c = base;
    c.ops = NULL;
    CHECK_ERR(calstore_init(&st, &c), INC_ERR_NULL);
    c = base;
    c.ops = &no_read;
    CHECK_ERR(calstore_init(&st, &c), INC_ERR_NULL);
    c = base;
    c.ops = &no_prog;
    CHECK_ERR(calstore_init(&st, &c), INC_ERR_NULL);
    c = base;
    c.ops = &no_erase;
    CHECK_ERR(calstore_init(&st, &c), INC_ERR_NULL);
    c = base;
    c.erased_value = 0x00u;
    CHECK_ERR(calstore_init(&st, &c), INC_ERR_UNSUPPORTED);
    c = base;
    c.prog_size = 0;
    CHECK_ERR(calstore_init(&st, &c), INC_ERR_INVAL);
    c = base;
    c.prog_size = 12;
    CHECK_ERR(calstore_init(&st, &c), INC_ERR_INVAL);
    c = base;
    c.prog_size = 64;
    CHECK_ERR(calstore_init(&st, &c), INC_ERR_INVAL);
    c = base;
    c.page_size = 1020;
    c.slot_size = 2040;
    CHECK_ERR(calstore_init(&st, &c), INC_ERR_INVAL);
    c = base;
    c.page_size = 0;
    CHECK_ERR(calstore_init(&st, &c), INC_ERR_INVAL);
    c = base;
    c.page_size = 256;
    c.slot_size = 512;
    CHECK_ERR(calstore_init(&st, &c), INC_ERR_INVAL); /* < 664 */
    c = base;
    c.slot_size = 1500;
    CHECK_ERR(calstore_init(&st, &c), INC_ERR_INVAL);
    c = base;
    c.slot_addr[1] = 0x08007E00u;
    CHECK_ERR(calstore_init(&st, &c), INC_ERR_INVAL); /* unaligned */
    c = base;
    c.slot_addr[1] = c.slot_addr[0];
    CHECK_ERR(calstore_init(&st, &c), INC_ERR_INVAL);
    c = base;
    c.slot_size = 2048;
    CHECK_ERR(calstore_init(&st, &c), INC_ERR_INVAL); /* overlap */
    c = base;
    c.slot_addr[1] = 0xFFFFFC00u;
    c.slot_size = 2048;
    CHECK_ERR(calstore_init(&st, &c), INC_ERR_INVAL);
    c = base;
    c.slot_size = CALSTORE_SLOT_MAX + 1024u;
    c.slot_addr[1] = 0x0A000000u;
    CHECK_ERR(calstore_init(&st, &c), INC_ERR_INVAL);
    c = base;
    c.page_size = 256;
    c.slot_size = 768;
    c.slot_addr[1] = 0x08007B00u;
    CHECK_OK(calstore_init(&st, &c));

    CHECK_EQ_INT(calstore_slot_min_size(8, 1024), 1024);
    CHECK_EQ_INT(calstore_slot_min_size(1, 256), 768); /* 656 + 4 = 660 -> 3 pages */
    CHECK_EQ_INT(calstore_slot_min_size(32, 64), 704); /* 672 + 32 */
    CHECK_EQ_INT(calstore_slot_min_size(3, 64), 0);
}

static void test_call_arguments(void)
{
    struct calstore st;
    struct calrec r, out;
    struct calrec_binding e;
    struct calstore_info info;

    setup(&g8);
    fix_record(&r);
    fix_binding(&e);
    CHECK_ERR(calstore_load(&fs.store, &e, NULL, &info), INC_ERR_NULL);
    CHECK_EQ_INT(info.used_slot, -1);
    memset(&out, 0x77, sizeof out);
    CHECK_ERR(calstore_load(NULL, &e, &out, NULL), INC_ERR_NULL);
    CHECK(fix_record_is_default(&out));
    CHECK_ERR(calstore_load(&fs.store, NULL, &out, NULL), INC_ERR_NULL);
    e.family = 9;
    CHECK_ERR(calstore_load(&fs.store, &e, &out, NULL), INC_ERR_INVAL);
    CHECK(fix_record_is_default(&out));
    CHECK_ERR(calstore_save(NULL, &r, NULL), INC_ERR_NULL);
    CHECK_ERR(calstore_save(&fs.store, NULL, &info), INC_ERR_NULL);
    CHECK_EQ_INT(info.used_slot, -1);

    /* A store that was never (successfully) initialised. */
    memset(&st, 0, sizeof st);
    CHECK_ERR(calstore_load(&st, &r.binding, &out, NULL), INC_ERR_STATE);
    CHECK_ERR(calstore_save(&st, &r, NULL), INC_ERR_STATE);
    fs.cfg.erased_value = 0;
    CHECK_ERR(calstore_init(&st, &fs.cfg), INC_ERR_UNSUPPORTED);
    CHECK_ERR(calstore_save(&st, &r, NULL), INC_ERR_STATE);
    CHECK_EQ_INT(simflash_steps(&fs.flash), 0);
}

int main(void)
{
    UNIT_RUN(test_missing);
    UNIT_RUN(test_save_load_8);
    UNIT_RUN(test_save_load_1);
    UNIT_RUN(test_reads_8);
    UNIT_RUN(test_reads_1);
    UNIT_RUN(test_corrupt_every_bit);
    UNIT_RUN(test_wrong_version);
    UNIT_RUN(test_wrong_sensor);
    UNIT_RUN(test_out_of_range);
    UNIT_RUN(test_status_priority);
    UNIT_RUN(test_seq_newer);
    UNIT_RUN(test_seq_wraparound);
    UNIT_RUN(test_driver_failures);
    UNIT_RUN(test_readback_verification);
    UNIT_RUN(test_init_arguments);
    UNIT_RUN(test_call_arguments);
    return unit_report();
}
