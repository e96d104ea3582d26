/*
 * adis16255.c - ADIS16250/ADIS16255 gyroscope driver (see adis16255.h).
 *
 * Sources: docs/sensor-facts.md §2 (ADIS16250/55 Rev B pp. 11, 12, 15 = A2, A3, A4; Linux adis16260 = A6;
 * staging adis16255 = A1), §4 (the Linux ADIS library's procedures). [KF-SCA3000] (SCA3000 +
 * ADIS16255 over bit-banged SPI) notes that "the 16255 needed configuration to reduce its bias":
 * hence SENS_AVG filtering, GYRO_OFF and autonull are first-class here.
 */
#include "inclino/adis16255.h"

#include "adis16255_regs.h"
#include "inclino/adis.h"

#define NS_PER_MS 1000000ull
#define NS_PER_US 1000ull

/* ------------------------------------------------------------------ pure functions */

/*
 * n / d rounded to nearest, ties away from zero, for d > 0 and |n| < INT32_MAX - d/2. C
 * division truncates toward zero (defined since C99), so each sign is handled on its magnitude
 * and no negative value is ever shifted. 32-bit on purpose (not fx_div64): it runs per sample,
 * and a 32-bit division is one instruction on the M3/M4 and rv32imac (__aeabi_idiv on the M0+)
 * where a 64-bit one is a libgcc call on every core.
 */
static int32_t div_round(int32_t n, int32_t d)
{
    if (n >= 0) {
        return (n + d / 2) / d;
    }
    return -((-n + d / 2) / d);
}

static bool range_valid(enum adis16255_range r)
{
    return r == ADIS16255_RANGE_80 || r == ADIS16255_RANGE_160 || r == ADIS16255_RANGE_320;
}

int adis16255_gyro_dps_from_word(uint16_t word, enum adis16255_range range, int32_t *dps_q16)
{
    int32_t n;
    if (dps_q16 == NULL) {
        return INC_ERR_NULL;
    }
    if (!range_valid(range)) {
        *dps_q16 = 0;
        return INC_ERR_INVAL;
    }
    /* LSB = range * 5/273 °/s; in Q16.16: n * range * 327680 / 273, and
     * 327680 = 273 * 1200 + 80, so the integer part needs no division and the remainder term
     * stays below 2^22 (|n * range| <= 32768). */
    n = adis_sign_extend(word, ADIS16255_GYRO_BITS) * (int32_t)range;
    *dps_q16 = n * 1200 + div_round(n * 80, 273);
    return INC_OK;
}

int32_t adis16255_temp_c_from_word(uint16_t word)
{
    /* 0.1453 °C/LSB (A3), 0 = 25 °C (A6): 0.1453 * 65536 = 9522.3808 = 9522 + 238/625. */
    const int32_t n = adis_sign_extend(word, ADIS16255_TEMP_BITS);
    return 25 * 65536 + n * 9522 + div_round(n * 238, 625);
}

int32_t adis16255_supply_v_from_word(uint16_t word)
{
    /* 1.8315 mV/LSB (A3): 1.8315e-3 * 65536 = 120.029184 = 120 + 2280/78125. */
    const int32_t n = (int32_t)adis_field(word, ADIS16255_SUPPLY_BITS);
    return n * 120 + div_round(n * 2280, 78125);
}

int32_t adis16255_angle_deg_from_word(uint16_t word)
{
    /* [U] 0.03663 °/LSB = 10/273 (Linux adis16260, A6): 655360/273 = 2400 + 160/273. */
    const int32_t n = (int32_t)adis_field(word, ADIS16255_ANGL_BITS);
    return n * 2400 + div_round(n * 160, 273);
}

int adis16255_gyro_off_word_from_dps(int32_t dps_q16, uint16_t *word, bool *saturated)
{
    int32_t n;
    if (word == NULL || saturated == NULL) {
        return INC_ERR_NULL;
    }
    /* [U] LSB 5/273 °/s: count = dps * 273 / 5 = dps_q16 * 273 / 327680. */
    n = adis_offset_counts((int64_t)dps_q16 * 273, 327680u, ADIS16255_GYRO_OFF_BITS, saturated);
    *word = (uint16_t)((uint32_t)n & 0x0FFFu);
    return INC_OK;
}

int32_t adis16255_gyro_off_dps_from_word(uint16_t word)
{
    const int32_t n = adis_sign_extend(word, ADIS16255_GYRO_OFF_BITS);
    return n * 1200 + div_round(n * 80, 273);
}

uint32_t adis16255_sample_period_us(uint8_t smpl_prd)
{
    /* TS = TB * (NS + 1) (A4). */
    const uint32_t tb = (smpl_prd & ADIS16255_SMPL_PRD_TB) ? ADIS16255_TB_SLOW_US
                                                           : ADIS16255_TB_FAST_US;
    return tb * ((uint32_t)(smpl_prd & ADIS16255_SMPL_PRD_NS_MASK) + 1u);
}

