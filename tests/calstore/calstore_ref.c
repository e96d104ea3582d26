/*
 * calstore_ref.c - frozen copy of the calstore.c that preceded the size work, with every public
 * function renamed ref_calstore_*. test_calstore_ref.c runs it side by side with the firmware
 * store as an oracle: same return codes, same info, same flash operations (order, addresses,
 * lengths, data). Do not restructure this file: its value is that it is the old implementation.
 */
#include "calstore_ref.h"

#include "inclino/crc32.h"

#define CALSTORE_INIT_MAGIC 0x43535431u
#define CALSTORE_COMMIT_MIN 4u /* the commit word is 4 bytes even when prog_size is 1 or 2 */

_Static_assert(sizeof(((struct calstore *)0)->buf) >= CALREC_IMAGE_SIZE + CALSTORE_PROG_MAX,
               "image buffer holds a padded image");

bool ref_calstore_seq_newer(uint32_t a, uint32_t b)
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

uint32_t ref_calstore_slot_min_size(uint32_t prog_size, uint32_t page_size)
{
    uint32_t bytes;
    if (!geometry_ok(prog_size, page_size)) {
        return 0;
    }
    bytes = round_up(CALREC_IMAGE_SIZE, prog_size) + commit_len(prog_size);
    return round_up(bytes, page_size);
}

int ref_calstore_init(struct calstore *st, const struct calstore_config *cfg)
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
    min_size = ref_calstore_slot_min_size(c->prog_size, c->page_size);
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

static int flash_read(struct calstore *st, unsigned slot, uint32_t off, uint8_t *buf, uint32_t len)
{
    return st->cfg.ops->read(st->cfg.ctx, st->cfg.slot_addr[slot] + off, buf, len);
}

/* The commit unit's contents: the commit word, repeated over the unit, little-endian. */
static void commit_fill(uint8_t *unit, uint32_t len)
{
    uint32_t i;
    for (i = 0; i < len; i += 4u) {
        calrec_put_le32(&unit[i], CALSTORE_COMMIT);
    }
}

/* 0 and *erased = whether bytes [off, off+len) of the slot are all erased. */
static int region_erased(struct calstore *st, unsigned slot, uint32_t off, uint32_t len,
                         bool *erased)
{
    uint32_t done = 0, i;

    *erased = true;
    while (done < len) {
        uint32_t n = len - done;
        int err;
        if (n > sizeof st->buf) {
            n = sizeof st->buf;
        }
        err = flash_read(st, slot, off + done, st->buf, n);
        if (err) {
            return err;
        }
        for (i = 0; i < n; i++) {
            if (st->buf[i] != CALSTORE_ERASED) {
                *erased = false;
                return INC_OK;
            }
        }
        done += n;
    }
    return INC_OK;
}

/* 0 and *crc = CRC-32 of slot bytes [0, len), streamed through the image buffer. */
static int region_crc(struct calstore *st, unsigned slot, uint32_t len, uint32_t *crc)
{
    uint32_t done = 0;

    *crc = 0;
    while (done < len) {
        uint32_t n = len - done;
        int err;
        if (n > sizeof st->buf) {
            n = sizeof st->buf;
        }
        err = flash_read(st, slot, done, st->buf, n);
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
    uint8_t unit[CALSTORE_PROG_MAX];
    uint8_t want[CALSTORE_PROG_MAX];
    uint32_t magic, length, seq, clen, coff, crc, i;
    bool erased;
    int err;

    si->status = INC_ERR_CRC;
    si->intact = false;
    si->seq = 0;

    err = flash_read(st, slot, 0, st->buf, CALREC_HEADER_SIZE);
    if (err) {
        return err;
    }
    magic = calrec_get_le32(&st->buf[CALREC_OFF_MAGIC]);
    length = calrec_get_le32(&st->buf[CALREC_OFF_LENGTH]);
    seq = calrec_get_le32(&st->buf[CALREC_OFF_SEQ]);

    if (magic != CALREC_MAGIC) {
        /* Never written, or garbage (torn erase, torn first program). "Empty" means every byte
         * a version-2 save would program is erased. */
        err = region_erased(st, slot, 0, st->commit_off + commit_len(prog), &erased);
        if (err) {
            return err;
        }
        si->status = erased ? INC_ERR_NOT_CALIBRATED : INC_ERR_CRC;
        return INC_OK;
    }
    /* The declared length must leave room for the commit unit inside the slot. A length that
     * does not is a corrupt header (or a record too big for this geometry): not intact. */
    clen = commit_len(prog);
    if (length % 4u != 0u || length < CALREC_MIN_SIZE || length > st->cfg.slot_size - clen ||
        round_up(length, prog) > st->cfg.slot_size - clen) {
        return INC_OK;
    }
    coff = round_up(length, prog);
    err = flash_read(st, slot, coff, unit, clen);
    if (err) {
        return err;
    }
    commit_fill(want, clen);
    for (i = 0; i < clen; i++) {
        if (unit[i] != want[i]) {
            return INC_OK; /* save not completed (or its commit unit damaged) */
        }
    }
    err = region_crc(st, slot, length - 4u, &crc);
    if (err) {
        return err;
    }
    err = flash_read(st, slot, length - 4u, unit, 4u);
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
    err = flash_read(st, slot, 0, st->buf, length);
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
        return ref_calstore_seq_newer(s[1].seq, s[0].seq) ? 1 : 0;
    }
    if (use0) {
        return 0;
    }
    return use1 ? 1 : -1;
}

