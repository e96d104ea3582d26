/* nav.c - dead reckoning between GPS fixes (inclino/nav.h). */
#include "inclino/nav.h"

#define H_FULL ((int64_t)360 * 65536 * 1000000000) /* 360 deg in Q16 deg x ns */
#define H_HALF (H_FULL / 2)
#define NS_PER_S 1000000000
#define PI_180_Q30 18740330 /* pi / 180 in Q30 (18740329.5) */
#define C_Q36 764981716     /* a pi / 180 1e-7 m, a = 6378137 m, Q36 */
#define C1_Q36 759860637    /* the same times (1 - e^2) */
#define E2_Q30 7188036      /* e^2 = 0.00669437999014 in Q30 */

static int64_t rdiv(int64_t num, int64_t den) /* round to nearest, ties away; den > 0 */
{
    int64_t q = num / den, r = num % den;
    if (2 * (r < 0 ? -r : r) >= den) q += num < 0 ? -1 : 1;
    return q;
}

static int64_t abs64(int64_t x)
{
    return x < 0 ? -x : x;
}

static int64_t sat_bound(int64_t b)
{
    return b > NAV_BOUND_MAX_Q16 ? NAV_BOUND_MAX_Q16 : (b < 0 ? 0 : b);
}

static int64_t wrap_h(int64_t h) /* [0, 360) */
{
    h %= H_FULL;
    return h < 0 ? h + H_FULL : h;
}

static int64_t wrap_pm(int64_t d) /* [-180, 180) */
{
    d = wrap_h(d);
    return d >= H_HALF ? d - H_FULL : d;
}

/* Q16 quantity per second times dt -> Q16 quantity. */
static int64_t per_s(int64_t rate_q16, uint32_t dt_ns)
{
    return rdiv(rate_q16 * (int64_t)dt_ns, NS_PER_S);
}

struct nav_cfg nav_default_cfg(fx_q16_t q_noise_g)
{
    struct nav_cfg c;
    c.cycle_ns = 13000000u;
    c.avg_passes = 2u;
    c.avg_w = 4u;
    c.blend = gpsb_default_cfg(q_noise_g);
    c.blend.max_gap_ns = 4000000000u;
    c.gain_pos = FX_Q16_ONE / 5;
    c.spread_cycles = 60u;
    c.gain_heading = FX_Q16_ONE / 10;
    c.course_min_mps = FX_Q16_INT(8);
    c.jump_reset = 3u;
    c.gps_bound_m = FX_Q16_INT(15);
    c.speed_bound_mps = FX_Q16_ONE / 2;
    c.course_bound_deg = FX_Q16_INT(3);
    c.accel_err_g = FX_Q16_ONE / 50;
    c.gyro_offset_bound = FX_Q16_ONE / 20;
    c.gyro_offset_uncal = FX_Q16_ONE / 2;
    c.gyro_scale_bound = (fx_q16_t)(FX_Q30_ONE / 200);
    c.heading_noise_deg = FX_Q16_ONE / 10;
    c.slip_deg = FX_Q16_ONE;
    c.pos_limit_m = FX_Q16_INT(50);
    c.speed_limit_mps = FX_Q16_INT(2);
    c.heading_limit_deg = FX_Q16_INT(10);
    return c;
}