bool adis16255_sclk_fast_allowed(uint8_t smpl_prd)
{
    /* >= 64 SPS: TS <= 15.624 ms (A4's example SMPL_PRD = 0x07 -> 64 SPS). */
    return (smpl_prd & ADIS16255_SMPL_PRD_TB) == 0u &&
           (smpl_prd & ADIS16255_SMPL_PRD_NS_MASK) <= ADIS16255_FAST_NS_MAX;
}

int adis16255_sens_avg_encode(enum adis16255_range range, uint8_t filter_m, uint16_t *word)
{
    if (word == NULL) {
        return INC_ERR_NULL;
    }
    if (!range_valid(range) || filter_m > ADIS16255_FILTER_M_MAX ||
        (range == ADIS16255_RANGE_160 && filter_m < ADIS16255_FILTER_M_MIN_160) ||
        (range == ADIS16255_RANGE_80 && filter_m < ADIS16255_FILTER_M_MIN_80)) {
        return INC_ERR_INVAL;
    }
    *word = (uint16_t)(((unsigned)range << ADIS16255_SENS_AVG_RANGE_SHIFT) | filter_m);
    return INC_OK;
}

int adis16255_status_decode(uint16_t raw, struct adis16255_status *out)
{
    if (out == NULL) {
        return INC_ERR_NULL;
    }
    out->raw = raw;
    out->supply_low = (raw & ADIS16255_STATUS_SUPPLY_LOW) != 0u;
    out->supply_high = (raw & ADIS16255_STATUS_SUPPLY_HIGH) != 0u;
    out->flash_update_fail = (raw & ADIS16255_STATUS_FLASH_FAIL) != 0u;
    out->spi_fail = (raw & ADIS16255_STATUS_SPI_FAIL) != 0u;
    out->overrange = (raw & ADIS16255_STATUS_OVERRANGE) != 0u;
    out->self_test_fail = (raw & ADIS16255_STATUS_SELF_TEST) != 0u;
    out->flash_checksum = (raw & ADIS16255_STATUS_FLASH_CRC) != 0u;
    out->alarm1 = (raw & ADIS16255_STATUS_ALARM1) != 0u;
    out->alarm2 = (raw & ADIS16255_STATUS_ALARM2) != 0u;
    return (raw & (uint16_t)~ADIS16255_STATUS_DEFINED) != 0u ? INC_ERR_BUS : INC_OK;
}

const char *adis16255_status_bit_name(unsigned bit)
{
    static const char *const names[10] = {
        "supply<4.75V",   "supply>5.25V",   "flash-update-fail", "spi-comm-fail", "overrange",
        "self-test-fail", "flash-checksum", "reserved",          "alarm1",        "alarm2",
    };
    return bit < 10u ? names[bit] : "reserved";
}

/* ------------------------------------------------------------------ bus helpers */

static uint64_t now(const struct adis16255 *dev)
{
    return hal_now_ns(dev->cfg.hal);
}

static void timing_for(bool fast, struct spi_timing *t)
{
    t->sclk_period_ns = spi_period_for_hz(fast ? ADIS16255_SCLK_FAST_HZ : ADIS16255_SCLK_SLOW_HZ);
    t->cs_setup_ns = ADIS16255_CS_SETUP_NS;
    t->cs_hold_ns = ADIS16255_CS_HOLD_NS;
    t->stall_ns = fast ? ADIS16255_STALL_NS : ADIS16255_STALL_SLOW_NS;
    t->gap_ns = 0;
}

static int use_timing(struct adis16255 *dev, bool fast)
{
    struct spi_timing t;
    timing_for(fast, &t);
    dev->fast = fast;
    return spi_dev_set_timing(&dev->spi, &t);
}

static int check_ready(const struct adis16255 *dev)
{
    if (dev == NULL) {
        return INC_ERR_NULL;
    }
    return dev->ready ? INC_OK : INC_ERR_STATE;
}

static bool uniform(const uint16_t *w, size_t n, uint16_t v)
{
    size_t i;
    for (i = 0; i < n; i++) {
        if (w[i] != v) {
            return false;
        }
    }
    return true;
}

/*
 * Every register read of this driver: one pipelined sequence whose trailing frame reads
 * SENS_AVG (adis_read_regs_tail), so the first word of the next read answers it when nothing
 * else went to the part in between (*chained: dev->spi.transfers is where the last read left
 * it). first and chained may be NULL.
 */
