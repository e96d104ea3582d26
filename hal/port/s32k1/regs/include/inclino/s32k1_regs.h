/*
 * s32k1_regs.h - the registers of the S32K1 family (S32K144, S32K116) the port touches: absolute
 * bus addresses and bit fields, named here from the S32K1xx Series Reference Manual
 * [S32K1XXRM] (chapters System Clock Generator, Peripheral Clock Controller, Port Control and
 * Interrupts, General-Purpose Input/Output, Watchdog Timer, Low Power Interrupt Timer) and the
 * Cortex-M NVIC of the ARMv7-M / ARMv6-M architecture manuals. Every access goes through
 * inclino/s32k_mmio.h with these addresses. Facts not confirmed against the manual are listed
 * in docs/unconfirmed-facts.md ("S32K1 port").
 */
#ifndef INCLINO_S32K1_REGS_H
#define INCLINO_S32K1_REGS_H

#include <stdint.h>

/* ---- SCG: System Clock Generator ------------------------------------------------------------ */
#define S32K_SCG_BASE 0x40064000u
#define S32K_SCG_CSR (S32K_SCG_BASE + 0x010u)  /* clock status (read only) */
#define S32K_SCG_RCCR (S32K_SCG_BASE + 0x014u) /* RUN clock control (32-bit writes only) */
#define S32K_SCG_SOSCCSR (S32K_SCG_BASE + 0x100u)
#define S32K_SCG_SOSCDIV (S32K_SCG_BASE + 0x104u)
#define S32K_SCG_SOSCCFG (S32K_SCG_BASE + 0x108u)
#define S32K_SCG_SIRCCSR (S32K_SCG_BASE + 0x200u)
#define S32K_SCG_SIRCDIV (S32K_SCG_BASE + 0x204u)
#define S32K_SCG_FIRCCSR (S32K_SCG_BASE + 0x300u)
#define S32K_SCG_FIRCDIV (S32K_SCG_BASE + 0x304u)
#define S32K_SCG_SPLLCSR (S32K_SCG_BASE + 0x600u)
#define S32K_SCG_SPLLDIV (S32K_SCG_BASE + 0x604u)
#define S32K_SCG_SPLLCFG (S32K_SCG_BASE + 0x608u)

/* CSR / RCCR fields: system clock source and the core, bus and slow (flash) dividers. */
#define S32K_SCG_SCS_SHIFT 24u
#define S32K_SCG_SCS_MASK (0xFu << 24)
#define S32K_SCG_SCS_SOSC 1u
#define S32K_SCG_SCS_SIRC 2u
#define S32K_SCG_SCS_FIRC 3u
#define S32K_SCG_SCS_SPLL 6u
#define S32K_SCG_DIVCORE_SHIFT 16u /* divide by value + 1 */
#define S32K_SCG_DIVBUS_SHIFT 4u
#define S32K_SCG_DIVSLOW_SHIFT 0u
#define S32K_SCG_CCR(scs, core, bus, slow)                                                   \
    (((uint32_t)(scs) << 24) | ((uint32_t)((core)-1u) << 16) | ((uint32_t)((bus)-1u) << 4) | \
     (uint32_t)((slow)-1u))

/* xCSR of each source: enable, lock, valid, selected-as-system-clock. */
#define S32K_SCG_XCSR_EN (1u << 0)
#define S32K_SCG_XCSR_LK (1u << 23)
#define S32K_SCG_XCSR_VLD (1u << 24)
#define S32K_SCG_XCSR_SEL (1u << 25)
/* xDIV: the asynchronous peripheral clocks DIV1 [2:0] and DIV2 [10:8]; 0 = off, n = /2^(n-1). */
#define S32K_SCG_DIV1_SHIFT 0u
#define S32K_SCG_DIV2_SHIFT 8u
#define S32K_SCG_DIV_1 1u
#define S32K_SCG_DIV_2 2u
/* SOSCCFG: RANGE [5:4] (3 = high, 8..40 MHz crystal), HGO bit 3, EREFS bit 2 (1 = crystal). */
#define S32K_SCG_SOSCCFG_RANGE_HIGH (3u << 4)
#define S32K_SCG_SOSCCFG_RANGE_MED (2u << 4)
#define S32K_SCG_SOSCCFG_EREFS (1u << 2)
/* SPLLCFG: PREDIV [10:8] (divide by value + 1), MULT [20:16] (multiply by value + 16);
 * VCO = SOSC / (PREDIV + 1) * (MULT + 16), SPLL_CLK = VCO / 2. */
