/* app_nav.c - the navigation mode: SCA3000 + ADIS16255 on one bus, GPS, dead reckoning
 * (inclino/app_nav.h). */
#include "inclino/app_nav.h"

struct app_nav_cfg app_nav_default_cfg(uint32_t lsb_ug)
{
    struct app_nav_cfg c;
    /* Q = 20 counts x lsb_ug micro-g, in Q16 g: 20 * lsb * 65536 / 1e6 */
    const int32_t q = (int32_t)(((uint64_t)20u * lsb_ug * 65536u + 500000u) / 1000000u);
    c.nav = nav_default_cfg(q > 0 ? q : 1);
    c.still.window = 125u; /* 1 s at 125 Hz */
    c.still.windows_required = 2u;
    /* gyro Q16 deg/s: var 4e9 = (0.97 deg/s)^2: noise and engine vibration pass, the mean and
     * drift tests and the speed catch motion */
    c.still.gyro_var_max = 4000000000u;
    /* accel Q16 g: var 4e6 = (30 mg)^2 (engine vibration at idle; the speed test catches a
     * smooth drive) */
    c.still.accel_var_max = 4000000u;
    c.still.gyro_mean_max = (uint32_t)FX_Q16_INT(2); /* a steady turn is not rest */
    c.still.accel_one_g = FX_Q16_ONE;
    c.still.accel_norm_tol = (uint32_t)(FX_Q16_ONE / 20);
    c.still.accel_drift_max = (uint32_t)(FX_Q16_ONE / 100);
    c.gps_latency_ns = 80000000u;
    return c;
}

int app_nav_init(struct app_nav *a, const struct app_nav_cfg *cfg)
{
    int rc;
    if (a == NULL || cfg == NULL) return INC_ERR_NULL;
    a->ready = false;
    a->cfg = *cfg;
    if ((rc = nav_init(&a->nav, &cfg->nav)) != INC_OK) return rc;
    if ((rc = still_init(&a->still, &cfg->still)) != INC_OK) return rc;
    if ((rc = nmea_init(&a->nmea)) != INC_OK) return rc;
    a->gyro_last = 0;
    a->acc_sum = 0;
    a->acc_n = 0u;
    a->acc_last = 0;
    a->rest_gyro_sum = a->rest_acc_sum = 0;
    a->rest_n = 0u;
    a->stats.gyro_samples = a->stats.accel_samples = a->stats.cycles = 0u;
    a->stats.nmea_sentences = a->stats.nmea_errors = a->stats.fixes = 0u;
    a->stats.fixes_refused = a->stats.offsets = 0u;
    a->stats.nmea_last_error = INC_OK;
    a->stats.nmea_last_why = NMEA_OK;
    a->ready = true;
    return INC_OK;
}

int app_nav_gyro(struct app_nav *a, fx_q16_t rate_dps, uint32_t dt_ns)
{
    if (a == NULL) return INC_ERR_NULL;
    if (!a->ready) return INC_ERR_STATE;
    a->gyro_last = rate_dps;
    a->stats.gyro_samples++;
    return nav_gyro(&a->nav, rate_dps, dt_ns);
}

int app_nav_accel(struct app_nav *a, const fx_q16_t acc_g[3])
{
    const int32_t g[3] = {0, 0, a != NULL ? a->gyro_last : 0};
    bool done = false;
    int rc;
    if (a == NULL || acc_g == NULL) return INC_ERR_NULL;
    if (!a->ready) return INC_ERR_STATE;
    a->stats.accel_samples++;
    a->acc_sum += acc_g[0];
    a->acc_n++;
    a->acc_last = acc_g[0];
    rc = still_push(&a->still, g, acc_g, &done);
    if (rc != INC_OK) return rc;
    /* only when standing: a steady drive on a smooth road can look still to the gate, so the
     * speed must say so too (no fix yet, or below NAV_REST_SPEED) */
    if (done && still_at_rest(&a->still) &&
        (!a->nav.blend.have_fix || fx_abs(a->nav.v_q16) < APP_NAV_REST_SPEED_Q16)) {
        const struct still_window *w = still_last(&a->still);
        if (w != NULL) {
            /* the mean of every window of this stop (one window's mean carries the noise of
             * one second; a stop of n windows, 1 / sqrt(n) of it) */
            if (a->rest_n < APP_NAV_REST_WINDOWS) {
                a->rest_gyro_sum += w->gyro_mean[2];
                a->rest_acc_sum += w->accel_mean[0];
                a->rest_n++;
            }
            (void)nav_gyro_offset(&a->nav, fx_div64(a->rest_gyro_sum, a->rest_n));
            (void)nav_accel_rest(&a->nav, fx_div64(a->rest_acc_sum, a->rest_n));
            a->stats.offsets++;
        }
    } else if (done) {
        a->rest_gyro_sum = a->rest_acc_sum = 0; /* the next stop starts its own mean */
        a->rest_n = 0u;
    }
    return INC_OK;
}