static int rd_regs(struct adis16255 *dev, const uint8_t *addrs, uint16_t *v, size_t n,
                   uint16_t *first, bool *chained)
{
    const bool ch = dev->tail_valid && dev->spi.transfers == dev->tail_mark;
    const int err = adis_read_regs_tail(&dev->spi, addrs, v, n, ADIS16255_REG_SENS_AVG, first);
    if (chained != NULL) {
        *chained = ch;
    }
    dev->tail_valid = err == INC_OK;
    dev->tail_mark = dev->spi.transfers;
    return err;
}

static int rd_reg(struct adis16255 *dev, uint8_t addr, uint16_t *v)
{
    return rd_regs(dev, &addr, v, 1u, NULL, NULL);
}

/* Read STATUS into dev->status. INC_ERR_BUS when the word cannot be a STATUS word. */
static int status_read(struct adis16255 *dev)
{
    uint16_t v;
    int err = rd_reg(dev, ADIS16255_REG_STATUS, &v);
    if (err != INC_OK) {
        return err;
    }
    err = adis16255_status_decode(v, &dev->status);
    if (err == INC_ERR_BUS) {
        dev->bus_errors++;
    }
    return err;
}

/*
 * Does the part answer sanely? SENS_AVG reads back as written: it can never be 0x0000 or
 * 0xFFFF (one range bit, reserved bits zero), so neither a stuck MISO nor a busy part's garbage
 * passes. *last gets the word read.
 */
static int alive(struct adis16255 *dev, uint16_t *last)
{
    int err = rd_reg(dev, ADIS16255_REG_SENS_AVG, last);
    if (err != INC_OK) {
        return err;
    }
    return *last == dev->sens_avg ? INC_OK : INC_ERR_BUSY;
}

/*
 * Wait until the part answers: first the busy time the driver knows of, then poll. The part
 * gives no busy flag (docs/sensor-facts.md §2: garbage or no answer while busy), so polling is the only
 * way to learn that a command took longer than its [U] duration, or that the part is busy for
 * a reason the driver did not cause. Polling a busy part is a bus access the part ignores.
 */
static int wait_idle(struct adis16255 *dev)
{
    uint64_t deadline;
    uint16_t last = 0;
    hal_delay_until(dev->cfg.hal, dev->busy_until_ns);
    deadline = now(dev) + (uint64_t)ADIS16255_BUSY_TIMEOUT_MS * NS_PER_MS;
    for (;;) {
        const int err = alive(dev, &last);
        if (err != INC_ERR_BUSY) {
            return err;
        }
        if (now(dev) >= deadline) {
            /* Never answered: a stuck line or missing part looks uniform, a busy part not. */
            return (last == 0x0000u || last == 0xFFFFu) ? INC_ERR_BUS : INC_ERR_BUSY;
        }
        hal_delay_ms(dev->cfg.hal, ADIS16255_POLL_MS);
    }
}

/*
 * Judge output words (ND, EA, plausibility). EA first: it may hide a bus fault (all ones reads
 * as ND|EA), which the STATUS word then reveals through its reserved bits. Stale words that are
 * all zero may be a stuck-low MISO: a SENS_AVG read-back decides.
 */
static int check_outputs(struct adis16255 *dev, const uint16_t *w, size_t n,
                         struct adis16255_status *status)
{
    bool ea = false, stale = false;
    size_t i;
    int err;
    for (i = 0; i < n; i++) {
        ea = ea || (w[i] & ADIS_FLAG_EA) != 0u;
        stale = stale || (w[i] & ADIS_FLAG_ND) == 0u;
    }
    if (ea) {
        err = status_read(dev);
        if (status != NULL) {
            *status = dev->status;
        }
        return err != INC_OK ? err : INC_ERR_DEVICE;
    }
    if (stale) {
        if (uniform(w, n, 0x0000u)) {
            uint16_t last;
            err = alive(dev, &last);
            if (err != INC_OK) {
                if (err == INC_ERR_BUSY) {
                    dev->bus_errors++;
                    return INC_ERR_BUS;
                }
                return err;
            }
        }
        return INC_ERR_STALE;
    }
    return INC_OK;
}

/* Clear ND of the sample registers so the next valid sample is a fresh one. */
static int discard_outputs(struct adis16255 *dev)
{
    static const uint8_t addrs[2] = {ADIS16255_REG_GYRO_OUT, ADIS16255_REG_TEMP_OUT};
    uint16_t w[2];
    int err = rd_regs(dev, addrs, w, 2u, NULL, NULL);
    sensor_dr_sync(dev->cfg.hal, &dev->dr); /* drop the edges seen so far */
    return err;
}

/* ------------------------------------------------------------------ configuration */

