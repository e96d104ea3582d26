/*
 * sca3000.c - SCA3000 driver on struct spi_dev (see sca3000.h for the API and the integrity
 * rules). Register map, framing and the unlock sequence: docs/sensor-facts.md 1.2-1.5;
 * modes and rates: 1.6; the seed (001) notes that the part needs no parameter set-up to give
 * data, so init only puts it in a known state.
 */
#include "inclino/sca3000.h"

#include "sca3000_regs.h"

/* Output data rate in mHz per variant and MODE[1:0] (docs/sensor-facts.md §1.6, Linux chip table). */
static const uint32_t odr_table[4][3] = {
    {250000u, 250000u, 0u},     /* D01: normal, bypass */
    {125000u, 62500u, 0u},      /* E02: normal, narrow */
    {100000u, 50000u, 400000u}, /* E04: normal, narrow, wide */
    {200000u, 50000u, 400000u}, /* E05 */
};

static bool readable(uint8_t addr)
{
    switch (addr) {
    case SCA3000_REG_REVID:
    case SCA3000_REG_STATUS:
    case SCA3000_REG_X_LSB:
    case SCA3000_REG_X_MSB:
    case SCA3000_REG_Y_LSB:
    case SCA3000_REG_Y_MSB:
    case SCA3000_REG_Z_LSB:
    case SCA3000_REG_Z_MSB:
    case SCA3000_REG_BUF_DATA:
    case SCA3000_REG_TEMP_LSB:
    case SCA3000_REG_TEMP_MSB:
    case SCA3000_REG_MODE:
    case SCA3000_REG_BUF_COUNT:
    case SCA3000_REG_INT_STATUS:
    case SCA3000_REG_INT_MASK:
    case SCA3000_REG_CTRL_DATA: return true;
    default: return false;
    }
}

/* [cmd][n bytes] in one CS period; raw. */
static int read_raw(struct sca3000 *dev, uint8_t addr, uint8_t *buf, size_t n)
{
    uint16_t tx[SCA3000_MAX_BURST + 1u];
    uint16_t rx[SCA3000_MAX_BURST + 1u];
    size_t i;
    int err;
    tx[0] = (uint16_t)((unsigned)addr << 2);
    for (i = 1; i <= n; i++) {
        tx[i] = 0;
    }
    err = spi_transfer(&dev->spi, tx, rx, n + 1u, SPI_CS_HOLD);
    if (err != INC_OK) {
        return err;
    }
    for (i = 0; i < n; i++) {
        buf[i] = (uint8_t)rx[i + 1u];
    }
    return INC_OK;
}

/* [cmd | write][val] in one CS period (docs/sensor-facts.md §1.2: one register per frame). */
static int write_raw(struct sca3000 *dev, uint8_t addr, uint8_t val)
{
    const uint16_t tx[2] = {(uint16_t)(((unsigned)addr << 2) | SCA3000_CMD_WRITE), val};
    return spi_transfer(&dev->spi, tx, NULL, 2u, SPI_CS_HOLD);
}

/*
 * A reply made only of 0x00 or only of 0xFF is what a MISO stuck low or high (or no device on a
 * pulled line) gives. Such a reply can also be genuine (0 g on all axes), so it is confirmed by
 * reading REVID, whose value is known since init.
 */
static int confirm_bus(struct sca3000 *dev)
{
    uint8_t id;
    int err;
    dev->revid_confirms++;
    err = read_raw(dev, SCA3000_REG_REVID, &id, 1u);
    if (err != INC_OK) {
        return err;
    }
    if (id != dev->revid) {
        dev->bus_errors++;
        return INC_ERR_BUS;
    }
    return INC_OK;
}

static int check_pattern(struct sca3000 *dev, const uint8_t *buf, size_t n)
{
    bool all0 = true, all1 = true;
    size_t i;
    for (i = 0; i < n; i++) {
        all0 = all0 && buf[i] == 0x00u;
        all1 = all1 && buf[i] == 0xFFu;
    }
    return (all0 || all1) ? confirm_bus(dev) : INC_OK;
}

