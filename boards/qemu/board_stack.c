/* board_stack.c - stack painting and high-water mark of the QEMU boards; see board.h. */
#include "board_common.h"

void board_paint_stack(uintptr_t sp)
{
    uint32_t *p;
    for (p = __stack_bottom__; (uintptr_t)p < sp; p++) {
        *p = BOARD_STACK_PATTERN;
    }
}

size_t board_stack_size(void)
{
    return (size_t)((uintptr_t)__stack_top__ - (uintptr_t)__stack_bottom__);
}

size_t board_stack_high_water(void)
{
    const uint32_t *p = __stack_bottom__;
    /* The stack grows down: the words never written are still painted at the bottom. */
    while (p != __stack_top__ && *p == BOARD_STACK_PATTERN) {
        p++;
    }
    return (size_t)((uintptr_t)__stack_top__ - (uintptr_t)p);
}
