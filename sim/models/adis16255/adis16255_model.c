/*
 * adis16255_model.c - simulated ADIS16250/ADIS16255 (see sim/adis16255.h).
 *
 * Facts: docs/sensor-facts.md §2 (A2 = Rev B p. 11 SPI frames, A3 = p. 12 output registers and ND/EA,
 * A4 = p. 15 SMPL_PRD and SCLK limits; A1/A6 register map, MSC_CTRL, STATUS, COMMAND).
 * Choices for [U] facts are marked [U] and listed in docs/drivers-adis16255.md ("Model").
 */
#include "inclino/sim/adis16255.h"
#include "inclino/sim/part.h"

#include <math.h>
#include <string.h>

/* Register addresses (lower byte). */
enum {
    R_ENDURANCE = 0x00,
    R_SUPPLY = 0x02,
    R_GYRO = 0x04,
    R_AUX_ADC = 0x0A,
    R_TEMP = 0x0C,
    R_ANGL = 0x0E,
    R_GYRO_OFF = 0x14,
    R_GYRO_SCALE = 0x16,
    R_ALM_MAG1 = 0x20,
    R_ALM_CTRL = 0x28,
    R_AUX_DAC = 0x30,
    R_GPIO_CTRL = 0x32,
    R_MSC_CTRL = 0x34,
    R_SMPL_PRD = 0x36,
    R_SENS_AVG = 0x38,
    R_SLP_CNT = 0x3A,
    R_STATUS = 0x3C,
    R_COMMAND = 0x3E,
};
#define IDX(a) ((unsigned)(a) >> 1)
#define ND_OUTPUTS                                                                                \
    ((1u << IDX(R_SUPPLY)) | (1u << IDX(R_GYRO)) | (1u << IDX(R_AUX_ADC)) | (1u << IDX(R_TEMP)) | \
     (1u << IDX(R_ANGL)))

#define ST_SUPPLY_LOW 0x0001u
#define ST_SUPPLY_HIGH 0x0002u
#define ST_FLASH_FAIL 0x0004u
#define ST_SPI_FAIL 0x0008u
#define ST_OVERRANGE 0x0010u
#define ST_SELF_TEST 0x0020u
#define ST_ALARM1 0x0100u

#define MSC_DR_LINE 0x0001u
#define MSC_DR_HIGH 0x0002u
#define MSC_DR_EN 0x0004u
#define MSC_ST_POS 0x0100u
#define MSC_ST_NEG 0x0200u
#define MSC_ST_INT 0x0400u

/* Output scales (A3): the ±320 °/s LSB is 0.07326 °/s = 320/4368; ±160 and ±80 halve and
 * quarter it [U]. */
#define GYRO_LSB_320 (320.0 / 4368.0)
#define TEMP_LSB 0.1453
#define SUPPLY_LSB 0.0018315
#define ANGL_LSB (160.0 / 4368.0) /* [U] 0.03663 °/LSB (Linux adis16260) */
#define TB_FAST_NS 1953000ull     /* A4: 1.953 ms */
#define TB_SLOW_NS 60540000ull    /* A4: 60.54 ms */

/* [U] timing of the part: the strict side, so a driver that cuts it is caught. */
static const struct sim_spi_timing timing_fast = {
    400u, /* 2.5 MHz (A4, >= 64 SPS) */
    0u,   100u,
    100u, 30000u, /* tSTALL [U]: Linux adis16260's 30 us, not the staging driver's 9 us */
    25u,  100u};
static const struct sim_spi_timing timing_slow = {
    1000u,                     /* 1 MHz (A4, < 64 SPS) */
    0u,    100u, 100u, 75000u, /* [U] low-power stall, by analogy with the ADIS1640x */
    25u,   100u};

/* Registers kept in flash (restored by reset, saved by flash update) and write masks. */
static bool nonvolatile(unsigned addr)
{
    return addr == R_GYRO_OFF || addr == R_GYRO_SCALE ||
           (addr >= R_ALM_MAG1 && addr <= R_ALM_CTRL) || addr == R_MSC_CTRL || addr == R_SMPL_PRD ||
           addr == R_SENS_AVG;
}

