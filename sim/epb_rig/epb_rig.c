/* epb_rig.c - see sim/epb_rig.h and docs/epb-demo.md. */
#include "inclino/sim/epb_rig_state.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

#include "inclino/s32k_wdog.h"
#include "inclino/sim/s32k_bus.h"

#define PI 3.14159265358979323846
#define DEG (PI / 180.0)

/* Flash of the calibration store: 2 pages of 1 KiB, 8-byte program units, one page per slot. */
#define RIG_FLASH_PAGE 1024u
#define RIG_FLASH_PROG 8u

static const struct epb_rig_part_info parts[EPB_RIG_PARTS] = {
    /* name          adis  variant         acc LSB   gyro LSB temp LSB rate    range */
    {"adis16405", true, SIM_ADIS16405, 0.003333, 0.05, 0.14, 819.2, 18.0},
    {"adis16400", true, SIM_ADIS16400, 0.003333, 0.05, 0.14, 819.2, 18.0},
    {"adis16364", true, SIM_ADIS16364, 0.001, 0.05, 0.136, 819.2, 5.0},
    {"adis16362", true, SIM_ADIS16362, 0.000333, 0.05, 0.136, 819.2, 1.7},
    {"sca3000-d01", false, SIM_SCA3000_D01, 0.00075, 0.0, 1.0 / 1.8, 250.0, 3.0},
    {"sca3000-e02", false, SIM_SCA3000_E02, 0.001, 0.0, 0.0, 125.0, 4.0},
};

const struct epb_rig_part_info *epb_rig_part_get(enum epb_rig_part p)
{
    return (unsigned)p < (unsigned)EPB_RIG_PARTS ? &parts[p] : NULL;
}

int epb_rig_part_from_name(const char *name, enum epb_rig_part *out)
{
    unsigned i;
    if (name == NULL || out == NULL) {
        return INC_ERR_NULL;
    }
    for (i = 0; i < (unsigned)EPB_RIG_PARTS; i++) {
        if (strcmp(name, parts[i].name) == 0) {
            *out = (enum epb_rig_part)i;
            return INC_OK;
        }
    }
    return INC_ERR_INVAL;
}

void epb_rig_vehicle_default(struct epb_rig_vehicle *v)
{
    /* Engine idle of a four-cylinder engine: the 2nd order (two firings per crank turn) is the
     * strongest, felt mostly vertically; 1st (imbalance), 4th and the 0.5 order (cycle-to-cycle
     * combustion irregularity) are smaller. Amplitudes at an ECU on the body, g. */
    static const struct epb_rig_order orders[EPB_RIG_ORDERS] = {
        {0.5, {0.0005, 0.0005, 0.001}, {0.02, 0.02, 0.0}},
        {1.0, {0.002, 0.003, 0.003}, {0.05, 0.05, 0.02}},
        {2.0, {0.005, 0.002, 0.015}, {0.3, 0.1, 0.05}},
        {4.0, {0.0015, 0.001, 0.004}, {0.05, 0.05, 0.02}},
    };
    memset(v, 0, sizeof(*v));
    v->slope_deg = atan(0.10) / DEG; /* 10 % grade */
    v->roll_deg = 0.0;
    v->temp_c = 25.0;
    v->idle_rpm = 750.0;
    memcpy(v->orders, orders, sizeof(orders));
    v->bump_rate_hz = 0.3;
    v->bump_amp_g = 0.008;
    v->bump_pitch_deg = 0.02;
    v->bump_freq_hz = 1.4;
    v->bump_zeta = 0.3;
    v->drive_off_s = -1.0;
    v->drive_accel_g = 0.12;
    v->drive_squat_deg = 0.4;
    v->road_noise_g = 0.05;
}

/* ---- Physics ----------------------------------------------------------------------------- */

static const double face_vec[CAL_FACES][3] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                              {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};

/* Pitch (deg) and pitch rate (deg/s) of one bump tau seconds after it began. */
static void bump_pitch(const struct epb_rig_vehicle *v, const struct epb_rig_bump *b, double tau,
                       double *amp_g, double *pitch, double *rate)
{
    const double w = 2.0 * PI * v->bump_freq_hz;
    const double z = v->bump_zeta;
    const double wd = w * sqrt(1.0 - z * z);
    const double e = exp(-z * w * tau);
    const double s = sin(wd * tau), c = cos(wd * tau);
    *amp_g = b->amp_g * e * s;
    *pitch = b->pitch_deg * e * s;
    *rate = b->pitch_deg * e * (wd * c - z * w * s);
}

