/*
 * sca3000_model.c - register-level SCA3000 model (see sim/sca3000.h for the behaviour and its
 * assumptions). Sources: docs/sensor-facts.md section 1 (register map 1.3, alignment
 * 1.4, indirect registers 1.5, modes and ring buffer 1.6).
 */
#include "inclino/sim/sca3000.h"
#include "inclino/sim/part.h"

#include <stddef.h>
#include <string.h>

/* Direct register addresses (docs/sensor-facts.md §1.3). */
enum {
    R_REVID = 0x00,
    R_STATUS = 0x02,
    R_X_LSB = 0x04,
    R_X_MSB = 0x05,
    R_Y_LSB = 0x06,
    R_Y_MSB = 0x07,
    R_Z_LSB = 0x08,
    R_Z_MSB = 0x09,
    R_BUF_DATA = 0x0F,
    R_TEMP_LSB = 0x12,
    R_TEMP_MSB = 0x13,
    R_MODE = 0x14,
    R_BUF_COUNT = 0x15,
    R_INT_STATUS = 0x16,
    R_I2C_RD_SEL = 0x17,
    R_CTRL_SEL = 0x18,
    R_UNLOCK = 0x1E,
    R_INT_MASK = 0x21,
    R_CTRL_DATA = 0x22,
};

/* Indirect registers (CTRL_SEL values, docs/sensor-facts.md §1.5). */
enum {
    I_I2C_DISABLE = 0x01,
    I_MD_CTRL = 0x02,
    I_MD_Y_TH = 0x03,
    I_MD_X_TH = 0x04,
    I_MD_Z_TH = 0x05,
    I_OUT_CTRL = 0x0B,
};

#define MODE_PROTECT 0x28u
#define INT_MASK_PROTECT 0x1Cu
#define MD_CTRL_PROTECT 0xC0u
#define OUT_CTRL_REQUIRED 0xE0u
#define MODE_BUF_EN 0x80u
#define MODE_BUF_8BIT 0x40u
#define MODE_MEAS_MASK 0x03u
#define MODE_MOTION 0x03u
#define STATUS_UNLOCKED 0x20u
#define STATUS_EEPROM 0x02u
#define STATUS_FRAME 0x01u
#define INT_RING_3_4 0x80u
#define INT_RING_1_2 0x40u

/* Sensitivity in g per LSB (docs/sensor-facts.md §1.1: 0.75, 1, 2, 6.25 mg/LSB; Linux scale / 9.81). */
static const double lsb_g[4] = {0.00075, 0.001, 0.002, 0.00625};

/* Output data rate in mHz per variant and MODE[1:0] 0..2 (docs/sensor-facts.md §1.6); 0 = no such mode. */
static const uint32_t odr_mhz[4][3] = {
    {250000u, 250000u, 0u},     /* D01: normal, bypass */
    {125000u, 62500u, 0u},      /* E02: normal, narrow (ODR halved) */
    {100000u, 50000u, 400000u}, /* E04: normal, narrow, wide */
    {200000u, 50000u, 400000u}, /* E05 */
};

/* Temperature (D01): counts = T * 1.8 + 214.6 (Linux offset -214.6 LSB, 0.555556 degC/LSB). */
#define TEMP_COUNTS_PER_C 1.8
#define TEMP_OFFSET_COUNTS 214.6

static void protocol(struct sim_sca3000 *m, const char *what, uint64_t t)
{
    m->protocol_errors++;
    m->last_protocol = what;
    sim_violation_report(m->log, SIM_VIOL_PROTOCOL, m->name, t, 0, 0);
}

static void update_int_pin(struct sim_sca3000 *m)
{
    bool active, level;
    if (m->int_dev < 0 || !m->attached) {
        return;
    }
    active = (m->int_status & m->int_mask & (INT_RING_3_4 | INT_RING_1_2)) != 0u &&
             !m->int_suppressed;
    level = (m->int_mask & 0x01u) != 0u ? active : !active;
    sim_pinbus_device_drive(m->bus, (unsigned)m->int_dev, m->int_pin, level);
}

