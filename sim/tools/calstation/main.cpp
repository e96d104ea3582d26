// calstation - the calibration-station tool (docs/calibration.md).
//
//   calstation simulate [--part A|<seed>] [--schedule calibration|validation|ambient]
//                       [--cycles N] [--samples N] [--noise-seed N] --out FILE.csv
//   calstation fit FILE.csv [--tmodel best|none|linear|parabola|lorentz|pwl|lorentz-cubic]
//   calstation compare [--cycles N] [--seeds S1,S2,...]   (part A plus seeded parts; default 2)
//
// Exit status: 0 success, 1 bad input (message on stderr, nothing written), 2 usage error.
#include "inclino/calstation/compare.hpp"
#include "inclino/calstation/fit.hpp"
#include "inclino/calstation/station.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

using namespace calstation;

namespace {

int usage()
{
    std::fputs("usage:\n"
               "  calstation simulate [--part A|<seed>] [--schedule calibration|validation|ambient]\n"
               "                      [--cycles N] [--samples N] [--noise-seed N] --out FILE.csv\n"
               "  calstation fit FILE.csv [--tmodel best|none|linear|parabola|lorentz|pwl|lorentz-cubic]\n"
               "  calstation compare [--cycles N] [--seeds S1,S2,...]\n",
               stderr);
    return 2;
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
            if (s == "calibration") cfg.schedule = Schedule::Calibration;
            else if (s == "validation") cfg.schedule = Schedule::Validation;
            else if (s == "ambient") cfg.schedule = Schedule::Ambient;
            else return usage();
        } else if (a == "--cycles" && parse_u64(val, v) && v >= 1 && v <= 100) {
            cfg.cycles = static_cast<int>(v);
        } else if (a == "--samples" && parse_u64(val, v) && v >= 1 && v <= 1000000) {
            cfg.samples = static_cast<int>(v);
        } else if (a == "--noise-seed" && parse_u64(val, v)) {
            cfg.noise_seed = v;
        } else if (a == "--out") {
            out = val;
        } else {
            return usage();
        }
    }
    if (out.empty()) return usage();
    const Station st = simulate_station(cfg);
    if (!write_file(out, format_station(st))) {
        std::fprintf(stderr, "calstation: cannot write '%s'\n", out.c_str());
        return 1;
    }
    std::printf("wrote %s: %zu rows\n", out.c_str(), st.rows.size());
    return 0;
}

int cmd_fit(int argc, char **argv)
{
    std::string in;
    FitOptions opt;
    for (int i = 0; i < argc; i++) {
        const std::string a = argv[i];
        if (a == "--tmodel" && i + 1 < argc) {
            if (!parse_tchoice(argv[++i], opt.tmodel)) return usage();
        } else if (a[0] != '-' && in.empty()) {
            in = a;
        } else {
            return usage();
        }
    }
    if (in.empty()) return usage();
    Station st;
    std::string e = read_station_file(in, st);
    if (!e.empty()) {
        std::fprintf(stderr, "calstation: %s\n", e.c_str());
        return 1;
    }
    CalResult res;
    e = fit_station(st, opt, res);
    if (!e.empty()) {
        std::fprintf(stderr, "calstation: %s: %s\n", in.c_str(), e.c_str());
        return 1;
    }
    std::fputs(res.report.c_str(), stdout);
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
                const std::string tok = s.substr(pos, c == std::string::npos ? std::string::npos : c - pos);
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
    std::transform(seeds.begin(), seeds.end(), parts.begin() + 1, [](uint64_t s) { return SimPart{false, s}; });
    for (const auto &p : parts) {
        const std::string e = compare_part(p, cfg, rows);
        if (!e.empty()) {
            std::fprintf(stderr, "calstation: compare: %s\n", e.c_str());
            return 1;
        }
    }
    std::fputs(format_compare(rows).c_str(), stdout);
    return 0;
}

} // namespace

int main(int argc, char **argv)
{
    if (argc < 2) return usage();
    const std::string cmd = argv[1];
    if (cmd == "simulate") return cmd_simulate(argc - 2, argv + 2);
    if (cmd == "fit") return cmd_fit(argc - 2, argv + 2);
    if (cmd == "compare") return cmd_compare(argc - 2, argv + 2);
    return usage();
}
