/*
 * image_att.c - the attitude measurement image (cross targets only; never run).
 *
 * It links what a product links to run the 3D estimator at 285.7 Hz: inclino_att with its fx
 * helpers, one instance (the image's own .bss), init once, then update every sample and the
 * quaternion and Euler getters. The build's size report (att_image.size.txt: flash and RAM per
 * module) and stack report (att_image.stack.txt) are the figures of docs/benchmarks.md,
 * "Attitude (3D estimator)".
 */
#include <stdbool.h>
#include <stdint.h>

#include "inclino/att.h"

volatile int32_t img_in[8];  /* stands in for the sensor */
volatile int32_t img_out[8]; /* and for the consumer */

static struct att est;

int main(void);

int main(void)
{
    static struct att_config c; /* an application keeps its configuration static too */
    if (att_config_default(&c, 18724571) != 0) return 1;
    if (att_init(&est, &c) != 0) return 1;
    for (;;) {
        struct att_sample s;
        int32_t q[4];
        fx_q16_t r, p;
        unsigned i;
        for (i = 0; i < 3u; i++) {
            s.gyro_dps[i] = img_in[i];
            s.acc_g[i] = img_in[3u + i];
        }
        s.sat = (uint8_t)img_in[6];
        s.veh_valid = img_in[7] != 0;
        s.speed_mps = img_in[7];
        s.yaw_rate_dps = img_in[2];
        img_out[0] = att_update(&est, &s);
        att_get_quat(&est, q);
        att_get_euler(&est, &r, &p);
        for (i = 0; i < 4u; i++)
            img_out[1u + i] = q[i];
        img_out[5] = r;
        img_out[6] = p;
        img_out[7] = att_get_bound(&est) | (att_get_valid(&est) ? 1 : 0);
    }
}
