/* faultmx.c - the fault matrix of the EPB path (see sim/faultmx.h). */
#include "inclino/sim/faultmx.h"

#include <math.h>
#include <string.h>

#include "inclino/error.h"
#include "inclino/sim/epb_rig_state.h"
#include "inclino/sim/part.h"

static const char *const names[FMX_FAULTS] = {
    "none",       "stuck_output", "frozen",    "bias_acc",   "bias_gyro",  "noise_burst",
    "saturation", "drift",        "miso_high", "miso_low",   "bit_flip",   "corrupt_frame",
    "missed_dr",  "device_error", "wrong_id",  "stuck_bit",  "rec_torn",   "rec_corrupt",
    "rec_offset", "rec_foreign",  "supply",    "temp_stuck", "temp_range", "extra_dr"};

const char *fmx_fault_name(enum fmx_fault f)
{
    return (unsigned)f < (unsigned)FMX_FAULTS ? names[f] : "?";
}

void fmx_capture(const struct epb_rig *r, const struct calrec *rec, struct fmx_setup *s)
{
    memcpy(s->flash, r->flash_mem, sizeof(s->flash));
    s->rec = *rec;
}

/* The slope-axis (x) register of the part and the bit weight of its data. */
static uint8_t slope_reg(const struct epb_rig *r)
{
    return r->info->adis ? 0x0Au : 0x05u; /* ADIS XACCL_OUT; SCA3000 X_MSB (8-bit registers) */
}

/* The station's verification: the unit powered up again with its record, every face measured
 * and checked (app_eol_verify). */
static int eol_verify(struct epb_rig *r, const struct fmx_setup *s, struct fmx_result *out)
{
    const uint32_t n = (uint32_t)(r->info->rate_sps + 0.5);
    const fx_q16_t tol = (fx_q16_t)lround(FMX_EOL_VERIFY_TOL_G * 65536.0);
    int f, err, st = INC_OK;
    err = epb_rig_power_up(r, &s->cfg);
    if (err != INC_OK) {
        return err;
    }
    out->eol_dev_g = 0.0;
    for (f = 0; f < CAL_FACES; f++) {
        struct app_face face;
        fx_q16_t dev = 0;
        int v;
        epb_rig_station(r, f, 25.0);
        epb_rig_wait(r, 0.2);
        err = app_eol_face(&r->app, n, FX_Q16_INT(1) / 20, FX_Q16_INT(2), &face);
        if (err != INC_OK) {
            return err;
        }
        v = app_eol_verify(&r->app, &face, f, tol, &dev);
        if (dev / 65536.0 > out->eol_dev_g) {
            out->eol_dev_g = dev / 65536.0;
        }
        if (v != INC_OK && st == INC_OK) {
            st = v;
        }
    }
    out->eol_status = st;
    return INC_OK;
}

/* The record faults: written into the flash before the power-up. */
static int record_fault(struct epb_rig *r, const struct fmx_setup *s, const struct fmx_case *c)
{
    struct calrec rec = s->rec;
    struct calstore_info info;
    int err;
    switch (c->fault) {
    case FMX_REC_TORN:
        /* the save lost power before its last program units (image tail and commit word) */
        memset(&r->flash_mem[600], CALSTORE_ERASED, 1024u - 600u);
        return INC_OK;
    case FMX_REC_CORRUPT: r->flash_mem[100] ^= 0x10u; return INC_OK;
    case FMX_REC_OFFSET: rec.acc_offset[0] += (int32_t)lround(c->amp * 65536.0); break;
    case FMX_REC_FOREIGN:
        if (r->info->adis) {
            rec.binding.serial = (rec.binding.serial + 1u) & 0xFFFFu;
        } else {
            rec.binding.revision = (rec.binding.revision + 1u) & 0xFFu;
        }
        break;
    default: return INC_OK;
    }
    /* A record with a correct CRC: saved through the firmware's own store. */
    err = epb_rig_power_up(r, &s->cfg);
    if (err != INC_OK) {
        return err;
    }
    err = calstore_save(&r->store, &rec, &info);
    if (err == INC_OK && c->fault == FMX_REC_FOREIGN) {
        err = calstore_save(&r->store, &rec,
                            &info); /* both slots: no older record to fall back on */
    }
    return err;
}

