// Temperature models of the calibration station (tools/calstation, tmodel.hpp): every fit
// recovers a noiseless model exactly (or its curve, where the parameters are not identifiable),
// the evaluation semantics (clamping, holding), and the refusals. Host only (C++/Eigen).
#include "inclino/calstation/tmodel.hpp"
#include "unit.h"

#include <cmath>
#include <vector>

using namespace calstation;

namespace
{

std::vector<TPoint> grid(double (*f)(double), double lo = -20.0, double hi = 60.0,
                         double step = 10.0, int reps = 1)
{
    std::vector<TPoint> v;
    for (int r = 0; r < reps; r++) {
        for (double t = lo; t <= hi + 1e-9; t += step)
            v.push_back({t, f(t)});
    }
    return v;
}

double lor(double t, double y0, double h, double w, double tc)
{
    const double r = 2.0 * (t - tc) / w;
    return y0 + h / (1.0 + r * r);
}

double f_lin(double t)
{
    return 0.002 - 0.0001 * (t - 20.0);
}
double f_par(double t)
{
    return 0.001 + 2e-5 * t - 3e-6 * t * t;
}
double f_lor_peak(double t)
{
    return lor(t, 0.01, 0.02, 30.0, 20.0);
}
double f_lor_tail(double t)
{
    return lor(t, -0.005, 0.012, 26.0, -25.0);
}
double f_lor_cubic(double t)
{
    const double u = (t - 20.0) / 40.0;
    return lor(t, 0.0, 0.012, 26.0, -25.0) - 0.0018 * u * u * u + 0.0004 * u;
}
double f_pwl(double t)
{
    // Knots at -20, 0, 20, 40, 60: 0, 1, 0, -2, 3 (mg).
    static const double k[5] = {0.0, 0.001, 0.0, -0.002, 0.003};
    const double s = (t + 20.0) / 20.0;
    int i = static_cast<int>(std::floor(s));
    if (i < 0) return k[0];
    if (i >= 4) return k[4];
    return k[i] + (k[i + 1] - k[i]) * (s - i);
}

double max_err(const TModel &m, double (*f)(double), double lo = -20.0, double hi = 60.0)
{
    double e = 0.0;
    for (double t = lo; t <= hi + 1e-9; t += 0.5)
        e = std::fmax(e, std::fabs(m.eval(t) - f(t)));
    return e;
}

} // namespace

static void test_linear()
{
    const TFit f = fit_linear(grid(f_lin, -20, 60, 10, 3));
    REQUIRE(f.ok);
    CHECK(f.model.kind == TKind::Linear);
    CHECK_NEAR(f.model.t_ref, 20.0, 1e-12);
    CHECK_NEAR(f.model.t_span, 40.0, 1e-12);
    CHECK_NEAR(f.model.p[0], 0.002, 1e-15);
    CHECK_NEAR(f.model.p[1], -0.004, 1e-15);
    CHECK_NEAR(max_err(f.model, f_lin), 0.0, 1e-15);
    // Held at the ends of the calibrated range (firmware contract), not extrapolated.
    CHECK_NEAR(f.model.eval(100.0), f_lin(60.0), 1e-15);
    CHECK_NEAR(f.model.eval(-70.0), f_lin(-20.0), 1e-15);
    CHECK(!fit_linear({{25.0, 0.0}, {25.5, 1.0}}).ok); // two temperatures < 1 degC apart
}

static void test_three_point()
{
    // Soak means at -20, -10, 25 (ambient), 40, 60: the procedure uses only cold, ambient, hot.
    std::vector<TPoint> m = {
        {-20, f_par(-20)}, {-10, 1.0}, {25, f_par(25)}, {40, -1.0}, {60, f_par(60)}};
    const TFit f = fit_three_point(m, 25.0);
    REQUIRE(f.ok);
    CHECK(f.model.kind == TKind::Parabola);
    // A parabola through the three points is the true parabola.
    CHECK_NEAR(max_err(f.model, f_par), 0.0, 1e-15);
    // [ADI-EPB]'s steps by hand: c = y(Ta); b from the hot point; a from the cold point.
    const double c = f_par(25), b = (f_par(60) - c) / 35.0;
    const double a = (f_par(-20) - (c + b * (-45.0))) / ((-45.0) * (-80.0));
    CHECK_NEAR(a, -3e-6, 1e-15);
    CHECK_NEAR(f.model.eval(0.0), c + b * (0 - 25.0) + a * (0 - 25.0) * (0 - 60.0), 1e-15);
    CHECK(!fit_three_point({{-20, 0}, {60, 0}}, 25.0).ok);
}