/* Write SMPL_PRD, SENS_AVG, MSC_CTRL and read them back. */
static int write_config(struct adis16255 *dev)
{
    static const uint8_t addrs[3] = {ADIS16255_REG_SMPL_PRD, ADIS16255_REG_SENS_AVG,
                                     ADIS16255_REG_MSC_CTRL};
    uint16_t v[3];
    int err = adis_write_byte(&dev->spi, ADIS16255_REG_SMPL_PRD, (uint8_t)dev->smpl_prd);
    if (err == INC_OK) {
        err = adis_write_reg(&dev->spi, ADIS16255_REG_SENS_AVG, dev->sens_avg);
    }
    if (err == INC_OK) {
        err = adis_write_reg(&dev->spi, ADIS16255_REG_MSC_CTRL, dev->msc_ctrl);
    }
    if (err == INC_OK) {
        err = rd_regs(dev, addrs, v, 3u, NULL, NULL);
    }
    if (err != INC_OK) {
        return err;
    }
    if (v[0] != dev->smpl_prd || v[1] != dev->sens_avg || v[2] != dev->msc_ctrl) {
        dev->id_check = ADIS16255_ID_READBACK;
        return INC_ERR_ID;
    }
    return INC_OK;
}

/*
 * Identity and plausibility without a PROD_ID (none exists on the ADIS16250/55, docs/sensor-facts.md
 * §2.3): stuck lines read uniform words; a real part has a 4.75..5.25 V supply reading, zeros in
 * the reserved bits of GYRO_SCALE (12-bit), SMPL_PRD (8-bit), MSC_CTRL and STATUS, and a
 * SENS_AVG with exactly one range bit.
 */
static int identify(struct adis16255 *dev)
{
    static const uint8_t addrs[5] = {ADIS16255_REG_SUPPLY_OUT, ADIS16255_REG_GYRO_SCALE,
                                     ADIS16255_REG_SENS_AVG, ADIS16255_REG_SMPL_PRD,
                                     ADIS16255_REG_MSC_CTRL};
    uint16_t v[5];
    int32_t supply;
    unsigned range;
    struct adis16255_status status;
    int err = rd_regs(dev, addrs, v, 5u, NULL, NULL);
    if (err != INC_OK) {
        return err;
    }
    if (uniform(v, 5u, 0xFFFFu)) {
        dev->id_check = ADIS16255_ID_STUCK_HIGH;
        dev->bus_errors++;
        return INC_ERR_BUS;
    }
    if (uniform(v, 5u, 0x0000u)) {
        dev->id_check = ADIS16255_ID_STUCK_LOW;
        dev->bus_errors++;
        return INC_ERR_BUS;
    }
    supply = adis16255_supply_v_from_word(v[0]);
    if (supply < (int32_t)(ADIS16255_SUPPLY_PLAUSIBLE_MIN_MV * 65536u / 1000u) ||
        supply > (int32_t)(ADIS16255_SUPPLY_PLAUSIBLE_MAX_MV * 65536u / 1000u)) {
        dev->id_check = ADIS16255_ID_SUPPLY;
        return INC_ERR_ID;
    }
    /* MSC_CTRL bit 11 is the memory test on the ADIS16260 relatives: tolerated. */
    if ((v[1] & 0xF000u) != 0u || (v[3] & 0xFF00u) != 0u || (v[4] & 0xF0F8u) != 0u) {
        dev->id_check = ADIS16255_ID_RESERVED_BITS;
        return INC_ERR_ID;
    }
    range = (v[2] & ADIS16255_SENS_AVG_RANGE_MASK) >> ADIS16255_SENS_AVG_RANGE_SHIFT;
    if ((v[2] & (uint16_t) ~(ADIS16255_SENS_AVG_RANGE_MASK | ADIS16255_SENS_AVG_FILTER_MASK)) !=
            0u ||
        (range != 1u && range != 2u && range != 4u)) {
        dev->id_check = ADIS16255_ID_SENS_AVG;
        return INC_ERR_ID;
    }
    /* STATUS last, read on its own: reading it clears latched bits (power-up glitches). */
    err = rd_reg(dev, ADIS16255_REG_STATUS, &v[0]);
    if (err != INC_OK) {
        return err;
    }
    if (adis16255_status_decode(v[0], &status) != INC_OK) {
        dev->id_check = ADIS16255_ID_RESERVED_BITS;
        return INC_ERR_ID;
    }
    return INC_OK;
}

static int check_cfg(const struct adis16255_cfg *cfg, uint16_t *sens_avg)
{
    int err;
    if (cfg->bus == NULL || cfg->hal == NULL) {
        return INC_ERR_NULL;
    }
    err = hal_check(cfg->hal);
    if (err != INC_OK) {
        return err;
    }
    if (cfg->cs == HAL_PIN_NONE || cfg->dr_line > 1u ||
        (cfg->dr_pin != HAL_PIN_NONE && !cfg->dr_enable)) {
        return INC_ERR_INVAL;
    }
    return adis16255_sens_avg_encode(cfg->range, cfg->filter_m, sens_avg);
}

