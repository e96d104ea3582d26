/*
 * adis_imu.c - simulated ADIS1636x/1640x (see sim/adis_imu.h and docs/drivers-adis-imu.md).
 *
 * Every number cites its source: docs/sensor-facts.md §3.x, [ADI-IMU-QS], or [U] for a model choice where the
 * fact sheet has no confirmed value (listed in docs/unconfirmed-facts.md).
 */
#include "inclino/sim/adis_imu.h"
#include "inclino/sim/part.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

/* ---- part facts ---- */

#define REG_FLASH_CNT 0x00u
#define REG_SUPPLY 0x02u
#define REG_GYRO 0x04u /* x, y, z at 0x04, 0x06, 0x08 */
#define REG_ACCL 0x0Au
#define REG_GYRO_OFF 0x1Au
#define REG_ACCL_OFF 0x20u
#define REG_MSC_CTRL 0x34u
#define REG_SMPL_PRD 0x36u
#define REG_SENS_AVG 0x38u
#define REG_DIAG 0x3Cu
#define REG_GLOB_CMD 0x3Eu
#define REG_PROD_ID 0x56u
#define IDX(a) ((unsigned)(a) >> 1)

#define MSC_DR_DIO2 0x0001u
#define MSC_DR_HIGH 0x0002u
#define MSC_DR_EN 0x0004u
#define MSC_SELF_TEST 0x0400u
#define MSC_MEM_TEST 0x0800u

#define DIAG_SUPPLY_LOW 0x0001u
#define DIAG_SUPPLY_HIGH 0x0002u
#define DIAG_SPI_FAIL 0x0008u
#define DIAG_OVERRANGE 0x0010u
#define DIAG_SELF_TEST 0x0020u

#define ND 0x8000u
#define EA 0x4000u

/* tB = 1/1638.4 s = 9765625/16 ns exactly (docs/sensor-facts.md §3.4, Linux 1638.404 SPS). */
#define TB_16 9765625ull
#define TB_SLOW 31u /* SMPL_PRD[7]: 52.851 SPS base = 1638.4/31 */

#define GYRO_OFF_LSB_DPS 0.0125 /* docs/sensor-facts.md §3.4, [ADI-IMU-QS] */
#define GYRO_LIMIT_COUNTS \
    6000                     /* [U] output clips at the rated range: +-300/150/75 deg/s
                                       are 6000 counts at 0.05/0.025/0.0125 deg/s */
#define TEMP_LSB_1636X 0.136 /* docs/sensor-facts.md §3.3 */
#define TEMP_LSB_1640X 0.14
#define SUPPLY_LSB_V 0.002418
#define MAGN_LSB_GAUSS 0.0005
#define AUX_LSB_V 0.0008058
#define SUPPLY_MIN_V 4.75 /* DIAG_STAT[0], [1] (docs/sensor-facts.md §3.4) */
#define SUPPLY_MAX_V 5.25
#define MEM_TEST_MS_NORMAL 17u /* ADIS16405 flash test 17 / 90 ms (docs/sensor-facts.md §3.4) */
#define MEM_TEST_MS_LOW_POWER 90u
#define CS_SETUP_NS 49u           /* [U] tCS recollection 48.8 ns */
#define CS_HOLD_NS 49u            /* [U] taken equal to tCS */
#define MOSI_SETUP_NS 20u         /* [U] */
#define MISO_DELAY_NS 100u        /* [U] tDAV */
#define PERIOD_NORMAL_NS 500u     /* 2 MHz (docs/sensor-facts.md §3.1) */
#define PERIOD_LOW_POWER_NS 3333u /* 300 kHz */
#define PERIOD_BURST_NS 1000u     /* 1 MHz */

struct variant {
    const char *name;
    uint16_t prod_id;
    bool is_1640x;
    double accel_lsb_g;   /* docs/sensor-facts.md §3.3 */
    int32_t accel_limit;  /* [U] rated range in counts: 10, 1.7, 5, 18, 18, 18 g */
    unsigned supply_bits; /* 12 (1636x) / 14 (1640x, Linux [U]) */
    unsigned startup_ms;  /* power-on: ADIS16405 220 ms, ADIS16367 180 ms (normal mode) */
    unsigned reset_ms[2]; /* normal, low power: ADIS16405 100/170, ADIS16367 60/130 [U
                                 for the 1636x, taken from the ADIS16367] */
};

static const struct variant variants[SIM_ADIS_IMU_VARIANTS] = {
    {"adis16360", 0x3FE8, false, 3.333e-3, 3000, 12, 180, {60, 130}},
    {"adis16362", 0x3FEA, false, 0.333e-3, 5105, 12, 180, {60, 130}},
    {"adis16364", 0x3FEC, false, 1.0e-3, 5000, 12, 180, {60, 130}},
    {"adis16365", 0x3FED, false, 3.333e-3, 5400, 12, 180, {60, 130}},
    {"adis16400", 0x4010, true, 3.333e-3, 5400, 14, 220, {100, 170}},
    {"adis16405", 0x4015, true, 3.333e-3, 5400, 14, 220, {100, 170}},
};

static const struct variant *var(const struct sim_adis_imu *m)
{
    return &variants[m->cfg.variant];
}

/* Writable registers: the stored bits, and the width a read sign-extends from (0: none). */
struct wreg {
    uint8_t addr;
    uint16_t mask;
    uint8_t sign_bits;
};