int app_nav_uart(struct app_nav *a, const char *data, size_t len, uint64_t t_arrival_ns)
{
    size_t off = 0;
    int used_fixes = 0;
    if (a == NULL || (data == NULL && len > 0u)) return INC_ERR_NULL;
    if (!a->ready) return INC_ERR_STATE;
    while (off < len) {
        struct nmea_msg m;
        size_t used = 0;
        const int rc = nmea_feed(&a->nmea, data + off, len - off, &used, &m);
        off += used;
        if (rc < 0) {
            a->stats.nmea_errors++;
            a->stats.nmea_last_error = rc;
            a->stats.nmea_last_why = a->nmea.why;
        } else if (rc == 1) {
            a->stats.nmea_sentences++;
            if (m.type == NMEA_RMC && nmea_msg_has_fix(&m)) {
                struct nav_fix_in f;
                int frc;
                f.lat_e7 = m.lat_e7;
                f.lon_e7 = m.lon_e7;
                f.speed_mmps = m.speed_mmps;
                f.course_cdeg = m.course_cdeg;
                f.has_speed = (m.has & NMEA_HAS_SPEED) != 0u;
                f.has_course = (m.has & NMEA_HAS_COURSE) != 0u;
                f.t_valid_ns = t_arrival_ns > a->cfg.gps_latency_ns
                                   ? t_arrival_ns - a->cfg.gps_latency_ns
                                   : 0u;
                frc = nav_fix(&a->nav, &f);
                if (frc >= 0) {
                    a->stats.fixes++;
                    used_fixes++;
                } else {
                    a->stats.fixes_refused++;
                }
            }
        } else if (used == 0u) {
            break;
        }
    }
    return used_fixes;
}

int app_nav_cycle(struct app_nav *a, uint32_t dt_ns, struct nav_out *out)
{
    struct nav_in in;
    if (a == NULL) return INC_ERR_NULL;
    if (!a->ready) return INC_ERR_STATE;
    in.a_fwd_g = a->acc_n > 0u ? fx_div64(a->acc_sum, a->acc_n) : a->acc_last;
    in.a_comp = false;
    in.dt_ns = dt_ns;
    a->acc_sum = 0;
    a->acc_n = 0u;
    a->stats.cycles++;
    return nav_step(&a->nav, &in, out);
}

/* ---- the bus ----------------------------------------------------------------------------- */

int app_nav_bus_init(struct app_nav_bus *b, struct app_nav *nav, const struct app_nav_bus_cfg *c)
{
    struct adis16255_cfg gc;
    struct sca3000_cfg ac;
    int rc;
    if (b == NULL || nav == NULL || c == NULL || c->bus == NULL || c->hal == NULL)
        return INC_ERR_NULL;
    if (c->cycle_ns == 0u || c->cycle_ns > NAV_MAX_DT_NS) return INC_ERR_INVAL;
    b->nav = nav;
    b->hal = c->hal;
    b->acc_variant = c->acc_variant;
    gc.bus = c->bus;
    gc.hal = c->hal;
    gc.cs = c->gyro_cs;
    gc.dr_pin = c->gyro_dr;
    gc.smpl_prd = ADIS16255_SMPL_PRD_DEFAULT; /* 256 SPS */
    gc.range = ADIS16255_RANGE_80;
    gc.filter_m = ADIS16255_FILTER_M_MIN_80;
    gc.dr_enable = true;
    gc.dr_active_high = true;
    gc.dr_line = 0u;
    gc.reset_at_init = false;
    gc.self_test_at_init = false;
    if ((rc = adis16255_init(&b->gyro, &gc)) != INC_OK) return rc;
    ac.bus = c->bus;
    ac.cs = c->acc_cs;
    ac.spi_mode0 = true; /* the other mode: the engine switches SCLK idle between the parts */
    ac.variant = c->acc_variant;
    ac.expected_revid = 0u;
    ac.hal = c->hal;
    ac.int_pin = HAL_PIN_NONE;
    if ((rc = sca3000_init(&b->acc, &ac)) != INC_OK) return rc;
    b->acc_period_ns = sca3000_period_ns(&b->acc);
    b->cycle_ns = c->cycle_ns;
    b->next_acc_ns = hal_now_ns(c->hal) + b->acc_period_ns;
    b->next_cycle_ns = hal_now_ns(c->hal) + c->cycle_ns;
    b->last_cycle_ns = hal_now_ns(c->hal);
    b->t_start_ns = b->last_cycle_ns - nav->nav.t_ns;
    b->last_gyro_ns = 0u;
    b->bus_ns_gyro = b->bus_ns_acc = 0u;
    b->reads_gyro = b->reads_acc = b->errors_gyro = b->errors_acc = b->missed_gyro = 0u;
    b->last_error = INC_OK;
    return INC_OK;
}

