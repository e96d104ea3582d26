/* epb_image_test.c - see epb_image_test.h. */
#include "epb_image_test.h"

void epb_test_part(struct sim_calpart_params *p)
{
    sim_calpart_ideal(p);
    p->acc_bias[0].y0 = 0.02;
    p->acc_bias[1].y0 = -0.01;
    p->acc_bias[2].y0 = 0.015;
    p->acc_scale[0].y0 = 1.02;
    p->acc_scale[2].y0 = 0.99;
    p->acc_noise_g = 0.002;
}

void epb_test_board(struct epb_image_board *b, struct epb_rig *rig, void (*hook)(void),
                    const struct calstore_config *store)
{
    b->hal = &rig->board.hal;
    b->spi = &rig->board.spi.bus;
    b->cs = SIM_BOARD_CS(0);
    b->dr = SIM_BOARD_DR(0);
    b->per_result = hook;
    b->store = store;
}