static uint64_t period_ns(const struct sim_sca3000 *m)
{
    unsigned meas = m->mode & MODE_MEAS_MASK;
    uint32_t mhz;
    if (meas == MODE_MOTION) {
        meas = 0; /* keep the clock of normal mode; outputs are frozen */
    }
    mhz = odr_mhz[m->variant][meas];
    if (mhz == 0u) {
        mhz = odr_mhz[m->variant][0];
    }
    return 1000000000000ull / mhz;
}

uint32_t sim_sca3000_odr_mhz(const struct sim_sca3000 *m)
{
    unsigned meas;
    if (m == NULL) {
        return 0;
    }
    meas = m->mode & MODE_MEAS_MASK;
    return meas == MODE_MOTION ? 0u : odr_mhz[m->variant][meas];
}

static void cancel_sampling(struct sim_sca3000 *m)
{
    if (m->sample_handle > 0) {
        sim_clock_cancel(m->bus->clk, m->sample_handle);
    }
    m->sample_handle = 0;
}

static void lock_up(struct sim_sca3000 *m, const char *what, uint64_t t)
{
    protocol(m, what, t);
    m->locked_up = true;
    cancel_sampling(m);
}

/* floor(c / 4) without relying on the rounding of negative division. */
static int32_t floor_div4(int32_t c)
{
    return c >= 0 ? c / 4 : -((-c + 3) / 4);
}

static void ring_push(struct sim_sca3000 *m, uint16_t w)
{
    if (m->ring_count == SIM_SCA3000_RING_SIZE) {
        m->ring[m->ring_head] = w;
        m->ring_head = (m->ring_head + 1u) % SIM_SCA3000_RING_SIZE;
        m->ring_overwritten++;
    } else {
        m->ring[(m->ring_head + m->ring_count) % SIM_SCA3000_RING_SIZE] = w;
        m->ring_count++;
    }
}

static void take_sample(struct sim_sca3000 *m, uint64_t t)
{
    struct sim_inertial_input truth, seen;
    const bool motion = (m->mode & MODE_MEAS_MASK) == MODE_MOTION;
    const double dt = (double)period_ns(m) * 1e-9;
    unsigned i;
    bool any_sat = false;

    if (m->physics.sample != NULL) {
        m->physics.sample(m->physics.ctx, t, &truth);
    } else {
        truth = m->input;
    }
    if (m->error.apply != NULL) {
        m->error.apply(m->error.ctx, &truth, &seen, t, dt);
    } else {
        seen = truth;
    }
    for (i = 0; i < 3u; i++) {
        double a = seen.accel_g[i];
        bool sat = false;
        int32_t c;
        if (m->range_g > 0.0) {
            if (a > m->range_g) {
                a = m->range_g;
                any_sat = true;
            } else if (a < -m->range_g) {
                a = -m->range_g;
                any_sat = true;
            }
        }
        c = motion ? 0 : sim_quantise(a, lsb_g[m->variant], 13, &sat);
        any_sat = any_sat || sat;
        m->count[i] = c;
    }
    m->saturated = any_sat;
    m->x = (uint16_t)(sim_twos(m->count[0], 13) << 3);
    m->y = (uint16_t)(sim_twos(m->count[1], 13) << 3);
    m->z = (uint16_t)(sim_twos(m->count[2], 13) << 3);
    if (m->variant == SIM_SCA3000_D01) {
        uint32_t raw = sim_quantise_unsigned(seen.temp_c * TEMP_COUNTS_PER_C + TEMP_OFFSET_COUNTS,
                                             1.0, 9, NULL);
        m->temp = (uint16_t)(raw << 5);
    } else {
        m->temp = 0;
    }
    m->samples++;

    if ((m->mode & MODE_BUF_EN) != 0u && !motion) {
        const unsigned sel = m->ind[I_OUT_CTRL] & 0x03u;
        const unsigned div = sel == 1u ? 2u : (sel == 2u ? 4u : 1u);
        if (m->ring_div_phase == 0u) {
            for (i = 0; i < 3u; i++) {
                if ((m->ind[I_OUT_CTRL] & (0x10u >> i)) != 0u) {
                    int32_t c11 = floor_div4(m->count[i]);
                    ring_push(m, (uint16_t)(((uint32_t)c11 & 0x7FFu) << 5));
                }
            }
            if (m->ring_count >= 144u) {
                m->int_status |= INT_RING_3_4;
            }
            if (m->ring_count >= 96u) {
                m->int_status |= INT_RING_1_2;
            }
            update_int_pin(m);
        }
        m->ring_div_phase = (m->ring_div_phase + 1u) % div;
    }
}

