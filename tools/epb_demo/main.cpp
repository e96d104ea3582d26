// epb_demo - the README's main command: the EPB application end to end on the simulated board,
// through the real drivers and the pin-level part models (docs/epb-demo.md).
//
//  1. End of line: the station turns the part through its six faces (25 degC, then optionally a
//     hot and a cold soak) and, at 25 degC, through a tilt sweep of each axis within +-30 deg;
//     the firmware averages each position and computes offset, gain and gyro offset on the
//     device; the station adds the cross-axis matrix, the nonlinearity cubics and [ADI-EPB]'s
//     three-point temperature models; the firmware stores the record in the simulated flash
//     (calstore).
//  2. The part goes into a car parked on a slope, engine idling.
//  3. Power cycle: a fresh application instance loads the record, bound to the part, and gives
//     its slope estimates with their error bounds, next to the true slope.
//
// Exit status: 0 when the last estimate is valid, the true slope lies within its bound (and
// within the bound of every other valid estimate) and the part saw no timing violation; 1
// otherwise; 2 for bad arguments or a set-up failure.
extern "C" {
#include "inclino/error.h"
#include "inclino/tool_summary.h"
}
#include "station.hpp"

extern "C" {
#include "inclino/sim/epb_rig.h"
#include "inclino/sim/vcd.h"
}

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace
{

constexpr double kQ16 = 65536.0, kQ30 = 1073741824.0;
constexpr double kPi = 3.14159265358979323846;
// The tilt sweep: every 7.5 deg from -30 to +30 deg ([ADI-EPB]'s road slopes) on each axis.
constexpr int kSweepSteps = 4;
constexpr double kSweepStepDeg = 7.5;

struct Options {
    double grade_pct = 10.0;
    bool slope_given = false;
    double slope_deg = 0.0;
    double roll_deg = 0.0;
    double temp_c = 25.0;
    std::string part = "adis16405";
    uint64_t part_seed = 0; // 0: part "A" (sim_calpart_paper)
    uint64_t seed = 1;
    double length_s = 7.5;
    double block_s = 0.0; // 0: app_cfg_default's 2.5 s
    double face_s = 1.0;
    bool tcal = true;
    bool sweep = true; // nonlinearity tilt sweep at the ambient soak
    bool eol = true;
    bool engine = true;
    bool bumps = true;
    double drive_off_s = -1.0;
    double t_cold = -20.0, t_hot = 60.0;
    std::string csv, est_csv, vcd, record_out;
    double vcd_ms = 10.0;
    std::string board; // "" / "sim": the simulated board; "s32k144": through the S32K1 port
    std::string spi = "bitbang";
};

void usage()
{
    std::fprintf(
        stderr,
        "usage: epb_demo [options]\n"
        "  --grade PCT         road grade in %% (default 10)\n"
        "  --slope-deg DEG     road slope in degrees instead of --grade\n"
        "  --roll-deg DEG      cross slope (default 0)\n"
        "  --temp C            temperature of the parked car, degC (default 25)\n"
        "  --board NAME        sim (default) or s32k144: the firmware runs through the S32K1 port\n"
        "                      (hal/port/s32k1) against its register models (docs/boards.md)\n"
        "  --spi NAME          with --board s32k144: bitbang (default) or lpspi\n"
        "  --part NAME         adis16405 (default), adis16400, adis16364, adis16362, sca3000-d01,\n"
        "                      sca3000-e02\n"
        "  --part-seed N       errors of a part drawn from seed N (default 0: part A, [ADI-EPB]/[TEMP-LORENTZ])\n"
        "  --seed N            noise and vibration seed (default 1)\n"
        "  --length S          parked scenario length, s (default 7.5: three 2.5 s estimates)\n"
        "  --block-s S         samples averaged per estimate, s (default 2.5; whole stillness windows)\n"
        "  --face-s S          end of line: seconds averaged per face (default 1)\n"
        "  --no-tcal           end of line at 25 degC only (no three-point temperature step)\n"
        "  --no-sweep          no tilt sweep: the nonlinearity stays uncorrected ([ADI-EPB]'s way)\n"
        "  --tcal-temps C,H    cold and hot soak temperatures (default -20,60)\n"
        "  --no-eol            skip the end of line: the flash stays empty (not calibrated)\n"
        "  --no-engine         engine off;  --no-bumps  no random bumps\n"
        "  --drive-off S       the car drives off S seconds into the scenario\n"
        "  --csv FILE          samples (time, gyro x y z deg/s, accel x y z g, temp) as imu_replay reads\n"
        "  --est-csv FILE      one row per estimate\n"
        "  --record-out FILE   the calibration record image written to flash (656 bytes)\n"
        "  --vcd FILE          the SPI bus and data-ready pins, the first --vcd-ms ms of the estimates\n"
        "  --vcd-ms MS         length of the VCD window (default 10; a full run would be gigabytes)\n");
}

bool num(const char *s, double &out)
{
    if (s == nullptr || *s == '\0') return false;
    char *end = nullptr;
    out = std::strtod(s, &end);
    return *end == '\0' && std::isfinite(out);
}

bool unum(const char *s, uint64_t &out)
{
    if (s == nullptr || *s == '\0' || *s == '-') return false;
    char *end = nullptr;
    out = std::strtoull(s, &end, 10);
    return *end == '\0';
}

bool parse(int argc, char **argv, Options &o)
{
    for (int i = 1; i < argc; i++) {
        const std::string a = argv[i];
        const char *v = i + 1 < argc ? argv[i + 1] : nullptr;
        auto take = [&](double &d) {
            i++;
            return num(v, d);
        };
        bool ok = true;
        if (a == "--grade")
            ok = take(o.grade_pct);
        else if (a == "--slope-deg") {
            ok = take(o.slope_deg);
            o.slope_given = true;
        } else if (a == "--roll-deg")
            ok = take(o.roll_deg);
        else if (a == "--temp")
            ok = take(o.temp_c);
        else if (a == "--board") {
            i++;
            ok = v != nullptr;
            if (ok) o.board = v;
        } else if (a == "--spi") {
            i++;
            ok = v != nullptr;
            if (ok) o.spi = v;
        } else if (a == "--part") {
            i++;
            ok = v != nullptr;
            if (ok) o.part = v;
        } else if (a == "--part-seed") {
            i++;
            ok = unum(v, o.part_seed);
        } else if (a == "--seed") {
            i++;
            ok = unum(v, o.seed);
        } else if (a == "--length")
            ok = take(o.length_s) && o.length_s > 0.0 && o.length_s <= 3600.0;
        else if (a == "--block-s")
            ok = take(o.block_s) && o.block_s >= 0.1 && o.block_s <= 600.0;
        else if (a == "--face-s")
            ok = take(o.face_s) && o.face_s >= 0.05 && o.face_s <= 600.0;
        else if (a == "--no-tcal")
            o.tcal = false;
        else if (a == "--no-sweep")
            o.sweep = false;
        else if (a == "--tcal-temps") {
            i++;
            ok = v != nullptr && std::sscanf(v, "%lf,%lf", &o.t_cold, &o.t_hot) == 2 &&
                 o.t_cold < 24.0 && o.t_hot > 26.0 && o.t_cold >= -100.0 && o.t_hot <= 200.0;
        } else if (a == "--no-eol")
            o.eol = false;
        else if (a == "--no-engine")
            o.engine = false;
        else if (a == "--no-bumps")
            o.bumps = false;
        else if (a == "--drive-off")
            ok = take(o.drive_off_s) && o.drive_off_s >= 0.0;
        else if (a == "--csv") {
            i++;
            ok = v != nullptr;
            if (ok) o.csv = v;
        } else if (a == "--est-csv") {
            i++;
            ok = v != nullptr;
            if (ok) o.est_csv = v;
        } else if (a == "--record-out") {
            i++;
            ok = v != nullptr;
            if (ok) o.record_out = v;
        } else if (a == "--vcd") {
            i++;
            ok = v != nullptr;
            if (ok) o.vcd = v;
        } else if (a == "--vcd-ms")
            ok = take(o.vcd_ms) && o.vcd_ms > 0.0 && o.vcd_ms <= 10000.0;
        else if (a == "-h" || a == "--help") {
            usage();
            std::exit(0);
        } else
            ok = false;
        if (!ok) {
            std::fprintf(stderr, "epb_demo: bad or missing value for '%s'\n", a.c_str());
            return false;
        }
    }
    if (!(std::fabs(o.grade_pct) <= 200.0) || !(std::fabs(o.slope_deg) <= 60.0) ||
        !(std::fabs(o.roll_deg) <= 30.0) || !(o.temp_c >= -40.0 && o.temp_c <= 125.0)) {
        std::fprintf(
            stderr,
            "epb_demo: slope within +-60 deg (+-200 %%), roll within +-30 deg, temperature -40..125 degC\n");
        return false;
    }
    return true;
}

double q16(int32_t v)
{
    return v / kQ16;
}

std::string slope_flag_names(uint32_t f)
{
    static const char *const names[] = {"not-still", "not-calibrated", "out-of-range", "magnitude",
                                        "bound"};
    std::string s;
    for (int i = 0; i < 5; i++) {
        if (f & (1u << i)) s += (s.empty() ? "" : ",") + std::string(names[i]);
    }
    return s;
}

std::string app_flag_names(uint32_t f)
{
    static const char *const names[] = {"not-calibrated", "temp-uncompensated", "sensor-errors",
                                        "saturated", "not-still"};
    std::string s;
    for (int i = 0; i < 5; i++) {
        if (f & (1u << i)) s += (s.empty() ? "" : ",") + std::string(names[i]);
    }
    return s;
}

const char *cal_status_text(int st)
{
    switch (st) {
    case INC_OK: return "loaded and bound to this part";
    case INC_ERR_NOT_CALIBRATED: return "not calibrated (flash erased: no record)";
    case INC_ERR_CRC: return "not calibrated (no intact record: torn or corrupt)";
    case INC_ERR_VERSION: return "not calibrated (record version not supported)";
    case INC_ERR_MISMATCH: return "not calibrated (record bound to another sensor)";
    case INC_ERR_RANGE: return "not calibrated (record out of range)";
    case INC_ERR_IO: return "not calibrated (flash error)";
    default: return "not calibrated";
    }
}

} // namespace