int nav_init(struct nav *s, const struct nav_cfg *cfg)
{
    unsigned i;
    int rc;
    if (s == NULL || cfg == NULL) return INC_ERR_NULL;
    s->ready = false;
    if (cfg->cycle_ns < 1000000u || cfg->cycle_ns > NAV_MAX_DT_NS || cfg->avg_passes < 1u ||
        cfg->avg_passes > AVG_CASCADE_MAX_PASSES || cfg->avg_w < 1u || cfg->avg_w > NAV_AVG_MAX_W ||
        cfg->gain_pos <= 0 || cfg->gain_pos > FX_Q16_ONE || cfg->spread_cycles < 1u ||
        cfg->spread_cycles > 64u || cfg->gain_heading < 0 || cfg->gain_heading > FX_Q16_ONE ||
        cfg->course_min_mps < 0 || cfg->jump_reset < 1u || cfg->gps_bound_m <= 0 ||
        cfg->speed_bound_mps < 0 || cfg->course_bound_deg < 0 || cfg->accel_err_g < 0 ||
        cfg->gyro_offset_bound < 0 || cfg->gyro_offset_uncal < 0 || cfg->gyro_scale_bound < 0 ||
        cfg->heading_noise_deg < 0 || cfg->slip_deg < 0 || cfg->slip_deg > FX_Q16_INT(90) ||
        cfg->pos_limit_m <= 0 || cfg->speed_limit_mps <= 0 || cfg->heading_limit_deg <= 0)
        return INC_ERR_INVAL;
    s->cfg = *cfg;
    rc = avg_cascade_init(&s->avg, s->avg_lines, NAV_AVG_MAX_W * AVG_CASCADE_MAX_PASSES, cfg->avg_w,
                          cfg->avg_passes);
    if (rc != INC_OK) return rc;
    rc = gpsb_init(&s->blend, &cfg->blend);
    if (rc != INC_OK) return rc;
    s->have_ref = s->have_heading = s->have_offset = s->have_rest_accel = false;
    s->ref_lat_e7 = s->ref_lon_e7 = 0;
    s->k_n_q36 = s->k_e_q36 = 0;
    s->t_ns = 0u;
    s->e_q32 = s->n_q32 = 0;
    s->h = s->h_raw = 0;
    s->gyro_offset = 0;
    s->rest_accel_g = 0;
    s->pend_e_q32 = s->pend_n_q32 = 0;
    s->corr_e_q32 = s->corr_n_q32 = 0;
    s->pend_left = 0u;
    s->jumps = 0u;
    s->b_h_ns = (int64_t)FX_Q16_INT(180) * NS_PER_S;
    s->b_v_q16 = NAV_BOUND_MAX_Q16;
    s->b_p_q16 = NAV_BOUND_MAX_Q16;
    s->s_q16 = 0;
    s->speed_gap = false;
    s->v_q16 = 0;
    s->k = 0;
    for (i = 0; i < NAV_RING; i++) {
        s->ring[i].t_ns = 0u;
        s->ring[i].e_q32 = s->ring[i].n_q32 = s->ring[i].h = s->ring[i].v_q32 = 0;
    }
    s->ring_head = s->ring_count = 0u;
    s->fixes = s->fixes_refused = s->resets = s->course_updates = 0u;
    s->ready = true;
    return INC_OK;
}

int nav_gyro_offset(struct nav *s, fx_q16_t offset_dps)
{
    if (s == NULL) return INC_ERR_NULL;
    if (!s->ready) return INC_ERR_STATE;
    s->gyro_offset = offset_dps;
    s->have_offset = true;
    return INC_OK;
}

int nav_accel_rest(struct nav *s, fx_q16_t a_fwd_g)
{
    if (s == NULL) return INC_ERR_NULL;
    if (!s->ready) return INC_ERR_STATE;
    s->rest_accel_g = a_fwd_g;
    s->have_rest_accel = true;
    return INC_OK;
}

int nav_gyro(struct nav *s, fx_q16_t rate_dps, uint32_t dt_ns)
{
    int32_t r, ra = 0;
    bool full;
    int rc;
    int64_t grow;
    if (s == NULL) return INC_ERR_NULL;
    if (!s->ready) return INC_ERR_STATE;
    if (dt_ns == 0u || dt_ns > NAV_MAX_DT_NS) return INC_ERR_RANGE;
    r = fx_clamp(fx_sub(rate_dps, s->gyro_offset), -FX_Q16_INT(2000), FX_Q16_INT(2000));
    rc = avg_cascade_push(&s->avg, r, &ra, &full);
    if (rc != INC_OK) return rc;
    /* |ra|, |r| <= 2000 deg/s: * dt <= 1e8 ns stays below 2^54 */
    s->h = wrap_h(s->h + (int64_t)ra * (int64_t)dt_ns);
    s->h_raw += ((int64_t)r - (int64_t)ra) * (int64_t)dt_ns; /* the lag h_raw - h */
    grow = (int64_t)(s->have_offset ? s->cfg.gyro_offset_bound : s->cfg.gyro_offset_uncal) +
           (((int64_t)s->cfg.gyro_scale_bound * abs64(r)) >> 30);
    s->b_h_ns += grow * (int64_t)dt_ns;
    if (s->b_h_ns > (int64_t)FX_Q16_INT(180) * NS_PER_S)
        s->b_h_ns = (int64_t)FX_Q16_INT(180) * NS_PER_S;
    return INC_OK;
}