/*
 * Read and check STATUS. confirm_zero: 0x00 (no flag set) is also what a MISO stuck low gives;
 * confirm it with REVID. Internal checks right after a data read skip that (the data read itself
 * was checked); the public sca3000_read_diag() does it.
 */
static int status_check(struct sca3000 *dev, bool confirm_zero)
{
    uint8_t st;
    int err = read_raw(dev, SCA3000_REG_STATUS, &st, 1u);
    if (err != INC_OK) {
        return err;
    }
    if (st == 0xFFu) {
        /* Every bit set, the unnamed ones too: not a status the part gives (MISO high). */
        dev->bus_errors++;
        return INC_ERR_BUS;
    }
    if (st == 0x00u && confirm_zero) {
        err = confirm_bus(dev);
        if (err != INC_OK) {
            return err;
        }
    }
    dev->status = st;
    if ((st & SCA3000_STATUS_FRAME) != 0u) {
        dev->frame_errors++;
        return INC_ERR_DEVICE;
    }
    if ((st & SCA3000_STATUS_EEPROM) != 0u) {
        return INC_ERR_DEVICE;
    }
    return INC_OK;
}

int sca3000_read_diag(struct sca3000 *dev, uint8_t *status)
{
    int err;
    if (dev == NULL) {
        return INC_ERR_NULL;
    }
    if (!dev->ready) {
        return INC_ERR_STATE;
    }
    err = status_check(dev, true);
    if (status != NULL && (err == INC_OK || err == INC_ERR_DEVICE)) {
        *status = dev->status;
    }
    return err;
}

/* Write, read back, check STATUS. */
static int write_verified(struct sca3000 *dev, uint8_t addr, uint8_t val)
{
    uint8_t back;
    int err = write_raw(dev, addr, val);
    if (err == INC_OK) {
        err = read_raw(dev, addr, &back, 1u);
    }
    if (err == INC_OK && back != val) {
        err = (back == 0x00u || back == 0xFFu) ? confirm_bus(dev) : INC_OK;
        if (err == INC_OK) {
            err = status_check(dev, false);
        }
        if (err == INC_OK) {
            err = INC_ERR_DEVICE; /* the part did not take the value */
        }
    }
    if (err == INC_OK) {
        err = status_check(dev, false);
    }
    return err;
}

/* Read-modify-write of a direct register: only the bits in `clear` change (to `set`). */
static int rmw(struct sca3000 *dev, uint8_t addr, uint8_t clear, uint8_t set, uint8_t *result)
{
    uint8_t v, nv;
    int err = read_raw(dev, addr, &v, 1u);
    if (err == INC_OK) {
        err = check_pattern(dev, &v, 1u); /* never write back what a stuck bus made up */
    }
    if (err != INC_OK) {
        return err;
    }
    nv = (uint8_t)((v & (uint8_t)~clear) | (set & clear));
    if (nv != v) {
        err = write_verified(dev, addr, nv);
    }
    if (err == INC_OK) {
        *result = nv;
    }
    return err;
}

static int ready(const struct sca3000 *dev)
{
    if (dev == NULL) {
        return INC_ERR_NULL;
    }
    return dev->ready ? INC_OK : INC_ERR_STATE;
}

