/*
 * adis_imu.c - ADIS1636x/1640x driver (see adis_imu.h, docs/drivers-adis-imu.md).
 *
 * Bus: every register access goes through the shared ADIS protocol (drivers/adis: pipelined
 * reads, byte writes). The driver owns the timing of its struct spi_dev: the part's SCLK limit
 * and stall depend on its mode, which SMPL_PRD selects (docs/sensor-facts.md §3.1: <= 2 MHz while
 * SMPL_PRD[7:0] <= 0x09, <= 300 kHz otherwise) and on the kind of read (burst <= 1 MHz, B1/B12).
 */
#include "inclino/adis_imu.h"

#include "adis_imu_regs.h"
#include "inclino/compiler.h"

#define NS_PER_MS 1000000ull

/* Helpers called from several places stay out of line (INC_NOINLINE): the M0+ image counts
 * every byte. */

/* The part's channel -> register address, per family (0 = the family has no such channel;
 * address 0x00 is FLASH_CNT, never an output). docs/sensor-facts.md §3.2. Every address here is
 * inside the family's burst (burst word i = register 0x02 + 2 i, so the word of address a is rx[a
 * / 2] after the command frame): the burst is read through this table too. */
static const uint8_t chan_addr[2][ADIS_IMU_CH_COUNT] = {
    /* 1636x: SUPPLY, gyro xyz, accel xyz, (no magn), XTEMP YTEMP ZTEMP, AUX_ADC */
    {0x02, 0x04, 0x06, 0x08, 0x0A, 0x0C, 0x0E, 0, 0, 0, 0x10, 0x12, 0x14, 0x16},
    /* 1640x: SUPPLY, gyro xyz, accel xyz, magn xyz, TEMP_OUT, (no), (no), AUX_ADC */
    {0x02, 0x04, 0x06, 0x08, 0x0A, 0x0C, 0x0E, 0x10, 0x12, 0x14, 0x16, 0, 0, 0x18},
};

/* ---- timing ---- */

static void timing_for(bool low_power, bool burst, struct spi_timing *t)
{
    uint32_t period = low_power ? ADIS_IMU_SCLK_PERIOD_LOW_POWER_NS
                                : ADIS_IMU_SCLK_PERIOD_NORMAL_NS;
    if (burst && period < ADIS_IMU_SCLK_PERIOD_BURST_NS) {
        period = ADIS_IMU_SCLK_PERIOD_BURST_NS;
    }
    t->sclk_period_ns = period;
    t->cs_setup_ns = ADIS_IMU_CS_SETUP_NS;
    t->cs_hold_ns = ADIS_IMU_CS_HOLD_NS;
    t->stall_ns = low_power ? ADIS_IMU_STALL_LOW_POWER_NS : ADIS_IMU_STALL_NORMAL_NS;
    /* Burst words are separated by one SCLK period (docs/sensor-facts.md §3.1). */
    t->gap_ns = burst ? (period > ADIS_IMU_BURST_GAP_NS ? period : ADIS_IMU_BURST_GAP_NS) : 0u;
}

/* Re-time the bus for low_power (mode) and burst (kind of read). */
static INC_NOINLINE int set_timing(struct adis_imu *dev, bool low_power, bool burst)
{
    struct spi_timing t;
    timing_for(low_power, burst, &t);
    return spi_dev_set_timing(&dev->spi, &t);
}

static int set_mode_timing(struct adis_imu *dev, bool low_power)
{
    dev->low_power = low_power;
    return set_timing(dev, low_power, false);
}

/* ---- busy handling ---- */

static int resync(struct adis_imu *dev);

_Static_assert(ADIS_IMU_CH_COUNT <= ADIS_MAX_PIPELINE, "every channel in one pipelined read");

/* Wait until the part has finished the last command. 0 = nothing pending: once the time has
 * passed it is cleared, so the sample path does not read the clock for it. */
static void wait_busy(struct adis_imu *dev)
{
    if (dev->busy_until_ns != 0u) {
        hal_delay_until(dev->cfg.hal, dev->busy_until_ns);
        dev->busy_until_ns = 0u;
    }
}

static int check_ready(const struct adis_imu *dev)
{
    if (dev == NULL) {
        return INC_ERR_NULL;
    }
    return dev->ready ? INC_OK : INC_ERR_STATE;
}

/* Entry of every bus operation: state valid, part not busy, driver in step with the part. */
static int enter(struct adis_imu *dev)
{
    int err = check_ready(dev);
    if (err != INC_OK) {
        return err;
    }
    wait_busy(dev);
    if (dev->resync_pending) {
        err = resync(dev);
    }
    return err;
}

static void start_busy(struct adis_imu *dev, uint32_t ms)
{
    dev->busy_until_ns = hal_now_ns(dev->cfg.hal) + (uint64_t)ms * NS_PER_MS;
}

/* ---- data-ready ---- */

