/*
 * calstore.c - two-slot, power-safe calibration storage. Protocol and proof sketch: see
 * docs/calibration-storage.md; the exhaustive power-cut test is tests/calstore/test_powercut.c.
 *
 * Design choices and why:
 *  - Two slots on separate erase pages, never one: erasing is the only operation that destroys
 *    a record, and it only ever hits the slot that does NOT hold the record a load would return
 *    at that moment.
 *  - A separate commit unit after the image, programmed last: a torn program of the image can
 *    leave any bit pattern between old and new (a cell is cleared or not), and a CRC rejects
 *    such patterns only with probability 1 - 2^-32. The commit word makes an unfinished save
 *    deterministically invisible: it is programmed only after the image read back correctly,
 *    and a load demands it bit-exact. The CRC then guards against later corruption.
 *  - Each program unit is programmed once per erase (image units, padding, commit unit are
 *    disjoint), so flash with ECC per program unit, which forbids reprogramming, works too.
 *  - Integrity (commit word + CRC over the length the header declares) is judged independently
 *    of the format version, so the sequence number of a record written by another firmware
 *    version still counts when choosing the next one.
 */
#include "inclino/calstore.h"

#include "inclino/crc32.h"

#define CALSTORE_INIT_MAGIC 0x43535431u
#define CALSTORE_COMMIT_MIN 4u /* the commit word is 4 bytes even when prog_size is 1 or 2 */

_Static_assert(sizeof(((struct calstore *)0)->buf) >= CALREC_IMAGE_SIZE + CALSTORE_PROG_MAX,
               "image buffer holds a padded image");

bool calstore_seq_newer(uint32_t a, uint32_t b)
{
    uint32_t d = a - b; /* modulo 2^32 */
    return d != 0u && d < 0x80000000u;
}

static bool is_pow2(uint32_t v)
{
    return v != 0u && (v & (v - 1u)) == 0u;
}

static uint32_t round_up(uint32_t v, uint32_t unit)
{
    return ((v + unit - 1u) / unit) * unit;
}

static uint32_t commit_len(uint32_t prog_size)
{
    return prog_size > CALSTORE_COMMIT_MIN ? prog_size : CALSTORE_COMMIT_MIN;
}

static bool geometry_ok(uint32_t prog_size, uint32_t page_size)
{
    return is_pow2(prog_size) && prog_size <= CALSTORE_PROG_MAX && page_size != 0u &&
           page_size % prog_size == 0u;
}

uint32_t calstore_slot_min_size(uint32_t prog_size, uint32_t page_size)
{
    uint32_t bytes;
    if (!geometry_ok(prog_size, page_size)) {
        return 0;
    }
    bytes = round_up(CALREC_IMAGE_SIZE, prog_size) + commit_len(prog_size);
    return round_up(bytes, page_size);
}

int calstore_init(struct calstore *st, const struct calstore_config *cfg)
{
    const struct calstore_config *c = cfg;
    uint32_t min_size;

    if (st == NULL || cfg == NULL) {
        return INC_ERR_NULL;
    }
    st->init_magic = 0;
    if (c->ops == NULL || c->ops->read == NULL || c->ops->program == NULL ||
        c->ops->erase == NULL) {
        return INC_ERR_NULL;
    }
    if (c->erased_value != CALSTORE_ERASED) {
        return INC_ERR_UNSUPPORTED;
    }
    min_size = calstore_slot_min_size(c->prog_size, c->page_size);
    if (min_size == 0u || c->slot_size < min_size || c->slot_size > CALSTORE_SLOT_MAX ||
        c->slot_size % c->page_size != 0u || c->slot_addr[0] % c->page_size != 0u ||
        c->slot_addr[1] % c->page_size != 0u) {
        return INC_ERR_INVAL;
    }
    /* Each slot must fit the 32-bit address space, and the two must not share a page. */
    if (c->slot_addr[0] > UINT32_MAX - c->slot_size ||
        c->slot_addr[1] > UINT32_MAX - c->slot_size) {
        return INC_ERR_INVAL;
    }
    if (c->slot_addr[0] < c->slot_addr[1] + c->slot_size &&
        c->slot_addr[1] < c->slot_addr[0] + c->slot_size) {
        return INC_ERR_INVAL;
    }
    st->cfg = *cfg;
    st->commit_off = round_up(CALREC_IMAGE_SIZE, c->prog_size);
    st->init_magic = CALSTORE_INIT_MAGIC;
    return INC_OK;
}

