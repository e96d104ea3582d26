// The calibration station end to end (tools/calstation): a simulated part measured on the
// simulated station, fitted, and checked against the part's true errors; and [TEMP-LORENTZ]'s
// comparison with the goal of the best model (<= 0.5 mg, <= 5 ppm/degC) on two parts, in-sample
// and held out. Host only (C++/Eigen).
#include "inclino/calstation/compare.hpp"
#include "inclino/calstation/fit.hpp"
#include "inclino/calstation/record.hpp"
#include "inclino/sim/calpart.h"
#include "unit.h"

#include <cmath>
#include <cstdio>

using namespace calstation;

namespace
{

// What the part reports (g, before quantisation, no noise) for specific force f at T, m = 0.
std::array<double, 3> truth_reading(const sim_calpart_params &p, const std::array<double, 3> &f,
                                    double t)
{
    std::array<double, 3> r{};
    for (int i = 0; i < 3; i++) {
        const double x = p.acc_axis[i][0] * f[0] + p.acc_axis[i][1] * f[1] +
                         p.acc_axis[i][2] * f[2];
        const double h = x + p.acc_nl2[i] * x * x + p.acc_nl3[i] * x * x * x;
        r[i] = sim_calpart_tcurve_eval(&p.acc_bias[i], t, 0.0) +
               sim_calpart_tcurve_eval(&p.acc_scale[i], t, 0.0) * h;
    }
    return r;
}

// Worst |corrected - true| (g) over tilts within +-max_deg about x and y, over temperatures.
double worst_error(const CalResult &c, const sim_calpart_params &p, double max_deg, double t_lo,
                   double t_hi, bool with_nonlin = true, bool with_misalign = true)
{
    CalResult cc = c;
    for (int i = 0; i < 3; i++) {
        if (!with_nonlin) cc.acc_nonlin[i] = {0, 0, 0, 0};
        if (!with_misalign) {
            for (int j = 0; j < 3; j++)
                cc.acc_misalign[i][j] = (i == j);
        }
    }
    double worst = 0.0;
    const double k = 3.14159265358979323846 / 180.0;
    for (double t = t_lo; t <= t_hi + 1e-9; t += 5.0) {
        for (double ax = -max_deg; ax <= max_deg + 1e-9; ax += max_deg / 6.0) {
            for (double ay = -max_deg; ay <= max_deg + 1e-9; ay += max_deg / 6.0) {
                const std::array<double, 3> f = {std::sin(ay * k),
                                                 -std::sin(ax * k) * std::cos(ay * k),
                                                 std::cos(ax * k) * std::cos(ay * k)};
                const auto o = apply_double(cc, truth_reading(p, f, t), t);
                for (int i = 0; i < 3; i++)
                    worst = std::fmax(worst, std::fabs(o[i] - f[i]));
            }
        }
    }
    return worst;
}

} // namespace