int sca3000_init(struct sca3000 *dev, const struct sca3000_cfg *cfg)
{
    uint8_t v;
    int err;
    if (dev == NULL || cfg == NULL || cfg->bus == NULL) {
        return INC_ERR_NULL;
    }
    dev->ready = false;
    dev->spi.bus = NULL;
    dev->revid = 0;
    dev->status = 0;
    dev->int_armed = false;
    sensor_dr_reset(&dev->int_edges);
    dev->pace_started = false;
    dev->next_ns = dev->sample_ns = 0u;
    dev->pace_missed = 0u;
    dev->bus_errors = dev->frame_errors = dev->revid_confirms = 0;
    if (cfg->variant == SCA3000_E01) {
        return INC_ERR_UNSUPPORTED; /* no source describes the E01 (docs/sensor-facts.md §1.1) */
    }
    if ((unsigned)cfg->variant > (unsigned)SCA3000_E05 || cfg->expected_revid == 0xFFu) {
        return INC_ERR_INVAL;
    }
    if (cfg->int_pin != HAL_PIN_NONE) {
        if (cfg->hal == NULL) {
            return INC_ERR_NULL;
        }
        err = hal_check(cfg->hal);
        if (err != INC_OK) {
            return err;
        }
    }
    dev->variant = cfg->variant;
    dev->expected_revid = cfg->expected_revid != 0u ? cfg->expected_revid
                                                    : (uint8_t)SCA3000_REVID_DEFAULT;
    dev->hal = cfg->hal;
    dev->int_pin = cfg->int_pin;
    {
        /* The SPI settings are the part's: built here, as the ADIS drivers build theirs. */
        static const struct spi_timing timing = SCA3000_SPI_TIMING_INIT;
        struct spi_dev_cfg dc;
        dc.cs = cfg->cs;
        dc.mode = cfg->spi_mode0 ? SPI_MODE_0 : SPI_MODE_3;
        dc.bits = 8u;
        dc.timing = timing;
        err = spi_dev_init(&dev->spi, cfg->bus, &dc);
    }
    if (err != INC_OK) {
        return err;
    }

    err = read_raw(dev, SCA3000_REG_REVID, &v, 1u);
    if (err != INC_OK) {
        return err;
    }
    dev->revid = v;
    if (v == 0x00u || v == 0xFFu) {
        dev->bus_errors++;
        return INC_ERR_BUS; /* MISO stuck low/high or no device */
    }
    if (v != dev->expected_revid) {
        return INC_ERR_ID;
    }

    err = status_check(dev, false);
    if (err == INC_ERR_DEVICE && dev->status == SCA3000_STATUS_FRAME) {
        /* A frame error from before this init (power-up, another driver): it is cleared by the
         * read; a second corrupt frame now would be ours. */
        err = status_check(dev, false);
    }
    if (err != INC_OK) {
        return err;
    }
    /* Acknowledge stale events (Linux clean setup, docs/sensor-facts.md §1.6). */
    err = read_raw(dev, SCA3000_REG_INT_STATUS, &v, 1u);
    if (err != INC_OK) {
        return err;
    }
    /* Normal measurement, ring and free-fall off, reserved bits kept. */
    err = rmw(dev, SCA3000_REG_MODE, (uint8_t)~SCA3000_MODE_PROTECT, 0u, &dev->mode_reg);
    if (err != INC_OK) {
        return err;
    }
    err = read_raw(dev, SCA3000_REG_INT_MASK, &dev->int_mask, 1u);
    if (err == INC_OK) {
        err = status_check(dev, false);
    }
    if (err != INC_OK) {
        return err;
    }
    dev->ready = true;
    return INC_OK;
}

uint8_t sca3000_revid(const struct sca3000 *dev)
{
    return dev != NULL ? dev->revid : 0u;
}

uint8_t sca3000_last_status(const struct sca3000 *dev)
{
    return dev != NULL ? dev->status : 0u;
}

int sca3000_read_burst(struct sca3000 *dev, uint8_t addr, uint8_t *buf, size_t n)
{
    int err = ready(dev);
    if (err != INC_OK) {
        return err;
    }
    if (buf == NULL) {
        return INC_ERR_NULL;
    }
    if (n == 0u || n > SCA3000_MAX_BURST || !readable(addr)) {
        return INC_ERR_INVAL;
    }
    return read_raw(dev, addr, buf, n);
}

int sca3000_read_reg(struct sca3000 *dev, uint8_t addr, uint8_t *val)
{
    return sca3000_read_burst(dev, addr, val, 1u);
}

int sca3000_set_mode(struct sca3000 *dev, enum sca3000_mode mode)
{
    int err = ready(dev);
    if (err != INC_OK) {
        return err;
    }
    if ((unsigned)mode > (unsigned)SCA3000_MODE_MOTION) {
        return INC_ERR_INVAL;
    }
    if (mode != SCA3000_MODE_MOTION && odr_table[dev->variant][mode] == 0u) {
        return INC_ERR_UNSUPPORTED; /* option 2 exists on the E04/E05 only */
    }
    dev->pace_started = false; /* the new rate's first sample is one period away */
    return rmw(dev, SCA3000_REG_MODE, SCA3000_MODE_MEAS_MASK, (uint8_t)mode, &dev->mode_reg);
}