/* Heading bound of the output, Q16 deg (<= 180). */
static int64_t heading_bound(const struct nav *s)
{
    int64_t b;
    if (!s->have_heading) return FX_Q16_INT(180);
    b = (s->b_h_ns + abs64(s->h_raw)) / NS_PER_S + 1 + s->cfg.heading_noise_deg;
    return b > FX_Q16_INT(180) ? FX_Q16_INT(180) : b;
}

static void ring_push(struct nav *s)
{
    struct nav_hist *e = &s->ring[s->ring_head];
    e->t_ns = s->t_ns;
    e->e_q32 = s->e_q32;
    e->n_q32 = s->n_q32;
    e->h = s->h;
    e->v_q32 = s->blend.v_q32;
    s->ring_head = (s->ring_head + 1u) % NAV_RING;
    if (s->ring_count < NAV_RING) s->ring_count++;
}

static int32_t q32_to_mm(int64_t x) /* Q32 m -> mm, rounded, saturating */
{
    const int64_t mm = rdiv(rdiv(x, 65536) * 1000, 65536);
    return mm > INT32_MAX ? INT32_MAX : (mm < INT32_MIN ? INT32_MIN : (int32_t)mm);
}

static void fill_out(const struct nav *s, struct nav_out *o)
{
    int64_t bh = heading_bound(s);
    o->t_ns = s->t_ns;
    o->east_mm = q32_to_mm(s->e_q32);
    o->north_mm = q32_to_mm(s->n_q32);
    o->pos_bound_mm = (uint32_t)((s->b_p_q16 * 1000 + 65535) >> 16 > 0xFFFFFFFF
                                     ? 0xFFFFFFFFu
                                     : (uint32_t)((s->b_p_q16 * 1000 + 65535) >> 16));
    o->pos_valid = s->have_ref && s->b_p_q16 <= s->cfg.pos_limit_m;
    o->speed_mps = s->v_q16;
    o->speed_bound_mps = (fx_q16_t)(s->b_v_q16 > INT32_MAX ? INT32_MAX : s->b_v_q16);
    o->speed_valid = s->blend.have_fix && !s->speed_gap && s->b_v_q16 <= s->cfg.speed_limit_mps;
    o->heading_deg = (fx_q16_t)rdiv(s->h, NS_PER_S);
    if (o->heading_deg >= FX_Q16_INT(360)) o->heading_deg -= FX_Q16_INT(360);
    o->heading_bound_deg = (fx_q16_t)bh;
    o->heading_valid = s->have_heading && bh <= s->cfg.heading_limit_deg;
    o->k = s->k;
}

