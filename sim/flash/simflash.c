/*
 * simflash.c - emulated NOR flash (see simflash.h for the semantics).
 *
 * Why these torn states: a NOR cell is programmed by adding charge and erased by removing it.
 * A program pulse cut short leaves each cell it was clearing either cleared or not, and never
 * touches the cells it was not clearing, hence "random subset of the bits being cleared". An
 * erase cut short can leave any pattern: many erase algorithms first pre-program the page
 * (bits 1 -> 0) and then erase it (bits 0 -> 1) sector-wide, so a cut page may hold old bytes,
 * partly erased bytes, fully erased bytes and bytes that were never data at all. The model
 * mixes all four, with a random erase progress per cut, so tests meet both nearly-intact and
 * nearly-erased pages. Everything is driven by a seeded xorshift32 so a failing case replays.
 */
#include "inclino/simflash.h"

#include <string.h>

static uint32_t rng_next(struct simflash *f)
{
    uint32_t x = f->rng;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    f->rng = x;
    return x;
}

int simflash_init(struct simflash *f, uint8_t *mem, size_t mem_size,
                  const struct simflash_geometry *geo)
{
    if (f == NULL || mem == NULL || geo == NULL) {
        return INC_ERR_NULL;
    }
    if (geo->page_size == 0u || geo->page_count == 0u || geo->prog_size == 0u ||
        geo->page_size % geo->prog_size != 0u || geo->page_count > UINT32_MAX / geo->page_size ||
        mem_size < (size_t)geo->page_size * geo->page_count) {
        return INC_ERR_INVAL;
    }
    memset(f, 0, sizeof *f);
    f->mem = mem;
    f->geo = *geo;
    f->size = geo->page_size * geo->page_count;
    f->reprogram = SIMFLASH_REPROGRAM_AND;
    f->powered = true;
    f->rng = 1u;
    memset(mem, 0xFF, f->size);
    return INC_OK;
}

void simflash_set_reprogram(struct simflash *f, enum simflash_reprogram mode)
{
    if (f != NULL) {
        f->reprogram = mode;
    }
}

static bool in_array(const struct simflash *f, uint32_t addr, uint32_t len)
{
    return addr <= f->size && len <= f->size - addr;
}

/* Common entry checks: power, and an injected failure on this call of op. */
static int enter(struct simflash *f, enum simflash_op op)
{
    if (!f->powered) {
        f->stats.failed++;
        return INC_ERR_IO;
    }
    f->op_calls[op]++;
    if (f->fail_at[op] != 0u && f->op_calls[op] == f->fail_at[op]) {
        f->fail_at[op] = 0;
        f->stats.failed++;
        return INC_ERR_IO;
    }
    return INC_OK;
}

/* Begin a program/erase step; true when power fails during it. */
static bool step_is_cut(struct simflash *f)
{
    f->steps++;
    return f->cut_at != 0u && f->steps == f->cut_at;
}

static void power_fail(struct simflash *f)
{
    f->powered = false;
    f->cut_at = 0;
    f->stats.failed++;
}

static uint8_t stuck_bits(const struct simflash *f, uint32_t addr)
{
    return (f->stuck && addr == f->stuck_addr) ? f->stuck_mask : 0u;
}

int simflash_read(struct simflash *f, uint32_t addr, uint8_t *buf, uint32_t len)
{
    int err;
    if (f == NULL || buf == NULL) {
        return INC_ERR_NULL;
    }
    if (!in_array(f, addr, len)) {
        f->stats.failed++;
        return INC_ERR_INVAL;
    }
    err = enter(f, SIMFLASH_OP_READ);
    if (err) {
        return err;
    }
    memcpy(buf, &f->mem[addr], len);
    f->stats.read_calls++;
    f->stats.read_bytes += len;
    return INC_OK;
}