enum sca3000_mode sca3000_get_mode(const struct sca3000 *dev)
{
    if (dev == NULL) {
        return SCA3000_MODE_NORMAL;
    }
    return (enum sca3000_mode)(dev->mode_reg & SCA3000_MODE_MEAS_MASK);
}

uint32_t sca3000_odr_mhz(const struct sca3000 *dev)
{
    unsigned m;
    if (dev == NULL || !dev->ready) {
        return 0u;
    }
    m = dev->mode_reg & SCA3000_MODE_MEAS_MASK;
    return m == SCA3000_MODE_MOTION ? 0u : odr_table[dev->variant][m];
}

uint32_t sca3000_period_ns(const struct sca3000 *dev)
{
    const uint32_t odr = sca3000_odr_mhz(dev);
    /* ceil(1e12 / odr_mhz) ns: never shorter than the part's period. */
    return odr == 0u ? 0u : (uint32_t)((1000000000000ull + odr - 1u) / odr);
}

int sca3000_wait_ready(struct sca3000 *dev, uint32_t timeout_ns, uint32_t *missed)
{
    uint32_t period;
    uint64_t now;
    int err = ready(dev);
    if (missed != NULL) {
        *missed = 0u;
    }
    if (err != INC_OK) {
        return err;
    }
    period = sca3000_period_ns(dev);
    if (dev->hal == NULL || period == 0u) {
        return INC_ERR_STATE;
    }
    now = hal_now_ns(dev->hal);
    if (!dev->pace_started) {
        /* The part may still hold a sample from before (its registers keep the last one),
         * which would not belong here: the first wait is one period too. */
        dev->next_ns = now + period;
        dev->pace_started = true;
    }
    dev->pace_missed = 0u;
    if (now < dev->next_ns) {
        if (timeout_ns != 0u && dev->next_ns - now > timeout_ns) {
            hal_delay_until(dev->hal, now + timeout_ns);
            return INC_ERR_TIMEOUT;
        }
        hal_delay_until(dev->hal, dev->next_ns);
        now = dev->next_ns;
    } else {
        const uint64_t late = (now - dev->next_ns) / period;
        dev->pace_missed = late > UINT32_MAX ? UINT32_MAX : (uint32_t)late;
    }
    dev->next_ns = now + period;
    dev->sample_ns = now;
    if (missed != NULL) {
        *missed = dev->pace_missed;
    }
    return INC_OK;
}

int sca3000_read_accel(struct sca3000 *dev, int16_t xyz[3])
{
    uint8_t b[6];
    int16_t c[3];
    int err = ready(dev);
    if (err != INC_OK) {
        return err;
    }
    if (xyz == NULL) {
        return INC_ERR_NULL;
    }
    if ((dev->mode_reg & SCA3000_MODE_MEAS_MASK) == SCA3000_MODE_MOTION) {
        return INC_ERR_STATE; /* no acceleration output in motion detection (docs/sensor-facts.md §1.6) */
    }
    /* From X_MSB the address decrements X_MSB, X_LSB, then wraps to Z_MSB, Z_LSB, Y_MSB, Y_LSB
     * (docs/sensor-facts.md §1.2): all three axes of one sample in one CS period. */
    err = read_raw(dev, SCA3000_REG_X_MSB, b, 6u);
    if (err == INC_OK) {
        err = check_pattern(dev, b, 6u);
    }
    if (err == INC_OK) {
        err = sca3000_accel_counts_from_word((uint16_t)(((unsigned)b[0] << 8) | b[1]), &c[0]);
    }
    if (err == INC_OK) {
        err = sca3000_accel_counts_from_word((uint16_t)(((unsigned)b[2] << 8) | b[3]), &c[2]);
    }
    if (err == INC_OK) {
        err = sca3000_accel_counts_from_word((uint16_t)(((unsigned)b[4] << 8) | b[5]), &c[1]);
    }
    if (err == INC_ERR_BUS) {
        dev->bus_errors++;
    }
    if (err == INC_OK) {
        err = status_check(dev, false);
    }
    if (err != INC_OK) {
        return err;
    }
    xyz[0] = c[0];
    xyz[1] = c[1];
    xyz[2] = c[2];
    return INC_OK;
}