static uint16_t write_mask(unsigned addr)
{
    switch (addr) {
    case R_GYRO_OFF:
    case R_GYRO_SCALE:
    case R_AUX_DAC: return 0x0FFFu;
    case R_MSC_CTRL: return 0x0707u;
    case R_SENS_AVG: return 0x0707u;
    case R_SMPL_PRD:
    case R_SLP_CNT:
    case R_GPIO_CTRL: return 0x00FFu;
    default:
        if (addr >= R_ALM_MAG1 && addr <= R_ALM_CTRL) {
            return 0xFFFFu;
        }
        return 0; /* read-only */
    }
}

static uint64_t now(const struct sim_adis16255 *m)
{
    return m->clk->now_ns;
}

uint64_t sim_adis16255_period_ns(const struct sim_adis16255 *m)
{
    const uint16_t p = m->reg[IDX(R_SMPL_PRD)];
    return ((p & 0x80u) ? TB_SLOW_NS : TB_FAST_NS) * ((uint64_t)(p & 0x7Fu) + 1u);
}

static bool fast_rate(const struct sim_adis16255 *m)
{
    const uint16_t p = m->reg[IDX(R_SMPL_PRD)];
    return (p & 0x80u) == 0u && (p & 0x7Fu) <= 7u;
}

static unsigned range_code(const struct sim_adis16255 *m)
{
    const unsigned c = (m->reg[IDX(R_SENS_AVG)] >> 8) & 7u;
    return (c == 1u || c == 2u) ? c : 4u; /* [U] an invalid code acts as ±320 */
}

double sim_adis16255_gyro_lsb(const struct sim_adis16255 *m)
{
    return GYRO_LSB_320 * (double)range_code(m) / 4.0;
}

static unsigned taps(const struct sim_adis16255 *m)
{
    unsigned mexp = m->reg[IDX(R_SENS_AVG)] & 7u;
    if (mexp > 6u) {
        mexp = 6u; /* [U] code 7: treated as the longest filter */
    }
    return 1u << mexp;
}

uint16_t sim_adis16255_status(const struct sim_adis16255 *m)
{
    return (uint16_t)(m->live | m->latched | m->fault_status | (m->st_error ? ST_SELF_TEST : 0u));
}

/* ------------------------------------------------------------------ data-ready pins */

static int dr_pin(const struct sim_adis16255 *m)
{
    return (m->reg[IDX(R_MSC_CTRL)] & MSC_DR_LINE) ? m->cfg.dio1 : m->cfg.dio0;
}

static bool dr_enabled(const struct sim_adis16255 *m)
{
    return m->connected && m->sampling && (m->reg[IDX(R_MSC_CTRL)] & MSC_DR_EN) != 0u &&
           dr_pin(m) >= 0;
}

/* Drive the selected DIO to its inactive level and release the other (both when data-ready
 * is off). The selected pin is never released on the way: that would glitch it to the board's
 * pull level, a false edge for an active-low line. */
static void dr_idle(struct sim_adis16255 *m)
{
    const int sel = dr_enabled(m) ? dr_pin(m) : -1;
    if (m->cfg.dio0 >= 0 && m->cfg.dio0 != sel) {
        sim_pinbus_device_release(m->cfg.bus, (unsigned)m->dio_dev, (unsigned)m->cfg.dio0);
    }
    if (m->cfg.dio1 >= 0 && m->cfg.dio1 != sel) {
        sim_pinbus_device_release(m->cfg.bus, (unsigned)m->dio_dev, (unsigned)m->cfg.dio1);
    }
    if (sel >= 0) {
        m->dr_high = (m->reg[IDX(R_MSC_CTRL)] & MSC_DR_HIGH) == 0u;
        sim_pinbus_device_drive(m->cfg.bus, (unsigned)m->dio_dev, (unsigned)sel, m->dr_high);
    }
}

static void dr_off(void *arg, uint64_t t)
{
    struct sim_adis16255 *m = arg;
    (void)t;
    m->ev_dr_off = 0;
    dr_idle(m);
}

static void dr_pulse(struct sim_adis16255 *m, uint64_t t)
{
    if (!dr_enabled(m) || m->dr_suppressed) {
        return;
    }
    m->dr_high = (m->reg[IDX(R_MSC_CTRL)] & MSC_DR_HIGH) != 0u;
    sim_pinbus_device_drive(m->cfg.bus, (unsigned)m->dio_dev, (unsigned)dr_pin(m), m->dr_high);
    m->dr_pulses++;
    if (m->ev_dr_off > 0) {
        sim_clock_cancel(m->clk, m->ev_dr_off);
    }
    m->ev_dr_off = sim_clock_schedule(m->clk, t + m->cfg.times.dr_pulse_ns, dr_off, m);
}