static const struct wreg wregs_1636x[] = {
    {0x1A, 0x1FFF, 13}, {0x1C, 0x1FFF, 13}, {0x1E, 0x1FFF, 13}, /* X/Y/ZGYRO_OFF (13-bit [U]) */
    {0x20, 0x0FFF, 12}, {0x22, 0x0FFF, 12}, {0x24, 0x0FFF, 12}, /* X/Y/ZACCL_OFF */
    {0x26, 0xFFFF, 0},  {0x28, 0xFFFF, 0},  {0x2A, 0x00FF, 0},  /* ALM_MAG1/2, ALM_SMPL1 */
    {0x2C, 0x00FF, 0},  {0x2E, 0xFFFF, 0},  {0x30, 0x0FFF, 0},  /* ALM_SMPL2, ALM_CTRL, AUX_DAC */
    {0x32, 0xFFFF, 0},  {0x34, 0x0FC7, 0},  {0x36, 0x00FF, 0},  /* GPIO_CTRL, MSC_CTRL, SMPL_PRD */
    {0x38, 0x0707, 0},  {0x3A, 0x01FF, 0},                      /* SENS_AVG, SLP_CNT */
};

static const struct wreg wregs_1640x[] = {
    {0x1A, 0x1FFF, 13}, {0x1C, 0x1FFF, 13}, {0x1E, 0x1FFF, 13},
    {0x20, 0x0FFF, 12}, {0x22, 0x0FFF, 12}, {0x24, 0x0FFF, 12},
    {0x26, 0x3FFF, 14}, {0x28, 0x3FFF, 14}, {0x2A, 0x3FFF, 14}, /* X/Y/ZMAGN_HIF */
    {0x2C, 0x0FFF, 0},  {0x2E, 0x0FFF, 0},  {0x30, 0x0FFF, 0},  /* X/Y/ZMAGN_SIF */
    {0x32, 0xFFFF, 0},  {0x34, 0x0FC7, 0},  {0x36, 0x00FF, 0},
    {0x38, 0x0707, 0},  {0x3A, 0x01FF, 0},  {0x40, 0xFFFF, 0},
    {0x42, 0xFFFF, 0},  {0x44, 0x00FF, 0},                     /* ALM_MAG1/2, ALM_SMPL1 */
    {0x46, 0x00FF, 0},  {0x48, 0xFFFF, 0},  {0x4A, 0x0FFF, 0}, /* ALM_SMPL2, ALM_CTRL, AUX_DAC */
};

static const struct wreg *find_wreg(const struct sim_adis_imu *m, uint8_t even)
{
    const struct wreg *t = var(m)->is_1640x ? wregs_1640x : wregs_1636x;
    const size_t n = var(m)->is_1640x ? sizeof(wregs_1640x) / sizeof(wregs_1640x[0])
                                      : sizeof(wregs_1636x) / sizeof(wregs_1636x[0]);
    size_t i;
    for (i = 0; i < n; i++) {
        if (t[i].addr == even) {
            return &t[i];
        }
    }
    return NULL;
}

/* Output registers carry ND/EA: SUPPLY_OUT .. AUX_ADC (0x02..0x16 or 0x02..0x18). */
static uint8_t last_output(const struct sim_adis_imu *m)
{
    return var(m)->is_1640x ? 0x18u : 0x16u;
}

static bool is_output(const struct sim_adis_imu *m, uint8_t even)
{
    return even >= REG_SUPPLY && even <= last_output(m);
}

/* Read-only registers that exist (besides the outputs). */
static bool is_readonly(const struct sim_adis_imu *m, uint8_t even)
{
    if (even == REG_FLASH_CNT || even == REG_DIAG || even == REG_PROD_ID) {
        return true;
    }
    return !var(m)->is_1640x && (even == 0x52u || even == 0x54u || even == 0x58u);
}

static int32_t sext(uint16_t v, unsigned bits)
{
    const uint32_t sign = 1UL << (bits - 1u);
    const uint32_t x = (uint32_t)v & ((1UL << bits) - 1UL);
    return (int32_t)(x ^ sign) - (int32_t)sign;
}

static uint16_t twos(int32_t c, unsigned bits)
{
    return (uint16_t)((uint32_t)c & ((1UL << bits) - 1UL));
}

/* Round half away from zero and clip to [lo, hi]; *sat |= clipped. */
static int32_t quant(double v, double lsb, int32_t lo, int32_t hi, bool *sat)
{
    double c = v / lsb;
    c = c < 0.0 ? -floor(-c + 0.5) : floor(c + 0.5);
    if (!(c <= (double)hi)) { /* also NaN */
        *sat = true;
        return isnan(c) ? 0 : hi;
    }
    if (c < (double)lo) {
        *sat = true;
        return lo;
    }
    return (int32_t)c;
}

/* ---- timing of the bus (core) ---- */

static void apply_bus_timing(struct sim_adis_imu *m)
{
    struct sim_spi_timing t;
    m->low_power = (m->reg[IDX(REG_SMPL_PRD)] & 0xFFu) > 0x09u; /* docs/sensor-facts.md §3.1 */
    memset(&t, 0, sizeof(t));
    t.min_period_ns = m->low_power ? PERIOD_LOW_POWER_NS : PERIOD_NORMAL_NS;
    t.min_cs_setup_ns = CS_SETUP_NS;
    t.min_cs_hold_ns = CS_HOLD_NS;
    t.min_stall_ns = m->low_power ? SIM_ADIS_IMU_STALL_LOW_POWER_NS : SIM_ADIS_IMU_STALL_NORMAL_NS;
    t.mosi_setup_ns = MOSI_SETUP_NS;
    t.miso_delay_ns = MISO_DELAY_NS;
    sim_adis_core_set_timing(&m->core, &t);
}

/* ---- busy ---- */

static void busy_done(void *arg, uint64_t now);

static void start_busy(struct sim_adis_imu *m, uint64_t now, uint32_t ms)
{
    const uint64_t until = now + (uint64_t)ms * 1000000u;
    if (until > m->busy_until) {
        m->busy_until = until;
    }
    if (m->busy_ev > 0) {
        sim_clock_cancel(m->clk, m->busy_ev);
    }
    m->busy_ev = sim_clock_schedule(m->clk, m->busy_until, busy_done, m);
}

