// Simulated calibration benches for the station's fit (tools/calstation, docs/calibration.md
// 4.3): a hand-placed cube (every face off its nominal direction by 1..2 deg in a random
// direction), a cube whose faces are not orthogonal, and the precise positioner. Each bench's
// residuals are asserted: the face-mean | |a| - 1 g | through the firmware's fixed-point
// correction (<= 0.05 mg on the hand-placed faces), never worse than the per-axis pair method on
// the same data (computed here, independently of the tool: each axis's offset and gain from its
// own face pair), and the positioner's result unchanged (0.51 mg on the +-30 deg tilt rows).
// Host only (C++/Eigen).
#include "inclino/calstation/fit.hpp"
#include "inclino/calstation/record.hpp"
#include "inclino/calstation/samples.hpp"
#include "unit.h"

#include <cmath>
#include <cstdio>
#include <numeric>

using namespace calstation;

namespace
{

// The per-axis pair method written out: offset_i = (A+_i + A-_i)/2, gain_i = (A+_i - A-_i)/2
// from axis i's own faces; a_i = (r_i - offset_i) / gain_i. The face-mean residual, mg (rms and
// max over the six faces of | |a| - 1 g |).
void pair_method(const Station &st, double &rms, double &max)
{
    std::array<double, 3> pos{}, neg{};
    for (const auto &r : st.rows) {
        for (int i = 0; i < 3; i++) {
            if (r.u[i] > 0.999) pos[i] = r.v[i] * st.acc_lsb_g;
            if (r.u[i] < -0.999) neg[i] = r.v[i] * st.acc_lsb_g;
        }
    }
    double ss = 0.0;
    int n = 0;
    max = 0.0;
    for (const auto &r : st.rows) {
        double m2 = 0.0;
        for (int i = 0; i < 3; i++) {
            const double a = (r.v[i] * st.acc_lsb_g - 0.5 * (pos[i] + neg[i])) /
                             (0.5 * (pos[i] - neg[i]));
            m2 += a * a;
        }
        const double e = (std::sqrt(m2) - 1.0) * 1e3;
        ss += e * e;
        max = std::fmax(max, std::fabs(e));
        n++;
    }
    rms = std::sqrt(ss / n);
}

struct Bench {
    double fw_rms_mg, fw_max_mg, pair_rms_mg, pair_max_mg;
    CalResult c;
};

// REQUIRE for a function that returns a value: the check counts, the bench stops.
#define NEED(cond)             \
    do {                       \
        CHECK(cond);           \
        if (!(cond)) return b; \
    } while (0)

Bench run_bench(const SimConfig &sc, FitOptions opt = FitOptions{})
{
    const Station st = simulate_station(sc);
    Bench b{};
    opt.tmodel_auto = true;
    const std::string e = fit_station(st, opt, b.c);
    NEED(e.empty());
    struct calrec rec;
    NEED(to_calrec(b.c, st, rec).empty());
    FwCheck fw;
    NEED(firmware_check(st, rec, fw).empty());
    b.fw_rms_mg = fw.mag_rms_mg;
    b.fw_max_mg = fw.mag_max_mg;
    pair_method(st, b.pair_rms_mg, b.pair_max_mg);
    return b;
}

SimConfig hand(uint64_t seed, double deg, double nonortho)
{
    SimConfig sc;
    sc.part = SimPart{true, 0};
    sc.schedule = Schedule::Hand;
    sc.samples = 1024; // 10 s at 102.4 Hz per face
    sc.rate_sps = 102.4;
    sc.placement_deg = deg;
    sc.placement_seed = seed;
    sc.noise_seed = seed;
    sc.nonortho_deg = nonortho;
    return sc;
}

} // namespace

