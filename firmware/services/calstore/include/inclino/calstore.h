/*
 * calstore.h - power-safe calibration storage in two flash slots.
 *
 * The record (inclino/calrec.h) is kept in two slots, each on its own erase page(s). A save
 * never touches the slot holding the newest valid record: it erases the other slot, programs
 * the new image (with a sequence number one above the kept record's, and its CRC-32), reads it
 * back, and only then programs a separate commit word after the image. A load accepts a slot
 * only when its commit word, CRC, version, binding and ranges are all right, and takes the
 * newer of the accepted slots (sequence numbers compared modulo 2^32). So a power cut at any
 * point of a save leaves the old record or, after the commit word is complete, the new one;
 * never a mixture. The argument, cut point by cut point, is in docs/calibration-storage.md.
 *
 * Flash is reached only through struct calstore_flash_ops plus a context pointer, in the style
 * of the HAL (inclino/hal.h): a real MCU's flash driver fills the table, the tests use the NOR
 * emulation of sim/flash. Nothing here allocates; the caller owns struct calstore (about
 * 700 bytes, most of it the image buffer; see docs/benchmarks.md).
 *
 * Status codes of calstore_load (the caller runs UNCALIBRATED on any non-zero code; the output
 * record is then the safe default of calrec_set_default, valid == false):
 *   INC_OK                  a valid record was loaded (out->valid == true)
 *   INC_ERR_NOT_CALIBRATED  both slots erased: the part was never calibrated
 *   INC_ERR_CRC             no intact record: torn or corrupted (bad magic, commit word or CRC)
 *   INC_ERR_VERSION         the newest intact record has a format version this firmware lacks
 *   INC_ERR_MISMATCH        the newest intact record belongs to another sensor part
 *   INC_ERR_RANGE           the newest intact record has a coefficient outside its limits
 *   INC_ERR_IO              the flash driver failed
 *   INC_ERR_NULL / INC_ERR_INVAL / INC_ERR_STATE   bad arguments or store not initialised
 */
#ifndef INCLINO_CALSTORE_H
#define INCLINO_CALSTORE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "inclino/calrec.h"
#include "inclino/error.h"