static bool busy_at(const struct sim_adis_imu *m, uint64_t t)
{
    return t < m->busy_until;
}

/* ---- data-ready ---- */

static void apply_dr(struct sim_adis_imu *m)
{
    const uint16_t msc = m->reg[IDX(REG_MSC_CTRL)];
    const unsigned pin = (msc & MSC_DR_DIO2) ? m->cfg.dio2 : m->cfg.dio1;
    const bool en = (msc & MSC_DR_EN) != 0u && pin != SIM_ADIS_IMU_NO_PIN;
    if (m->dr_pin != SIM_ADIS_IMU_NO_PIN && (!en || m->dr_pin != pin)) {
        sim_pinbus_device_release(m->cfg.bus, (unsigned)m->dr_dev, m->dr_pin);
        m->dr_pin = SIM_ADIS_IMU_NO_PIN;
    }
    if (m->dr_off_ev > 0) {
        sim_clock_cancel(m->clk, m->dr_off_ev);
        m->dr_off_ev = 0;
    }
    if (en) {
        m->dr_pin = pin;
        m->dr_active_high = (msc & MSC_DR_HIGH) != 0u;
        sim_pinbus_device_drive(m->cfg.bus, (unsigned)m->dr_dev, pin, !m->dr_active_high);
    }
}

static void dr_off(void *arg, uint64_t now)
{
    struct sim_adis_imu *m = arg;
    (void)now;
    m->dr_off_ev = 0;
    if (m->dr_pin != SIM_ADIS_IMU_NO_PIN) {
        sim_pinbus_device_drive(m->cfg.bus, (unsigned)m->dr_dev, m->dr_pin, !m->dr_active_high);
    }
}

/* The injected spurious pulse (SIM_FAULT_EXTRA_DATA_READY): the line pulses as for a sample,
 * but no new sample is behind it. */
static void dr_extra(void *arg, uint64_t now)
{
    struct sim_adis_imu *m = arg;
    m->dr_extra_ev = 0;
    if (!m->dr_extra || m->dr_pin == SIM_ADIS_IMU_NO_PIN || m->dr_off_ev > 0 || m->dr_suppressed) {
        return;
    }
    sim_pinbus_device_drive(m->cfg.bus, (unsigned)m->dr_dev, m->dr_pin, m->dr_active_high);
    m->dr_off_ev = sim_clock_schedule(m->clk, now + SIM_ADIS_IMU_DR_PULSE_NS, dr_off, m);
    m->dr_extra_pulses++;
}

static void dr_pulse(struct sim_adis_imu *m, uint64_t now)
{
    if (m->dr_pin == SIM_ADIS_IMU_NO_PIN || m->dr_off_ev > 0 || m->dr_suppressed) {
        return;
    }
    sim_pinbus_device_drive(m->cfg.bus, (unsigned)m->dr_dev, m->dr_pin, m->dr_active_high);
    m->dr_off_ev = sim_clock_schedule(m->clk, now + SIM_ADIS_IMU_DR_PULSE_NS, dr_off, m);
    m->dr_pulses++;
    if (m->dr_extra && m->dr_extra_ev == 0) {
        m->dr_extra_ev = sim_clock_schedule(m->clk, now + m->period_16 / 32u, dr_extra, m);
        if (m->dr_extra_ev < 0) {
            m->dr_extra_ev = 0;
        }
    }
}

/* ---- Bartlett filter (docs/sensor-facts.md §3.4 SENS_AVG; [ADI-IMU-QS]) ---- */

#define HMASK (SIM_ADIS_IMU_HIST - 1u)

/* Sums of the N newest x and y1 values ending at index `last`. */
static void filter_resum(struct sim_adis_imu_filter *f, uint32_t last, unsigned n)
{
    unsigned j;
    f->s1 = 0.0;
    f->s2 = 0.0;
    for (j = 0; j < n; j++) {
        f->s1 += f->x[(last - j) & HMASK];
        f->s2 += f->y1[(last - j) & HMASK];
    }
}

/* New N: rebuild the first-stage history for it from the raw history (2N - 1 <= 127 raw
 * samples back), so the output continues as if the part had always filtered with N. */
static void filter_retap(struct sim_adis_imu_filter *f, uint32_t last, unsigned n)
{
    unsigned j, k;
    for (j = 0; j < n; j++) {
        const uint32_t p = last - j;
        double s = 0.0;
        for (k = 0; k < n; k++) {
            s += f->x[(p - k) & HMASK];
        }
        f->y1[p & HMASK] = s / (double)n;
    }
    filter_resum(f, last, n);
}

static double filter_step(struct sim_adis_imu_filter *f, uint32_t idx, unsigned n, double v)
{
    double y1;
    f->x[idx & HMASK] = v;
    f->s1 += v - f->x[(idx - n) & HMASK];
    y1 = f->s1 / (double)n;
    f->y1[idx & HMASK] = y1;
    f->s2 += y1 - f->y1[(idx - n) & HMASK];
    if ((idx & HMASK) == 0u) {
        filter_resum(f, idx, n); /* no drift of the running sums over long runs */
    }
    return f->s2 / (double)n;
}

static void apply_taps(struct sim_adis_imu *m)
{
    const unsigned mm = m->reg[IDX(REG_SENS_AVG)] & 0x7u;
    const unsigned n = 1u << (mm > 6u ? 6u : mm);
    unsigned i;
    if (n == m->taps) {
        return;
    }
    m->taps = n;
    for (i = 0; i < SIM_ADIS_IMU_FILTERED; i++) {
        filter_retap(&m->filt[i], m->hist_idx - 1u, n);
    }
}