/* ------------------------------------------------------------------ sampling */

static void sample_event(void *arg, uint64_t t);

static void schedule_sample(struct sim_adis16255 *m, uint64_t t)
{
    if (m->ev_sample > 0) {
        sim_clock_cancel(m->clk, m->ev_sample);
    }
    m->ev_sample = sim_clock_schedule(m->clk, t, sample_event, m);
}

static void filter_reset(struct sim_adis16255 *m)
{
    m->hist_len = 0;
    m->hist_pos = 0;
}

static double filter_push(struct sim_adis16255 *m, double x)
{
    const unsigned n = taps(m);
    double sum = 0.0;
    unsigned i, k;
    m->hist[m->hist_pos] = x;
    m->hist_pos = (m->hist_pos + 1u) % SIM_ADIS16255_HIST;
    if (m->hist_len < SIM_ADIS16255_HIST) {
        m->hist_len++;
    }
    k = n < m->hist_len ? n : m->hist_len;
    /* [U] a moving average of the last 2^M samples (the seed's "average filtering"; the
     * ADIS1636x uses a Bartlett window): identical for a steady input. */
    for (i = 0; i < k; i++) {
        sum += m->hist[(m->hist_pos + SIM_ADIS16255_HIST - 1u - i) % SIM_ADIS16255_HIST];
    }
    return sum / (double)k;
}

static void do_sample(struct sim_adis16255 *m, uint64_t t)
{
    struct sim_inertial_input in, out;
    const double dt = (double)sim_adis16255_period_ns(m) * 1e-9;
    const uint16_t msc = m->reg[IDX(R_MSC_CTRL)];
    const double lim = 80.0 * (double)range_code(m);
    const double off = (double)((int32_t)((m->reg[IDX(R_GYRO_OFF)] ^ 0x800u) & 0xFFFu) - 2048);
    const double wrap = 16384.0 * ANGL_LSB;
    double rate, y, yc;
    bool over = false;

    if (m->physics.sample != NULL) {
        m->physics.sample(m->physics.ctx, t, &in);
    } else {
        in = m->input;
    }
    if (m->error.apply != NULL) {
        m->error.apply(m->error.ctx, &in, &out, t, dt);
    } else {
        out = in;
    }
    rate = out.rate_dps[m->cfg.axis];
    /* Self-test moves the sensing element: the output shifts (a failing part does not). */
    if (m->self_test_active && !m->self_test_fail) {
        rate += SIM_ADIS16255_ST_DPS;
    }
    if (msc & MSC_ST_POS) {
        rate += SIM_ADIS16255_MAN_ST_DPS;
    }
    if (msc & MSC_ST_NEG) {
        rate -= SIM_ADIS16255_MAN_ST_DPS;
    }
    /* Digital path [U] order: filter, then GYRO_SCALE (0x0800 = 1.0), then GYRO_OFF in the
     * output's units, so autonull's negative mean cancels the bias whatever the scale. */
    y = filter_push(m, rate) * (double)m->reg[IDX(R_GYRO_SCALE)] / 2048.0 +
        off * SIM_ADIS16255_OFF_LSB;
    m->rate_out_dps = y;
    if (m->autonull_active && m->autonull_n < m->autonull_target) {
        m->autonull_sum += y;
        m->autonull_n++;
    }
    yc = y;
    if (yc > lim) {
        yc = lim;
        over = true;
    } else if (yc < -lim) {
        yc = -lim;
        over = true;
    }
    if (over && !m->self_test_active) {
        m->latched |= ST_OVERRANGE;
    }
    m->reg[IDX(R_GYRO)] = sim_twos(sim_quantise(yc, sim_adis16255_gyro_lsb(m), 14, NULL), 14);
    m->reg[IDX(R_TEMP)] = sim_twos(sim_quantise(out.temp_c - 25.0, TEMP_LSB, 12, NULL), 12);
    m->reg[IDX(R_SUPPLY)] = (uint16_t)sim_quantise_unsigned(out.supply_v, SUPPLY_LSB, 12, NULL);
    m->live = (uint16_t)((out.supply_v < 4.75 ? ST_SUPPLY_LOW : 0u) |
                         (out.supply_v > 5.25 ? ST_SUPPLY_HIGH : 0u));
    /* ANGL_OUT [U]: integral of the output rate, unsigned 14 bits, wrapping. */
    m->angle_deg = fmod(m->angle_deg + yc * dt, wrap);
    if (m->angle_deg < 0.0) {
        m->angle_deg += wrap;
    }
    m->reg[IDX(R_ANGL)] = (uint16_t)((uint32_t)floor(m->angle_deg / ANGL_LSB) & 0x3FFFu);
    m->nd |= ND_OUTPUTS;
    m->samples++;
    dr_pulse(m, t);
}

