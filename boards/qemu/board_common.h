/* board_common.h - shared by the QEMU boards (private to boards/qemu). */
#ifndef INCLINO_BOARD_COMMON_H
#define INCLINO_BOARD_COMMON_H

#include <stdint.h>

#include "board.h"
#include "inclino/rt.h"

/*
 * Fill the stack below sp with BOARD_STACK_PATTERN. Called from rt_init_hook with its own stack
 * pointer: everything above it belongs to the startup's frames, everything below is free.
 */
void board_paint_stack(uintptr_t sp);

#endif /* INCLINO_BOARD_COMMON_H */
