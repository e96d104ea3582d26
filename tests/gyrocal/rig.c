/* rig.c - see rig.h. */
#include "rig.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct rig rig;

static void physics(void *ctx, uint64_t t, struct sim_inertial_input *in)
{
    const struct rig *r = ctx;
    double ts;
    sim_inertial_at_rest(in);
    if (t >= r->motion.from_ns && t < r->motion.to_ns) {
        in->rate_dps[2] += r->motion.rate_dps;
        if (r->motion.vib_dps != 0.0) {
            const double s = r->motion.vib_dps *
                             sin(2.0 * 3.14159265358979 * 17.0 * (double)t * 1e-9);
            in->rate_dps[0] += s;
            in->rate_dps[1] += s;
            in->rate_dps[2] += s;
        }
    }
    ts = t >= r->temp.t0_ns ? (double)(t - r->temp.t0_ns) * 1e-9 : 0.0;
    in->temp_c = r->temp.start_c;
    if (r->temp.tau_s > 0.0) {
        in->temp_c += r->temp.rise_c * (1.0 - exp(-ts / r->temp.tau_s));
    }
    if (r->temp.ramp_c_per_s != 0.0 && t > r->temp.ramp_from_ns) {
        in->temp_c += r->temp.ramp_c_per_s * (double)(t - r->temp.ramp_from_ns) * 1e-9;
    }
}

static void error_apply(void *ctx, const struct sim_inertial_input *in,
                        struct sim_inertial_input *out, uint64_t t_ns, double dt_s)
{
    struct rig *r = ctx;
    sim_noise_apply(&r->noise, in, out, t_ns, dt_s);
    if (r->acc_on) {
        unsigned i;
        for (i = 0; i < 3u; i++) {
            r->acc_sum[i] += rig_bias_dps(i);
            r->acc_sum_reg[i] += sim_noise_bias_now(&r->noise, SIM_NOISE_GYRO(i)) +
                                 sim_adis_imu_gyro_offset_dps(&r->part, i);
        }
        r->acc_n++;
    }
    if (r->hist_on) {
        unsigned i;
        if (r->hist_n == r->hist_cap) {
            const size_t cap = r->hist_cap == 0u ? 65536u : 2u * r->hist_cap;
            uint64_t *t = realloc(r->hist_t, cap * sizeof(*t));
            double *c = t != NULL ? realloc(r->hist_c, 3u * cap * sizeof(*c)) : NULL;
            if (t != NULL) {
                r->hist_t = t;
            }
            if (c == NULL) {
                r->hist_on = false; /* out of memory: rig_bias_window reports no data */
                r->hist_n = 0;
                return;
            }
            r->hist_c = c;
            r->hist_cap = cap;
        }
        r->hist_t[r->hist_n] = t_ns;
        for (i = 0; i < 3u; i++) {
            r->hist_c[3u * r->hist_n + i] = (r->hist_n > 0u ? r->hist_c[3u * (r->hist_n - 1u) + i]
                                                            : 0.0) +
                                            sim_noise_bias_now(&r->noise, SIM_NOISE_GYRO(i));
        }
        r->hist_n++;
    }
}

int rig_history(void)
{
    rig.hist_on = true;
    rig.hist_n = 0;
    return 0;
}

/* Index of the last recorded sample with time <= t, or -1. */
static long hist_find(uint64_t t)
{
    long lo = 0, hi = (long)rig.hist_n - 1;
    if (rig.hist_n == 0u || rig.hist_t[0] > t) {
        return -1;
    }
    while (lo < hi) {
        const long mid = (lo + hi + 1) / 2;
        if (rig.hist_t[mid] <= t) {
            lo = mid;
        } else {
            hi = mid - 1;
        }
    }
    return lo;
}

int rig_bias_window(uint64_t t1, uint64_t t2, double out[3])
{
    const long a = hist_find(t1), b = hist_find(t2);
    unsigned i;
    if (b < 0 || b <= a) {
        return -1;
    }
    for (i = 0; i < 3u; i++) {
        const double ca = a >= 0 ? rig.hist_c[3u * (size_t)a + i] : 0.0;
        out[i] = (rig.hist_c[3u * (size_t)b + i] - ca) / (double)(b - a);
    }
    return 0;
}

static int spy_transfer(void *ctx, struct spi_dev *dev, const uint16_t *tx, uint16_t *rx, size_t n,
                        enum spi_cs_policy cs)
{
    struct rig *r = ctx;
    size_t i;
    for (i = 0; tx != NULL && i < n; i++) {
        if ((tx[i] & 0xFF00u) == 0xBE00u && r->cmd_count < RIG_CMD_LOG) {
            r->cmd_log[r->cmd_count++] = tx[i];
        }
    }
    return r->board.spi.bus.ops->transfer(r->board.spi.bus.ctx, dev, tx, rx, n, cs);
}

static int spy_attach(void *ctx, struct spi_dev *dev)
{
    struct rig *r = ctx;
    const struct spi_bus *in = &r->board.spi.bus;
    return in->ops->attach != NULL ? in->ops->attach(in->ctx, dev) : 0;
}