static void sample_event(void *arg, uint64_t t);

static void schedule_sampling(struct sim_sca3000 *m, uint64_t t)
{
    int h;
    cancel_sampling(m);
    m->sample_period_ns = period_ns(m);
    h = sim_clock_schedule(m->bus->clk, t, sample_event, m);
    m->sample_handle = h > 0 ? h : 0;
}

#define INT_EXTRA_NS 1000u /* width of an injected spurious INT pulse */

/* The injected spurious pulse (SIM_FAULT_EXTRA_DATA_READY): INT active for INT_EXTRA_NS, then
 * back to the level the ring buffer gives; no new sample behind it. */
static void int_extra_end(void *arg, uint64_t t)
{
    struct sim_sca3000 *m = arg;
    (void)t;
    m->int_extra_ev = 0;
    update_int_pin(m);
}

static void int_extra_start(void *arg, uint64_t t)
{
    struct sim_sca3000 *m = arg;
    int h;
    m->int_extra_ev = 0;
    if (!m->int_extra || m->int_dev < 0 || !m->attached || m->int_suppressed) {
        return;
    }
    sim_pinbus_device_drive(m->bus, (unsigned)m->int_dev, m->int_pin, (m->int_mask & 0x01u) != 0u);
    m->int_extra_pulses++;
    h = sim_clock_schedule(m->bus->clk, t + INT_EXTRA_NS, int_extra_end, m);
    m->int_extra_ev = h > 0 ? h : 0;
}

static void sample_event(void *arg, uint64_t t)
{
    struct sim_sca3000 *m = arg;
    m->sample_handle = 0;
    if (m->locked_up || !m->attached) {
        return;
    }
    take_sample(m, t);
    schedule_sampling(m, t + m->sample_period_ns);
    if (m->int_extra && m->int_extra_ev == 0) {
        const int h = sim_clock_schedule(m->bus->clk, t + m->sample_period_ns / 2u, int_extra_start,
                                         m);
        m->int_extra_ev = h > 0 ? h : 0;
    }
}

/* ---- SPI ---------------------------------------------------------------------------------- */

static uint8_t next_addr(uint8_t a)
{
    if (a == R_X_LSB) {
        return R_Z_MSB; /* the documented X_LSB -> Z_MSB wrap */
    }
    if (a == R_BUF_DATA) {
        return R_BUF_DATA; /* FIFO port: the address does not move */
    }
    return (uint8_t)((a - 1u) & 0x3Fu);
}

static bool ind_valid(const struct sim_sca3000 *m, uint8_t sel)
{
    switch (sel) {
    case I_I2C_DISABLE: return m->variant == SIM_SCA3000_D01;
    case I_MD_CTRL:
    case I_MD_Y_TH:
    case I_MD_X_TH:
    case I_MD_Z_TH:
    case I_OUT_CTRL: return true;
    default: return false;
    }
}

static uint8_t peek_reg(const struct sim_sca3000 *m, uint8_t a)
{
    switch (a) {
    case R_REVID: return m->wrong_id ? (uint8_t)(m->revid + 1u) : m->revid;
    case R_STATUS:
        return (uint8_t)((m->unlocked ? STATUS_UNLOCKED : 0u) |
                         ((m->faults & SIM_SCA3000_FAULT_EEPROM) != 0u ? STATUS_EEPROM : 0u) |
                         (m->frame_error ? STATUS_FRAME : 0u));
    case R_X_LSB: return (uint8_t)(m->lx & 0xFFu);
    case R_X_MSB: return (uint8_t)(m->lx >> 8);
    case R_Y_LSB: return (uint8_t)(m->ly & 0xFFu);
    case R_Y_MSB: return (uint8_t)(m->ly >> 8);
    case R_Z_LSB: return (uint8_t)(m->lz & 0xFFu);
    case R_Z_MSB: return (uint8_t)(m->lz >> 8);
    case R_BUF_DATA:
        if (m->ring_count == 0u) {
            return 0;
        }
        return m->ring_byte == 0u ? (uint8_t)(m->ring[m->ring_head] >> 8)
                                  : (uint8_t)(m->ring[m->ring_head] & 0xFFu);
    case R_TEMP_LSB: return (uint8_t)(m->ltemp & 0xFFu);
    case R_TEMP_MSB: return (uint8_t)(m->ltemp >> 8);
    case R_MODE: return m->mode;
    case R_BUF_COUNT: return m->lcount;
    case R_INT_STATUS: return m->int_status;
    case R_INT_MASK: return m->int_mask;
    case R_CTRL_DATA: return m->unlocked && ind_valid(m, m->ctrl_sel) ? m->ind[m->ctrl_sel] : 0u;
    default: return 0;
    }
}