static void test_hand_placed()
{
    // Eight cubes placed by hand, each face 1..2 deg off in a random direction.
    double worst = 0.0, worst_pair = 1e9;
    for (uint64_t seed = 1; seed <= 8; seed++) {
        const Bench b = run_bench(hand(seed, 2.0, 0.0));
        std::printf("hand-placed seed %llu: firmware face-mean rms %.4f max %.4f mg; pair method "
                    "rms %.4f max %.4f mg; nominal fit rms %.3f mg; placement max %.2f deg\n",
                    static_cast<unsigned long long>(seed), b.fw_rms_mg, b.fw_max_mg, b.pair_rms_mg,
                    b.pair_max_mg, b.c.res_nominal.mag_rms_mg, b.c.res_chosen.ang_max_deg);
        CHECK(b.c.method == FitMethod::Magnitude);
        CHECK(!b.c.warnings.empty()); // the placement is reported
        CHECK(b.fw_max_mg <= 0.05);
        CHECK(b.fw_rms_mg <= b.pair_rms_mg);
        CHECK(b.c.res_magnitude.mag_rms_mg <= b.c.res_pair.mag_rms_mg);
        // The placement the tool reports is the simulated one (1..2 deg per face).
        CHECK(b.c.res_chosen.ang_max_deg > 0.9 && b.c.res_chosen.ang_max_deg < 2.6);
        // The nominal-direction fit alone misses 1 g by mg (the 1.1 mg on a real cube).
        CHECK(b.c.res_nominal.mag_rms_mg > 1.0);
        worst = std::fmax(worst, b.fw_max_mg);
        worst_pair = std::fmin(worst_pair, b.pair_rms_mg);
    }
    std::printf("hand-placed, 8 cubes: worst face-mean %.4f mg; best pair-method rms %.4f mg\n",
                worst, worst_pair);
}

static void test_non_orthogonal_cube()
{
    // A cube whose faces lean 1 deg (opposite faces parallel), placed precisely, then also
    // by hand.
    for (double place : {0.0, 2.0}) {
        const Bench b = run_bench(hand(11, place, 1.0));
        std::printf("non-orthogonal cube (1 deg), placement %.0f deg: face-mean rms %.4f max %.4f "
                    "mg; pair rms %.4f max %.4f mg; fit %s\n",
                    place, b.fw_rms_mg, b.fw_max_mg, b.pair_rms_mg, b.pair_max_mg,
                    fit_method_name(b.c.method));
        CHECK(b.c.method == FitMethod::Magnitude);
        CHECK(b.fw_max_mg <= 0.05);
        CHECK(b.fw_rms_mg <= b.pair_rms_mg + 0.02);
    }
}

static void test_positioner()
{
    // The precise positioner (part A's full calibration schedule): the nominal fit is kept and
    // nothing warns; the firmware's result on the +-30 deg tilt rows stays 0.51 mg or better.
    SimConfig sc;
    sc.part = SimPart{true, 0};
    FitOptions opt;
    const Station st = simulate_station(sc);
    CalResult c;
    REQUIRE(fit_station(st, opt, c).empty());
    CHECK(c.method == FitMethod::Nominal);
    CHECK(c.warnings.empty());
    struct calrec rec;
    REQUIRE(to_calrec(c, st, rec).empty());
    FwCheck fw;
    REQUIRE(firmware_check(st, rec, fw).empty());
    std::printf(
        "positioner: tilt rows %.3f mg; | |a|-1g | rms %.4f mg (tool's pair method %.4f mg); "
        "nominal fit against the directions %.4f mg, magnitude fit %.4f mg\n",
        fw.max_tilt_err_mg, fw.mag_rms_mg, c.res_pair.mag_rms_mg, c.res_nominal.dir_rms_mg,
        c.res_magnitude.mag_rms_mg);
    CHECK(fw.max_tilt_err_mg <= 0.51);
    CHECK(c.res_nominal.dir_rms_mg < 2.0 * c.res_nominal.mag_rms_mg + 0.05);
    CHECK(c.res_nominal.mag_rms_mg <= c.res_pair.mag_rms_mg);
}

