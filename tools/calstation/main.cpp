// calstation - the calibration-station tool (docs/calibration.md).
//
//   calstation simulate [--part A|<seed>] [--schedule calibration|validation|ambient]
//                       [--cycles N] [--samples N] [--noise-seed N] [--binding F,P,R,S,L1,L2]
//                       --out FILE.csv
//   calstation fit FILE.csv [--tmodel best|none|linear|parabola|lorentz|pwl|lorentz-cubic]
//                  [--out RECORD.bin] [--seq N]
//   calstation show RECORD.bin
//   calstation compare [--cycles N] [--seeds S1,S2,...]   (part A plus seeded parts; default 2)
//
// Exit status: 0 success, 1 bad input (message on stderr, nothing written), 2 usage error.
// The last line on stdout is the summary (docs/tool-summary.md): a refusal gives
// error=<inc_err name> problem=<slug> [line=N] [column=NAME] [coefficient=NAME].
#include "inclino/error.h"
#include "inclino/tool_summary.h"
#include "inclino/calstation/compare.hpp"
#include "inclino/calstation/fit.hpp"
#include "inclino/calstation/record.hpp"
#include "inclino/calstation/station.hpp"

#include <algorithm>
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

bool parse_u64(const char *s, uint64_t &v)
{
    char *end = nullptr;
    v = std::strtoull(s, &end, 0);
    return end != s && *end == '\0';
}

bool write_file(const std::string &path, const std::string &data)
{
    const std::string tmp = path + ".tmp";
    {
        std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
        if (!f) return false;
        f.write(data.data(), static_cast<std::streamsize>(data.size()));
        if (!f) return false;
    }
    return std::rename(tmp.c_str(), path.c_str()) == 0;
}

int cmd_simulate(int argc, char **argv)
{
    SimConfig cfg;
    std::string out;
    for (int i = 0; i < argc; i++) {
        const std::string a = argv[i];
        uint64_t v = 0;
        if (i + 1 >= argc) return usage();
        const char *val = argv[++i];
        if (a == "--part") {
            if (std::strcmp(val, "A") == 0) {
                cfg.part.paper = true;
            } else if (parse_u64(val, v)) {
                cfg.part.paper = false;
                cfg.part.curve_seed = v;
            } else {
                return usage();
            }
        } else if (a == "--schedule") {
            const std::string s = val;
            if (s == "calibration")
                cfg.schedule = Schedule::Calibration;
            else if (s == "validation")
                cfg.schedule = Schedule::Validation;
            else if (s == "ambient")
                cfg.schedule = Schedule::Ambient;
            else
                return usage();
        } else if (a == "--cycles" && parse_u64(val, v) && v >= 1 && v <= 100) {
            cfg.cycles = static_cast<int>(v);
        } else if (a == "--samples" && parse_u64(val, v) && v >= 1 && v <= 1000000) {
            cfg.samples = static_cast<int>(v);
        } else if (a == "--noise-seed" && parse_u64(val, v)) {
            cfg.noise_seed = v;
        } else if (a == "--out") {
            out = val;
        } else if (a == "--binding") {
            // family,product,revision,serial,lot_id1,lot_id2 of the part the record is for
            std::string b = val;
            size_t pos = 0;
            for (int k = 0; k < 6; k++) {
                const size_t c = b.find(',', pos);
                if ((k < 5) != (c != std::string::npos)) return usage();
                const std::string tok = b.substr(pos, c == std::string::npos ? std::string::npos
                                                                             : c - pos);
                if (!parse_u64(tok.c_str(), v) || v > 0xFFFFFFFFull) return usage();
                cfg.binding[k] = static_cast<uint32_t>(v);
                pos = c + 1;
            }
            cfg.have_binding = true;
        } else {
            return usage();
        }
    }
    if (out.empty()) return usage();
    const Station st = simulate_station(cfg);
    if (!write_file(out, format_station(st))) {
        std::fprintf(stderr, "calstation: cannot write '%s'\n", out.c_str());
        return refuse("cannot write", "ERR_IO", "cannot-write");
    }
    std::printf("wrote %s: %zu rows\n", out.c_str(), st.rows.size());
    tool_summary_add("rows", "%zu", st.rows.size());
    return 0;
}