/* ---- sampling ---- */

static double gyro_lsb(const struct sim_adis_imu *m)
{
    switch ((m->reg[IDX(REG_SENS_AVG)] >> 8) & 0x7u) {
    case 2u: return 0.025;  /* +-150 deg/s [U encoding] */
    case 1u: return 0.0125; /* +-75 deg/s */
    default: return 0.05;   /* +-300 deg/s (code 4) */
    }
}

static void input_now(struct sim_adis_imu *m, uint64_t t, struct sim_inertial_input *in)
{
    if (m->cfg.physics != NULL && m->cfg.physics->sample != NULL) {
        m->cfg.physics->sample(m->cfg.physics->ctx, t, in);
    } else {
        *in = m->input;
    }
}

/* Output registers from the filter state and the non-filtered inputs. */
static void compute_outputs(struct sim_adis_imu *m, const struct sim_inertial_input *e)
{
    const struct variant *v = var(m);
    const double glsb = gyro_lsb(m);
    bool sat = false, dummy = false;
    uint16_t diag = 0;
    unsigned i;
    int32_t c;
    for (i = 0; i < 3u; i++) {
        /* User offsets add to the output [U sign convention], after the filter (a constant
         * passes the filter unchanged, so only the moment it takes effect differs). */
        const double g = m->filtered[i] +
                         sext(m->reg[IDX(REG_GYRO_OFF) + i], 13) * GYRO_OFF_LSB_DPS;
        const double a = m->filtered[3u + i] +
                         sext(m->reg[IDX(REG_ACCL_OFF) + i], 12) * v->accel_lsb_g;
        c = quant(g, glsb, -GYRO_LIMIT_COUNTS, GYRO_LIMIT_COUNTS, &sat);
        m->reg[IDX(REG_GYRO) + i] = twos(c, 14);
        c = quant(a, v->accel_lsb_g, -v->accel_limit, v->accel_limit, &sat);
        m->reg[IDX(REG_ACCL) + i] = twos(c, 14);
    }
    if (v->is_1640x) {
        for (i = 0; i < 3u; i++) {
            c = quant(m->magn_gauss[i], MAGN_LSB_GAUSS, -8192, 8191, &sat);
            m->reg[IDX(0x10u) + i] = twos(c, 14);
        }
        c = quant(e->temp_c - 25.0, TEMP_LSB_1640X, -2048, 2047, &dummy);
        m->reg[IDX(0x16u)] = twos(c, 12);
    } else {
        c = quant(e->temp_c - 25.0, TEMP_LSB_1636X, -2048, 2047, &dummy);
        for (i = 0; i < 3u; i++) {
            m->reg[IDX(0x10u) + i] = twos(c, 12); /* one die temperature for all three */
        }
    }
    c = quant(e->supply_v, SUPPLY_LSB_V, 0, (int32_t)((1u << v->supply_bits) - 1u), &dummy);
    m->reg[IDX(REG_SUPPLY)] = (uint16_t)c;
    c = quant(m->aux_v, AUX_LSB_V, 0, 4095, &dummy);
    m->reg[IDX(last_output(m))] = (uint16_t)c;
    if (sat) {
        diag |= DIAG_OVERRANGE;
    }
    if (e->supply_v < SUPPLY_MIN_V) {
        diag |= DIAG_SUPPLY_LOW;
    } else if (e->supply_v > SUPPLY_MAX_V) {
        diag |= DIAG_SUPPLY_HIGH;
    }
    m->diag |= diag;
    /* ND on every output register (indices 1 .. last). */
    for (i = IDX(REG_SUPPLY); i <= IDX(last_output(m)); i++) {
        m->nd |= 1ull << i;
    }
}

static void take_sample(struct sim_adis_imu *m, uint64_t t)
{
    struct sim_inertial_input in, e;
    double vals[SIM_ADIS_IMU_FILTERED];
    unsigned i;
    input_now(m, t, &in);
    if (m->cfg.error != NULL && m->cfg.error->apply != NULL) {
        m->cfg.error->apply(m->cfg.error->ctx, &in, &e, t, (double)m->period_16 / 16e9);
    } else {
        e = in;
    }
    if (m->prec_active) {
        for (i = 0; i < 3u; i++) {
            m->prec_sum[i] += e.rate_dps[i];
        }
        m->prec_n++;
    }
    for (i = 0; i < 3u; i++) {
        vals[i] = e.rate_dps[i];
        vals[3u + i] = e.accel_g[i];
    }
    for (i = 0; i < SIM_ADIS_IMU_FILTERED; i++) {
        m->filtered[i] = filter_step(&m->filt[i], m->hist_idx, m->taps, vals[i]);
    }
    m->hist_idx++;
    m->samples++;
    compute_outputs(m, &e);
    if (!busy_at(m, t)) {
        dr_pulse(m, t);
    }
}

static void sample_event(void *arg, uint64_t now)
{
    struct sim_adis_imu *m = arg;
    m->sample_ev = 0;
    take_sample(m, now);
    m->next_sample_16 += m->period_16;
    m->sample_ev = sim_clock_schedule(m->clk, (m->next_sample_16 + 15u) / 16u, sample_event, m);
}

/* Sample period from SMPL_PRD, or 819.2 SPS while precision autonull runs ([ADI-IMU-QS]: "the IMU
 * sets its own sample rate and filter for the 30 s"). */
static void restart_sampling(struct sim_adis_imu *m, uint64_t now)
{
    const uint16_t prd = m->prec_active ? 0x01u : (uint16_t)(m->reg[IDX(REG_SMPL_PRD)] & 0xFFu);
    uint64_t units = (uint64_t)(prd & 0x7Fu) + 1u;
    if ((prd & 0x80u) != 0u) {
        units *= TB_SLOW;
    }
    m->period_16 = units * TB_16;
    if (m->sample_ev > 0) {
        sim_clock_cancel(m->clk, m->sample_ev);
    }
    m->next_sample_16 = now * 16u + units * TB_16;
    m->sample_ev = sim_clock_schedule(m->clk, (m->next_sample_16 + 15u) / 16u, sample_event, m);
}