static int send_reset(struct adis16255 *dev)
{
    int err = adis_write_byte(&dev->spi, ADIS16255_REG_COMMAND, ADIS16255_CMD_RESET);
    dev->busy_until_ns = now(dev) + (uint64_t)ADIS16255_RESET_MS * NS_PER_MS;
    hal_delay_until(dev->cfg.hal, dev->busy_until_ns);
    return err;
}

int adis16255_init(struct adis16255 *dev, const struct adis16255_cfg *cfg)
{
    struct spi_dev_cfg dc;
    uint16_t sens_avg = 0;
    int err;
    if (dev == NULL || cfg == NULL) {
        return INC_ERR_NULL;
    }
    dev->ready = false;
    dev->dr_attached = false;
    dev->bus_errors = 0u;
    dev->sensor_missed = 0u;
    dev->id_check = ADIS16255_ID_OK;
    dev->busy_until_ns = 0;
    sensor_dr_reset(&dev->dr);
    dev->status.raw = 0;
    err = check_cfg(cfg, &sens_avg);
    if (err != INC_OK) {
        return err;
    }
    dev->cfg = *cfg;
    dev->smpl_prd = cfg->smpl_prd;
    dev->sens_avg = sens_avg;
    dev->tail_valid = false;
    dev->tail_mark = 0u;
    dev->tail_fails = 0u;
    dev->msc_ctrl = (uint16_t)((cfg->dr_enable ? ADIS16255_MSC_DR_EN : 0u) |
                               (cfg->dr_active_high ? ADIS16255_MSC_DR_POL_HIGH : 0u) |
                               (cfg->dr_line != 0u ? ADIS16255_MSC_DR_LINE : 0u));
    /* The part's rate (non-volatile SMPL_PRD) is unknown until read: start at the SCLK and
     * stall that every rate allows. */
    dc.cs = cfg->cs;
    dc.mode = SPI_MODE_3;
    dc.bits = 16;
    timing_for(false, &dc.timing);
    dev->fast = false;
    err = spi_dev_init(&dev->spi, cfg->bus, &dc);
    if (err != INC_OK) {
        return err;
    }
    if (cfg->reset_at_init) {
        err = send_reset(dev);
        if (err != INC_OK) {
            return err;
        }
    }
    err = identify(dev);
    if (err == INC_OK) {
        err = write_config(dev);
    }
    if (err == INC_OK) {
        err = use_timing(dev, adis16255_sclk_fast_allowed((uint8_t)dev->smpl_prd));
    }
    if (err != INC_OK) {
        return err;
    }
    dev->ready = true;
    if (cfg->self_test_at_init) {
        err = adis16255_self_test(dev);
    } else {
        err = discard_outputs(dev);
    }
    /* Conditions that persist after the latched bits were cleared: the part is not usable. */
    if (err == INC_OK) {
        err = status_read(dev);
        if (err == INC_OK && dev->status.raw != 0u) {
            err = INC_ERR_DEVICE;
        }
    }
    if (err == INC_OK && cfg->dr_pin != HAL_PIN_NONE) {
        err = hal_irq_attach(cfg->hal, cfg->dr_pin,
                             cfg->dr_active_high ? HAL_EDGE_RISING : HAL_EDGE_FALLING,
                             sensor_dr_isr, &dev->dr);
        dev->dr_attached = err == INC_OK;
        sensor_dr_sync(dev->cfg.hal, &dev->dr);
    }
    if (err != INC_OK) {
        dev->ready = false;
    }
    return err;
}

/* ------------------------------------------------------------------ reading */

static void sample_clear(struct adis16255_sample *s)
{
    s->valid = false;
    s->flags = 0;
    s->rate_dps_q16 = 0;
    s->temp_c_q16 = 0;
    s->gyro_word = 0;
    s->temp_word = 0;
    s->t_ns = 0;
    s->status.raw = 0;
    (void)adis16255_status_decode(0, &s->status);
}