void epb_rig_truth(struct epb_rig *r, double t, double a[3], double rate[3])
{
    const struct epb_rig_vehicle *v = &r->veh;
    double pitch = v->slope_deg, bz = 0.0, prate = 0.0;
    unsigned k, i;
    if (r->mode == EPB_RIG_STATION) {
        for (i = 0; i < 3u; i++) {
            a[i] = r->station_dir[i];
            rate[i] = 0.0;
        }
        return;
    }
    for (k = 0; k < r->bump_count; k++) {
        const double tau = t - r->bumps[k].t0;
        if (tau >= 0.0) {
            double ag, p, pr;
            bump_pitch(v, &r->bumps[k], tau, &ag, &p, &pr);
            bz += ag;
            pitch += p;
            prate += pr;
        }
    }
    if (v->drive_off_s >= 0.0 && t > v->drive_off_s) {
        const double ramp = t - v->drive_off_s < 1.0 ? t - v->drive_off_s : 1.0;
        pitch += v->drive_squat_deg * ramp;
        if (t - v->drive_off_s < 1.0) {
            prate += v->drive_squat_deg;
        }
    }
    r->last_pitch_deg = pitch;
    a[0] = sin(pitch * DEG);
    a[1] = cos(pitch * DEG) * sin(v->roll_deg * DEG);
    a[2] = cos(pitch * DEG) * cos(v->roll_deg * DEG) + bz;
    rate[0] = 0.0;
    rate[1] = -prate; /* right-handed about y (left): nose up is a negative rate */
    rate[2] = 0.0;
    if (v->idle_rpm > 0.0) {
        const double f1 = v->idle_rpm / 60.0;
        for (k = 0; k < EPB_RIG_ORDERS; k++) {
            const struct epb_rig_order *o = &v->orders[k];
            for (i = 0; i < 3u; i++) {
                const double s = sin(2.0 * PI * o->order * f1 * t + r->phase[k][i]);
                a[i] += o->amp_g[i] * s;
                rate[i] += o->amp_dps[i] * s;
            }
        }
    }
    if (v->drive_off_s >= 0.0 && t > v->drive_off_s) {
        const double ramp = t - v->drive_off_s < 1.0 ? t - v->drive_off_s : 1.0;
        a[0] += v->drive_accel_g * ramp;
        a[0] += 0.4 * v->road_noise_g * sim_rng_gauss(&r->rng);
        a[1] += 0.4 * v->road_noise_g * sim_rng_gauss(&r->rng);
        a[2] += v->road_noise_g * sim_rng_gauss(&r->rng);
        for (i = 0; i < 3u; i++) {
            rate[i] += 20.0 * v->road_noise_g * sim_rng_gauss(&r->rng); /* 1 deg/s at 50 mg */
        }
    }
}

/* Bumps begin as virtual time passes them (Poisson arrivals from the rig's generator). */
static void spawn_bumps(struct epb_rig *r, double t)
{
    const struct epb_rig_vehicle *v = &r->veh;
    if (v->bump_rate_hz <= 0.0) {
        return;
    }
    while (r->next_bump_s <= t) {
        struct epb_rig_bump b;
        b.t0 = r->next_bump_s;
        b.amp_g = v->bump_amp_g * (0.3 + 0.7 * sim_rng_uniform(&r->rng));
        b.pitch_deg = v->bump_pitch_deg * (0.3 + 0.7 * sim_rng_uniform(&r->rng));
        if (sim_rng_uniform(&r->rng) < 0.5) {
            b.amp_g = -b.amp_g;
            b.pitch_deg = -b.pitch_deg;
        }
        if (r->bump_count < EPB_RIG_BUMPS) {
            r->bumps[r->bump_count++] = b;
        } else {
            unsigned k;
            for (k = 1; k < EPB_RIG_BUMPS; k++) {
                r->bumps[k - 1] = r->bumps[k];
            }
            r->bumps[EPB_RIG_BUMPS - 1] = b;
        }
        r->bump_total++;
        r->next_bump_s += -log(1.0 - sim_rng_uniform(&r->rng)) / v->bump_rate_hz;
    }
}