/* The MSC_CTRL data-ready bits (all in the low byte) for a setting; 0 when disabled. */
static INC_NOINLINE uint16_t dr_bits(bool enable, unsigned line, bool active_low)
{
    uint16_t bits = 0u;
    if (enable) {
        bits = ADIS_IMU_MSC_DR_EN;
        if (!active_low) {
            bits |= ADIS_IMU_MSC_DR_POL_HIGH;
        }
        if (line == (unsigned)ADIS_IMU_DR_DIO2) {
            bits |= ADIS_IMU_MSC_DR_LINE_DIO2;
        }
    }
    return bits;
}

#define DR_MASK (ADIS_IMU_MSC_DR_EN | ADIS_IMU_MSC_DR_POL_HIGH | ADIS_IMU_MSC_DR_LINE_DIO2)

/* Write the data-ready bits of MSC_CTRL (dr_bits), the other bits as cached. */
static int write_dr(struct adis_imu *dev, uint16_t bits)
{
    const uint16_t msc = (uint16_t)((dev->msc_ctrl & ~DR_MASK) | bits);
    /* The data-ready bits are all in the low byte: one frame. */
    const int err = adis_write_byte(&dev->spi, ADIS_IMU_REG_MSC_CTRL, (uint8_t)(msc & 0xFFu));
    if (err == INC_OK) {
        dev->msc_ctrl = msc;
    }
    return err;
}

/* ---- resync after reset / at init ---- */

/* The registers init reads; resync reads the three mode registers among them. */
static const uint8_t id_addrs[5] = {ADIS_IMU_REG_PROD_ID, ADIS_IMU_REG_SMPL_PRD,
                                    ADIS_IMU_REG_SENS_AVG, ADIS_IMU_REG_MSC_CTRL,
                                    ADIS_IMU_REG_DIAG_STAT};

/* Cache SMPL_PRD, SENS_AVG and MSC_CTRL as read (v[0..2]) and time the bus for the mode. */
static int apply_mode(struct adis_imu *dev, const uint16_t *v)
{
    dev->smpl_prd = (uint16_t)(v[0] & 0xFFu);
    dev->sens_avg = v[1];
    dev->msc_ctrl = v[2];
    return set_mode_timing(dev, adis_imu_smpl_prd_is_low_power((uint8_t)dev->smpl_prd));
}

/* Read the mode registers (at the low-power limits, safe in either mode) and re-time the bus. */
static int resync(struct adis_imu *dev)
{
    uint16_t v[3];
    int err = set_mode_timing(dev, true);
    if (err == INC_OK) {
        err = adis_read_regs(&dev->spi, &id_addrs[1], v, 3u);
    }
    if (err != INC_OK) {
        return err;
    }
    err = apply_mode(dev, v);
    dev->resync_pending = false;
    /* A reset restores MSC_CTRL from flash: put data-ready back as configured. */
    if (err == INC_OK && dev->dr_enabled) {
        const uint16_t want = dr_bits(true, dev->dr_line, dev->dr_active_low);
        if ((dev->msc_ctrl & DR_MASK) != want) {
            err = write_dr(dev, want);
        }
    }
    return err;
}

/* Zero n bytes without libc. */
static INC_NOINLINE void zero(void *p, size_t n)
{
    uint8_t *b = p;
    while (n-- != 0u) {
        *b++ = 0u;
    }
}

/* ---- init ---- */

static int check_cfg(const struct adis_imu_cfg *cfg)
{
    int err;
    if (cfg->hal == NULL || cfg->bus == NULL) {
        return INC_ERR_NULL;
    }
    err = hal_check(cfg->hal);
    if (err != INC_OK) {
        return err;
    }
    if (cfg->cs == HAL_PIN_NONE || cfg->dr_line > (uint8_t)ADIS_IMU_DR_DIO2 ||
        (cfg->variant >= (uint8_t)ADIS_IMU_VARIANT_COUNT &&
         cfg->variant != (uint8_t)ADIS_IMU_ANY)) {
        return INC_ERR_INVAL;
    }
    return INC_OK;
}

static uint32_t reset_ms_for(uint8_t variant)
{
    const struct adis_imu_variant_info *vi = adis_imu_variant_info((enum adis_imu_variant)variant);
    uint32_t longest = 0;
    unsigned i;
    if (vi != NULL) {
        return vi->reset_ms;
    }
    for (i = 0; i < (unsigned)ADIS_IMU_VARIANT_COUNT; i++) {
        vi = adis_imu_variant_info((enum adis_imu_variant)i);
        if (vi->reset_ms > longest) {
            longest = vi->reset_ms;
        }
    }
    return longest;
}

