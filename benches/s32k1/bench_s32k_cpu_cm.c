/*
 * bench_s32k_cpu_cm.c - the firmware's own instructions per sample on the S32K1 port: the ADIS
 * sample read (sensor_next through the port, the SPI engine and the driver) and the signal path
 * (app_step), measured under QEMU -icount with the port's _sim build against the register and
 * device models of the EPB rig (sim/epb_rig: ADIS16405, 819.2 samples/s, S32K144EVB wiring).
 * Not a test.
 *
 * What runs is the firmware and the models in one image; the models' instructions are taken out
 * with the bus meter (inclino/sim/s32k_bus.h): SysTick is read when the firmware enters a model
 * (every register access through s32k_mmio_*, the PRIMASK and WFI seam) and when it leaves it
 * (a firmware interrupt handler run from a model counts as firmware). The time asleep in WFI
 * is the model's: on the part no instruction runs. What remains, per sample:
 *   read_instr   the read: driver, engine, port, interrupt handlers, and per register access
 *                the call into the seam (a few instructions more than the one ldr/str of the
 *                direct build: an upper bound);
 *   app_instr    app_step;
 *   the meter's own cost per enter/leave pair is measured and subtracted.
 * Cases: the bit-banged engine (its delays poll the simulated LPIT in the _sim build, so its
 * figure counts polling the part would not do: not its CPU time, which benches/s32k1's frame
 * bench gives), LPSPI polling, LPSPI sleeping on its interrupt (irq_wait, the boards' choice).
 * With -icount shift=6 one instruction is 64 ns of virtual time and SysTick counts 40 ns.
 * Output: one line per case,
 *   CPU engine=E samples=N read_instr=R app_instr=A pairs=P sleeps=S
 * (per sample, instructions).
 */
#include <stdio.h>
#include <string.h>

#include "inclino/sim/epb_rig_state.h"
#include "inclino/s32k_mmio.h"
#include "inclino/sim/s32k_bus.h"

#define SYST_CSR (*(volatile uint32_t *)0xE000E010u)
#define SYST_RVR (*(volatile uint32_t *)0xE000E014u)
#define SYST_CVR (*(volatile uint32_t *)0xE000E018u)
#define TICK_MASK 0x00FFFFFFu
#define WARMUP 16u
#define SAMPLES 64u
#define CAL_PAIRS 4096u

static struct epb_rig rig;
static uint32_t depth, t_mark, pairs;
static uint64_t fw_ticks; /* ticks outside the models since ticks_start */

static void ticks_start(void)
{
    SYST_CSR = 0;
    SYST_RVR = TICK_MASK;
    SYST_CVR = 0;
    SYST_CSR = 5u;
    depth = 0u;
    fw_ticks = 0u;
    t_mark = SYST_CVR;
}

/* Ticks from a (earlier) to b (later) of the down-counter; intervals below 2^24 ticks. */
static uint32_t el(uint32_t a, uint32_t b)
{
    return (a - b) & TICK_MASK;
}

/* Firmware ticks so far: the sum of the intervals between the models' calls (each short, so
 * the 24-bit counter never wraps inside one, however long the models run). */
static uint64_t fw_now(void)
{
    return depth == 0u ? fw_ticks + el(t_mark, SYST_CVR) : fw_ticks;
}

static void m_enter(void)
{
    if (depth++ == 0u) {
        fw_ticks += el(t_mark, SYST_CVR);
    }
    pairs++;
}

static void m_leave(void)
{
    if (depth > 0u && --depth == 0u) {
        t_mark = SYST_CVR;
    }
}

static const struct s32k_bus_meter meter = {m_enter, m_leave};

/* The breakdown of the read (lpspi_irq): the engine's transfer and the HAL's clock, through
 * wrappers put in front of the bus and HAL ops tables. */
static const struct spi_bus_ops *bus_orig;
static const struct hal_ops *hal_orig;
static struct spi_bus_ops bus_wrap;
static struct hal_ops hal_wrap;
static uint64_t xfer_t, now_t; /* ticks inside, models' ticks taken out */
static uint32_t xfer_p, now_p; /* meter pairs inside */
static uint32_t xfer_n, now_n;

static int w_transfer(void *ctx, struct spi_dev *dev, const uint16_t *tx, uint16_t *rx, size_t n,
                      enum spi_cs_policy cs)
{
    const uint64_t f0 = fw_now();
    const uint32_t p0 = pairs;
    const int r = bus_orig->transfer(ctx, dev, tx, rx, n, cs);
    xfer_t += fw_now() - f0;
    xfer_p += pairs - p0;
    xfer_n++;
    return r;
}