/* addr: a driver address (a slot's first byte plus an offset). */
static int flash_read(struct calstore *st, uint32_t addr, uint8_t *buf, uint32_t len)
{
    return st->cfg.ops->read(st->cfg.ctx, addr, buf, len);
}

/* The commit unit's contents: the commit word, repeated over the unit, little-endian. */
static void commit_fill(uint8_t *unit, uint32_t len)
{
    uint32_t i;
    for (i = 0; i < len; i += 4u) {
        calrec_put_le32(&unit[i], CALSTORE_COMMIT);
    }
}

/*
 * Compare the len flash bytes at driver address addr with want[0..len), or with the erased
 * value when want is NULL. Returns a driver error, else 0 when every byte matched and 1 at the first that did not
 * (nothing after it is read). The bytes are read in pieces of at most CALSTORE_PROG_MAX into a
 * local buffer when want is given (want may then be st->buf), else in pieces of sizeof st->buf
 * into st->buf.
 */
static int region_differs(struct calstore *st, uint32_t addr, uint32_t len, const uint8_t *want)
{
    uint8_t piece[CALSTORE_PROG_MAX];
    uint8_t *buf = (want != NULL) ? piece : st->buf;
    const uint32_t cap = (want != NULL) ? sizeof piece : sizeof st->buf;
    uint32_t done, i;

    for (done = 0; done < len; done += cap) {
        uint32_t n = len - done;
        int err;
        if (n > cap) {
            n = cap;
        }
        err = flash_read(st, addr + done, buf, n);
        if (err) {
            return err;
        }
        for (i = 0; i < n; i++) {
            if (buf[i] != ((want != NULL) ? want[done + i] : CALSTORE_ERASED)) {
                return 1;
            }
        }
    }
    return INC_OK;
}

/* 0 and *crc = CRC-32 of the len flash bytes at addr, streamed through the image buffer. */
static int region_crc(struct calstore *st, uint32_t addr, uint32_t len, uint32_t *crc)
{
    uint32_t done = 0;

    *crc = 0;
    while (done < len) {
        uint32_t n = len - done;
        int err;
        if (n > sizeof st->buf) {
            n = sizeof st->buf;
        }
        err = flash_read(st, addr + done, st->buf, n);
        if (err) {
            return err;
        }
        *crc = crc32_update(*crc, st->buf, n);
        done += n;
    }
    return INC_OK;
}

/*
 * Judge one slot against the expected binding. Returns a driver error (the judgement is then
 * unknown and the caller stops), else 0 with si filled in.
 */
static int judge_slot(struct calstore *st, unsigned slot, const struct calrec_binding *expect,
                      struct calstore_slot_info *si)
{
    const uint32_t prog = st->cfg.prog_size;
    const uint32_t clen = commit_len(prog);
    const uint32_t base = st->cfg.slot_addr[slot];
    uint8_t unit[CALSTORE_PROG_MAX];
    uint32_t magic, length, seq, crc;
    int err;

    si->status = INC_ERR_CRC;
    si->intact = false;
    si->seq = 0;

    err = flash_read(st, base, st->buf, CALREC_HEADER_SIZE);
    if (err) {
        return err;
    }
    magic = calrec_get_le32(&st->buf[CALREC_OFF_MAGIC]);
    length = calrec_get_le32(&st->buf[CALREC_OFF_LENGTH]);
    seq = calrec_get_le32(&st->buf[CALREC_OFF_SEQ]);

