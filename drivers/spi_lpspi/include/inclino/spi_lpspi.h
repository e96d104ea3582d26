/*
 * spi_lpspi.h - the S32K1 LPSPI as an SPI engine behind struct spi_bus (spi.h).
 *
 * A sensor driver cannot tell it from the bit-banged engine: the same devices, modes, frame sizes
 * and struct spi_timing minima, the same two CS policies. Every register is reached through
 * inclino/s32k_mmio.h ([S32K1XXRM], LPSPI chapter; map in spi_lpspi_regs.h).
 *
 * Configuration. The engine is an LPSPI instance in master mode whose PCS0..PCS3 outputs are
 * muxed to the chip-select pins of the board; cfg.pcs_pin[k] names the hal_pin_t a device's
 * spi_dev_cfg.cs must use to be served by PCSk (HAL_PIN_NONE: PCSk not wired). A device whose CS
 * is not in that map is refused at attach (INC_ERR_INVAL). PCS lines are active low.
 *
 * Timing mapping (per transfer, recomputed when a device or its timing differs from the last
 * one programmed): with the functional clock f (cfg.fclk_hz, from the PCC) and a prescaler 2^p
 * (TCR PRESCALE), one count is c = 2^p / f. For the device's period P, setup S, hold H, stall T
 * and gap G the engine picks the smallest p for which every count fits its 8-bit field:
 *   SCK period   (SCKDIV + 2) c >= P, and each half floor((SCKDIV + 2) / 2) c >= ceil(P / 2);
 *   PCS -> SCK   (PCSSCK + 1) c >= S;           SCK -> PCS (SCKPCS + 1) c >= H;
 *   SPI_CS_TOGGLE: PCS high between frames  (DBT + 2) c >= T;
 *   SPI_CS_HOLD:   last edge -> next first edge in the continuous transfer
 *                                            (DBT + 1) c >= max(G, ceil(P / 2)).
 * Every count is rounded up, so every interval is at least what the device asked for, never
 * shorter. When no prescaler fits (a stall or period longer than 257 x 128 counts) the transfer
 * fails with INC_ERR_TIMING and nothing reaches the bus. Between transfers to one device the
 * stall T is kept in software (hal_delay_until from the time the engine saw the frame end).
 * CCR is written with the module disabled (MEN = 0), so a device change costs a disable/enable.
 * When the SCK idle level (CPOL) changes, the engine loads the command and waits half a period
 * with every PCS negated before the first frame, as the bit-banged engine does.
 *
 * FIFO, no DMA: the CPU keeps the TX FIFO filled (never more words in flight than the RX FIFO
 * holds, read from PARAM, so RX cannot overflow). SPI_CS_HOLD is one continuous transfer (TCR
 * CONT) ended by a command with CONT = 0. How the CPU waits for the words in flight:
 *   cfg.irq_wait false  it polls FSR/SR (watermarks 0): busy for the whole bus time;
 *   cfg.irq_wait true   it sets the RX watermark to the words in flight (RDF when they are
 *                       all in), enables RDIE/TEIE/REIE and sleeps in hal_irq_wait (the port's
 *                       WFI) until the deadline of the wait; the board's LPSPI interrupt
 *                       handler calls spi_lpspi_isr (which disables the enables again) and wakes
 *                       the HAL (s32k_hal_wake). With a 4-word FIFO a 13-word ADIS burst is
 *                       4 sleeps; the CPU runs only to refill the FIFO. Any other interrupt
 *                       (a data-ready edge) only makes the engine look again. The last wait of
 *                       a transfer (PCS negated, SCK->PCS delay: a few counts) polls.
 *
 * Errors (the module is reset and re-programmed on the next transfer; rx must not be used):
 *   INC_ERR_TIMING   the timing does not fit the LPSPI counters at this clock;
 *   INC_ERR_BUSY     the module was still busy (SR MBF) before a transfer started;
 *   INC_ERR_BUS      SR TEF (TX FIFO underrun) or REF (RX FIFO overflow) was set;
 *   INC_ERR_TIMEOUT  the words and the end of the transfer (PCS negated) did not all come
 *                    within twice the expected bus time of n + 1 words + cfg.timeout_ns
 *                    (or SPI_LPSPI_POLL_LIMIT status reads or sleeps without
 *                    progress); polls read the clock every SPI_LPSPI_CLOCK_EVERY-th time, so a
 *                    timeout is seen up to that many status reads after its deadline;
 *   INC_ERR_UNSUPPORTED  PARAM reports a FIFO or PCS count this engine cannot use (init).
 */