int cmd_fit(int argc, char **argv)
{
    std::string in, out;
    FitOptions opt;
    uint64_t seq = 1;
    for (int i = 0; i < argc; i++) {
        const std::string a = argv[i];
        if (a == "--tmodel" && i + 1 < argc) {
            if (!parse_tchoice(argv[++i], opt.tmodel)) return usage();
        } else if (a == "--out" && i + 1 < argc) {
            out = argv[++i];
        } else if (a == "--seq" && i + 1 < argc) {
            if (!parse_u64(argv[++i], seq) || seq > 0xFFFFFFFFull) return usage();
        } else if (a[0] != '-' && in.empty()) {
            in = a;
        } else {
            return usage();
        }
    }
    if (in.empty()) return usage();
    // Any error below: message on stderr, exit 1, and no record file is written.
    Station st;
    std::string e = read_station_file(in, st);
    if (!e.empty()) {
        std::fprintf(stderr, "calstation: %s\n", e.c_str());
        return refuse(e, "ERR_FORMAT", "input");
    }
    CalResult res;
    e = fit_station(st, opt, res);
    if (!e.empty()) {
        std::fprintf(stderr, "calstation: %s: %s\n", in.c_str(), e.c_str());
        return refuse(e, "ERR_DEGENERATE", "fit");
    }
    std::fputs(res.report.c_str(), stdout);
    struct calrec rec;
    e = to_calrec(res, st, rec);
    FwCheck fw;
    if (e.empty()) e = firmware_check(st, rec, fw);
    if (!e.empty()) {
        std::fprintf(stderr, "calstation: %s: %s\n", in.c_str(), e.c_str());
        return refuse(e, "ERR_RANGE", "record");
    }
    tool_summary_add("fw_rows", "%zu", fw.rows);
    tool_summary_add("fw_max_lsb", "%.2f", fw.max_lsb);
    tool_summary_add("fw_max_err_mg", "%.3f", fw.max_err_mg);
    tool_summary_add("fw_max_tilt_err_mg", "%.3f", fw.max_tilt_err_mg);
    std::printf(
        "firmware check (fixed point, firmware/signal/cal, on the quantised record): %zu acc rows, "
        "max |firmware - double model| = %.2f LSB Q16; max |corrected - true| = %.3f mg "
        "(tilt rows within +-30 deg: %.3f mg)\n",
        fw.rows, fw.max_lsb, fw.max_err_mg, fw.max_tilt_err_mg);
    if (!out.empty()) {
        std::vector<uint8_t> img;
        e = encode_record(rec, static_cast<uint32_t>(seq), img);
        if (!e.empty()) {
            std::fprintf(stderr, "calstation: %s\n", e.c_str());
            return refuse(e, "ERR_RANGE", "encode");
        }
        if (!write_file(out, std::string(img.begin(), img.end()))) {
            std::fprintf(stderr, "calstation: cannot write '%s'\n", out.c_str());
            return refuse("cannot write", "ERR_IO", "cannot-write");
        }
        tool_summary_add("record_bytes", "%zu", img.size());
        tool_summary_add("format", "%u", static_cast<unsigned>(CALREC_VERSION));
        tool_summary_add("seq", "%u", static_cast<unsigned>(seq));
        tool_summary_add("crc", "0x%08X",
                         static_cast<unsigned>(calrec_get_le32(&img[CALREC_OFF_CRC])));
        std::printf("wrote %s: calibration record format %u, %zu bytes, seq %u, CRC-32 0x%08X\n",
                    out.c_str(), CALREC_VERSION, img.size(), static_cast<unsigned>(seq),
                    calrec_get_le32(&img[CALREC_OFF_CRC]));
    }
    return 0;
}