int adis_imu_init(struct adis_imu *dev, const struct adis_imu_cfg *cfg)
{
    struct spi_dev_cfg dc;
    uint16_t v[5];
    uint8_t found;
    int err;

    if (dev == NULL || cfg == NULL) {
        return INC_ERR_NULL;
    }
    zero(dev, sizeof(*dev));
    dev->found_variant = (uint8_t)ADIS_IMU_UNKNOWN;
    err = check_cfg(cfg);
    if (err != INC_OK) {
        return err;
    }
    dev->cfg = *cfg;
    /* Start at the low-power limits: valid whatever mode the part is in (Linux does the same,
     * docs/sensor-facts.md §4 "ADIS16400-specific setup"). */
    dc.cs = cfg->cs;
    dc.mode = SPI_MODE_3;
    dc.bits = 16;
    timing_for(true, false, &dc.timing);
    err = spi_dev_init(&dev->spi, cfg->bus, &dc);
    if (err != INC_OK) {
        return err;
    }
    dev->low_power = true;
    /* A new spi_dev does not know when CS last rose (e.g. an init right after a failed one):
     * keep the longest stall before the first frame. */
    hal_delay_ns(cfg->hal, ADIS_IMU_STALL_LOW_POWER_NS);
    if (cfg->reset_at_init) {
        err = adis_write_byte(&dev->spi, ADIS_IMU_REG_GLOB_CMD, (uint8_t)ADIS_IMU_CMD_SW_RESET);
        if (err != INC_OK) {
            return err;
        }
        start_busy(dev, reset_ms_for(cfg->variant));
        wait_busy(dev);
    }
    err = adis_read_regs(&dev->spi, id_addrs, v, 5u);
    if (err != INC_OK) {
        return err;
    }
    dev->found_id = v[0];
    found = (uint8_t)adis_imu_variant_from_prod_id(v[0]);
    dev->found_variant = found;
    dev->id_known = true;
    if (v[0] == 0x0000u || v[0] == 0xFFFFu) {
        dev->bus_errors++;
        return INC_ERR_BUS; /* nothing drives MISO, or it is stuck */
    }
    if (found == (uint8_t)ADIS_IMU_UNKNOWN ||
        (cfg->variant != (uint8_t)ADIS_IMU_ANY && found != cfg->variant)) {
        return INC_ERR_ID;
    }
    if ((v[4] & ADIS_IMU_DIAG_UNUSED) != 0u) {
        dev->bus_errors++;
        return INC_ERR_BUS;
    }
    dev->info = adis_imu_variant_info((enum adis_imu_variant)found);
    dev->init_diag = v[4];
    dev->last_diag = v[4];
    err = apply_mode(dev, &v[1]);
    if (err != INC_OK) {
        return err;
    }
    dev->ready = true;
    if (cfg->dr_pin != HAL_PIN_NONE) {
        err = adis_imu_dr_config(dev, true, (enum adis_imu_dr_line)cfg->dr_line,
                                 cfg->dr_active_low);
    }
    if (err == INC_OK && cfg->self_test_at_init) {
        err = adis_imu_self_test(dev, NULL);
    }
    if (err != INC_OK) {
        dev->ready = false;
    }
    return err;
}

int adis_imu_found(const struct adis_imu *dev, uint16_t *prod_id, enum adis_imu_variant *variant)
{
    if (dev == NULL) {
        return INC_ERR_NULL;
    }
    if (!dev->id_known) {
        return INC_ERR_STATE;
    }
    if (prod_id != NULL) {
        *prod_id = dev->found_id;
    }
    if (variant != NULL) {
        *variant = (enum adis_imu_variant)dev->found_variant;
    }
    return INC_OK;
}

/* ---- samples ---- */

static unsigned family(const struct adis_imu *dev)
{
    return dev->info->family;
}

static void sample_clear(const struct adis_imu *dev, struct adis_imu_sample *out, uint64_t t)
{
    zero(out, sizeof(*out));
    out->gyro_range = (uint8_t)adis_imu_gyro_range(dev);
    out->t_ns = t;
}

/* The words of the channels in mask that the part has, w[address / 2] (as a burst returns them
 * after its command frame), into a cleared sample: raw, counts (data field sign-extended for
 * gyro, accel, magn (14 bits) and temperatures (12 bits), masked for SUPPLY_OUT (the variant's
 * width) and AUX_ADC (12 bits)), present and stale (ND clear). */
static void sample_fill(const struct adis_imu *dev, struct adis_imu_sample *out, unsigned mask,
                        const uint16_t *w)
{
    const uint8_t *addr = chan_addr[family(dev)];
    unsigned ch, present = 0u, stale = 0u;
    for (ch = 0; ch < (unsigned)ADIS_IMU_CH_COUNT; ch++) {
        const unsigned a = addr[ch];
        if (a != 0u && (mask & ADIS_IMU_CH(ch)) != 0u) {
            const uint16_t word = w[a / 2u];
            unsigned bits = ch >= (unsigned)ADIS_IMU_CH_TEMP0 ? 12u : 14u;
            if (ch == (unsigned)ADIS_IMU_CH_SUPPLY) {
                bits = dev->info->supply_bits;
            }
            out->raw[ch] = word;
            out->counts[ch] = (ch == (unsigned)ADIS_IMU_CH_SUPPLY ||
                               ch == (unsigned)ADIS_IMU_CH_AUX)
                                  ? (int32_t)adis_field(word, bits)
                                  : adis_sign_extend(word, bits);
            present |= ADIS_IMU_CH(ch);
            if ((word & ADIS_FLAG_ND) == 0u) {
                stale |= ADIS_IMU_CH(ch);
            }
        }
    }
    out->present = (uint16_t)present;
    out->stale = (uint16_t)stale;
}