/* A register as the bus reads it: a stuck bit (injected) applies on top. */
static uint8_t peek(const struct sim_sca3000 *m, uint8_t a)
{
    uint8_t v = peek_reg(m, a);
    return (uint8_t)sim_stuck_bit_apply(&m->stuck, a, v);
}

/* The byte of register a has been clocked out completely: apply the read's side effect. */
static void commit_read(struct sim_sca3000 *m, uint8_t a)
{
    switch (a) {
    case R_STATUS: m->frame_error = false; break;
    case R_INT_STATUS:
        m->int_status = 0;
        update_int_pin(m);
        break;
    case R_BUF_DATA:
        if (m->ring_count > 0u) {
            if (m->ring_byte == 0u) {
                m->ring_byte = 1u;
            } else {
                m->ring_byte = 0u;
                m->ring_head = (m->ring_head + 1u) % SIM_SCA3000_RING_SIZE;
                m->ring_count--;
            }
        }
        break;
    default: break;
    }
}

static void write_unlock(struct sim_sca3000 *m, uint8_t v)
{
    m->unlock_step_this_frame = true;
    m->unlocked = false;
    if (v == 0x00u) {
        m->unlock_step = 1;
    } else if (v == 0x50u && m->unlock_step == 1u) {
        m->unlock_step = 2;
    } else if (v == 0xA0u && m->unlock_step == 2u) {
        m->unlock_step = 0;
        m->unlocked = true;
    } else {
        m->unlock_step = 0;
    }
}

static void write_indirect(struct sim_sca3000 *m, uint8_t v, uint64_t t)
{
    const uint8_t sel = m->ctrl_sel;
    if (!m->unlocked) {
        return; /* locked: ignored */
    }
    switch (sel) {
    case I_I2C_DISABLE:
        if (m->variant != SIM_SCA3000_D01) {
            protocol(m, "I2C_DISABLE exists on the D01 only", t);
            return;
        }
        break;
    case I_MD_CTRL:
        if (((v ^ m->ind[I_MD_CTRL]) & MD_CTRL_PROTECT) != 0u) {
            lock_up(m, "MD_CTRL protected bits [7:6] changed", t);
            return;
        }
        break;
    case I_MD_Y_TH:
    case I_MD_X_TH:
    case I_MD_Z_TH: break;
    case I_OUT_CTRL:
        if ((v & OUT_CTRL_REQUIRED) != OUT_CTRL_REQUIRED) {
            lock_up(m, "OUT_CTRL bits [7:5] cleared: the part stops working", t);
            return;
        }
        break;
    default: lock_up(m, "CTRL_DATA write to a reserved indirect register", t); return;
    }
    m->ind[sel] = v;
}

static void write_mode(struct sim_sca3000 *m, uint8_t v, uint64_t t)
{
    const uint8_t old = m->mode;
    const unsigned meas = v & MODE_MEAS_MASK;
    if (((v ^ old) & MODE_PROTECT) != 0u) {
        lock_up(m, "MODE reserved bits (0x28) changed", t);
        return;
    }
    if (meas != MODE_MOTION && odr_mhz[m->variant][meas] == 0u) {
        protocol(m, "MODE option 2 does not exist on this variant", t);
        return;
    }
    if ((v & MODE_BUF_8BIT) != 0u) {
        protocol(m, "8-bit ring mode is not modelled", t);
    }
    m->mode = v;
    if ((old & MODE_BUF_EN) == 0u && (v & MODE_BUF_EN) != 0u) {
        m->ring_head = 0;
        m->ring_count = 0;
        m->ring_div_phase = 0;
    }
    if (((old ^ v) & MODE_MEAS_MASK) != 0u) {
        /* New filter and rate: the next sample comes one new period from now. */
        schedule_sampling(m, t + period_ns(m));
        if (meas == MODE_MOTION) {
            m->x = m->y = m->z = 0;
            m->count[0] = m->count[1] = m->count[2] = 0;
        }
    }
}