int cmd_show(int argc, char **argv)
{
    if (argc != 1) return usage();
    std::ifstream f(argv[0], std::ios::binary);
    if (!f) {
        std::fprintf(stderr, "calstation: cannot open '%s'\n", argv[0]);
        return refuse("cannot open", "ERR_IO", "cannot-open");
    }
    std::vector<uint8_t> img((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    if (img.size() < CALREC_OFF_BINDING + 24u) {
        std::fprintf(stderr, "calstation: %s: %zu bytes, not a calibration record\n", argv[0],
                     img.size());
        return refuse("not a calibration record", "ERR_FORMAT", "not-a-record");
    }
    // Decode against the binding the image itself carries: this shows what is inside; the
    // firmware decodes against the identity it reads from the part.
    struct calrec_binding b;
    b.family = calrec_get_le32(&img[CALREC_OFF_BINDING]);
    b.product = calrec_get_le32(&img[CALREC_OFF_BINDING + 4]);
    b.revision = calrec_get_le32(&img[CALREC_OFF_BINDING + 8]);
    b.serial = calrec_get_le32(&img[CALREC_OFF_BINDING + 12]);
    b.lot_id1 = calrec_get_le32(&img[CALREC_OFF_BINDING + 16]);
    b.lot_id2 = calrec_get_le32(&img[CALREC_OFF_BINDING + 20]);
    struct calrec r;
    uint32_t seq = 0;
    const int e = calrec_decode(img.data(), img.size(), &b, &r, &seq);
    if (e != INC_OK) {
        std::fprintf(stderr, "calstation: %s: calrec_decode refused the image (%s)\n", argv[0],
                     inc_err_name(e));
        tool_summary_add("error", "%s", inc_err_name(e));
        tool_summary_add("problem", "record-refused");
        return 1;
    }
    tool_summary_add("format", "%u",
                     static_cast<unsigned>(calrec_get_le32(&img[CALREC_OFF_VERSION])));
    tool_summary_add("seq", "%u", static_cast<unsigned>(seq));
    tool_summary_add("family", "%u", static_cast<unsigned>(b.family));
    tool_summary_add("product", "%u", static_cast<unsigned>(b.product));
    const CalResult c = from_calrec(r);
    static const char *const ax[3] = {"x", "y", "z"};
    std::printf(
        "record: format %u, seq %u, binding family %u product %u revision %u serial %u lot %u/%u\n",
        calrec_get_le32(&img[CALREC_OFF_VERSION]), seq, b.family, b.product, b.revision, b.serial,
        b.lot_id1, b.lot_id2);
    for (int a = 0; a < 3; a++) {
        std::printf(
            "acc %s: offset %+.6f g  gain %.7f  M row % .7f % .7f % .7f  nonlin c0..c3 % .6f % .6f % .6f % .6f\n",
            ax[a], c.acc_offset[a], c.acc_gain[a], c.acc_misalign[a][0], c.acc_misalign[a][1],
            c.acc_misalign[a][2], c.acc_nonlin[a][0], c.acc_nonlin[a][1], c.acc_nonlin[a][2],
            c.acc_nonlin[a][3]);
        for (int q = 0; q < 2; q++) {
            const TModel &m = q ? c.acc_tscale[a] : c.acc_tbias[a];
            std::printf("      %s: %s", q ? "tscale" : "tbias ", tkind_name(m.kind));
            if (m.kind != TKind::None && m.kind != TKind::Lorentz)
                std::printf(" t_ref %.3f t_span %.3f", m.t_ref, m.t_span);
            if (m.kind == TKind::Pwl) std::printf(" n %d", m.n);
            std::printf(" p");
            for (int k = 0; k < m.params(); k++)
                std::printf(" %.7g", m.p[k]);
            std::printf("\n");
        }
    }
    std::printf("gyro: offset %+.5f %+.5f %+.5f deg/s, scale %.7f %.7f %.7f\n", c.gyro_offset[0],
                c.gyro_offset[1], c.gyro_offset[2], c.gyro_scale[0], c.gyro_scale[1],
                c.gyro_scale[2]);
    return 0;
}

int cmd_compare(int argc, char **argv)
{
    CompareConfig cfg;
    std::vector<uint64_t> seeds = {2};
    for (int i = 0; i < argc; i++) {
        const std::string a = argv[i];
        uint64_t v = 0;
        if (a == "--cycles" && i + 1 < argc && parse_u64(argv[i + 1], v) && v >= 1 && v <= 100) {
            cfg.cycles = static_cast<int>(v);
            i++;
        } else if (a == "--seeds" && i + 1 < argc) {
            seeds.clear();
            std::string s = argv[++i];
            size_t pos = 0;
            while (pos <= s.size()) {
                const size_t c = s.find(',', pos);
                const std::string tok = s.substr(pos, c == std::string::npos ? std::string::npos
                                                                             : c - pos);
                if (!parse_u64(tok.c_str(), v)) return usage();
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

int run(int argc, char **argv)
{
    if (argc < 2) return usage();
    const std::string cmd = argv[1];
    tool_summary_add("command", "%s", cmd.c_str());
    if (cmd == "simulate") return cmd_simulate(argc - 2, argv + 2);
    if (cmd == "fit") return cmd_fit(argc - 2, argv + 2);
    if (cmd == "compare") return cmd_compare(argc - 2, argv + 2);
    if (cmd == "show") return cmd_show(argc - 2, argv + 2);
    return usage();
}

} // namespace

int main(int argc, char **argv)
{
    tool_summary_begin("calstation");
    const int status = run(argc, argv);
    return tool_summary_end(status == 0 ? "ok" : "error", status);
}