/* ---- commands ---- */

static void set_gyro_offset(struct sim_adis_imu *m, unsigned axis, double counts)
{
    double c = counts < 0.0 ? -floor(-counts + 0.5) : floor(counts + 0.5);
    if (c > 4095.0) { /* 13-bit two's complement, saturating */
        c = 4095.0;
    } else if (c < -4096.0) {
        c = -4096.0;
    }
    m->reg[IDX(REG_GYRO_OFF) + axis] = twos((int32_t)c, 13);
}

static void busy_done(void *arg, uint64_t now)
{
    struct sim_adis_imu *m = arg;
    m->busy_ev = 0;
    if (m->prec_active) {
        unsigned i;
        /* Precision autonull: offset = -(mean rate over the 30 s) in 0.0125 deg/s LSB. The mean
         * is of the sensor before the user offset, so the old offset does not matter. */
        m->prec_active = false;
        for (i = 0; i < 3u; i++) {
            const double mean = m->prec_n > 0u ? m->prec_sum[i] / (double)m->prec_n : 0.0;
            set_gyro_offset(m, i, -mean / GYRO_OFF_LSB_DPS);
        }
        restart_sampling(m, now);
    }
    if (m->self_test_active) {
        m->self_test_active = false;
        if (m->self_test_fail != 0u) {
            m->diag |= (uint16_t)(m->self_test_fail | DIAG_SELF_TEST);
        }
        m->reg[IDX(REG_MSC_CTRL)] &= (uint16_t)~MSC_SELF_TEST; /* clears itself when done */
    }
    m->reg[IDX(REG_MSC_CTRL)] &= (uint16_t)~MSC_MEM_TEST;
}

static void load_from_flash(struct sim_adis_imu *m)
{
    const struct wreg *t = var(m)->is_1640x ? wregs_1640x : wregs_1636x;
    const size_t n = var(m)->is_1640x ? sizeof(wregs_1640x) / sizeof(wregs_1640x[0])
                                      : sizeof(wregs_1636x) / sizeof(wregs_1636x[0]);
    size_t i;
    for (i = 0; i < n; i++) {
        m->reg[IDX(t[i].addr)] = m->flash[IDX(t[i].addr)];
    }
    m->reg[IDX(REG_FLASH_CNT)] = m->flash[IDX(REG_FLASH_CNT)];
}

static void store_to_flash(struct sim_adis_imu *m)
{
    const struct wreg *t = var(m)->is_1640x ? wregs_1640x : wregs_1636x;
    const size_t n = var(m)->is_1640x ? sizeof(wregs_1640x) / sizeof(wregs_1640x[0])
                                      : sizeof(wregs_1636x) / sizeof(wregs_1636x[0]);
    size_t i;
    for (i = 0; i < n; i++) {
        m->flash[IDX(t[i].addr)] = m->reg[IDX(t[i].addr)];
    }
    /* The self-test and memory-test bits are commands, not settings. */
    m->flash[IDX(REG_MSC_CTRL)] &= (uint16_t) ~(MSC_SELF_TEST | MSC_MEM_TEST);
    m->flash[IDX(REG_FLASH_CNT)]++;
    m->reg[IDX(REG_FLASH_CNT)] = m->flash[IDX(REG_FLASH_CNT)];
    m->flash_writes++;
}

static void glob_cmd(struct sim_adis_imu *m, uint8_t cmd, uint64_t now)
{
    uint32_t busy_ms = 0;
    unsigned i;
    m->commands++;
    if (cmd & 0x80u) {
        /* Software reset: settings come back from flash; busy for the reset time of the mode
         * the part was in (docs/sensor-facts.md §3.4). Other bits in the same write are ignored. */
        const uint32_t ms = var(m)->reset_ms[m->low_power ? 1 : 0];
        m->prec_active = false;
        m->self_test_active = false;
        load_from_flash(m);
        m->diag = 0;
        apply_bus_timing(m);
        apply_taps(m);
        apply_dr(m);
        restart_sampling(m, now);
        start_busy(m, now, ms);
        return;
    }
    if (cmd & 0x01u) {
        /* Autonull ([ADI-IMU-QS]): the part reads each gyro output and writes the opposite into its
         * offset register. The output already holds the old offset, so new = old - output; the
         * output is taken at the filter's full resolution, before quantisation [U]. */
        for (i = 0; i < 3u; i++) {
            const double old = sext(m->reg[IDX(REG_GYRO_OFF) + i], 13);
            set_gyro_offset(m, i, old - sim_adis_imu_gyro_dps(m, i) / GYRO_OFF_LSB_DPS);
        }
        busy_ms += SIM_ADIS_IMU_AUTONULL_MS;
    }
    if (cmd & 0x02u) {
        /* Factory calibration restore: user offsets back to zero [U: gyro and accel]. */
        for (i = 0; i < 3u; i++) {
            m->reg[IDX(REG_GYRO_OFF) + i] = 0;
            m->reg[IDX(REG_ACCL_OFF) + i] = 0;
        }
        busy_ms += SIM_ADIS_IMU_FACTORY_RESTORE_MS;
    }
    if (cmd & 0x08u) {
        store_to_flash(m);
        busy_ms += SIM_ADIS_IMU_FLASH_UPDATE_MS;
    }
    if (cmd & 0x10u) {
        m->prec_active = true;
        m->prec_n = 0;
        m->prec_sum[0] = m->prec_sum[1] = m->prec_sum[2] = 0.0;
        restart_sampling(m, now);
        busy_ms += SIM_ADIS_IMU_PRECISION_AUTONULL_MS;
    }
    /* bit 2 (AUX DAC latch) takes no time here. */
    if (busy_ms > 0u) {
        start_busy(m, now, busy_ms);
    }
}