static void sample_event(void *arg, uint64_t t)
{
    struct sim_adis16255 *m = arg;
    m->ev_sample = 0;
    if (!m->sampling || !m->connected) {
        return;
    }
    do_sample(m, t);
    schedule_sample(m, t + sim_adis16255_period_ns(m));
}

/* ------------------------------------------------------------------ commands */

static void apply_rate(struct sim_adis16255 *m)
{
    sim_adis_core_set_timing(&m->core, fast_rate(m) ? &timing_fast : &timing_slow);
}

static void command_done(void *arg, uint64_t t)
{
    struct sim_adis16255 *m = arg;
    m->ev_cmd = 0;
    if (m->autonull_active) {
        m->autonull_active = false;
        if (m->autonull_n > 0u) {
            const double mean = m->autonull_sum / (double)m->autonull_n;
            const int32_t old = (int32_t)((m->reg[IDX(R_GYRO_OFF)] ^ 0x800u) & 0xFFFu) - 2048;
            int32_t nw = old - (int32_t)lround(mean / SIM_ADIS16255_OFF_LSB);
            if (nw > 2047) {
                nw = 2047;
            } else if (nw < -2048) {
                nw = -2048;
            }
            m->reg[IDX(R_GYRO_OFF)] = sim_twos(nw, 12);
        }
    }
    if (m->reset_pending) {
        /* The part restarts from its flash copy; volatile registers and outputs clear. */
        unsigned i;
        m->reset_pending = false;
        for (i = 1; i < SIM_ADIS16255_REGS; i++) {
            m->reg[i] = nonvolatile(i * 2u) ? m->flash[i] : 0u;
        }
        m->nd = 0;
        m->latched = 0;
        m->st_error = false;
        m->self_test_active = false;
        m->angle_deg = 0.0;
        filter_reset(m);
        m->sampling = true;
        apply_rate(m);
        dr_idle(m);
        schedule_sample(m, t); /* a first sample as soon as the part runs again */
    }
}

static void command(struct sim_adis16255 *m, uint8_t v, uint64_t t)
{
    uint64_t dur = 0;
    m->commands++;
    if (v & 0x01u) { /* autonull: average the next 2^M samples */
        m->autonull_active = true;
        m->autonull_target = taps(m);
        m->autonull_n = 0;
        m->autonull_sum = 0.0;
        dur += m->autonull_target * sim_adis16255_period_ns(m) + m->cfg.times.autonull_extra_ns;
    }
    if (v & 0x02u) { /* factory calibration restore [U]: RAM only, flash unchanged */
        m->reg[IDX(R_GYRO_OFF)] = 0;
        m->reg[IDX(R_GYRO_SCALE)] = 0x0800u;
        dur += m->cfg.times.factory_restore_ns;
    }
    if (v & 0x08u) { /* flash update */
        unsigned i;
        for (i = 1; i < SIM_ADIS16255_REGS; i++) {
            if (nonvolatile(i * 2u)) {
                m->flash[i] = m->reg[i];
            }
        }
        m->flash[IDX(R_MSC_CTRL)] &= (uint16_t) ~(MSC_ST_INT | MSC_ST_POS | MSC_ST_NEG);
        m->reg[IDX(R_ENDURANCE)]++;
        dur += m->cfg.times.flash_update_ns;
    }
    if (v & 0x80u) { /* software reset: nothing runs until it is done */
        m->reset_pending = true;
        m->sampling = false;
        m->autonull_active = false;
        if (m->ev_sample > 0) {
            sim_clock_cancel(m->clk, m->ev_sample);
            m->ev_sample = 0;
        }
        dr_idle(m);
        dur += m->cfg.times.reset_ns;
    }
    if (dur == 0) {
        return; /* DAC latch or nothing: immediate */
    }
    if (t + dur > m->busy_until) {
        m->busy_until = t + dur;
    }
    if (m->ev_cmd > 0) {
        sim_clock_cancel(m->clk, m->ev_cmd);
    }
    m->ev_cmd = sim_clock_schedule(m->clk, m->busy_until, command_done, m);
}

