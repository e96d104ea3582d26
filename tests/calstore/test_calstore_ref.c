/* Two-slot store, differential: the firmware store against the frozen implementation it
 * replaced (calstore_ref.c). For every pair of slot states (erased, valid, other sensor, bad CRC,
 * no commit, garbage, other lengths and versions, out of range) on several geometries, load and
 * save with and without an injected driver failure or stuck bit: the same return code, info,
 * output record, flash operations (order, address, length and a hash of programmed data) and
 * final flash contents. Plus calstore_init / calstore_slot_min_size over edge geometries. */
#include <string.h>

#include "calstore_ref.h"
#include "fixture.h"
#include "inclino/crc32.h"
#include "unit.h"

static const struct fix_geometry geos[] = {
    {"1KiB/8", 1024u, 8u, 1u, SIMFLASH_REPROGRAM_ERROR},
    {"256/4 x3", 256u, 4u, 3u, SIMFLASH_REPROGRAM_AND},
    {"1KiB/2", 1024u, 2u, 1u, SIMFLASH_REPROGRAM_ERROR},
    {"512/1 x2", 512u, 1u, 2u, SIMFLASH_REPROGRAM_AND},
    {"1KiB/32", 1024u, 32u, 1u, SIMFLASH_REPROGRAM_ERROR},
};

/* ---- A logging driver in front of the emulation ------------------------------------------- */

#define LOG_MAX 160u
struct op_log {
    unsigned n;
    uint32_t op[LOG_MAX], addr[LOG_MAX], len[LOG_MAX], hash[LOG_MAX];
    int rc[LOG_MAX];
};
static struct op_log *cur_log;

static void log_op(uint32_t op, uint32_t addr, uint32_t len, uint32_t hash, int rc)
{
    struct op_log *l = cur_log;
    if (l->n < LOG_MAX) {
        l->op[l->n] = op;
        l->addr[l->n] = addr;
        l->len[l->n] = len;
        l->hash[l->n] = hash;
        l->rc[l->n] = rc;
    }
    l->n++;
}

static int lg_read(void *ctx, uint32_t addr, uint8_t *buf, uint32_t len)
{
    int rc = simflash_read(ctx, addr, buf, len);
    log_op(0, addr, len, 0, rc);
    return rc;
}

static int lg_program(void *ctx, uint32_t addr, const uint8_t *buf, uint32_t len)
{
    int rc = simflash_program(ctx, addr, buf, len);
    log_op(1, addr, len, crc32_update(0, buf, len), rc);
    return rc;
}

static int lg_erase(void *ctx, uint32_t addr)
{
    int rc = simflash_erase(ctx, addr);
    log_op(2, addr, 0, 0, rc);
    return rc;
}

static const struct calstore_flash_ops lg_ops = {lg_read, lg_program, lg_erase};

/* ---- Slot states ---------------------------------------------------------------------------- */

enum {
    ST_ERASED,
    ST_VALID,
    ST_OTHER_SENSOR,
    ST_BAD_CRC,
    ST_NO_COMMIT,
    ST_GARBAGE_END,
    ST_GARBAGE_BYTE,
    ST_VERSION3,
    ST_LONGER,
    ST_LEN_ODD,
    ST_LEN_SHORT,
    ST_LEN_HUGE,
    ST_LEN_MIN,
    ST_RANGE,
    ST_COUNT
};

static uint8_t mem[FIX_FLASH_MAX];
static uint8_t start[FIX_FLASH_MAX];
static struct fix_store fs;

static void reseal_len(uint8_t *img, uint32_t len)
{
    calrec_put_le32(&img[len - 4u], crc32_update(0, img, len - 4u));
}

static void put_state(unsigned slot, unsigned state, uint32_t seq)
{
    static uint8_t img[1024];
    struct calrec r;
    uint32_t base = fs.cfg.slot_addr[slot];
    uint32_t len = CALREC_IMAGE_SIZE;
    uint8_t b = 0x00;

    fix_record_variant(&r, (int)seq);
    memset(img, 0x3C, sizeof img);
    REQUIRE(calrec_encode(&r, seq, img, CALREC_IMAGE_SIZE) == INC_OK);
    switch (state) {
    case ST_ERASED: return;
    case ST_VALID: break;
    case ST_OTHER_SENSOR:
        calrec_put_le32(&img[CALREC_OFF_BINDING + 12u], 0x4321u);
        fix_reseal(img);
        break;
    case ST_BAD_CRC: img[200] ^= 0x10u; break;
    case ST_NO_COMMIT: REQUIRE(simflash_poke(&fs.flash, base, img, len) == INC_OK); return;
    case ST_GARBAGE_END: /* magic erased, one byte of the commit unit programmed */
        REQUIRE(simflash_poke(&fs.flash, base + fs.store.commit_off, &b, 1u) == INC_OK);
        return;
    case ST_GARBAGE_BYTE: REQUIRE(simflash_poke(&fs.flash, base + 300u, &b, 1u) == INC_OK); return;
    case ST_VERSION3:
        calrec_put_le32(&img[CALREC_OFF_VERSION], 3u);
        fix_reseal(img);
        break;
    case ST_LONGER: /* intact record of a future, longer version */
        len = 720u;
        calrec_put_le32(&img[CALREC_OFF_LENGTH], len);
        reseal_len(img, len);
        break;
    case ST_LEN_ODD: calrec_put_le32(&img[CALREC_OFF_LENGTH], 658u); break;
    case ST_LEN_SHORT: calrec_put_le32(&img[CALREC_OFF_LENGTH], 16u); break;
    case ST_LEN_HUGE: calrec_put_le32(&img[CALREC_OFF_LENGTH], 0xFFFFFFFCu); break;
    case ST_LEN_MIN: /* the smallest intact record any version can write */
        len = CALREC_MIN_SIZE;
        calrec_put_le32(&img[CALREC_OFF_LENGTH], len);
        reseal_len(img, len);
        break;
    default: /* ST_RANGE */
        calrec_put_le32(&img[CALREC_OFF_ACC_GAIN], 0u);
        fix_reseal(img);
        break;
    }
    if (len + 64u > fs.cfg.slot_size) {
        len = CALREC_IMAGE_SIZE; /* a longer image does not fit this geometry: plain record */
        calrec_put_le32(&img[CALREC_OFF_LENGTH], len);
        fix_reseal(img);
    }
    REQUIRE(fix_put_image(&fs, slot, img, len) == INC_OK);
}