int app_nav_bus_uart(struct app_nav_bus *b, const char *data, size_t len)
{
    uint64_t now;
    if (b == NULL || b->hal == NULL) return INC_ERR_NULL;
    now = hal_now_ns(b->hal);
    return app_nav_uart(b->nav, data, len, now > b->t_start_ns ? now - b->t_start_ns : 0u);
}

static void read_gyro(struct app_nav_bus *b)
{
    struct adis16255_sample s;
    const uint64_t t0 = hal_now_ns(b->hal);
    const int rc = adis16255_read_sample(&b->gyro, &s);
    const uint64_t t1 = hal_now_ns(b->hal);
    b->bus_ns_gyro += t1 - t0;
    b->reads_gyro++;
    if (rc != INC_OK || !s.valid) {
        b->errors_gyro++;
        b->last_error = rc;
        return;
    }
    if (b->last_gyro_ns != 0u && t0 > b->last_gyro_ns) {
        const uint64_t dt = t0 - b->last_gyro_ns;
        (void)app_nav_gyro(b->nav, s.rate_dps_q16,
                           (uint32_t)(dt > NAV_MAX_DT_NS ? NAV_MAX_DT_NS : dt));
    }
    b->last_gyro_ns = t0;
}

static void read_acc(struct app_nav_bus *b)
{
    int16_t xyz[3];
    fx_q16_t g[3];
    unsigned i;
    const uint64_t t0 = hal_now_ns(b->hal);
    int rc = sca3000_read_accel(&b->acc, xyz);
    const uint64_t t1 = hal_now_ns(b->hal);
    b->bus_ns_acc += t1 - t0;
    b->reads_acc++;
    for (i = 0; rc == INC_OK && i < 3u; i++)
        rc = sca3000_accel_g_from_counts(xyz[i], b->acc_variant, &g[i]);
    if (rc != INC_OK) {
        b->errors_acc++;
        b->last_error = rc;
        return;
    }
    (void)app_nav_accel(b->nav, g);
}

int app_nav_bus_run(struct app_nav_bus *b, uint64_t until_ns, struct nav_out *out)
{
    int cycles = 0;
    if (b == NULL) return INC_ERR_NULL;
    for (;;) {
        uint64_t now = hal_now_ns(b->hal);
        uint64_t next = b->next_acc_ns < b->next_cycle_ns ? b->next_acc_ns : b->next_cycle_ns;
        if (now >= until_ns) break;
        if (next > until_ns) next = until_ns;
        if (next > now) {
            uint32_t missed = 0;
            const uint64_t wait = next - now;
            const int rc = adis16255_wait_ready(
                &b->gyro, (uint32_t)(wait > 0xFFFFFFFFu ? 0xFFFFFFFFu : wait), &missed);
            if (rc == INC_OK) {
                b->missed_gyro += missed;
                read_gyro(b);
                continue; /* look at the deadlines again */
            }
            if (rc != INC_ERR_TIMEOUT) b->last_error = rc;
            now = hal_now_ns(b->hal);
        }
        if (now >= b->next_acc_ns) {
            read_acc(b);
            b->next_acc_ns += b->acc_period_ns;
        }
        if (now >= b->next_cycle_ns) {
            struct nav_out o;
            const uint64_t t = hal_now_ns(b->hal);
            (void)app_nav_cycle(b->nav, (uint32_t)(t - b->last_cycle_ns), &o);
            b->last_cycle_ns = t;
            b->next_cycle_ns += b->cycle_ns;
            if (out != NULL) *out = o;
            cycles++;
        }
    }
    return cycles;
}