#define S32K_SCG_SPLLCFG_PREDIV_SHIFT 8u
#define S32K_SCG_SPLLCFG_MULT_SHIFT 16u

/* ---- PCC: Peripheral Clock Controller (one 32-bit register per peripheral) ------------------ */
#define S32K_PCC_BASE 0x40065000u
#define S32K_PCC_FLEXCAN0 (S32K_PCC_BASE + 0x090u) /* PCC index 36 */
#define S32K_PCC_LPSPI0 (S32K_PCC_BASE + 0x0B0u)
#define S32K_PCC_LPSPI1 (S32K_PCC_BASE + 0x0B4u)
#define S32K_PCC_LPIT (S32K_PCC_BASE + 0x0DCu)
#define S32K_PCC_PORTA (S32K_PCC_BASE + 0x124u)
#define S32K_PCC_PORT(n) (S32K_PCC_PORTA + 4u * (uint32_t)(n)) /* PORTA..PORTE */
#define S32K_PCC_CGC (1u << 30)                                /* clock gate control */
#define S32K_PCC_PR (1u << 31)                                 /* peripheral present (read) */
#define S32K_PCC_PCS_SHIFT 24u                                 /* functional clock source [26:24] */
#define S32K_PCC_PCS_MASK (7u << 24)
#define S32K_PCC_PCS_SOSCDIV2 1u
#define S32K_PCC_PCS_SIRCDIV2 2u
#define S32K_PCC_PCS_FIRCDIV2 3u
#define S32K_PCC_PCS_SPLLDIV2 6u

/* ---- PORT: pin control and interrupts (PORTA..PORTE) ---------------------------------------- */
#define S32K_PORT_BASE(n) (0x40049000u + 0x1000u * (uint32_t)(n))
#define S32K_PORT_PCR(n, pin) (S32K_PORT_BASE(n) + 4u * (uint32_t)(pin))
#define S32K_PORT_ISFR(n) (S32K_PORT_BASE(n) + 0x0A0u) /* interrupt status, w1c */
#define S32K_PORT_PCR_PS (1u << 0)                     /* pull select: 1 = up */
#define S32K_PORT_PCR_PE (1u << 1)                     /* pull enable */
#define S32K_PORT_PCR_MUX_SHIFT 8u                     /* [10:8]: 0 analog, 1 GPIO, 2..7 alt */
#define S32K_PORT_PCR_MUX_MASK (7u << 8)
#define S32K_PORT_PCR_MUX_GPIO 1u
#define S32K_PORT_PCR_IRQC_SHIFT 16u /* [19:16] */
#define S32K_PORT_PCR_IRQC_MASK (0xFu << 16)
#define S32K_PORT_PCR_ISF (1u << 24) /* w1c */
#define S32K_PORT_IRQC_OFF 0u
#define S32K_PORT_IRQC_RISING 9u
#define S32K_PORT_IRQC_FALLING 10u
#define S32K_PORT_IRQC_EITHER 11u
#define S32K_PORT_COUNT 5u
#define S32K_PORT_PINS 32u

/* ---- GPIO (PTA..PTE) ------------------------------------------------------------------------ */
#define S32K_GPIO_BASE(n) (0x400FF000u + 0x40u * (uint32_t)(n))
#define S32K_GPIO_PDOR(n) (S32K_GPIO_BASE(n) + 0x00u) /* data output */
#define S32K_GPIO_PSOR(n) (S32K_GPIO_BASE(n) + 0x04u) /* set output (write 1) */
#define S32K_GPIO_PCOR(n) (S32K_GPIO_BASE(n) + 0x08u) /* clear output (write 1) */
#define S32K_GPIO_PTOR(n) (S32K_GPIO_BASE(n) + 0x0Cu) /* toggle output (write 1) */
#define S32K_GPIO_PDIR(n) (S32K_GPIO_BASE(n) + 0x10u) /* data input */
#define S32K_GPIO_PDDR(n) (S32K_GPIO_BASE(n) + 0x14u) /* direction: 1 = output */
#define S32K_GPIO_PIDR(n) (S32K_GPIO_BASE(n) + 0x18u) /* input disable */