/* ---- bus hooks ---- */

static void protocol_error(struct sim_adis_imu *m, uint64_t t)
{
    m->protocol_errors++;
    sim_violation_report(m->cfg.log, SIM_VIOL_PROTOCOL, m->name, t, 0, 0);
}

static void write_byte(struct sim_adis_imu *m, uint8_t addr, uint8_t value, uint64_t t)
{
    const uint8_t even = (uint8_t)(addr & 0x7Eu);
    const bool hi = (addr & 1u) != 0u;
    const struct wreg *w;
    uint16_t old, nv;
    if (even == REG_GLOB_CMD) {
        if (!hi) {
            glob_cmd(m, value, t);
        }
        return;
    }
    w = find_wreg(m, even);
    if (w == NULL) {
        protocol_error(m, t); /* read-only or no register there: the part ignores it */
        return;
    }
    old = m->reg[IDX(even)];
    nv = hi ? (uint16_t)((old & 0x00FFu) | (uint16_t)value << 8)
            : (uint16_t)((old & 0xFF00u) | value);
    nv &= w->mask;
    if (even == REG_SENS_AVG) {
        const unsigned mm = nv & 0x7u, range = (nv >> 8) & 0x7u;
        if (!hi && mm == 7u) { /* "not a valid setting" (Linux): refused */
            protocol_error(m, t);
            return;
        }
        if (hi && range != 1u && range != 2u && range != 4u) { /* [U] encoding */
            protocol_error(m, t);
            return;
        }
    }
    m->reg[IDX(even)] = nv;
    switch (even) {
    case REG_SMPL_PRD:
        apply_bus_timing(m);
        if (!m->prec_active) {
            restart_sampling(m, t);
        }
        break;
    case REG_SENS_AVG: apply_taps(m); break;
    case REG_MSC_CTRL:
        if (!hi) {
            apply_dr(m);
        } else if ((nv & MSC_SELF_TEST) && !(old & MSC_SELF_TEST)) {
            m->self_test_active = true;
            start_busy(m, t, SIM_ADIS_IMU_SELF_TEST_MS);
        } else if ((nv & MSC_MEM_TEST) && !(old & MSC_MEM_TEST)) {
            start_busy(m, t, m->low_power ? MEM_TEST_MS_LOW_POWER : MEM_TEST_MS_NORMAL);
        }
        break;
    default: break;
    }
}

static uint16_t read_word_reg(struct sim_adis_imu *m, uint8_t even)
{
    const struct wreg *w;
    if (is_output(m, even)) {
        uint16_t v = m->reg[IDX(even)];
        if (m->nd & (1ull << IDX(even))) {
            v |= ND;
        }
        if ((m->diag | m->fault_diag) != 0u) {
            v |= EA;
        }
        m->nd &= ~(1ull << IDX(even)); /* ND: new since the last read of this register */
        return v;
    }
    if (even == REG_DIAG) {
        const uint16_t d = (uint16_t)(m->diag | m->fault_diag);
        m->diag = 0; /* clears on read [U] */
        return d;
    }
    if (is_readonly(m, even)) {
        return m->reg[IDX(even)];
    }
    w = find_wreg(m, even);
    if (w == NULL) {
        return 0; /* GLOB_CMD, reserved */
    }
    if (w->sign_bits != 0u) {
        return (uint16_t)sext(m->reg[IDX(even)], w->sign_bits); /* read back sign-extended (B13) */
    }
    return m->reg[IDX(even)];
}

/* A register as the bus reads it: a stuck bit (injected) applies on top. */
static uint16_t read_word(struct sim_adis_imu *m, uint8_t even)
{
    uint16_t v = read_word_reg(m, even);
    return sim_stuck_bit_apply(&m->stuck, even, v);
}

static uint16_t op_read(void *model, uint8_t addr, uint64_t t)
{
    struct sim_adis_imu *m = model;
    (void)t;
    if (addr >= 2u * SIM_ADIS_IMU_REGS) {
        return 0;
    }
    return read_word(m, (uint8_t)(addr & 0x7Eu));
}

static void op_write(void *model, uint8_t addr, uint8_t value, uint64_t t)
{
    struct sim_adis_imu *m = model;
    if (addr >= 2u * SIM_ADIS_IMU_REGS) {
        protocol_error(m, t);
        return;
    }
    write_byte(m, addr, value, t);
}

static bool op_busy(void *model, uint64_t t)
{
    return busy_at(model, t);
}

static unsigned op_burst(void *model, uint16_t *words, unsigned max, uint64_t t)
{
    struct sim_adis_imu *m = model;
    const unsigned n = var(m)->is_1640x ? 12u : 11u;
    unsigned i;
    (void)t;
    for (i = 0; i < n && i < max; i++) {
        words[i] = read_word(m, (uint8_t)(REG_SUPPLY + 2u * i));
    }
    /* ADIS16405 burst bug (EZ forum, docs/sensor-facts.md §3.6): with a negative XGYRO_OFF, after the
     * first burst negative X-gyro values lose bit 13. Off by default. */
    if (m->cfg.burst_bug && m->cfg.variant == SIM_ADIS16405 && m->bursts_served > 0u &&
        (m->reg[IDX(REG_GYRO_OFF)] & 0x1000u) && (words[1] & 0x2000u)) {
        words[1] &= (uint16_t)~0x2000u;
    }
    m->bursts_served++;
    return i;
}

