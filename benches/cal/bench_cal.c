/*
 * bench_cal.c - benchmark driver for firmware/signal/cal (not a test; benches/cal/bench_cal.sh on the
 * host with callgrind, benches/cal/bench_cal_cm.sh on Cortex-M under QEMU -icount).
 *
 * The record is the station's record for simulated part A (golden_record_a.h: Lorentz + cubic
 * temperature models, full misalignment matrix, cubic nonlinearity), so the per-sample path runs
 * with realistic coefficients. Inputs are prepared beforehand; each function runs BENCH_N times.
 *   bench_cal <case>     case: acc_apply gyro_apply acc_set_temp tmodel_<kind> flip avg_add
 *                        turn_add (kind: linear parabola lorentz pwl lorentz_cubic)
 * On the host, callgrind --toggle-collect=<function> counts only that function and its callees.
 * On Cortex-M (BENCH_CM defined) every case is timed with SysTick and printed.
 */
#include <stdio.h>
#include <string.h>

#include "inclino/cal.h"
#include "golden_record_a.h"
#include "unit.h"

#ifdef BENCH_CM
#define BENCH_N 256
#else
#define BENCH_N 100000
#endif

static fx_q16_t in3[BENCH_N][3], temp[BENCH_N];
static int32_t pos[BENCH_N], neg[BENCH_N];
static struct calrec rec;
static struct cal_acc acc;
static struct cal_gyro gyro;
static struct calrec_tmodel models[5];
static volatile int32_t sink;

static int32_t range(uint32_t *s, int32_t lo, int32_t hi)
{
    return lo + (int32_t)(unit_rand32(s) % (uint32_t)(hi - lo + 1));
}

static int prepare(void)
{
    struct calrec_binding b;
    uint32_t s = 0x13579BDu;
    int i;
    memset(&b, 0, sizeof b);
    b.family = CALREC_FAMILY_SCA3000;
    b.product = CALREC_SCA3000_D01;
    b.revision = 0x52;
    if (calrec_decode(golden_record_a, sizeof golden_record_a, &b, &rec, NULL) != INC_OK ||
        cal_acc_init(&acc, &rec, FX_Q16_INT(25)) != INC_OK ||
        cal_gyro_init(&gyro, &rec) != INC_OK) {
        return -1;
    }
    for (i = 0; i < BENCH_N; i++) {
        /* Tilted readings within +-1.2 g (EPB slopes, vibration), rates within +-300 deg/s. */
        in3[i][0] = range(&s, -78643, 78643);
        in3[i][1] = range(&s, -78643, 78643);
        in3[i][2] = range(&s, -78643, 78643);
        temp[i] = range(&s, -30 * 65536, 70 * 65536);
        pos[i] = range(&s, 62000, 69000);
        neg[i] = range(&s, -69000, -62000);
    }
    /* One model of each kind: the record's Lorentz + cubic, and typical others. */
    memset(models, 0, sizeof models);
    models[0].kind = CALREC_TM_LINEAR;
    models[0].t_ref = 20 * 65536;
    models[0].t_span = 40 * 65536;
    models[0].p[0] = 100;
    models[0].p[1] = -400;
    models[1] = models[0];
    models[1].kind = CALREC_TM_PARABOLA;
    models[1].p[2] = 150;
    models[2].kind = CALREC_TM_LORENTZ;
    models[2].p[0] = -300;
    models[2].p[1] = 800;
    models[2].p[2] = 26 * 65536;
    models[2].p[3] = -25 * 65536;
    models[3].kind = CALREC_TM_PWL;
    models[3].n = 9;
    models[3].t_ref = -20 * 65536;
    models[3].t_span = 10 * 65536;
    for (i = 0; i < 9; i++)
        models[3].p[i] = 900 - 100 * i;
    models[4] = rec.acc_tbias[0];
    return 0;
}

#ifndef BENCH_CM

