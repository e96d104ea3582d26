/*
 * vectors.c - the complete vector table of the S32K144 (123 external interrupts, IRQ 0..122), named
 * after the interrupt assignments of [S32K1XXRM] (its interrupt-map attachment); reserved
 * entries are 0. Every handler is a weak alias of Default_Handler except those this board
 * defines (PORTA..PORTE_IRQHandler, LPIT0_Ch1_IRQHandler).
 * ARMv7-M: MemManage, BusFault, UsageFault and DebugMon exist on the Cortex-M4F.
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
void DMA0_IRQHandler(void) WEAK_DEFAULT;               /* 0 */
void DMA1_IRQHandler(void) WEAK_DEFAULT;               /* 1 */
void DMA2_IRQHandler(void) WEAK_DEFAULT;               /* 2 */
void DMA3_IRQHandler(void) WEAK_DEFAULT;               /* 3 */
void DMA4_IRQHandler(void) WEAK_DEFAULT;               /* 4 */
void DMA5_IRQHandler(void) WEAK_DEFAULT;               /* 5 */
void DMA6_IRQHandler(void) WEAK_DEFAULT;               /* 6 */
void DMA7_IRQHandler(void) WEAK_DEFAULT;               /* 7 */
void DMA8_IRQHandler(void) WEAK_DEFAULT;               /* 8 */
void DMA9_IRQHandler(void) WEAK_DEFAULT;               /* 9 */
void DMA10_IRQHandler(void) WEAK_DEFAULT;              /* 10 */
void DMA11_IRQHandler(void) WEAK_DEFAULT;              /* 11 */
void DMA12_IRQHandler(void) WEAK_DEFAULT;              /* 12 */
void DMA13_IRQHandler(void) WEAK_DEFAULT;              /* 13 */
void DMA14_IRQHandler(void) WEAK_DEFAULT;              /* 14 */
void DMA15_IRQHandler(void) WEAK_DEFAULT;              /* 15 */
void DMA_Error_IRQHandler(void) WEAK_DEFAULT;          /* 16 */
void MCM_IRQHandler(void) WEAK_DEFAULT;                /* 17 */
void FTFC_IRQHandler(void) WEAK_DEFAULT;               /* 18 */
void Read_Collision_IRQHandler(void) WEAK_DEFAULT;     /* 19 */
void LVD_LVW_IRQHandler(void) WEAK_DEFAULT;            /* 20 */
void FTFC_Fault_IRQHandler(void) WEAK_DEFAULT;         /* 21 */
void WDOG_EWM_IRQHandler(void) WEAK_DEFAULT;           /* 22 */
void RCM_IRQHandler(void) WEAK_DEFAULT;                /* 23 */
void LPI2C0_Master_IRQHandler(void) WEAK_DEFAULT;      /* 24 */
void LPI2C0_Slave_IRQHandler(void) WEAK_DEFAULT;       /* 25 */
void LPSPI0_IRQHandler(void) WEAK_DEFAULT;             /* 26 */
void LPSPI1_IRQHandler(void) WEAK_DEFAULT;             /* 27 */
void LPSPI2_IRQHandler(void) WEAK_DEFAULT;             /* 28 */
void LPUART0_RxTx_IRQHandler(void) WEAK_DEFAULT;       /* 31 */
void LPUART1_RxTx_IRQHandler(void) WEAK_DEFAULT;       /* 33 */
void LPUART2_RxTx_IRQHandler(void) WEAK_DEFAULT;       /* 35 */
void ADC0_IRQHandler(void) WEAK_DEFAULT;               /* 39 */
void ADC1_IRQHandler(void) WEAK_DEFAULT;               /* 40 */
void CMP0_IRQHandler(void) WEAK_DEFAULT;               /* 41 */
void ERM_single_fault_IRQHandler(void) WEAK_DEFAULT;   /* 44 */
void ERM_double_fault_IRQHandler(void) WEAK_DEFAULT;   /* 45 */
void RTC_IRQHandler(void) WEAK_DEFAULT;                /* 46 */
void RTC_Seconds_IRQHandler(void) WEAK_DEFAULT;        /* 47 */
void LPIT0_Ch0_IRQHandler(void) WEAK_DEFAULT;          /* 48 */
void LPIT0_Ch1_IRQHandler(void) WEAK_DEFAULT;          /* 49 */
void LPIT0_Ch2_IRQHandler(void) WEAK_DEFAULT;          /* 50 */
void LPIT0_Ch3_IRQHandler(void) WEAK_DEFAULT;          /* 51 */
void PDB0_IRQHandler(void) WEAK_DEFAULT;               /* 52 */
void SCG_IRQHandler(void) WEAK_DEFAULT;                /* 57 */
void LPTMR0_IRQHandler(void) WEAK_DEFAULT;             /* 58 */
void PORTA_IRQHandler(void) WEAK_DEFAULT;              /* 59 */
void PORTB_IRQHandler(void) WEAK_DEFAULT;              /* 60 */
void PORTC_IRQHandler(void) WEAK_DEFAULT;              /* 61 */
void PORTD_IRQHandler(void) WEAK_DEFAULT;              /* 62 */
void PORTE_IRQHandler(void) WEAK_DEFAULT;              /* 63 */
void SWI_IRQHandler(void) WEAK_DEFAULT;                /* 64 */
void PDB1_IRQHandler(void) WEAK_DEFAULT;               /* 68 */
void FLEXIO_IRQHandler(void) WEAK_DEFAULT;             /* 69 */
void CAN0_ORed_IRQHandler(void) WEAK_DEFAULT;          /* 78 */
void CAN0_Error_IRQHandler(void) WEAK_DEFAULT;         /* 79 */
void CAN0_Wake_Up_IRQHandler(void) WEAK_DEFAULT;       /* 80 */
void CAN0_ORed_0_15_MB_IRQHandler(void) WEAK_DEFAULT;  /* 81 */
void CAN0_ORed_16_31_MB_IRQHandler(void) WEAK_DEFAULT; /* 82 */
void CAN1_ORed_IRQHandler(void) WEAK_DEFAULT;          /* 85 */
void CAN1_Error_IRQHandler(void) WEAK_DEFAULT;         /* 86 */
void CAN1_ORed_0_15_MB_IRQHandler(void) WEAK_DEFAULT;  /* 88 */
void CAN2_ORed_IRQHandler(void) WEAK_DEFAULT;          /* 92 */
void CAN2_Error_IRQHandler(void) WEAK_DEFAULT;         /* 93 */
void CAN2_ORed_0_15_MB_IRQHandler(void) WEAK_DEFAULT;  /* 95 */
void FTM0_Ch0_Ch1_IRQHandler(void) WEAK_DEFAULT;       /* 99 */
void FTM0_Ch2_Ch3_IRQHandler(void) WEAK_DEFAULT;       /* 100 */
void FTM0_Ch4_Ch5_IRQHandler(void) WEAK_DEFAULT;       /* 101 */
void FTM0_Ch6_Ch7_IRQHandler(void) WEAK_DEFAULT;       /* 102 */
void FTM0_Fault_IRQHandler(void) WEAK_DEFAULT;         /* 103 */
void FTM0_Ovf_Reload_IRQHandler(void) WEAK_DEFAULT;    /* 104 */
void FTM1_Ch0_Ch1_IRQHandler(void) WEAK_DEFAULT;       /* 105 */
void FTM1_Ch2_Ch3_IRQHandler(void) WEAK_DEFAULT;       /* 106 */
void FTM1_Ch4_Ch5_IRQHandler(void) WEAK_DEFAULT;       /* 107 */
void FTM1_Ch6_Ch7_IRQHandler(void) WEAK_DEFAULT;       /* 108 */
void FTM1_Fault_IRQHandler(void) WEAK_DEFAULT;         /* 109 */
void FTM1_Ovf_Reload_IRQHandler(void) WEAK_DEFAULT;    /* 110 */
void FTM2_Ch0_Ch1_IRQHandler(void) WEAK_DEFAULT;       /* 111 */
void FTM2_Ch2_Ch3_IRQHandler(void) WEAK_DEFAULT;       /* 112 */
void FTM2_Ch4_Ch5_IRQHandler(void) WEAK_DEFAULT;       /* 113 */
void FTM2_Ch6_Ch7_IRQHandler(void) WEAK_DEFAULT;       /* 114 */
void FTM2_Fault_IRQHandler(void) WEAK_DEFAULT;         /* 115 */
void FTM2_Ovf_Reload_IRQHandler(void) WEAK_DEFAULT;    /* 116 */
void FTM3_Ch0_Ch1_IRQHandler(void) WEAK_DEFAULT;       /* 117 */
void FTM3_Ch2_Ch3_IRQHandler(void) WEAK_DEFAULT;       /* 118 */
void FTM3_Ch4_Ch5_IRQHandler(void) WEAK_DEFAULT;       /* 119 */
void FTM3_Ch6_Ch7_IRQHandler(void) WEAK_DEFAULT;       /* 120 */
void FTM3_Fault_IRQHandler(void) WEAK_DEFAULT;         /* 121 */
void FTM3_Ovf_Reload_IRQHandler(void) WEAK_DEFAULT;    /* 122 */

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
        DMA0_IRQHandler,               /* IRQ 0 */
        DMA1_IRQHandler,               /* IRQ 1 */
        DMA2_IRQHandler,               /* IRQ 2 */
        DMA3_IRQHandler,               /* IRQ 3 */
        DMA4_IRQHandler,               /* IRQ 4 */
        DMA5_IRQHandler,               /* IRQ 5 */
        DMA6_IRQHandler,               /* IRQ 6 */
        DMA7_IRQHandler,               /* IRQ 7 */
        DMA8_IRQHandler,               /* IRQ 8 */
        DMA9_IRQHandler,               /* IRQ 9 */
        DMA10_IRQHandler,              /* IRQ 10 */
        DMA11_IRQHandler,              /* IRQ 11 */
        DMA12_IRQHandler,              /* IRQ 12 */
        DMA13_IRQHandler,              /* IRQ 13 */
        DMA14_IRQHandler,              /* IRQ 14 */
        DMA15_IRQHandler,              /* IRQ 15 */
        DMA_Error_IRQHandler,          /* IRQ 16 */
        MCM_IRQHandler,                /* IRQ 17 */
        FTFC_IRQHandler,               /* IRQ 18 */
        Read_Collision_IRQHandler,     /* IRQ 19 */
        LVD_LVW_IRQHandler,            /* IRQ 20 */
        FTFC_Fault_IRQHandler,         /* IRQ 21 */
        WDOG_EWM_IRQHandler,           /* IRQ 22 */
        RCM_IRQHandler,                /* IRQ 23 */
        LPI2C0_Master_IRQHandler,      /* IRQ 24 */
        LPI2C0_Slave_IRQHandler,       /* IRQ 25 */
        LPSPI0_IRQHandler,             /* IRQ 26 */
        LPSPI1_IRQHandler,             /* IRQ 27 */
        LPSPI2_IRQHandler,             /* IRQ 28 */
        0,                             /* IRQ 29 */
        0,                             /* IRQ 30 */
        LPUART0_RxTx_IRQHandler,       /* IRQ 31 */
        0,                             /* IRQ 32 */
        LPUART1_RxTx_IRQHandler,       /* IRQ 33 */
        0,                             /* IRQ 34 */
        LPUART2_RxTx_IRQHandler,       /* IRQ 35 */
        0,                             /* IRQ 36 */
        0,                             /* IRQ 37 */
        0,                             /* IRQ 38 */
        ADC0_IRQHandler,               /* IRQ 39 */
        ADC1_IRQHandler,               /* IRQ 40 */
        CMP0_IRQHandler,               /* IRQ 41 */
        0,                             /* IRQ 42 */
        0,                             /* IRQ 43 */
        ERM_single_fault_IRQHandler,   /* IRQ 44 */
        ERM_double_fault_IRQHandler,   /* IRQ 45 */
        RTC_IRQHandler,                /* IRQ 46 */
        RTC_Seconds_IRQHandler,        /* IRQ 47 */
        LPIT0_Ch0_IRQHandler,          /* IRQ 48 */
        LPIT0_Ch1_IRQHandler,          /* IRQ 49 */
        LPIT0_Ch2_IRQHandler,          /* IRQ 50 */
        LPIT0_Ch3_IRQHandler,          /* IRQ 51 */
        PDB0_IRQHandler,               /* IRQ 52 */
        0,                             /* IRQ 53 */
        0,                             /* IRQ 54 */
        0,                             /* IRQ 55 */
        0,                             /* IRQ 56 */
        SCG_IRQHandler,                /* IRQ 57 */
        LPTMR0_IRQHandler,             /* IRQ 58 */
        PORTA_IRQHandler,              /* IRQ 59 */
        PORTB_IRQHandler,              /* IRQ 60 */
        PORTC_IRQHandler,              /* IRQ 61 */
        PORTD_IRQHandler,              /* IRQ 62 */
        PORTE_IRQHandler,              /* IRQ 63 */
        SWI_IRQHandler,                /* IRQ 64 */
        0,                             /* IRQ 65 */
        0,                             /* IRQ 66 */
        0,                             /* IRQ 67 */
        PDB1_IRQHandler,               /* IRQ 68 */
        FLEXIO_IRQHandler,             /* IRQ 69 */
        0,                             /* IRQ 70 */
        0,                             /* IRQ 71 */
        0,                             /* IRQ 72 */
        0,                             /* IRQ 73 */
        0,                             /* IRQ 74 */
        0,                             /* IRQ 75 */
        0,                             /* IRQ 76 */
        0,                             /* IRQ 77 */
        CAN0_ORed_IRQHandler,          /* IRQ 78 */
        CAN0_Error_IRQHandler,         /* IRQ 79 */
        CAN0_Wake_Up_IRQHandler,       /* IRQ 80 */
        CAN0_ORed_0_15_MB_IRQHandler,  /* IRQ 81 */
        CAN0_ORed_16_31_MB_IRQHandler, /* IRQ 82 */
        0,                             /* IRQ 83 */
        0,                             /* IRQ 84 */
        CAN1_ORed_IRQHandler,          /* IRQ 85 */
        CAN1_Error_IRQHandler,         /* IRQ 86 */
        0,                             /* IRQ 87 */
        CAN1_ORed_0_15_MB_IRQHandler,  /* IRQ 88 */
        0,                             /* IRQ 89 */
        0,                             /* IRQ 90 */
        0,                             /* IRQ 91 */
        CAN2_ORed_IRQHandler,          /* IRQ 92 */
        CAN2_Error_IRQHandler,         /* IRQ 93 */
        0,                             /* IRQ 94 */
        CAN2_ORed_0_15_MB_IRQHandler,  /* IRQ 95 */
        0,                             /* IRQ 96 */
        0,                             /* IRQ 97 */
        0,                             /* IRQ 98 */
        FTM0_Ch0_Ch1_IRQHandler,       /* IRQ 99 */
        FTM0_Ch2_Ch3_IRQHandler,       /* IRQ 100 */
        FTM0_Ch4_Ch5_IRQHandler,       /* IRQ 101 */
        FTM0_Ch6_Ch7_IRQHandler,       /* IRQ 102 */
        FTM0_Fault_IRQHandler,         /* IRQ 103 */
        FTM0_Ovf_Reload_IRQHandler,    /* IRQ 104 */
        FTM1_Ch0_Ch1_IRQHandler,       /* IRQ 105 */
        FTM1_Ch2_Ch3_IRQHandler,       /* IRQ 106 */
        FTM1_Ch4_Ch5_IRQHandler,       /* IRQ 107 */
        FTM1_Ch6_Ch7_IRQHandler,       /* IRQ 108 */
        FTM1_Fault_IRQHandler,         /* IRQ 109 */
        FTM1_Ovf_Reload_IRQHandler,    /* IRQ 110 */
        FTM2_Ch0_Ch1_IRQHandler,       /* IRQ 111 */
        FTM2_Ch2_Ch3_IRQHandler,       /* IRQ 112 */
        FTM2_Ch4_Ch5_IRQHandler,       /* IRQ 113 */
        FTM2_Ch6_Ch7_IRQHandler,       /* IRQ 114 */
        FTM2_Fault_IRQHandler,         /* IRQ 115 */
        FTM2_Ovf_Reload_IRQHandler,    /* IRQ 116 */
        FTM3_Ch0_Ch1_IRQHandler,       /* IRQ 117 */
        FTM3_Ch2_Ch3_IRQHandler,       /* IRQ 118 */
        FTM3_Ch4_Ch5_IRQHandler,       /* IRQ 119 */
        FTM3_Ch6_Ch7_IRQHandler,       /* IRQ 120 */
        FTM3_Fault_IRQHandler,         /* IRQ 121 */
        FTM3_Ovf_Reload_IRQHandler,    /* IRQ 122 */
    },
};

_Static_assert(sizeof(s32k1_vectors) == 4u * (16u + 123u), "vector table size");