static void physics(void *ctx, uint64_t t_ns, struct sim_inertial_input *in)
{
    struct epb_rig *r = ctx;
    double t;
    sim_inertial_at_rest(in);
    if (r->mode == EPB_RIG_STATION) {
        in->temp_c = r->station_temp_c;
        epb_rig_truth(r, 0.0, in->accel_g, in->rate_dps);
        return;
    }
    t = t_ns >= r->t0_ns ? (double)(t_ns - r->t0_ns) * 1e-9 : 0.0;
    spawn_bumps(r, t);
    in->temp_c = r->veh.temp_c;
    epb_rig_truth(r, t, in->accel_g, in->rate_dps);
}

/* ---- Set-up ------------------------------------------------------------------------------- */

int epb_rig_init(struct epb_rig *r, enum epb_rig_part part, const struct sim_calpart_params *errors,
                 uint64_t seed)
{
    static const struct simflash_geometry geo = {RIG_FLASH_PAGE, 2u, RIG_FLASH_PROG};
    struct sim_calpart_params p;
    int err;
    if (r == NULL) {
        return INC_ERR_NULL;
    }
    if (epb_rig_part_get(part) == NULL) {
        return INC_ERR_INVAL;
    }
    memset(r, 0, sizeof(*r));
    r->part = part;
    r->info = epb_rig_part_get(part);
    if (errors != NULL) {
        p = *errors;
    } else {
        sim_calpart_paper(&p);
    }
    sim_calpart_init(&r->errors, &p, seed ^ 0x4E4F495345ull); /* "NOISE" */
    r->em = sim_calpart_error_model(&r->errors);
    r->phys.sample = physics;
    r->phys.ctx = r;
    sim_rng_seed(&r->rng, seed ^ 0x56454849434Cull); /* "VEHICL" */
    epb_rig_station(r, CAL_FACE_ZP, 25.0);
    epb_rig_vehicle_default(&r->veh);
    err = sim_board_init(&r->board);
    if (err != INC_OK) {
        return err;
    }
    err = simflash_init(&r->flash, r->flash_mem, sizeof(r->flash_mem), &geo);
    if (err != INC_OK) {
        return err;
    }
    if (r->info->adis) {
        struct sim_adis_imu_cfg c;
        memset(&c, 0, sizeof(c));
        c.variant = (enum sim_adis_imu_variant)r->info->sim_variant;
        c.bus = &r->board.bus;
        c.cs = SIM_BOARD_CS(0);
        c.sclk = SIM_BOARD_SCLK;
        c.mosi = SIM_BOARD_MOSI;
        c.miso = SIM_BOARD_MISO;
        c.dio1 = SIM_BOARD_DR(0);
        c.dio2 = SIM_BOARD_DR(1);
        c.log = &r->board.log;
        c.physics = &r->phys;
        c.error = &r->em;
        c.seed = seed;
        c.power_on_busy = true;
        err = sim_adis_imu_init(&r->adis, &c);
        if (err != INC_OK) {
            return err;
        }
        /* The part's start-up time (the driver does not wait it: its caller does). */
        hal_delay_ms(&r->board.hal, ADIS_IMU_STARTUP_MS);
    } else {
        struct sim_sca3000_cfg c;
        memset(&c, 0, sizeof(c));
        c.bus = &r->board.bus;
        c.cs = SIM_BOARD_CS(0);
        c.sclk = SIM_BOARD_SCLK;
        c.mosi = SIM_BOARD_MOSI;
        c.miso = SIM_BOARD_MISO;
        c.int_pin = SIM_BOARD_DR(0);
        c.variant = (enum sim_sca3000_variant)r->info->sim_variant;
        c.range_g = r->info->range_g;
        c.log = &r->board.log;
        err = sim_sca3000_init(&r->sca, &c);
        if (err != INC_OK) {
            return err;
        }
        sim_sca3000_set_physics(&r->sca, &r->phys);
        sim_sca3000_set_error_model(&r->sca, &r->em);
        hal_delay_ms(&r->board.hal, 10u);
    }
    return INC_OK;
}