    if (magic != CALREC_MAGIC) {
        /* Never written, or garbage (torn erase, torn first program). "Empty" means every byte
         * a version-2 save would program is erased. */
        err = region_differs(st, base, st->commit_off + clen, NULL);
        if (err < 0) {
            return err;
        }
        si->status = err ? INC_ERR_CRC : INC_ERR_NOT_CALIBRATED;
        return INC_OK;
    }
    /* The declared length must leave room for the commit unit inside the slot. A length that
     * does not is a corrupt header (or a record too big for this geometry): not intact. */
    if (length % 4u != 0u || length < CALREC_MIN_SIZE || length > st->cfg.slot_size - clen ||
        round_up(length, prog) > st->cfg.slot_size - clen) {
        return INC_OK;
    }
    commit_fill(unit, clen);
    err = region_differs(st, base + round_up(length, prog), clen, unit);
    if (err) {
        return err < 0 ? err : INC_OK; /* 1: save not completed (or its commit unit damaged) */
    }
    err = region_crc(st, base, length - 4u, &crc);
    if (err) {
        return err;
    }
    err = flash_read(st, base + length - 4u, unit, 4u);
    if (err) {
        return err;
    }
    if (crc != calrec_get_le32(unit)) {
        return INC_OK;
    }
    si->intact = true;
    si->seq = seq;

    if (length > CALREC_IMAGE_SIZE) {
        si->status = INC_ERR_VERSION; /* intact, but not a version this firmware can read */
        return INC_OK;
    }
    err = flash_read(st, base, st->buf, length);
    if (err) {
        return err;
    }
    /* Re-checks magic, version, length and CRC on the very bytes it judges, then binding and
     * ranges. A difference from the streamed CRC (flash changing under us) gives INC_ERR_CRC. */
    si->status = calrec_check_image(st->buf, length, expect);
    return INC_OK;
}

/* The newer of the slots flagged use0/use1 (by sequence number), -1 if neither. Ties: slot 0. */
static int newest(const struct calstore_slot_info s[2], bool use0, bool use1)
{
    if (use0 && use1) {
        return calstore_seq_newer(s[1].seq, s[0].seq) ? 1 : 0;
    }
    if (use0) {
        return 0;
    }
    return use1 ? 1 : -1;
}

/*
 * Judge both slots into info->slot[]. Returns a driver error, else 0 with pick[0] = the newest
 * valid slot (status INC_OK) and pick[1] = the newest intact slot, each -1 if there is none.
 */
static int judge_both(struct calstore *st, const struct calrec_binding *expect,
                      struct calstore_info *info, int pick[2])
{
    const struct calstore_slot_info *s = info->slot;
    unsigned i;

    for (i = 0; i < 2u; i++) {
        int err = judge_slot(st, i, expect, &info->slot[i]);
        if (err) {
            return err;
        }
    }
    pick[0] = newest(s, s[0].status == INC_OK, s[1].status == INC_OK);
    pick[1] = newest(s, s[0].intact, s[1].intact);
    return INC_OK;
}

static void info_clear(struct calstore_info *info)
{
    unsigned s;
    for (s = 0; s < 2u; s++) {
        info->slot[s].status = INC_ERR_NOT_CALIBRATED;
        info->slot[s].intact = false;
        info->slot[s].seq = 0;
    }
    info->used_slot = -1;
    info->seq = 0;
}

/* The info a load or save fills in: the caller's, else *local; cleared either way. */
static struct calstore_info *info_begin(struct calstore_info *info, struct calstore_info *local)
{
    struct calstore_info *inf = (info != NULL) ? info : local;
    info_clear(inf);
    return inf;
}

static bool store_ready(const struct calstore *st)
{
    return st->init_magic == CALSTORE_INIT_MAGIC;
}

int calstore_load(struct calstore *st, const struct calrec_binding *expect, struct calrec *out,
                  struct calstore_info *info)
{
    struct calstore_info local;
    struct calstore_info *inf = info_begin(info, &local);
    const struct calstore_slot_info *s = inf->slot;
    int pick[2], err;

