// calstation - the calibration-station tool (docs/calibration.md).
//
//   calstation simulate [--part A|<seed>] [--schedule calibration|validation|ambient]
//                       [--cycles N] [--samples N] [--noise-seed N] [--binding F,P,R,S,L1,L2]
//                       --out FILE.csv
//   calstation fit FILE.csv [--tmodel best|none|linear|parabola|lorentz|pwl|lorentz-cubic]
//                  [--out RECORD.bin] [--seq N]
//   calstation show RECORD.bin
//   calstation dflash RECORD.bin --out FILE [--format srec|ihex]
//   calstation compare [--cycles N] [--seeds S1,S2,...]   (part A plus seeded parts; default 2)
//
// Exit status: 0 success, 1 bad input (message on stderr, nothing written), 2 usage error.
// The last line on stdout is the summary (docs/tool-summary.md): a refusal gives
// error=<inc_err name> problem=<slug> [line=N] [column=NAME] [coefficient=NAME].
#include "inclino/error.h"
#include "inclino/tool_summary.h"
#include "inclino/calstation/compare.hpp"
#include "inclino/calstation/dflash.hpp"
#include "inclino/calstation/fit.hpp"
#include "inclino/calstation/record.hpp"
#include "inclino/calstation/samples.hpp"
#include "inclino/calstation/station.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <exception>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

using namespace calstation;

