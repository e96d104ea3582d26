/*
 * fixture.h - shared set-up for the calibration-storage tests: a known record, a flash
 * geometry table, and helpers to build a store over the emulated NOR flash.
 */
#ifndef INCLINO_TEST_CALSTORE_FIXTURE_H
#define INCLINO_TEST_CALSTORE_FIXTURE_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/calrec.h"
#include "inclino/calstore.h"
#include "inclino/simflash.h"

/* Largest emulated flash any calstore test uses (two slots). Static, so QEMU's RAM suffices. */
#define FIX_FLASH_MAX 2048u

struct fix_geometry {
    const char *name;
    uint32_t page_size;
    uint32_t prog_size;
    uint32_t slot_pages;
    enum simflash_reprogram reprogram;
};

/* A flash + store pair over a caller buffer; slot 0 at 0, slot 1 right after it. */
struct fix_store {
    struct simflash flash;
    struct calstore store;
    struct calstore_config cfg;
    uint32_t size; /* bytes of flash in use (both slots) */
};

/* The binding of the known record (an ADIS16364 with serial and lot numbers). */
void fix_binding(struct calrec_binding *b);

/* The known record of the golden-bytes test (every field distinct, every model kind used). */
void fix_record(struct calrec *r);

/* A valid record different for each variant (used as the k-th write of a sequence). */
void fix_record_variant(struct calrec *r, int variant);

/* Field-by-field equality, `valid` included. */
bool fix_record_equal(const struct calrec *a, const struct calrec *b);

/* True when r is exactly the safe default (calrec_set_default), valid == false. */
bool fix_record_is_default(const struct calrec *r);

/* Set up flash over mem (>= 2 * slot bytes) and the store for geometry g. 0 or an error. */
int fix_store_init(struct fix_store *fs, uint8_t *mem, uint32_t mem_size,
                   const struct fix_geometry *g);

/* Put a committed image of r with sequence seq into slot s through the back door. */
int fix_put_image(struct fix_store *fs, unsigned s, const uint8_t *img, uint32_t len);

/* Encode r with seq, then fix_put_image. */
int fix_put_record(struct fix_store *fs, unsigned s, const struct calrec *r, uint32_t seq);

/* Recompute the CRC of a version-2 image after a test patched it. */
void fix_reseal(uint8_t *img);

#endif /* INCLINO_TEST_CALSTORE_FIXTURE_H */