static void run(const char *c)
{
    int i;
    fx_q16_t out[3];
    if (!strcmp(c, "acc_apply")) {
        for (i = 0; i < BENCH_N; i++)
            sink += cal_acc_apply(&acc, in3[i], out) + out[0];
    } else if (!strcmp(c, "gyro_apply")) {
        for (i = 0; i < BENCH_N; i++)
            sink += cal_gyro_apply(&gyro, in3[i], out) + out[0];
    } else if (!strcmp(c, "acc_set_temp")) {
        for (i = 0; i < BENCH_N; i++)
            sink += cal_acc_set_temp(&acc, temp[i]);
    } else if (!strncmp(c, "tmodel_", 7)) {
        static const char *const kinds[5] = {"linear", "parabola", "lorentz", "pwl",
                                             "lorentz_cubic"};
        int k;
        for (k = 0; k < 5; k++) {
            if (!strcmp(c + 7, kinds[k])) {
                for (i = 0; i < BENCH_N; i++) {
                    int32_t y;
                    sink += cal_tmodel_eval(&models[k], temp[i], &y) + y;
                }
            }
        }
    } else if (!strcmp(c, "flip")) {
        for (i = 0; i < BENCH_N; i++) {
            fx_q16_t o;
            fx_q30_t g;
            sink += cal_flip(pos[i], neg[i], &o, &g) + o;
        }
    } else if (!strcmp(c, "avg_add")) {
        static struct cal_avg a;
        cal_avg_reset(&a);
        for (i = 0; i < BENCH_N; i++)
            sink += cal_avg_add(&a, in3[i]);
    } else if (!strcmp(c, "turn_add")) {
        static struct cal_turn t;
        const fx_q16_t off[3] = {100, -200, 300};
        (void)cal_turn_start(&t, off, 1310720);
        for (i = 0; i < BENCH_N; i++)
            sink += cal_turn_add(&t, in3[i]);
    }
}

int main(int argc, char **argv)
{
    if (prepare() != 0) {
        fprintf(stderr, "bench_cal: the golden record does not decode\n");
        return 1;
    }
    if (argc > 1) {
        run(argv[1]);
    }
    return 0;
}

#else /* BENCH_CM: SysTick under QEMU -icount (see bench_cal_cm.sh) */

#define SYST_CSR (*(volatile uint32_t *)0xE000E010u)
#define SYST_RVR (*(volatile uint32_t *)0xE000E014u)
#define SYST_CVR (*(volatile uint32_t *)0xE000E018u)

static void ticks_reset(void)
{
    SYST_CSR = 0;
    SYST_RVR = 0x00FFFFFFu;
    SYST_CVR = 0;
    SYST_CSR = 5u;
}

/* Baselines with the same shapes as the measured calls. */
__attribute__((noinline)) static int empty_apply(const void *st, const fx_q16_t in[3],
                                                 fx_q16_t out[3])
{
    __asm__ volatile("" ::: "memory");
    out[0] = in[0];
    return st != NULL;
}

__attribute__((noinline)) static int empty_temp(const void *st, fx_q16_t t)
{
    __asm__ volatile("" ::: "memory");
    return st != NULL && t != 0;
}

__attribute__((noinline)) static int empty_eval(const void *m, fx_q16_t t, int32_t *y)
{
    __asm__ volatile("" ::: "memory");
    *y = t;
    return m != NULL;
}

#define TIMED(name, loop_fn, loop_empty)                                           \
    do {                                                                           \
        uint32_t t0, t1, t2, t3;                                                   \
        int i;                                                                     \
        ticks_reset();                                                             \
        t0 = SYST_CVR;                                                             \
        for (i = 0; i < BENCH_N; i++) {                                            \
            loop_fn;                                                               \
        }                                                                          \
        t1 = SYST_CVR;                                                             \
        t2 = SYST_CVR;                                                             \
        for (i = 0; i < BENCH_N; i++) {                                            \
            loop_empty;                                                            \
        }                                                                          \
        t3 = SYST_CVR;                                                             \
        printf("BENCH %s %lu %lu\n", name, (unsigned long)((t0 - t1) & 0xFFFFFFu), \
               (unsigned long)((t2 - t3) & 0xFFFFFFu));                            \
    } while (0)

int main(void)
{
    fx_q16_t out[3];
    int32_t y;
    int k;
    static const char *const names[5] = {"cal_tmodel_eval linear", "cal_tmodel_eval parabola",
                                         "cal_tmodel_eval lorentz", "cal_tmodel_eval pwl",
                                         "cal_tmodel_eval lorentz_cubic"};
    if (prepare() != 0) {
        printf("bench_cal: the golden record does not decode\n");
        return 1;
    }
    printf("BENCH_N %d\n", BENCH_N);
    TIMED("cal_acc_apply", sink += cal_acc_apply(&acc, in3[i], out),
          sink += empty_apply(&acc, in3[i], out));
    TIMED("cal_gyro_apply", sink += cal_gyro_apply(&gyro, in3[i], out),
          sink += empty_apply(&gyro, in3[i], out));
    TIMED("cal_acc_set_temp", sink += cal_acc_set_temp(&acc, temp[i]),
          sink += empty_temp(&acc, temp[i]));
    for (k = 0; k < 5; k++) {
        TIMED(names[k], sink += cal_tmodel_eval(&models[k], temp[i], &y),
              sink += empty_eval(&models[k], temp[i], &y));
    }
    return 0;
}

#endif
