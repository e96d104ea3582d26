/*
 * s32k_ftfc.h - the S32K1 flash controller (FTFC) on the FlexNVM data flash (D-flash).
 *
 * Facts ([S32K1XXRM], chapters "Flash Memory Module (FTFC)" and "SIM"; sizes from the
 * [S32K1XX-DS] memory tables; the unconfirmed ones in docs/unconfirmed-facts.md):
 *   - D-flash is read at 0x10000000 (FlexNVM); S32K144: 64 KiB FlexNVM, S32K116: 32 KiB; erase
 *     sector 2 KiB; program unit a phrase of 8 bytes (command 0x07 Program Phrase), erase
 *     command 0x09 Erase Flash Sector. In FCCOB a D-flash address is 0x800000 + offset.
 *   - Registers are 8-bit at 0x40020000: FSTAT (CCIF 0x80, RDCOLERR 0x40, ACCERR 0x20,
 *     FPVIOL 0x10, MGSTAT0 0x01), FCCOB0..B in big-endian byte order inside each 32-bit word
 *     (FCCOB3 at +4 ... FCCOB0 at +7, FCCOB7 at +8 ... FCCOB4 at +0xB, FCCOBB at +0xC ...
 *     FCCOB8 at +0xF), FDPROT at +0x17.
 *   - The FlexNVM split between D-flash and EEPROM backup is the partition code DEPART,
 *     SIM_FCFG1[15:12] (0x4004804C). DEPART = 0xF: the part was never partitioned.
 *
 * Partition policy: the driver never partitions the part (Program Partition can be done once,
 * and only an Erase All Blocks undoes it). At init it reads DEPART and derives the D-flash size
 * from the part's table; a part that was never partitioned (0xF) is refused with INC_ERR_STATE,
 * a code the table marks reserved, or one that leaves no D-flash, with INC_ERR_UNSUPPORTED. The
 * end-of-line station partitions the part once (all FlexNVM as D-flash: DEPART 0x0, no EEPROM)
 * before the calibration record is written (docs/calibration-storage.md).
 *
 * Command sequence (every command): wait for CCIF = 1 (a command still running after the poll
 * limit: INC_ERR_BUSY); clear ACCERR and FPVIOL by writing 1; load FCCOB0..; launch by writing
 * CCIF = 1; wait for CCIF = 1 (INC_ERR_TIMEOUT after the poll limit); then check, in order:
 *   ACCERR  -> INC_ERR_INVAL  (the controller refused the command: address, alignment, code)
 *   FPVIOL  -> INC_ERR_STATE  (the range is protected, FDPROT)
 *   MGSTAT0 -> INC_ERR_IO     (the array operation failed its verify)
 * Addresses are offsets into the D-flash; the driver checks range and alignment itself before
 * anything reaches the controller (INC_ERR_INVAL) and never relies on ACCERR for that.
 *
 * Code executing from P-flash may read P-flash while the FlexNVM is busy (separate blocks);
 * reading D-flash during a D-flash command is a read collision (RDCOLERR): the driver does not.
 */
#ifndef INCLINO_S32K_FTFC_H
#define INCLINO_S32K_FTFC_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "inclino/error.h"

#ifdef __cplusplus
extern "C" {
#endif

#define S32K_FTFC_BASE 0x40020000u
#define S32K_FTFC_REGION_SIZE 0x1000u
#define S32K_SIM_FCFG1 0x4004804Cu
#define S32K_DFLASH_BASE 0x10000000u
#define S32K_DFLASH_SECTOR 2048u
#define S32K_FTFC_PHRASE 8u
#define S32K144_FLEXNVM_SIZE 0x10000u       /* 64 KiB */
#define S32K116_FLEXNVM_SIZE 0x8000u        /* 32 KiB */
#define S32K_FTFC_DFLASH_CMD_ADDR 0x800000u /* FCCOB address of D-flash offset 0 */

/* Register offsets and bits. */
#define S32K_FTFC_FSTAT 0x00u
#define S32K_FTFC_FCNFG 0x01u
#define S32K_FTFC_FCCOB(n) (((n) & ~3u) + 4u + (3u - ((n)&3u))) /* FCCOB0..FCCOBB */
#define S32K_FTFC_FDPROT 0x17u
#define S32K_FTFC_FSTAT_CCIF 0x80u
#define S32K_FTFC_FSTAT_RDCOLERR 0x40u
#define S32K_FTFC_FSTAT_ACCERR 0x20u
#define S32K_FTFC_FSTAT_FPVIOL 0x10u
#define S32K_FTFC_FSTAT_MGSTAT0 0x01u
#define S32K_FTFC_CMD_PROGRAM_PHRASE 0x07u
#define S32K_FTFC_CMD_ERASE_SECTOR 0x09u
#define S32K_SIM_FCFG1_DEPART(v) (((v) >> 12) & 0xFu)
#define S32K_DEPART_UNPARTITIONED 0xFu

/* Status reads one wait may take (a bound, not a time: about 0.5 s at 112 MHz). */
#define S32K_FTFC_POLL_DEFAULT 20000000u

enum s32k_ftfc_part {
    S32K_FTFC_S32K144 = 0,
    S32K_FTFC_S32K116 = 1,
};

struct s32k_ftfc_cfg {
    enum s32k_ftfc_part part;
    uint32_t ftfc_base;   /* S32K_FTFC_BASE */
    uint32_t fcfg1_addr;  /* S32K_SIM_FCFG1 */
    uint32_t dflash_base; /* S32K_DFLASH_BASE (where D-flash is read) */
    uint32_t poll_limit;  /* 0: S32K_FTFC_POLL_DEFAULT */
};

struct s32k_ftfc_stats {
    uint32_t commands, erases, phrases;
    uint32_t accerr, fpviol, mgstat0, timeouts;
    uint8_t last_fstat; /* FSTAT after the last failed command */
};

struct s32k_ftfc {
    struct s32k_ftfc_cfg cfg;
    uint32_t dflash_size; /* bytes of D-flash the partition gives */
    uint8_t depart;
    bool ready;
    struct s32k_ftfc_stats stats;
};

/*
 * Read the partition and size the D-flash. Returns 0, INC_ERR_NULL, INC_ERR_INVAL (part),
 * INC_ERR_STATE (never partitioned), INC_ERR_UNSUPPORTED (reserved code or no D-flash).
 * Touches no flash.
 */
int s32k_ftfc_init(struct s32k_ftfc *f, const struct s32k_ftfc_cfg *cfg);

/* D-flash bytes for a partition code on a part, or 0 (reserved / none); 0xF reports the
 * whole FlexNVM (what it would be), the driver still refuses it. */
uint32_t s32k_ftfc_dflash_size(enum s32k_ftfc_part part, uint8_t depart);

/* Erase the 2 KiB sector at D-flash offset off (a multiple of S32K_DFLASH_SECTOR). */
int s32k_ftfc_erase_sector(struct s32k_ftfc *f, uint32_t off);

/* Program len bytes (multiple of 8, off a multiple of 8), one Program Phrase per 8 bytes, in
 * address order; stops at the first failing phrase. Every phrase must be erased. */
int s32k_ftfc_program(struct s32k_ftfc *f, uint32_t off, const uint8_t *buf, uint32_t len);

/* Copy len bytes at D-flash offset off (any alignment) into buf. */
int s32k_ftfc_read(struct s32k_ftfc *f, uint32_t off, uint8_t *buf, uint32_t len);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_S32K_FTFC_H */
