/*
 * main.c - the S32K144EVB EPB image: the EPB application on the board
 * (boards/s32k1/s32k_image.c); the vectors are in isr.c. The startup
 * (boards/s32k1/startup_s32k1.c) has configured the watchdog before main.
 */
#include "s32k_image.h"

S32K1_EARLY(main) S32K1_STEP int main(void)
{
    s32k_epb_main(&s32k_board_s32k144evb);
    return 0;
}
