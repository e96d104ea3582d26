/*
 * calstore_ref.h - the reference (pre-size-work) two-slot store, see calstore_ref.c. Same
 * contracts as the functions of inclino/calstore.h without the ref_ prefix.
 */
#ifndef INCLINO_TEST_CALSTORE_CALSTORE_REF_H
#define INCLINO_TEST_CALSTORE_CALSTORE_REF_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/calstore.h"

bool ref_calstore_seq_newer(uint32_t a, uint32_t b);
uint32_t ref_calstore_slot_min_size(uint32_t prog_size, uint32_t page_size);
int ref_calstore_init(struct calstore *st, const struct calstore_config *cfg);
int ref_calstore_load(struct calstore *st, const struct calrec_binding *expect, struct calrec *out,
                      struct calstore_info *info);
int ref_calstore_save(struct calstore *st, const struct calrec *rec, struct calstore_info *info);

#endif /* INCLINO_TEST_CALSTORE_CALSTORE_REF_H */