int adis16255_read_sample(struct adis16255 *dev, struct adis16255_sample *s)
{
    static const uint8_t addrs[2] = {ADIS16255_REG_GYRO_OUT, ADIS16255_REG_TEMP_OUT};
    uint16_t w[2];
    uint16_t first = 0u;
    bool chained;
    int32_t rate;
    int err;
    if (s == NULL) {
        return INC_ERR_NULL;
    }
    sample_clear(s);
    err = check_ready(dev);
    if (err != INC_OK) {
        return err;
    }
    /* One pipelined sequence: 3 frames for 2 registers; the first word answers the previous
     * read's trailing SENS_AVG command (rd_regs). */
    err = rd_regs(dev, addrs, w, 2u, &first, &chained);
    if (err != INC_OK) {
        return err;
    }
    if (chained && first != dev->sens_avg &&
        !(first == w[0] && first == w[1] && (first == 0x0000u || first == 0xFFFFu))) {
        /* Not a stuck line (that is the bus-fault classification below): garbage or a part
         * that lost its configuration. */
        dev->tail_fails++;
        s->gyro_word = w[0];
        s->temp_word = w[1];
        return INC_ERR_BUSY;
    }
    s->t_ns = now(dev);
    s->gyro_word = w[0];
    s->temp_word = w[1];
    s->flags = (uint8_t)(((w[0] & ADIS_FLAG_ND) ? ADIS16255_SAMPLE_GYRO_NEW : 0u) |
                         ((w[1] & ADIS_FLAG_ND) ? ADIS16255_SAMPLE_TEMP_NEW : 0u));
    if ((w[0] | w[1]) & ADIS_FLAG_EA) {
        s->flags |= ADIS16255_SAMPLE_ALARM;
    }
    err = check_outputs(dev, w, 2u, &s->status);
    if (err != INC_OK) {
        return err;
    }
    err = adis16255_gyro_dps_from_word(w[0], dev->cfg.range, &rate);
    if (err != INC_OK) {
        return err;
    }
    s->rate_dps_q16 = rate;
    s->temp_c_q16 = adis16255_temp_c_from_word(w[1]);
    s->valid = true;
    return INC_OK;
}

uint32_t adis16255_dr_timeout_us(const struct adis16255 *dev)
{
    if (dev == NULL) {
        return 0;
    }
    return 2u * adis16255_sample_period_us((uint8_t)dev->smpl_prd) + ADIS16255_DR_MARGIN_US;
}

/* Wait for a data-ready edge until deadline_ns; *missed = edges beyond one. */
static int wait_edge(struct adis16255 *dev, uint64_t deadline_ns, uint32_t *missed)
{
    uint32_t pending = 0;
    int err = sensor_dr_wait(dev->cfg.hal, &dev->dr, deadline_ns, &pending);
    *missed = err == INC_OK ? pending - 1u : 0u;
    return err;
}

int adis16255_wait_ready(struct adis16255 *dev, uint32_t timeout_ns, uint32_t *missed)
{
    uint32_t m = 0;
    int err = check_ready(dev);
    if (err == INC_OK && !dev->dr_attached) {
        err = INC_ERR_STATE;
    }
    if (err == INC_OK) {
        const uint64_t t = timeout_ns != 0u ? timeout_ns
                                            : (uint64_t)adis16255_dr_timeout_us(dev) * NS_PER_US;
        err = wait_edge(dev, now(dev) + t, &m);
    }
    if (missed != NULL) {
        *missed = m;
    }
    return err;
}

int adis16255_wait_sample(struct adis16255 *dev, uint32_t timeout_us, struct adis16255_sample *s)
{
    uint32_t missed = 0;
    int err;
    if (s == NULL) {
        return INC_ERR_NULL;
    }
    sample_clear(s);
    err = check_ready(dev);
    if (err != INC_OK) {
        return err;
    }
    if (!dev->dr_attached) {
        return INC_ERR_STATE;
    }
    if (timeout_us == 0u) {
        timeout_us = adis16255_dr_timeout_us(dev);
    }
    err = wait_edge(dev, now(dev) + (uint64_t)timeout_us * NS_PER_US, &missed);
    if (err != INC_OK) {
        return err; /* missed data-ready: no sample is made up */
    }
    err = adis16255_read_sample(dev, s);
    if (missed > 0u) {
        s->flags |= ADIS16255_SAMPLE_OVERRUN;
    }
    return err;
}

/* One output register with the sample checks, converted by conv; *out = 0 on error. */
static int read_output(struct adis16255 *dev, uint8_t addr, int32_t (*conv)(uint16_t), int32_t *out)
{
    uint16_t w;
    int err;
    if (out == NULL) {
        return INC_ERR_NULL;
    }
    *out = 0;
    err = check_ready(dev);
    if (err == INC_OK) {
        err = rd_reg(dev, addr, &w);
    }
    if (err == INC_OK) {
        err = check_outputs(dev, &w, 1u, NULL);
    }
    if (err == INC_OK) {
        *out = conv(w);
    }
    return err;
}

int adis16255_read_supply(struct adis16255 *dev, int32_t *v_q16)
{
    return read_output(dev, ADIS16255_REG_SUPPLY_OUT, adis16255_supply_v_from_word, v_q16);
}

int adis16255_read_angle(struct adis16255 *dev, int32_t *deg_q16)
{
    return read_output(dev, ADIS16255_REG_ANGL_OUT, adis16255_angle_deg_from_word, deg_q16);
}

int adis16255_read_diag(struct adis16255 *dev, struct adis16255_status *out)
{
    int err;
    if (out == NULL) {
        return INC_ERR_NULL;
    }
    err = check_ready(dev);
    if (err != INC_OK) {
        return err;
    }
    err = status_read(dev);
    *out = dev->status;
    return err;
}