static const struct spi_bus_ops spy_ops = {spy_transfer, spy_attach};

int rig_setup(enum sim_adis_imu_variant v, const struct sim_noise_cfg *ncfg,
              const struct gyrocal_cfg *gcfg)
{
    int err;
    free(rig.hist_t);
    free(rig.hist_c);
    memset(&rig, 0, sizeof(rig));
    err = sim_board_init(&rig.board);
    if (err != 0) {
        return err;
    }
    err = sim_noise_init(&rig.noise, ncfg);
    if (err != 0) {
        return err;
    }
    rig.err_hook.apply = error_apply;
    rig.err_hook.ctx = &rig;
    rig.phys.sample = physics;
    rig.phys.ctx = &rig;
    rig.temp.start_c = 25.0;
    rig.part_cfg.variant = v;
    rig.part_cfg.bus = &rig.board.bus;
    rig.part_cfg.cs = SIM_BOARD_CS(0);
    rig.part_cfg.sclk = SIM_BOARD_SCLK;
    rig.part_cfg.mosi = SIM_BOARD_MOSI;
    rig.part_cfg.miso = SIM_BOARD_MISO;
    rig.part_cfg.dio1 = SIM_BOARD_DR(0);
    rig.part_cfg.dio2 = SIM_BOARD_DR(1);
    rig.part_cfg.log = &rig.board.log;
    rig.part_cfg.seed = 77u;
    rig.part_cfg.power_on_busy = true;
    rig.part_cfg.physics = &rig.phys;
    rig.part_cfg.error = &rig.err_hook;
    err = sim_adis_imu_init(&rig.part, &rig.part_cfg);
    if (err != 0) {
        return err;
    }
    hal_delay_ms(&rig.board.hal, ADIS_IMU_STARTUP_MS);
    rig.spy.ops = &spy_ops;
    rig.spy.ctx = &rig;
    rig.cfg.hal = &rig.board.hal;
    rig.cfg.bus = &rig.spy;
    rig.cfg.cs = SIM_BOARD_CS(0);
    rig.cfg.variant = (uint8_t)v; /* same order in both enums */
    rig.cfg.dr_pin = SIM_BOARD_DR(0);
    rig.cfg.dr_line = ADIS_IMU_DR_DIO1;
    err = adis_imu_init(&rig.imu, &rig.cfg);
    if (err != 0) {
        return err;
    }
    if (gcfg != NULL) {
        rig.gcfg = *gcfg;
    } else {
        err = gyrocal_default_cfg(&rig.gcfg, rig.imu.info, ADIS_IMU_RANGE_300);
        if (err != 0) {
            return err;
        }
    }
    return gyrocal_init(&rig.gc, &rig.imu, &rig.gcfg);
}

uint64_t rig_now(void)
{
    return hal_now_ns(&rig.board.hal);
}

void rig_wait_ms(uint32_t ms)
{
    hal_delay_ms(&rig.board.hal, ms);
}

double rig_bias_dps(unsigned axis)
{
    const struct gyrocal_correction c = gyrocal_correction_get(&rig.gc);
    double b = sim_noise_bias_now(&rig.noise, SIM_NOISE_GYRO(axis)) +
               sim_adis_imu_gyro_offset_dps(&rig.part, axis);
    if (c.valid && axis < 3u) {
        b += (double)c.corr[axis] / 320.0;
    }
    return b;
}

void rig_bias_mean2(double seconds, double out[3], double out_reg[3])
{
    unsigned i;
    rig.acc_on = true;
    rig.acc_n = 0;
    for (i = 0; i < 3u; i++) {
        rig.acc_sum[i] = rig.acc_sum_reg[i] = 0.0;
    }
    hal_delay_until(&rig.board.hal, rig_now() + (uint64_t)(seconds * 1e9 + 0.5));
    rig.acc_on = false;
    for (i = 0; i < 3u; i++) {
        out[i] = rig.acc_n > 0u ? rig.acc_sum[i] / (double)rig.acc_n : rig_bias_dps(i);
        if (out_reg != NULL) {
            out_reg[i] = rig.acc_n > 0u ? rig.acc_sum_reg[i] / (double)rig.acc_n
                                        : sim_noise_bias_now(&rig.noise, SIM_NOISE_GYRO(i)) +
                                              sim_adis_imu_gyro_offset_dps(&rig.part, i);
        }
    }
}

void rig_bias_mean(double seconds, double out[3])
{
    rig_bias_mean2(seconds, out, NULL);
}

unsigned rig_cmd_seen(uint16_t w)
{
    unsigned i, n = 0;
    for (i = 0; i < rig.cmd_count; i++) {
        n += rig.cmd_log[i] == w;
    }
    return n;
}

unsigned rig_violations(void)
{
    if (rig.board.log.total != 0u) {
        sim_violation_log_print(&rig.board.log, stdout);
    }
    return rig.board.log.total;
}