static bool all_stuck(const uint16_t *w, size_t n)
{
    size_t i;
    if (w[0] != 0x0000u && w[0] != 0xFFFFu) {
        return false;
    }
    for (i = 1; i < n; i++) {
        if (w[i] != w[0]) {
            return false;
        }
    }
    return true;
}

static int read_diag_raw(struct adis_imu *dev, uint16_t *diag)
{
    uint16_t d = 0;
    int err = adis_read_reg(&dev->spi, ADIS_IMU_REG_DIAG_STAT, &d);
    if (err != INC_OK) {
        return err;
    }
    if ((d & ADIS_IMU_DIAG_UNUSED) != 0u) {
        dev->bus_errors++;
        return INC_ERR_BUS; /* bit 7 is never set by a live part */
    }
    dev->last_diag = d;
    *diag = d;
    return INC_OK;
}

/*
 * Judge a set of output words (docs/sensor-facts.md §3.3): a bus that cannot be a live part, then EA
 * (DIAG_STAT read and kept), then ND. `stuck` says the words looked like a stuck MISO.
 */
static int sample_finish(struct adis_imu *dev, struct adis_imu_sample *out, const uint16_t *w,
                         size_t n, bool stuck)
{
    unsigned any = 0u; /* the words ORed: EA in any */
    size_t i;
    if (stuck) {
        dev->bus_errors++;
        out->valid = 0;
        return INC_ERR_BUS;
    }
    for (i = 0; i < n; i++) {
        any |= w[i];
    }
    if ((any & ADIS_FLAG_EA) != 0u) {
        uint16_t d = 0;
        int err;
        out->valid = 0;
        err = read_diag_raw(dev, &d);
        if (err != INC_OK) {
            return err;
        }
        out->diag = d;
        dev->device_errors++;
        return INC_ERR_DEVICE;
    }
    out->valid = (uint16_t)(out->present & ~out->stale);
    if (out->stale != 0u) {
        dev->stale_reads++;
        return INC_ERR_STALE;
    }
    return INC_OK;
}

int adis_imu_read_sample(struct adis_imu *dev, struct adis_imu_sample *out)
{
    uint16_t rx[1u + 12u];
    size_t n;
    int err, err2;
    if (out == NULL) {
        return INC_ERR_NULL;
    }
    err = enter(dev);
    if (err != INC_OK) {
        return err;
    }
    n = dev->info->burst_words;
    sample_clear(dev, out, hal_now_ns(dev->cfg.hal));
    err = set_timing(dev, dev->low_power, true);
    if (err == INC_OK) {
        /* DIN 0x3E00, then zeros while the part streams the outputs (docs/sensor-facts.md §3.1). */
        const uint16_t tx[1u + 12u] = {ADIS_IMU_BURST_CMD};
        err = spi_transfer(&dev->spi, tx, rx, n + 1u, SPI_CS_HOLD);
    }
    err2 = set_mode_timing(dev, dev->low_power);
    if (err == INC_OK) {
        err = err2;
    }
    if (err != INC_OK) {
        return err;
    }
    dev->bursts++;
    /* Burst words are the output registers in address order from SUPPLY_OUT (0x02). */
    sample_fill(dev, out, ADIS_IMU_CH_ALL, rx);
    /* A live part always reports a supply in range, so n equal 0x0000/0xFFFF words are a bus
     * fault whatever the data. */
    return sample_finish(dev, out, &rx[1], n, all_stuck(&rx[1], n));
}

int adis_imu_read_channels(struct adis_imu *dev, uint16_t mask, struct adis_imu_sample *out)
{
    uint8_t addrs[ADIS_IMU_CH_COUNT];
    uint16_t v[ADIS_IMU_CH_COUNT];
    uint16_t w[0x1Au / 2u] = {0}; /* v by address / 2, for sample_fill */
    size_t n = 0, i;
    bool stuck;
    unsigned ch;
    int err;
    if (out == NULL) {
        return INC_ERR_NULL;
    }
    err = enter(dev);
    if (err != INC_OK) {
        return err;
    }
    for (ch = 0; ch < (unsigned)ADIS_IMU_CH_COUNT; ch++) {
        const uint8_t a = chan_addr[family(dev)][ch];
        if ((mask & ADIS_IMU_CH(ch)) != 0u && a != 0u) {
            addrs[n++] = a;
        }
    }
    if (n == 0u) {
        return INC_ERR_INVAL;
    }
    sample_clear(dev, out, hal_now_ns(dev->cfg.hal));
    err = adis_read_regs(&dev->spi, addrs, v, n);
    if (err != INC_OK) {
        return err;
    }
    dev->reg_reads++;
    for (i = 0; i < n; i++) {
        w[addrs[i] / 2u] = v[i];
    }
    sample_fill(dev, out, mask, w);
    stuck = all_stuck(v, n);
    if (stuck) {
        /* Equal 0x0000 words can be a still part read twice (ND clear, zero data): ask for
         * PROD_ID, which a live part never returns as 0x0000 or 0xFFFF. */
        uint16_t id = 0;
        err = adis_read_reg(&dev->spi, ADIS_IMU_REG_PROD_ID, &id);
        if (err != INC_OK) {
            return err;
        }
        stuck = id != dev->found_id;
    }
    return sample_finish(dev, out, v, n, stuck);
}