int sca3000_read_temp(struct sca3000 *dev, uint16_t *raw9)
{
    uint8_t b[2];
    uint16_t t;
    int err = ready(dev);
    if (err != INC_OK) {
        return err;
    }
    if (raw9 == NULL) {
        return INC_ERR_NULL;
    }
    if (dev->variant != SCA3000_D01) {
        return INC_ERR_UNSUPPORTED; /* E0x: no temperature sensor (docs/sensor-facts.md §1.1) */
    }
    err = read_raw(dev, SCA3000_REG_TEMP_MSB, b, 2u);
    if (err == INC_OK) {
        err = check_pattern(dev, b, 2u);
    }
    if (err == INC_OK) {
        err = status_check(dev, false);
    }
    if (err != INC_OK) {
        return err;
    }
    t = sca3000_temp_counts_from_word((uint16_t)(((unsigned)b[0] << 8) | b[1]));
    *raw9 = t;
    return INC_OK;
}

int sca3000_read_sample(struct sca3000 *dev, struct sca3000_sample *s)
{
    struct sca3000_sample r;
    int err;
    if (s == NULL) {
        return ready(dev) != INC_OK ? ready(dev) : INC_ERR_NULL;
    }
    err = sca3000_read_accel(dev, r.xyz);
    if (err != INC_OK) {
        return err;
    }
    r.temp_raw = 0;
    r.temp_valid = false;
    if (dev->variant == SCA3000_D01) {
        err = sca3000_read_temp(dev, &r.temp_raw);
        if (err != INC_OK) {
            return err;
        }
        r.temp_valid = true;
    }
    *s = r;
    return INC_OK;
}

int sca3000_unlock(struct sca3000 *dev)
{
    static const uint8_t seq[3] = {0x00u, 0x50u, 0xA0u};
    unsigned i;
    int err = ready(dev);
    if (err == INC_OK) {
        err = status_check(dev, false);
    }
    if (err != INC_OK || (dev->status & SCA3000_STATUS_UNLOCKED) != 0u) {
        return err;
    }
    /* Three separate CS periods: the part does not take the sequence in one (docs/sensor-facts.md §1.2). */
    for (i = 0; i < 3u && err == INC_OK; i++) {
        err = write_raw(dev, SCA3000_REG_UNLOCK, seq[i]);
    }
    if (err == INC_OK) {
        err = status_check(dev, false);
    }
    if (err == INC_OK && (dev->status & SCA3000_STATUS_UNLOCKED) == 0u) {
        err = confirm_bus(dev); /* a dead bus reads "locked" too */
        if (err == INC_OK) {
            err = INC_ERR_DEVICE;
        }
    }
    return err;
}

static bool ind_valid(const struct sca3000 *dev, uint8_t sel)
{
    switch (sel) {
    case SCA3000_IND_I2C_DISABLE: return dev->variant == SCA3000_D01;
    case SCA3000_IND_MD_CTRL:
    case SCA3000_IND_MD_Y_TH:
    case SCA3000_IND_MD_X_TH:
    case SCA3000_IND_MD_Z_TH:
    case SCA3000_IND_OUT_CTRL: return true;
    default: return false;
    }
}

/* Unlock, select, read CTRL_DATA (no STATUS check yet). */
static int ind_select_read(struct sca3000 *dev, uint8_t sel, uint8_t *val)
{
    int err = sca3000_unlock(dev);
    if (err == INC_OK) {
        err = write_raw(dev, SCA3000_REG_CTRL_SEL, sel);
    }
    if (err == INC_OK) {
        err = read_raw(dev, SCA3000_REG_CTRL_DATA, val, 1u);
    }
    if (err == INC_OK) {
        err = check_pattern(dev, val, 1u);
    }
    return err;
}

