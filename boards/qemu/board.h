/*
 * board.h - what the QEMU test boards (board_arm.c, board_rv32.c) offer the tests.
 *
 * The boards run every cross test on the image startup of hal/rt (see rt.h) and add:
 *   - stack painting: the whole stack region is filled with BOARD_STACK_PATTERN at reset; at exit
 *     the board prints "stack high-water: N of M bytes" (N = bytes ever used, found by scanning
 *     for the first overwritten word) and fails the test if the whole stack was used;
 *   - faults: any exception without a handler prints "FAULT: ..." and exits QEMU with status
 *     BOARD_FAULT_STATUS (Cortex-M) or 1 (rv32, whose QEMU semihosting reports only 0 or 1), so a
 *     fault never hangs a test;
 *   - the exit status of main() becomes QEMU's exit status (semihosting).
 * Tests that link the board see INCLINO_QEMU_BOARD defined.
 */
#ifndef INCLINO_BOARD_H
#define INCLINO_BOARD_H

#include <stddef.h>
#include <stdint.h>

#define BOARD_STACK_PATTERN 0xA5A5A5A5u
#define BOARD_FAULT_STATUS 126

/* Bytes of stack used so far (highest extent since reset), and the stack's size. */
size_t board_stack_high_water(void);
size_t board_stack_size(void);

#endif /* INCLINO_BOARD_H */