int simflash_program(struct simflash *f, uint32_t addr, const uint8_t *data, uint32_t len)
{
    const uint32_t unit = f != NULL ? f->geo.prog_size : 1u;
    uint32_t u, i;
    int err;

    if (f == NULL || data == NULL) {
        return INC_ERR_NULL;
    }
    if (!in_array(f, addr, len) || addr % unit != 0u || len % unit != 0u) {
        f->stats.failed++;
        return INC_ERR_INVAL;
    }
    err = enter(f, SIMFLASH_OP_PROGRAM);
    if (err) {
        return err;
    }
    f->stats.prog_calls++;
    for (u = 0; u < len; u += unit) {
        uint8_t *cell = &f->mem[addr + u];
        const uint8_t *src = &data[u];
        bool erased = true;

        for (i = 0; i < unit; i++) {
            erased = erased && cell[i] == 0xFFu;
        }
        if (!erased && f->reprogram == SIMFLASH_REPROGRAM_ERROR) {
            f->stats.failed++;
            return INC_ERR_IO;
        }
        if (step_is_cut(f)) {
            for (i = 0; i < unit; i++) {
                uint8_t clear = (uint8_t)(cell[i] & (uint8_t)~src[i] &
                                          (uint8_t)~stuck_bits(f, addr + u + i));
                if (f->cut_mode == SIMFLASH_CUT_TORN) {
                    clear &= (uint8_t)rng_next(f);
                } else if (f->cut_mode == SIMFLASH_CUT_BEFORE) {
                    clear = 0;
                }
                cell[i] &= (uint8_t)~clear;
            }
            power_fail(f);
            return INC_ERR_IO;
        }
        for (i = 0; i < unit; i++) {
            cell[i] &= (uint8_t)(src[i] | stuck_bits(f, addr + u + i));
        }
        if (!erased) {
            f->stats.reprograms++;
        }
        f->stats.prog_units++;
    }
    return INC_OK;
}

int simflash_erase(struct simflash *f, uint32_t addr)
{
    uint8_t *page;
    int err;

    if (f == NULL) {
        return INC_ERR_NULL;
    }
    if (addr % f->geo.page_size != 0u || addr >= f->size) {
        f->stats.failed++;
        return INC_ERR_INVAL;
    }
    err = enter(f, SIMFLASH_OP_ERASE);
    if (err) {
        return err;
    }
    page = &f->mem[addr];
    if (step_is_cut(f)) {
        if (f->cut_mode == SIMFLASH_CUT_AFTER) {
            memset(page, 0xFF, f->geo.page_size);
        } else if (f->cut_mode == SIMFLASH_CUT_TORN) {
            uint32_t i, progress = rng_next(f) & 0xFFu; /* share of bytes already erased, /256 */
            for (i = 0; i < f->geo.page_size; i++) {
                uint32_t r = rng_next(f);
                if ((r & 0xFFu) < progress) {
                    page[i] = 0xFFu;
                    continue;
                }
                switch ((r >> 8) & 3u) {
                case 0: break;                                              /* untouched */
                case 1: page[i] |= (uint8_t)((r >> 16) & (r >> 24)); break; /* a few bits up */
                case 2: page[i] = (uint8_t)(r >> 16); break;                /* garbage */
                default: page[i] |= (uint8_t)(r >> 16); break;              /* half erased */
                }
            }
        }
        power_fail(f);
        return INC_ERR_IO;
    }
    memset(page, 0xFF, f->geo.page_size);
    f->stats.erases++;
    return INC_OK;
}

static int op_read(void *ctx, uint32_t addr, uint8_t *buf, uint32_t len)
{
    return simflash_read((struct simflash *)ctx, addr, buf, len);
}

static int op_program(void *ctx, uint32_t addr, const uint8_t *buf, uint32_t len)
{
    return simflash_program((struct simflash *)ctx, addr, buf, len);
}

static int op_erase(void *ctx, uint32_t addr)
{
    return simflash_erase((struct simflash *)ctx, addr);
}

const struct calstore_flash_ops simflash_calstore_ops = {
    .read = op_read,
    .program = op_program,
    .erase = op_erase,
};