int nav_step(struct nav *s, const struct nav_in *in, struct nav_out *out)
{
    fx_q16_t a, v = 0;
    int64_t bh;
    if (s == NULL || in == NULL) return INC_ERR_NULL;
    if (!s->ready) return INC_ERR_STATE;
    if (in->dt_ns == 0u || in->dt_ns > NAV_MAX_DT_NS) return INC_ERR_RANGE;
    s->t_ns += in->dt_ns;
    a = in->a_comp ? in->a_fwd_g : fx_sub(in->a_fwd_g, s->rest_accel_g);
    if (s->blend.have_fix) {
        int rc = gpsb_step(&s->blend, a, in->dt_ns, &v);
        const int64_t a_err = fx_mul_q16(s->cfg.accel_err_g, GPSB_G0_Q16); /* Q16 m/s^2 */
        const int64_t a_abs = fx_mul_q16(fx_abs(fx_clamp(a, -FX_Q16_INT(16), FX_Q16_INT(16))),
                                         GPSB_G0_Q16);
        int64_t k = s->blend.last_k, bv;
        s->speed_gap = rc == INC_ERR_TIMEOUT;
        s->k = (fx_q30_t)k;
        s->s_q16 = sat_bound(s->s_q16 + per_s(a_abs + a_err, in->dt_ns));
        bv = k * sat_bound(s->b_v_q16 + per_s(a_err, in->dt_ns)) +
             (FX_Q30_ONE - k) * sat_bound((int64_t)s->cfg.speed_bound_mps + s->s_q16);
        s->b_v_q16 = sat_bound((bv + (FX_Q30_ONE - 1)) >> 30); /* rounded up */
    }
    v = fx_clamp(v, -FX_Q16_INT(NAV_V_MAX_MPS), FX_Q16_INT(NAV_V_MAX_MPS));
    s->v_q16 = v;
    bh = heading_bound(s);
    if (s->have_ref) {
        const int64_t av = abs64(v);
        int64_t grow = s->b_v_q16; /* Q16 m/s */
        if (s->have_heading) {
            fx_q30_t sn, cs;
            int64_t ve, vn, ang = bh + s->cfg.slip_deg;
            fx_sincos_deg((fx_q16_t)rdiv(s->h, NS_PER_S), &sn, &cs);
            ve = rdiv((int64_t)v * cs, (int64_t)1 << 30); /* Q16 m/s */
            vn = rdiv((int64_t)v * sn, (int64_t)1 << 30);
            /* Q16 m/s * dt_ns * 2^16 / 1e9 = * 8192 / 125000000: |ve| <= 2^23, dt <= 1e8 */
            s->e_q32 += rdiv(ve * (int64_t)in->dt_ns * 8192, 125000000);
            s->n_q32 += rdiv(vn * (int64_t)in->dt_ns * 8192, 125000000);
            if (ang > FX_Q16_INT(180)) ang = FX_Q16_INT(180);
            grow += (((av * ang) >> 16) * PI_180_Q30 >> 30) + 1;
        } else {
            grow += av; /* no heading: it may have gone anywhere at that speed */
        }
        s->b_p_q16 = sat_bound(s->b_p_q16 + per_s(grow, in->dt_ns) + 1);
        if (s->pend_left > 0u) {
            const int64_t de = s->pend_e_q32 / s->pend_left, dn = s->pend_n_q32 / s->pend_left;
            const int64_t f = (int64_t)s->cfg.gain_pos / s->cfg.spread_cycles; /* Q16 */
            s->e_q32 += de;
            s->n_q32 += dn;
            s->corr_e_q32 += de;
            s->corr_n_q32 += dn;
            s->pend_e_q32 -= de;
            s->pend_n_q32 -= dn;
            s->pend_left--;
            if (s->b_p_q16 > s->cfg.gps_bound_m)
                s->b_p_q16 -= ((s->b_p_q16 - s->cfg.gps_bound_m) * f) >> 16;
        }
    }
    ring_push(s);
    if (out != NULL) fill_out(s, out);
    return INC_OK;
}

void nav_radii_q36(int32_t lat_e7, int64_t *k_n_q36, int64_t *k_e_q36)
{
    const fx_q16_t lat = (fx_q16_t)rdiv((int64_t)lat_e7 * 65536, 10000000);
    fx_q30_t sn, cs;
    int64_t s2, w, rw;
    fx_sincos_deg(lat, &sn, &cs);
    s2 = ((int64_t)sn * sn) >> 30;
    w = FX_Q30_ONE - ((E2_Q30 * s2) >> 30); /* 1 - e^2 sin^2, Q30 in (0.993, 1] */
    rw = fx_sqrt_q30((fx_q30_t)w);
    if (k_e_q36 != NULL) *k_e_q36 = rdiv((int64_t)C_Q36 * cs, rw);
    if (k_n_q36 != NULL) {
        int64_t t = rdiv((int64_t)C1_Q36 << 30, w);
        *k_n_q36 = rdiv(t << 30, rw);
    }
}

