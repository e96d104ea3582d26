// epb_campaign - the EPB accuracy campaign (docs/campaign.md): seeded Monte Carlo cases of the
// EPB application, or [ADI-EPB]'s Table 1 reproduced term by term.
//
//   epb_campaign [--seed S] [--first K] [--cases N] [--blocks B] [--lot N] [--csv FILE]
//                [--no-sweep] [--no-tcal] [--single-axis]
//   epb_campaign --table1 [--csv FILE]
//
// Exit status: 0 when every valid estimate lies within its bound and the largest |error| of the
// valid ones is within --max-err-deg (default 0.25); 1 otherwise; 2 for bad arguments or a case
// that could not run.
extern "C" {
#include "inclino/tool_summary.h"
}
#include "inclino/campaign/campaign.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace
{

void usage()
{
    std::fprintf(
        stderr,
        "usage: epb_campaign [--seed S] [--first K] [--cases N] [--blocks B] [--lot N]\n"
        "                    [--csv FILE] [--max-err-deg D] [--no-sweep] [--no-tcal] [--single-axis]\n"
        "       epb_campaign --table1 [--csv FILE]\n"
        "  --seed S       campaign seed (default 1); case i runs with case_seed(S, i)\n"
        "  --first K      first case index (default 0): --first K --cases 1 reruns case K alone\n"
        "  --cases N      number of cases (default 100, 1..10^7)\n"
        "  --blocks B     estimates per case (default 4, 1..100; 2.5 s each)\n"
        "  --lot N        characterisation lot for the budget (default 24 parts, 1..1000)\n"
        "  --csv FILE     one row per estimate (or Table 1's rows)\n"
        "  --max-err-deg  the figure to reach (default 0.25)\n");
}

bool parse_u64(const char *s, uint64_t lo, uint64_t hi, uint64_t &out)
{
    if (s == nullptr || *s == '\0' || *s == '-' || *s == '+') return false;
    errno = 0;
    char *end = nullptr;
    const unsigned long long v = std::strtoull(s, &end, 10);
    if (errno != 0 || *end != '\0' || v < lo || v > hi) return false;
    out = v;
    return true;
}

bool parse_double(const char *s, double lo, double hi, double &out)
{
    if (s == nullptr || *s == '\0') return false;
    errno = 0;
    char *end = nullptr;
    const double v = std::strtod(s, &end);
    if (errno != 0 || *end != '\0' || !(v >= lo && v <= hi)) return false;
    out = v;
    return true;
}

int do_table1(const campaign::Config &c, const std::string &csv)
{
    campaign::Table1 t;
    const std::string err = campaign::table1(c, t);
    if (!err.empty()) {
        std::fprintf(stderr, "epb_campaign: %s\n", err.c_str());
        return tool_summary_error("table1", 2);
    }
    std::printf(
        "[ADI-EPB] Table 1 (example part: ADI ADXC1500/ADXC1501, combined gyro and 2/3-axis "
        "accelerometer), reproduced\nterm by term on simulated parts, each error term "
        "alone; worst-case sum of the terms in mg, converted with asin(total / 1 g)\n\n");
    std::printf("%-26s %9s %9s | %9s %9s | %9s %9s   %s\n", "term [mg]", "art.bef", "art.aft",
                "sim.bef", "sim.aft", "ours.bef", "ours.aft", "calibration");
    for (const auto &r : t.rows) {
        std::printf("%-26s %9.2f %9.2f | %9.2f %9.2f | %9.3f %9.3f   %s\n", r.term.c_str(),
                    r.article_before * 1e3, r.article_after * 1e3, r.sim_before * 1e3,
                    r.sim_after * 1e3, r.ours_before * 1e3, r.ours_after * 1e3, r.method.c_str());
    }
    std::printf("%-26s %9.2f %9.2f | %9.2f %9.2f | %9.3f %9.3f\n", "total",
                t.article_total_before * 1e3, t.article_total_after * 1e3, t.sim_total_before * 1e3,
                t.sim_total_after * 1e3, t.ours_total_before * 1e3, t.ours_total_after * 1e3);
    std::printf("%-26s %9.2f %9.2f | %9.2f %9.2f | %9.3f %9.3f\n", "worst case [deg]",
                t.deg(t.article_total_before), t.deg(t.article_total_after),
                t.deg(t.sim_total_before), t.deg(t.sim_total_after), t.deg(t.ours_total_before),
                t.deg(t.ours_total_after));
    std::printf("\nnotes:\n");
    for (const auto &r : t.rows)
        if (!r.note.empty()) std::printf("  %s: %s\n", r.term.c_str(), r.note.c_str());
    if (!csv.empty()) {
        FILE *f = std::fopen(csv.c_str(), "w");
        bool ok = f != nullptr;
        if (ok) {
            ok = std::fprintf(f, "term,article_before_mg,article_after_mg,sim_before_mg,"
                                 "sim_after_mg,ours_before_mg,ours_after_mg\n") > 0;
            for (const auto &r : t.rows) {
                ok = ok &&
                     std::fprintf(f, "\"%s\",%.4f,%.4f,%.4f,%.4f,%.4f,%.4f\n", r.term.c_str(),
                                  r.article_before * 1e3, r.article_after * 1e3, r.sim_before * 1e3,
                                  r.sim_after * 1e3, r.ours_before * 1e3, r.ours_after * 1e3) > 0;
            }
            ok = std::fclose(f) == 0 && ok;
        }
        if (!ok) {
            std::fprintf(stderr, "epb_campaign: cannot write %s\n", csv.c_str());
            return tool_summary_error("io", 2);
        }
    }
    tool_summary_add("mode", "table1");
    tool_summary_add("article_before_mg", "%.1f", t.article_total_before * 1e3);
    tool_summary_add("article_after_mg", "%.1f", t.article_total_after * 1e3);
    tool_summary_add("sim_before_mg", "%.1f", t.sim_total_before * 1e3);
    tool_summary_add("sim_after_mg", "%.1f", t.sim_total_after * 1e3);
    tool_summary_add("sim_before_deg", "%.2f", t.deg(t.sim_total_before));
    tool_summary_add("sim_after_deg", "%.2f", t.deg(t.sim_total_after));
    tool_summary_add("ours_before_mg", "%.2f", t.ours_total_before * 1e3);
    tool_summary_add("ours_after_mg", "%.3f", t.ours_total_after * 1e3);
    tool_summary_add("ours_after_deg", "%.3f", t.deg(t.ours_total_after));
    return tool_summary_end("ok", 0);
}

} // namespace

