/*
 * spi_lpspi_regs.h - the LPSPI register map of the S32K1 family, as the reference manual gives it
 * ([S32K1XXRM], chapter "Low Power Serial Peripheral Interface (LPSPI)"; base addresses from
 * its memory map). Shared by the driver (spi_lpspi.c) and the register model
 * (sim/models/s32k1/lpspi), so the two cannot disagree on an offset or a bit.
 */
#ifndef INCLINO_SPI_LPSPI_REGS_H
#define INCLINO_SPI_LPSPI_REGS_H

/* Instances. S32K144: LPSPI0..2; S32K116: LPSPI0..1. */
#define LPSPI0_BASE 0x4002C000u
#define LPSPI1_BASE 0x4002D000u
#define LPSPI2_BASE 0x4002E000u
#define LPSPI_REGION_SIZE 0x1000u

/* Register offsets. */
#define LPSPI_VERID 0x00u
#define LPSPI_PARAM 0x04u
#define LPSPI_CR 0x10u
#define LPSPI_SR 0x14u
#define LPSPI_IER 0x18u
#define LPSPI_DER 0x1Cu
#define LPSPI_CFGR0 0x20u
#define LPSPI_CFGR1 0x24u
#define LPSPI_DMR0 0x30u
#define LPSPI_DMR1 0x34u
#define LPSPI_CCR 0x40u
#define LPSPI_FCR 0x58u
#define LPSPI_FSR 0x5Cu
#define LPSPI_TCR 0x60u
#define LPSPI_TDR 0x64u
#define LPSPI_RSR 0x70u
#define LPSPI_RDR 0x74u

/* PARAM: FIFO sizes as log2 of words, number of PCS lines. */
#define LPSPI_PARAM_TXFIFO(v) ((v)&0xFFu)
#define LPSPI_PARAM_RXFIFO(v) (((v) >> 8) & 0xFFu)
#define LPSPI_PARAM_PCSNUM(v) (((v) >> 16) & 0xFFu)

/* CR */
#define LPSPI_CR_MEN (1u << 0)
#define LPSPI_CR_RST (1u << 1)
#define LPSPI_CR_DOZEN (1u << 2)
#define LPSPI_CR_DBGEN (1u << 3)
#define LPSPI_CR_RTF (1u << 8)
#define LPSPI_CR_RRF (1u << 9)

/* SR: TDF, RDF and MBF read-only; WCF..DMF write 1 to clear. */
#define LPSPI_SR_TDF (1u << 0)
#define LPSPI_SR_RDF (1u << 1)
#define LPSPI_SR_WCF (1u << 8)
#define LPSPI_SR_FCF (1u << 9)
#define LPSPI_SR_TCF (1u << 10)
#define LPSPI_SR_TEF (1u << 11)
#define LPSPI_SR_REF (1u << 12)
#define LPSPI_SR_DMF (1u << 13)
#define LPSPI_SR_MBF (1u << 24)
#define LPSPI_SR_W1C_MASK 0x3F00u

/* IER: an interrupt enable per SR flag, same bit positions. */
#define LPSPI_IER_RDIE LPSPI_SR_RDF
#define LPSPI_IER_TEIE LPSPI_SR_TEF
#define LPSPI_IER_REIE LPSPI_SR_REF

/* CFGR1 */
#define LPSPI_CFGR1_MASTER (1u << 0)
#define LPSPI_CFGR1_SAMPLE (1u << 1)
#define LPSPI_CFGR1_AUTOPCS (1u << 2)
#define LPSPI_CFGR1_NOSTALL (1u << 3)
#define LPSPI_CFGR1_PCSPOL_SHIFT 8u
#define LPSPI_CFGR1_PCSPOL_MASK (0xFu << 8)
#define LPSPI_CFGR1_MATCFG_MASK (7u << 16)
#define LPSPI_CFGR1_PINCFG_MASK (3u << 24)
#define LPSPI_CFGR1_OUTCFG (1u << 26)
#define LPSPI_CFGR1_PCSCFG (1u << 27)

/* CCR: SCK period (SCKDIV + 2), PCS->SCK (PCSSCK + 1), SCK->PCS (SCKPCS + 1), and DBT: PCS
 * negated between frames (DBT + 2) or, in a continuous transfer, last SCK edge of one frame to
 * the first of the next (DBT + 1); every count in cycles of the prescaled functional clock. */
#define LPSPI_CCR_SCKDIV_SHIFT 0u
#define LPSPI_CCR_DBT_SHIFT 8u
#define LPSPI_CCR_PCSSCK_SHIFT 16u
#define LPSPI_CCR_SCKPCS_SHIFT 24u
#define LPSPI_CCR_FIELD_MAX 255u

/* FCR: watermarks; FSR: FIFO fill levels. */
#define LPSPI_FCR_TXWATER_SHIFT 0u
#define LPSPI_FCR_RXWATER_SHIFT 16u
#define LPSPI_FSR_TXCOUNT(v) ((v)&0x1Fu)
#define LPSPI_FSR_RXCOUNT(v) (((v) >> 16) & 0x1Fu)

/* TCR (the command word; written through the TX FIFO). */
#define LPSPI_TCR_FRAMESZ_MASK 0xFFFu /* frame size - 1 */
#define LPSPI_TCR_WIDTH_MASK (3u << 16)
#define LPSPI_TCR_TXMSK (1u << 18)
#define LPSPI_TCR_RXMSK (1u << 19)
#define LPSPI_TCR_CONTC (1u << 20)
#define LPSPI_TCR_CONT (1u << 21)
#define LPSPI_TCR_BYSW (1u << 22)
#define LPSPI_TCR_LSBF (1u << 23)
#define LPSPI_TCR_PCS_SHIFT 24u
#define LPSPI_TCR_PCS_MASK (3u << 24)
#define LPSPI_TCR_PRESCALE_SHIFT 27u
#define LPSPI_TCR_PRESCALE_MASK (7u << 27)
#define LPSPI_TCR_CPHA (1u << 30)
#define LPSPI_TCR_CPOL (1u << 31)

/* RSR */
#define LPSPI_RSR_SOF (1u << 0)
#define LPSPI_RSR_RXEMPTY (1u << 1)

#endif /* INCLINO_SPI_LPSPI_REGS_H */