/* ---- One scenario, run on both implementations --------------------------------------------- */

struct outcome {
    struct op_log log;
    int rc;
    struct calstore_info info;
    struct calrec out;
    uint8_t flash[FIX_FLASH_MAX];
};
static struct outcome got, want;
static unsigned mismatches, scenarios;

/* fault: 0 none; 1..8 fail the n-th read; 9, 10 the 1st / 2nd program; 11 the 1st erase;
 * 12 stuck bit in the image, 13 stuck bit in the commit unit of the written slot (0 or 1). */
/* The emulation in its power-on state (no faults armed, counters 0) over mem. */
static void fresh_flash(const struct fix_geometry *g)
{
    struct simflash_geometry geo;
    geo.page_size = g->page_size;
    geo.prog_size = g->prog_size;
    geo.page_count = 2u * g->slot_pages;
    REQUIRE(simflash_init(&fs.flash, mem, sizeof mem, &geo) == INC_OK);
    simflash_set_reprogram(&fs.flash, g->reprogram);
}

static void run(const struct fix_geometry *g, bool ref, unsigned op, unsigned fault,
                struct outcome *o)
{
    struct calrec r;
    struct calrec_binding e;
    struct calstore_info *ip = (op & 2u) ? NULL : &o->info;

    fresh_flash(g);
    memcpy(mem, start, fs.size);
    if (fault >= 12u) {
        /* A stuck bit in the image or in the commit unit of slot 1. */
        uint32_t at = (fault == 12u) ? 100u : fs.store.commit_off;
        simflash_set_stuck(&fs.flash, fs.cfg.slot_addr[1] + at, 0x01u);
    }
    cur_log = &o->log;
    memset(&o->log, 0, sizeof o->log);
    memset(&o->info, 0x6B, sizeof o->info);
    memset(&o->out, 0x6B, sizeof o->out);
    if (fault >= 1u && fault <= 8u) {
        simflash_fail_op(&fs.flash, SIMFLASH_OP_READ, fault);
    } else if (fault == 9u || fault == 10u) {
        simflash_fail_op(&fs.flash, SIMFLASH_OP_PROGRAM, fault - 8u);
    } else if (fault == 11u) {
        simflash_fail_op(&fs.flash, SIMFLASH_OP_ERASE, 1u);
    }
    fix_record_variant(&r, 7);
    fix_binding(&e);
    if (op & 1u) {
        o->rc = ref ? ref_calstore_save(&fs.store, &r, ip) : calstore_save(&fs.store, &r, ip);
    } else {
        o->rc = ref ? ref_calstore_load(&fs.store, &e, &o->out, ip)
                    : calstore_load(&fs.store, &e, &o->out, ip);
    }
    memcpy(o->flash, mem, fs.size);
}

static bool same(const struct outcome *a, const struct outcome *b)
{
    unsigned i;
    if (a->rc != b->rc || a->log.n != b->log.n || memcmp(a->flash, b->flash, fs.size) != 0) {
        return false;
    }
    for (i = 0; i < a->log.n && i < LOG_MAX; i++) {
        if (a->log.op[i] != b->log.op[i] || a->log.addr[i] != b->log.addr[i] ||
            a->log.len[i] != b->log.len[i] || a->log.hash[i] != b->log.hash[i] ||
            a->log.rc[i] != b->log.rc[i]) {
            return false;
        }
    }
    for (i = 0; i < 2u; i++) {
        if (a->info.slot[i].status != b->info.slot[i].status ||
            /* bytes, not bools: an output left untouched holds the 0x6B fill, no valid bool */
            memcmp(&a->info.slot[i].intact, &b->info.slot[i].intact, sizeof(bool)) != 0 ||
            a->info.slot[i].seq != b->info.slot[i].seq) {
            return false;
        }
    }
    return a->info.used_slot == b->info.used_slot && a->info.seq == b->info.seq &&
           fix_record_equal(&a->out, &b->out);
}