static void self_test_done(void *arg, uint64_t t)
{
    struct sim_adis16255 *m = arg;
    (void)t;
    m->ev_st = 0;
    m->self_test_active = false;
    m->st_error = m->self_test_fail;
    m->reg[IDX(R_MSC_CTRL)] &= (uint16_t)~MSC_ST_INT;
    filter_reset(m); /* [U] the filter restarts, so no self-test sample leaks into outputs */
}

/* ------------------------------------------------------------------ SPI hooks */

static uint16_t m_read_reg(void *model, uint8_t addr, uint64_t t)
{
    struct sim_adis16255 *m = model;
    const unsigned a = (unsigned)(addr & 0x3Eu);
    const unsigned i = IDX(a);
    uint16_t v;
    (void)t;
    if ((1u << i) & ND_OUTPUTS) {
        v = m->reg[i];
        if (m->nd & (1u << i)) {
            v |= 0x8000u;
        }
        if (sim_adis16255_status(m) != 0u) {
            v |= 0x4000u;
        }
        m->nd &= ~(1u << i); /* ND returns to 0 after the read (A3) */
        return v;
    }
    if (a == R_STATUS) {
        v = sim_adis16255_status(m);
        m->latched = 0; /* [U] latched bits clear on read */
        return v;
    }
    if (a == R_COMMAND) {
        return 0;
    }
    return m->reg[i];
}

/* A register as the bus reads it: a stuck bit (injected) applies on top. */
static uint16_t m_read(void *model, uint8_t addr, uint64_t t)
{
    struct sim_adis16255 *m = model;
    uint16_t v = m_read_reg(model, addr, t);
    return sim_stuck_bit_apply(&m->stuck, (uint8_t)(addr & 0x3Eu), v);
}

static void m_write(void *model, uint8_t addr, uint8_t value, uint64_t t)
{
    struct sim_adis16255 *m = model;
    const unsigned a = (unsigned)(addr & 0x3Eu);
    const unsigned i = IDX(a);
    const bool hi = (addr & 1u) != 0u;
    const uint16_t mask = write_mask(a);
    uint16_t old, nw;
    if (a == R_COMMAND) {
        if (!hi) {
            command(m, value, t);
        }
        return;
    }
    if (mask == 0u) {
        return;
    }
    old = m->reg[i];
    nw = hi ? (uint16_t)((old & 0x00FFu) | (uint16_t)value << 8)
            : (uint16_t)((old & 0xFF00u) | value);
    nw &= mask;
    m->reg[i] = nw;
    if (a == R_SMPL_PRD) {
        /* The new rate and its SCLK limit hold from the next frame; an unchanged value keeps
         * the sampling phase. */
        apply_rate(m);
        if (m->sampling && nw != old) {
            schedule_sample(m, t + sim_adis16255_period_ns(m));
        }
    } else if (a == R_MSC_CTRL) {
        if ((nw & MSC_ST_INT) && !(old & MSC_ST_INT) && !m->self_test_active) {
            m->self_test_active = true;
            m->ev_st = sim_clock_schedule(m->clk, t + m->cfg.times.self_test_ns, self_test_done, m);
        }
        if ((nw ^ old) & (MSC_DR_EN | MSC_DR_HIGH | MSC_DR_LINE)) {
            dr_idle(m);
        }
    }
}

static bool m_busy(void *model, uint64_t t)
{
    const struct sim_adis16255 *m = model;
    return t < m->busy_until;
}

static void m_frame_error(void *model, unsigned flags, uint64_t t)
{
    struct sim_adis16255 *m = model;
    (void)flags;
    (void)t;
    /* A frame the part could not decode (timing rule broken): SPI communication failure. */
    m->latched |= ST_SPI_FAIL;
    m->frame_errors++;
}

static const struct sim_adis_ops adis16255_ops = {
    .read = m_read,
    .write = m_write,
    .busy = m_busy,
    .burst = NULL, /* no burst command on this part */
};

/* ------------------------------------------------------------------ public */