/* ------------------------------------------------------------------ configuration changes */

int adis16255_set_sample_period(struct adis16255 *dev, uint8_t smpl_prd)
{
    uint16_t v;
    int err = check_ready(dev);
    if (err != INC_OK) {
        return err;
    }
    err = wait_idle(dev);
    if (err == INC_OK) {
        /* Written at the current SCLK (the part switches at this frame's CS rise); every later
         * frame uses the new rate's SCLK and stall. */
        err = adis_write_byte(&dev->spi, ADIS16255_REG_SMPL_PRD, smpl_prd);
    }
    if (err == INC_OK) {
        dev->smpl_prd = smpl_prd;
        dev->cfg.smpl_prd = smpl_prd;
        err = use_timing(dev, adis16255_sclk_fast_allowed(smpl_prd));
    }
    if (err == INC_OK) {
        err = rd_reg(dev, ADIS16255_REG_SMPL_PRD, &v);
    }
    if (err == INC_OK && v != smpl_prd) {
        err = INC_ERR_ID;
    }
    return err;
}

/* Once the part answers, write a 16-bit register and read it back: INC_ERR_ID on a mismatch. */
static int write_verified(struct adis16255 *dev, uint8_t addr, uint16_t word)
{
    uint16_t v;
    int err = wait_idle(dev);
    if (err == INC_OK) {
        err = adis_write_reg(&dev->spi, addr, word);
    }
    if (err == INC_OK) {
        err = rd_reg(dev, addr, &v);
    }
    if (err == INC_OK && v != word) {
        err = INC_ERR_ID;
    }
    return err;
}

int adis16255_set_sens_avg(struct adis16255 *dev, enum adis16255_range range, uint8_t filter_m)
{
    uint16_t word = 0;
    int err = check_ready(dev);
    if (err != INC_OK) {
        return err;
    }
    err = adis16255_sens_avg_encode(range, filter_m, &word);
    if (err == INC_OK) {
        err = write_verified(dev, ADIS16255_REG_SENS_AVG, word);
    }
    if (err == INC_OK) {
        dev->sens_avg = word;
        dev->cfg.range = range;
        dev->cfg.filter_m = filter_m;
        /* Outputs latched under the old range would be scaled wrongly: drop them. */
        err = discard_outputs(dev);
    }
    return err;
}

int adis16255_set_gyro_offset(struct adis16255 *dev, int32_t dps_q16, bool *saturated)
{
    uint16_t word = 0;
    bool sat = false;
    int err = check_ready(dev);
    if (err != INC_OK) {
        return err;
    }
    (void)adis16255_gyro_off_word_from_dps(dps_q16, &word, &sat);
    if (saturated != NULL) {
        *saturated = sat;
    }
    return write_verified(dev, ADIS16255_REG_GYRO_OFF, word);
}

int adis16255_get_gyro_offset(struct adis16255 *dev, int32_t *dps_q16)
{
    uint16_t v;
    int err;
    if (dps_q16 == NULL) {
        return INC_ERR_NULL;
    }
    *dps_q16 = 0;
    err = check_ready(dev);
    if (err != INC_OK) {
        return err;
    }
    err = rd_reg(dev, ADIS16255_REG_GYRO_OFF, &v);
    if (err != INC_OK) {
        return err;
    }
    if ((v & 0xF000u) != 0u) {
        return INC_ERR_BUS; /* a 12-bit register with upper bits set: not the part */
    }
    *dps_q16 = adis16255_gyro_off_dps_from_word(v);
    return INC_OK;
}

/* ------------------------------------------------------------------ commands */

/* Send one COMMAND byte once the part answers, wait its time, wait until it answers again. */
static int command(struct adis16255 *dev, uint8_t cmd, uint64_t wait_ns)
{
    int err = wait_idle(dev);
    if (err != INC_OK) {
        return err;
    }
    err = adis_write_byte(&dev->spi, ADIS16255_REG_COMMAND, cmd);
    if (err != INC_OK) {
        return err;
    }
    dev->busy_until_ns = now(dev) + wait_ns;
    return wait_idle(dev);
}

int adis16255_autonull(struct adis16255 *dev)
{
    uint64_t window_ns;
    int err = check_ready(dev);
    if (err != INC_OK) {
        return err;
    }
    /* The part averages over its filter window (2^M samples); wait two windows on top. */
    window_ns = ((uint64_t)adis16255_sample_period_us((uint8_t)dev->smpl_prd) * NS_PER_US)
                << dev->cfg.filter_m;
    err = command(dev, ADIS16255_CMD_AUTONULL,
                  (uint64_t)ADIS16255_AUTONULL_MS * NS_PER_MS + 2u * window_ns);
    if (err == INC_OK) {
        err = discard_outputs(dev);
    }
    return err;
}

