// fault_matrix - inject every fault of the matrix (sim/faultmx.h) into the EPB rig's parked
// measurement, for each part family, and report per case: detected, latency, status and fault
// word, valid-but-wrong estimates (docs/safety.md).
//
// The end of line (six faces at 25 degC, tilt sweep, three-point temperature step) runs once per
// part as in epb_demo; its flash image is the start of every case.
//
// Exit status: 0 when every case is detected or harmless, no estimate is valid-but-wrong and
// every detection is within the stated latency; 1 otherwise; 2 for bad arguments or a set-up
// failure.
extern "C" {
#include "inclino/error.h"
#include "inclino/sim/faultmx.h"
#include "inclino/sim/faultmx_drive.h"
#include "inclino/tool_summary.h"
}
#include "station.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <numeric>
#include <string>
#include <vector>

namespace
{

constexpr double kPi = 3.14159265358979323846;

struct Case {
    enum epb_rig_part part;
    fmx_case c;
};

// Stated detection latency: within the estimate after the one the fault came on in (two blocks
// of avg_n samples from the onset), the power-up itself for the record and identity faults.
uint32_t latency_limit(uint32_t avg_n)
{
    return 2u * avg_n;
}

int eol(enum epb_rig_part part, const sim_calpart_params &type, uint64_t seed, bool baseline,
        fmx_setup &s)
{
    struct epb_rig *rig = epb_rig_instance();
    int err = epb_rig_init(rig, part, &type, seed);
    if (err != INC_OK) return err;
    const epb_rig_part_info *pi = epb_rig_info(rig);
    app_cfg cfg;
    app_cfg_default(&cfg, epb_rig_rate_mhz(rig));
    err = epb_rig_power_up(rig, &cfg);
    if (err != INC_OK) return err;
    const uint32_t n_face = static_cast<uint32_t>(std::lround(pi->rate_sps));
    std::vector<double> temps = {25.0};
    if (pi->temp_lsb_c > 0.0) {
        temps.push_back(60.0);
        temps.push_back(-20.0);
    }
    std::vector<epb::Soak> soaks;
    for (double t : temps) {
        epb::Soak sk;
        sk.chamber_c = sk.temp_c = t;
        for (int f = 0; f < CAL_FACES; f++) {
            epb_rig_station(rig, f, t);
            epb_rig_wait(rig, 0.2);
            err = app_eol_face(epb_rig_app(rig), n_face, FX_Q16_INT(1) / 20, FX_Q16_INT(2),
                               &sk.faces[f]);
            if (err != INC_OK) return err;
        }
        if (pi->temp_lsb_c > 0.0) {
            const double sum = std::accumulate(
                sk.faces.begin(), sk.faces.end(), 0.0,
                [](double acc, const app_face &f) { return acc + f.temp_c / 65536.0; });
            sk.temp_c = sum / CAL_FACES;
        }
        if (soaks.empty()) {
            for (int a = 0; a < 3; a++) {
                for (int step = -4; step <= 4; step++) {
                    const double th = step * 7.5 * kPi / 180.0;
                    epb::SweepPoint sp;
                    sp.dir[a] = std::sin(th);
                    sp.dir[a == 2 ? 0 : 2] = std::cos(th);
                    epb_rig_station_dir(rig, sp.dir.data(), t);
                    epb_rig_wait(rig, 0.2);
                    err = app_eol_face(epb_rig_app(rig), n_face, FX_Q16_INT(1) / 20, FX_Q16_INT(2),
                                       &sp.meas);
                    if (err != INC_OK) return err;
                    sk.sweep.push_back(sp);
                }
            }
        }
        calrec_set_default(&sk.six);
        err = app_eol_six_position(sk.faces.data(), &sk.six);
        if (err != INC_OK) return err;
        soaks.push_back(sk);
    }
    epb::StationOut st;
    if (!epb::station_record(soaks, epb_rig_app(rig)->id, st).empty()) return INC_ERR_INVAL;
    calstore_info info;
    err = app_eol_save(epb_rig_app(rig), &st.rec, epb_rig_store(rig), &info);
    if (err != INC_OK) return err;
    const epb::Budget bud = epb::derive_budget(type, st, pi->acc_lsb_g, pi->temp_lsb_c, n_face,
                                               cfg);
    cfg.budget = bud.b;
    cfg.noise_floor_g = bud.b.noise_sigma_g / APP_QUIET_DIV; // the part's rated noise floor
    s.eol_verify = !baseline;
    s.temp_ref = !baseline;
    if (baseline) { // the diagnostics of the fault matrix off: the figure before them
        cfg.noise_floor_g = 0;
        cfg.budget.offset_drift_g = 0;
        cfg.rec_offset_max_g = 0;
        cfg.rec_gain_tol = 0;
        cfg.rec_misalign_max = 0;
        cfg.temp_step_max_c = 0;
        cfg.temp_ref_tol_c = 0;
    }
    s.part = part;
    s.type = type;
    s.seed = seed;
    s.cfg = cfg;
    fmx_capture(rig, &st.rec, &s);
    return INC_OK;
}

void add(std::vector<Case> &v, enum epb_rig_part p, enum fmx_fault f, double amp, double onset,
         uint8_t bit = 0, double step_deg = 0.0)
{
    Case c;
    c.part = p;
    c.c.fault = f;
    c.c.amp = amp;
    c.c.onset_s = onset;
    c.c.bit = bit;
    c.c.slope_step_deg = step_deg;
    v.push_back(c);
}

// The matrix. full: more amplitudes and onsets (the small-but-harmful region).
std::vector<Case> matrix(bool full)
{
    std::vector<Case> v;
    const enum epb_rig_part parts[] = {EPB_RIG_ADIS16405, EPB_RIG_SCA3000_D01};
    const std::vector<double> onsets = full ? std::vector<double>{3.0, 4.0, 6.3}
                                            : std::vector<double>{4.0};
    for (enum epb_rig_part p : parts) {
        const bool adis = epb_rig_part_get(p)->adis;
        add(v, p, FMX_NONE, 0.0, 4.0);
        for (double on : onsets) {
            add(v, p, FMX_FROZEN, 0.0, on);
            add(v, p, FMX_FROZEN, 0.0, on, 0, -5.7106); // then the car is lifted level
            add(v, p, FMX_STUCK_OUTPUT, 0.0995, on);    // the slope-axis value: plausible
            add(v, p, FMX_STUCK_OUTPUT, 0.0995, on, 0, -5.7106);
            add(v, p, FMX_STUCK_OUTPUT, 0.0, on);
            for (double b : full ? std::vector<double>{0.005, 0.008, 0.010, 0.012, 0.015, 0.020,
                                                       0.030, 0.050, -0.010, -0.020, -0.050}
                                 : std::vector<double>{0.005, 0.010, 0.015, 0.020, 0.050, -0.050})
                add(v, p, FMX_BIAS_ACC, b, on);
            for (double d : full ? std::vector<double>{0.0005, 0.001, 0.002, 0.005, -0.005}
                                 : std::vector<double>{0.001, 0.005})
                add(v, p, FMX_DRIFT, d, on);
            if (adis) add(v, p, FMX_BIAS_GYRO, 2.0, on);
            add(v, p, FMX_NOISE_BURST, 0.05, on);
            add(v, p, FMX_SATURATION, adis ? 20.0 : 4.0, on);
        }
        add(v, p, FMX_MISO_HIGH, 0.0, 4.0);
        add(v, p, FMX_MISO_LOW, 0.0, 4.0);
        for (uint8_t b : {0, 3, 7, 9, 13})
            add(v, p, FMX_BIT_FLIP, 0.0, 4.0, b);
        add(v, p, FMX_CORRUPT_FRAME, 0.0, 4.0);
        add(v, p, FMX_MISSED_DR, 0.1, 4.0);
        add(v, p, FMX_EXTRA_DR, 0.0, 4.0);
        add(v, p, FMX_DEVICE_ERROR, 0.0, 4.0);
        add(v, p, FMX_WRONG_ID, 0.0, 0.0);
        const std::vector<uint8_t> bits = adis ? std::vector<uint8_t>{0, 1, 2, 3, 4, 5, 8, 12}
                                               : std::vector<uint8_t>{0, 1, 2, 3, 5, 7};
        for (uint8_t b : bits)
            add(v, p, FMX_STUCK_BIT, 0.0, 4.0, b);
        add(v, p, FMX_REC_TORN, 0.0, 0.0);
        add(v, p, FMX_REC_CORRUPT, 0.0, 0.0);
        for (double o : full ? std::vector<double>{0.005, 0.010, 0.020, 0.040, -0.040}
                             : std::vector<double>{0.010, 0.040, -0.040})
            add(v, p, FMX_REC_OFFSET, o, 0.0);
        add(v, p, FMX_REC_FOREIGN, 0.0, 0.0);
        add(v, p, FMX_SUPPLY, 4.5, 4.0);
        add(v, p, FMX_SUPPLY, 5.6, 4.0);
        add(v, p, FMX_TEMP_STUCK, 25.0, 4.0);
        add(v, p, FMX_TEMP_STUCK, 25.0, 0.0);
        add(v, p, FMX_TEMP_RANGE, 150.0, 4.0);
        add(v, p, FMX_TEMP_RANGE, -60.0, 4.0);
    }
    return v;
}

// ---- the driving matrix (sim/faultmx_drive.h) ----

struct DScen {
    const char *name;
    double onset_s; // the car is driving at the onset (docs/safety.md)
};

const DScen kScen[] = {{"braking", 16.0},      {"cornering", 20.0},   {"rough_road", 20.0},
                       {"acceleration", 10.0}, {"lane_change", 20.0}, {"banked_slope", 20.0},
                       {"speed_bumps", 12.0},  {"parking", 12.0}};

void dadd(std::vector<fmxd_case> &v, const DScen &sc, enum fmxd_fault f, double amp,
          unsigned axis = 0)
{
    fmxd_case c;
    c.fault = f;
    c.scenario = sc.name;
    c.amp = amp;
    c.onset_s = sc.onset_s;
    c.axis = axis;
    v.push_back(c);
}

std::vector<fmxd_case> dmatrix(bool full)
{
    std::vector<fmxd_case> v;
    const size_t ns = full ? sizeof(kScen) / sizeof(kScen[0]) : 3u;
    for (size_t i = 0; i < ns; i++) {
        const DScen &sc = kScen[i];
        dadd(v, sc, FMXD_NONE, 0.0);
        for (unsigned a : full ? std::vector<unsigned>{0, 1} : std::vector<unsigned>{0}) {
            dadd(v, sc, FMXD_STUCK_ACC, 0.0, a);
            dadd(v, sc, FMXD_STUCK_GYRO, 0.0, 1u - a);
            for (double b : full ? std::vector<double>{0.02, 0.05, -0.05, 0.1}
                                 : std::vector<double>{0.05, -0.05})
                dadd(v, sc, FMXD_BIAS_ACC, b, a);
            for (double b :
                 full ? std::vector<double>{0.5, 1.0, 2.0, -2.0} : std::vector<double>{2.0})
                dadd(v, sc, FMXD_BIAS_GYRO, b, 1u - a);
            dadd(v, sc, FMXD_SATURATION, 0.0, a);
            for (double d :
                 full ? std::vector<double>{0.001, 0.005, -0.005} : std::vector<double>{0.005})
                dadd(v, sc, FMXD_DRIFT_ACC, d, a);
            for (double d : full ? std::vector<double>{0.02, 0.1} : std::vector<double>{0.1})
                dadd(v, sc, FMXD_DRIFT_GYRO, d, 1u - a);
            for (double b :
                 full ? std::vector<double>{0.05, -0.05, 0.03} : std::vector<double>{0.05})
                dadd(v, sc, FMXD_AUX_BIAS, b, a);
        }
        dadd(v, sc, FMXD_FROZEN, 0.0);
        dadd(v, sc, FMXD_NOISE_BURST, 0.05);
        dadd(v, sc, FMXD_SPEED_LOST, 0.0);
        dadd(v, sc, FMXD_SPEED_FROZEN, 0.0);
        dadd(v, sc, FMXD_SPEED_STUCK, 0.0);
        dadd(v, sc, FMXD_READ_ERROR, 0.1);
    }
    return v;
}

// Stated detection latency of the driving matrix: 1 s (820 samples at 819.2 SPS): the
// diagnostics' two-stage low-pass (group delay 0.62 s) and persistence (0.05 s) with the output
// interval, rounded up.
constexpr uint32_t kDriveLatency = 820u;

int run_driving(bool full, bool baseline, bool no_aux, uint64_t seed, FILE *csv)
{
    if (csv != nullptr) {
        std::fprintf(csv, "scenario,fault,amp,onset_s,axis,aux,detected,latency_samples,"
                          "latency_limit,outputs,valid,valid_wrong,read_errors,diag_word,att_word,"
                          "false_diag,max_err_deg,bound_deg,max_veh_ratio,max_xchk_mg,verdict\n");
    }
    fmxd_setup s;
    s.seed = seed;
    s.diagnostics = !baseline;
    s.aux = !no_aux;
    unsigned n = 0, detected = 0, harmless = 0, valid_wrong = 0, vw_outputs = 0, late = 0,
             false_alarms = 0, hd = 0;
    double veh_ratio_ff = 0.0, xchk_ff = 0.0, bound_ff = 0.0;
    unsigned ff_valid = 0, ff_b[3] = {0, 0, 0};
    for (const fmxd_case &c : dmatrix(full)) {
        fmxd_result r;
        const int err = fmxd_run(&s, &c, &r);
        if (err != INC_OK) {
            std::fprintf(stderr, "fault_matrix: driving case %s/%s failed (%s)\n", c.scenario,
                         fmxd_fault_name(c.fault), inc_err_name(err));
            return tool_summary_error(inc_err_name(err), 2);
        }
        n++;
        std::string verdict;
        if (r.valid_wrong > 0) {
            valid_wrong++;
            vw_outputs += r.valid_wrong;
        }
        if (c.fault == FMXD_NONE) {
            if (r.false_diag != 0u) false_alarms++;
            if (r.max_veh_ratio > veh_ratio_ff) veh_ratio_ff = r.max_veh_ratio;
            if (r.max_xchk_g > xchk_ff) xchk_ff = r.max_xchk_g;
            if (r.max_bound_deg > bound_ff) bound_ff = r.max_bound_deg;
            ff_valid += r.valid;
            for (unsigned k = 0; k < 3u; k++)
                ff_b[k] += r.valid_b[k];
            verdict = r.false_diag ? "false-alarm" : (r.valid_wrong ? "VALID-WRONG" : "ok");
        } else if (r.detected && r.latency <= kDriveLatency) {
            detected++;
            verdict = r.valid_wrong ? "VALID-WRONG" : "detected";
        } else if (r.detected && r.valid_wrong == 0) {
            harmless++;
            hd++;
            verdict = "harmless-then-detected";
        } else if (r.detected) {
            late++;
            verdict = "LATE";
        } else {
            if (r.valid_wrong == 0) harmless++;
            verdict = r.valid_wrong ? "VALID-WRONG" : "harmless";
        }
        if (c.fault != FMXD_NONE && r.false_diag != 0u) {
            false_alarms++; // a diagnostic fired before the fault came on
            verdict = "false-alarm";
        }
        if (csv != nullptr) {
            std::fprintf(csv,
                         "%s,%s,%g,%g,%u,%d,%d,%ld,%u,%u,%u,%u,%u,0x%02x,0x%02x,0x%02x,%.4f,"
                         "%.4f,%.3f,%.2f,%s\n",
                         c.scenario, fmxd_fault_name(c.fault), c.amp, c.onset_s, c.axis,
                         s.aux ? 1 : 0, r.detected ? 1 : 0,
                         r.latency == UINT32_MAX ? -1L : static_cast<long>(r.latency),
                         kDriveLatency, r.outputs, r.valid, r.valid_wrong, r.read_errors,
                         r.diag_word, r.att_word, r.false_diag, r.max_err_deg, r.bound_deg,
                         r.max_veh_ratio, r.max_xchk_g * 1e3, verdict.c_str());
        }
        std::printf("%-12s %-12s amp %-6g axis %u %-22s det %d lat %6ld  valid %u/%u wrong %u  "
                    "diag 0x%02x att 0x%02x  max|err| %.3f bound %.3f  veh %.2f xchk %.1f mg\n",
                    c.scenario, fmxd_fault_name(c.fault), c.amp, c.axis, verdict.c_str(),
                    r.detected ? 1 : 0,
                    r.latency == UINT32_MAX ? -1L : static_cast<long>(r.latency), r.valid,
                    r.outputs, r.valid_wrong, r.diag_word, r.att_word, r.max_err_deg, r.bound_deg,
                    r.max_veh_ratio, r.max_xchk_g * 1e3);
    }
    if (csv != nullptr && (std::ferror(csv) != 0 || std::fclose(csv) != 0)) {
        return tool_summary_error("io", 2);
    }
    const bool pass = valid_wrong == 0 && late == 0 && false_alarms == 0;
    tool_summary_add("matrix", "%s", full ? "driving-full" : "driving-short");
    tool_summary_add("diagnostics", "%s", baseline ? "off" : "on");
    tool_summary_add("aux", "%s", no_aux ? "no" : "sca3000");
    tool_summary_add("cases", "%u", n);
    tool_summary_add("detected", "%u", detected);
    tool_summary_add("harmless", "%u", harmless);
    tool_summary_add("harmless_then_detected", "%u", hd);
    tool_summary_add("valid_wrong", "%u", valid_wrong);
    tool_summary_add("valid_wrong_outputs", "%u", vw_outputs);
    tool_summary_add("late", "%u", late);
    tool_summary_add("false_alarms", "%u", false_alarms);
    tool_summary_add("ff_veh_ratio_max", "%.3f", veh_ratio_ff);
    tool_summary_add("ff_xchk_mg_max", "%.2f", xchk_ff * 1e3);
    tool_summary_add("ff_bound_deg_max", "%.3f", bound_ff);
    tool_summary_add("ff_valid", "%u", ff_valid);
    tool_summary_add("ff_bound_le2", "%u", ff_b[0]);
    tool_summary_add("ff_bound_le5", "%u", ff_b[1]);
    tool_summary_add("ff_bound_le10", "%u", ff_b[2]);
    return tool_summary_end(pass ? "ok" : "fail", pass ? 0 : 1);
}

bool unum(const char *s, uint64_t &out)
{
    if (s == nullptr || *s < '0' || *s > '9') return false;
    char *end = nullptr;
    errno = 0;
    out = std::strtoull(s, &end, 10);
    return *end == '\0' && errno == 0;
}

void usage()
{
    std::fprintf(
        stderr, "usage: fault_matrix [--driving [--no-aux]] [--full] [--baseline] [--csv FILE]\n"
                "                    [--seed N] [--blocks N]\n"
                "  --driving    the driving matrix (ESC attitude output on sim/vehicle scenarios)\n"
                "               instead of the parked one; --no-aux: no SCA3000 beside the IMU\n"
                "  --full       every amplitude and onset (default: the short matrix of CI)\n"
                "  --baseline   the matrix's diagnostics off (noise floor, offset-change term and\n"
                "               check, record plausibility, end-of-line verification)\n"
                "  --csv FILE   one row per case\n"
                "  --seed N     noise and vibration seed (default 1)\n"
                "  --blocks N   estimates per case, 2..100 (default 5: 12.5 s parked)\n");
}

} // namespace