static uint64_t w_now(void *ctx)
{
    const uint64_t f0 = fw_now();
    const uint32_t p0 = pairs;
    const uint64_t r = hal_orig->now_ns(ctx);
    now_t += fw_now() - f0;
    now_p += pairs - p0;
    now_n++;
    return r;
}

static const struct sensor_ops *sens_orig;
static struct sensor_ops sens_wrap;
static uint64_t wait_t, rd_t;
static uint32_t wait_p, rd_p;

static int w_wait(void *dev, uint32_t timeout_ns)
{
    const uint64_t f0 = fw_now();
    const uint32_t p0 = pairs;
    const int r = sens_orig->wait_ready(dev, timeout_ns);
    wait_t += fw_now() - f0;
    wait_p += pairs - p0;
    return r;
}

static int w_read(void *dev, struct sensor_sample *out)
{
    const uint64_t f0 = fw_now();
    const uint32_t p0 = pairs;
    const int r = sens_orig->read(dev, out);
    rd_t += fw_now() - f0;
    rd_p += pairs - p0;
    return r;
}

static double instr(double ticks)
{
    return ticks * 40.0 / 64.0;
}

/* Firmware ticks per turn of an empty loop (the baseline of the two calibrations below). */
static double loop_base(void)
{
    volatile uint32_t sink = 0;
    uint32_t i;
    const uint64_t f0 = fw_now();
    for (i = 0; i < CAL_PAIRS; i++) {
        sink += i;
    }
    (void)sink;
    return (double)(fw_now() - f0) / CAL_PAIRS;
}

/* Firmware ticks of one meter pair as the seam makes it (the meter's own instructions). */
static double pair_overhead(void)
{
    uint32_t i;
    const uint64_t f0 = fw_now();
    for (i = 0; i < CAL_PAIRS; i++) {
        s32k_bus_meter_enter();
        s32k_bus_meter_leave();
    }
    return (double)(fw_now() - f0) / CAL_PAIRS - loop_base();
}

/* Firmware ticks of one s32k_mmio_read32 through the seam (the call and the meter pair), to
 * compare with the 2 instructions (address literal, ldr) of the direct build. An address no
 * model maps: the bus only counts it. */
static double access_overhead(void)
{
    volatile uint32_t sink = 0;
    uint32_t i;
    const uint64_t f0 = fw_now();
    for (i = 0; i < CAL_PAIRS; i++) {
        sink += s32k_mmio_read32(0x4007F000u);
    }
    (void)sink;
    return (double)(fw_now() - f0) / CAL_PAIRS - loop_base();
}

/* Per sample as the direct build runs it: each register access 2 instructions, not the seam's. */
static double direct(uint64_t t, uint32_t p, double acc)
{
    return instr(((double)t - p * acc) / SAMPLES) + 2.0 * p / SAMPLES;
}

enum wrap { WRAP_NONE, WRAP_XFER, WRAP_NOW, WRAP_SENSOR };

