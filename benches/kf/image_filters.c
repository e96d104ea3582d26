/*
 * image_filters.c - the filter measurement images (cross targets only; never run).
 *
 * One image per filter, chosen by KF_IMAGE at compile time, each linking only what a product
 * links to run that filter on one axis at 819.2 SPS. The build's size report
 * (<image>.size.txt: flash and RAM per module; the instance is the image's own .bss) and stack
 * report (<image>.stack.txt) are the figures of docs/benchmarks.md, "Kalman and tilt":
 *   1 kf_image_ma      moving average of N = 82 (inclino_avg), the comparison
 *   2 kf_image_fixed   the fixed scalar Kalman filter (inclino_kf, generic filter, n = 1)
 *   3 kf_image_adapt   the adaptive filter of [CN110567483] (inclino_kf, kf_adapt, one axis)
 *   4 kf_image_kf2     the generic filter with n = 2 (angle, bias), predict + update
 *   5 kf_image_tilt    roll and pitch (inclino_tilt, all three modes: tilt_step)
 */
#include <stdbool.h>
#include <stdint.h>

#if KF_IMAGE == 1
#include "inclino/avg.h"
#elif KF_IMAGE == 5
#include "inclino/tilt.h"
#else
#include "inclino/kf.h"
#include "inclino/kf_adapt.h"
#endif

volatile int32_t img_in[6];  /* stands in for the sensor */
volatile int32_t img_out[2]; /* and for the consumer */

#if KF_IMAGE == 1
static AVG_MOVING_DEFINE(ma, 82);
#elif KF_IMAGE == 2 || KF_IMAGE == 4
static struct kf filt;
#elif KF_IMAGE == 3
static struct kf_adapt filt;
#else
static struct tilt filt;
#endif

int main(void);

int main(void)
{
#if KF_IMAGE == 1
    if (avg_moving_init(&ma, ma_line, 82u, 82u) != 0) return 1;
    for (;;) {
        int32_t y;
        bool full;
        (void)avg_moving_push(&ma, img_in[0], &y, &full);
        img_out[0] = y;
    }
#elif KF_IMAGE == 2
    static const fx_q30_t one = FX_Q30_ONE;
    static const int64_t q = KF_P_ONE_Q16 / 1000000, r = KF_P_ONE_Q16 / 1000, p0 = KF_P_ONE_Q16;
    static const struct kf_model m = {1, 0, &one, 0, &q};
    if (kf_init(&filt, 1u, 0, &p0) != 0) return 1;
    for (;;) {
        (void)kf_predict(&filt, &m, 0);
        (void)kf_update_row(&filt, &one, r, img_in[0]);
        img_out[0] = kf_x(&filt, 0);
    }
#elif KF_IMAGE == 3
    struct kf_adapt_config c = {32u,
                                KF_P_ONE_Q16 / 100000000,
                                41000,
                                KF_P_ONE_Q16 / 5000,
                                -FX_Q16_INT(238),
                                KF_P_ONE_Q16 / 5000};
    if (kf_adapt_init(&filt, &c) != 0) return 1;
    for (;;) {
        int32_t y;
        (void)kf_adapt_process(&filt, img_in[0], &y, 0);
        img_out[0] = y;
    }
#elif KF_IMAGE == 4
    static const fx_q30_t a[4] = {FX_Q30_ONE, -1310720, 0, FX_Q30_ONE}, b[2] = {1310720, 0};
    static const fx_q30_t h[2] = {FX_Q30_ONE, 0};
    static const int64_t q[4] = {KF_P_ONE_Q16 / 800000, 0, 0, KF_P_ONE_Q16 / 4000000000};
    static const int64_t p0[4] = {KF_P_ONE_Q16, 0, 0, KF_P_ONE_Q16};
    static const struct kf_model m = {2, 1, a, b, q};
    if (kf_init(&filt, 2u, 0, p0) != 0) return 1;
    for (;;) {
        int32_t u = img_in[1];
        (void)kf_predict(&filt, &m, &u);
        (void)kf_update_row(&filt, h, KF_P_ONE_Q16, img_in[0]);
        img_out[0] = kf_x(&filt, 0);
    }
#else
    static struct tilt_config c; /* an application keeps its configuration static too */
    if (tilt_config_default(&c, 1220703u) != 0) return 1;
    c.mode = (uint32_t)img_in[5] % 3u; /* every mode is reachable */
    if (tilt_init(&filt, &c) != 0) return 1;
    for (;;) {
        struct tilt_input in;
        struct tilt_output o;
        unsigned i;
        for (i = 0; i < 3u; i++) {
            in.accel_g[i] = img_in[i];
            in.gyro_dps[i] = img_in[3u + i];
        }
        in.flags = 0;
        (void)tilt_step(&filt, &in, 1220703u, &o);
        img_out[0] = o.angle_deg[0];
        img_out[1] = o.angle_deg[1];
    }
#endif
}
