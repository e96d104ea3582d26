/*
 * A fault must end the test with a failure, never hang it: the program executes a permanently
 * undefined instruction; the board's fault path (rt_fault) reports it and exits QEMU with
 * BOARD_FAULT_STATUS (126) on Cortex-M, 1 on rv32. Registered with EXPECT_STATUS, so a hang
 * (timeout), a normal exit or any other status fails.
 */
#include "unit.h"

int main(void)
{
    unit_checks++; /* the harness's "no checks" rule is not the point here */
#if defined(__arm__)
    __asm volatile("udf #0");
#elif defined(__riscv)
    __asm volatile("unimp");
#endif
    return 0;
}
