/*
 * startup_cm.c - reset and exception entry for any Cortex-M (M0+, M3, M4F); see rt.h.
 *
 * The vector table holds the 16 architectural entries and 32 external interrupts (IRQ0..31,
 * the most an M0+ has). Every handler is a weak alias of Default_Handler, so a HAL port or an
 * MCU-family port overrides one by defining a function of the same name (SysTick_Handler,
 * IRQ5_Handler, ...). A family port with more interrupts brings its own vector table.
 *
 * ARMv6-M has no MemManage, BusFault, UsageFault or DebugMon exception; their entries are
 * reserved there and never taken, so one table serves every core.
 */
#include <stdint.h>

#include "inclino/rt.h"

int main(void);
void Reset_Handler(void);
void Default_Handler(void);

#define RT_WEAK_ALIAS __attribute__((weak, alias("Default_Handler")))
void NMI_Handler(void) RT_WEAK_ALIAS;
void HardFault_Handler(void) RT_WEAK_ALIAS;
void MemManage_Handler(void) RT_WEAK_ALIAS;
void BusFault_Handler(void) RT_WEAK_ALIAS;
void UsageFault_Handler(void) RT_WEAK_ALIAS;
void SVC_Handler(void) RT_WEAK_ALIAS;
void DebugMon_Handler(void) RT_WEAK_ALIAS;
void PendSV_Handler(void) RT_WEAK_ALIAS;
void SysTick_Handler(void) RT_WEAK_ALIAS;
void IRQ0_Handler(void) RT_WEAK_ALIAS;
void IRQ1_Handler(void) RT_WEAK_ALIAS;
void IRQ2_Handler(void) RT_WEAK_ALIAS;
void IRQ3_Handler(void) RT_WEAK_ALIAS;
void IRQ4_Handler(void) RT_WEAK_ALIAS;
void IRQ5_Handler(void) RT_WEAK_ALIAS;
void IRQ6_Handler(void) RT_WEAK_ALIAS;
void IRQ7_Handler(void) RT_WEAK_ALIAS;
void IRQ8_Handler(void) RT_WEAK_ALIAS;
void IRQ9_Handler(void) RT_WEAK_ALIAS;
void IRQ10_Handler(void) RT_WEAK_ALIAS;
void IRQ11_Handler(void) RT_WEAK_ALIAS;
void IRQ12_Handler(void) RT_WEAK_ALIAS;
void IRQ13_Handler(void) RT_WEAK_ALIAS;
void IRQ14_Handler(void) RT_WEAK_ALIAS;
void IRQ15_Handler(void) RT_WEAK_ALIAS;
void IRQ16_Handler(void) RT_WEAK_ALIAS;
void IRQ17_Handler(void) RT_WEAK_ALIAS;
void IRQ18_Handler(void) RT_WEAK_ALIAS;
void IRQ19_Handler(void) RT_WEAK_ALIAS;
void IRQ20_Handler(void) RT_WEAK_ALIAS;
void IRQ21_Handler(void) RT_WEAK_ALIAS;
void IRQ22_Handler(void) RT_WEAK_ALIAS;
void IRQ23_Handler(void) RT_WEAK_ALIAS;
void IRQ24_Handler(void) RT_WEAK_ALIAS;
void IRQ25_Handler(void) RT_WEAK_ALIAS;
void IRQ26_Handler(void) RT_WEAK_ALIAS;
void IRQ27_Handler(void) RT_WEAK_ALIAS;
void IRQ28_Handler(void) RT_WEAK_ALIAS;
void IRQ29_Handler(void) RT_WEAK_ALIAS;
void IRQ30_Handler(void) RT_WEAK_ALIAS;
void IRQ31_Handler(void) RT_WEAK_ALIAS;

typedef void (*rt_handler)(void);

/* The initial stack pointer is an address, not a handler: a struct avoids casting it. */
struct rt_vector_table {
    const uint32_t *initial_sp;
    rt_handler handler[15 + 32];
};

__attribute__((used, section(".isr_vector"))) const struct rt_vector_table rt_vectors = {
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
        IRQ0_Handler,
        IRQ1_Handler,
        IRQ2_Handler,
        IRQ3_Handler,
        IRQ4_Handler,
        IRQ5_Handler,
        IRQ6_Handler,
        IRQ7_Handler,
        IRQ8_Handler,
        IRQ9_Handler,
        IRQ10_Handler,
        IRQ11_Handler,
        IRQ12_Handler,
        IRQ13_Handler,
        IRQ14_Handler,
        IRQ15_Handler,
        IRQ16_Handler,
        IRQ17_Handler,
        IRQ18_Handler,
        IRQ19_Handler,
        IRQ20_Handler,
        IRQ21_Handler,
        IRQ22_Handler,
        IRQ23_Handler,
        IRQ24_Handler,
        IRQ25_Handler,
        IRQ26_Handler,
        IRQ27_Handler,
        IRQ28_Handler,
        IRQ29_Handler,
        IRQ30_Handler,
        IRQ31_Handler,
    },
};


void Reset_Handler(void)
{
    const uint32_t *src = __data_load__;
    uint32_t *dst;

#if defined(__ARM_FP)
    /*
     * The hard-float ABI (M4F) may place floating-point instructions in any function the
     * compiler sees fit (the firmware has none; the tests and newlib do): grant full access
     * to CP10/CP11 in CPACR (ARMv7-M ARM B3.2.20) before anything else runs.
     */
    *(volatile uint32_t *)0xE000ED88u |= (0xFu << 20);
    __asm volatile("dsb\n\tisb" ::: "memory");
#endif

    /* .data: initial values live in flash at __data_load__ (the linker script's AT>FLASH). */
    for (dst = __data_start__; dst != __data_end__; dst++, src++) {
        *dst = *src;
    }
    for (dst = __bss_start__; dst != __bss_end__; dst++) {
        *dst = 0u;
    }

    rt_init_hook();
    rt_exit_hook(main());
    for (;;) {
    }
}

/*
 * Any exception without its own handler. Naked so that it touches no stack before choosing one:
 * when the faulting stack pointer is within 512 bytes of the bottom (an overflow, or close to
 * one), the stack pointer is reset to the top of the stack region; otherwise rt_fault runs below
 * the hardware's exception frame, which stays intact for inspection. Thumb-1 only (M0+).
 */
__attribute__((naked)) void Default_Handler(void)
{
    __asm volatile("mov  r1, sp\n\t"
                   "ldr  r0, =__stack_bottom__ + 512\n\t"
                   "cmp  r1, r0\n\t"
                   "bhs  1f\n\t"
                   "ldr  r0, =__stack_top__\n\t"
                   "mov  sp, r0\n"
                   "1:\n\t"
                   "mrs  r0, ipsr\n\t"
                   "bl   rt_fault\n\t"
                   "b    .\n\t"
                   ".ltorg");
}