static void apply_write(struct sim_sca3000 *m, uint8_t a, uint8_t v, uint64_t t)
{
    m->writes_applied++;
    switch (a) {
    case R_MODE: write_mode(m, v, t); break;
    case R_I2C_RD_SEL: break; /* I2C only; harmless over SPI */
    case R_CTRL_SEL:
        if (m->unlocked) {
            m->ctrl_sel = v;
        }
        break;
    case R_UNLOCK: write_unlock(m, v); break;
    case R_INT_MASK:
        if (((v ^ m->int_mask) & INT_MASK_PROTECT) != 0u) {
            lock_up(m, "INT_MASK protected bits (0x1C) changed", t);
            return;
        }
        m->int_mask = v;
        update_int_pin(m);
        break;
    case R_CTRL_DATA: write_indirect(m, v, t); break;
    case R_REVID:
    case R_STATUS:
    case R_X_LSB:
    case R_X_MSB:
    case R_Y_LSB:
    case R_Y_MSB:
    case R_Z_LSB:
    case R_Z_MSB:
    case R_BUF_DATA:
    case R_TEMP_LSB:
    case R_TEMP_MSB:
    case R_BUF_COUNT:
    case R_INT_STATUS: protocol(m, "write to a read-only register (ignored)", t); break;
    default: lock_up(m, "write to a reserved register", t); break;
    }
}

static uint16_t op_begin(void *model, unsigned flags, uint64_t t)
{
    struct sim_sca3000 *m = model;
    (void)flags;
    (void)t;
    m->frames++;
    m->lx = m->x;
    m->ly = m->y;
    m->lz = m->z;
    m->ltemp = m->temp;
    m->lcount = (uint8_t)(m->ring_count > 255u ? 255u : m->ring_count);
    m->is_write = false;
    m->bad_cmd = false;
    m->have_out = false;
    m->ring_byte = 0;
    m->unlock_step_this_frame = false;
    return 0x00; /* shifted out during the command byte */
}

static uint16_t op_word(void *model, uint16_t mosi, unsigned index, unsigned flags, uint64_t t)
{
    struct sim_sca3000 *m = model;
    (void)flags;
    (void)t;
    if (m->locked_up) {
        return 0;
    }
    if (index == 0u) {
        const uint8_t cmd = (uint8_t)mosi;
        if ((cmd & 0x01u) != 0u) {
            m->bad_cmd = true;
            return 0;
        }
        m->addr = (uint8_t)(cmd >> 2);
        m->is_write = (cmd & 0x02u) != 0u;
        if (m->is_write) {
            return 0;
        }
        m->out_addr = m->addr;
        m->have_out = true;
        return peek(m, m->out_addr);
    }
    if (m->bad_cmd) {
        return 0;
    }
    if (m->is_write) {
        if (index == 1u) {
            m->wdata = (uint8_t)mosi;
        }
        return 0;
    }
    commit_read(m, m->out_addr);
    m->out_addr = next_addr(m->out_addr);
    return peek(m, m->out_addr);
}

static void op_end(void *model, unsigned words, unsigned flags, uint64_t t)
{
    struct sim_sca3000 *m = model;
    bool corrupt = flags != 0u;
    if (m->locked_up) {
        return;
    }
    if (words == 0u && flags == 0u) {
        return; /* CS pulsed without a clock: nothing happened */
    }
    if (m->bad_cmd) {
        protocol(m, "command byte with bit0 set", t);
        corrupt = true;
    } else if (m->is_write && words != 2u) {
        protocol(m, "write frame is not exactly [command][data]", t);
        corrupt = true;
    }
    if (!corrupt && m->is_write) {
        apply_write(m, m->addr, m->wdata, t);
    }
    if (!m->unlock_step_this_frame) {
        m->unlock_step = 0; /* any other frame between the UNLOCK writes restarts the sequence */
    }
    if (corrupt) {
        m->frame_error = true;
        m->corrupt_frames++;
    }
}

