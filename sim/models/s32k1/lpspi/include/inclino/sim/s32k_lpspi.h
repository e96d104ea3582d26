/*
 * sim/s32k_lpspi.h - register-level model of one S32K1 LPSPI instance (master mode).
 *
 * Mapped into the simulated S32K1 bus (s32k_bus.h) at its base address, it keeps the registers
 * of spi_lpspi_regs.h, a TX FIFO of commands and data and an RX FIFO, and shifts frames out on
 * the simulated pin bus (sim/pinbus.h) in virtual time, one scheduled event per pin change:
 *
 *   PCS assert -> first SCK edge      (PCSSCK + 1) counts
 *   leading -> trailing edge          floor((SCKDIV + 2) / 2) counts, trailing -> leading the rest
 *   last edge -> PCS negate           (SCKPCS + 1) counts
 *   PCS negate -> next PCS assert     >= (DBT + 2) counts
 *   continuous (TCR CONT): last edge of a word -> first edge of the next  (DBT + 1) counts
 *
 * with one count = 2^PRESCALE / fclk, each delay rounded up to whole ns. CPHA = 0: SOUT is set at
 * PCS assert and at each trailing edge, SIN sampled at the leading edge; CPHA = 1: SOUT set at
 * the leading edge, SIN sampled at the trailing edge (CFGR1 SAMPLE = 0). SCK moves to the idle
 * level of a command when the command is loaded with every PCS negated. PCS lines are active low
 * (CFGR1 PCSPOL = 0, the only polarity modelled). Only what the engine uses is modelled: 1-bit
 * width, MSB first, frames of 1..16 bits (wider: counted in bad_commands and not sent).
 *
 * Status: TDF = TXCOUNT <= TXWATER, RDF = RXCOUNT > RXWATER, MBF while a frame runs or a PCS is
 * asserted; WCF at each word's end, FCF at each PCS negation, TCF at a PCS negation with the TX
 * FIFO empty; TEF when a word is written into a full TX FIFO (dropped), REF when a received word
 * finds the RX FIFO full (dropped). CCR and CFGR1 written while CR MEN = 1 are ignored and
 * counted (locked_writes), as they must only be written with the module disabled.
 *
 * Interrupt: when cfg.core is set, the model raises cfg.irq in that core's NVIC
 * (sim_s32k_core_raise) whenever a flag enabled in IER is set after a register access or a
 * shifter event (a level that stays high is raised again on every change, as the NVIC re-pends
 * a peripheral line that is still asserted).
 *
 * Faults for the tests: force_tef / force_ref set the flag at the next word; stall_engine stops
 * the shifter (the module stays busy, nothing moves: the driver must time out).
 */
#ifndef INCLINO_SIM_S32K_LPSPI_H
#define INCLINO_SIM_S32K_LPSPI_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/error.h"
#include "inclino/sim/clock.h"
#include "inclino/sim/pinbus.h"
#include "inclino/sim/s32k_core.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SIM_LPSPI_FIFO 4u /* words in each FIFO of the S32K1 LPSPI */
#define SIM_LPSPI_PCS 4u  /* PCS0..PCS3 */
#define SIM_LPSPI_NO_PIN 0xFFu

struct sim_s32k_lpspi_cfg {
    uint32_t base; /* LPSPI0_BASE, ... */
    uint32_t fclk_hz;
    struct sim_clock *clk;
    struct sim_pinbus *bus;
    unsigned sck, sout, sin;
    unsigned pcs[SIM_LPSPI_PCS]; /* pin of PCSk, or SIM_LPSPI_NO_PIN */
    struct sim_s32k_core *core;  /* the interrupt goes to this core's NVIC (NULL: none) */
    unsigned irq;                /* its IRQ number (S32K1_IRQ_LPSPI0) */
};

enum sim_lpspi_phase {
    SIM_LPSPI_IDLE = 0, /* PCS negated, nothing scheduled */
    SIM_LPSPI_ASSERT,   /* waiting to assert PCS */
    SIM_LPSPI_LEAD,     /* waiting for a leading edge */
    SIM_LPSPI_TRAIL,    /* waiting for a trailing edge */
    SIM_LPSPI_HOLDING,  /* continuous transfer: PCS asserted, waiting for the next word */
    SIM_LPSPI_NEGATE,   /* waiting to negate PCS */
};

struct sim_s32k_lpspi {
    struct sim_s32k_lpspi_cfg cfg;
    /* registers */
    uint32_t cr, sr_w1c, ier, der, cfgr0, cfgr1, ccr, fcr, dmr0, dmr1;
    uint32_t tcr; /* the command in effect */
    struct {
        uint32_t v;
        bool cmd;
    } txf[SIM_LPSPI_FIFO];
    unsigned tx_head, tx_len;
    uint32_t rxf[SIM_LPSPI_FIFO];
    unsigned rx_head, rx_len;
    /* shifter */
    enum sim_lpspi_phase phase;
    int event;        /* pending event handle, 0 when none */
    unsigned pcs_on;  /* asserted PCS index, or SIM_LPSPI_PCS when none */
    uint16_t out, in; /* the word shifting out and in */
    unsigned bit;     /* bits left of the current word */
    unsigned bits;    /* frame size of the current word */
    uint64_t t_negate, t_last_edge;
    bool negated_once;
    /* faults */
    bool force_tef, force_ref, stall_engine;
    /* statistics */
    uint32_t frames, words, locked_writes, bad_commands;
    uint32_t irqs;                          /* times the interrupt was raised */
    uint64_t t_first_assert, t_last_negate; /* bus time: first PCS fall, latest PCS rise */
};

/* Reset state, map into the S32K1 bus at cfg->base. Returns 0 or the bus's error. */
int sim_s32k_lpspi_init(struct sim_s32k_lpspi *m, const struct sim_s32k_lpspi_cfg *cfg);

/* The value PARAM reads: TXFIFO = RXFIFO = log2(SIM_LPSPI_FIFO), PCSNUM = SIM_LPSPI_PCS. */
uint32_t sim_s32k_lpspi_param(void);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_SIM_S32K_LPSPI_H */
