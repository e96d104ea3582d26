/*
 * s32k_flexcan.h - FlexCAN driver of the S32K1 family (module inclino_s32k1_flexcan, prefix
 * s32k_flexcan_). Classic CAN 2.0 with 11-bit identifiers, polled message buffers (no interrupt,
 * no Rx FIFO, no CAN FD). docs/can.md; register facts from [NXP-S32K1-RM], chapter FlexCAN.
 *
 * Registers (offsets from the instance base; CAN0 0x40024000, CAN1 0x40025000, CAN2 0x4002B000):
 *   MCR 0x00, CTRL1 0x04, TIMER 0x08, RXMGMASK 0x10, ECR 0x1C, ESR1 0x20, IMASK1 0x28,
 *   IFLAG1 0x30, message buffers from 0x80, 16 bytes each with 8-byte payloads:
 *   word 0 C/S (CODE 27:24, SRR 22, IDE 21, RTR 20, DLC 19:16, TIME STAMP 15:0),
 *   word 1 ID (standard ID in 28:18), words 2-3 data bytes 0-3 and 4-7, byte 0 in bits 31:24.
 *
 * Initialisation (s32k_flexcan_init), the reference manual's sequence:
 *   1. MCR[MDIS] = 1 (disabled; the clock source may only change now), CTRL1[CLKSRC] = 0:
 *      the oscillator clock (on the S32K1 the SOSCDIV2 output; the board sets it to 8 MHz);
 *   2. MCR[MDIS] = 0, wait for MCR[LPMACK] = 0; soft reset (MCR[SOFTRST], wait until it clears);
 *   3. freeze: MCR[FRZ] = MCR[HALT] = 1, wait for MCR[FRZACK] = 1;
 *   4. MCR: MAXMB = n_mb - 1, SRXDIS (no self reception), IRMQ = 0 (the global mask);
 *      CTRL1 bit timing (below); every message buffer inactive (C/S, ID and data 0: the buffer RAM
 *      is not reset); RXMGMASK = all 11 ID bits; the Rx buffer EMPTY with its ID; IMASK1 = 0;
 *   5. leave freeze: MCR[HALT] = MCR[FRZ] = 0, wait for MCR[FRZACK] = 0 and MCR[NOTRDY] = 0.
 *   Every wait is bounded (cfg.poll_limit reads): INC_ERR_TIMEOUT.
 *
 * Bit timing for 500 kbit/s from the 8 MHz oscillator clock (CTRL1, not CBT): PRESDIV 0 (time
 * quantum 125 ns), 16 tq per bit = SYNC 1 + PROPSEG 7 + PSEG1 6 + PSEG2 2, RJW 2; sample point
 * at 14/16 = 87.5 %. CTRL1 fields hold value - 1: PROPSEG 6, PSEG1 5, PSEG2 1, RJW 1.
 *
 * Transmit (s32k_flexcan_send): a Tx buffer whose CODE is not DATA (or whose IFLAG is set) is
 * free; its IFLAG is cleared, C/S is written INACTIVE (0b1000), then the ID, the data words, and
 * last C/S with CODE DATA (0b1100), the DLC, IDE = 0, RTR = 0. All Tx buffers busy: INC_ERR_BUSY.
 * Receive (s32k_flexcan_receive): the Rx buffer's IFLAG; C/S is read (locks the buffer), CODE
 * FULL (0b0010) or OVERRUN (0b0110), ID, DLC and data, then TIMER is read (unlocks), IFLAG
 * cleared (write 1), and the buffer is EMPTY (0b0100) again. Nothing: INC_ERR_STALE; an OVERRUN:
 * the frame is delivered and *overrun set.
 * Errors (ESR1; its error bits clear when it is read, so the driver keeps them in dev->last_esr1
 * from every read until s32k_flexcan_error_state reports them): s32k_flexcan_error_state returns FLTCONF 1x bus off: INC_ERR_BUS; FLTCONF 01
 * error passive: INC_ERR_DEVICE; ACKERR (no node acknowledged a frame): INC_ERR_TIMEOUT. Send and
 * receive read ESR1 first and refuse with INC_ERR_BUS while bus off (nothing is queued); an error
 * passive node still sends, and frames nobody acknowledges stay pending until every Tx buffer is
 * busy (INC_ERR_BUSY).
 *
 * Freestanding C11; registers only through inclino/s32k_mmio.h.
 */
