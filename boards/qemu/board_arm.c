/*
 * board_arm.c - the Cortex-M QEMU test board (mps2-an385 / mps2-an386); see board.h.
 *
 * The reset path is the image startup (hal/rt/arm/startup_cm.c: .data copy, .bss zeroing);
 * this file supplies its hooks: paint the stack, initialise newlib's semihosting I/O and
 * constructors, exit(main()) so the status reaches QEMU, and fault handling. Linked with
 * -specs=nano.specs -specs=rdimon.specs -nostartfiles (see cmake/inclino_cross.cmake).
 */
#include <errno.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "board_common.h"

void initialise_monitor_handles(void);
void __libc_init_array(void);
void _init(void);
void _fini(void);
void *_sbrk(ptrdiff_t incr);

/* -nostartfiles drops crti/crtn, which define these; __libc_init_array and exit call them. */
__attribute__((weak)) void _init(void)
{
}

__attribute__((weak)) void _fini(void)
{
}

/*
 * The heap is the RAM between .bss and the end of RAM (the stack sits below .data, see
 * cortex-m-sections.ld). libgloss's weak _sbrk assumes the heap grows towards the stack pointer,
 * which is not our layout, so the board brings its own, bounded by the linker's symbols.
 */
void *_sbrk(ptrdiff_t incr)
{
    static uintptr_t brk;
    uintptr_t start = (uintptr_t)__heap_start__;
    uintptr_t end = (uintptr_t)__heap_end__;
    uintptr_t prev;
    if (brk == 0u) {
        brk = start;
    }
    if ((incr >= 0 && (uintptr_t)incr > end - brk) ||
        (incr < 0 && (uintptr_t)(-incr) > brk - start)) {
        errno = ENOMEM;
        return (void *)-1;
    }
    prev = brk;
    brk += (uintptr_t)incr;
    return (void *)prev;
}

/* ARM semihosting call (bkpt 0xAB in Thumb state): op in r0, argument block in r1. */
static int board_semihost(int op, const void *arg)
{
    register int r0 __asm("r0") = op;
    register const void *r1 __asm("r1") = arg;
    __asm volatile("bkpt 0xAB" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
}

#define SEMIHOST_SYS_WRITE0 0x04
#define SEMIHOST_SYS_EXIT 0x18
#define SEMIHOST_SYS_EXIT_EXTENDED 0x20
#define SEMIHOST_ADP_APPLICATION_EXIT 0x20026u
#define SEMIHOST_ADP_RUNTIME_ERROR 0x20023u

static void board_put_hex(char *buf, uint32_t v)
{
    int i;
    buf[0] = '0';
    buf[1] = 'x';
    for (i = 0; i < 8; i++) {
        buf[2 + i] = "0123456789abcdef"[(v >> (28 - 4 * i)) & 0xFu];
    }
    buf[10] = '\0';
}

static void board_write(const char *s)
{
    (void)board_semihost(SEMIHOST_SYS_WRITE0, s);
}

/*
 * Every exception without a handler ends here (Default_Handler, on a fresh stack). It uses
 * neither newlib nor the faulting stack: a fault inside printf must still get out.
 */
void rt_fault(uint32_t cause, uintptr_t fault_sp)
{
    static const char *const names[] = {"thread",    "reset",    "NMI",       "HardFault",
                                        "MemManage", "BusFault", "UsageFault"};
    char hex[11];
    const uint32_t block[2] = {SEMIHOST_ADP_APPLICATION_EXIT, BOARD_FAULT_STATUS};

    board_write("FAULT: exception ");
    board_put_hex(hex, cause);
    board_write(hex);
    board_write(cause < sizeof(names) / sizeof(names[0]) ? " (" : " (IRQ/other");
    if (cause < sizeof(names) / sizeof(names[0])) {
        board_write(names[cause]);
    }
    board_write("), sp ");
    board_put_hex(hex, (uint32_t)fault_sp);
    board_write(hex);
    /* The hardware stacked r0-r3, r12, lr, pc, xpsr at the faulting sp: show the pc. */
    if (fault_sp >= (uintptr_t)__stack_bottom__ && fault_sp + 32u <= (uintptr_t)__stack_top__) {
        board_write(", stacked pc ");
        board_put_hex(hex, ((const uint32_t *)fault_sp)[6]);
        board_write(hex);
    }
    board_write("\n");
    (void)board_semihost(SEMIHOST_SYS_EXIT_EXTENDED, block);
    /* Only if the extended exit is not supported: plain exit, "run-time error" = status 1. */
    (void)board_semihost(SEMIHOST_SYS_EXIT, (const void *)SEMIHOST_ADP_RUNTIME_ERROR);
    for (;;) {
    }
}

static void board_stack_report(void)
{
    size_t used = board_stack_high_water();
    size_t size = board_stack_size();
    printf("stack high-water: %u of %u bytes\n", (unsigned)used, (unsigned)size);
    if (used >= size) {
        printf("FAIL: stack overflow (all %u bytes of the stack were used)\n", (unsigned)size);
        fflush(stdout);
        _Exit(BOARD_FAULT_STATUS);
    }
    fflush(stdout);
}

void rt_init_hook(void)
{
    uintptr_t sp;
    __asm volatile("mov %0, sp" : "=r"(sp));
    board_paint_stack(sp);
    initialise_monitor_handles();
    __libc_init_array();
    (void)atexit(board_stack_report);
}

void rt_exit_hook(int status)
{
    exit(status);
}
