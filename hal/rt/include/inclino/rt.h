/*
 * rt.h - the freestanding run-time of Inclino's cross images: startup hooks and the memory
 * functions gcc may call.
 *
 * The cross images link with -nostdlib -lgcc: no C library. gcc still emits calls to memcpy,
 * memset, memmove and memcmp for struct copies, large initialisers and comparisons, even with
 * -ffreestanding, so this module provides them (mem.c, standard C semantics).
 *
 * Startup (one per architecture, not part of the library but linked as an object into every
 * cross executable, see hal/rt/CMakeLists.txt):
 *   arm/startup_cm.c  vector table, Reset_Handler, Default_Handler for any Cortex-M
 *   riscv/crt0.S      _start (gp, sp, mtvec), trap entry for rv32
 * Both copy .data from its load address in flash, zero .bss, call rt_init_hook(), main() and
 * rt_exit_hook(main's result). The same startup runs the QEMU test boards (boards/qemu),
 * which override the hooks below; so every test under QEMU also exercises the image startup.
 *
 * Linker scripts: arm/cortex-m-sections.ld and riscv/rv32-sections.ld hold the sections; a small
 * top-level script per board or image gives MEMORY (regions FLASH and RAM) and __stack_size and
 * INCLUDEs them. RAM layout: [stack][.data][.bss][heap up to the end of RAM]; the stack sits at
 * the bottom of RAM, so an overflow runs off RAM (a bus fault on most parts) instead of silently
 * overwriting .data.
 */
#ifndef INCLINO_RT_H
#define INCLINO_RT_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/*
 * Called by the startup after .data and .bss are initialised, before main(). Weak; the default
 * does nothing. The QEMU boards paint the stack and initialise newlib here.
 */
void rt_init_hook(void);

/*
 * Called with main()'s return value when main() returns. Weak; the default sleeps forever (on
 * an MCU, main never returns). The QEMU boards report the stack high-water mark and exit QEMU
 * with this status.
 */
void rt_exit_hook(int status);

/*
 * Called for every exception or interrupt that has no handler of its own (Cortex-M: the
 * exception number from IPSR, e.g. 3 = HardFault; RISC-V: mcause). fault_sp is the stack
 * pointer at the time of the fault (Cortex-M: it points at the hardware's exception frame r0-r3,
 * r12, lr, pc, xPSR). It runs on a usable stack even after an overflow: the startup resets the
 * stack pointer to the top of the stack region when the faulting one is within 512 bytes of the
 * bottom (Cortex-M) or always (RISC-V, where the faulting pc is in mepc). Weak; the default spins forever so a
 * debugger finds the arguments in the first two argument registers. Must not return.
 */
void rt_fault(uint32_t cause, uintptr_t fault_sp);

/* The linker-script symbols the startup and the boards use (addresses only, never values). */
extern uint32_t __data_load__[];  /* load address of .data in FLASH */
extern uint32_t __data_start__[]; /* .data in RAM, word aligned */
extern uint32_t __data_end__[];
extern uint32_t __bss_start__[]; /* .bss, word aligned */
extern uint32_t __bss_end__[];
extern uint32_t __stack_bottom__[]; /* lowest address of the stack region */
extern uint32_t __stack_top__[];    /* initial stack pointer (one past the highest word) */
extern uint32_t __heap_start__[];   /* free RAM after .bss, up to __heap_end__ (end of RAM) */
extern uint32_t __heap_end__[];

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_RT_H */