int main(int argc, char **argv)
{
    Options o;
    tool_summary_begin("epb_demo");
    if (!parse(argc, argv, o)) {
        usage();
        return tool_summary_error("usage", 2);
    }
    enum epb_rig_part part;
    if (epb_rig_part_from_name(o.part.c_str(), &part) != INC_OK) {
        std::fprintf(stderr, "epb_demo: unknown part '%s'\n", o.part.c_str());
        tool_summary_add("part", "%s", o.part.c_str());
        usage();
        return tool_summary_error("unknown-part", 2);
    }
    const auto wall0 = std::chrono::steady_clock::now();
    struct epb_rig *const rig = epb_rig_instance();
    sim_calpart_params type;
    if (o.part_seed == 0)
        sim_calpart_paper(&type);
    else
        sim_calpart_seeded(&type, o.part_seed);
    int err = epb_rig_init(rig, part, &type, o.seed);
    if (err != INC_OK) {
        std::fprintf(stderr, "epb_demo: rig set-up failed (%s)\n", inc_err_name(err));
        return tool_summary_error(inc_err_name(err), 2);
    }
    if (!o.board.empty()) {
        tool_summary_add("board", "%s", o.board.c_str());
        tool_summary_add("spi", "%s", o.spi.c_str());
        if (o.board == "s32k144" && o.spi == "bitbang") {
            err = epb_rig_set_board(rig, EPB_RIG_BOARD_S32K144);
        } else if (o.board == "s32k144" && o.spi == "lpspi") {
            err = epb_rig_set_board_spi(rig, EPB_RIG_BOARD_S32K144, true);
        } else if (o.board == "sim" && o.spi == "bitbang") {
            err = epb_rig_set_board(rig, EPB_RIG_BOARD_SIM);
        } else {
            std::fprintf(stderr, "epb_demo: unknown --board/--spi '%s'/'%s'\n", o.board.c_str(),
                         o.spi.c_str());
            usage();
            return tool_summary_error("usage", 2);
        }
        if (err != INC_OK) {
            std::fprintf(stderr, "epb_demo: board set-up failed (%s)\n", inc_err_name(err));
            return tool_summary_error(inc_err_name(err), 2);
        }
    }
    const epb_rig_part_info *pi = epb_rig_info(rig);
    tool_summary_add("part", "%s", pi->name);
    tool_summary_add("eol", "%d", o.eol ? 1 : 0);
    struct app_cfg cfg;
    app_cfg_default(&cfg, epb_rig_rate_mhz(rig));
    if (o.block_s > 0.0) {
        const double w = std::floor(o.block_s * epb_rig_info(rig)->rate_sps / cfg.still.window +
                                    0.5);
        cfg.avg_n = static_cast<uint32_t>(std::max(1.0, w)) * cfg.still.window;
    }
    const uint32_t n_face = static_cast<uint32_t>(std::lround(o.face_s * pi->rate_sps));

    std::printf(
        "Inclino EPB demo: %s (pin-level model, %.1f SPS, accel LSB %.3f mg), errors of %s, seed %llu\n",
        pi->name, pi->rate_sps, pi->acc_lsb_g * 1e3,
        o.part_seed == 0 ? "part A ([ADI-EPB]/[TEMP-LORENTZ])" : "a seeded part",
        (unsigned long long)o.seed);
    if (o.part_seed != 0) std::printf("  part seed %llu\n", (unsigned long long)o.part_seed);

    // ---- 1. End of line ------------------------------------------------------------------
    err = epb_rig_power_up(rig, &cfg);
    if (err != INC_OK) {
        std::fprintf(stderr, "epb_demo: firmware start failed (%s)\n", inc_err_name(err));
        return tool_summary_error(inc_err_name(err), 2);
    }
    epb::StationOut st;
    size_t sweep_points = 0;
    if (o.eol) {
        std::printf(
            "\nEnd of line: six faces per soak%s, %u samples each (%.1f s), firmware on-device flip\n",
            o.sweep ? " and a tilt sweep at 25 degC" : "", n_face, o.face_s);
        std::vector<double> temps = {25.0};
        if (o.tcal && pi->temp_lsb_c <= 0.0) {
            std::printf("  (the %s has no temperature output: no temperature step)\n", pi->name);
        } else if (o.tcal) {
            temps.push_back(o.t_hot);
            temps.push_back(o.t_cold);
        }
        std::vector<epb::Soak> soaks;
        for (double t : temps) {
            epb::Soak s;
            s.chamber_c = s.temp_c = t;
            for (int f = 0; f < CAL_FACES; f++) {
                epb_rig_station(rig, f, t);
                epb_rig_wait(rig, 0.2); // the turn settles
                err = app_eol_face(epb_rig_app(rig), n_face, FX_Q16_INT(1) / 20, FX_Q16_INT(2),
                                   &s.faces[f]);
                if (err != INC_OK) {
                    std::fprintf(stderr, "epb_demo: face %d at %.1f degC failed (%s)\n", f, t,
                                 inc_err_name(err));
                    return tool_summary_error(inc_err_name(err), 2);
                }
            }
            if (pi->temp_lsb_c > 0.0) { // the part's own reading, as the firmware will see it
                double sum = 0.0;
                for (const app_face &f : s.faces)
                    sum += q16(f.temp_c);
                s.temp_c = sum / CAL_FACES;
            }
            if (o.sweep && soaks.empty()) { // the tilt table, at the ambient soak only
                for (int a = 0; a < 3; a++) {
                    for (int step = -kSweepSteps; step <= kSweepSteps; step++) {
                        const double th = step * kSweepStepDeg * kPi / 180.0;
                        epb::SweepPoint sp;
                        sp.dir[a] = std::sin(th);
                        sp.dir[a == 2 ? 0 : 2] = std::cos(th);
                        epb_rig_station_dir(rig, sp.dir.data(), t);
                        epb_rig_wait(rig, 0.2);
                        err = app_eol_face(epb_rig_app(rig), n_face, FX_Q16_INT(1) / 20,
                                           FX_Q16_INT(2), &sp.meas);
                        if (err != INC_OK) {
                            std::fprintf(stderr,
                                         "epb_demo: sweep point %d of axis %d failed (%s)\n", step,
                                         a, inc_err_name(err));
                            return tool_summary_error(inc_err_name(err), 2);
                        }
                        s.sweep.push_back(sp);
                    }
                }
            }
            calrec_set_default(&s.six);
            err = app_eol_six_position(s.faces.data(), &s.six);
            if (err != INC_OK) {
                std::fprintf(stderr, "epb_demo: six-position at %.1f degC failed (%s)\n", t,
                             inc_err_name(err));
                return tool_summary_error(inc_err_name(err), 2);
            }
            std::printf(
                "  %6.1f degC (part reads %6.2f)  offset [mg] %+8.3f %+8.3f %+8.3f   gain %.5f %.5f %.5f",
                t, s.temp_c, q16(s.six.acc_offset[0]) * 1e3, q16(s.six.acc_offset[1]) * 1e3,
                q16(s.six.acc_offset[2]) * 1e3, s.six.acc_gain[0] / kQ30, s.six.acc_gain[1] / kQ30,
                s.six.acc_gain[2] / kQ30);
            if (pi->gyro_lsb_dps > 0.0) {
                std::printf("   gyro offset [deg/s] %+.3f %+.3f %+.3f", q16(s.six.gyro_offset[0]),
                            q16(s.six.gyro_offset[1]), q16(s.six.gyro_offset[2]));
            }
            std::printf("\n");
            if (soaks.empty()) sweep_points = s.sweep.size();
            soaks.push_back(s);
        }
        const std::string serr = epb::station_record(soaks, epb_rig_app(rig)->id, st);
        if (!serr.empty()) {
            std::fprintf(stderr, "epb_demo: station: %s\n", serr.c_str());
            return tool_summary_error("station", 2);
        }
        std::printf(
            "  station: cross-axis matrix from the 25 degC faces (off-diagonal up to %.2f mrad)",
            [&] {
                double m = 0;
                for (int i = 0; i < 3; i++)
                    for (int j = 0; j < 3; j++)
                        if (i != j) m = std::fmax(m, std::fabs(st.misalign[i][j]));
                return m * 1e3;
            }());
        if (st.nonlin) {
            std::printf(
                ";\n           nonlinearity cubics from the faces and a %zu-point tilt sweep (fit rms %.3f %.3f %.3f mg)",
                soaks[0].sweep.size(), st.nl_rms[0] * 1e3, st.nl_rms[1] * 1e3, st.nl_rms[2] * 1e3);
        }
        if (st.tcal)
            std::printf(
                ";\n           [ADI-EPB] three-point models of offset and gain (%.2f/%.2f/%.2f degC as read)",
                st.t_cold, st.t_amb, st.t_hot);
        std::printf("\n");
        calstore_info info;
        err = app_eol_save(epb_rig_app(rig), &st.rec, epb_rig_store(rig), &info);
        if (err != INC_OK) {
            std::fprintf(stderr, "epb_demo: calstore_save failed (%s)\n", inc_err_name(err));
            return tool_summary_error(inc_err_name(err), 2);
        }
        std::printf(
            "  record: %u bytes, sequence %u, saved by calstore to slot %d of the simulated flash, bound to "
            "family %u product %u revision %u serial %u\n",
            CALREC_IMAGE_SIZE, info.seq, info.used_slot, st.rec.binding.family,
            st.rec.binding.product, st.rec.binding.revision, st.rec.binding.serial);
        if (!o.record_out.empty()) {
            uint8_t img[CALREC_IMAGE_SIZE];
            FILE *f = std::fopen(o.record_out.c_str(), "wb");
            if (f == nullptr || calrec_encode(&st.rec, info.seq, img, sizeof img) != INC_OK ||
                std::fwrite(img, 1, sizeof img, f) != sizeof img || std::fclose(f) != 0) {
                std::fprintf(stderr, "epb_demo: cannot write %s\n", o.record_out.c_str());
                return tool_summary_error("io", 2);
            }
        }
    } else {
        std::printf("\nEnd of line skipped (--no-eol): the simulated flash stays erased\n");
        st.tcal = false;
        calrec_set_default(&st.rec);
    }

    // The part type's residuals become the application's budget (docs/epb-demo.md).
    const epb::Budget bud = epb::derive_budget(type, st, pi->acc_lsb_g, pi->temp_lsb_c, n_face,
                                               cfg);
    cfg.budget = bud.b;

    // ---- 2. The part goes into the car, which parks on the slope --------------------------
    struct epb_rig_vehicle veh;
    epb_rig_vehicle_default(&veh);
    veh.slope_deg = o.slope_given ? o.slope_deg : std::atan(o.grade_pct / 100.0) * 180.0 / kPi;
    veh.roll_deg = o.roll_deg;
    veh.temp_c = o.temp_c;
    if (!o.engine) veh.idle_rpm = 0.0;
    if (!o.bumps) veh.bump_rate_hz = 0.0;
    veh.drive_off_s = o.drive_off_s;
    const double true_deg = veh.slope_deg;
    const double true_pct = 100.0 * std::tan(true_deg * kPi / 180.0);
    epb_rig_park(rig, &veh);
    epb_rig_wait(rig, 1.0); // the ECU wakes up a second after the car has come to rest
    std::printf(
        "\nParked: %.2f %% grade (%.3f deg), cross slope %.2f deg, %.1f degC, %s, %s%s\n", true_pct,
        true_deg, o.roll_deg, o.temp_c, o.engine ? "engine idling at 750 rpm" : "engine off",
        o.bumps ? "random bumps (0.3/s)" : "no bumps",
        o.drive_off_s >= 0.0
            ? (", drives off at " + std::to_string(o.drive_off_s).substr(0, 4) + " s").c_str()
            : "");

    // ---- 3. Power cycle: the ECU starts in the parked car ------------------------------------
    err = epb_rig_power_up(rig, &cfg);
    if (err != INC_OK) {
        std::fprintf(stderr, "epb_demo: firmware start after the power cycle failed (%s)\n",
                     inc_err_name(err));
        return tool_summary_error(inc_err_name(err), 2);
    }
    std::printf("\nPower cycle: fresh application instance, calibration %s\n",
                cal_status_text(epb_rig_app(rig)->cal_status));
    tool_summary_add("calibration", "%s", inc_err_name(epb_rig_app(rig)->cal_status));
    tool_summary_add("calibrated", "%d", app_calibrated(epb_rig_app(rig)) ? 1 : 0);

    FILE *csv = nullptr, *est = nullptr;
    if (!o.csv.empty()) {
        csv = std::fopen(o.csv.c_str(), "w");
        if (csv == nullptr) {
            std::fprintf(stderr, "epb_demo: cannot write %s\n", o.csv.c_str());
            return tool_summary_error("io", 2);
        }
        std::fprintf(
            csv,
            "# epb_demo %s, %.3f deg slope, %.1f degC, seed %llu: raw samples (nominal scale)\n",
            pi->name, true_deg, o.temp_c, (unsigned long long)o.seed);
        std::fprintf(csv,
                     "time_s,gyro_x_dps,gyro_y_dps,gyro_z_dps,accel_x_g,accel_y_g,accel_z_g%s\n",
                     pi->temp_lsb_c > 0.0 ? ",temp_c" : "");
    }
    if (!o.est_csv.empty()) {
        est = std::fopen(o.est_csv.c_str(), "w");
        if (est == nullptr) {
            std::fprintf(stderr, "epb_demo: cannot write %s\n", o.est_csv.c_str());
            return tool_summary_error("io", 2);
        }
        std::fprintf(
            est,
            "block,time_s,slope_deg,grade_pct,bound_deg,bound_pct,valid,slope_flags,app_flags,true_deg,"
            "error_deg,within,accel_x_g,accel_y_g,accel_z_g,temp_c,sigma_meas_g,noise_g,accel_bound_g,n\n");
    }
    static struct sim_vcd vcd;
    bool vcd_open = false;
    const double vcd_t0 = epb_rig_now_s(rig);
    if (!o.vcd.empty()) {
        if (epb_rig_vcd_open(rig, &vcd, o.vcd.c_str()) != INC_OK) {
            std::fprintf(stderr, "epb_demo: cannot write %s\n", o.vcd.c_str());
            return tool_summary_error("io", 2);
        }
        vcd_open = true;
    }

    const uint32_t blocks = std::max<uint32_t>(
        1u, static_cast<uint32_t>(o.length_s * pi->rate_sps / cfg.avg_n));
    std::printf("  %u estimates of %u samples (%.2f s each)\n", blocks, cfg.avg_n,
                cfg.avg_n / pi->rate_sps);
    std::printf("  %5s %7s %10s %9s %9s %8s %9s %7s  %s\n", "block", "t [s]", "slope[deg]",
                "grade[%]", "+-[deg]", "+-[%]", "err[deg]", "inside", "status");
    std::vector<app_result> results;
    bool all_valid_inside = true;
    uint32_t reads = 0;
    while (results.size() < blocks) {
        sensor_sample s;
        app_corrected c;
        app_result r;
        bool done = false;
        const int rerr = sensor_next(epb_rig_sensor(rig), 0u, &s);
        reads++;
        err = app_step(epb_rig_app(rig), &s, rerr, &c, &done, &r);
        if (err != INC_OK) {
            std::fprintf(stderr, "epb_demo: app_step failed (%s)\n", inc_err_name(err));
            return tool_summary_error(inc_err_name(err), 2);
        }
        if (rerr == INC_OK && csv != nullptr) {
            std::fprintf(csv, "%.9f,%.7f,%.7f,%.7f,%.7f,%.7f,%.7f", s.t_ns * 1e-9,
                         q16(s.gyro_dps[0]), q16(s.gyro_dps[1]), q16(s.gyro_dps[2]),
                         q16(s.accel_g[0]), q16(s.accel_g[1]), q16(s.accel_g[2]));
            if (pi->temp_lsb_c > 0.0) std::fprintf(csv, ",%.7f", q16(s.temp_c));
            std::fprintf(csv, "\n");
        }
        if (vcd_open && (epb_rig_now_s(rig) - vcd_t0) * 1e3 >= o.vcd_ms) {
            sim_vcd_close(&vcd);
            vcd_open = false;
        }
        if (reads > 4u * blocks * cfg.avg_n + 100u) {
            std::fprintf(stderr, "epb_demo: the sensor does not deliver samples (last error %s)\n",
                         inc_err_name(rerr));
            return tool_summary_error("no-samples", 2);
        }
        if (!done) continue;
        results.push_back(r);
        const double e = q16(r.slope.slope_deg) - true_deg;
        const bool inside = std::fabs(e) <= q16(r.slope.bound_deg);
        if (r.valid && !inside) all_valid_inside = false;
        std::string why = r.valid ? "valid" : "NOT VALID";
        const std::string sf = slope_flag_names(r.slope.flags),
                          af = app_flag_names(r.flags & ~APP_F_TEMP_UNCOMP);
        if (!sf.empty()) why += " " + sf;
        if (!af.empty() && !r.valid) why += " [" + af + "]";
        if (r.flags & APP_F_TEMP_UNCOMP) why += " (temperature not compensated)";
        std::printf("  %5zu %7.2f %10.4f %9.3f %9.4f %8.3f %+9.4f %7s  %s\n", results.size(),
                    epb_rig_scenario_s(rig), q16(r.slope.slope_deg), q16(r.slope.grade_pct),
                    q16(r.slope.bound_deg), q16(r.slope.bound_pct), e, inside ? "yes" : "NO",
                    why.c_str());
        if (est != nullptr) {
            std::fprintf(
                est,
                "%zu,%.6f,%.6f,%.6f,%.6f,%.6f,%d,%u,%u,%.6f,%.6f,%d,%.7f,%.7f,%.7f,%.4f,%.7f,%.7f,%.7f,%u\n",
                results.size(), epb_rig_scenario_s(rig), q16(r.slope.slope_deg),
                q16(r.slope.grade_pct), q16(r.slope.bound_deg), q16(r.slope.bound_pct),
                r.valid ? 1 : 0, r.slope.flags, r.flags, true_deg, e, inside ? 1 : 0,
                q16(r.accel_g[0]), q16(r.accel_g[1]), q16(r.accel_g[2]), q16(r.temp_c),
                q16(r.sigma_meas_g), q16(r.slope.noise_g), q16(r.slope.accel_bound_g), r.n);
        }
    }
    if (vcd_open) sim_vcd_close(&vcd);
    if (csv != nullptr && std::fclose(csv) != 0) {
        std::fprintf(stderr, "epb_demo: write error %s\n", o.csv.c_str());
        return tool_summary_error("io", 2);
    }
    if (est != nullptr && std::fclose(est) != 0) {
        std::fprintf(stderr, "epb_demo: write error %s\n", o.est_csv.c_str());
        return tool_summary_error("io", 2);
    }

    // ---- Report ------------------------------------------------------------------------------
    const app_result &r = results.back();
    const slope_budget &b = r.budget;
    std::printf(
        "\nError budget of the last estimate ([ADI-EPB] Table 1, worst case per axis; e_a on the slope axis):\n");
    const double sens_g = std::fabs(q16(r.accel_g[cfg.slope.slope_axis])) * b.sensitivity / kQ30;
    std::printf("  %-13s %8.3f mg  (%.4f %% of |A| = %.4f g)  %s\n", "sensitivity", sens_g * 1e3,
                b.sensitivity / kQ30 * 100.0, std::fabs(q16(r.accel_g[cfg.slope.slope_axis])),
                app_calibrated(epb_rig_app(rig)) ? bud.terms[0].origin.c_str()
                                                 : "uncalibrated: [ADI-EPB] before calibration");
    std::printf("  %-13s %8.3f mg  %s\n", "offset", q16(b.offset_g) * 1e3,
                app_calibrated(epb_rig_app(rig)) ? bud.terms[1].origin.c_str()
                                                 : "uncalibrated: [ADI-EPB] before calibration");
    std::printf("  %-13s %8.3f mg  %s\n", "nonlinearity", q16(b.nonlinearity_g) * 1e3,
                bud.terms[2].origin.c_str());
    std::printf("  %-13s %8.3f mg  %s\n", "temperature", q16(b.temperature_g) * 1e3,
                (r.flags & APP_F_TEMP_UNCOMP) ? "not compensated here: [ADI-EPB]'s 50 mg"
                                              : bud.terms[3].origin.c_str());
    std::printf(
        "  %-13s %8.3f mg  k %.2f x sigma %.3f mg / sqrt(%u); sigma = max(rated %.3f, measured %.3f) mg\n",
        "noise", q16(r.slope.noise_g) * 1e3, q16(b.k_sigma), q16(b.noise_sigma_g) * 1e3, r.n,
        q16(cfg.budget.noise_sigma_g) * 1e3, q16(r.sigma_meas_g) * 1e3);
    std::printf("  %-13s %8.3f mg  -> bound %.4f deg (exact for the box A +- e_a, slope.h)\n",
                "e_a", q16(r.slope.accel_bound_g) * 1e3, q16(r.slope.bound_deg));

    const double e = q16(r.slope.slope_deg) - true_deg;
    const bool inside = std::fabs(e) <= q16(r.slope.bound_deg);
    const unsigned viol = epb_rig_violations(rig);
    std::printf(
        "\nResult: slope %.4f deg = %.3f %% grade, bound +-%.4f deg (+-%.3f %%); true %.4f deg = %.3f %%; error %+.4f deg\n",
        q16(r.slope.slope_deg), q16(r.slope.grade_pct), q16(r.slope.bound_deg),
        q16(r.slope.bound_pct), true_deg, true_pct, e);
    std::printf("        %s, true slope %s the bound%s\n", r.valid ? "VALID" : "NOT VALID",
                inside ? "within" : "OUTSIDE",
                app_calibrated(epb_rig_app(rig)) ? "" : "; NOT CALIBRATED");
    if (!r.valid) {
        std::printf("        flags: slope [%s] application [%s]\n",
                    slope_flag_names(r.slope.flags).c_str(), app_flag_names(r.flags).c_str());
    }
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    std::printf(
        "Bus: %u timing/protocol violations; %u samples read in the parked phase; %.1f s simulated in %.2f s wall\n",
        viol, reads, epb_rig_now_s(rig), wall);
    epb_rig_print_violations(rig, stdout);
    const bool pass = r.valid && inside && viol == 0u && all_valid_inside;
    std::printf("%s\n", pass ? "PASS" : "FAIL");
    const std::string sfl = slope_flag_names(r.slope.flags), afl = app_flag_names(r.flags);
    tool_summary_add("sweep_points", "%zu", sweep_points);
    tool_summary_add("nonlinearity", "%s", st.nonlin ? "corrected" : "uncorrected");
    tool_summary_add("tcal", "%d", st.tcal ? 1 : 0);
    tool_summary_add("estimates", "%zu", results.size());
    tool_summary_add("slope_deg", "%.4f", q16(r.slope.slope_deg));
    tool_summary_add("grade_pct", "%.3f", q16(r.slope.grade_pct));
    tool_summary_add("bound_deg", "%.4f", q16(r.slope.bound_deg));
    tool_summary_add("bound_pct", "%.3f", q16(r.slope.bound_pct));
    tool_summary_add("true_deg", "%.4f", true_deg);
    tool_summary_add("true_pct", "%.3f", true_pct);
    tool_summary_add("error_deg", "%+.4f", e);
    tool_summary_add("valid", "%d", r.valid ? 1 : 0);
    tool_summary_add("inside", "%d", inside ? 1 : 0);
    tool_summary_add("all_valid_inside", "%d", all_valid_inside ? 1 : 0);
    tool_summary_add("slope_flags", "%s", sfl.empty() ? "none" : sfl.c_str());
    tool_summary_add("app_flags", "%s", afl.empty() ? "none" : afl.c_str());
    tool_summary_add("budget_sensitivity_mg", "%.3f", sens_g * 1e3);
    tool_summary_add("budget_offset_mg", "%.3f", q16(b.offset_g) * 1e3);
    tool_summary_add("budget_nonlinearity_mg", "%.3f", q16(b.nonlinearity_g) * 1e3);
    tool_summary_add("budget_temperature_mg", "%.3f", q16(b.temperature_g) * 1e3);
    tool_summary_add("budget_noise_mg", "%.3f", q16(r.slope.noise_g) * 1e3);
    tool_summary_add("accel_bound_mg", "%.3f", q16(r.slope.accel_bound_g) * 1e3);
    tool_summary_add("violations", "%u", viol);
    tool_summary_add("reads", "%u", reads);
    tool_summary_add("verdict", "%s", pass ? "PASS" : "FAIL");
    return tool_summary_end(pass ? "ok" : "fail", pass ? 0 : 1);
}
