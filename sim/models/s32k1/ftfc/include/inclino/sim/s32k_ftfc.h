/*
 * sim/s32k_ftfc.h - register-level model of the S32K1 FTFC and its FlexNVM data flash.
 *
 * Mapped into the simulated S32K1 bus (s32k_bus.h): the FTFC registers at S32K_FTFC_BASE
 * (8-bit FSTAT, FCNFG, FCCOB0..B in the byte order of s32k_ftfc.h, FDPROT), the D-flash array
 * at S32K_DFLASH_BASE (read with any width, writes ignored and counted) and, unless
 * cfg.map_fcfg1 is false (a SIM model of the port serves it), SIM_FCFG1 with the partition code.
 *
 * The array is NOR: erased bytes read 0xFF, Erase Flash Sector (0x09) sets a 2 KiB sector to
 * 0xFF, Program Phrase (0x07) clears bits of one 8-byte phrase. A phrase that is not fully
 * erased is not programmed: MGSTAT0 is set and the phrase is unchanged (counted in
 * reprograms), the part's rule that a phrase is programmed once per erase. Launch (writing
 * CCIF = 1 while CCIF = 1 and ACCERR = FPVIOL = 0) checks the command: an unknown code, a
 * P-flash address (bit 23 clear: not modelled), an address outside the partition's D-flash or
 * misaligned sets ACCERR and does nothing; a protected range (FDPROT bit = 0, eight equal
 * regions) sets FPVIOL. Otherwise CCIF reads 0 for erase_ns or program_ns of virtual time,
 * then the effect happens and CCIF returns to 1. FCCOB writes while CCIF = 0 are ignored and
 * counted, a D-flash read while CCIF = 0 sets RDCOLERR.
 *
 * Power cuts (the semantics of sim/flash, simflash.h): sim_s32k_ftfc_cut_power_at(m, n, mode,
 * seed) makes the n-th program/erase command from now the interrupted one; it ends in the
 * state mode gives (BEFORE: no effect, TORN: some bits / bytes, pseudo-random per seed, AFTER:
 * done), completes with MGSTAT0 (the driver returns INC_ERR_IO), and every later command
 * completes with MGSTAT0 and no effect until sim_s32k_ftfc_power_on() (the reboot). The array
 * keeps its contents across the cut, as flash does.
 */
#ifndef INCLINO_SIM_S32K_FTFC_MODEL_H
#define INCLINO_SIM_S32K_FTFC_MODEL_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/error.h"
#include "inclino/s32k_ftfc.h"
#include "inclino/sim/clock.h"
#include "inclino/simflash.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Modelled command times (typical figures of the data sheet are in docs/unconfirmed-facts.md;
 * the tests may shorten them). */
#define SIM_FTFC_ERASE_NS_DEFAULT 1000000u /* sector erase */
#define SIM_FTFC_PROGRAM_NS_DEFAULT 60000u /* phrase program */

struct sim_s32k_ftfc_cfg {
    enum s32k_ftfc_part part; /* FlexNVM size: 64 KiB (S32K144) or 32 KiB (S32K116) */
    uint8_t depart;           /* SIM_FCFG1 DEPART the model reports (0xF: never partitioned) */
    struct sim_clock *clk;
    uint32_t erase_ns, program_ns; /* 0: the defaults */
    bool map_fcfg1;
};

struct sim_s32k_ftfc_stats {
    uint32_t launches, erases, phrases, accerr, fpviol, reprograms;
    uint32_t locked_writes, array_writes, read_collisions, failed_off;
};

struct sim_s32k_ftfc {
    struct sim_s32k_ftfc_cfg cfg;
    uint32_t flexnvm_size, dflash_size;
    uint8_t fstat, fcnfg, fdprot;
    uint8_t fccob[12];
    uint8_t mem[S32K144_FLEXNVM_SIZE];
    /* the command in flight */
    uint8_t cmd;
    uint32_t off;
    uint8_t data[S32K_FTFC_PHRASE];
    int event;
    /* power */
    bool powered;
    uint32_t steps, cut_at;
    enum simflash_cut_mode cut_mode;
    uint32_t rng;
    struct sim_s32k_ftfc_stats stats;
};

/* Erase the whole array (factory state), reset the registers, map the regions. */
int sim_s32k_ftfc_init(struct sim_s32k_ftfc *m, const struct sim_s32k_ftfc_cfg *cfg);

void sim_s32k_ftfc_cut_power_at(struct sim_s32k_ftfc *m, uint32_t n, enum simflash_cut_mode mode,
                                uint32_t seed);
/* Power back on (reboot): registers reset, array kept, no cut armed. */
void sim_s32k_ftfc_power_on(struct sim_s32k_ftfc *m);
bool sim_s32k_ftfc_powered(const struct sim_s32k_ftfc *m);
/* Program/erase commands launched since init (the steps a cut can hit). */
uint32_t sim_s32k_ftfc_steps(const struct sim_s32k_ftfc *m);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_SIM_S32K_FTFC_MODEL_H */