namespace
{

int usage()
{
    std::fputs(
        "usage:\n"
        "  calstation simulate [--part A|<seed>] [--schedule calibration|validation|ambient]\n"
        "                      [--cycles N] [--samples N] [--noise-seed N] [--binding F,P,R,S,L1,L2]\n"
        "                      --out FILE.csv\n"
        "  calstation fit FILE.csv [--tmodel best|none|linear|parabola|lorentz|pwl|lorentz-cubic]\n"
        "                 [--out RECORD.bin] [--seq N]\n"
        "  calstation show RECORD.bin\n"
        "  calstation dflash RECORD.bin --out FILE [--format srec|ihex]\n"
        "  calstation compare [--cycles N] [--seeds S1,S2,...]\n",
        stderr);
    tool_summary_add("error", "usage");
    return 2;
}

// The summary keys of a refusal: the library reports its problems as text, which is sorted
// here into an error code and a short problem name (the message itself stays on stderr).
struct Problem {
    const char *needle, *code, *slug;
};
const Problem kProblems[] = {
    {"empty station file", "ERR_FORMAT", "empty-file"},
    {"empty sample file", "ERR_FORMAT", "empty-file"},
    {"placeholder temperature", "ERR_INVAL", "placeholder-temperature"},
    {"no acceleration column", "ERR_FORMAT", "no-acc-column"},
    {"no still face", "ERR_DEGENERATE", "no-faces"},
    {"a directory", "ERR_IO", "cannot-open"},
    {"no column header", "ERR_FORMAT", "no-header"},
    {"no measurement rows", "ERR_FORMAT", "no-rows"},
    {"missing setting", "ERR_FORMAT", "missing-setting"},
    {"is not a finite number", "ERR_FORMAT", "not-finite"},
    {" fields, expected", "ERR_FORMAT", "field-count"},
    {"cannot open", "ERR_IO", "cannot-open"},
    {"cannot write", "ERR_IO", "cannot-write"},
    {"too few measurements", "ERR_DEGENERATE", "too-few"},
    {"at the same position", "ERR_DEGENERATE", "same-position"},
    {"+1 g and -1 g swapped", "ERR_DEGENERATE", "swapped"},
    {"one temperature only", "ERR_DEGENERATE", "one-temperature"},
    {"degenerate data", "ERR_DEGENERATE", "degenerate"},
    {"coefficient out of range", "ERR_RANGE", "coefficient-range"},
    {"no binding", "ERR_INVAL", "no-binding"},
    {"binding out of range", "ERR_RANGE", "binding-range"},
    {"not a calibration record", "ERR_FORMAT", "not-a-record"},
    {"calrec_decode refused", "ERR_CRC", "record-refused"},
};

int refuse(const std::string &msg, const char *fallback_code, const char *fallback_slug)
{
    const char *code = fallback_code, *slug = fallback_slug;
    for (const Problem &p : kProblems) {
        if (msg.find(p.needle) != std::string::npos) {
            code = p.code;
            slug = p.slug;
            break;
        }
    }
    // An inc_err name in the message ("(ERR_CRC)") is the code itself.
    const size_t en = msg.find("(ERR_");
    if (en != std::string::npos) {
        const size_t close = msg.find(')', en);
        if (close != std::string::npos) {
            tool_summary_add("error", "%s", msg.substr(en + 1, close - en - 1).c_str());
            code = nullptr;
        }
    }
    if (code != nullptr) tool_summary_add("error", "%s", code);
    tool_summary_add("problem", "%s", slug);
    const size_t ln = msg.find("line ");
    if (ln != std::string::npos) {
        const long v = std::strtol(msg.c_str() + ln + 5, nullptr, 10);
        if (v > 0) tool_summary_add("line", "%ld", v);
    }
    const size_t col = msg.find("column '");
    if (col != std::string::npos) {
        const size_t end = msg.find('\'', col + 8);
        if (end != std::string::npos)
            tool_summary_add("column", "%s", msg.substr(col + 8, end - col - 8).c_str());
    }
    const size_t co = msg.find("coefficient out of range: ");
    if (co != std::string::npos) {
        const size_t b = co + 26, end = msg.find(' ', b);
        tool_summary_add("coefficient", "%s",
                         msg.substr(b, end == std::string::npos ? end : end - b).c_str());
    }
    return 1;
}

// Strict decimal: digits only, no sign, no leading zero ("010" is refused: octal or decimal?),
// no overflow, within [lo, hi]. With hex_ok also 0x... (the binding words are chip ids).
bool parse_uint(const char *s, uint64_t lo, uint64_t hi, uint64_t &v, bool hex_ok = false)
{
    if (s == nullptr || *s == '\0') return false;
    int base = 10;
    const char *p = s;
    if (hex_ok && p[0] == '0' && (p[1] == 'x' || p[1] == 'X') && p[2] != '\0') {
        base = 16;
        p += 2;
    } else if (p[0] == '0' && p[1] != '\0') {
        return false;
    }
    uint64_t r = 0;
    for (; *p; p++) {
        unsigned d;
        if (*p >= '0' && *p <= '9')
            d = static_cast<unsigned>(*p - '0');
        else if (base == 16 && *p >= 'a' && *p <= 'f')
            d = static_cast<unsigned>(*p - 'a' + 10);
        else if (base == 16 && *p >= 'A' && *p <= 'F')
            d = static_cast<unsigned>(*p - 'A' + 10);
        else
            return false;
        if (r > (UINT64_MAX - d) / static_cast<uint64_t>(base)) return false;
        r = r * static_cast<uint64_t>(base) + d;
    }
    if (r < lo || r > hi) return false;
    v = r;
    return true;
}

// A finite decimal number taking the whole argument, within [lo, hi].
bool parse_real(const char *s, double lo, double hi, double &v)
{
    if (s == nullptr || *s == '\0') return false;
    char *end = nullptr;
    errno = 0;
    const double r = std::strtod(s, &end);
    if (*end != '\0' || errno == ERANGE || !std::isfinite(r) || r < lo || r > hi) return false;
    v = r;
    return true;
}

int bad_arg(const char *opt, const char *val, const char *want)
{
    std::fprintf(stderr, "calstation: %s '%s': expected %s\n", opt, val ? val : "", want);
    tool_summary_add("error", "usage");
    tool_summary_add("problem", "bad-argument");
    tool_summary_add("option", "%s", opt[0] == '-' && opt[1] == '-' ? opt + 2 : opt);
    return 2;
}

// family,product,revision,serial,lot_id1,lot_id2 or "generic" (family 4, product 1).
bool parse_binding(const std::string &b, std::array<uint32_t, 6> &out)
{
    if (b == "generic") {
        out = {CALREC_FAMILY_GENERIC, 1u, 0u, 0u, 0u, 0u};
        return true;
    }
    size_t pos = 0;
    for (int k = 0; k < 6; k++) {
        const size_t c = b.find(',', pos);
        if ((k < 5) != (c != std::string::npos)) return false;
        const std::string tok = b.substr(pos, c == std::string::npos ? std::string::npos : c - pos);
        uint64_t v = 0;
        if (!parse_uint(tok.c_str(), 0, 0xFFFFFFFFull, v, true)) return false;
        out[k] = static_cast<uint32_t>(v);
        pos = c + 1;
    }
    return true;
}

int write_refused(const std::string &e)
{
    std::fprintf(stderr, "calstation: %s\n", e.c_str());
    tool_summary_add("error", "ERR_IO");
    tool_summary_add("problem", "cannot-write");
    return 1;
}

// Units of the acceleration: g, or m/s^2 with the value of 1 g.
struct Units {
    bool ms2 = false;
    bool given = false; // --units on the command line (else a sample CSV's unit is detected)
    double g = calstation::kStandardGravity;
    double per_g() const
    {
        return ms2 ? g : 1.0;
    }
    const char *name() const
    {
        return ms2 ? "m/s2" : "g";
    }
};

// --units / --g; returns 0 when not one of them, 1 when taken (i advanced), or a usage status.
int units_option(int argc, char **argv, int &i, Units &u, int &status)
{
    const std::string a = argv[i];
    if (a != "--units" && a != "--g") return 0;
    if (i + 1 >= argc) {
        status = bad_arg(argv[i], "", "a value");
        return -1;
    }
    const char *val = argv[++i];
    if (a == "--units") {
        const std::string v = val;
        u.given = true;
        if (v == "g")
            u.ms2 = false;
        else if (v == "m/s2" || v == "m/s^2" || v == "ms2" || v == "mps2")
            u.ms2 = true;
        else {
            status = bad_arg("--units", val, "g or m/s2");
            return -1;
        }
    } else if (!parse_real(val, 9.7, 9.9, u.g)) {
        status = bad_arg("--g", val, "the value of 1 g in m/s^2, 9.7..9.9 (default 9.80665)");
        return -1;
    }
    return 1;
}

int cmd_simulate(int argc, char **argv)
{
    SimConfig cfg;
    std::string out;
    Units units;
    bool samples = false, with_temp = true;
    for (int i = 0; i < argc; i++) {
        const std::string a = argv[i];
        uint64_t v = 0;
        int ust = 0;
        const int uo = units_option(argc, argv, i, units, ust);
        if (uo < 0) return ust;
        if (uo > 0) continue;
        if (i + 1 >= argc) return bad_arg(argv[i], "", "a value");
        const char *val = argv[++i];
        if (a == "--part") {
            if (std::strcmp(val, "A") == 0) {
                cfg.part.paper = true;
            } else if (parse_uint(val, 0, UINT64_MAX, v)) {
                cfg.part.paper = false;
                cfg.part.curve_seed = v;
            } else {
                return bad_arg("--part", val, "A or a seed 0..2^64-1 (decimal)");
            }
        } else if (a == "--schedule") {
            const std::string s = val;
            if (s == "calibration")
                cfg.schedule = Schedule::Calibration;
            else if (s == "validation")
                cfg.schedule = Schedule::Validation;
            else if (s == "ambient")
                cfg.schedule = Schedule::Ambient;
            else if (s == "hand")
                cfg.schedule = Schedule::Hand;
            else
                return bad_arg("--schedule", val, "calibration, validation, ambient or hand");
        } else if (a == "--cycles") {
            if (!parse_uint(val, 1, 100, v)) return bad_arg("--cycles", val, "1..100 (decimal)");
            cfg.cycles = static_cast<int>(v);
        } else if (a == "--samples") {
            if (!parse_uint(val, 1, 1000000, v)) return bad_arg("--samples", val, "1..1000000");
            cfg.samples = static_cast<int>(v);
        } else if (a == "--noise-seed") {
            if (!parse_uint(val, 0, UINT64_MAX, v))
                return bad_arg("--noise-seed", val, "0..2^64-1 (decimal)");
            cfg.noise_seed = v;
        } else if (a == "--placement-seed") {
            if (!parse_uint(val, 0, UINT64_MAX, v))
                return bad_arg("--placement-seed", val, "0..2^64-1 (decimal)");
            cfg.placement_seed = v;
        } else if (a == "--placement-deg") {
            if (!parse_real(val, 0.0, 10.0, cfg.placement_deg))
                return bad_arg("--placement-deg", val, "0..10 degrees");
        } else if (a == "--nonortho-deg") {
            if (!parse_real(val, -5.0, 5.0, cfg.nonortho_deg))
                return bad_arg("--nonortho-deg", val, "-5..5 degrees");
        } else if (a == "--out") {
            out = val;
        } else if (a == "--format") {
            const std::string f = val;
            if (f == "station")
                samples = false;
            else if (f == "samples")
                samples = true;
            else if (f == "samples-notemp")
                samples = true, with_temp = false;
            else
                return bad_arg("--format", val, "station, samples or samples-notemp");
        } else if (a == "--rate") {
            if (!parse_real(val, 1.0, 100000.0, cfg.rate_sps))
                return bad_arg("--rate", val, "1..100000 samples/s");
        } else if (a == "--binding") {
            if (!parse_binding(val, cfg.binding))
                return bad_arg("--binding", val, "generic or six integers F,P,R,S,L1,L2");
            cfg.have_binding = true;
        } else {
            return usage();
        }
    }
    if (out.empty()) return usage();
    cfg.keep_samples = samples;
    if (samples && cfg.schedule != Schedule::Hand && cfg.schedule != Schedule::Ambient)
        return bad_arg("--format", "samples", "--schedule hand or ambient with samples");
    const Station st = simulate_station(cfg);
    const std::string e = write_output(
        out, samples ? format_samples(st, units.per_g(), with_temp) : format_station(st), {});
    if (!e.empty()) return write_refused(e);
    if (samples)
        std::printf("wrote %s: %zu samples (%s)\n", out.c_str(), st.samples.size(), units.name());
    else
        std::printf("wrote %s: %zu rows\n", out.c_str(), st.rows.size());
    tool_summary_add("rows", "%zu", st.rows.size());
    if (samples) tool_summary_add("samples", "%zu", st.samples.size());
    return 0;
}

// The coefficients of a result in physical units (fit and show print the same block).
void print_coefficients(const CalResult &c, bool gyro_known, bool gyro_scale_known)
{
    static const char *const ax[3] = {"x", "y", "z"};
    for (int a = 0; a < 3; a++) {
        std::printf("acc %s: offset %+.6f g  gain %.7f  M row % .7f % .7f % .7f  nonlin c0..c3 "
                    "% .6f % .6f % .6f % .6f\n",
                    ax[a], c.acc_offset[a], c.acc_gain[a], c.acc_misalign[a][0],
                    c.acc_misalign[a][1], c.acc_misalign[a][2], c.acc_nonlin[a][0],
                    c.acc_nonlin[a][1], c.acc_nonlin[a][2], c.acc_nonlin[a][3]);
        for (int q = 0; q < 2; q++) {
            const TModel &m = q ? c.acc_tscale[a] : c.acc_tbias[a];
            std::printf("      %s: %s", q ? "tscale" : "tbias ", tkind_name(m.kind));
            if (m.kind != TKind::None && m.kind != TKind::Lorentz)
                std::printf(" t_ref %.3f t_span %.3f", m.t_ref, m.t_span);
            if (m.kind == TKind::Pwl) std::printf(" n %d", m.n);
            if (m.params() > 0) std::printf(" p");
            for (int k = 0; k < m.params(); k++)
                std::printf(" %.7g", m.p[k]);
            std::printf("\n");
        }
    }
    if (!gyro_known) {
        std::printf("gyro: not calibrated (offset 0, scale 1: the identity)\n");
    } else {
        std::printf("gyro: offset %+.5f %+.5f %+.5f deg/s, scale %.7f %.7f %.7f%s\n",
                    c.gyro_offset[0], c.gyro_offset[1], c.gyro_offset[2], c.gyro_scale[0],
                    c.gyro_scale[1], c.gyro_scale[2],
                    gyro_scale_known ? "" : " (scale not calibrated: no turns)");
    }
}

// Without --units, a sample CSV whose median |a| is 8.5..11 (it reads about 9.8 at rest) is in
// m/s^2: no accelerometer in g reads 9.8 g at rest. Re-parsed then, and said.
std::string detect_units(const std::string &text, Units &u, SampleFile &sf, bool &detected)
{
    detected = false;
    if (u.given || sf.acc_g.empty()) return "";
    std::vector<double> m(sf.acc_g.size());
    std::transform(sf.acc_g.begin(), sf.acc_g.end(), m.begin(), [](const std::array<double, 3> &a) {
        return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    });
    std::nth_element(m.begin(), m.begin() + static_cast<long>(m.size() / 2), m.end());
    const double med = m[m.size() / 2];
    if (!(med >= 8.5 && med <= 11.0)) return "";
    u.ms2 = true;
    detected = true;
    return parse_samples(text, u.per_g(), sf);
}

// The input of fit and apply: a station file or a sample CSV, in g or m/s^2.
struct Input {
    bool samples = false;
    bool units_detected = false;
    Station st;
    SampleFile sf;
    std::vector<Segment> seg;
    size_t skipped = 0;
};

std::string load_input(const std::string &path, Units &u, double t_ref, bool t_ref_set,
                       size_t window, Input &in)
{
    std::string text;
    std::string e = read_input(path, size_t(1) << 30, text);
    if (!e.empty()) return e;
    if (is_station_text(text)) {
        e = parse_station(text, in.st);
        if (!e.empty()) return path + ": " + e;
        if (u.ms2) in.st.acc_lsb_g /= u.g;
        if (t_ref_set) in.st.t_ref_c = t_ref;
        return "";
    }
    in.samples = true;
    e = parse_samples(text, u.per_g(), in.sf);
    if (e.empty()) e = detect_units(text, u, in.sf, in.units_detected);
    if (!e.empty()) return path + ": " + e;
    in.seg = find_segments(in.sf, window);
    e = station_from_segments(in.sf, in.seg, t_ref, in.st, in.skipped);
    return e.empty() ? e : path + ": " + e;
}

std::string faces_csv(const CalResult &c, const FwCheck &fw)
{
    std::string o =
        "# calstation fit --faces-csv: | |a| - 1 g | per static row (position mean), mg\n"
        "row,line,block,temp_c,ux,uy,uz,raw_mg,pair_mg,nominal_mg,magnitude_mg,"
        "chosen_mg,angle_deg,firmware_mg\n";
    char b[400];
    for (size_t k = 0; k < c.rows.size(); k++) {
        const RowResidual &r = c.rows[k];
        std::snprintf(b, sizeof b,
                      "%zu,%d,%ld,%.4f,%.6f,%.6f,%.6f,%.5f,%.5f,%.5f,%.5f,%.5f,%.4f,%.5f\n", k + 1,
                      r.line, r.block, r.temp_c, r.u[0], r.u[1], r.u[2], r.raw_mg, r.pair_mg,
                      r.nominal_mg, r.magnitude_mg, r.chosen_mg, r.angle_deg,
                      k < fw.row_mag_mg.size() ? fw.row_mag_mg[k] : 0.0);
        o += b;
    }
    return o;
}

// The temperature data (per block flip) and every model's curve, for the plot.
std::string tfits_csv(const CalResult &c)
{
    std::string o = "# calstation fit --tcsv: per block flip (source=data) and each model's curve\n"
                    "# bias_mg: B(T) in mg; scale_ppm: (K(T) - K(t_ref)) / K(t_ref) in ppm\n"
                    "source,axis,temp_c,bias_mg,scale_ppm\n";
    char b[200];
    static const char *const ax[3] = {"x", "y", "z"};
    for (int a = 0; a < 3; a++) {
        const double kref = c.acc_gain[a];
        for (const auto &bl : c.blocks) {
            if (!bl.have[a]) continue;
            std::snprintf(b, sizeof b, "data,%s,%.4f,%.5f,%.4f\n", ax[a], bl.t, bl.bias[a] * 1e3,
                          (bl.scale[a] / kref - 1.0) * 1e6);
            o += b;
        }
        if (c.soaks.size() < 2) continue;
        double lo = 1e300, hi = -1e300;
        for (const auto &bl : c.blocks) {
            lo = std::min(lo, bl.t);
            hi = std::max(hi, bl.t);
        }
        for (int k = 0; k < TemperatureFits::kKinds; k++) {
            const TFit &fb = c.tfits.bias[k][a], &fs = c.tfits.scale[k][a];
            if (!fb.ok || !fs.ok) continue;
            for (int i = 0; i <= 200; i++) {
                const double t = lo + (hi - lo) * i / 200.0;
                std::snprintf(b, sizeof b, "%s,%s,%.4f,%.5f,%.4f\n", TemperatureFits::name(k),
                              ax[a], t, fb.model.eval(t) * 1e3,
                              (fs.model.eval(t) / kref - 1.0) * 1e6);
                o += b;
            }
        }
    }
    return o;
}

int cmd_fit(int argc, char **argv)
{
    std::string in, out, faces_out, t_out;
    FitOptions opt;
    opt.tmodel_auto = true;
    Units units;
    uint64_t seq = 1, window = 0;
    double t_ref = 25.0;
    bool t_ref_set = false, have_binding = false;
    std::array<uint32_t, 6> binding{};
    for (int i = 0; i < argc; i++) {
        const std::string a = argv[i];
        int st = 0;
        const int uo = units_option(argc, argv, i, units, st);
        if (uo < 0) return st;
        if (uo > 0) continue;
        const bool has_val = i + 1 < argc;
        if (a == "--tmodel" && has_val) {
            if (!parse_tchoice(argv[++i], opt.tmodel))
                return bad_arg("--tmodel", argv[i],
                               "best, none, linear, parabola, lorentz, pwl or lorentz-cubic");
            opt.tmodel_auto = false;
        } else if (a == "--fit" && has_val) {
            if (!parse_fit_method(argv[++i], opt.method))
                return bad_arg("--fit", argv[i], "auto, nominal, pair or magnitude");
        } else if (a == "--out" && has_val) {
            out = argv[++i];
        } else if (a == "--faces-csv" && has_val) {
            faces_out = argv[++i];
        } else if (a == "--tcsv" && has_val) {
            t_out = argv[++i];
        } else if (a == "--seq" && has_val) {
            if (!parse_uint(argv[++i], 0, 0xFFFFFFFFull, seq))
                return bad_arg("--seq", argv[i], "0..4294967295 (decimal)");
        } else if (a == "--window" && has_val) {
            if (!parse_uint(argv[++i], 5, 1000000, window))
                return bad_arg("--window", argv[i], "5..1000000 samples");
        } else if (a == "--t-ref" && has_val) {
            if (!parse_real(argv[++i], -100.0, 200.0, t_ref))
                return bad_arg("--t-ref", argv[i], "a temperature -100..200 degC");
            t_ref_set = true;
        } else if (a == "--binding" && has_val) {
            if (!parse_binding(argv[++i], binding))
                return bad_arg("--binding", argv[i], "generic or six integers F,P,R,S,L1,L2");
            have_binding = true;
        } else if (!a.empty() && a[0] != '-' && in.empty()) {
            in = a;
        } else {
            return usage();
        }
    }
    if (in.empty()) return usage();
    // Any error below: message on stderr, exit 1, and no file is written.
    Input inp;
    std::string e = load_input(in, units, t_ref, t_ref_set, window, inp);
    if (!e.empty()) {
        std::fprintf(stderr, "calstation: %s\n", e.c_str());
        return refuse(e, "ERR_FORMAT", "input");
    }
    Station &st = inp.st;
    std::printf("units: %s%s%s", units.name(),
                inp.units_detected ? " (detected: the samples read about 9.8 at rest; --units g "
                                     "to read them as g)"
                                   : "",
                units.ms2 ? "" : "\n");
    if (units.ms2)
        std::printf(", 1 g = %.6g m/s^2 (%s; --g sets it)\n", units.g,
                    units.g == kStandardGravity ? "standard gravity" : "set with --g");
    if (inp.samples) {
        std::printf("samples: %zu, %zu still intervals, %zu used as faces, %zu not near a face "
                    "(skipped)%s\n",
                    inp.sf.acc_g.size(), inp.seg.size(), st.rows.size(), inp.skipped,
                    inp.sf.col_temp < 0 ? "; no temperature column: every row at t_ref" : "");
    }
    if (have_binding) {
        st.binding = binding;
        st.have_binding = true;
    } else if (!st.have_binding) {
        st.binding = {CALREC_FAMILY_GENERIC, 1u, 0u, 0u, 0u, 0u};
        st.have_binding = true;
        std::printf("binding: generic (family %u: an IMU no firmware driver reads; for calstation "
                    "apply and host use; --binding sets the part's identity)\n",
                    static_cast<unsigned>(CALREC_FAMILY_GENERIC));
    }
    CalResult res;
    e = fit_station(st, opt, res);
    if (!e.empty()) {
        std::fprintf(stderr, "calstation: %s: %s\n", in.c_str(), e.c_str());
        return refuse(e, "ERR_DEGENERATE", "fit");
    }
    std::fputs(res.report.c_str(), stdout);
    std::printf("coefficients (physical units, before quantisation to the record):\n");
    print_coefficients(res, res.have_gyro, res.gyro_scale_fitted);
    struct calrec rec;
    e = to_calrec(res, st, rec);
    FwCheck fw;
    if (e.empty()) e = firmware_check(st, rec, fw);
    if (!e.empty()) {
        std::fprintf(stderr, "calstation: %s: %s\n", in.c_str(), e.c_str());
        return refuse(e, "ERR_RANGE", "record");
    }
    std::printf(
        "firmware check (fixed point, firmware/signal/cal, on the quantised record): %zu acc rows, "
        "max |firmware - double model| = %.2f LSB Q16; ||a|-1g| rms %.4f mg max %.4f mg; max |a - u| "
        "= %.3f mg (tilt rows within +-30 deg: %s)\n",
        fw.rows, fw.max_lsb, fw.mag_rms_mg, fw.mag_max_mg, fw.max_err_mg,
        fw.max_tilt_err_mg > 0.0 ? (std::to_string(fw.max_tilt_err_mg).substr(0, 5) + " mg").c_str()
                                 : "n/a");
    // On samples: the firmware on every sample, face means as the session is scored.
    FaceResidual fr_before, fr_after, fr_pair;
    if (inp.samples) {
        std::vector<std::array<double, 3>> o;
        size_t range = 0;
        e = apply_firmware(rec, inp.sf.acc_g, inp.sf.temp_c, st.t_ref_c, o, range);
        if (e.empty()) {
            fr_before = face_residual(inp.sf.acc_g, inp.seg);
            fr_after = face_residual(o, inp.seg);
            FitOptions po = opt;
            po.method = FitMethod::Pair;
            CalResult pr;
            struct calrec prec;
            if (fit_station(st, po, pr).empty() && to_calrec(pr, st, prec).empty() &&
                apply_firmware(prec, inp.sf.acc_g, inp.sf.temp_c, st.t_ref_c, o, range).empty())
                fr_pair = face_residual(o, inp.seg);
            std::printf(
                "samples through the firmware: face-mean ||a|-1g| over %zu faces: before rms "
                "%.4f mg max %.4f mg; after rms %.4f mg max %.4f mg (per-axis pair method: "
                "rms %.4f mg max %.4f mg)\n",
                fr_after.faces, fr_before.rms_mg, fr_before.max_mg, fr_after.rms_mg,
                fr_after.max_mg, fr_pair.rms_mg, fr_pair.max_mg);
        } else {
            std::fprintf(stderr, "calstation: %s\n", e.c_str());
            return refuse(e, "ERR_RANGE", "firmware");
        }
    }
    const std::vector<std::string> inputs = {in};
    if (!faces_out.empty()) {
        e = write_output(faces_out, faces_csv(res, fw), inputs);
        if (!e.empty()) return write_refused(e);
    }
    if (!t_out.empty()) {
        e = write_output(t_out, tfits_csv(res), inputs);
        if (!e.empty()) return write_refused(e);
    }
    std::vector<uint8_t> img;
    if (!out.empty()) {
        e = encode_record(rec, static_cast<uint32_t>(seq), img);
        if (!e.empty()) {
            std::fprintf(stderr, "calstation: %s\n", e.c_str());
            return refuse(e, "ERR_RANGE", "encode");
        }
        e = write_output(out, std::string(img.begin(), img.end()), inputs);
        if (!e.empty()) return write_refused(e);
        std::printf("wrote %s: calibration record format %u, %zu bytes, seq %u, CRC-32 0x%08X\n",
                    out.c_str(), CALREC_VERSION, img.size(), static_cast<unsigned>(seq),
                    calrec_get_le32(&img[CALREC_OFF_CRC]));
    } else {
        std::printf("no record written (--out RECORD.bin writes one)\n");
    }
    tool_summary_add("input", "%s", inp.samples ? "samples" : "station");
    tool_summary_add("units", "%s", units.name());
    tool_summary_add("units_detected", "%d", inp.units_detected ? 1 : 0);
    tool_summary_add("g", "%.6g", units.g);
    tool_summary_add("acc_rows", "%zu", res.res_chosen.rows);
    tool_summary_add("fit", "%s", fit_method_name(res.method));
    tool_summary_add("tmodel", "%s",
                     res.acc_tbias[0].kind == TKind::None ? "none"
                                                          : tkind_name(res.acc_tbias[0].kind));
    tool_summary_add("mag_rms_mg", "%.4f", res.res_chosen.mag_rms_mg);
    tool_summary_add("mag_max_mg", "%.4f", res.res_chosen.mag_max_mg);
    tool_summary_add("dir_rms_mg", "%.4f", res.res_chosen.dir_rms_mg);
    tool_summary_add("raw_mag_rms_mg", "%.4f", res.res_raw.mag_rms_mg);
    tool_summary_add("pair_mag_rms_mg", "%.4f", res.res_pair.mag_rms_mg);
    tool_summary_add("nominal_mag_rms_mg", "%.4f", res.res_nominal.mag_rms_mg);
    tool_summary_add("magnitude_mag_rms_mg", "%.4f", res.res_magnitude.mag_rms_mg);
    tool_summary_add("placement_max_deg", "%.3f", res.res_chosen.ang_max_deg);
    tool_summary_add("warnings", "%zu", res.warnings.size());
    tool_summary_add("gyro", "%s",
                     !res.have_gyro          ? "not-calibrated"
                     : res.gyro_scale_fitted ? "calibrated"
                                             : "offset-only");
    tool_summary_add("fw_rows", "%zu", fw.rows);
    tool_summary_add("fw_max_lsb", "%.2f", fw.max_lsb);
    tool_summary_add("fw_mag_rms_mg", "%.4f", fw.mag_rms_mg);
    tool_summary_add("fw_max_err_mg", "%.3f", fw.max_err_mg);
    if (fw.max_tilt_err_mg > 0.0)
        tool_summary_add("fw_max_tilt_err_mg", "%.3f", fw.max_tilt_err_mg);
    else
        tool_summary_add("fw_max_tilt_err_mg", "n/a");
    if (inp.samples) {
        tool_summary_add("faces", "%zu", fr_after.faces);
        tool_summary_add("face_rms_before_mg", "%.4f", fr_before.rms_mg);
        tool_summary_add("face_rms_mg", "%.4f", fr_after.rms_mg);
        tool_summary_add("face_max_mg", "%.4f", fr_after.max_mg);
        tool_summary_add("pair_face_rms_mg", "%.4f", fr_pair.rms_mg);
        tool_summary_add("pair_face_max_mg", "%.4f", fr_pair.max_mg);
    }
    if (!out.empty()) {
        tool_summary_add("record_bytes", "%zu", img.size());
        tool_summary_add("format", "%u", static_cast<unsigned>(CALREC_VERSION));
        tool_summary_add("seq", "%u", static_cast<unsigned>(seq));
        tool_summary_add("crc", "0x%08X",
                         static_cast<unsigned>(calrec_get_le32(&img[CALREC_OFF_CRC])));
    } else {
        tool_summary_add("record", "none");
    }
    return 0;
}

// Read and decode a record image against the binding it carries.
int load_record(const char *path, struct calrec &r, struct calrec_binding &b, uint32_t &seq,
                uint32_t &format)
{
    std::string data;
    const std::string e = read_input(path, 1u << 20, data);
    if (!e.empty()) {
        std::fprintf(stderr, "calstation: %s\n", e.c_str());
        return refuse(e, "ERR_IO", "cannot-open");
    }
    std::vector<uint8_t> img(data.begin(), data.end());
    if (img.size() < CALREC_OFF_BINDING + 24u) {
        std::fprintf(stderr, "calstation: %s: %zu bytes, not a calibration record\n", path,
                     img.size());
        return refuse("not a calibration record", "ERR_FORMAT", "not-a-record");
    }
    // Decode against the binding the image itself carries: this shows what is inside; the
    // firmware decodes against the identity it reads from the part.
    (void)calrec_image_binding(img.data(), img.size(), &b); /* the size is checked above */
    const int d = calrec_decode(img.data(), img.size(), &b, &r, &seq);
    if (d != INC_OK) {
        std::fprintf(stderr, "calstation: %s: calrec_decode refused the image (%s)\n", path,
                     inc_err_name(d));
        tool_summary_add("error", "%s", inc_err_name(d));
        tool_summary_add("problem", "record-refused");
        return 1;
    }
    format = calrec_get_le32(&img[CALREC_OFF_VERSION]);
    return 0;
}

bool gyro_identity(const struct calrec &r)
{
    for (int a = 0; a < 3; a++)
        if (r.gyro_offset[a] != 0 || r.gyro_scale[a] != CALREC_Q30_ONE) return false;
    return true;
}

int cmd_show(int argc, char **argv)
{
    if (argc != 1) return usage();
    struct calrec r;
    struct calrec_binding b;
    uint32_t seq = 0, format = 0;
    const int st = load_record(argv[0], r, b, seq, format);
    if (st != 0) return st;
    tool_summary_add("format", "%u", static_cast<unsigned>(format));
    tool_summary_add("seq", "%u", static_cast<unsigned>(seq));
    tool_summary_add("family", "%u", static_cast<unsigned>(b.family));
    tool_summary_add("product", "%u", static_cast<unsigned>(b.product));
    const bool gid = gyro_identity(r);
    tool_summary_add("gyro", "%s", gid ? "not-calibrated" : "calibrated");
    tool_summary_add("tmodel", "%s", record_has_tmodel(r) ? "yes" : "none");
    const CalResult c = from_calrec(r);
    std::printf(
        "record: format %u, seq %u, binding family %u%s product %u revision %u serial %u lot %u/%u\n",
        format, seq, b.family, b.family == CALREC_FAMILY_GENERIC ? " (generic)" : "", b.product,
        b.revision, b.serial, b.lot_id1, b.lot_id2);
    bool scale_id = true;
    for (int a = 0; a < 3; a++)
        scale_id &= r.gyro_scale[a] == CALREC_Q30_ONE;
    print_coefficients(c, !gid, !scale_id);
    return 0;
}

// calstation apply REC IN.csv -o OUT.csv: the firmware correction on every sample.
int cmd_apply(int argc, char **argv)
{
    std::string rec_path, in, out;
    Units units;
    double temp = 25.0;
    bool temp_set = false;
    uint64_t window = 0;
    for (int i = 0; i < argc; i++) {
        const std::string a = argv[i];
        int st = 0;
        const int uo = units_option(argc, argv, i, units, st);
        if (uo < 0) return st;
        if (uo > 0) continue;
        const bool has_val = i + 1 < argc;
        if ((a == "-o" || a == "--out") && has_val) {
            out = argv[++i];
        } else if (a == "--temp" && has_val) {
            if (!parse_real(argv[++i], -100.0, 200.0, temp))
                return bad_arg("--temp", argv[i], "a temperature -100..200 degC");
            temp_set = true;
        } else if (a == "--window" && has_val) {
            if (!parse_uint(argv[++i], 5, 1000000, window))
                return bad_arg("--window", argv[i], "5..1000000 samples");
        } else if (!a.empty() && a[0] != '-' && rec_path.empty()) {
            rec_path = a;
        } else if (!a.empty() && a[0] != '-' && in.empty()) {
            in = a;
        } else {
            return usage();
        }
    }
    if (rec_path.empty() || in.empty() || out.empty()) return usage();
    struct calrec r;
    struct calrec_binding b;
    uint32_t seq = 0, format = 0;
    const int st = load_record(rec_path.c_str(), r, b, seq, format);
    if (st != 0) return st;
    std::string text;
    std::string e = read_input(in, size_t(1) << 30, text);
    if (e.empty() && is_station_text(text))
        e = "'" + in + "' is a station file: apply takes a sample CSV (docs/calibration.md 4.5)";
    SampleFile sf;
    bool detected = false;
    if (e.empty()) {
        e = parse_samples(text, units.per_g(), sf);
        if (e.empty()) e = detect_units(text, units, sf, detected);
        if (!e.empty()) e = in + ": " + e;
    }
    if (!e.empty()) {
        std::fprintf(stderr, "calstation: %s\n", e.c_str());
        return refuse(e, "ERR_FORMAT", "input");
    }
    if (record_has_tmodel(r) && sf.col_temp < 0 && !temp_set) {
        const std::string m = "the record has temperature models: the samples need a temperature "
                              "column (temp_c) or --temp C";
        std::fprintf(stderr, "calstation: %s\n", m.c_str());
        tool_summary_add("error", "ERR_INVAL");
        tool_summary_add("problem", "no-temperature");
        return 1;
    }
    std::vector<double> temps = sf.temp_c;
    if (temp_set) temps.clear();
    std::vector<std::array<double, 3>> o;
    size_t range = 0;
    e = apply_firmware(r, sf.acc_g, temps, temp, o, range);
    if (!e.empty()) {
        std::fprintf(stderr, "calstation: %s\n", e.c_str());
        return refuse(e, "ERR_RANGE", "firmware");
    }
    std::string csv;
    for (const auto &c : sf.comments)
        csv += c + "\n";
    char buf[64];
    for (size_t c = 0; c < sf.header.size(); c++)
        csv += (c ? "," : "") + sf.header[c];
    csv += "\n";
    for (size_t k = 0; k < sf.fields.size(); k++) {
        std::vector<std::string> f = sf.fields[k];
        for (int a = 0; a < 3; a++) {
            std::snprintf(buf, sizeof buf, "%.9g", o[k][a] * units.per_g());
            f[sf.col[a]] = buf;
        }
        for (size_t c = 0; c < f.size(); c++)
            csv += (c ? "," : "") + f[c];
        csv += "\n";
    }
    e = write_output(out, csv, {in, rec_path});
    if (!e.empty()) return write_refused(e);
    const std::vector<Segment> seg = find_segments(sf, window);
    const FaceResidual before = face_residual(sf.acc_g, seg), after = face_residual(o, seg);
    std::printf(
        "applied %s (firmware cal_acc_apply, fixed point) to %zu samples of %s (%s%s) -> %s; "
        "%zu beyond +-64 g\n",
        rec_path.c_str(), o.size(), in.c_str(), units.name(),
        units.ms2 ? (", 1 g = " + std::to_string(units.g)).c_str() : "", out.c_str(), range);
    if (after.faces) {
        std::printf(
            "face-mean ||a|-1g| over %zu still faces: before rms %.4f mg max %.4f mg; after "
            "rms %.4f mg max %.4f mg\n",
            after.faces, before.rms_mg, before.max_mg, after.rms_mg, after.max_mg);
    } else {
        std::printf("face-mean residual: n/a (no still face found in the samples)\n");
    }
    tool_summary_add("samples", "%zu", o.size());
    tool_summary_add("units", "%s", units.name());
    tool_summary_add("units_detected", "%d", detected ? 1 : 0);
    tool_summary_add("g", "%.6g", units.g);
    tool_summary_add("range", "%zu", range);
    tool_summary_add("faces", "%zu", after.faces);
    if (after.faces) {
        tool_summary_add("face_rms_before_mg", "%.4f", before.rms_mg);
        tool_summary_add("face_rms_mg", "%.4f", after.rms_mg);
        tool_summary_add("face_max_mg", "%.4f", after.max_mg);
    } else {
        tool_summary_add("face_rms_mg", "n/a");
    }
    return 0;
}

int cmd_compare(int argc, char **argv)
{
    CompareConfig cfg;
    std::vector<uint64_t> seeds = {2};
    for (int i = 0; i < argc; i++) {
        const std::string a = argv[i];
        uint64_t v = 0;
        if (a == "--cycles" && i + 1 < argc) {
            if (!parse_uint(argv[++i], 1, 100, v))
                return bad_arg("--cycles", argv[i], "1..100 (decimal)");
            cfg.cycles = static_cast<int>(v);
        } else if (a == "--seeds" && i + 1 < argc) {
            seeds.clear();
            std::string s = argv[++i];
            size_t pos = 0;
            while (pos <= s.size()) {
                const size_t c = s.find(',', pos);
                const std::string tok = s.substr(pos, c == std::string::npos ? std::string::npos
                                                                             : c - pos);
                if (!parse_uint(tok.c_str(), 0, UINT64_MAX, v))
                    return bad_arg("--seeds", tok.c_str(),
                                   "seeds 0..2^64-1 (decimal), comma-separated");
                seeds.push_back(v);
                if (c == std::string::npos) break;
                pos = c + 1;
            }
        } else {
            return usage();
        }
    }
    std::vector<CompareAxis> rows;
    std::vector<SimPart> parts(seeds.size() + 1, SimPart{true, 0});
    std::transform(seeds.begin(), seeds.end(), parts.begin() + 1, [](uint64_t s) {
        return SimPart{false, s};
    });
    for (const auto &p : parts) {
        const std::string e = compare_part(p, cfg, rows);
        if (!e.empty()) {
            std::fprintf(stderr, "calstation: compare: %s\n", e.c_str());
            return refuse(e, "ERR_DEGENERATE", "compare");
        }
    }
    std::fputs(format_compare(rows).c_str(), stdout);
    tool_summary_add("parts", "%zu", parts.size());
    tool_summary_add("rows", "%zu", rows.size());
    return 0;
}

// calstation dflash REC --out FILE: the record as the S32K1 images' data flash holds it, for the
// probe (docs/calibration.md 4.6).
int cmd_dflash(int argc, char **argv)
{
    std::string rec_path, out, format = "srec";
    for (int i = 0; i < argc; i++) {
        const std::string a = argv[i];
        const bool has_val = i + 1 < argc;
        if ((a == "-o" || a == "--out") && has_val) {
            out = argv[++i];
        } else if (a == "--format" && has_val) {
            format = argv[++i];
            if (format != "srec" && format != "ihex")
                return bad_arg("--format", argv[i], "srec or ihex");
        } else if (!a.empty() && a[0] != '-' && rec_path.empty()) {
            rec_path = a;
        } else {
            return usage();
        }
    }
    if (rec_path.empty() || out.empty()) return usage();
    struct calrec r;
    struct calrec_binding b;
    uint32_t seq = 0, rec_format = 0;
    const int st = load_record(rec_path.c_str(), r, b, seq, rec_format);
    if (st != 0) return st;
    std::vector<uint8_t> bytes;
    uint32_t addr = 0;
    std::string e = dflash_image(r, bytes, addr);
    if (!e.empty()) {
        std::fprintf(stderr, "calstation: %s: %s\n", rec_path.c_str(), e.c_str());
        return refuse(e, "ERR_RANGE", "record");
    }
    e = write_output(out, format == "srec" ? to_srec(bytes, addr) : to_ihex(bytes, addr),
                     {rec_path});
    if (!e.empty()) return write_refused(e);
    const uint32_t crc = calrec_get_le32(&bytes[CALREC_OFF_CRC]);
    std::printf("wrote %s: %s, data flash 0x%08X..0x%08X (two sectors: slot 0 the record of %s, "
                "seq 1, CRC-32 0x%08X; slot 1 erased)\n",
                out.c_str(), format == "srec" ? "S-records" : "Intel HEX",
                static_cast<unsigned>(addr), static_cast<unsigned>(addr + bytes.size() - 1u),
                rec_path.c_str(), static_cast<unsigned>(crc));
    tool_summary_add("format", "%s", format.c_str());
    tool_summary_add("address", "0x%08X", static_cast<unsigned>(addr));
    tool_summary_add("bytes", "%zu", bytes.size());
    tool_summary_add("seq", "1");
    tool_summary_add("crc", "0x%08X", static_cast<unsigned>(crc));
    tool_summary_add("family", "%u", static_cast<unsigned>(b.family));
    tool_summary_add("serial", "%u", static_cast<unsigned>(b.serial));
    return 0;
}

int run(int argc, char **argv)
{
    if (argc < 2) return usage();
    const std::string cmd = argv[1];
    tool_summary_add("command", "%s", cmd.c_str());
    if (cmd == "simulate") return cmd_simulate(argc - 2, argv + 2);
    if (cmd == "fit") return cmd_fit(argc - 2, argv + 2);
    if (cmd == "compare") return cmd_compare(argc - 2, argv + 2);
    if (cmd == "show") return cmd_show(argc - 2, argv + 2);
    if (cmd == "dflash") return cmd_dflash(argc - 2, argv + 2);
    if (cmd == "apply") return cmd_apply(argc - 2, argv + 2);
    return usage();
}

} // namespace

int main(int argc, char **argv)
{
    tool_summary_begin("calstation");
    int status = 1;
    try {
        status = run(argc, argv);
    } catch (const std::exception &ex) {
        // Never an abort: every failure ends with a message, the summary and exit 1.
        std::fprintf(stderr, "calstation: internal error: %s\n", ex.what());
        tool_summary_add("error", "internal");
        status = 1;
    }
    return tool_summary_end(status == 0 ? "ok" : "error", status);
}