static void phys_clear(struct adis_imu_phys *out)
{
    unsigned i;
    for (i = 0; i < 3u; i++) {
        out->gyro_dps[i] = out->accel_g[i] = out->magn_gauss[i] = out->temp_c[i] = 0;
    }
    out->supply_v = out->aux_v = 0;
    out->valid = 0;
}

int adis_imu_to_phys(const struct adis_imu *dev, const struct adis_imu_sample *in,
                     struct adis_imu_phys *out)
{
    unsigned i;
    int err = check_ready(dev);
    if (err != INC_OK) {
        return err;
    }
    if (in == NULL || out == NULL) {
        return INC_ERR_NULL;
    }
    for (i = 0; i < 3u && err == INC_OK; i++) {
        err = adis_imu_gyro_dps_from_counts(in->counts[ADIS_IMU_CH_GYRO_X + i],
                                            (enum adis_imu_range)in->gyro_range, &out->gyro_dps[i]);
        if (err == INC_OK) {
            err = adis_imu_accel_g_from_counts(in->counts[ADIS_IMU_CH_ACCEL_X + i],
                                               dev->info->accel_lsb_ug, &out->accel_g[i]);
        }
        if (err == INC_OK) {
            err = adis_imu_temp_c_from_counts(in->counts[ADIS_IMU_CH_TEMP0 + i],
                                              (enum adis_imu_family)family(dev), &out->temp_c[i]);
        }
        out->magn_gauss[i] = adis_imu_magn_gauss_from_counts(in->counts[ADIS_IMU_CH_MAGN_X + i]);
    }
    if (err != INC_OK) {
        /* a sample with a gyro range the driver never records: no value at all */
        phys_clear(out);
        return err;
    }
    out->supply_v = adis_imu_supply_v_from_counts(in->counts[ADIS_IMU_CH_SUPPLY]);
    out->aux_v = adis_imu_aux_v_from_counts(in->counts[ADIS_IMU_CH_AUX]);
    out->valid = in->valid;
    for (i = 0; i < (unsigned)ADIS_IMU_CH_COUNT; i++) {
        if ((in->valid & ADIS_IMU_CH(i)) == 0u) {
            /* Never hand out a number for a channel that is not valid. */
            if (i >= (unsigned)ADIS_IMU_CH_GYRO_X && i <= (unsigned)ADIS_IMU_CH_GYRO_Z) {
                out->gyro_dps[i - ADIS_IMU_CH_GYRO_X] = 0;
            } else if (i >= (unsigned)ADIS_IMU_CH_ACCEL_X && i <= (unsigned)ADIS_IMU_CH_ACCEL_Z) {
                out->accel_g[i - ADIS_IMU_CH_ACCEL_X] = 0;
            } else if (i >= (unsigned)ADIS_IMU_CH_MAGN_X && i <= (unsigned)ADIS_IMU_CH_MAGN_Z) {
                out->magn_gauss[i - ADIS_IMU_CH_MAGN_X] = 0;
            } else if (i >= (unsigned)ADIS_IMU_CH_TEMP0 && i <= (unsigned)ADIS_IMU_CH_TEMP2) {
                out->temp_c[i - ADIS_IMU_CH_TEMP0] = 0;
            } else if (i == (unsigned)ADIS_IMU_CH_SUPPLY) {
                out->supply_v = 0;
            } else {
                out->aux_v = 0;
            }
        }
    }
    return INC_OK;
}

/* ---- registers ---- */

/* The start of a register read: INC_ERR_NULL for no value, else enter's result. */
static int read_enter(struct adis_imu *dev, const uint16_t *value)
{
    return value == NULL ? INC_ERR_NULL : enter(dev);
}

int adis_imu_read_reg(struct adis_imu *dev, uint8_t addr, uint16_t *value)
{
    const struct adis_imu_reg_desc *d;
    const int err = read_enter(dev, value);
    if (err != INC_OK) {
        return err;
    }
    d = adis_imu_reg_find((enum adis_imu_family)family(dev), addr);
    if (d == NULL || (d->access & ADIS_IMU_RO) == 0u) {
        return INC_ERR_INVAL;
    }
    if (addr == ADIS_IMU_REG_DIAG_STAT) {
        return read_diag_raw(dev, value);
    }
    return adis_read_reg(&dev->spi, addr, value);
}