#ifndef INCLINO_SPI_LPSPI_H
#define INCLINO_SPI_LPSPI_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/hal.h"
#include "inclino/spi.h"
#include "inclino/spi_lpspi_regs.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SPI_LPSPI_PCS_COUNT 4u
/* Status reads one wait may take before it is a timeout (a bound when no clock runs). */
#define SPI_LPSPI_POLL_LIMIT 200000u
/* Polls between two clock reads of a polling wait (the deadline check). */
#define SPI_LPSPI_CLOCK_EVERY 8u
/* Extra time over the expected bus time before a wait times out (cfg.timeout_ns == 0). */
#define SPI_LPSPI_TIMEOUT_DEFAULT_NS 100000u

struct spi_lpspi_cfg {
    const struct hal *hal; /* time: the stall between transfers, timeouts */
    uint32_t base;         /* LPSPI0_BASE, ... */
    uint32_t fclk_hz;      /* the LPSPI functional clock (PCC PCS selection), > 0 */
    hal_pin_t pcs_pin[SPI_LPSPI_PCS_COUNT]; /* the CS pin PCSk drives, or HAL_PIN_NONE */
    uint32_t timeout_ns;                    /* 0: SPI_LPSPI_TIMEOUT_DEFAULT_NS */
    bool irq_wait; /* sleep on the LPSPI interrupt instead of polling (see above) */
};

/* The register fields one device's timing maps to (see the mapping above). */
struct spi_lpspi_clock {
    uint8_t prescale; /* TCR PRESCALE: count = 2^prescale / fclk */
    uint8_t sckdiv, dbt, pcssck, sckpcs;
};

struct spi_lpspi_stats {
    uint32_t reconfigs;     /* CCR written (device or timing changed) */
    uint32_t errors;        /* transfers that failed */
    uint32_t last_sr;       /* SR at the last error */
    uint32_t max_in_flight; /* most words in the FIFOs at once */
    uint32_t sleeps;        /* hal_irq_wait calls (cfg.irq_wait) */
};

struct spi_lpspi {
    struct spi_lpspi_cfg cfg;
    struct spi_bus bus;  /* the interface this engine serves; pass &lp.bus to spi_dev_init */
    unsigned fifo_words; /* min(TX, RX) FIFO depth read from PARAM */
    bool programmed;     /* ccr holds what CCR has */
    uint32_t ccr;
    bool cpol_known;
    bool cpol;
    bool released_any;
    hal_pin_t last_cs;
    uint64_t last_release_ns;
    /* the register fields of the last timing (spi_lpspi_clock_for), kept while it repeats */
    bool ck_valid;
    uint8_t ck_cs, ck_bits;
    struct spi_timing ck_t;
    struct spi_lpspi_clock ck;
    uint32_t ck_word_ns, ck_hold_ns, ck_settle_ns;
    struct spi_lpspi_stats stats;
};

/*
 * Reset the module and set it up as a master (PCS active low, FIFOs empty). Returns 0,
 * INC_ERR_NULL, INC_ERR_INVAL (fclk 0, no PCS pin, a pin twice) or INC_ERR_UNSUPPORTED (PARAM).
 */
int spi_lpspi_init(struct spi_lpspi *lp, const struct spi_lpspi_cfg *cfg);

/* The LPSPI interrupt's work (cfg.irq_wait): disable the interrupt enables, so the level that
 * woke the CPU does not fire again; the engine re-reads the status. Call it from the board's
 * LPSPIn_IRQHandler, then wake the HAL. NULL: nothing. */
void spi_lpspi_isr(struct spi_lpspi *lp);

/*
 * The register fields for timing t with policy cs at fclk_hz (the mapping above). Returns 0,
 * INC_ERR_NULL, INC_ERR_INVAL (fclk 0, bad timing) or INC_ERR_TIMING (no prescaler fits).
 */
int spi_lpspi_clock_for(uint32_t fclk_hz, const struct spi_timing *t, enum spi_cs_policy cs,
                        struct spi_lpspi_clock *out);

/* ns of `counts` counts at prescale p (rounded up): what the hardware keeps for a field. */
uint32_t spi_lpspi_counts_ns(uint32_t fclk_hz, unsigned prescale, uint32_t counts);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_SPI_LPSPI_H */