/* ---- WDOG: watchdog timer ------------------------------------------------------------------- */
#define S32K_WDOG_BASE 0x40052000u
#define S32K_WDOG_CS (S32K_WDOG_BASE + 0x00u)
#define S32K_WDOG_CNT (S32K_WDOG_BASE + 0x04u)
#define S32K_WDOG_TOVAL (S32K_WDOG_BASE + 0x08u)
#define S32K_WDOG_WIN (S32K_WDOG_BASE + 0x0Cu)
#define S32K_WDOG_UNLOCK_KEY 0xD928C520u  /* one 32-bit write to CNT (CMD32EN = 1) */
#define S32K_WDOG_REFRESH_KEY 0xB480A602u /* one 32-bit write to CNT (CMD32EN = 1) */
#define S32K_WDOG_CS_STOP (1u << 0)
#define S32K_WDOG_CS_WAIT (1u << 1)
#define S32K_WDOG_CS_DBG (1u << 2)
#define S32K_WDOG_CS_UPDATE (1u << 5) /* later reconfiguration allowed (after an unlock) */
#define S32K_WDOG_CS_INT (1u << 6)
#define S32K_WDOG_CS_EN (1u << 7)
#define S32K_WDOG_CS_CLK_LPO (1u << 8) /* CLK [9:8] = 1: the 128 kHz LPO clock */
#define S32K_WDOG_CS_RCS (1u << 10)    /* reconfiguration success (read) */
#define S32K_WDOG_CS_ULK (1u << 11)    /* unlocked (read) */
#define S32K_WDOG_CS_PRES (1u << 12)   /* fixed 256 pre-scaler */
#define S32K_WDOG_CS_CMD32EN (1u << 13)
#define S32K_WDOG_CS_FLG (1u << 14) /* interrupt flag, w1c */
#define S32K_WDOG_CS_WIN (1u << 15)
#define S32K_WDOG_LPO_HZ 128000u

/* ---- LPIT0: low power interrupt timer ------------------------------------------------------- */
#define S32K_LPIT_BASE 0x40037000u
#define S32K_LPIT_MCR (S32K_LPIT_BASE + 0x008u)
#define S32K_LPIT_MSR (S32K_LPIT_BASE + 0x00Cu)  /* TIFn, w1c */
#define S32K_LPIT_MIER (S32K_LPIT_BASE + 0x010u) /* TIEn */
#define S32K_LPIT_TVAL(ch) (S32K_LPIT_BASE + 0x020u + 0x10u * (uint32_t)(ch))
#define S32K_LPIT_CVAL(ch) (S32K_LPIT_BASE + 0x024u + 0x10u * (uint32_t)(ch))
#define S32K_LPIT_TCTRL(ch) (S32K_LPIT_BASE + 0x028u + 0x10u * (uint32_t)(ch))
#define S32K_LPIT_MCR_M_CEN (1u << 0)  /* module clock enable */
#define S32K_LPIT_MCR_SW_RST (1u << 1) /* software reset */
#define S32K_LPIT_MCR_DBG_EN (1u << 3) /* keep running in debug mode */
#define S32K_LPIT_TCTRL_T_EN (1u << 0) /* MODE [3:2] = 0: 32-bit periodic counter */
#define S32K_LPIT_TCTRL_TSOT (1u << 16)
#define S32K_LPIT_TIF(ch) (1u << (ch))

/* ---- NVIC (Cortex-M, both cores) ------------------------------------------------------------ */
#define S32K_NVIC_ISER(n) (0xE000E100u + 4u * (uint32_t)(n)) /* set enable, IRQ 32n..32n+31 */
#define S32K_NVIC_ICER(n) (0xE000E180u + 4u * (uint32_t)(n)) /* clear enable */
#define S32K_NVIC_ICPR(n) (0xE000E280u + 4u * (uint32_t)(n)) /* clear pending */

/* The parts of the family the port knows. */
enum s32k_part {
    S32K_PART_144 = 0, /* Cortex-M4F, PORTA..E vectors 59..63 */
    S32K_PART_116 = 1, /* Cortex-M0+, one PORT vector (9) */
};

/* ---- Interrupt numbers the port uses ------------------------------------------------------- */
/* S32K144: one vector per port (PORTA 59 .. PORTE 63), LPIT0 channel 1 = 49. */
#define S32K144_IRQ_PORTA 59u
#define S32K144_IRQ_LPIT0_CH1 49u
/* S32K116: one vector for every port (PORT 9), one for all LPIT0 channels (20). */
#define S32K116_IRQ_PORT 9u
#define S32K1_IRQ_LPSPI0 26u /* both parts */
#define S32K116_IRQ_LPIT0 20u

#endif /* INCLINO_S32K1_REGS_H */
