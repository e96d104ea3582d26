// kf_bench - figures of docs/benchmarks.md, "Kalman and tilt" (host tool).
//
//   kf_bench step [--runs R] [--n N] [--seed S] [--k K] [--step-g G] [--c-frac F] [--more 0|1]
//       Tilt steps of 5 and 1 deg (pitch) at 819.2 SPS with engine-idle vibration, passenger
//       bumps and sensor noise (the vibration model below, docs/kalman.md); each accelerometer
//       axis goes through a moving average of N (inclino_avg), the fixed scalar Kalman filter
//       (inclino_kf, n = 1) and the adaptive filter of [CN110567483] (inclino_kf_adapt); pitch is
//       atan2(-a_x, sqrt(a_y^2 + a_z^2)) of the filtered axes (tilt_accel_angles). Prints the rms
//       error after settling and the 10-90 % rise time of the ensemble mean, per filter.
//   kf_bench tune [--runs R] [--n N]
//       The tuning procedure of docs/kalman.md run as a search: prints the best adaptive
//       constants found for the 5 deg step under the noise constraint.
//   kf_bench cost <filter> <count>
//       count updates of one filter, for callgrind (--toggle-collect=<function>):
//       ma, kf1, kf2, kf4, adapt, tilt-feedback, tilt-printed, tilt-kf2.
//
// Vibration model (g, per axis x/y/z; every run draws new phases, bumps and noise):
//   engine idle, 4 cylinders at 750 rpm +-2 % (slow wander, 0.3 Hz): orders 1, 2, 4 at 12.5,
//     25, 50 Hz with amplitudes x 0.004/0.015/0.004, y 0.003/0.010/0.003, z 0.008/0.030/0.008;
//   passengers moving: bumps at random times (Poisson, 0.5 per s), raised-cosine pulses of
//     0.2..0.6 s, amplitude normal with sigma x 0.02, y 0.01, z 0.02 (content below ~5 Hz);
//   sensor white noise 5.7 mg rms (ADIS1636x/1640x, 0.2 mg/sqrt(Hz) at 819.2 SPS), quantised to
//     the 3.333 mg LSB of the part, then converted to Q16 g as the driver does.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <numeric>
#include <random>
#include <string>
#include <vector>

extern "C" {
#include "inclino/avg.h"
#include "inclino/kf.h"
#include "inclino/kf_adapt.h"
#include "inclino/tilt.h"
#include "inclino/tool_cli.h"
#include "inclino/tool_summary.h"
}