int adis_imu_read_known(struct adis_imu *dev, uint8_t addr, uint16_t *value)
{
    const int err = read_enter(dev, value);
    return err != INC_OK ? err : adis_read_reg(&dev->spi, addr, value);
}

int adis_imu_write_reg(struct adis_imu *dev, uint8_t addr, uint16_t value)
{
    const struct adis_imu_reg_desc *d;
    int err = enter(dev);
    if (err != INC_OK) {
        return err;
    }
    d = adis_imu_reg_find((enum adis_imu_family)family(dev), addr);
    if (d == NULL || d->access != (uint8_t)ADIS_IMU_RW || addr == ADIS_IMU_REG_SMPL_PRD ||
        addr == ADIS_IMU_REG_SENS_AVG || addr == ADIS_IMU_REG_MSC_CTRL) {
        return INC_ERR_INVAL;
    }
    return adis_write_reg(&dev->spi, addr, value);
}

int adis_imu_read_diag(struct adis_imu *dev, uint16_t *diag)
{
    int err;
    if (diag == NULL) {
        return INC_ERR_NULL;
    }
    err = enter(dev);
    if (err != INC_OK) {
        return err;
    }
    return read_diag_raw(dev, diag);
}

/* ---- rate and filter ---- */

int adis_imu_set_sample_period(struct adis_imu *dev, uint8_t smpl_prd)
{
    const bool lp = adis_imu_smpl_prd_is_low_power(smpl_prd);
    int err = enter(dev);
    if (err != INC_OK) {
        return err;
    }
    /* SMPL_PRD[15:8] is unused: one frame. The part takes its new mode when CS rises. */
    err = adis_write_byte(&dev->spi, ADIS_IMU_REG_SMPL_PRD, smpl_prd);
    if (err != INC_OK) {
        return err;
    }
    dev->smpl_prd = smpl_prd;
    if (lp != dev->low_power) {
        /* Across the mode change, keep the longer (low-power) stall once, then the new mode's
         * SCLK and stall. */
        hal_delay_ns(dev->cfg.hal, ADIS_IMU_STALL_LOW_POWER_NS);
    }
    return set_mode_timing(dev, lp);
}

uint32_t adis_imu_current_period_ns(const struct adis_imu *dev)
{
    if (dev == NULL || !dev->ready) {
        return 0;
    }
    return adis_imu_sample_period_ns((uint8_t)dev->smpl_prd);
}

static unsigned range_min_m(enum adis_imu_range r)
{
    switch (r) {
    case ADIS_IMU_RANGE_300: return 0u;
    case ADIS_IMU_RANGE_150: return ADIS_IMU_RANGE_150_MIN_M;
    case ADIS_IMU_RANGE_75: return ADIS_IMU_RANGE_75_MIN_M;
    default: return 0xFFu;
    }
}

int adis_imu_set_filter(struct adis_imu *dev, unsigned taps_log2, enum adis_imu_range range)
{
    const unsigned min_m = range_min_m(range);
    unsigned k;
    bool range_first;
    int err;
    if (taps_log2 > ADIS_IMU_SENS_AVG_M_MAX || min_m > ADIS_IMU_SENS_AVG_M_MAX ||
        taps_log2 < min_m) {
        err = check_ready(dev);
        return err != INC_OK ? err : INC_ERR_INVAL;
    }
    err = enter(dev);
    if (err != INC_OK) {
        return err;
    }
    /* Byte order keeps every intermediate setting legal: when the taps shrink, widen the range
     * (high byte) first; when they grow, add taps (low byte) first. */
    range_first = taps_log2 < (dev->sens_avg & ADIS_IMU_SENS_AVG_M_MASK);
    for (k = 0; k < 2u && err == INC_OK; k++) {
        const bool high = (k == 0u) == range_first;
        err = adis_write_byte(&dev->spi, (uint8_t)(ADIS_IMU_REG_SENS_AVG + (high ? 1u : 0u)),
                              (uint8_t)(high ? (unsigned)range : taps_log2));
    }
    if (err == INC_OK) {
        dev->sens_avg = (uint16_t)((unsigned)range << ADIS_IMU_SENS_AVG_RANGE_SHIFT | taps_log2);
    }
    return err;
}

enum adis_imu_range adis_imu_gyro_range(const struct adis_imu *dev)
{
    unsigned code;
    if (dev == NULL) {
        return ADIS_IMU_RANGE_300;
    }
    code = (dev->sens_avg >> ADIS_IMU_SENS_AVG_RANGE_SHIFT) & 0x7u;
    if (code == (unsigned)ADIS_IMU_RANGE_150) {
        return ADIS_IMU_RANGE_150;
    }
    if (code == (unsigned)ADIS_IMU_RANGE_75) {
        return ADIS_IMU_RANGE_75;
    }
    return ADIS_IMU_RANGE_300;
}