/* A physics or model fault through the part interface (on: inject, else clear). */
static int part_fault(struct sim_part *p, struct epb_rig *r, const struct fmx_case *c, double dt_s,
                      bool on)
{
    struct sim_fault_arg a;
    enum sim_fault f;
    memset(&a, 0, sizeof(a));
    a.channels = SIM_PART_CH(SIM_PART_ACCEL_X);
    switch (c->fault) {
    case FMX_STUCK_OUTPUT:
    case FMX_SATURATION:
        f = SIM_FAULT_SATURATION;
        a.value = c->amp;
        break;
    case FMX_FROZEN:
        f = SIM_FAULT_FROZEN_OUTPUT;
        a.channels = SIM_PART_INERTIAL | SIM_PART_CH(SIM_PART_TEMP);
        break;
    case FMX_BIAS_ACC:
        f = SIM_FAULT_BIAS_JUMP;
        a.value = c->amp;
        break;
    case FMX_DRIFT:
        f = SIM_FAULT_BIAS_JUMP;
        a.value = c->amp * dt_s;
        break;
    case FMX_BIAS_GYRO:
        f = SIM_FAULT_BIAS_JUMP;
        a.channels = SIM_PART_CH(SIM_PART_RATE_Y);
        a.value = c->amp;
        break;
    case FMX_NOISE_BURST:
        f = SIM_FAULT_NOISE_BURST;
        a.channels = SIM_PART_CH(SIM_PART_ACCEL_X) | SIM_PART_CH(SIM_PART_ACCEL_Y) |
                     SIM_PART_CH(SIM_PART_ACCEL_Z);
        a.value = c->amp;
        a.duration_ns = 1000000000ull;
        a.seed = 0x5eedu;
        break;
    case FMX_MISO_HIGH: f = SIM_FAULT_MISO_STUCK_HIGH; break;
    case FMX_MISO_LOW: f = SIM_FAULT_MISO_STUCK_LOW; break;
    case FMX_BIT_FLIP:
        f = SIM_FAULT_CORRUPT_FRAME;
        a.mask = (uint16_t)(1u << (c->bit & 15u));
        break;
    case FMX_CORRUPT_FRAME:
        f = SIM_FAULT_CORRUPT_FRAME;
        a.mask = 0x0101u;
        break;
    case FMX_MISSED_DR: f = SIM_FAULT_NO_DATA_READY; break;
    case FMX_EXTRA_DR: f = SIM_FAULT_EXTRA_DATA_READY; break;
    case FMX_DEVICE_ERROR: f = SIM_FAULT_DEVICE_ERROR; break;
    case FMX_WRONG_ID: f = SIM_FAULT_WRONG_ID; break;
    case FMX_STUCK_BIT:
        f = SIM_FAULT_STUCK_BIT;
        a.addr = slope_reg(r);
        a.bit = c->bit;
        a.level = true;
        break;
    case FMX_SUPPLY:
        f = SIM_FAULT_SATURATION;
        a.channels = SIM_PART_CH(SIM_PART_SUPPLY);
        a.value = c->amp;
        break;
    case FMX_TEMP_STUCK:
    case FMX_TEMP_RANGE:
        f = SIM_FAULT_SATURATION;
        a.channels = SIM_PART_CH(SIM_PART_TEMP);
        a.value = c->amp;
        break;
    default: return INC_OK;
    }
    return on ? sim_part_inject(p, f, &a) : sim_part_clear(p, f);
}

static bool is_record_fault(enum fmx_fault f)
{
    return f == FMX_REC_TORN || f == FMX_REC_CORRUPT || f == FMX_REC_OFFSET || f == FMX_REC_FOREIGN;
}