#ifndef INCLINO_S32K_FLEXCAN_H
#define INCLINO_S32K_FLEXCAN_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "inclino/error.h"

#ifdef __cplusplus
extern "C" {
#endif

#define S32K_CAN0_BASE 0x40024000u
#define S32K_CAN1_BASE 0x40025000u
#define S32K_CAN2_BASE 0x4002B000u

#define S32K_FLEXCAN_MCR 0x00u
#define S32K_FLEXCAN_CTRL1 0x04u
#define S32K_FLEXCAN_TIMER 0x08u
#define S32K_FLEXCAN_RXMGMASK 0x10u
#define S32K_FLEXCAN_ECR 0x1Cu
#define S32K_FLEXCAN_ESR1 0x20u
#define S32K_FLEXCAN_IMASK1 0x28u
#define S32K_FLEXCAN_IFLAG1 0x30u
#define S32K_FLEXCAN_MB0 0x80u
#define S32K_FLEXCAN_MB_SIZE 16u
#define S32K_FLEXCAN_REGION 0x1000u /* one instance's address space */

/* MCR bits */
#define S32K_FLEXCAN_MCR_MDIS (1u << 31)
#define S32K_FLEXCAN_MCR_FRZ (1u << 30)
#define S32K_FLEXCAN_MCR_RFEN (1u << 29)
#define S32K_FLEXCAN_MCR_HALT (1u << 28)
#define S32K_FLEXCAN_MCR_NOTRDY (1u << 27)
#define S32K_FLEXCAN_MCR_SOFTRST (1u << 25)
#define S32K_FLEXCAN_MCR_FRZACK (1u << 24)
#define S32K_FLEXCAN_MCR_SUPV (1u << 23)
#define S32K_FLEXCAN_MCR_LPMACK (1u << 20)
#define S32K_FLEXCAN_MCR_SRXDIS (1u << 17)
#define S32K_FLEXCAN_MCR_IRMQ (1u << 16)
#define S32K_FLEXCAN_MCR_MAXMB_MASK 0x7Fu

/* CTRL1 fields */
#define S32K_FLEXCAN_CTRL1_PRESDIV(x) (((uint32_t)(x)&0xFFu) << 24)
#define S32K_FLEXCAN_CTRL1_RJW(x) (((uint32_t)(x)&0x3u) << 22)
#define S32K_FLEXCAN_CTRL1_PSEG1(x) (((uint32_t)(x)&0x7u) << 19)
#define S32K_FLEXCAN_CTRL1_PSEG2(x) (((uint32_t)(x)&0x7u) << 16)
#define S32K_FLEXCAN_CTRL1_CLKSRC (1u << 13)
#define S32K_FLEXCAN_CTRL1_PROPSEG(x) ((uint32_t)(x)&0x7u)

/* ESR1 bits */
#define S32K_FLEXCAN_ESR1_ERRINT (1u << 1)
#define S32K_FLEXCAN_ESR1_BOFFINT (1u << 2)
#define S32K_FLEXCAN_ESR1_FLTCONF_SHIFT 4u
#define S32K_FLEXCAN_ESR1_FLTCONF_MASK (3u << 4)
#define S32K_FLEXCAN_ESR1_TX (1u << 6)
#define S32K_FLEXCAN_ESR1_IDLE (1u << 7)
#define S32K_FLEXCAN_ESR1_STFERR (1u << 10)
#define S32K_FLEXCAN_ESR1_FRMERR (1u << 11)
#define S32K_FLEXCAN_ESR1_CRCERR (1u << 12)
#define S32K_FLEXCAN_ESR1_ACKERR (1u << 13)
#define S32K_FLEXCAN_ESR1_BIT0ERR (1u << 14)
#define S32K_FLEXCAN_ESR1_BIT1ERR (1u << 15)

/* Message buffer C/S word */
#define S32K_FLEXCAN_CS_CODE_SHIFT 24u
#define S32K_FLEXCAN_CS_CODE_MASK (0xFu << 24)
#define S32K_FLEXCAN_CS_SRR (1u << 22)
#define S32K_FLEXCAN_CS_IDE (1u << 21)
#define S32K_FLEXCAN_CS_RTR (1u << 20)
#define S32K_FLEXCAN_CS_DLC_SHIFT 16u
#define S32K_FLEXCAN_CS_DLC_MASK (0xFu << 16)
#define S32K_FLEXCAN_ID_STD_SHIFT 18u
#define S32K_FLEXCAN_ID_STD_MASK (0x7FFu << 18)

/* CODE values */
#define S32K_FLEXCAN_CODE_RX_INACTIVE 0x0u
#define S32K_FLEXCAN_CODE_RX_FULL 0x2u
#define S32K_FLEXCAN_CODE_RX_EMPTY 0x4u
#define S32K_FLEXCAN_CODE_RX_OVERRUN 0x6u
#define S32K_FLEXCAN_CODE_TX_INACTIVE 0x8u
#define S32K_FLEXCAN_CODE_TX_ABORT 0x9u
#define S32K_FLEXCAN_CODE_TX_DATA 0xCu

/* The 500 kbit/s timing from an 8 MHz clock (see above). */
#define S32K_FLEXCAN_CLK_HZ 8000000u
#define S32K_FLEXCAN_BITRATE 500000u
#define S32K_FLEXCAN_TQ_PER_BIT 16u
#define S32K_FLEXCAN_CTRL1_500K                                                                \
    (S32K_FLEXCAN_CTRL1_PRESDIV(0) | S32K_FLEXCAN_CTRL1_RJW(1) | S32K_FLEXCAN_CTRL1_PSEG1(5) | \
     S32K_FLEXCAN_CTRL1_PSEG2(1) | S32K_FLEXCAN_CTRL1_PROPSEG(6))

struct s32k_flexcan_cfg {
    uint32_t base;       /* S32K_CAN0_BASE, ... */
    uint8_t n_mb;        /* message buffers used, 2..32 (IFLAG1); S32K144 CAN0 has 32, S32K116 16 */
    uint8_t rx_mb;       /* the Rx buffer, < n_mb */
    uint8_t tx_first;    /* the Tx buffers: tx_first .. tx_first + tx_count - 1, < n_mb, */
    uint8_t tx_count;    /* not holding rx_mb; 1..8 */
    uint16_t rx_id;      /* the standard ID the Rx buffer accepts, <= 0x7FF */
    uint32_t clk_hz;     /* the protocol clock; only S32K_FLEXCAN_CLK_HZ is supported */
    uint32_t poll_limit; /* most status reads a wait makes (>= 1) */
};

struct s32k_flexcan {
    struct s32k_flexcan_cfg cfg;
    uint32_t last_esr1;
    uint32_t sent, received, overruns;
    bool ready;
};

/* Fill cfg for CAN0 of an S32K144 (32 buffers; Rx buffer 8, Tx buffers 9..12) with rx_id. */
void s32k_flexcan_cfg_default(struct s32k_flexcan_cfg *cfg, uint16_t rx_id);

/* Initialise (the sequence above). INC_ERR_NULL, INC_ERR_INVAL (cfg), INC_ERR_UNSUPPORTED
 * (clock), INC_ERR_TIMEOUT (a mode acknowledge never came). */
int s32k_flexcan_init(struct s32k_flexcan *dev, const struct s32k_flexcan_cfg *cfg);

/* The ESR1 error state: 0, INC_ERR_BUS (bus off), INC_ERR_DEVICE (error passive),
 * INC_ERR_TIMEOUT (ACKERR). INC_ERR_NULL, INC_ERR_STATE (not initialised). */
int s32k_flexcan_error_state(struct s32k_flexcan *dev);

/* Queue one frame. id <= 0x7FF, dlc <= 8 (data may be NULL when dlc == 0). INC_ERR_NULL,
 * INC_ERR_INVAL, INC_ERR_STATE, INC_ERR_BUSY (every Tx buffer pending), INC_ERR_BUS (bus off). */
int s32k_flexcan_send(struct s32k_flexcan *dev, uint16_t id, const uint8_t *data, uint8_t dlc);

/* Take a received frame. INC_ERR_STALE (none), INC_ERR_NULL, INC_ERR_STATE, INC_ERR_BUS (bus
 * off). */
int s32k_flexcan_receive(struct s32k_flexcan *dev, uint16_t *id, uint8_t data[8], uint8_t *dlc,
                         bool *overrun);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_S32K_FLEXCAN_H */