namespace
{

constexpr double kFs = 819.2;
constexpr uint32_t kDtNs = 1220703u;
constexpr double kQ16 = 65536.0;
constexpr double kP = 281474976710656.0; // 2^48
constexpr double kLsb = 0.003333;        // ADIS1636x/1640x accelerometer, g per LSB
constexpr double kT0 = 4.0;              // step time, s
constexpr double kDur = 12.0;            // run length, s

int64_t pf(double v)
{
    return static_cast<int64_t>(std::llround(v * kP));
}
int32_t q16(double v)
{
    return static_cast<int32_t>(std::lround(v * kQ16));
}

// One run of accelerometer samples (Q16 g) for a pitch step of `step_deg` at kT0.
std::vector<std::array<int32_t, 3>> make_run(double step_deg, uint64_t seed)
{
    std::mt19937_64 g(seed);
    std::normal_distribution<double> nd(0.0, 1.0);
    std::uniform_real_distribution<double> ud(0.0, 1.0);
    const size_t n = static_cast<size_t>(kDur * kFs);
    const double amp[3][3] = {{0.004, 0.015, 0.004}, {0.003, 0.010, 0.003}, {0.008, 0.030, 0.008}};
    const double order[3] = {1, 2, 4};
    const double bump_sigma[3] = {0.02, 0.01, 0.02};
    double phase[3][3];
    for (auto &a : phase)
        std::generate(std::begin(a), std::end(a), [&] { return 2 * M_PI * ud(g); });
    const double wander_phase = 2 * M_PI * ud(g);
    // bumps: start time, length, amplitude per axis
    struct Bump {
        double t, len, a[3];
    };
    std::vector<Bump> bumps;
    for (double t = -1.0;;) {
        t += -std::log(1.0 - ud(g)) / 0.5;
        if (t > kDur) break;
        Bump b{t,
               0.2 + 0.4 * ud(g),
               {bump_sigma[0] * nd(g), bump_sigma[1] * nd(g), bump_sigma[2] * nd(g)}};
        bumps.push_back(b);
    }
    std::vector<std::array<int32_t, 3>> out(n);
    double crank_angle = 0;
    for (size_t k = 0; k < n; k++) {
        const double t = k / kFs;
        const double th = (t >= kT0 ? step_deg : 0.0) * M_PI / 180;
        const double f_crank = 12.5 * (1 + 0.02 * std::sin(2 * M_PI * 0.3 * t + wander_phase));
        crank_angle += 2 * M_PI * f_crank / kFs;
        double a[3] = {-std::sin(th), 0.0, std::cos(th)};
        for (int ax = 0; ax < 3; ax++) {
            for (int o = 0; o < 3; o++)
                a[ax] += amp[ax][o] * std::sin(order[o] * crank_angle + phase[ax][o]);
            for (const Bump &b : bumps) {
                if (t >= b.t && t < b.t + b.len) {
                    a[ax] += b.a[ax] * 0.5 * (1 - std::cos(2 * M_PI * (t - b.t) / b.len));
                }
            }
            a[ax] += 0.0057 * nd(g);
            const double counts = std::nearbyint(a[ax] / kLsb);
            out[k][ax] = q16(counts * kLsb);
        }
    }
    return out;
}

// A filter applied to the three axes.
struct Filter {
    virtual ~Filter() = default;
    virtual void reset() = 0;
    virtual void push(const std::array<int32_t, 3> &z, std::array<int32_t, 3> *y) = 0;
};

struct MaFilter final : Filter {
    uint32_t n;
    std::vector<int32_t> line[3];
    avg_moving m[3] = {};
    explicit MaFilter(uint32_t n_) : n(n_)
    {
        init();
    }
    void reset() override
    {
        init();
    }
    void init()
    {
        for (int i = 0; i < 3; i++) {
            line[i].assign(n, 0);
            if (avg_moving_init(&m[i], line[i].data(), n, n) != INC_OK) std::abort();
        }
    }
    void push(const std::array<int32_t, 3> &z, std::array<int32_t, 3> *y) override
    {
        for (int i = 0; i < 3; i++) {
            bool full;
            avg_moving_push(&m[i], z[i], &(*y)[i], &full);
        }
    }
};

// The fixed Kalman filter: the generic filter with one state, A = H = 1, constant Q and R.
struct FixedKf final : Filter {
    int64_t q, r, p0;
    kf f[3] = {};
    bool started[3] = {false, false, false};
    fx_q30_t one = FX_Q30_ONE;
    FixedKf(int64_t q_, int64_t r_, int64_t p0_) : q(q_), r(r_), p0(p0_)
    {
    }
    void reset() override
    {
        std::fill(std::begin(started), std::end(started), false);
    }
    void push(const std::array<int32_t, 3> &z, std::array<int32_t, 3> *y) override
    {
        const kf_model m{1, 0, &one, nullptr, &q};
        for (int i = 0; i < 3; i++) {
            if (!started[i]) {
                kf_init(&f[i], 1, &z[i], &p0);
                started[i] = true;
            } else {
                kf_predict(&f[i], &m, nullptr);
                kf_update_row(&f[i], &one, r, z[i]);
            }
            (*y)[i] = kf_x(&f[i], 0);
        }
    }
};

struct AdaptKf final : Filter {
    std::array<kf_adapt_config, 3> c;
    kf_adapt f[3] = {};
    explicit AdaptKf(const std::array<kf_adapt_config, 3> &c_) : c(c_)
    {
        init();
    }
    void reset() override
    {
        init();
    }
    void init()
    {
        for (int i = 0; i < 3; i++)
            if (kf_adapt_init(&f[i], &c[i]) != INC_OK) std::abort();
    }
    void push(const std::array<int32_t, 3> &z, std::array<int32_t, 3> *y) override
    {
        for (int i = 0; i < 3; i++)
            kf_adapt_process(&f[i], z[i], &(*y)[i], nullptr);
    }
};

struct Result {
    double rms = 0, rise = 0, t90 = 0, mean_err = 0, rms_after = 0;
};

Result evaluate(Filter &flt, double step_deg, int runs, uint64_t seed)
{
    const size_t n = static_cast<size_t>(kDur * kFs);
    const size_t k0 = static_cast<size_t>(std::ceil(kT0 * kFs));
    const size_t w0 = static_cast<size_t>((kT0 + 4.0) * kFs); // noise window: 4..8 s after the step
    const size_t a0 = k0 + static_cast<size_t>(0.1 * kFs), a1 = k0 + static_cast<size_t>(1.0 * kFs);
    std::vector<double> mean(n, 0.0);
    double se = 0, sm = 0, sa = 0;
    long cnt = 0, cnta = 0;
    for (int r = 0; r < runs; r++) {
        const auto run = make_run(step_deg, seed + static_cast<uint64_t>(r) * 7919u);
        flt.reset();
        for (size_t k = 0; k < n; k++) {
            std::array<int32_t, 3> y{};
            flt.push(run[k], &y);
            fx_q16_t roll, pitch;
            tilt_accel_angles(y.data(), &roll, &pitch);
            const double p = pitch / kQ16;
            mean[k] += p / runs;
            if (k >= a0 && k < a1) { // just after the step: 0.1 .. 1 s
                sa += (p - step_deg) * (p - step_deg);
                cnta++;
            }
            if (k >= w0) {
                se += (p - step_deg) * (p - step_deg);
                sm += p - step_deg;
                cnt++;
            }
        }
    }
    Result res;
    res.rms = std::sqrt(se / cnt);
    res.mean_err = sm / cnt;
    res.rms_after = std::sqrt(sa / cnta);
    // 10-90 % of the ensemble mean, from the step on (relative to the pre-step mean level)
    double base = 0;
    for (size_t k = k0 - static_cast<size_t>(kFs); k < k0; k++)
        base += mean[k] / kFs;
    size_t k10 = 0, k90 = 0;
    for (size_t k = k0; k < n; k++) {
        const double frac = (mean[k] - base) / step_deg;
        if (!k10 && frac >= 0.1) k10 = k;
        if (!k90 && frac >= 0.9) {
            k90 = k;
            break;
        }
    }
    res.rise = (k90 && k10) ? (k90 - k10) / kFs : NAN;
    res.t90 = k90 ? (k90 - k0) / kFs : NAN;
    return res;
}

// Fixed filter tuned to the moving average's white-noise level: K = 2 / (N + 1) in steady state.
FixedKf make_fixed(uint32_t n)
{
    const double k = 2.0 / (n + 1.0), r = 0.03 * 0.03; // R: total disturbance on x, g^2
    const double q = r * k * k / (1 - k);
    return FixedKf(pf(q), pf(r), pf(r));
}

// Command-line options (tools/lib/cli: decimal, whole field, range-checked; a refusal names the
// option and its range). The ranges keep every derived constant inside the filters' documented
// ranges: N >= 2 (K = 2 / (N + 1) < 1), window k in 2..KF_ADAPT_WIN_MAX, C fraction in [0, 1].
struct Options {
    uint32_t runs = 0, n = 82, k = 32;
    uint64_t seed = 1;
    double stepg = 0.0872, cfrac = 0.1;
    uint32_t more = 0;
};
constexpr uint32_t kRunsMax = 10000;
constexpr uint32_t kNMax = 4096;
constexpr uint64_t kCostMax = 100000000; // updates of `cost` (400 MB of input at most)

// Options from argv[2..]; `allowed` lists the options of the command ("--runs --n ...").
int parse_options(int argc, char **argv, const std::string &allowed, Options *o)
{
    for (int i = 2; i < argc; i++) {
        const std::string name(argv[i]);
        if (name.rfind("--", 0) != 0 || allowed.find(name + " ") == std::string::npos) {
            cli_error("%s: unknown option for '%s' (options: %s)", argv[i], argv[1],
                      allowed.substr(0, allowed.size() - 1).c_str());
            return INC_ERR_INVAL;
        }
        const char *v = cli_value(argc, argv, &i);
        int rc = INC_ERR_INVAL;
        if (v == nullptr) return INC_ERR_INVAL;
        if (name == "--runs") rc = cli_parse_u32("--runs", v, 1, kRunsMax, &o->runs);
        if (name == "--n") rc = cli_parse_u32("--n", v, 2, kNMax, &o->n);
        if (name == "--k") rc = cli_parse_u32("--k", v, 2, KF_ADAPT_WIN_MAX, &o->k);
        if (name == "--seed") rc = cli_parse_u64("--seed", v, 0, UINT64_MAX, &o->seed);
        if (name == "--step-g") rc = cli_parse_double("--step-g", v, 0.0, 2.0, 0, &o->stepg);
        if (name == "--c-frac") rc = cli_parse_double("--c-frac", v, 0.0, 1.0, 0, &o->cfrac);
        if (name == "--more") rc = cli_parse_u32("--more", v, 0, 1, &o->more);
        if (rc != INC_OK) return rc;
    }
    return INC_OK;
}

// ---- the tuning procedure of docs/kalman.md ----------------------------------------------------
//
// Per axis, from a still recording (engine idling, no tilt change):
//   sz2  = variance of the samples (the measurement noise the filter sees, vibration included)
//   mdz  = mean |dz| for the chosen window k
// and from the requirements:
//   Ks   = steady-state gain for the noise target (2 / (N + 1): the white-noise level of a moving
//          average of N)
//   step = the smallest change (on this axis, in g) that must be followed at full speed
// the constants are
//   A  = sz2                         (R at rest)
//   Qr = Ks^2 A / (1 - Ks)           (the Q that gives Ks at rest: P- = Qr / Ks, K = P-/(P- + A))
//   C  = Qr * c_frac,  D = Qr (1 - c_frac) / mdz   (Q at rest = Qr on average)
//   Qs = C + D * step,  B = -A / Qs  (R falls to 0 where |dz| reaches `step`: gain -> 1)
//   p0 = A
struct AxisStats {
    double sz2 = 0, mdz = 0;
};

AxisStats still_stats(int axis, uint32_t k, int runs, uint64_t seed)
{
    AxisStats st;
    long cnt = 0;
    double s1 = 0, s2 = 0, sdz = 0;
    for (int r = 0; r < runs; r++) {
        const auto run = make_run(0.0, seed + 1000003u * static_cast<uint64_t>(r + 1));
        std::vector<double> win;
        for (const auto &smp : run) {
            const double z = smp[axis] / kQ16;
            s1 += z;
            s2 += z * z;
            win.push_back(z);
            if (win.size() > k) win.erase(win.begin());
            if (win.size() == k) {
                const double sum = std::accumulate(win.begin(), win.end(), 0.0);
                sdz += std::fabs((k * z - sum) / (k - 1));
            }
            cnt++;
        }
    }
    st.sz2 = s2 / cnt - (s1 / cnt) * (s1 / cnt);
    st.mdz = sdz / cnt;
    return st;
}

kf_adapt_config tune_axis(const AxisStats &st, uint32_t k, double ks, double step, double c_frac)
{
    const double a = st.sz2, qr = ks * ks * a / (1 - ks);
    kf_adapt_config cfg{};
    cfg.window = k;
    cfg.a = pf(a);
    cfg.p0 = pf(a);
    if (step <= 0) {
        // No change on this axis needs following fast: a fixed filter (D = 0, B = 0, Q = Qr).
        cfg.c = pf(qr);
        cfg.d = 0;
        cfg.b = 0;
        return cfg;
    }
    const double c = std::max(qr * c_frac, 1.0 / kP), d = qr * (1 - c_frac) / st.mdz;
    const double qs = c + d * step;
    cfg.c = pf(c);
    cfg.d = static_cast<int64_t>(std::llround(d * 4294967296.0));
    cfg.b = q16(std::max(-32767.0, -a / qs));
    return cfg;
}

// The tuning of the figures: window 32, C = 10 % of Qr, Ks = 2 / (N + 1); x and y follow a 5 deg
// tilt change at full speed (step sin 5 deg = 0.0872 g), z needs no speed (a 5 deg tilt changes
// it by 1 - cos 5 deg = 0.004 g): a fixed filter. Statistics from 20 still runs.
std::array<kf_adapt_config, 3> adapt_tuned(uint32_t n, uint32_t k, double step, double c_frac,
                                           uint64_t seed, double ks_mult = 1.0)
{
    std::array<kf_adapt_config, 3> c;
    for (int ax = 0; ax < 3; ax++) {
        c[ax] = tune_axis(still_stats(ax, k, 20, seed), k, ks_mult * 2.0 / (n + 1.0),
                          ax == 2 ? 0.0 : step, c_frac);
    }
    return c;
}

int usage_error()
{
    tool_summary_add("error", "usage");
    return 2;
}

// Every axis's constants accepted by kf_adapt_init (the filters would refuse them otherwise).
bool configs_valid(const std::array<kf_adapt_config, 3> &c)
{
    for (const auto &cfg : c) {
        kf_adapt f{};
        if (kf_adapt_init(&f, &cfg) != INC_OK) return false;
    }
    return true;
}

int cmd_tune(int argc, char **argv)
{
    Options o;
    o.runs = 30;
    if (parse_options(argc, argv, "--runs --n --seed ", &o) != INC_OK) return usage_error();
    const int runs = static_cast<int>(o.runs);
    const uint32_t n = o.n;
    const uint64_t seed = o.seed;
    MaFilter ma(n);
    const Result rm = evaluate(ma, 5.0, runs, seed);
    std::printf("moving average N = %u: rms %.4f deg, rise %.1f ms\n", n, rm.rms, rm.rise * 1e3);
    unsigned goals = 0;
    for (uint32_t k : {8u, 16u, 24u, 32u})
        for (double km : {0.75, 1.0})
            for (double st : {0.0, 0.04, 0.06, 0.0872, 0.12})
                for (double cf : {0.0, 0.1}) {
                    const auto cfg = adapt_tuned(n, k, st, cf, seed + 99991u, km);
                    if (!configs_valid(cfg)) continue; // not a filter kf_adapt accepts
                    AdaptKf ak(cfg);
                    const Result r = evaluate(ak, 5.0, runs, seed);
                    std::printf("k %2u Ks x %.2f step %.3f Cfrac %.1f: rms %.4f rise %.1f ms%s\n",
                                k, km, st, cf, r.rms, r.rise * 1e3,
                                (r.rms <= rm.rms && r.rise <= rm.rise / 4) ? "  GOAL" : "");
                    if (r.rms <= rm.rms && r.rise <= rm.rise / 4) goals++;
                    std::fflush(stdout);
                }
    tool_summary_add("ma_rms_deg", "%.4f", rm.rms);
    tool_summary_add("ma_rise_ms", "%.1f", rm.rise * 1e3);
    tool_summary_add("goals", "%u", goals);
    return 0;
}

int cmd_step(int argc, char **argv)
{
    Options o;
    o.runs = 100;
    if (parse_options(argc, argv, "--runs --n --seed --k --step-g --c-frac --more ", &o) != INC_OK)
        return usage_error();
    const int runs = static_cast<int>(o.runs);
    const uint32_t n = o.n;
    const uint64_t seed = o.seed;
    const uint32_t k = o.k;
    const double stepg = o.stepg;
    const double cfrac = o.cfrac;
    const auto ac = adapt_tuned(n, k, stepg, cfrac, seed + 99991u);
    if (!configs_valid(ac)) {
        cli_error("the tuned adaptive filter is outside kf_adapt's ranges (--k %u, --step-g %g, "
                  "--c-frac %g)",
                  k, stepg, cfrac);
        tool_summary_add("error", "ERR_INVAL");
        return 1;
    }
    MaFilter ma(n);
    FixedKf fk = make_fixed(n);
    AdaptKf ak(ac);
    std::printf("runs %d, N %u; adaptive: window %u, step %.3f g, C fraction %.2f\n", runs, n, k,
                stepg, cfrac);
    for (int ax = 0; ax < 3; ax++) {
        std::printf("  axis %c: C %.4g g^2, D %.4g g, A %.4g g^2, B %.4f, p0 %.4g g^2\n", "xyz"[ax],
                    ac[ax].c / kP, ac[ax].d / 4294967296.0, ac[ax].a / kP, ac[ax].b / kQ16,
                    ac[ax].p0 / kP);
    }
    std::printf(
        "| step | filter | rms error 4..8 s after (deg) | mean error (deg) | rms error 0.1..1 s after (deg) | 10-90 %% rise (ms) | step to 90 %% (ms) |\n");
    std::printf("|---|---|---:|---:|---:|---:|---:|\n");
    std::vector<double> steps = {5.0, 1.0};
    if (o.more != 0u) steps = {5.0, 1.0, 2.0, 10.0, 20.0};
    for (double step : steps) {
        Filter *fs[3] = {&ma, &fk, &ak};
        const char *names[3] = {"moving average", "fixed Kalman", "adaptive Kalman"};
        for (int i = 0; i < 3; i++) {
            const Result r = evaluate(*fs[i], step, runs, seed);
            char nm[40];
            std::snprintf(nm, sizeof nm, i == 0 ? "%s N = %u" : "%s", names[i], n);
            std::printf("| %.0f deg | %s | %.4f | %+.4f | %.4f | %.1f | %.1f |\n", step, nm, r.rms,
                        r.mean_err, r.rms_after, r.rise * 1e3, r.t90 * 1e3);
            if (step == 5.0) { // the 5 deg step's figures, per filter
                static const char *const key[3] = {"ma", "kf", "adapt"};
                char kk[40];
                std::snprintf(kk, sizeof kk, "%s_rms_deg", key[i]);
                tool_summary_add(kk, "%.4f", r.rms);
                std::snprintf(kk, sizeof kk, "%s_rise_ms", key[i]);
                tool_summary_add(kk, "%.1f", r.rise * 1e3);
            }
        }
    }
    return 0;
}

// ---- cost (callgrind) -------------------------------------------------------------------------

int cmd_cost(const char *which, const char *count_text)
{
    uint64_t count64 = 0;
    if (cli_parse_u64("COUNT", count_text, 1, kCostMax, &count64) != INC_OK) return usage_error();
    const long count = static_cast<long>(count64);
    std::mt19937 g(5);
    std::normal_distribution<double> nd(0.0, 1.0);
    std::vector<int32_t> z(static_cast<size_t>(count));
    std::generate(z.begin(), z.end(), [&] { return q16(0.01 * nd(g)); });
    int32_t sink = 0;
    const std::string w(which);
    if (w == "ma") {
        std::vector<int32_t> line(82);
        avg_moving m;
        avg_moving_init(&m, line.data(), 82, 82);
        for (long i = 0; i < count; i++) {
            int32_t y;
            bool full;
            avg_moving_push(&m, z[i], &y, &full);
            sink += y;
        }
    } else if (w == "kf1" || w == "kf2" || w == "kf4") {
        const unsigned n = w == "kf1" ? 1 : (w == "kf2" ? 2 : 4);
        const int32_t one = FX_Q30_ONE, dt = 1310720; // 5/4096 s
        int64_t p0[16] = {0}, q[16] = {0};
        fx_q30_t a[16] = {0}, b[4] = {0}, h[4] = {one, 0, 0, 0};
        for (unsigned i = 0; i < n; i++) {
            a[i * n + i] = one;
            p0[i * n + i] = pf(1.0);
            q[i * n + i] = pf(1e-6);
        }
        if (n >= 2) { // angle/bias (kf2) or two of them (kf4)
            a[0 * n + 1] = -dt;
            b[0] = dt;
        }
        if (n == 4) {
            a[2 * n + 3] = -dt;
            b[2] = dt;
        }
        kf f;
        kf_init(&f, n, nullptr, p0);
        const kf_model m{static_cast<uint8_t>(n), static_cast<uint8_t>(n >= 2 ? 1 : 0), a, b, q};
        const int64_t r = pf(0.25);
        for (long i = 0; i < count; i++) {
            const int32_t u = z[i];
            kf_predict(&f, &m, &u);
            kf_update_row(&f, h, r, z[i]);
            sink += kf_x(&f, 0);
        }
    } else if (w == "adapt") {
        kf_adapt f;
        kf_adapt_config c{};
        c.window = 8;
        c.c = pf(1e-8);
        c.d = static_cast<int64_t>(std::llround(1e-6 * 4294967296.0));
        c.a = pf(2.5e-4);
        c.b = -q16(0.5);
        c.p0 = pf(2.5e-4);
        kf_adapt_init(&f, &c);
        for (long i = 0; i < count; i++) {
            int32_t y;
            kf_adapt_process(&f, z[i], &y, nullptr);
            sink += y;
        }
    } else if (w.rfind("tilt-", 0) == 0) {
        tilt_config c;
        tilt_config_default(&c, kDtNs);
        c.mode = w == "tilt-feedback"
                     ? TILT_MODE_FEEDBACK
                     : (w == "tilt-printed" ? TILT_MODE_SEED_PRINTED : TILT_MODE_KF2);
        tilt t;
        tilt_init(&t, &c);
        for (long i = 0; i < count; i++) {
            tilt_input in{};
            in.accel_g[0] = q16(-0.05) + z[i];
            in.accel_g[1] = q16(0.02) - z[i];
            in.accel_g[2] = q16(0.998) + z[(i + 1) % count];
            in.gyro_dps[0] = q16(0.5) + 30 * z[i];
            in.gyro_dps[1] = q16(-0.2) - 30 * z[i];
            tilt_output o;
            tilt_step(&t, &in, kDtNs, &o);
            sink += o.angle_deg[0];
        }
    } else {
        std::fprintf(stderr, "unknown filter %s\n", which);
        tool_summary_add("error", "unknown-filter");
        return 2;
    }
    std::printf("%s: %ld updates (checksum %d)\n", which, count, static_cast<int>(sink));
    tool_summary_add("filter", "%s", which);
    tool_summary_add("updates", "%ld", count);
    tool_summary_add("checksum", "%d", static_cast<int>(sink));
    return 0;
}

} // namespace

