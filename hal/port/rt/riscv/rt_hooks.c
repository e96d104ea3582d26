/*
 * rt_hooks.c - default (weak) hooks of the rv32 startup (crt0.S); see rt.h.
 */
#include <stdint.h>

#include "inclino/rt.h"

/* An interrupt arrived (mcause with bit 31 set); a HAL or platform port defines this. */
void rt_irq_handler(uint32_t mcause);

__attribute__((weak)) void rt_init_hook(void)
{
}

__attribute__((weak)) void rt_exit_hook(int status)
{
    (void)status;
    for (;;) {
        __asm volatile("wfi");
    }
}

__attribute__((weak)) void rt_fault(uint32_t cause, uintptr_t fault_sp)
{
    (void)cause;
    (void)fault_sp;
    for (;;) {
    }
}

/*
 * No port claimed interrupts but one was enabled and taken: that is a fault too (returning would
 * take it again at once). rt_fault does not return; the stack is not reset here because the
 * interrupt frame is intact.
 */
__attribute__((weak)) void rt_irq_handler(uint32_t mcause)
{
    uintptr_t sp;
    __asm volatile("mv %0, sp" : "=r"(sp));
    rt_fault(mcause, sp);
}