static void test_part_a_end_to_end()
{
    SimConfig sc;
    sc.part = SimPart{true, 0};
    const Station st = simulate_station(sc);
    // The station file round trip is lossless enough for the fit (format_station's digits).
    Station back;
    CHECK_EQ_INT(parse_station(format_station(st), back).size(), 0);
    CHECK_EQ_INT(back.rows.size(), st.rows.size());

    CalResult c;
    const std::string e = fit_station(back, FitOptions{}, c);
    REQUIRE(e.empty());
    std::fputs(c.report.c_str(), stdout);
    sim_calpart_params p;
    sim_calpart_paper(&p);

    // Offsets: the true bias at 25 degC (the flip offset also carries the nonlinearity's even
    // part, nl2 = 8 mg, which the nonlinearity fit moves back out).
    for (int i = 0; i < 3; i++) {
        CHECK_NEAR(c.acc_offset[i], sim_calpart_tcurve_eval(&p.acc_bias[i], 25.0, 0.0), 0.0003);
        CHECK(c.acc_tbias[i].kind == TKind::LorentzCubic);
        CHECK(c.acc_tscale[i].kind == TKind::LorentzCubic);
        CHECK_NEAR(c.acc_tbias[i].eval(25.0), 0.0, 1e-12);
        CHECK_NEAR(c.acc_tscale[i].eval(25.0), 0.0, 1e-12);
    }
    CHECK(c.have_nonlin);
    // Whole correction over -20..60 degC, tilts within +-30 deg about both axes ([ADI-EPB]'s EPB
    // range): within 0.6 mg (0.034 deg of tilt). What is left is mostly the cubic's truncation of
    // the inverse element nonlinearity (its v^4 term, 5*nl2*nl3 = 0.5 mg at 1 g) and the
    // temperature models' residual.
    const double full = worst_error(c, p, 30.0, -20.0, 60.0);
    const double at25 = worst_error(c, p, 30.0, 25.0, 25.0);
    // [ADI-EPB]'s two-point flip alone (ambient block: offset and gain, no misalignment, no
    // nonlinearity, no temperature model) for comparison.
    CalResult flip = c;
    for (int i = 0; i < 3; i++) {
        flip.acc_offset[i] = c.blocks[0].bias[i];
        flip.acc_gain[i] = c.blocks[0].scale[i];
        flip.acc_tbias[i] = TModel{};
        flip.acc_tscale[i] = TModel{};
        flip.acc_nonlin[i] = {0, 0, 0, 0};
        for (int j = 0; j < 3; j++)
            flip.acc_misalign[i][j] = (i == j);
    }
    const double two_point = worst_error(flip, p, 30.0, 25.0, 25.0);
    std::printf("worst error within +-30 deg: %.3f mg over -20..60 degC, %.3f mg at 25 degC; "
                "two-point flip only at 25 degC: %.3f mg\n",
                full * 1e3, at25 * 1e3, two_point * 1e3);
    CHECK(full < 0.0006);
    CHECK(at25 < 0.00045);
    CHECK(two_point > 0.008);
    // The record: quantised, bound to the part, encoded; it decodes to the same words; the
    // firmware's fixed-point correction on the station rows stays within the stated end-to-end
    // bound of the double model (cal.h: <= 5 LSB typical) and within 0.6 mg of the truth on
    // the +-30 deg tilt rows (noise of the 2000-sample means included).
    {
        struct calrec rec, dec;
        REQUIRE(to_calrec(c, back, rec).empty());
        std::vector<uint8_t> img;
        REQUIRE(encode_record(rec, 9u, img).empty());
        CHECK_EQ_INT(img.size(), CALREC_IMAGE_SIZE);
        uint32_t seq = 0;
        CHECK_OK(calrec_decode(img.data(), img.size(), &rec.binding, &dec, &seq));
        CHECK_EQ_INT(seq, 9);
        CHECK_EQ_INT(dec.acc_tbias[2].kind, CALREC_TM_LORENTZ_CUBIC);
        CHECK_EQ_INT(dec.acc_gain[1], rec.acc_gain[1]);
        CHECK_EQ_INT(dec.acc_misalign[0][2], rec.acc_misalign[0][2]);
        FwCheck fw;
        REQUIRE(firmware_check(back, dec, fw).empty());
        std::printf(
            "firmware check: %zu rows, max |fw - double| %.2f LSB, max error %.3f mg, tilt rows %.3f mg\n",
            fw.rows, fw.max_lsb, fw.max_err_mg, fw.max_tilt_err_mg);
        CHECK(fw.rows == 996);
        CHECK(fw.max_lsb <= 5.0);
        CHECK(fw.max_tilt_err_mg < 0.6);
        // Round trip of the coefficients within half an LSB of their format.
        const CalResult d = from_calrec(dec);
        for (int i = 0; i < 3; i++) {
            CHECK_NEAR(d.acc_offset[i], c.acc_offset[i], 0.5 / 65536.0);
            CHECK_NEAR(d.acc_gain[i], c.acc_gain[i], 0.5 / 1073741824.0);
            CHECK_NEAR(d.gyro_scale[i], c.gyro_scale[i], 0.5 / 1073741824.0);
            CHECK_NEAR(d.acc_tbias[i].eval(-5.0), c.acc_tbias[i].eval(-5.0), 2e-5);
        }
    }
    // Gyro: offset from the 100 s still interval, scale from +-360 deg turns.
    REQUIRE(c.have_gyro);
    for (int i = 0; i < 3; i++) {
        CHECK_NEAR(c.gyro_offset[i], p.gyro_bias_dps[i], 0.002);
        CHECK_NEAR(c.gyro_scale[i], p.gyro_scale[i], 2e-4);
    }
}

