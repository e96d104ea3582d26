/*
 * main.c - the S32K116EVB image: the EPB application on the board (boards/s32k1/s32k_image.c)
 * and this part's vectors: one PORT vector for all five ports, LPIT0 (one vector for all
 * channels), LPSPI0 (the LPSPI engine's wake-up, when an image brings it up). The startup (boards/s32k1/startup_s32k1.c) has configured the watchdog before main.
 */
#include <stdint.h>

#include "s32k_image.h"

void PORT_IRQHandler(void);
void LPIT0_IRQHandler(void);
void LPSPI0_IRQHandler(void);

S32K1_EARLY(PORT_IRQHandler) void PORT_IRQHandler(void)
{
    uint32_t port;
    for (port = 0; port < S32K_PORT_COUNT; port++) {
        s32k_board_port_isr(&s32k_image_board, port);
    }
}

S32K1_EARLY(LPIT0_IRQHandler) void LPIT0_IRQHandler(void)
{
    s32k_board_lpit_isr(&s32k_image_board);
}

S32K1_EARLY(LPSPI0_IRQHandler) void LPSPI0_IRQHandler(void)
{
    s32k_board_lpspi_isr(&s32k_image_board);
}

S32K1_EARLY(main) S32K1_STEP int main(void)
{
    s32k_epb_main(&s32k_board_s32k116evb);
    return 0;
}