/* ---- commands ---- */

uint32_t adis_imu_command_ms(const struct adis_imu *dev, enum adis_imu_cmd cmd)
{
    switch (cmd) {
    case ADIS_IMU_CMD_AUTONULL: return ADIS_IMU_AUTONULL_MS;
    case ADIS_IMU_CMD_FACTORY_RESTORE: return ADIS_IMU_FACTORY_RESTORE_MS;
    case ADIS_IMU_CMD_AUX_DAC_LATCH: return ADIS_IMU_AUX_DAC_LATCH_MS;
    case ADIS_IMU_CMD_FLASH_UPDATE: return ADIS_IMU_FLASH_UPDATE_MS;
    case ADIS_IMU_CMD_PRECISION_AUTONULL: return ADIS_IMU_PRECISION_AUTONULL_MS;
    case ADIS_IMU_CMD_SW_RESET:
        return (dev != NULL && dev->info != NULL) ? dev->info->reset_ms
                                                  : reset_ms_for(ADIS_IMU_ANY);
    default: return 0u;
    }
}

int adis_imu_command_start(struct adis_imu *dev, enum adis_imu_cmd cmd)
{
    int err;
    const uint32_t ms = adis_imu_command_ms(dev, cmd);
    if (ms == 0u && cmd != ADIS_IMU_CMD_AUX_DAC_LATCH) {
        return check_ready(dev) != INC_OK ? check_ready(dev) : INC_ERR_INVAL;
    }
    err = enter(dev); /* an earlier command still running is waited out: this one is not lost */
    if (err != INC_OK) {
        return err;
    }
    err = adis_write_byte(&dev->spi, ADIS_IMU_REG_GLOB_CMD, (uint8_t)cmd);
    if (err != INC_OK) {
        return err;
    }
    start_busy(dev, ms);
    if (cmd == ADIS_IMU_CMD_SW_RESET) {
        /* The part comes back with its flash settings (maybe another mode): re-read them
         * before the next access. */
        dev->resync_pending = true;
    }
    return INC_OK;
}

int adis_imu_command(struct adis_imu *dev, enum adis_imu_cmd cmd)
{
    int err = adis_imu_command_start(dev, cmd);
    if (err != INC_OK) {
        return err;
    }
    return adis_imu_wait_idle(dev);
}

bool adis_imu_busy(const struct adis_imu *dev)
{
    if (dev == NULL || !dev->ready) {
        return false;
    }
    return hal_now_ns(dev->cfg.hal) < dev->busy_until_ns;
}

int adis_imu_wait_idle(struct adis_imu *dev)
{
    return enter(dev);
}

/* ---- offsets ---- */

static int offset_addr(unsigned axis, uint8_t base, uint8_t *addr)
{
    if (axis > 2u) {
        return INC_ERR_INVAL;
    }
    *addr = (uint8_t)(base + 2u * axis);
    return INC_OK;
}

static int set_offset(struct adis_imu *dev, unsigned axis, int32_t counts, uint8_t base,
                      unsigned bits)
{
    const int32_t lo = -(int32_t)(1L << (bits - 1u)), hi = (int32_t)(1L << (bits - 1u)) - 1;
    uint8_t addr = 0;
    int err = check_ready(dev);
    if (err != INC_OK) {
        return err;
    }
    err = offset_addr(axis, base, &addr);
    if (err != INC_OK) {
        return err;
    }
    if (counts < lo || counts > hi) {
        return INC_ERR_RANGE;
    }
    err = enter(dev);
    if (err != INC_OK) {
        return err;
    }
    /* Two's complement in the low `bits` bits, upper bits clear. */
    return adis_write_reg(&dev->spi, addr, (uint16_t)((uint32_t)counts & ((1UL << bits) - 1UL)));
}

static int get_offset(struct adis_imu *dev, unsigned axis, int32_t *counts, uint8_t base,
                      unsigned bits)
{
    uint8_t addr = 0;
    uint16_t v = 0;
    int err = check_ready(dev);
    if (err != INC_OK) {
        return err;
    }
    if (counts == NULL) {
        return INC_ERR_NULL;
    }
    err = offset_addr(axis, base, &addr);
    if (err == INC_OK) {
        err = enter(dev);
    }
    if (err == INC_OK) {
        err = adis_read_reg(&dev->spi, addr, &v);
    }
    if (err == INC_OK) {
        *counts = adis_sign_extend(v, bits);
    }
    return err;
}

int adis_imu_set_gyro_offset(struct adis_imu *dev, unsigned axis, int32_t counts)
{
    return set_offset(dev, axis, counts, ADIS_IMU_REG_XGYRO_OFF, ADIS_IMU_GYRO_OFF_BITS);
}

int adis_imu_get_gyro_offset(struct adis_imu *dev, unsigned axis, int32_t *counts)
{
    return get_offset(dev, axis, counts, ADIS_IMU_REG_XGYRO_OFF, ADIS_IMU_GYRO_OFF_BITS);
}