int main(int argc, char **argv)
{
    tool_summary_begin("epb_campaign");
    campaign::Config c;
    uint64_t seed = 1, first = 0, cases = 100, lot = 24, blocks = 4;
    double max_err = 0.25;
    std::string csv;
    bool t1 = false;
    for (int i = 1; i < argc; i++) {
        const std::string a = argv[i];
        const char *v = i + 1 < argc ? argv[i + 1] : nullptr;
        bool ok = true, val = true;
        if (a == "--seed")
            ok = parse_u64(v, 0, UINT64_MAX, seed);
        else if (a == "--first")
            ok = parse_u64(v, 0, 1000000000000ull, first);
        else if (a == "--cases")
            ok = parse_u64(v, 1, 10000000, cases);
        else if (a == "--blocks")
            ok = parse_u64(v, 1, 100, blocks);
        else if (a == "--lot")
            ok = parse_u64(v, 1, 1000, lot);
        else if (a == "--max-err-deg")
            ok = parse_double(v, 0.0, 90.0, max_err);
        else if (a == "--csv")
            ok = v != nullptr && *v != '\0', csv = v ? v : "";
        else {
            val = false;
            if (a == "--table1")
                t1 = true;
            else if (a == "--no-sweep")
                c.sweep = false;
            else if (a == "--no-tcal")
                c.tcal = false;
            else if (a == "--single-axis")
                c.two_axis = false;
            else if (a == "-h" || a == "--help") {
                usage();
                return 0;
            } else {
                usage();
                tool_summary_add("option", "%s", a.c_str());
                return tool_summary_error("bad-option", 2);
            }
        }
        if (!ok) {
            usage();
            tool_summary_add("option", "%s", a.c_str());
            return tool_summary_error("bad-value", 2);
        }
        if (val) i++;
    }
    c.blocks = static_cast<int>(blocks);
    if (t1) return do_table1(c, csv);

    campaign::Characterisation ch;
    std::string err = campaign::characterise(c, 0x4c4f54ull, static_cast<unsigned>(lot), ch);
    if (!err.empty()) {
        std::fprintf(stderr, "epb_campaign: characterisation: %s\n", err.c_str());
        return tool_summary_error("characterisation", 2);
    }
    std::printf(
        "EPB campaign: seed %llu, cases %llu..%llu, %llu estimates each; budget of the part "
        "type from a %llu-part lot:\n  sensitivity %.4f %%, offset %.3f mg, nonlinearity "
        "%.3f mg, temperature %.3f mg, sigma %.3f mg (lot model residual %.3f mg)\n",
        (unsigned long long)seed, (unsigned long long)first,
        (unsigned long long)(first + cases - 1), (unsigned long long)blocks,
        (unsigned long long)lot, ch.sensitivity * 100, ch.offset * 1e3, ch.nonlinearity * 1e3,
        ch.temperature * 1e3, ch.sigma * 1e3, ch.lot_static_g * 1e3);
    FILE *f = nullptr;
    if (!csv.empty()) {
        f = std::fopen(csv.c_str(), "w");
        if (f == nullptr || std::fprintf(f, "%s\n", campaign::csv_header().c_str()) < 0) {
            std::fprintf(stderr, "epb_campaign: cannot write %s\n", csv.c_str());
            if (f) std::fclose(f);
            return tool_summary_error("io", 2);
        }
    }
    uint64_t n_est = 0, n_valid = 0, n_out = 0, failed = 0, worst_case = 0, cold = 0;
    double worst = 0.0, worst_ratio = 0.0, worst_bound = 0.0, max_valid_bound = 0.0;
    double worst_cold = 0.0;
    bool io_ok = true;
    std::vector<campaign::Estimate> est;
    for (uint64_t k = first; k < first + cases; k++) {
        est.clear();
        campaign::Scenario sc;
        err = campaign::run_case(c, ch, seed, k, est, sc);
        if (!err.empty()) {
            std::fprintf(stderr, "epb_campaign: case %llu: %s\n", (unsigned long long)k,
                         err.c_str());
            failed++;
            continue;
        }
        for (const auto &e : est) {
            n_est++;
            if (f != nullptr)
                io_ok = io_ok && std::fprintf(f, "%s\n", campaign::csv_row(e).c_str()) > 0;
            if (!e.valid) continue;
            n_valid++;
            const double ae = std::fabs(e.error_deg);
            if (!e.inside) {
                n_out++;
                if (n_out <= 20)
                    std::printf(
                        "  OUTSIDE: case %llu block %d: true %.4f roll %.2f T %.1f est %.4f "
                        "err %+.4f bound %.4f flags 0x%x\n",
                        (unsigned long long)k, e.block, e.true_deg, e.true_roll, e.true_temp_c,
                        e.slope_deg, e.error_deg, e.bound_deg, e.flags);
            }
            if (ae > worst) {
                worst = ae;
                worst_case = k;
                worst_bound = e.bound_deg;
            }
            if (sc.cold_start) worst_cold = std::max(worst_cold, ae);
            worst_ratio = std::max(worst_ratio, ae / e.bound_deg);
            max_valid_bound = std::max(max_valid_bound, e.bound_deg);
        }
        if (sc.cold_start) cold++;
    }
    if (f != nullptr) io_ok = (std::fclose(f) == 0) && io_ok;
    if (!io_ok) {
        std::fprintf(stderr, "epb_campaign: cannot write %s\n", csv.c_str());
        return tool_summary_error("io", 2);
    }
    const bool pass = failed == 0 && n_out == 0 && worst <= max_err && n_valid > 0;
    std::printf("cases %llu (cold starts %llu, failed %llu), estimates %llu, valid %llu, valid "
                "outside their bound %llu\nworst |error| of the valid ones %.4f deg (case %llu, "
                "bound %.4f), largest |error|/bound %.3f, largest valid bound %.4f deg\n%s\n",
                (unsigned long long)cases, (unsigned long long)cold, (unsigned long long)failed,
                (unsigned long long)n_est, (unsigned long long)n_valid, (unsigned long long)n_out,
                worst, (unsigned long long)worst_case, worst_bound, worst_ratio, max_valid_bound,
                pass ? "PASS" : "FAIL");
    tool_summary_add("mode", "campaign");
    tool_summary_add("seed", "%llu", (unsigned long long)seed);
    tool_summary_add("first", "%llu", (unsigned long long)first);
    tool_summary_add("cases", "%llu", (unsigned long long)cases);
    tool_summary_add("failed", "%llu", (unsigned long long)failed);
    tool_summary_add("cold_starts", "%llu", (unsigned long long)cold);
    tool_summary_add("estimates", "%llu", (unsigned long long)n_est);
    tool_summary_add("valid", "%llu", (unsigned long long)n_valid);
    tool_summary_add("outside", "%llu", (unsigned long long)n_out);
    tool_summary_add("max_err_deg", "%.4f", worst);
    tool_summary_add("worst_case", "%llu", (unsigned long long)worst_case);
    tool_summary_add("max_err_cold_deg", "%.4f", worst_cold);
    tool_summary_add("max_ratio", "%.3f", worst_ratio);
    tool_summary_add("max_bound_deg", "%.4f", max_valid_bound);
    tool_summary_add("verdict", "%s", pass ? "PASS" : "FAIL");
    return tool_summary_end(pass ? "ok" : "fail", pass ? 0 : 1);
}