static const struct sim_spi_slave_ops model_ops = {
    .frame_begin = op_begin,
    .word = op_word,
    .frame_end = op_end,
};

/* ---- public ------------------------------------------------------------------------------- */

void sim_sca3000_power_cycle(struct sim_sca3000 *m)
{
    if (m == NULL) {
        return;
    }
    m->mode = SIM_SCA3000_MODE_DEFAULT;
    m->int_mask = SIM_SCA3000_INT_MASK_DEFAULT;
    m->int_status = 0;
    m->ctrl_sel = 0;
    memset(m->ind, 0, sizeof(m->ind));
    m->ind[I_MD_CTRL] = SIM_SCA3000_MD_CTRL_DEFAULT;
    m->ind[I_OUT_CTRL] = SIM_SCA3000_OUT_CTRL_DEFAULT;
    m->frame_error = false;
    m->unlocked = false;
    m->locked_up = false;
    m->unlock_step = 0;
    m->x = m->y = m->z = m->temp = 0;
    m->ring_head = m->ring_count = m->ring_div_phase = 0;
    update_int_pin(m);
    if (m->attached) {
        schedule_sampling(m, m->bus->clk->now_ns);
    }
}

int sim_sca3000_init(struct sim_sca3000 *m, const struct sim_sca3000_cfg *cfg)
{
    struct sim_spi_slave_cfg sc;
    static const struct sim_spi_timing limits = {
        .min_period_ns = SIM_SCA3000_TIMING_MIN_PERIOD_NS,
        .min_half_ns = SIM_SCA3000_TIMING_MIN_HALF_NS,
        .min_cs_setup_ns = SIM_SCA3000_TIMING_CS_SETUP_NS,
        .min_cs_hold_ns = SIM_SCA3000_TIMING_CS_HOLD_NS,
        .min_stall_ns = SIM_SCA3000_TIMING_STALL_NS,
        .mosi_setup_ns = SIM_SCA3000_TIMING_MOSI_SETUP_NS,
        .miso_delay_ns = SIM_SCA3000_TIMING_MISO_DELAY_NS,
    };
    int err;
    if (m == NULL || cfg == NULL || cfg->bus == NULL || cfg->bus->clk == NULL) {
        return INC_ERR_NULL;
    }
    if ((unsigned)cfg->variant > (unsigned)SIM_SCA3000_E05 ||
        (cfg->int_pin != SIM_SCA3000_NO_PIN && cfg->int_pin >= SIM_PINBUS_MAX_PINS) ||
        cfg->range_g < 0.0) {
        return INC_ERR_INVAL;
    }
    memset(m, 0, sizeof(*m));
    m->bus = cfg->bus;
    m->variant = cfg->variant;
    m->name = cfg->name != NULL ? cfg->name : "sca3000";
    m->log = cfg->log;
    m->range_g = cfg->range_g;
    m->revid = cfg->revid != 0u ? cfg->revid : (uint8_t)SIM_SCA3000_REVID_DEFAULT;
    m->int_pin = cfg->int_pin;
    m->int_dev = -1;
    sim_inertial_at_rest(&m->input);

    sc.name = m->name;
    sc.bus = cfg->bus;
    sc.cs = cfg->cs;
    sc.sclk = cfg->sclk;
    sc.mosi = cfg->mosi;
    sc.miso = cfg->miso;
    sc.mode = SIM_SPI_MODE_AUTO_0_3;
    sc.bits = 8;
    sc.timing = cfg->timing != NULL ? *cfg->timing : limits;
    sc.ops = &model_ops;
    sc.model = m;
    sc.log = cfg->log;
    err = sim_spi_slave_init(&m->slave, &sc);
    if (err != INC_OK) {
        return err;
    }
    if (cfg->int_pin != SIM_SCA3000_NO_PIN) {
        int d = sim_pinbus_add_device(cfg->bus);
        if (d < 0) {
            return d;
        }
        m->int_dev = d;
    }
    m->attached = true;
    sim_sca3000_power_cycle(m);
    return INC_OK;
}