static void op_dropped(void *model, unsigned flags, uint64_t t)
{
    struct sim_adis_imu *m = model;
    (void)flags;
    (void)t;
    m->diag |= DIAG_SPI_FAIL;
    m->spi_failures++;
}

static const struct sim_adis_ops imu_ops = {op_read, op_write, op_busy, op_burst};

/* ---- public ---- */

int sim_adis_imu_init(struct sim_adis_imu *m, const struct sim_adis_imu_cfg *cfg)
{
    struct sim_adis_cfg ac;
    const struct variant *v;
    struct sim_inertial_input in;
    uint64_t now;
    unsigned i, j;
    int err;
    if (m == NULL || cfg == NULL || cfg->bus == NULL || cfg->bus->clk == NULL) {
        return INC_ERR_NULL;
    }
    if ((unsigned)cfg->variant >= (unsigned)SIM_ADIS_IMU_VARIANTS ||
        (cfg->dio1 != SIM_ADIS_IMU_NO_PIN && cfg->dio1 >= SIM_PINBUS_MAX_PINS) ||
        (cfg->dio2 != SIM_ADIS_IMU_NO_PIN && cfg->dio2 >= SIM_PINBUS_MAX_PINS)) {
        return INC_ERR_INVAL;
    }
    memset(m, 0, sizeof(*m));
    m->cfg = *cfg;
    v = var(m);
    m->name = cfg->name != NULL ? cfg->name : v->name;
    m->clk = cfg->bus->clk;
    m->dr_pin = SIM_ADIS_IMU_NO_PIN;
    now = m->clk->now_ns;

    /* Defaults (docs/sensor-facts.md §3.2, B5/B6): MSC_CTRL 0x0006, SMPL_PRD 0x0001, SENS_AVG 0x0402,
     * SIF 0x0800 on the 1640x; FLASH_CNT starts at 0 [U]. */
    m->reg[IDX(REG_PROD_ID)] = v->prod_id;
    m->reg[IDX(REG_MSC_CTRL)] = 0x0006u;
    m->reg[IDX(REG_SMPL_PRD)] = 0x0001u;
    m->reg[IDX(REG_SENS_AVG)] = 0x0402u;
    if (v->is_1640x) {
        m->reg[IDX(0x2Cu)] = m->reg[IDX(0x2Eu)] = m->reg[IDX(0x30u)] = 0x0800u;
    } else {
        m->reg[IDX(0x52u)] = 0x1234u; /* LOT_ID1, LOT_ID2, SERIAL_NUM: arbitrary */
        m->reg[IDX(0x54u)] = 0x5678u;
        m->reg[IDX(0x58u)] = 0x0042u;
    }
    memcpy(m->flash, m->reg, sizeof(m->flash));

    memset(&ac, 0, sizeof(ac));
    ac.name = m->name;
    ac.bus = cfg->bus;
    ac.cs = cfg->cs;
    ac.sclk = cfg->sclk;
    ac.mosi = cfg->mosi;
    ac.miso = cfg->miso;
    ac.addr_mask = 0x7Fu;
    ac.burst_cmd = 0x3E00u;
    ac.burst_min_period_ns = PERIOD_BURST_NS;
    ac.ops = &imu_ops;
    ac.model = m;
    ac.log = cfg->log;
    ac.seed = cfg->seed;
    ac.frame_error = op_dropped; /* DIAG_STAT[3] SPI communication failure */
    err = sim_adis_core_init(&m->core, &ac);
    if (err != INC_OK) {
        return err;
    }
    apply_bus_timing(m);
    err = sim_pinbus_add_device(cfg->bus);
    if (err < 0) {
        return err;
    }
    m->dr_dev = err;

    sim_inertial_at_rest(&m->input);
    /* The filter starts settled on the input at init (the part has been running). */
    m->taps = 1u << (m->reg[IDX(REG_SENS_AVG)] & 0x7u);
    input_now(m, now, &in);
    for (i = 0; i < SIM_ADIS_IMU_FILTERED; i++) {
        const double x = i < 3u ? in.rate_dps[i] : in.accel_g[i - 3u];
        for (j = 0; j < SIM_ADIS_IMU_HIST; j++) {
            m->filt[i].x[j] = x;
            m->filt[i].y1[j] = x;
        }
        filter_resum(&m->filt[i], 0, m->taps);
        m->filtered[i] = x;
    }
    m->hist_idx = 1;
    compute_outputs(m, &in);
    apply_dr(m);
    restart_sampling(m, now);
    if (cfg->power_on_busy) {
        start_busy(m, now, v->startup_ms);
    }
    return INC_OK;
}

void sim_adis_imu_set_input(struct sim_adis_imu *m, const struct sim_inertial_input *in)
{
    if (m != NULL && in != NULL) {
        m->input = *in;
    }
}

void sim_adis_imu_set_physics(struct sim_adis_imu *m, const struct sim_physics *p)
{
    if (m == NULL) {
        return;
    }
    if (p != NULL) {
        m->physics_hook = *p;
        m->cfg.physics = &m->physics_hook;
    } else {
        m->cfg.physics = NULL;
    }
}

void sim_adis_imu_set_error_model(struct sim_adis_imu *m, const struct sim_error_model *e)
{
    if (m == NULL) {
        return;
    }
    if (e != NULL) {
        m->error_hook = *e;
        m->cfg.error = &m->error_hook;
    } else {
        m->cfg.error = NULL;
    }
}

void sim_adis_imu_set_magn(struct sim_adis_imu *m, double x, double y, double z)
{
    if (m != NULL) {
        m->magn_gauss[0] = x;
        m->magn_gauss[1] = y;
        m->magn_gauss[2] = z;
    }
}

void sim_adis_imu_set_aux(struct sim_adis_imu *m, double volts)
{
    if (m != NULL) {
        m->aux_v = volts;
    }
}