static void s32k_port_isr0(void *arg)
{
    s32k_board_port_isr(arg, 0u);
}
static void s32k_port_isr1(void *arg)
{
    s32k_board_port_isr(arg, 1u);
}
static void s32k_port_isr2(void *arg)
{
    s32k_board_port_isr(arg, 2u);
}
static void s32k_port_isr3(void *arg)
{
    s32k_board_port_isr(arg, 3u);
}
static void s32k_port_isr4(void *arg)
{
    s32k_board_port_isr(arg, 4u);
}
static void s32k_lpspi_isr(void *arg)
{
    s32k_board_lpspi_isr(arg);
}

static void s32k_lpit_isr(void *arg)
{
    s32k_board_lpit_isr(arg);
}

int epb_rig_set_board(struct epb_rig *r, enum epb_rig_board board)
{
    return epb_rig_set_board_spi(r, board, false);
}

/* LPSPI0's model on the rig's wires: SCK/SOUT/SIN on sclk/mosi/miso, the part's PCS on cs0. */
static int rig_lpspi_up(struct epb_rig *r, const struct s32k_board_desc *d)
{
    const struct s32k_board_pins *p = &d->pins;
    const uint8_t pcs = r->info->adis ? p->cs_imu_pcs : p->cs_acc_pcs;
    struct sim_s32k_lpspi_cfg mc;
    unsigned k;
    if (pcs >= SIM_LPSPI_PCS) {
        return INC_ERR_UNSUPPORTED;
    }
    mc.base = LPSPI0_BASE;
    mc.fclk_hz = d->clock == S32K_CLOCK_SPLL_80 ? S32K_BOARD_LPSPI_SPLL_HZ : S32K_FIRCDIV2_HZ;
    mc.clk = &r->board.clk;
    mc.bus = &r->board.bus;
    mc.sck = SIM_BOARD_SCLK;
    mc.sout = SIM_BOARD_MOSI;
    mc.sin = SIM_BOARD_MISO;
    for (k = 0; k < SIM_LPSPI_PCS; k++) {
        mc.pcs[k] = SIM_LPSPI_NO_PIN;
    }
    mc.pcs[pcs] = SIM_BOARD_CS(0);
    mc.core = &r->s32k_core; /* the engine sleeps on LPSPI0's interrupt (s32k_board.h) */
    mc.irq = S32K1_IRQ_LPSPI0;
    return sim_s32k_lpspi_init(&r->s32k_lpspi, &mc);
}

int epb_rig_set_board_spi(struct epb_rig *r, enum epb_rig_board board, bool lpspi)
{
    static const sim_s32k_isr port_isr[S32K_PORT_COUNT] = {
        s32k_port_isr0, s32k_port_isr1, s32k_port_isr2, s32k_port_isr3, s32k_port_isr4};
    const struct s32k_board_desc *d = &s32k_board_s32k144evb;
    const struct s32k_board_pins *p = &d->pins;
    unsigned i;
    int err;
    if (r == NULL) {
        return INC_ERR_NULL;
    }
    if (board == EPB_RIG_BOARD_SIM) {
        if (lpspi) {
            return INC_ERR_INVAL;
        }
        r->mcu = board;
        return INC_OK;
    }
    if (board != EPB_RIG_BOARD_S32K144) {
        return INC_ERR_INVAL;
    }
    s32k_bus_reset();
    err = sim_s32k_core_init(&r->s32k_core, &r->board.clk);
    if (err == INC_OK) {
        err = sim_s32k_lpit_init(&r->s32k_lpit, &r->board.clk, &r->s32k_core, d->part, S32K_TIME_HZ,
                                 SIM_S32K_ACCESS_NS_DEFAULT);
    }
    if (err == INC_OK) {
        err = sim_s32k_port_gpio_init(&r->s32k_gpio, &r->board.bus, &r->s32k_core, d->part);
    }
    /* The EVB's sensor header on the rig's wires: the part under test is on cs0/dr0. */
    if (err == INC_OK) {
        err = sim_s32k_port_gpio_connect(&r->s32k_gpio, p->sclk, SIM_BOARD_SCLK);
    }
    if (err == INC_OK) {
        err = sim_s32k_port_gpio_connect(&r->s32k_gpio, p->mosi, SIM_BOARD_MOSI);
    }
    if (err == INC_OK) {
        err = sim_s32k_port_gpio_connect(&r->s32k_gpio, p->miso, SIM_BOARD_MISO);
    }
    if (err == INC_OK) {
        err = sim_s32k_port_gpio_connect(&r->s32k_gpio, r->info->adis ? p->cs_imu : p->cs_acc,
                                         SIM_BOARD_CS(0));
    }
    if (err == INC_OK) {
        err = sim_s32k_port_gpio_connect(&r->s32k_gpio, r->info->adis ? p->cs_acc : p->cs_imu,
                                         SIM_BOARD_CS(1));
    }
    if (err == INC_OK) {
        err = sim_s32k_port_gpio_connect(&r->s32k_gpio, r->info->adis ? p->dr_imu : p->dr_acc,
                                         SIM_BOARD_DR(0));
    }
    if (err == INC_OK) {
        err = sim_s32k_port_gpio_connect(&r->s32k_gpio, p->rst_imu, SIM_BOARD_RST(0));
    }
    if (err != INC_OK) {
        return err;
    }
    for (i = 0; i < S32K_PORT_COUNT; i++) {
        sim_s32k_core_set_handler(&r->s32k_core, S32K144_IRQ_PORTA + i, port_isr[i], &r->s32k);
    }
    sim_s32k_core_set_handler(&r->s32k_core, S32K144_IRQ_LPIT0_CH1, s32k_lpit_isr, &r->s32k);
    sim_s32k_core_set_handler(&r->s32k_core, S32K1_IRQ_LPSPI0, s32k_lpspi_isr, &r->s32k);
    /* What the startup does first, then the board's bring-up. */
    err = s32k_wdog_init(true);
    if (err == INC_OK && lpspi) {
        err = rig_lpspi_up(r, d);
    }
    if (err == INC_OK) {
        err = s32k_board_init(&r->s32k, d, lpspi ? S32K_BOARD_SPI_LPSPI : S32K_BOARD_SPI_BITBANG,
                              true);
    }
    if (err == INC_OK) {
        r->mcu = board;
    }
    return err;
}

