/*
 * s32k1_startup.h - what the S32K1 boards' startup (startup_s32k1.c) and vector tables
 * (boards/<board>/vectors.c) share. Not a module header: compiled into the images only.
 */
#ifndef INCLINO_S32K1_STARTUP_H
#define INCLINO_S32K1_STARTUP_H

#include <stdint.h>

#include "inclino/compiler.h"
/* Linker-script symbols (s32k1-sections.ld). */
extern uint32_t __data_load__[];
extern uint32_t __data_start__[];
extern uint32_t __data_end__[];
extern uint32_t __bss_start__[];
extern uint32_t __bss_end__[];
extern uint32_t __stack_top__[];

typedef void (*s32k1_handler)(void);

/* Vector table: initial SP, then 15 core exceptions and the part's IRQs (<= 123). */
struct s32k1_vector_table {
    const uint32_t *initial_sp;
    s32k1_handler handler[15 + S32K1_IRQS];
};

/*
 * Start-up code: s32k1-sections.ld places the sections .text.s32k_early.* first after the vector
 * table, before the other code that fills the space up to the flash configuration field at
 * 0x400 (what does not fit goes on after it). By section name, not by object file, so the
 * placement holds with link-time optimisation too (one link-time object, no startup_s32k1.c.obj);
 * one section per function, so --gc-sections still drops what an image does not reach.
 */
#define S32K1_EARLY(name) __attribute__((section(".text.s32k_early." #name)))

/*
 * Kept out of its caller: with LTO gcc would inline the whole bring-up and the main loop into
 * Reset_Handler, whose one frame then holds the locals of every step at once (the stack report's
 * worst case grows). Each step keeps its own frame, live only while it runs.
 */
#define S32K1_STEP INC_NOINLINE

void Reset_Handler(void);
void Default_Handler(void);
int main(void);

#endif /* INCLINO_S32K1_STARTUP_H */