uint32_t simflash_steps(const struct simflash *f)
{
    return f != NULL ? f->steps : 0u;
}

int simflash_cut_power_at(struct simflash *f, uint32_t n, enum simflash_cut_mode mode,
                          uint32_t seed)
{
    if (f == NULL) {
        return INC_ERR_NULL;
    }
    if (n == 0u || n > UINT32_MAX - f->steps || (unsigned)mode > (unsigned)SIMFLASH_CUT_AFTER) {
        return INC_ERR_INVAL;
    }
    f->cut_at = f->steps + n;
    f->cut_mode = mode;
    f->rng = (seed != 0u) ? seed : 0x9E3779B9u; /* xorshift must not start at 0 */
    return INC_OK;
}

void simflash_power_on(struct simflash *f)
{
    if (f != NULL) {
        f->powered = true;
        f->cut_at = 0;
    }
}

bool simflash_powered(const struct simflash *f)
{
    return f != NULL && f->powered;
}

int simflash_fail_op(struct simflash *f, enum simflash_op op, uint32_t n)
{
    if (f == NULL) {
        return INC_ERR_NULL;
    }
    if ((unsigned)op > (unsigned)SIMFLASH_OP_ERASE || n == 0u || n > UINT32_MAX - f->op_calls[op]) {
        return INC_ERR_INVAL;
    }
    f->fail_at[op] = f->op_calls[op] + n;
    return INC_OK;
}

int simflash_set_stuck(struct simflash *f, uint32_t addr, uint8_t mask)
{
    if (f == NULL) {
        return INC_ERR_NULL;
    }
    if (addr >= f->size) {
        return INC_ERR_INVAL;
    }
    f->stuck = mask != 0u;
    f->stuck_addr = addr;
    f->stuck_mask = mask;
    return INC_OK;
}

int simflash_flip_bit(struct simflash *f, uint32_t addr, unsigned bit)
{
    if (f == NULL) {
        return INC_ERR_NULL;
    }
    if (addr >= f->size || bit > 7u) {
        return INC_ERR_INVAL;
    }
    f->mem[addr] ^= (uint8_t)(1u << bit);
    return INC_OK;
}

int simflash_poke(struct simflash *f, uint32_t addr, const uint8_t *data, uint32_t len)
{
    if (f == NULL || data == NULL) {
        return INC_ERR_NULL;
    }
    if (!in_array(f, addr, len)) {
        return INC_ERR_INVAL;
    }
    memcpy(&f->mem[addr], data, len);
    return INC_OK;
}

int simflash_peek(const struct simflash *f, uint32_t addr, uint8_t *buf, uint32_t len)
{
    if (f == NULL || buf == NULL) {
        return INC_ERR_NULL;
    }
    if (!in_array(f, addr, len)) {
        return INC_ERR_INVAL;
    }
    memcpy(buf, &f->mem[addr], len);
    return INC_OK;
}

const struct simflash_stats *simflash_get_stats(const struct simflash *f)
{
    return f != NULL ? &f->stats : NULL;
}

void simflash_reset_stats(struct simflash *f)
{
    if (f != NULL) {
        memset(&f->stats, 0, sizeof f->stats);
    }
}

int simflash_calstore_config(struct simflash *f, struct calstore_config *out)
{
    uint32_t slot;
    if (f == NULL || out == NULL) {
        return INC_ERR_NULL;
    }
    if (f->geo.page_count % 2u != 0u) {
        return INC_ERR_INVAL;
    }
    slot = f->geo.page_size * (f->geo.page_count / 2u);
    out->ops = &simflash_calstore_ops;
    out->ctx = f;
    out->page_size = f->geo.page_size;
    out->prog_size = f->geo.prog_size;
    out->erased_value = CALSTORE_ERASED;
    out->slot_addr[0] = 0u;
    out->slot_addr[1] = slot;
    out->slot_size = slot;
    return INC_OK;
}
