/*
 * isr.c - the S32K144's interrupt vectors the S32K1 port uses, shared by this board's images:
 * one PORT vector per port (PORTA..PORTE), LPIT0 channel 1 (the time base) and LPSPI0 (the
 * LPSPI engine's wake-up, when an image brings it up), each calling the
 * bring-up's ISR on s32k_image_board (boards/s32k1/s32k_image.h).
 */
#include "s32k_image.h"

void PORTA_IRQHandler(void);
void PORTB_IRQHandler(void);
void PORTC_IRQHandler(void);
void PORTD_IRQHandler(void);
void PORTE_IRQHandler(void);
void LPIT0_Ch1_IRQHandler(void);
void LPSPI0_IRQHandler(void);

S32K1_EARLY(PORTA_IRQHandler) void PORTA_IRQHandler(void)
{
    s32k_board_port_isr(&s32k_image_board, 0u);
}

S32K1_EARLY(PORTB_IRQHandler) void PORTB_IRQHandler(void)
{
    s32k_board_port_isr(&s32k_image_board, 1u);
}

S32K1_EARLY(PORTC_IRQHandler) void PORTC_IRQHandler(void)
{
    s32k_board_port_isr(&s32k_image_board, 2u);
}

S32K1_EARLY(PORTD_IRQHandler) void PORTD_IRQHandler(void)
{
    s32k_board_port_isr(&s32k_image_board, 3u);
}

S32K1_EARLY(PORTE_IRQHandler) void PORTE_IRQHandler(void)
{
    s32k_board_port_isr(&s32k_image_board, 4u);
}

S32K1_EARLY(LPIT0_Ch1_IRQHandler) void LPIT0_Ch1_IRQHandler(void)
{
    s32k_board_lpit_isr(&s32k_image_board);
}

S32K1_EARLY(LPSPI0_IRQHandler) void LPSPI0_IRQHandler(void)
{
    s32k_board_lpspi_isr(&s32k_image_board);
}