int adis_imu_set_accel_offset(struct adis_imu *dev, unsigned axis, int32_t counts)
{
    return set_offset(dev, axis, counts, ADIS_IMU_REG_XACCL_OFF, ADIS_IMU_ACCEL_OFF_BITS);
}

int adis_imu_get_accel_offset(struct adis_imu *dev, unsigned axis, int32_t *counts)
{
    return get_offset(dev, axis, counts, ADIS_IMU_REG_XACCL_OFF, ADIS_IMU_ACCEL_OFF_BITS);
}

/* ---- data-ready ---- */

int adis_imu_dr_config(struct adis_imu *dev, bool enable, enum adis_imu_dr_line line,
                       bool active_low)
{
    const struct hal *hal;
    int err = check_ready(dev);
    if (err != INC_OK) {
        return err;
    }
    if ((unsigned)line > (unsigned)ADIS_IMU_DR_DIO2) {
        return INC_ERR_INVAL;
    }
    if (enable && dev->cfg.dr_pin == HAL_PIN_NONE) {
        return INC_ERR_STATE;
    }
    err = enter(dev);
    if (err != INC_OK) {
        return err;
    }
    hal = dev->cfg.hal;
    err = write_dr(dev, dr_bits(enable, (unsigned)line, active_low));
    if (err != INC_OK) {
        return err;
    }
    if (dev->cfg.dr_pin != HAL_PIN_NONE) {
        err = hal_irq_attach(hal, dev->cfg.dr_pin, active_low ? HAL_EDGE_FALLING : HAL_EDGE_RISING,
                             enable ? sensor_dr_isr : NULL, &dev->dr);
        if (err != INC_OK) {
            return err;
        }
    }
    sensor_dr_sync(hal, &dev->dr);
    dev->dr_enabled = enable;
    dev->dr_line = (uint8_t)line;
    dev->dr_active_low = active_low;
    return INC_OK;
}

int adis_imu_wait_ready(struct adis_imu *dev, uint32_t timeout_ns, uint32_t *missed)
{
    const struct hal *hal;
    uint64_t deadline;
    uint32_t pending = 0;
    int err = enter(dev);
    if (err != INC_OK) {
        return err;
    }
    if (!dev->dr_enabled) {
        return INC_ERR_STATE;
    }
    hal = dev->cfg.hal;
    if (timeout_ns == 0u) {
        /* adis_imu_current_period_ns of a ready driver */
        timeout_ns = 3u * adis_imu_sample_period_ns((uint8_t)dev->smpl_prd);
    }
    deadline = hal_now_ns(hal) + timeout_ns;
    err = sensor_dr_wait(hal, &dev->dr, deadline, &pending);
    if (err == INC_ERR_TIMEOUT) {
        dev->timeouts++;
    }
    if (err == INC_OK && missed != NULL) {
        *missed = pending - 1u;
    }
    return err;
}

int adis_imu_dr_flush(struct adis_imu *dev)
{
    int err = check_ready(dev);
    if (err != INC_OK) {
        return err;
    }
    sensor_dr_sync(dev->cfg.hal, &dev->dr);
    return INC_OK;
}

/* ---- self-test ---- */

int adis_imu_self_test(struct adis_imu *dev, uint16_t *diag)
{
    uint16_t msc = 0, d = 0;
    unsigned polls;
    int err = enter(dev);
    if (err != INC_OK) {
        return err;
    }
    /* MSC_CTRL[10] is in the high byte; the part clears it when the test is done (B7). */
    err = adis_write_byte(&dev->spi, ADIS_IMU_REG_MSC_CTRL + 1u,
                          (uint8_t)((dev->msc_ctrl | ADIS_IMU_MSC_SELF_TEST) >> 8));
    if (err != INC_OK) {
        return err;
    }
    start_busy(dev, dev->info->self_test_ms);
    wait_busy(dev);
    for (polls = 0;; polls++) {
        err = adis_read_reg(&dev->spi, ADIS_IMU_REG_MSC_CTRL, &msc);
        if (err != INC_OK) {
            return err;
        }
        if ((msc & ADIS_IMU_MSC_SELF_TEST) == 0u) {
            break;
        }
        if (polls >= ADIS_IMU_SELF_TEST_POLLS) {
            dev->timeouts++;
            return INC_ERR_TIMEOUT;
        }
        hal_delay_ms(dev->cfg.hal, ADIS_IMU_SELF_TEST_POLL_MS);
    }
    dev->msc_ctrl = msc;
    err = read_diag_raw(dev, &d);
    if (err != INC_OK) {
        return err;
    }
    if (diag != NULL) {
        *diag = d;
    }
    if ((d & ADIS_IMU_DIAG_SELF_TEST_BITS) != 0u) {
        dev->device_errors++;
        return INC_ERR_DEVICE;
    }
    return INC_OK;
}