static void test_slot_states(void)
{
    unsigned g, s0, s1, op, fault;

    for (g = 0; g < sizeof geos / sizeof geos[0]; g++) {
        CHECK_OK(fix_store_init(&fs, mem, sizeof mem, &geos[g]));
        fs.cfg.ops = &lg_ops;
        CHECK_OK(calstore_init(&fs.store, &fs.cfg));
        for (s0 = 0; s0 < ST_COUNT; s0++) {
            for (s1 = 0; s1 < ST_COUNT; s1++) {
                memset(mem, 0xFF, fs.size);
                put_state(0, s0, 5u);
                put_state(1, s1, s0 == s1 ? 0xFFFFFFFFu : 6u);
                memcpy(start, mem, fs.size);
                for (op = 0; op < 4u; op++) {
                    for (fault = 0; fault <= 13u; fault++) {
                        run(&geos[g], false, op, fault, &got);
                        run(&geos[g], true, op, fault, &want);
                        scenarios++;
                        if (!same(&got, &want) && mismatches++ < 8u) {
                            unit_fail(__FILE__, __LINE__,
                                      "geometry %s slots %u/%u op %u fault %u: rc %d ref %d, "
                                      "%u ops ref %u",
                                      geos[g].name, s0, s1, op, fault, got.rc, want.rc, got.log.n,
                                      want.log.n);
                        }
                    }
                }
            }
        }
    }
    CHECK_EQ_INT(mismatches, 0);
    CHECK(scenarios > 1000u);
}

/* calstore_init and calstore_slot_min_size over edge geometries and slot placements. */
static void test_init_edges(void)
{
    static const uint32_t sizes[] = {0u, 1u, 2u, 3u, 4u, 8u, 16u, 32u, 64u, 96u, 256u, 700u, 1024u};
    static const uint32_t addrs[] = {0u, 512u, 1024u, 1536u, 2048u, 0xFFFFFC00u, 0xFFFFF800u};
    static const uint32_t slots[] = {
        0u, 512u, 768u, 1024u, 2048u, CALSTORE_SLOT_MAX, CALSTORE_SLOT_MAX + 1024u};
    struct calstore st;
    struct calstore_config c;
    unsigned p, q, a0, a1, sl, bad = 0;

    for (p = 0; p < sizeof sizes / sizeof sizes[0]; p++) {
        for (q = 0; q < sizeof sizes / sizeof sizes[0]; q++) {
            if (calstore_slot_min_size(sizes[p], sizes[q]) !=
                ref_calstore_slot_min_size(sizes[p], sizes[q])) {
                bad++;
            }
            for (a0 = 0; a0 < sizeof addrs / sizeof addrs[0]; a0++) {
                for (a1 = 0; a1 < sizeof addrs / sizeof addrs[0]; a1++) {
                    for (sl = 0; sl < sizeof slots / sizeof slots[0]; sl++) {
                        int rc, ref_rc;
                        uint32_t ref_off;
                        memset(&c, 0, sizeof c);
                        c.ops = &lg_ops;
                        c.page_size = sizes[q];
                        c.prog_size = sizes[p];
                        c.erased_value = 0xFFu;
                        c.slot_addr[0] = addrs[a0];
                        c.slot_addr[1] = addrs[a1];
                        c.slot_size = slots[sl];
                        memset(&st, 0x42, sizeof st);
                        ref_rc = ref_calstore_init(&st, &c);
                        ref_off = st.commit_off;
                        memset(&st, 0x42, sizeof st);
                        rc = calstore_init(&st, &c);
                        if (rc != ref_rc || (rc == INC_OK && st.commit_off != ref_off)) {
                            if (bad++ < 4u) {
                                unit_fail(__FILE__, __LINE__, "init %u %u %u %u %u: %d ref %d", p,
                                          q, a0, a1, sl, rc, ref_rc);
                            }
                        }
                    }
                }
            }
        }
    }
    /* NULLs, a missing function, the erased value. */
    fix_store_init(&fs, mem, sizeof mem, &geos[0]);
    c = fs.cfg;
    CHECK_EQ_INT(calstore_init(NULL, &c), ref_calstore_init(NULL, &c));
    CHECK_EQ_INT(calstore_init(&st, NULL), ref_calstore_init(&st, NULL));
    c.erased_value = 0;
    CHECK_EQ_INT(calstore_init(&st, &c), ref_calstore_init(&st, &c));
    c = fs.cfg;
    c.ops = NULL;
    CHECK_EQ_INT(calstore_init(&st, &c), ref_calstore_init(&st, &c));
    {
        static const struct calstore_flash_ops no_erase = {lg_read, lg_program, NULL};
        c.ops = &no_erase;
        CHECK_EQ_INT(calstore_init(&st, &c), ref_calstore_init(&st, &c));
    }
    CHECK_EQ_INT(bad, 0);
}

int main(void)
{
    UNIT_RUN(test_init_edges);
    UNIT_RUN(test_slot_states);
    return unit_report();
}