int run_command(int argc, char **argv)
{
    if (argc >= 2) tool_summary_add("command", "%s", argv[1]);
    if (argc >= 2 && std::strcmp(argv[1], "step") == 0) return cmd_step(argc, argv);
    if (argc >= 2 && std::strcmp(argv[1], "tune") == 0) return cmd_tune(argc, argv);
    if (argc == 4 && std::strcmp(argv[1], "cost") == 0) return cmd_cost(argv[2], argv[3]);
    std::fprintf(stderr,
                 "usage: kf_bench step [--runs 1..10000] [--n 2..4096] [--seed S] [--k 2..%u]\n"
                 "                     [--step-g 0..2] [--c-frac 0..1] [--more 0|1]\n"
                 "       kf_bench tune [--runs 1..10000] [--n 2..4096] [--seed S]\n"
                 "       kf_bench cost ma|kf1|kf2|kf4|adapt|tilt-feedback|tilt-printed|tilt-kf2 "
                 "COUNT(1..%llu)\n",
                 static_cast<unsigned>(KF_ADAPT_WIN_MAX),
                 static_cast<unsigned long long>(kCostMax));
    tool_summary_add("error", "usage");
    return 2;
}

// The last line on stdout is the summary (docs/tool-summary.md).
int main(int argc, char **argv)
{
    tool_summary_begin("kf_bench");
    cli_set_program("kf_bench");
    const int st = run_command(argc, argv);
    return tool_summary_end(st == 0 ? "ok" : "error", st);
}
