/*
 * rt_hooks.c - the default (weak) hooks of both startups (arm/startup_cm.c, riscv/crt0.S); see
 * rt.h. A board or test port overrides one by defining a function of the same name. `wfi` is
 * an instruction on both architectures.
 */
#include <stdint.h>

#include "inclino/rt.h"

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