    if (out == NULL) {
        return INC_ERR_NULL;
    }
    calrec_set_default(out);
    if (st == NULL || expect == NULL) {
        return INC_ERR_NULL;
    }
    if (!store_ready(st)) {
        return INC_ERR_STATE;
    }
    err = calrec_check_binding(expect);
    if (err) {
        return err;
    }
    err = judge_both(st, expect, inf, pick);
    if (err) {
        return err;
    }
    if (pick[0] < 0) {
        /* Nothing usable. Report why, most specific first: what is wrong with the newest intact
         * record; else damage; else the flash is simply empty. */
        if (pick[1] >= 0) {
            return s[pick[1]].status;
        }
        if (s[0].status == INC_ERR_CRC || s[1].status == INC_ERR_CRC) {
            return INC_ERR_CRC;
        }
        return INC_ERR_NOT_CALIBRATED;
    }
    err = flash_read(st, st->cfg.slot_addr[pick[0]], st->buf, CALREC_IMAGE_SIZE);
    if (err) {
        return err;
    }
    err = calrec_decode(st->buf, CALREC_IMAGE_SIZE, expect, out, NULL);
    if (err) {
        return err; /* out is the safe default */
    }
    inf->used_slot = pick[0];
    inf->seq = s[pick[0]].seq;
    return INC_OK;
}

int calstore_save(struct calstore *st, const struct calrec *rec, struct calstore_info *info)
{
    struct calstore_info local;
    struct calstore_info *inf = info_begin(info, &local);
    uint8_t unit[CALSTORE_PROG_MAX];
    uint32_t seq, body, clen, off, i, base;
    unsigned target;
    int pick[2], keep, err;

    if (st == NULL || rec == NULL) {
        return INC_ERR_NULL;
    }
    if (!store_ready(st)) {
        return INC_ERR_STATE;
    }
    err = calrec_check(rec);
    if (err) {
        return err;
    }
    /* Keep what a load would return now (the newest valid record); failing that, the newest
     * intact one. The new record goes to the other slot with the kept sequence number + 1, so
     * it is newer than everything intact that survives the save. */
    err = judge_both(st, &rec->binding, inf, pick);
    if (err) {
        return err;
    }
    keep = (pick[0] >= 0) ? pick[0] : pick[1];
    target = (keep == 0) ? 1u : 0u;
    base = st->cfg.slot_addr[target];
    seq = (keep >= 0) ? inf->slot[keep].seq + 1u : 1u; /* wraps modulo 2^32 by design */

    err = calrec_encode(rec, seq, st->buf, sizeof st->buf);
    if (err) {
        return err;
    }
    body = st->commit_off; /* the image rounded up to whole program units */
    for (i = CALREC_IMAGE_SIZE; i < body; i++) {
        st->buf[i] = CALSTORE_ERASED; /* padding is programmed as erased bytes */
    }

    /* 1. Erase the target slot, page by page. */
    for (off = 0; off < st->cfg.slot_size; off += st->cfg.page_size) {
        err = st->cfg.ops->erase(st->cfg.ctx, base + off);
        if (err) {
            return err;
        }
    }
    /* 2. Program the image. */
    err = st->cfg.ops->program(st->cfg.ctx, base, st->buf, body);
    if (err) {
        return err;
    }
    /* 3. Read it back before committing: a save that did not program correctly must never
     *    become visible. Compared in small pieces so st->buf stays the reference. */
    err = region_differs(st, base, body, st->buf);
    if (err) {
        return err < 0 ? err : INC_ERR_IO;
    }
    /* 4. Commit: the last program step of a save. */
    clen = commit_len(st->cfg.prog_size);
    commit_fill(unit, clen);
    err = st->cfg.ops->program(st->cfg.ctx, base + body, unit, clen);
    if (err) {
        return err;
    }
    err = region_differs(st, base + body, clen, unit);
    if (err) {
        return err < 0 ? err : INC_ERR_IO;
    }
    inf->used_slot = (int)target;
    inf->seq = seq;
    return INC_OK;
}