int main(int argc, char **argv)
{
    tool_summary_begin("fault_matrix");
    bool full = false, baseline = false, driving = false, no_aux = false;
    std::string csv_path;
    uint64_t seed = 1, blocks = 5;
    for (int i = 1; i < argc; i++) {
        const std::string a = argv[i];
        const char *v = i + 1 < argc ? argv[i + 1] : nullptr;
        bool ok = true;
        if (a == "--full")
            full = true;
        else if (a == "--driving")
            driving = true;
        else if (a == "--no-aux")
            no_aux = true;
        else if (a == "--baseline")
            baseline = true;
        else if (a == "--csv") {
            ok = v != nullptr && *v != '\0';
            if (ok) csv_path = v;
            i++;
        } else if (a == "--seed") {
            ok = unum(v, seed);
            i++;
        } else if (a == "--blocks") {
            ok = unum(v, blocks) && blocks >= 2 && blocks <= 100;
            i++;
        } else if (a == "-h" || a == "--help") {
            usage();
            return 0;
        } else
            ok = false;
        if (!ok) {
            std::fprintf(stderr, "fault_matrix: bad or missing value for '%s'\n", a.c_str());
            usage();
            return tool_summary_error("usage", 2);
        }
    }
    FILE *csv = nullptr;
    if (!csv_path.empty()) {
        csv = std::fopen(csv_path.c_str(), "w");
        if (csv == nullptr) {
            std::fprintf(stderr, "fault_matrix: cannot write %s\n", csv_path.c_str());
            return tool_summary_error("io", 2);
        }
    }
    if (driving) return run_driving(full, baseline, no_aux, seed, csv);
    if (csv != nullptr) {
        std::fprintf(
            csv,
            "part,fault,amp,onset_s,bit,slope_step_deg,modelled,init,cal,detected,latency_samples,"
            "latency_limit,estimates,valid,valid_wrong,read_errors,fault_word,"
            "max_err_deg,bound_deg,eol_verify,eol_dev_mg,verdict\n");
    }
    const std::vector<Case> cases = matrix(full);
    fmx_setup setups[EPB_RIG_PARTS];
    bool have[EPB_RIG_PARTS] = {};
    sim_calpart_params type;
    sim_calpart_paper(&type);
    unsigned n = 0, detected = 0, harmless = 0, valid_wrong = 0, late = 0, unmodelled = 0,
             refused = 0, false_alarms = 0, vw_estimates = 0, eol_false = 0;
    for (const Case &k : cases) {
        if (!have[k.part]) {
            const int err = eol(k.part, type, seed, baseline, setups[k.part]);
            if (err != INC_OK) {
                std::fprintf(stderr, "fault_matrix: end of line failed (%s)\n", inc_err_name(err));
                return tool_summary_error(inc_err_name(err), 2);
            }
            epb_rig_vehicle_default(&setups[k.part].veh);
            setups[k.part].blocks = static_cast<uint32_t>(blocks);
            have[k.part] = true;
        }
        const fmx_setup &s = setups[k.part];
        fmx_result r;
        const int err = fmx_run(&s, &k.c, &r);
        if (err != INC_OK) {
            std::fprintf(stderr, "fault_matrix: case %s failed (%s)\n", fmx_fault_name(k.c.fault),
                         inc_err_name(err));
            return tool_summary_error(inc_err_name(err), 2);
        }
        const bool modelled = r.inject_status != INC_ERR_UNSUPPORTED;
        const uint32_t lim = latency_limit(s.cfg.avg_n);
        std::string verdict;
        if (!modelled) {
            verdict = "not-modelled";
            unmodelled++;
        } else {
            n++;
            if (r.valid_wrong > 0) {
                valid_wrong++;
                vw_estimates += r.valid_wrong;
            }
            if (k.c.fault == FMX_NONE) {
                if (r.eol_status != INC_OK) eol_false++;
                if (r.detected) false_alarms++;
                verdict = r.detected ? "false-alarm" : (r.valid_wrong ? "VALID-WRONG" : "ok");
            } else if (r.detected && r.latency <= lim) {
                detected++;
                if (r.latency == 0 &&
                    (r.init_status != 0 || r.cal_status != 0 || r.eol_status != 0))
                    refused++;
                verdict = r.valid_wrong ? "VALID-WRONG" : "detected";
            } else if (r.detected && r.valid_wrong == 0) {
                // detected after the stated latency, but no estimate was wrong before: harmless
                // until detected (a slow drift inside the offset-change term)
                harmless++;
                verdict = "harmless-then-detected";
            } else if (r.detected) {
                late++;
                verdict = "LATE";
            } else {
                if (r.valid_wrong == 0) harmless++;
                verdict = r.valid_wrong ? "VALID-WRONG" : "harmless";
            }
        }
        const char *pname = epb_rig_part_get(k.part)->name;
        if (csv != nullptr) {
            std::fprintf(
                csv,
                "%s,%s,%g,%g,%u,%g,%d,%s,%s,%d,%ld,%u,%u,%u,%u,%u,0x%06x,%.4f,%.4f,%s,%.3f,%s\n",
                pname, fmx_fault_name(k.c.fault), k.c.amp, k.c.onset_s, k.c.bit, k.c.slope_step_deg,
                modelled ? 1 : 0, inc_err_name(r.init_status), inc_err_name(r.cal_status),
                r.detected ? 1 : 0, r.latency == UINT32_MAX ? -1L : static_cast<long>(r.latency),
                lim, r.estimates, r.valid, r.valid_wrong, r.read_errors, r.fault_word,
                r.max_err_deg, r.bound_deg, inc_err_name(r.eol_status), r.eol_dev_g * 1e3,
                verdict.c_str());
        }
        std::printf(
            "%-11s %-13s amp %-7g onset %-4g bit %-2u step %-7g %-12s det %d lat %6ld  valid %u/%u "
            "wrong %u  word 0x%06x  max|err| %.3f bound %.3f\n",
            pname, fmx_fault_name(k.c.fault), k.c.amp, k.c.onset_s, k.c.bit, k.c.slope_step_deg,
            verdict.c_str(), r.detected ? 1 : 0,
            r.latency == UINT32_MAX ? -1L : static_cast<long>(r.latency), r.valid, r.estimates,
            r.valid_wrong, r.fault_word, r.max_err_deg, r.bound_deg);
    }
    if (csv != nullptr && (std::ferror(csv) != 0 || std::fclose(csv) != 0)) {
        std::fprintf(stderr, "fault_matrix: write error %s\n", csv_path.c_str());
        return tool_summary_error("io", 2);
    }
    const bool pass = valid_wrong == 0 && late == 0 && false_alarms == 0 && eol_false == 0;
    tool_summary_add("matrix", "%s", full ? "full" : "short");
    tool_summary_add("diagnostics", "%s", baseline ? "off" : "on");
    tool_summary_add("cases", "%u", n);
    tool_summary_add("detected", "%u", detected);
    tool_summary_add("refused", "%u", refused);
    tool_summary_add("harmless", "%u", harmless);
    tool_summary_add("valid_wrong", "%u", valid_wrong);
    tool_summary_add("valid_wrong_estimates", "%u", vw_estimates);
    tool_summary_add("late", "%u", late);
    tool_summary_add("false_alarms", "%u", false_alarms);
    tool_summary_add("not_modelled", "%u", unmodelled);
    tool_summary_add("eol_false_rejects", "%u", eol_false);
    return tool_summary_end(pass ? "ok" : "fail", pass ? 0 : 1);
}