uint32_t epb_rig_rate_mhz(const struct epb_rig *r)
{
    return (uint32_t)(r->info->rate_sps * 1000.0 + 0.5);
}

int epb_rig_power_up(struct epb_rig *r, const struct app_cfg *cfg)
{
    struct calstore_config sc;
    const struct hal *fw_hal;
    const struct spi_bus *fw_bus;
    hal_pin_t fw_cs = SIM_BOARD_CS(0);
    hal_pin_t fw_dr = SIM_BOARD_DR(0);
    int err;
    if (r == NULL || cfg == NULL) {
        return INC_ERR_NULL;
    }
    fw_hal = &r->board.hal;
    fw_bus = &r->board.spi.bus;
    memset(&r->imu, 0, sizeof(r->imu));
    memset(&r->sca_dev, 0, sizeof(r->sca_dev));
    memset(&r->app, 0, sizeof(r->app));
    if (r->mcu == EPB_RIG_BOARD_S32K144) {
        fw_hal = &r->s32k.hal;
        fw_bus = r->s32k.spi;
        fw_cs = r->info->adis ? r->s32k.desc->pins.cs_imu : r->s32k.desc->pins.cs_acc;
        fw_dr = r->s32k.desc->pins.dr_imu;
    }
    if (r->info->adis) {
        struct adis_imu_cfg c;
        memset(&c, 0, sizeof(c));
        c.hal = fw_hal;
        c.bus = fw_bus;
        c.cs = fw_cs;
        c.variant = (uint8_t)r->info->sim_variant; /* same order in both enums */
        c.dr_pin = fw_dr;
        c.dr_line = (uint8_t)ADIS_IMU_DR_DIO1;
        err = adis_imu_init(&r->imu, &c);
        if (err == INC_OK) {
            /* The application averages; the part's own filter would make its samples
             * correlated and the noise term of the bound optimistic (docs/epb-demo.md). */
            err = adis_imu_set_filter(&r->imu, 0u, ADIS_IMU_RANGE_300);
        }
        if (err == INC_OK) {
            err = adis_imu_dr_flush(&r->imu);
        }
        r->sensor.ops = &adis_imu_sensor_ops;
        r->sensor.dev = &r->imu;
    } else {
        struct sca3000_cfg c;
        memset(&c, 0, sizeof(c));
        c.bus = fw_bus;
        c.cs = fw_cs;
        c.variant = (enum sca3000_variant)r->info->sim_variant; /* same order */
        c.hal = fw_hal;
        c.int_pin = HAL_PIN_NONE;
        err = sca3000_init(&r->sca_dev, &c);
        r->sensor.ops = &sca3000_sensor_ops;
        r->sensor.dev = &r->sca_dev;
    }
    if (err != INC_OK) {
        return err;
    }
    err = simflash_calstore_config(&r->flash, &sc); /* a slot in each of its two pages */
    if (err == INC_OK) {
        err = calstore_init(&r->store, &sc);
    }
    if (err != INC_OK) {
        return err;
    }
    return app_init(&r->app, cfg, &r->sensor, &r->store);
}