int sca3000_ind_read(struct sca3000 *dev, uint8_t sel, uint8_t *val)
{
    uint8_t v;
    int err = ready(dev);
    if (err != INC_OK) {
        return err;
    }
    if (val == NULL) {
        return INC_ERR_NULL;
    }
    if (!ind_valid(dev, sel)) {
        return INC_ERR_INVAL;
    }
    err = ind_select_read(dev, sel, &v);
    if (err == INC_OK) {
        err = status_check(dev, false);
    }
    if (err == INC_OK) {
        *val = v;
    }
    return err;
}

int sca3000_ind_write(struct sca3000 *dev, uint8_t sel, uint8_t val)
{
    uint8_t old, nv, back, protect;
    int err = ready(dev);
    if (err != INC_OK) {
        return err;
    }
    if (!ind_valid(dev, sel)) {
        return INC_ERR_INVAL;
    }
    protect = sel == SCA3000_IND_MD_CTRL    ? SCA3000_MD_CTRL_PROTECT
              : sel == SCA3000_IND_OUT_CTRL ? SCA3000_OUT_CTRL_PROTECT
                                            : 0u;
    err = ind_select_read(dev, sel, &old);
    if (err != INC_OK) {
        return err;
    }
    if (sel == SCA3000_IND_OUT_CTRL &&
        (old & SCA3000_OUT_CTRL_PROTECT) != SCA3000_OUT_CTRL_PROTECT) {
        /* OUT_CTRL[7:5] must read set on a working part: writing them back clear would stop it. */
        return INC_ERR_DEVICE;
    }
    nv = (uint8_t)((old & protect) | (val & (uint8_t)~protect));
    err = write_raw(dev, SCA3000_REG_CTRL_DATA, nv);
    if (err == INC_OK) {
        err = read_raw(dev, SCA3000_REG_CTRL_DATA, &back, 1u);
    }
    if (err == INC_OK) {
        err = status_check(dev, false);
    }
    if (err == INC_OK && back != nv) {
        err = INC_ERR_DEVICE;
    }
    return err;
}

int sca3000_ring_config(struct sca3000 *dev, uint8_t axes, unsigned divider)
{
    const uint8_t all = SCA3000_OUT_CTRL_X | SCA3000_OUT_CTRL_Y | SCA3000_OUT_CTRL_Z;
    uint8_t div_bits;
    int err = ready(dev);
    if (err != INC_OK) {
        return err;
    }
    if (axes == 0u || (axes & (uint8_t)~all) != 0u) {
        return INC_ERR_INVAL;
    }
    if (divider == 1u) {
        div_bits = 0u;
    } else if (divider == 2u) {
        div_bits = 1u;
    } else if (divider == 4u) {
        div_bits = 2u;
    } else {
        return INC_ERR_INVAL;
    }
    return sca3000_ind_write(dev, SCA3000_IND_OUT_CTRL, (uint8_t)(axes | div_bits));
}

int sca3000_ring_enable(struct sca3000 *dev, bool on)
{
    int err = ready(dev);
    if (err != INC_OK) {
        return err;
    }
    return rmw(dev, SCA3000_REG_MODE, SCA3000_MODE_BUF_EN | SCA3000_MODE_BUF_8BIT,
               on ? SCA3000_MODE_BUF_EN : 0u, &dev->mode_reg);
}

int sca3000_ring_count(struct sca3000 *dev, unsigned *count)
{
    uint8_t c;
    int err = ready(dev);
    if (err != INC_OK) {
        return err;
    }
    if (count == NULL) {
        return INC_ERR_NULL;
    }
    err = read_raw(dev, SCA3000_REG_BUF_COUNT, &c, 1u);
    if (err != INC_OK) {
        return err;
    }
    if (c > SCA3000_RING_CAPACITY) {
        dev->bus_errors++;
        return INC_ERR_BUS; /* more than the ring holds: not a count (e.g. MISO high) */
    }
    if (c == 0u) {
        err = confirm_bus(dev); /* "empty" is also what a MISO stuck low says */
        if (err != INC_OK) {
            return err;
        }
    }
    *count = c;
    return INC_OK;
}

