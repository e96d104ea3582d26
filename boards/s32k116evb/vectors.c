/*
 * vectors.c - the complete vector table of the S32K116 (32 external interrupts, IRQ 0..31), named
 * after the interrupt assignments of [S32K1XXRM] (its interrupt-map attachment); reserved
 * entries are 0. Every handler is a weak alias of Default_Handler except those this board
 * defines (PORT_IRQHandler, LPIT0_IRQHandler).
 * ARMv6-M (Cortex-M0+): entries 4..6 and 12 are reserved and never taken; the aliases only
 * keep one table layout for both parts. IRQ 27 is reserved on this part.
 */
#include <stdint.h>

#include "s32k1_startup.h"

/* An exception without a handler: park; the watchdog resets the part within its timeout. */
S32K1_EARLY(Default_Handler) void Default_Handler(void)
{
    for (;;) {
    }
}

#define WEAK_DEFAULT __attribute__((weak, alias("Default_Handler")))
void NMI_Handler(void) WEAK_DEFAULT;
void HardFault_Handler(void) WEAK_DEFAULT;
void MemManage_Handler(void) WEAK_DEFAULT;
void BusFault_Handler(void) WEAK_DEFAULT;
void UsageFault_Handler(void) WEAK_DEFAULT;
void SVC_Handler(void) WEAK_DEFAULT;
void DebugMon_Handler(void) WEAK_DEFAULT;
void PendSV_Handler(void) WEAK_DEFAULT;
void SysTick_Handler(void) WEAK_DEFAULT;
void DMA0_IRQHandler(void) WEAK_DEFAULT;                 /* 0 */
void DMA1_IRQHandler(void) WEAK_DEFAULT;                 /* 1 */
void DMA2_IRQHandler(void) WEAK_DEFAULT;                 /* 2 */
void DMA3_IRQHandler(void) WEAK_DEFAULT;                 /* 3 */
void DMA_Error_IRQHandler(void) WEAK_DEFAULT;            /* 4 */
void ERM_fault_IRQHandler(void) WEAK_DEFAULT;            /* 5 */
void RTC_IRQHandler(void) WEAK_DEFAULT;                  /* 6 */
void RTC_Seconds_IRQHandler(void) WEAK_DEFAULT;          /* 7 */
void LPTMR0_IRQHandler(void) WEAK_DEFAULT;               /* 8 */
void PORT_IRQHandler(void) WEAK_DEFAULT;                 /* 9 */
void CAN0_ORed_Err_Wakeup_IRQHandler(void) WEAK_DEFAULT; /* 10 */
void CAN0_ORed_0_31_MB_IRQHandler(void) WEAK_DEFAULT;    /* 11 */
void FTM0_Ch0_7_IRQHandler(void) WEAK_DEFAULT;           /* 12 */
void FTM0_Fault_IRQHandler(void) WEAK_DEFAULT;           /* 13 */
void FTM0_Ovf_Reload_IRQHandler(void) WEAK_DEFAULT;      /* 14 */
void FTM1_Ch0_7_IRQHandler(void) WEAK_DEFAULT;           /* 15 */
void FTM1_Fault_IRQHandler(void) WEAK_DEFAULT;           /* 16 */
void FTM1_Ovf_Reload_IRQHandler(void) WEAK_DEFAULT;      /* 17 */
void FTFC_IRQHandler(void) WEAK_DEFAULT;                 /* 18 */
void PDB0_IRQHandler(void) WEAK_DEFAULT;                 /* 19 */
void LPIT0_IRQHandler(void) WEAK_DEFAULT;                /* 20 */
void SCG_CMU_LVD_LVWSCG_IRQHandler(void) WEAK_DEFAULT;   /* 21 */
void WDOG_IRQHandler(void) WEAK_DEFAULT;                 /* 22 */
void RCM_IRQHandler(void) WEAK_DEFAULT;                  /* 23 */
void LPI2C0_Master_Slave_IRQHandler(void) WEAK_DEFAULT;  /* 24 */
void FLEXIO_IRQHandler(void) WEAK_DEFAULT;               /* 25 */
void LPSPI0_IRQHandler(void) WEAK_DEFAULT;               /* 26 */
void ADC0_IRQHandler(void) WEAK_DEFAULT;                 /* 28 */
void CMP0_IRQHandler(void) WEAK_DEFAULT;                 /* 29 */
void LPUART1_RxTx_IRQHandler(void) WEAK_DEFAULT;         /* 30 */
void LPUART0_RxTx_IRQHandler(void) WEAK_DEFAULT;         /* 31 */

__attribute__((used, section(".isr_vector"))) const struct s32k1_vector_table s32k1_vectors = {
    __stack_top__,
    {
        Reset_Handler,
        NMI_Handler,
        HardFault_Handler,
        MemManage_Handler,
        BusFault_Handler,
        UsageFault_Handler,
        0,
        0,
        0,
        0,
        SVC_Handler,
        DebugMon_Handler,
        0,
        PendSV_Handler,
        SysTick_Handler,
        DMA0_IRQHandler,                 /* IRQ 0 */
        DMA1_IRQHandler,                 /* IRQ 1 */
        DMA2_IRQHandler,                 /* IRQ 2 */
        DMA3_IRQHandler,                 /* IRQ 3 */
        DMA_Error_IRQHandler,            /* IRQ 4 */
        ERM_fault_IRQHandler,            /* IRQ 5 */
        RTC_IRQHandler,                  /* IRQ 6 */
        RTC_Seconds_IRQHandler,          /* IRQ 7 */
        LPTMR0_IRQHandler,               /* IRQ 8 */
        PORT_IRQHandler,                 /* IRQ 9 */
        CAN0_ORed_Err_Wakeup_IRQHandler, /* IRQ 10 */
        CAN0_ORed_0_31_MB_IRQHandler,    /* IRQ 11 */
        FTM0_Ch0_7_IRQHandler,           /* IRQ 12 */
        FTM0_Fault_IRQHandler,           /* IRQ 13 */
        FTM0_Ovf_Reload_IRQHandler,      /* IRQ 14 */
        FTM1_Ch0_7_IRQHandler,           /* IRQ 15 */
        FTM1_Fault_IRQHandler,           /* IRQ 16 */
        FTM1_Ovf_Reload_IRQHandler,      /* IRQ 17 */
        FTFC_IRQHandler,                 /* IRQ 18 */
        PDB0_IRQHandler,                 /* IRQ 19 */
        LPIT0_IRQHandler,                /* IRQ 20 */
        SCG_CMU_LVD_LVWSCG_IRQHandler,   /* IRQ 21 */
        WDOG_IRQHandler,                 /* IRQ 22 */
        RCM_IRQHandler,                  /* IRQ 23 */
        LPI2C0_Master_Slave_IRQHandler,  /* IRQ 24 */
        FLEXIO_IRQHandler,               /* IRQ 25 */
        LPSPI0_IRQHandler,               /* IRQ 26 */
        0,                               /* IRQ 27 */
        ADC0_IRQHandler,                 /* IRQ 28 */
        CMP0_IRQHandler,                 /* IRQ 29 */
        LPUART1_RxTx_IRQHandler,         /* IRQ 30 */
        LPUART0_RxTx_IRQHandler,         /* IRQ 31 */
    },
};

_Static_assert(sizeof(s32k1_vectors) == 4u * (16u + 32u), "vector table size");