int nav_project(const struct nav *s, int32_t lat_e7, int32_t lon_e7, int64_t *e_q32, int64_t *n_q32)
{
    int64_t dlat, dlon;
    if (s == NULL || e_q32 == NULL || n_q32 == NULL) return INC_ERR_NULL;
    if (!s->have_ref) return INC_ERR_STATE;
    dlat = (int64_t)lat_e7 - s->ref_lat_e7;
    dlon = (int64_t)lon_e7 - s->ref_lon_e7;
    if (dlon > 1800000000) dlon -= 3600000000;
    if (dlon < -1800000000) dlon += 3600000000;
    if (abs64(dlat) > NAV_REF_SPAN_E7 || abs64(dlon) > NAV_REF_SPAN_E7) return INC_ERR_RANGE;
    /* |d| <= 5e6, k < 2^30: product < 2^53; Q36 -> Q32 */
    *e_q32 = rdiv(dlon * s->k_e_q36, 16);
    *n_q32 = rdiv(dlat * s->k_n_q36, 16);
    return INC_OK;
}

/* Interpolated history at t; false when t is outside the ring. */
static bool hist_at(const struct nav *s, uint64_t t, struct nav_hist *o)
{
    uint32_t i;
    const struct nav_hist *prev = NULL;
    if (s->ring_count == 0u) return false;
    for (i = 0; i < s->ring_count; i++) {
        const uint32_t idx = (s->ring_head + NAV_RING - s->ring_count + i) % NAV_RING;
        const struct nav_hist *e = &s->ring[idx];
        if (e->t_ns >= t) {
            if (e->t_ns == t || prev == NULL) {
                if (prev == NULL && e->t_ns != t) return false; /* older than the ring */
                *o = *e;
                return true;
            }
            {
                const int64_t span = (int64_t)(e->t_ns - prev->t_ns);
                const int64_t f = (int64_t)(t - prev->t_ns);
                int64_t dh = wrap_pm(e->h - prev->h);
                o->t_ns = t;
                o->e_q32 = prev->e_q32 + rdiv((e->e_q32 - prev->e_q32) * f, span);
                o->n_q32 = prev->n_q32 + rdiv((e->n_q32 - prev->n_q32) * f, span);
                /* |dh| < 2000 deg/s x 0.1 s in Q16 ns (< 2^54): scale f / span first */
                o->h = wrap_h(prev->h + (dh / span) * f + rdiv((dh % span) * f, span));
                o->v_q32 = prev->v_q32 + rdiv((e->v_q32 - prev->v_q32) / 65536 * f, span) * 65536;
                return true;
            }
        }
        prev = e;
    }
    return false; /* newer than the last cycle */
}

static void seat(struct nav *s, int32_t lat_e7, int32_t lon_e7)
{
    s->ref_lat_e7 = lat_e7;
    s->ref_lon_e7 = lon_e7;
    nav_radii_q36(lat_e7, &s->k_n_q36, &s->k_e_q36);
    s->have_ref = true;
    s->e_q32 = s->n_q32 = 0;
    s->pend_e_q32 = s->pend_n_q32 = 0;
    s->pend_left = 0u;
    s->b_p_q16 = s->cfg.gps_bound_m;
    s->ring_count = 0u;
    s->jumps = 0u;
}

static int64_t course_to_h(uint16_t cdeg) /* 90 - course, Q16 deg x ns */
{
    const int64_t c = rdiv((int64_t)cdeg * 65536, 100);
    return wrap_h(((int64_t)FX_Q16_INT(90) - c) * NS_PER_S);
}