static void test_ambient_only()
{
    // No chamber: --tmodel none gives an ambient calibration; "best" refuses (one temperature).
    SimConfig sc;
    sc.schedule = Schedule::Ambient;
    sc.samples = 500;
    const Station st = simulate_station(sc);
    CalResult c;
    FitOptions o;
    std::string e = fit_station(st, o, c);
    CHECK(e.find("one temperature only") != std::string::npos);
    o.tmodel = TChoice::None;
    e = fit_station(st, o, c);
    REQUIRE(e.empty());
    sim_calpart_params p;
    sim_calpart_paper(&p);
    CHECK(worst_error(c, p, 30.0, 25.0, 25.0) < 0.0008);
    CHECK(c.acc_tbias[0].kind == TKind::None);
}

static void test_compare_goal()
{
    // [TEMP-LORENTZ] reproduced: part A and a seeded part B, fitted from their own data.
    std::vector<CompareAxis> rows;
    CompareConfig cfg;
    if (UNIT_SANITIZED) {
        // The sanitizer build runs the same code paths on one chamber cycle of part A (the
        // figures below need the full ten cycles; the host build asserts them).
        cfg.cycles = 1;
        cfg.validation_cycles = 1;
        REQUIRE(compare_part(SimPart{true, 0}, cfg, rows).empty());
        REQUIRE(rows.size() == 3);
        for (const auto &r : rows) {
            CHECK(r.bias[0].in_sample > 13.0 && r.bias[0].in_sample < 15.0);
        }
        return;
    }
    REQUIRE(compare_part(SimPart{true, 0}, cfg, rows).empty());
    REQUIRE(compare_part(SimPart{false, 2}, cfg, rows).empty());
    std::fputs(format_compare(rows).c_str(), stdout);
    REQUIRE(rows.size() == 6);
    const int best = 5, linear = 1, lorentz = 3, firmware = CompareAxis::kCells - 1;
    for (const auto &r : rows) {
        // The best model as the firmware evaluates it (quantised record, fixed point) meets the
        // goal too, within 0.02 mg / 0.05 ppm/degC of the double-precision fit.
        CHECK(r.bias[firmware].ok && r.scale[firmware].ok);
        CHECK(r.bias[firmware].in_all <= 0.5 && r.bias[firmware].held_out <= 0.5);
        CHECK(r.scale[firmware].in_all <= 5.0 && r.scale[firmware].held_out <= 5.0);
        CHECK_NEAR(r.bias[firmware].in_sample, r.bias[best].in_sample, 0.02);
        CHECK_NEAR(r.scale[firmware].in_sample, r.scale[best].in_sample, 0.05);
        // Goal: best model <= 0.5 mg and <= 5 ppm/degC, in the paper's definition, over every
        // soak (with hysteresis and noise), and held out at temperatures it never saw.
        CHECK(r.bias[best].ok && r.scale[best].ok);
        CHECK(r.bias[best].in_sample <= 0.5);
        CHECK(r.bias[best].in_all <= 0.5);
        CHECK(r.bias[best].held_out <= 0.5);
        CHECK(r.scale[best].in_sample <= 5.0);
        CHECK(r.scale[best].in_all <= 5.0);
        CHECK(r.scale[best].held_out <= 5.0);
        // The raw magnitudes are the paper's (the 0.3 mg below 14 are the hysteresis branches at
        // the turning points and the noise).
        CHECK(r.bias[0].in_sample > 13.5 && r.bias[0].in_sample < 14.5);
        CHECK(r.scale[0].in_sample > 150.0 && r.scale[0].in_sample < 153.0);
        if (r.part == "A") {
            // Part A lands near the paper: bias 6.91 (linear), 1.3 mg (Lorentz); scale factor
            // 45.89 and 11.8 ppm/degC.
            CHECK(r.bias[linear].in_sample > 6.0 && r.bias[linear].in_sample < 8.0);
            CHECK(r.bias[lorentz].in_sample > 0.9 && r.bias[lorentz].in_sample < 1.8);
            CHECK(r.scale[linear].in_sample > 38.0 && r.scale[linear].in_sample < 55.0);
            CHECK(r.scale[lorentz].in_sample > 9.0 && r.scale[lorentz].in_sample < 16.0);
        }
    }
}

int main()
{
    UNIT_RUN(test_part_a_end_to_end);
    UNIT_RUN(test_ambient_only);
    UNIT_RUN(test_compare_goal);
    return unit_report();
}