static int run(const char *name, bool lpspi, bool sleep, enum wrap wrap)
{
    struct app_cfg cfg;
    struct epb_rig_vehicle v;
    double read_t = 0.0, app_t = 0.0, ovh, acc;
    uint32_t n, pairs0, sleeps0;
    int err = epb_rig_init(&rig, EPB_RIG_ADIS16405, NULL, 1u);
    if (err == INC_OK) {
        err = epb_rig_set_board_spi(&rig, EPB_RIG_BOARD_S32K144, lpspi);
    }
    if (err == INC_OK) {
        err = app_cfg_default(&cfg, epb_rig_rate_mhz(&rig));
    }
    if (err == INC_OK) {
        err = epb_rig_power_up(&rig, &cfg);
    }
    if (err != INC_OK) {
        printf("CPU engine=%s error=%d\n", name, err);
        return err;
    }
    if (lpspi) {
        rig.s32k.lp.cfg.irq_wait = sleep; /* the engines share memory: only the one running */
    }
    epb_rig_vehicle_default(&v);
    v.bump_rate_hz = 0.0;
    epb_rig_park(&rig, &v);
    ticks_start();
    s32k_bus_set_meter(&meter);
    ovh = pair_overhead();
    acc = access_overhead();
    if (wrap == WRAP_XFER) {
        bus_orig = rig.s32k.spi->ops;
        bus_wrap = *bus_orig;
        bus_wrap.transfer = w_transfer;
        if (lpspi) {
            rig.s32k.lp.bus.ops = &bus_wrap;
        } else {
            rig.s32k.bb.bus.ops = &bus_wrap;
        }
    } else if (wrap == WRAP_SENSOR) {
        sens_orig = rig.sensor.ops;
        sens_wrap = *sens_orig;
        sens_wrap.wait_ready = w_wait;
        sens_wrap.read = w_read;
        rig.sensor.ops = &sens_wrap;
    } else if (wrap == WRAP_NOW) {
        hal_orig = rig.s32k.hal.ops;
        hal_wrap = *hal_orig;
        hal_wrap.now_ns = w_now;
        rig.s32k.hal.ops = &hal_wrap;
    }
    pairs0 = 0u;
    sleeps0 = 0u;
    for (n = 0; n < WARMUP + SAMPLES; n++) {
        struct sensor_sample smp;
        struct app_result res;
        bool done = false;
        uint64_t f0, f1, f2;
        int rerr;
        if (n == WARMUP) {
            read_t = app_t = 0.0;
            pairs0 = pairs;
            sleeps0 = lpspi ? rig.s32k.lp.stats.sleeps : 0u;
            xfer_t = now_t = wait_t = rd_t = 0u;
            wait_p = rd_p = 0u;
            xfer_p = now_p = 0u;
            xfer_n = now_n = 0u;
        }
        f0 = fw_now();
        rerr = sensor_next(epb_rig_sensor(&rig), 0u, &smp);
        f1 = fw_now();
        (void)app_step(&rig.app, &smp, rerr, NULL, &done, &res);
        f2 = fw_now();
        if (rerr != INC_OK) {
            printf("CPU engine=%s read_error=%d\n", name, rerr);
            s32k_bus_set_meter(NULL);
            return rerr;
        }
        read_t += (double)(f1 - f0);
        app_t += (double)(f2 - f1);
    }
    s32k_bus_set_meter(NULL);
    {
        const double p = (double)(pairs - pairs0) / SAMPLES;
        printf("CPU engine=%s samples=%u read_instr=%.0f app_instr=%.0f pairs=%.1f sleeps=%.2f "
               "pair_instr=%.1f access_instr=%.1f read_direct_instr=%.0f\n",
               name, (unsigned)SAMPLES, instr(read_t / SAMPLES - p * ovh), instr(app_t / SAMPLES),
               p, (double)((lpspi ? rig.s32k.lp.stats.sleeps : 0u) - sleeps0) / SAMPLES, instr(ovh),
               instr(acc), instr(read_t / SAMPLES) - p * (instr(acc) - 2.0));
        if (wrap == WRAP_XFER) {
            printf("CPU engine=%s transfers=%.2f transfer_instr=%.0f transfer_direct_instr=%.0f\n",
                   name, (double)xfer_n / SAMPLES, instr(((double)xfer_t - xfer_p * ovh) / SAMPLES),
                   direct(xfer_t, xfer_p, acc));
        } else if (wrap == WRAP_SENSOR) {
            printf("CPU engine=%s wait_ready_instr=%.0f read_op_instr=%.0f "
                   "wait_ready_direct_instr=%.0f read_op_direct_instr=%.0f\n",
                   name, instr(((double)wait_t - wait_p * ovh) / SAMPLES),
                   instr(((double)rd_t - rd_p * ovh) / SAMPLES), direct(wait_t, wait_p, acc),
                   direct(rd_t, rd_p, acc));
        } else if (wrap == WRAP_NOW) {
            printf("CPU engine=%s now_calls=%.2f now_instr=%.0f now_direct_instr=%.0f\n", name,
                   (double)now_n / SAMPLES, instr(((double)now_t - now_p * ovh) / SAMPLES),
                   direct(now_t, now_p, acc));
        }
    }
    return 0;
}

int main(void)
{
    int err = run("bitbang", false, false, WRAP_NONE);
    if (err == 0) {
        err = run("lpspi_poll", true, false, WRAP_NONE);
    }
    if (err == 0) {
        err = run("lpspi_irq", true, true, WRAP_NONE);
    }
    if (err == 0) {
        err = run("lpspi_irq", true, true, WRAP_XFER);
    }
    if (err == 0) {
        err = run("lpspi_irq", true, true, WRAP_NOW);
    }
    if (err == 0) {
        err = run("lpspi_irq", true, true, WRAP_SENSOR);
    }
    return err == 0 ? 0 : 1;
}
