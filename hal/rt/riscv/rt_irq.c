/*
 * rt_irq.c - the default (weak) interrupt entry of the rv32 startup (crt0.S); see rt.h.
 */
#include <stdint.h>

#include "inclino/rt.h"

/* An interrupt arrived (mcause with bit 31 set); a HAL or platform port defines this. */
void rt_irq_handler(uint32_t mcause);

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