int fmx_run(const struct fmx_setup *s, const struct fmx_case *c, struct fmx_result *out)
{
    struct epb_rig *r = epb_rig_instance();
    static struct sim_part part;
    struct epb_rig_vehicle veh = s->veh;
    uint64_t samples = 0, reads = 0, onset = 0;
    double t0, t_on = 0.0;
    const uint64_t max_reads = 4ull * s->blocks * s->cfg.avg_n + 100u;
    uint32_t blocks = 0;
    bool injected = false, cleared = false, stepped = false;
    double t_step = 0.0, old_deg = veh.slope_deg;
    const double block_s = (double)s->cfg.avg_n / epb_rig_part_get(s->part)->rate_sps;
    int err;

    memset(out, 0, sizeof(*out));
    out->latency = UINT32_MAX;
    err = epb_rig_init(r, s->part, &s->type, s->seed);
    if (err != INC_OK) {
        return err;
    }
    memcpy(r->flash_mem, s->flash, sizeof(r->flash_mem));
    if (r->info->adis) {
        sim_adis_imu_part(&r->adis, &part);
    } else {
        sim_sca3000_part(&r->sca, &part);
    }
    if (c->fault == FMX_TEMP_STUCK) {
        veh.temp_c = -20.0; /* the car is cold; the sensor keeps reading c->amp */
    }
    out->true_deg = veh.slope_deg;
    err = record_fault(r, s, c);
    if (err == INC_OK && s->eol_verify && (c->fault == FMX_NONE || c->fault == FMX_REC_OFFSET)) {
        err = eol_verify(r, s, out);
    }
    if (err != INC_OK) {
        return err;
    }
    if (out->eol_status != INC_OK) {
        out->detected = true; /* rejected at the end of line: the unit never ships */
        out->latency = 0;
        return INC_OK;
    }
    epb_rig_park(r, &veh);
    epb_rig_wait(r, 1.0);
    if (c->fault == FMX_WRONG_ID) { /* the part came out of a reset as another one */
        out->inject_status = part_fault(&part, r, c, 0.0, true);
        injected = true;
    }
    out->init_status = epb_rig_power_up(r, &s->cfg);
    out->cal_status = r->app.cal_status;
    if (s->temp_ref && out->init_status == INC_OK) {
        /* the ECU's board temperature sensor: the car's temperature */
        app_set_temp_ref(&r->app, (fx_q16_t)lround(veh.temp_c * 65536.0), true);
    }
    if (out->init_status != INC_OK || (out->cal_status != INC_OK && c->fault != FMX_NONE)) {
        out->detected = true; /* refused at the power-up: never a valid estimate */
        out->latency = 0;
        if (out->init_status != INC_OK) {
            return INC_OK;
        }
    }
    if (is_record_fault(c->fault)) {
        injected = true; /* present from the power-up: every estimate counts */
    }
    t0 = epb_rig_now_s(r);
    while (blocks < s->blocks && reads < max_reads) {
        struct sensor_sample smp;
        struct app_result res;
        bool done = false;
        int rerr;
        const double t = epb_rig_now_s(r) - t0;
        if (!injected && t >= c->onset_s) {
            out->inject_status = part_fault(&part, r, c, 0.0, true);
            injected = true;
            onset = samples;
            t_on = t;
        } else if (injected && !cleared && c->fault == FMX_DRIFT) {
            (void)part_fault(&part, r, c, t - t_on, true);
        } else if (injected && !cleared && c->fault == FMX_BIT_FLIP && samples > onset) {
            (void)part_fault(&part, r, c, 0.0, false); /* one read only */
            cleared = true;
        } else if (injected && !cleared && c->fault == FMX_MISSED_DR && t - t_on >= c->amp) {
            (void)part_fault(&part, r, c, 0.0, false);
            cleared = true;
        }
        if (injected && !stepped && c->slope_step_deg != 0.0 && t - t_on >= 1.0) {
            struct epb_rig_vehicle v2 = veh;
            v2.slope_deg += c->slope_step_deg;
            epb_rig_park(r, &v2);
            stepped = true;
            t_step = t;
            out->true_deg = v2.slope_deg;
        }
        if (out->inject_status == INC_ERR_UNSUPPORTED) {
            return INC_OK; /* not modelled for this part */
        }
        rerr = sensor_next(epb_rig_sensor(r), 0u, &smp);
        reads++;
        if (rerr != INC_OK) {
            out->read_errors++;
            if (!out->detected && injected) {
                out->detected = true;
                out->latency = (uint32_t)(samples - onset);
            }
        } else {
            samples++;
        }
        err = app_step(&r->app, &smp, rerr, NULL, &done, &res);
        if (err != INC_OK) {
            return err;
        }
        if (!done) {
            continue;
        }
        blocks++;
        if (!injected) {
            continue; /* ended before the fault */
        }
        {
            const double est = res.slope.slope_deg / 65536.0;
            const double t_end = epb_rig_now_s(r) - t0;
            double e = est - (stepped ? out->true_deg : old_deg);
            if (stepped && t_end - block_s < t_step) { /* the block holds both slopes */
                const double e0 = est - old_deg;
                e = fabs(e0) < fabs(e) ? e0 : e;
            }
            const double b = res.slope.bound_deg / 65536.0;
            out->estimates++;
            out->fault_word |= res.flags | (res.slope.flags << 16);
            if (res.valid) {
                out->valid++;
                if (fabs(e) > b) {
                    out->valid_wrong++;
                }
                if (fabs(e) >= out->max_err_deg) {
                    out->max_err_deg = fabs(e);
                    out->bound_deg = b;
                }
            } else if (!out->detected) {
                out->detected = true; /* for FMX_NONE: a false alarm */
                out->latency = (uint32_t)(samples - onset);
            }
            if (out->bound_deg == 0.0) {
                out->bound_deg = b;
            }
        }
    }
    return INC_OK;
}