void epb_rig_face_dir(int face, double dir[3])
{
    const int f = face >= 0 && face < CAL_FACES ? face : CAL_FACE_ZP;
    unsigned i;
    for (i = 0; i < 3u; i++) {
        dir[i] = face_vec[f][i];
    }
}

void epb_rig_station(struct epb_rig *r, int face, double temp_c)
{
    const int f = face >= 0 && face < CAL_FACES ? face : CAL_FACE_ZP;
    epb_rig_station_dir(r, face_vec[f], temp_c);
    r->face = f;
}

void epb_rig_station_dir(struct epb_rig *r, const double dir[3], double temp_c)
{
    unsigned i;
    r->mode = EPB_RIG_STATION;
    r->face = -1;
    for (i = 0; i < 3u; i++) {
        r->station_dir[i] = dir[i];
    }
    r->station_temp_c = temp_c;
}

void epb_rig_park(struct epb_rig *r, const struct epb_rig_vehicle *v)
{
    unsigned k, i;
    r->veh = *v;
    r->mode = EPB_RIG_VEHICLE;
    r->t0_ns = r->board.clk.now_ns;
    r->bump_count = 0;
    r->bump_total = 0;
    r->last_pitch_deg = v->slope_deg;
    for (k = 0; k < EPB_RIG_ORDERS; k++) {
        for (i = 0; i < 3u; i++) {
            r->phase[k][i] = 2.0 * PI * sim_rng_uniform(&r->rng);
        }
    }
    r->next_bump_s = v->bump_rate_hz > 0.0 ? -log(1.0 - sim_rng_uniform(&r->rng)) / v->bump_rate_hz
                                           : 0.0;
}

void epb_rig_wait(struct epb_rig *r, double seconds)
{
    if (seconds > 0.0) {
        hal_delay_until(&r->board.hal, r->board.clk.now_ns + (uint64_t)(seconds * 1e9 + 0.5));
    }
}

double epb_rig_scenario_s(const struct epb_rig *r)
{
    return r->board.clk.now_ns >= r->t0_ns ? (double)(r->board.clk.now_ns - r->t0_ns) * 1e-9 : 0.0;
}

double epb_rig_now_s(const struct epb_rig *r)
{
    return (double)r->board.clk.now_ns * 1e-9;
}

unsigned epb_rig_violations(const struct epb_rig *r)
{
    return r->board.log.total;
}

struct epb_rig *epb_rig_instance(void)
{
    static struct epb_rig rig;
    return &rig;
}

const struct epb_rig_part_info *epb_rig_info(const struct epb_rig *r)
{
    return r->info;
}

struct app *epb_rig_app(struct epb_rig *r)
{
    return &r->app;
}

const struct sensor *epb_rig_sensor(const struct epb_rig *r)
{
    return &r->sensor;
}

struct calstore *epb_rig_store(struct epb_rig *r)
{
    return &r->store;
}

struct sim_pinbus *epb_rig_pinbus(struct epb_rig *r)
{
    return &r->board.bus;
}

void epb_rig_print_violations(const struct epb_rig *r, FILE *out)
{
    if (r->board.log.total != 0u) {
        sim_violation_log_print(&r->board.log, out);
    }
}

unsigned epb_rig_bump_count(const struct epb_rig *r)
{
    return r->bump_total;
}

int epb_rig_vcd_open(struct epb_rig *r, struct sim_vcd *v, const char *path)
{
    return sim_vcd_open(v, path, &r->board.bus, SIM_BOARD_SPI_MASK | SIM_PIN_MASK(SIM_BOARD_DR(0)));
}

int epb_rig_vcd_start(struct epb_rig *r, struct sim_vcd *v, FILE *f)
{
    return sim_vcd_start(v, f, &r->board.bus, SIM_BOARD_SPI_MASK | SIM_PIN_MASK(SIM_BOARD_DR(0)));
}
