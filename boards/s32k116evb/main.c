/*
 * main.c - the S32K116EVB image: the board (boards/s32k1: clocks, pins, HAL port, bit-banged
 * SPI) and the EPB application (boards/generic/epb_image.c) on it; the PORT and LPIT0 vectors.
 * The startup (boards/s32k1/startup_s32k1.c) has configured the watchdog before main.
 */
#include <stddef.h>
#include <stdint.h>

#include "epb_image.h"
#include "inclino/s32k_board.h"
#include "inclino/s32k_wdog.h"

void PORT_IRQHandler(void);
void LPIT0_IRQHandler(void);
void PORTA_IRQHandler(void);
void PORTB_IRQHandler(void);
void PORTC_IRQHandler(void);
void PORTD_IRQHandler(void);
void PORTE_IRQHandler(void);
void LPIT0_Ch1_IRQHandler(void);

static struct s32k_board board;

/* One vector for all five ports. */
void PORT_IRQHandler(void)
{
    uint32_t port;
    for (port = 0; port < S32K_PORT_COUNT; port++) {
        s32k_board_port_isr(&board, port);
    }
}

void LPIT0_IRQHandler(void)
{
    s32k_board_lpit_isr(&board);
}

int main(void)
{
    struct epb_image_board eb;
    if (s32k_board_init(&board, &s32k_board_s32k116evb, S32K_BOARD_SPI_BITBANG, true) != INC_OK) {
        for (;;) {
            /* no refresh: the watchdog resets the part and the bring-up is tried again */
        }
    }
    eb.hal = &board.hal;
    eb.spi = board.spi;
    eb.cs = board.desc->pins.cs_imu;
    eb.dr = board.desc->pins.dr_imu;
    eb.per_result = s32k_wdog_refresh;
    epb_image_run_on(&eb);
    return 0;
}