int adis16255_factory_restore(struct adis16255 *dev)
{
    static const uint8_t addrs[2] = {ADIS16255_REG_GYRO_OFF, ADIS16255_REG_GYRO_SCALE};
    uint16_t v[2];
    int err = check_ready(dev);
    if (err != INC_OK) {
        return err;
    }
    err = command(dev, ADIS16255_CMD_FACTORY_RESTORE,
                  (uint64_t)ADIS16255_FACTORY_RESTORE_MS * NS_PER_MS);
    if (err == INC_OK) {
        err = rd_regs(dev, addrs, v, 2u, NULL, NULL);
    }
    if (err == INC_OK && (v[0] != 0u || v[1] != ADIS16255_GYRO_SCALE_UNITY)) {
        err = INC_ERR_DEVICE;
    }
    return err;
}

int adis16255_flash_update(struct adis16255 *dev)
{
    uint16_t before, after;
    int err = check_ready(dev);
    if (err != INC_OK) {
        return err;
    }
    err = wait_idle(dev);
    if (err == INC_OK) {
        err = rd_reg(dev, ADIS16255_REG_ENDURANCE, &before);
    }
    if (err == INC_OK) {
        err = command(dev, ADIS16255_CMD_FLASH_UPDATE,
                      (uint64_t)ADIS16255_FLASH_UPDATE_MS * NS_PER_MS);
    }
    if (err == INC_OK) {
        err = rd_reg(dev, ADIS16255_REG_ENDURANCE, &after);
    }
    if (err == INC_OK) {
        err = status_read(dev);
    }
    /* The write counter proves the update ran exactly once. */
    if (err == INC_OK && (after != (uint16_t)(before + 1u) || dev->status.flash_update_fail)) {
        err = INC_ERR_DEVICE;
    }
    return err;
}

int adis16255_reset(struct adis16255 *dev)
{
    uint64_t deadline;
    int err = check_ready(dev);
    if (err != INC_OK) {
        return err;
    }
    err = wait_idle(dev);
    if (err != INC_OK) {
        return err;
    }
    /* After the reset the part runs at its flash rate, maybe below 64 SPS: slow SCLK until the
     * configuration is back. */
    err = use_timing(dev, false);
    if (err == INC_OK) {
        err = send_reset(dev);
    }
    if (err != INC_OK) {
        return err;
    }
    /* The part reloads its flash copy: write the driver's configuration again, polling while
     * the part is still busy (the read-back fails). */
    deadline = now(dev) + (uint64_t)ADIS16255_BUSY_TIMEOUT_MS * NS_PER_MS;
    for (;;) {
        err = write_config(dev);
        if (err != INC_ERR_ID || now(dev) >= deadline) {
            break;
        }
        hal_delay_ms(dev->cfg.hal, ADIS16255_POLL_MS);
    }
    if (err == INC_OK) {
        dev->id_check = ADIS16255_ID_OK;
        err = use_timing(dev, adis16255_sclk_fast_allowed((uint8_t)dev->smpl_prd));
    }
    if (err == INC_OK) {
        err = discard_outputs(dev);
    }
    return err;
}

int adis16255_self_test(struct adis16255 *dev)
{
    uint64_t deadline;
    uint16_t v;
    int err = check_ready(dev);
    if (err != INC_OK) {
        return err;
    }
    err = wait_idle(dev);
    if (err != INC_OK) {
        return err;
    }
    /* Only the upper byte (address 0x35) holds the self-test bits: one frame, the data-ready
     * bits in the lower byte are untouched. */
    err = adis_write_byte(&dev->spi, ADIS16255_REG_MSC_CTRL + 1u,
                          (uint8_t)((dev->msc_ctrl | ADIS16255_MSC_ST_INT) >> 8));
    if (err != INC_OK) {
        return err;
    }
    deadline = now(dev) + (uint64_t)ADIS16255_SELF_TEST_TIMEOUT_MS * NS_PER_MS;
    hal_delay_ms(dev->cfg.hal, ADIS16255_SELF_TEST_MS);
    for (;;) {
        err = rd_reg(dev, ADIS16255_REG_MSC_CTRL, &v);
        if (err != INC_OK) {
            return err;
        }
        if (v == dev->msc_ctrl) {
            break; /* bit 10 cleared itself: done */
        }
        if (now(dev) >= deadline) {
            return INC_ERR_TIMEOUT;
        }
        hal_delay_ms(dev->cfg.hal, ADIS16255_POLL_MS);
    }
    err = status_read(dev);
    if (err == INC_OK && dev->status.self_test_fail) {
        err = INC_ERR_DEVICE;
    }
    if (err == INC_OK) {
        err = discard_outputs(dev);
    } else {
        (void)discard_outputs(dev);
    }
    return err;
}
