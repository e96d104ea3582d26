/*
 * simflash.h - emulated NOR flash for tests: erase/program semantics, power cuts, corruption.
 *
 * Semantics (those of NOR flash in microcontrollers and serial NOR parts):
 *   - The array is page_count pages of page_size bytes; an erased byte reads 0xFF.
 *   - erase(addr) sets a whole page to 0xFF; addr must be the start of a page. One STEP.
 *   - program(addr, data, len): addr and len multiples of prog_size. Programming can only clear
 *     bits (1 -> 0). Each program unit of prog_size bytes is one STEP, done in address order.
 *   - Programming a unit that is not fully erased (a "reprogram"):
 *       SIMFLASH_REPROGRAM_AND (default): the cells are ANDed with the data, as the NOR array
 *         physically does (bits already 0 stay 0). Counted in stats.reprograms so a test can
 *         prove the code under test never relies on it.
 *       SIMFLASH_REPROGRAM_ERROR: refused with INC_ERR_IO, unit unchanged, as MCU flash
 *         controllers with per-unit ECC (or a program-error flag) do.
 *   - read has no steps and never changes the array.
 *
 * Power cuts: simflash_cut_power_at(f, n, mode, seed) makes the n-th program/erase step from
 * now the interrupted one. That step is left in a defined state chosen by mode:
 *   SIMFLASH_CUT_BEFORE  the step had no effect;
 *   SIMFLASH_CUT_TORN    partial effect, pseudo-random from seed (deterministic per seed):
 *                        program: each bit the step would clear is cleared or not;
 *                        erase: a random fraction of the page's bytes is erased, the others
 *                        are left as they were, partly erased (bits set) or random garbage;
 *   SIMFLASH_CUT_AFTER   the step completed, power failed right after it.
 * The interrupted call returns INC_ERR_IO (units before it in the same call are programmed),
 * and every later read, program or erase fails with INC_ERR_IO, changing nothing, until
 * simflash_power_on(): that is the "reboot".
 *
 * Other faults: single bit flips and raw writes through a back door (ignore power and
 * semantics), an I/O error injected on the n-th call of one operation, and one stuck-at-1
 * location (bits that never program, while program still reports success: tests the
 * read-back verification of the code under test).
 *
 * The caller owns the struct and the array memory (no heap). Addresses are offsets from the
 * start of the array.
 */
#ifndef INCLINO_SIMFLASH_H
#define INCLINO_SIMFLASH_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "inclino/calstore.h"
#include "inclino/error.h"

