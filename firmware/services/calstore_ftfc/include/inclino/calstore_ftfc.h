/*
 * calstore_ftfc.h - the calibration store (calstore.h) on the S32K1 FlexNVM data flash.
 *
 * calstore_ftfc_ops fills struct calstore_flash_ops with the FTFC driver (s32k_ftfc.h); its ctx
 * is the struct s32k_ftfc. Addresses are D-flash offsets. Geometry: erase page = one 2 KiB
 * sector, program unit = one 8-byte phrase (the store never programs a phrase twice without an
 * erase, which the FTFC forbids). calstore_ftfc_config() puts the two slots in two consecutive
 * sectors starting at sector `first_sector` of the D-flash.
 */
#ifndef INCLINO_CALSTORE_FTFC_H
#define INCLINO_CALSTORE_FTFC_H

#include "inclino/calstore.h"
#include "inclino/s32k_ftfc.h"

#ifdef __cplusplus
extern "C" {
#endif

extern const struct calstore_flash_ops calstore_ftfc_ops;

/* The first D-flash sector the S32K1 images keep the record in (slot 0; slot 1 in the next):
 * boards/s32k1 (s32k_image_store) and the station's data-flash image (calstation dflash). */
#define CALSTORE_FTFC_IMAGE_SECTOR 0u

/*
 * A calstore configuration for an initialised FTFC driver: slot 0 in sector first_sector, slot
 * 1 in the next one. Returns 0, INC_ERR_NULL, INC_ERR_STATE (driver not ready) or
 * INC_ERR_NO_SPACE (the two sectors are not inside the partition's D-flash, or a slot cannot
 * hold the record).
 */
int calstore_ftfc_config(struct s32k_ftfc *f, uint32_t first_sector, struct calstore_config *out);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_CALSTORE_FTFC_H */