static int judge_both(struct calstore *st, const struct calrec_binding *expect,
                      struct calstore_info *info)
{
    unsigned s;

    for (s = 0; s < 2u; s++) {
        int err = judge_slot(st, s, expect, &info->slot[s]);
        if (err) {
            return err;
        }
    }
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

static bool store_ready(const struct calstore *st)
{
    return st->init_magic == CALSTORE_INIT_MAGIC;
}

int ref_calstore_load(struct calstore *st, const struct calrec_binding *expect, struct calrec *out,
                      struct calstore_info *info)
{
    struct calstore_info local;
    struct calstore_info *inf;
    const struct calstore_slot_info *s;
    int pick, err;

    info_clear(&local);
    inf = (info != NULL) ? info : &local;
    info_clear(inf);
    s = inf->slot;
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
    err = judge_both(st, expect, inf);
    if (err) {
        return err;
    }
    pick = newest(s, s[0].status == INC_OK, s[1].status == INC_OK);
    if (pick < 0) {
        /* Nothing usable. Report why, most specific first: what is wrong with the newest intact
         * record; else damage; else the flash is simply empty. */
        pick = newest(s, s[0].intact, s[1].intact);
        if (pick >= 0) {
            return s[pick].status;
        }
        if (s[0].status == INC_ERR_CRC || s[1].status == INC_ERR_CRC) {
            return INC_ERR_CRC;
        }
        return INC_ERR_NOT_CALIBRATED;
    }
    err = flash_read(st, (unsigned)pick, 0, st->buf, CALREC_IMAGE_SIZE);
    if (err) {
        return err;
    }
    err = calrec_decode(st->buf, CALREC_IMAGE_SIZE, expect, out, NULL);
    if (err) {
        return err; /* out is the safe default */
    }
    inf->used_slot = pick;
    inf->seq = s[pick].seq;
    return INC_OK;
}

int ref_calstore_save(struct calstore *st, const struct calrec *rec, struct calstore_info *info)
{
    struct calstore_info local;
    struct calstore_info *inf;
    const struct calstore_slot_info *s;
    uint8_t unit[CALSTORE_PROG_MAX];
    uint8_t back[CALSTORE_PROG_MAX];
    uint32_t seq, body, clen, off, i;
    unsigned target;
    int keep, err;

    info_clear(&local);
    inf = (info != NULL) ? info : &local;
    info_clear(inf);
    s = inf->slot;
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
    err = judge_both(st, &rec->binding, inf);
    if (err) {
        return err;
    }
    keep = newest(s, s[0].status == INC_OK, s[1].status == INC_OK);
    if (keep < 0) {
        keep = newest(s, s[0].intact, s[1].intact);
    }
    target = (keep == 0) ? 1u : 0u;
    seq = (keep >= 0) ? s[keep].seq + 1u : 1u; /* wraps modulo 2^32 by design */

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
        err = st->cfg.ops->erase(st->cfg.ctx, st->cfg.slot_addr[target] + off);
        if (err) {
            return err;
        }
    }
    /* 2. Program the image. */
    err = st->cfg.ops->program(st->cfg.ctx, st->cfg.slot_addr[target], st->buf, body);
    if (err) {
        return err;
    }
    /* 3. Read it back before committing: a save that did not program correctly must never
     *    become visible. Compared in small pieces so st->buf stays the reference. */
    for (off = 0; off < body; off += sizeof back) {
        uint32_t n = body - off;
        if (n > sizeof back) {
            n = sizeof back;
        }
        err = flash_read(st, target, off, back, n);
        if (err) {
            return err;
        }
        for (i = 0; i < n; i++) {
            if (back[i] != st->buf[off + i]) {
                return INC_ERR_IO;
            }
        }
    }
    /* 4. Commit: the last program step of a save. */
    clen = commit_len(st->cfg.prog_size);
    commit_fill(unit, clen);
    err = st->cfg.ops->program(st->cfg.ctx, st->cfg.slot_addr[target] + body, unit, clen);
    if (err) {
        return err;
    }
    err = flash_read(st, target, body, back, clen);
    if (err) {
        return err;
    }
    for (i = 0; i < clen; i++) {
        if (back[i] != unit[i]) {
            return INC_ERR_IO;
        }
    }
    inf->used_slot = (int)target;
    inf->seq = seq;
    return INC_OK;
}