static void test_lorentz_peak()
{
    const TFit f = fit_lorentz(grid(f_lor_peak, -20, 60, 10, 2), 0.5);
    REQUIRE(f.ok);
    CHECK(f.converged);
    CHECK(f.model.kind == TKind::Lorentz);
    CHECK_NEAR(f.model.p[0], 0.01, 1e-9);
    CHECK_NEAR(f.model.p[1], 0.02, 1e-9);
    CHECK_NEAR(f.model.p[2], 30.0, 1e-5);
    CHECK_NEAR(f.model.p[3], 20.0, 1e-5);
    CHECK_NEAR(max_err(f.model, f_lor_peak), 0.0, 1e-9);
    // Bounded outside the range: between y0 and y0 + H.
    CHECK_NEAR(f.model.eval(150.0), f_lor_peak(150.0), 1e-9);
    CHECK(f.model.eval(150.0) > 0.01 && f.model.eval(150.0) < 0.03);
}

static void test_lorentz_tail()
{
    // Peak below the range: only the tail is seen. The curve is recovered.
    const TFit f = fit_lorentz(grid(f_lor_tail), 0.5);
    REQUIRE(f.ok);
    CHECK(f.converged);
    CHECK_NEAR(max_err(f.model, f_lor_tail), 0.0, 2e-7);
    // The height limit is honoured.
    const TFit g = fit_lorentz(grid(f_lor_tail), 0.01);
    CHECK(!g.ok || std::fabs(g.model.p[1]) <= 0.01);
}

static void test_lorentz_cubic()
{
    const TFit f = fit_lorentz_cubic(grid(f_lor_cubic, -20, 60, 10, 2), 0.5);
    REQUIRE(f.ok);
    CHECK(f.converged);
    CHECK(f.model.kind == TKind::LorentzCubic);
    CHECK_NEAR(f.model.t_ref, 20.0, 1e-12);
    CHECK_NEAR(f.model.t_span, 40.0, 1e-12);
    CHECK_NEAR(max_err(f.model, f_lor_cubic, -20, 60), 0.0, 5e-7);
    // The plain Lorentz leaves the cubic term: clearly worse on the same data.
    const TFit l = fit_lorentz(grid(f_lor_cubic, -20, 60, 10, 2), 0.5);
    REQUIRE(l.ok);
    CHECK(max_err(l.model, f_lor_cubic) > 1e-4);
    // Held at the ends: the whole model (Lorentz and polynomial) is evaluated at the clamped T.
    CHECK_NEAR(f.model.eval(90.0), f.model.eval(60.0), 0.0);
    CHECK_NEAR(f.model.eval(-45.0), f.model.eval(-20.0), 0.0);
}

static void test_pwl()
{
    const TFit f = fit_pwl(grid(f_pwl, -20, 60, 5, 1), -20.0, 20.0, 5);
    REQUIRE(f.ok);
    CHECK(f.model.kind == TKind::Pwl);
    CHECK_EQ_INT(f.model.n, 5);
    CHECK_NEAR(f.model.p[0], 0.0, 1e-15);
    CHECK_NEAR(f.model.p[1], 0.001, 1e-15);
    CHECK_NEAR(f.model.p[3], -0.002, 1e-15);
    CHECK_NEAR(f.model.p[4], 0.003, 1e-15);
    CHECK_NEAR(max_err(f.model, f_pwl, -40, 80), 0.0, 1e-15);
    // A knot with no data around it is refused.
    CHECK(!fit_pwl({{-20, 0}, {-10, 0}}, -20.0, 20.0, 5).ok);
    CHECK(!fit_pwl(grid(f_pwl), -20.0, 10.0, 17).ok); // more than 16 knots
}

static void test_refusals()
{
    const TFit f = fit_lorentz(grid(f_lor_peak, -20, 20, 10), 0.5); // 5 temperatures: ok
    CHECK(f.ok);
    const TFit g = fit_lorentz(grid(f_lor_peak, -20, 10, 10), 0.5); // 4 temperatures
    CHECK(!g.ok);
    CHECK(g.message.find("at least 5 soak temperatures") != std::string::npos);
    const TFit h = fit_lorentz_cubic(grid(f_lor_peak, -20, 40, 10), 0.5); // 7 < 8
    CHECK(!h.ok);
    CHECK(!fit_linear({}).ok);
}

int main()
{
    UNIT_RUN(test_linear);
    UNIT_RUN(test_three_point);
    UNIT_RUN(test_lorentz_peak);
    UNIT_RUN(test_lorentz_tail);
    UNIT_RUN(test_lorentz_cubic);
    UNIT_RUN(test_pwl);
    UNIT_RUN(test_refusals);
    return unit_report();
}