int sim_adis16255_init(struct sim_adis16255 *m, const struct sim_adis16255_cfg *cfg)
{
    struct sim_adis_cfg ac;
    int dev, err;
    unsigned i;
    if (m == NULL || cfg == NULL || cfg->bus == NULL || cfg->bus->clk == NULL) {
        return INC_ERR_NULL;
    }
    if (cfg->axis > 2u) {
        return INC_ERR_INVAL;
    }
    memset(m, 0, sizeof(*m));
    m->cfg = *cfg;
    if (m->cfg.name == NULL) {
        m->cfg.name = "adis16255";
    }
    if (m->cfg.times.reset_ns == 0) m->cfg.times.reset_ns = 100000000ull;
    if (m->cfg.times.flash_update_ns == 0) m->cfg.times.flash_update_ns = 50000000ull;
    if (m->cfg.times.factory_restore_ns == 0) m->cfg.times.factory_restore_ns = 30000000ull;
    if (m->cfg.times.autonull_extra_ns == 0) m->cfg.times.autonull_extra_ns = 10000000ull;
    if (m->cfg.times.self_test_ns == 0) m->cfg.times.self_test_ns = 30000000ull;
    if (m->cfg.times.dr_pulse_ns == 0) m->cfg.times.dr_pulse_ns = 50000ull;
    m->clk = cfg->bus->clk;
    sim_inertial_at_rest(&m->input);
    /* Defaults: A4 (SMPL_PRD 0x0001), A1/A6 (GYRO_SCALE 0x0800), [U] SENS_AVG 0x0402 (±320,
     * 4 taps) and MSC_CTRL 0x0006 (data-ready on DIO0, active high) as on the ADIS1636x. */
    m->reg[IDX(R_ENDURANCE)] = cfg->endurance;
    m->reg[IDX(R_GYRO_SCALE)] = 0x0800u;
    m->reg[IDX(R_SMPL_PRD)] = 0x0001u;
    m->reg[IDX(R_SENS_AVG)] = 0x0402u;
    m->reg[IDX(R_MSC_CTRL)] = 0x0006u;
    for (i = 0; i < SIM_ADIS16255_REGS; i++) {
        m->flash[i] = m->reg[i];
    }
    dev = sim_pinbus_add_device(cfg->bus);
    if (dev < 0) {
        return dev;
    }
    m->dio_dev = dev;
    memset(&ac, 0, sizeof(ac));
    ac.name = m->cfg.name;
    ac.bus = cfg->bus;
    ac.cs = cfg->cs;
    ac.sclk = cfg->sclk;
    ac.mosi = cfg->mosi;
    ac.miso = cfg->miso;
    ac.timing = timing_fast;
    ac.addr_mask = 0x3F; /* 6-bit addresses (A2) */
    ac.burst_cmd = 0;
    ac.ops = &adis16255_ops;
    ac.model = m;
    ac.log = cfg->log;
    ac.seed = cfg->seed;
    ac.frame_error = m_frame_error;
    err = sim_adis_core_init(&m->core, &ac);
    if (err != INC_OK) {
        return err;
    }
    m->connected = true;
    m->sampling = true;
    apply_rate(m);
    dr_idle(m);
    /* The part is taken as powered up and running: its first sample is due now (it happens at
     * the first clock advance), then one every TS. */
    schedule_sample(m, now(m));
    return m->ev_sample > 0 ? INC_OK : INC_ERR_NO_SPACE;
}

void sim_adis16255_set_input(struct sim_adis16255 *m, const struct sim_inertial_input *in)
{
    if (m != NULL && in != NULL) {
        m->input = *in;
    }
}

void sim_adis16255_set_physics(struct sim_adis16255 *m, const struct sim_physics *p)
{
    if (m == NULL) {
        return;
    }
    if (p == NULL) {
        memset(&m->physics, 0, sizeof(m->physics));
    } else {
        m->physics = *p;
    }
}

void sim_adis16255_set_error_model(struct sim_adis16255 *m, const struct sim_error_model *e)
{
    if (m == NULL) {
        return;
    }
    if (e == NULL) {
        memset(&m->error, 0, sizeof(m->error));
    } else {
        m->error = *e;
    }
}

void sim_adis16255_force_busy(struct sim_adis16255 *m, uint64_t ns)
{
    if (m != NULL && now(m) + ns > m->busy_until) {
        m->busy_until = now(m) + ns;
    }
}