void sim_adis_imu_set_self_test_fail(struct sim_adis_imu *m, uint16_t diag_bits)
{
    if (m != NULL) {
        m->self_test_fail = diag_bits;
    }
}

void sim_adis_imu_raise_diag(struct sim_adis_imu *m, uint16_t diag_bits)
{
    if (m != NULL) {
        m->diag |= diag_bits;
    }
}

uint16_t sim_adis_imu_peek(const struct sim_adis_imu *m, uint8_t addr)
{
    if (m == NULL || addr >= 2u * SIM_ADIS_IMU_REGS) {
        return 0;
    }
    if ((addr & 0x7Eu) == REG_DIAG) {
        return (uint16_t)(m->diag | m->fault_diag);
    }
    return m->reg[IDX(addr)];
}

void sim_adis_imu_poke(struct sim_adis_imu *m, uint8_t addr, uint16_t value)
{
    if (m == NULL || addr >= 2u * SIM_ADIS_IMU_REGS) {
        return;
    }
    write_byte(m, (uint8_t)(addr & 0x7Eu), (uint8_t)(value & 0xFFu), m->clk->now_ns);
    write_byte(m, (uint8_t)((addr & 0x7Eu) + 1u), (uint8_t)(value >> 8), m->clk->now_ns);
}

double sim_adis_imu_gyro_dps(const struct sim_adis_imu *m, unsigned axis)
{
    if (m == NULL || axis > 2u) {
        return 0.0;
    }
    return m->filtered[axis] + sim_adis_imu_gyro_offset_dps(m, axis);
}

double sim_adis_imu_gyro_offset_dps(const struct sim_adis_imu *m, unsigned axis)
{
    if (m == NULL || axis > 2u) {
        return 0.0;
    }
    return sext(m->reg[IDX(REG_GYRO_OFF) + axis], 13) * GYRO_OFF_LSB_DPS;
}

bool sim_adis_imu_is_busy(const struct sim_adis_imu *m)
{
    return m != NULL && busy_at(m, m->clk->now_ns);
}

double sim_adis_imu_rate_sps(const struct sim_adis_imu *m)
{
    if (m == NULL || m->period_16 == 0u) {
        return 0.0;
    }
    return 16e9 / (double)m->period_16;
}

/* ---- the part interface ---- */

static void p_set_input(void *model, const struct sim_inertial_input *in)
{
    sim_adis_imu_set_input(model, in);
}

static void p_set_physics(void *model, const struct sim_physics *p)
{
    sim_adis_imu_set_physics(model, p);
}

static void p_set_error_model(void *model, const struct sim_error_model *e)
{
    sim_adis_imu_set_error_model(model, e);
}

static void p_get_error_model(const void *model, struct sim_error_model *e)
{
    const struct sim_adis_imu *m = model;
    if (m->cfg.error != NULL) {
        *e = *m->cfg.error;
    } else {
        memset(e, 0, sizeof(*e));
    }
}

static struct sim_spi_slave *p_slave(void *model)
{
    return &((struct sim_adis_imu *)model)->core.slave;
}

#define FAULT_DIAG_DEFAULT 0x0040u /* DIAG_STAT[6]: flash checksum [U] on the 1636x/1640x */

static int p_fault(void *model, enum sim_fault f, const struct sim_fault_arg *a, bool on)
{
    struct sim_adis_imu *m = model;
    switch (f) {
    case SIM_FAULT_WRONG_ID:
        if (on) {
            if (m->true_prod_id == 0u) {
                m->true_prod_id = m->reg[IDX(REG_PROD_ID)];
            }
            m->reg[IDX(REG_PROD_ID)] = (uint16_t)(m->true_prod_id + 1u);
        } else if (m->true_prod_id != 0u) {
            m->reg[IDX(REG_PROD_ID)] = m->true_prod_id;
            m->true_prod_id = 0;
        }
        return INC_OK;
    case SIM_FAULT_BUSY:
        if (on) {
            const uint64_t ns = a->duration_ns != 0u ? a->duration_ns : UINT64_MAX / 2u;
            if (m->clk->now_ns + ns > m->busy_until) {
                m->busy_until = m->clk->now_ns + ns;
            }
        } else {
            m->busy_until = m->clk->now_ns;
        }
        return INC_OK;
    case SIM_FAULT_NO_DATA_READY: m->dr_suppressed = on; return INC_OK;
    case SIM_FAULT_EXTRA_DATA_READY: m->dr_extra = on; return INC_OK;
    case SIM_FAULT_DEVICE_ERROR:
        m->fault_diag = on ? (a->mask != 0u ? a->mask : FAULT_DIAG_DEFAULT) : 0u;
        return INC_OK;
    case SIM_FAULT_STUCK_BIT: return sim_stuck_bit_fault(&m->stuck, a, on, 0x7Eu, 16u);
    default: return INC_ERR_UNSUPPORTED;
    }
}

static uint16_t p_peek(const void *model, uint8_t addr)
{
    return sim_adis_imu_peek(model, addr);
}

static void p_poke(void *model, uint8_t addr, uint16_t value)
{
    sim_adis_imu_poke(model, addr, value);
}

const struct sim_part_ops sim_adis_imu_part_ops = {
    .kind = "adis_imu",
    .set_input = p_set_input,
    .set_physics = p_set_physics,
    .set_error_model = p_set_error_model,
    .get_error_model = p_get_error_model,
    .slave = p_slave,
    .fault = p_fault,
    .peek = p_peek,
    .poke = p_poke,
};

void sim_adis_imu_part(struct sim_adis_imu *m, struct sim_part *p)
{
    sim_part_bind(p, &sim_adis_imu_part_ops, m, m != NULL ? m->clk : NULL);
}
