/*
 * board_rv32.c - the rv32 QEMU test board (machine virt, -bios none); see board.h.
 *
 * The reset path is the image startup (hal/rt/riscv/crt0.S: gp, sp, mtvec, .data copy,
 * .bss zeroing); this file supplies its hooks: paint the stack, turn main()'s result into QEMU's
 * exit status (0 or 1, see rv32/mini_libc.c) and make every trap a reported failure.
 */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "board_common.h"

void rv32_exit_hooks(void);

void rv32_exit_hooks(void)
{
    size_t used = board_stack_high_water();
    size_t size = board_stack_size();
    printf("stack high-water: %u of %u bytes\n", (unsigned)used, (unsigned)size);
    if (used >= size) {
        printf("FAIL: stack overflow (all %u bytes of the stack were used)\n", (unsigned)size);
        abort(); /* not exit(): that would run this hook again */
    }
}

void rt_init_hook(void)
{
    uintptr_t sp;
    __asm volatile("mv %0, sp" : "=r"(sp));
    board_paint_stack(sp);
}

void rt_exit_hook(int status)
{
    exit(status);
}

/* A trap (mcause without the interrupt bit) or an unclaimed interrupt: report and fail. */
void rt_fault(uint32_t cause, uintptr_t fault_sp)
{
    uint32_t mepc;
    /* Zicsr: see hal/rt/riscv/crt0.S. */
    __asm volatile(".option push\n\t.option arch, +zicsr\n\tcsrr %0, mepc\n\t.option pop"
                   : "=r"(mepc));
    printf("FAULT: mcause 0x%lx, mepc 0x%lx, sp 0x%lx\n", (unsigned long)cause, (unsigned long)mepc,
           (unsigned long)fault_sp);
    (void)fflush(stdout);
    abort();
}