void sim_adis16255_fail_self_test(struct sim_adis16255 *m, bool fail)
{
    if (m != NULL) {
        m->self_test_fail = fail;
    }
}

void sim_adis16255_suppress_dr(struct sim_adis16255 *m, bool suppress)
{
    if (m != NULL) {
        m->dr_suppressed = suppress;
    }
}

void sim_adis16255_disconnect(struct sim_adis16255 *m)
{
    if (m == NULL || !m->connected) {
        return;
    }
    sim_spi_slave_detach(&m->core.slave);
    m->connected = false;
    dr_idle(m);
    if (m->ev_sample > 0) {
        sim_clock_cancel(m->clk, m->ev_sample);
        m->ev_sample = 0;
    }
}

uint16_t sim_adis16255_peek(const struct sim_adis16255 *m, uint8_t addr)
{
    if (m == NULL) {
        return 0;
    }
    if ((addr & 0x3Eu) == R_STATUS) {
        return sim_adis16255_status(m);
    }
    return m->reg[IDX(addr & 0x3Eu)];
}

void sim_adis16255_poke(struct sim_adis16255 *m, uint8_t addr, uint16_t value)
{
    if (m != NULL) {
        m->reg[IDX(addr & 0x3Eu)] = value;
    }
}

uint16_t sim_adis16255_flash(const struct sim_adis16255 *m, uint8_t addr)
{
    return m != NULL ? m->flash[IDX(addr & 0x3Eu)] : 0u;
}

/* ------------------------------------------------------------------ the part interface */

static void p_set_input(void *model, const struct sim_inertial_input *in)
{
    sim_adis16255_set_input(model, in);
}

static void p_set_physics(void *model, const struct sim_physics *p)
{
    sim_adis16255_set_physics(model, p);
}

static void p_set_error_model(void *model, const struct sim_error_model *e)
{
    sim_adis16255_set_error_model(model, e);
}

static void p_get_error_model(const void *model, struct sim_error_model *e)
{
    *e = ((const struct sim_adis16255 *)model)->error;
}

static struct sim_spi_slave *p_slave(void *model)
{
    return &((struct sim_adis16255 *)model)->core.slave;
}

#define GYRO_SCALE_FOREIGN 0x1000u /* a reserved GYRO_SCALE bit: "another part" */

static int p_fault(void *model, enum sim_fault f, const struct sim_fault_arg *a, bool on)
{
    struct sim_adis16255 *m = model;
    switch (f) {
    case SIM_FAULT_WRONG_ID:
        if (on) {
            m->reg[IDX(R_GYRO_SCALE)] |= GYRO_SCALE_FOREIGN;
        } else {
            m->reg[IDX(R_GYRO_SCALE)] &= (uint16_t)~GYRO_SCALE_FOREIGN;
        }
        return INC_OK;
    case SIM_FAULT_BUSY:
        if (on) {
            sim_adis16255_force_busy(m, a->duration_ns != 0u ? a->duration_ns : UINT64_MAX / 2u);
        } else {
            m->busy_until = now(m);
        }
        return INC_OK;
    case SIM_FAULT_NO_DATA_READY: sim_adis16255_suppress_dr(m, on); return INC_OK;
    case SIM_FAULT_DEVICE_ERROR:
        m->fault_status = on ? (a->mask != 0u ? a->mask : ST_ALARM1) : 0u;
        return INC_OK;
    case SIM_FAULT_STUCK_BIT: return sim_stuck_bit_fault(&m->stuck, a, on, 0x3Eu, 16u);
    default: return INC_ERR_UNSUPPORTED;
    }
}

static uint16_t p_peek(const void *model, uint8_t addr)
{
    return sim_adis16255_peek(model, addr);
}

static void p_poke(void *model, uint8_t addr, uint16_t value)
{
    sim_adis16255_poke(model, addr, value);
}

const struct sim_part_ops sim_adis16255_part_ops = {
    .kind = "adis16255",
    .set_input = p_set_input,
    .set_physics = p_set_physics,
    .set_error_model = p_set_error_model,
    .get_error_model = p_get_error_model,
    .slave = p_slave,
    .fault = p_fault,
    .peek = p_peek,
    .poke = p_poke,
};

void sim_adis16255_part(struct sim_adis16255 *m, struct sim_part *p)
{
    sim_part_bind(p, &sim_adis16255_part_ops, m, m != NULL ? m->clk : NULL);
}