#ifdef __cplusplus
extern "C" {
#endif

struct simflash_geometry {
    uint32_t page_size;  /* erase page, bytes, > 0, a multiple of prog_size */
    uint32_t page_count; /* > 0; page_size * page_count must fit in uint32_t */
    uint32_t prog_size;  /* program unit, bytes, > 0 */
};

enum simflash_reprogram {
    SIMFLASH_REPROGRAM_AND = 0,
    SIMFLASH_REPROGRAM_ERROR = 1,
};

enum simflash_cut_mode {
    SIMFLASH_CUT_BEFORE = 0,
    SIMFLASH_CUT_TORN = 1,
    SIMFLASH_CUT_AFTER = 2,
};

enum simflash_op {
    SIMFLASH_OP_READ = 0,
    SIMFLASH_OP_PROGRAM = 1,
    SIMFLASH_OP_ERASE = 2,
};

/* Counters since init or simflash_reset_stats(). Steps that were cut are not counted as done. */
struct simflash_stats {
    uint32_t erases;     /* completed page erases */
    uint32_t prog_units; /* completed program units */
    uint32_t prog_calls; /* program calls accepted */
    uint32_t read_calls; /* read calls served */
    uint32_t read_bytes; /* bytes read */
    uint32_t reprograms; /* program units that were not fully erased beforehand */
    uint32_t failed;     /* calls that returned an error (power off, bad args, injected) */
};

/* State. Fields are private to simflash.c; use the functions. */
struct simflash {
    uint8_t *mem;
    uint32_t size;
    struct simflash_geometry geo;
    enum simflash_reprogram reprogram;
    bool powered;
    uint32_t steps;  /* program/erase steps begun since init */
    uint32_t cut_at; /* step number that is interrupted; 0 = none armed */
    enum simflash_cut_mode cut_mode;
    uint32_t rng;
    uint32_t op_calls[3]; /* calls per enum simflash_op since init */
    uint32_t fail_at[3];  /* op_calls value that fails with INC_ERR_IO; 0 = none */
    bool stuck;
    uint32_t stuck_addr;
    uint8_t stuck_mask;
    struct simflash_stats stats;
};

/*
 * Set up f over mem (at least page_size * page_count bytes) and erase it all (factory state:
 * 0xFF), powered, no faults armed. INC_ERR_NULL; INC_ERR_INVAL for a bad geometry or mem_size.
 */
int simflash_init(struct simflash *f, uint8_t *mem, size_t mem_size,
                  const struct simflash_geometry *geo);

/* Choose the reprogram behaviour (see above). */
void simflash_set_reprogram(struct simflash *f, enum simflash_reprogram mode);

/* The three flash operations (see the semantics above). 0, INC_ERR_NULL, INC_ERR_INVAL
 * (alignment, range), INC_ERR_IO (power off, cut, injected error, refused reprogram). */
int simflash_read(struct simflash *f, uint32_t addr, uint8_t *buf, uint32_t len);
int simflash_program(struct simflash *f, uint32_t addr, const uint8_t *data, uint32_t len);
int simflash_erase(struct simflash *f, uint32_t addr);

/* The same operations as a calstore flash driver; ctx is the struct simflash. */
extern const struct calstore_flash_ops simflash_calstore_ops;

/* A calibration store's configuration on all of f (initialised): two slots of half its pages
 * each, slot 0 first, with f's page and program sizes and simflash_calstore_ops. INC_ERR_NULL;
 * INC_ERR_INVAL when f's page count is odd. */
int simflash_calstore_config(struct simflash *f, struct calstore_config *out);

/* ---- Power ------------------------------------------------------------------------------- */

/* Program/erase steps begun since init (a cut step counts as begun). */
uint32_t simflash_steps(const struct simflash *f);

/* Arm a cut on the n-th step from now (n >= 1), else INC_ERR_INVAL. seed drives CUT_TORN. */
int simflash_cut_power_at(struct simflash *f, uint32_t n, enum simflash_cut_mode mode,
                          uint32_t seed);

/* Power returns (a reboot): operations work again; any armed cut is disarmed. */
void simflash_power_on(struct simflash *f);

/* False from the moment a cut happened until simflash_power_on(). */
bool simflash_powered(const struct simflash *f);

/* ---- Other faults and back door ---------------------------------------------------------- */

/* The n-th call (n >= 1) from now of op fails with INC_ERR_IO and changes nothing. */
int simflash_fail_op(struct simflash *f, enum simflash_op op, uint32_t n);

/* Bits of mask at addr never program (stay 1) from now on; program still returns 0. One
 * location at a time; mask 0 removes it. */
int simflash_set_stuck(struct simflash *f, uint32_t addr, uint8_t mask);

/* Invert bit (0..7) of the byte at addr: a retention error / cosmic ray. */
int simflash_flip_bit(struct simflash *f, uint32_t addr, unsigned bit);

/* Raw copy into / out of the array, ignoring power and NOR semantics (test set-up). */
int simflash_poke(struct simflash *f, uint32_t addr, const uint8_t *data, uint32_t len);
int simflash_peek(const struct simflash *f, uint32_t addr, uint8_t *buf, uint32_t len);

const struct simflash_stats *simflash_get_stats(const struct simflash *f);
void simflash_reset_stats(struct simflash *f);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_SIMFLASH_H */
