/*
 * calrec_ref.h - the reference (pre-table) calibration record codec, see calrec_ref.c. Same
 * contracts as the functions of inclino/calrec.h without the ref_ prefix.
 */
#ifndef INCLINO_TEST_CALSTORE_CALREC_REF_H
#define INCLINO_TEST_CALSTORE_CALREC_REF_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "inclino/calrec.h"

void ref_calrec_set_default(struct calrec *rec);
int ref_calrec_check_binding(const struct calrec_binding *b);
bool ref_calrec_binding_equal(const struct calrec_binding *a, const struct calrec_binding *b);
int ref_calrec_check(const struct calrec *rec);
int ref_calrec_encode(const struct calrec *rec, uint32_t seq, uint8_t *img, size_t cap);
int ref_calrec_check_image(const uint8_t *img, size_t len, const struct calrec_binding *expect);
int ref_calrec_decode(const uint8_t *img, size_t len, const struct calrec_binding *expect,
                      struct calrec *out, uint32_t *seq);
uint32_t ref_calrec_get_le32(const uint8_t *p);
void ref_calrec_put_le32(uint8_t *p, uint32_t v);

#endif /* INCLINO_TEST_CALSTORE_CALREC_REF_H */