#ifdef __cplusplus
extern "C" {
#endif

/*
 * The flash driver. Addresses are byte addresses in the driver's own address space (an offset
 * into the flash, or an absolute address; the store only adds offsets to the slot addresses).
 * Every function returns 0 or a negative inc_err code (INC_ERR_IO for a device failure); on
 * failure the store stops and reports the error.
 */
struct calstore_flash_ops {
    /* Copy len bytes at addr into buf. Any address and length inside the flash. */
    int (*read)(void *ctx, uint32_t addr, uint8_t *buf, uint32_t len);
    /*
     * Program len bytes from buf at addr. addr and len are multiples of prog_size and the range
     * lies in one slot; every program unit written was erased since it was last programmed
     * (the store never programs a unit twice, so ECC flash that forbids it works). The driver
     * splits the request as its hardware needs and returns only when the data is programmed.
     */
    int (*program)(void *ctx, uint32_t addr, const uint8_t *buf, uint32_t len);
    /* Erase the page that starts at addr (addr is a multiple of page_size). */
    int (*erase)(void *ctx, uint32_t addr);
};

#define CALSTORE_PROG_MAX 32u /* largest supported program granularity, bytes */
#define CALSTORE_SLOT_MAX \
    0x01000000u               /* largest slot, bytes (16 MiB; keeps offsets far from overflow) */
#define CALSTORE_ERASED 0xFFu /* the only supported erased byte value (NOR flash) */
#define CALSTORE_COMMIT 0xC0A1E5CAu /* commit word: the slot's save completed */

/* Configuration, copied into the store by calstore_init. */
struct calstore_config {
    const struct calstore_flash_ops *ops;
    void *ctx;             /* passed back to every ops call */
    uint32_t page_size;    /* erase page, bytes; a multiple of prog_size */
    uint32_t prog_size;    /* program granularity, bytes: a power of two, 1..CALSTORE_PROG_MAX */
    uint8_t erased_value;  /* value of an erased byte; must be CALSTORE_ERASED */
    uint32_t slot_addr[2]; /* first byte of each slot, multiples of page_size */
    uint32_t slot_size;    /* bytes per slot: a multiple of page_size, at least
                                 calstore_slot_min_size(prog_size, page_size), at most
                                 CALSTORE_SLOT_MAX; the two slots must not overlap */
};

/* The store's state: caller-allocated, fixed size. Fields are private to calstore.c. */
struct calstore {
    struct calstore_config cfg;
    uint32_t commit_off; /* offset of the commit unit in a slot for a version-2 image */
    uint32_t init_magic; /* set by calstore_init; guards use of an uninitialised store */
    uint8_t buf[CALREC_IMAGE_SIZE + CALSTORE_PROG_MAX]; /* image buffer (padded to prog_size) */
};

/* Result of one slot as judged by calstore_load / calstore_save. */
struct calstore_slot_info {
    int status;   /* INC_OK (valid), or the load status codes listed above */
    bool intact;  /* committed and CRC-correct (any version, any binding) */
    uint32_t seq; /* its sequence number when intact, else 0 */
};

/* What a load or save saw and did (optional output). */
struct calstore_info {
    struct calstore_slot_info slot[2];
    int used_slot; /* load: slot the record came from; save: slot written; -1 none */
    uint32_t seq;  /* sequence number of that record */
};

/*
 * Smallest slot_size for a geometry: the version-2 image rounded up to prog_size, plus one
 * commit unit of max(prog_size, 4) bytes, rounded up to whole pages. 0 for an invalid geometry.
 */
uint32_t calstore_slot_min_size(uint32_t prog_size, uint32_t page_size);

/*
 * Check cfg and set up st. INC_ERR_NULL (st, cfg, cfg->ops or an ops function NULL);
 * INC_ERR_INVAL (geometry as documented in struct calstore_config violated);
 * INC_ERR_UNSUPPORTED (erased_value != CALSTORE_ERASED). Touches no flash.
 */
int calstore_init(struct calstore *st, const struct calstore_config *cfg);

/*
 * Load the calibration of the part identified by *expect (read from the part at boot).
 * *out always receives either a valid record (return 0, out->valid true) or the safe default
 * (non-zero return, out->valid false); see the status list at the top. info may be NULL.
 * Reads flash only.
 */
int calstore_load(struct calstore *st, const struct calrec_binding *expect, struct calrec *out,
                  struct calstore_info *info);

/*
 * Store rec (bound to the part in rec->binding) as the newest record. Refuses before touching
 * flash: INC_ERR_NULL, INC_ERR_STATE, INC_ERR_INVAL (binding), INC_ERR_RANGE (coefficients).
 * Otherwise erases and programs the slot that does not hold the newest record valid for
 * rec->binding (slot 0 when neither slot holds an intact record), with a sequence number one
 * above the kept slot's, and returns 0 once the commit word is programmed and read back.
 * INC_ERR_IO: the driver failed or the read-back differed; the previous record is still in
 * place and calstore_load returns it (unless the failure hit the commit word itself, in which
 * case a load returns either the old or the new record; reload to know which).
 * info may be NULL; on success info->used_slot / info->seq describe the written record.
 */
int calstore_save(struct calstore *st, const struct calrec *rec, struct calstore_info *info);

/*
 * True when sequence number a is newer than b: (a - b) mod 2^32 lies in [1, 2^31 - 1] (serial
 * number arithmetic). Equal numbers and numbers exactly 2^31 apart are not newer either way;
 * the store then prefers slot 0. The store only ever writes kept + 1, so it never creates that
 * case itself.
 */
bool calstore_seq_newer(uint32_t a, uint32_t b);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_CALSTORE_H */