static void fix_speed_heading(struct nav *s, const struct nav_fix_in *f, const struct nav_hist *h)
{
    const int64_t a_err = fx_mul_q16(s->cfg.accel_err_g, GPSB_G0_Q16);
    const uint64_t age = s->t_ns - f->t_valid_ns;
    fx_q16_t v_fix = 0;
    if (f->has_speed) {
        /* mm/s -> Q16 m/s; plus the blended change since the fix was valid */
        int64_t v = rdiv((int64_t)f->speed_mmps * 65536, 1000);
        if (h != NULL) v += rdiv(s->blend.v_q32 - h->v_q32, (int64_t)1 << 16);
        v_fix = fx_sat32(v);
        (void)gpsb_fix(&s->blend, v_fix);
        s->v_q16 = v_fix;
        s->b_v_q16 = sat_bound(
            (int64_t)s->cfg.speed_bound_mps +
            per_s(a_err, (uint32_t)(age > NAV_MAX_DT_NS * 4ull ? NAV_MAX_DT_NS : age)));
        s->s_q16 = 0;
        s->speed_gap = false;
    }
    if (f->has_course && f->has_speed && v_fix >= s->cfg.course_min_mps) {
        const int64_t hc = course_to_h(f->course_cdeg);
        /* the course comes from the velocity: its bound scales as 1 / speed */
        const int64_t cb = v_fix > 0
                               ? (int64_t)s->cfg.course_bound_deg * s->cfg.course_min_mps / v_fix
                               : s->cfg.course_bound_deg;
        if (!s->have_heading) {
            s->h = hc;
            s->h_raw = 0;
            s->b_h_ns = cb * NS_PER_S;
            s->have_heading = true;
            s->course_updates++;
        } else if (h != NULL) {
            const int64_t e = wrap_pm(hc - h->h);
            const int64_t gate = (heading_bound(s) + cb) * NS_PER_S;
            if (abs64(e) <= gate) {
                const int64_t g = s->cfg.gain_heading;
                s->h = wrap_h(s->h + (e / 65536) * g);
                s->b_h_ns = s->b_h_ns - ((s->b_h_ns / 65536) * g) + cb * g / 65536 * NS_PER_S;
                s->course_updates++;
            }
        }
    }
}

int nav_fix(struct nav *s, const struct nav_fix_in *f)
{
    int64_t ze, zn, de, dn, innov;
    struct nav_hist h;
    if (s == NULL || f == NULL) return INC_ERR_NULL;
    if (!s->ready) return INC_ERR_STATE;
    if (f->lat_e7 < -900000000 || f->lat_e7 > 900000000 || f->lon_e7 < -1800000000 ||
        f->lon_e7 > 1800000000 || (f->has_course && f->course_cdeg >= 36000u))
        return INC_ERR_INVAL;
    if (!s->have_ref || nav_project(s, f->lat_e7, f->lon_e7, &ze, &zn) != INC_OK) {
        seat(s, f->lat_e7, f->lon_e7);
        fix_speed_heading(s, f, NULL);
        s->fixes++;
        return 1;
    }
    if (f->t_valid_ns > s->t_ns || !hist_at(s, f->t_valid_ns, &h)) {
        s->fixes_refused++;
        return INC_ERR_RANGE;
    }
    de = ze - h.e_q32;
    dn = zn - h.n_q32;
    {
        int64_t a = de / 65536, b = dn / 65536; /* Q16 m */
        const int64_t lim = (int64_t)1 << 31;
        if (a > lim || a < -lim || b > lim || b < -lim)
            innov = NAV_BOUND_MAX_Q16;
        else
            innov = (int64_t)fx_isqrt64((uint64_t)(a * a) + (uint64_t)(b * b));
    }
    if (innov > s->b_p_q16 + s->cfg.gps_bound_m) {
        s->fixes_refused++;
        if (++s->jumps < s->cfg.jump_reset) return INC_ERR_REJECTED;
        /* the receiver keeps saying so: re-seat the track on it */
        s->corr_e_q32 += ze - s->e_q32;
        s->corr_n_q32 += zn - s->n_q32;
        s->e_q32 = ze;
        s->n_q32 = zn;
        s->pend_e_q32 = s->pend_n_q32 = 0;
        s->pend_left = 0u;
        s->b_p_q16 = s->cfg.gps_bound_m;
        s->jumps = 0u;
        s->resets++;
        s->ring_count = 0u;
        fix_speed_heading(s, f, NULL);
        return INC_OK;
    }
    s->jumps = 0u;
    /* gain * innovation, spread over the next cycles (added to what is still pending) */
    s->pend_e_q32 += (de / 65536) * s->cfg.gain_pos + (((de % 65536) * s->cfg.gain_pos) >> 16);
    s->pend_n_q32 += (dn / 65536) * s->cfg.gain_pos + (((dn % 65536) * s->cfg.gain_pos) >> 16);
    s->pend_left = s->cfg.spread_cycles;
    fix_speed_heading(s, f, &h);
    s->fixes++;
    return INC_OK;
}