int sca3000_ring_read(struct sca3000 *dev, int16_t *values, size_t cap, size_t *n)
{
    uint8_t b[SCA3000_MAX_BURST];
    unsigned count;
    size_t want, done = 0;
    int err = ready(dev);
    if (err != INC_OK) {
        return err;
    }
    if (n == NULL || (values == NULL && cap > 0u)) {
        return INC_ERR_NULL;
    }
    err = sca3000_ring_count(dev, &count);
    if (err != INC_OK) {
        return err;
    }
    want = count < cap ? count : cap;
    while (done < want) {
        size_t k = want - done, i;
        if (k > SCA3000_MAX_BURST / 2u) {
            k = SCA3000_MAX_BURST / 2u;
        }
        /* BUF_DATA is a FIFO port: the address does not decrement, each 2 bytes are one value. */
        err = read_raw(dev, SCA3000_REG_BUF_DATA, b, 2u * k);
        if (err == INC_OK) {
            err = check_pattern(dev, b, 2u * k);
        }
        if (err != INC_OK) {
            return err;
        }
        for (i = 0; i < k; i++) {
            values[done + i] = sca3000_ring_counts_from_word(
                (uint16_t)(((unsigned)b[2u * i] << 8) | b[2u * i + 1u]));
        }
        done += k;
    }
    err = status_check(dev, false);
    if (err != INC_OK) {
        return err;
    }
    *n = want;
    return INC_OK;
}

int sca3000_int_config(struct sca3000 *dev, uint8_t sources, bool active_high)
{
    const uint8_t ring = SCA3000_INT_RING_3_4 | SCA3000_INT_RING_1_2;
    int err = ready(dev);
    if (err != INC_OK) {
        return err;
    }
    if ((sources & (uint8_t)~ring) != 0u) {
        return INC_ERR_INVAL; /* only the ring events are supported by this driver */
    }
    err = rmw(dev, SCA3000_REG_INT_MASK, (uint8_t)(ring | SCA3000_INT_MASK_ACTIVE_HIGH),
              (uint8_t)(sources | (active_high ? SCA3000_INT_MASK_ACTIVE_HIGH : 0u)),
              &dev->int_mask);
    if (err != INC_OK) {
        return err;
    }
    dev->int_active_high = active_high;
    if (dev->int_pin != HAL_PIN_NONE) {
        /* the data-ready helper of every driver counts the INT edges (inclino/sensor.h) */
        sensor_dr_sync(dev->hal, &dev->int_edges);
        err = hal_irq_attach(dev->hal, dev->int_pin,
                             active_high ? HAL_EDGE_RISING : HAL_EDGE_FALLING, sensor_dr_isr,
                             &dev->int_edges);
        if (err != INC_OK) {
            return err;
        }
        dev->int_armed = true;
    }
    return INC_OK;
}

int sca3000_int_status(struct sca3000 *dev, uint8_t *status)
{
    uint8_t v;
    int err = ready(dev);
    if (err != INC_OK) {
        return err;
    }
    if (status == NULL) {
        return INC_ERR_NULL;
    }
    err = read_raw(dev, SCA3000_REG_INT_STATUS, &v, 1u);
    if (err == INC_OK) {
        err = check_pattern(dev, &v, 1u); /* 0x00 ("nothing") or 0xFF: confirm the bus */
    }
    if (err == INC_OK) {
        err = status_check(dev, false);
    }
    if (err == INC_OK) {
        *status = v;
    }
    return err;
}

static bool int_line_active(const struct sca3000 *dev)
{
    return hal_pin_read(dev->hal, dev->int_pin) == dev->int_active_high;
}

int sca3000_wait_int(struct sca3000 *dev, uint64_t deadline_ns)
{
    int err = ready(dev);
    if (err != INC_OK) {
        return err;
    }
    if (!dev->int_armed) {
        return INC_ERR_STATE;
    }
    if (int_line_active(dev)) {
        sensor_dr_sync(dev->hal, &dev->int_edges); /* active now: the edges so far are seen */
        return INC_OK;
    }
    err = sensor_dr_wait(dev->hal, &dev->int_edges, deadline_ns, NULL);
    if (err == INC_ERR_TIMEOUT && int_line_active(dev)) {
        return INC_OK;
    }
    return err;
}