static void test_samples_path()
{
    // The hand-placed session as raw samples in m/s^2 with the moves between faces: the
    // stillness detection finds the six faces, and the firmware on every sample gives the
    // face means of the fit.
    SimConfig sc = hand(5, 2.0, 0.0);
    sc.keep_samples = true;
    const Station sim = simulate_station(sc);
    const std::string csv = format_samples(sim, kStandardGravity, false);
    SampleFile sf;
    REQUIRE(parse_samples(csv, kStandardGravity, sf).empty());
    CHECK_EQ_INT(sf.acc_g.size(), sim.samples.size());
    const std::vector<Segment> seg = find_segments(sf, 0);
    CHECK_EQ_INT(seg.size(), 6);
    Station st;
    size_t skipped = 9;
    REQUIRE(station_from_segments(sf, seg, 25.0, st, skipped).empty());
    CHECK_EQ_INT(skipped, 0);
    const int seen = std::accumulate(seg.begin(), seg.end(), 0, [](int acc, const Segment &g) {
        return acc | 1 << (2 * g.axis + (g.sign < 0));
    });
    CHECK_EQ_INT(seen, 63);
    st.have_binding = true;
    st.binding = {CALREC_FAMILY_GENERIC, 1, 0, 0, 0, 0};
    FitOptions opt;
    opt.tmodel_auto = true;
    CalResult c;
    REQUIRE(fit_station(st, opt, c).empty());
    struct calrec rec;
    REQUIRE(to_calrec(c, st, rec).empty());
    std::vector<std::array<double, 3>> out;
    size_t range = 1;
    REQUIRE(apply_firmware(rec, sf.acc_g, {}, 25.0, out, range).empty());
    CHECK_EQ_INT(range, 0);
    const FaceResidual before = face_residual(sf.acc_g, seg), after = face_residual(out, seg);
    std::printf(
        "samples: %zu, faces %zu, face-mean before rms %.3f mg, after rms %.4f max %.4f mg\n",
        sf.acc_g.size(), after.faces, before.rms_mg, after.rms_mg, after.max_mg);
    CHECK(before.rms_mg > 10.0);
    CHECK(after.max_mg <= 0.05);
    // Bad sample files.
    SampleFile bad;
    CHECK(parse_samples("", 1.0, bad).find("empty") != std::string::npos);
    CHECK(parse_samples("t,foo\n0,1\n", 1.0, bad).find("no acceleration column") !=
          std::string::npos);
    CHECK(parse_samples("ax,ay,az\n1,2\n", 1.0, bad).find("fields") != std::string::npos);
    CHECK(parse_samples("ax,ay,az\n1,nan,0\n", 1.0, bad).find("not a finite") != std::string::npos);
    CHECK(parse_samples("ax,ay,az\n100,0,0\n", 1.0, bad).find("64 g") != std::string::npos);
    CHECK(parse_samples("ax [m/s^2],AY,acc_z_mps2,temp_c\n9.8,0,0,25\n", kStandardGravity, bad)
              .empty());
    CHECK_EQ_INT(bad.col_temp, 3);
}

static void test_refusals_and_flags()
{
    // A placeholder temperature far from t_ref is refused (not a zeroed report).
    Station st = simulate_station(hand(2, 0.0, 0.0));
    for (auto &r : st.rows)
        r.temp_c = 0.0;
    FitOptions opt;
    opt.tmodel_auto = true;
    CalResult c;
    CHECK(fit_station(st, opt, c).find("placeholder temperature") != std::string::npos);
    // The same value at t_ref is accepted; one temperature gives no temperature model.
    st.t_ref_c = 0.0;
    REQUIRE(fit_station(st, opt, c).empty());
    CHECK(c.one_temperature);
    CHECK(c.acc_tbias[0].kind == TKind::None);
    CHECK(!c.have_gyro);
    CHECK(c.report.find("gyro: not calibrated") != std::string::npos);
    CHECK(c.report.find("n/a") != std::string::npos); // no tilt rows
    // Forcing the nominal fit on a hand-placed cube warns that it misses 1 g.
    opt.method = FitMethod::Nominal;
    const Station hs = simulate_station(hand(3, 2.0, 0.0));
    REQUIRE(fit_station(hs, opt, c).empty());
    CHECK(c.method == FitMethod::Nominal);
    CHECK_EQ_INT(c.warnings.size(), 2);
}

int main()
{
    UNIT_RUN(test_hand_placed);
    UNIT_RUN(test_non_orthogonal_cube);
    UNIT_RUN(test_positioner);
    UNIT_RUN(test_samples_path);
    UNIT_RUN(test_refusals_and_flags);
    return unit_report();
}
