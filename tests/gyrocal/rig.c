/* rig.c - see rig.h. */
#include "rig.h"

#include <math.h>
#include <stdio.h>
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
            const double s = r->motion.vib_dps * sin(2.0 * 3.14159265358979 * 17.0 * (double)t * 1e-9);
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
        }
        r->acc_n++;
    }
}

static int spy_transfer(void *ctx, struct spi_dev *dev, const uint16_t *tx, uint16_t *rx,
                        size_t n, enum spi_cs_policy cs)
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

void rig_bias_mean(double seconds, double out[3])
{
    unsigned i;
    rig.acc_on = true;
    rig.acc_n = 0;
    rig.acc_sum[0] = rig.acc_sum[1] = rig.acc_sum[2] = 0.0;
    hal_delay_until(&rig.board.hal, rig_now() + (uint64_t)(seconds * 1e9 + 0.5));
    rig.acc_on = false;
    for (i = 0; i < 3u; i++) {
        out[i] = rig.acc_n > 0u ? rig.acc_sum[i] / (double)rig.acc_n : rig_bias_dps(i);
    }
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