void sim_sca3000_set_input(struct sim_sca3000 *m, const struct sim_inertial_input *in)
{
    if (m != NULL && in != NULL) {
        m->input = *in;
    }
}

void sim_sca3000_set_physics(struct sim_sca3000 *m, const struct sim_physics *p)
{
    if (m == NULL) {
        return;
    }
    if (p != NULL) {
        m->physics = *p;
    } else {
        m->physics.sample = NULL;
        m->physics.ctx = NULL;
    }
}

void sim_sca3000_set_error_model(struct sim_sca3000 *m, const struct sim_error_model *e)
{
    if (m == NULL) {
        return;
    }
    if (e != NULL) {
        m->error = *e;
    } else {
        m->error.apply = NULL;
        m->error.ctx = NULL;
    }
}

void sim_sca3000_set_faults(struct sim_sca3000 *m, uint8_t faults)
{
    if (m != NULL) {
        m->faults = faults;
    }
}

void sim_sca3000_detach(struct sim_sca3000 *m)
{
    if (m == NULL || !m->attached) {
        return;
    }
    cancel_sampling(m);
    sim_spi_slave_detach(&m->slave);
    if (m->int_dev >= 0) {
        sim_pinbus_device_release(m->bus, (unsigned)m->int_dev, m->int_pin);
    }
    m->attached = false;
}

/* ---- the part interface ------------------------------------------------------------------ */

static void p_set_input(void *model, const struct sim_inertial_input *in)
{
    sim_sca3000_set_input(model, in);
}

static void p_set_physics(void *model, const struct sim_physics *p)
{
    sim_sca3000_set_physics(model, p);
}

static void p_set_error_model(void *model, const struct sim_error_model *e)
{
    sim_sca3000_set_error_model(model, e);
}

static void p_get_error_model(const void *model, struct sim_error_model *e)
{
    *e = ((const struct sim_sca3000 *)model)->error;
}

static struct sim_spi_slave *p_slave(void *model)
{
    return &((struct sim_sca3000 *)model)->slave;
}

static int p_fault(void *model, enum sim_fault f, const struct sim_fault_arg *a, bool on)
{
    struct sim_sca3000 *m = model;
    switch (f) {
    case SIM_FAULT_WRONG_ID: m->wrong_id = on; return INC_OK;
    case SIM_FAULT_NO_DATA_READY:
        m->int_suppressed = on;
        update_int_pin(m);
        return INC_OK;
    case SIM_FAULT_EXTRA_DATA_READY: m->int_extra = on; return INC_OK;
    case SIM_FAULT_DEVICE_ERROR:
        if (on) {
            m->faults |= SIM_SCA3000_FAULT_EEPROM;
        } else {
            m->faults &= (uint8_t)~SIM_SCA3000_FAULT_EEPROM;
        }
        return INC_OK;
    case SIM_FAULT_STUCK_BIT: return sim_stuck_bit_fault(&m->stuck, a, on, 0x3Fu, 8u);
    default: return INC_ERR_UNSUPPORTED;
    }
}

static uint16_t p_peek(const void *model, uint8_t addr)
{
    return peek(model, (uint8_t)(addr & 0x3Fu));
}

static void p_poke(void *model, uint8_t addr, uint16_t value)
{
    struct sim_sca3000 *m = model;
    apply_write(m, (uint8_t)(addr & 0x3Fu), (uint8_t)value, m->bus->clk->now_ns);
}

const struct sim_part_ops sim_sca3000_part_ops = {
    .kind = "sca3000",
    .set_input = p_set_input,
    .set_physics = p_set_physics,
    .set_error_model = p_set_error_model,
    .get_error_model = p_get_error_model,
    .slave = p_slave,
    .fault = p_fault,
    .peek = p_peek,
    .poke = p_poke,
};

void sim_sca3000_part(struct sim_sca3000 *m, struct sim_part *p)
{
    sim_part_bind(p, &sim_sca3000_part_ops, m, m != NULL && m->bus != NULL ? m->bus->clk : NULL);
}
