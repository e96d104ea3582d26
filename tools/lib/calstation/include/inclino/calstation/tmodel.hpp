// tmodel.hpp - temperature models of bias and scale factor: double-precision evaluation with
// the firmware's semantics, and the fits of the calibration station ([ADI-EPB]'s three-point
// parabola, [TEMP-LORENTZ]'s linear and Lorentz fits, a piecewise-linear table, Lorentz + cubic).
//
// The parameterisation is the one of the calibration record (firmware/signal/calrec, calrec.h); the
// values here are in the physical unit of the quantity (g for bias, unitless for the relative
// scale-factor deviation) before quantisation to Q16.16 / Q30:
//   LINEAR        y = p0 + p1*u                      u = clamp((T - t_ref) / t_span, -1, 1)
//   PARABOLA      y = p0 + p1*u + p2*u^2
//   LORENTZ       y = p0 + p1 / (1 + ((T - p3) / (p2 / 2))^2)   (p1 peak height, p2 FWHM w,
//                                                                 p3 centre Tc; no clamp)
//   PWL           n knots T_i = t_ref + i*t_span, y_i = p[i], linear between, held at the ends
//   LORENTZ_CUBIC the LORENTZ term plus p4*u + p5*u^2 + p6*u^3, all evaluated at T clamped to
//                 [t_ref - t_span, t_ref + t_span] (the two parts may cancel inside the
//                 calibrated range and must not be extrapolated apart)
// [TEMP-LORENTZ]'s Lorentz formula did not survive; the usual form y0 + (2A/pi) w / (4(T-Tc)^2 + w^2)
// is the same curve with p1 = 2A/(pi w): p1 (height) is used because it stays in the y format.
// The clamp of u (the polynomial models hold their end values outside [t_ref - t_span,
// t_ref + t_span], the calibrated range) is the firmware's documented contract
// (docs/calibration.md): a parabola is never extrapolated outside the chamber range.
#ifndef INCLINO_CALSTATION_TMODEL_HPP
#define INCLINO_CALSTATION_TMODEL_HPP

#include <array>
#include <string>
#include <vector>

namespace calstation
{

enum class TKind { None = 0, Linear = 1, Parabola = 2, Lorentz = 3, Pwl = 4, LorentzCubic = 5 };

constexpr int kTParams = 16; // parameter words per model (= calrec CALREC_TM_PARAMS)

struct TModel {
    TKind kind = TKind::None;
    int n = 0;          // PWL knot count
    double t_ref = 0.0; // degC
    double t_span = 0.0;
    std::array<double, kTParams> p{};

    double eval(double t_c) const;
    // The parameters the kind uses, p[0..params()-1]: 2, 3, 4, 7 or n (PWL); 0 for None.
    int params() const;
};

// Whether parameter k of a model of kind `kind` is a temperature in degC (the Lorentz width p2
// and centre p3), not a value of the quantity.
bool tparam_is_degc(TKind kind, int k);

const char *tkind_name(TKind k);

// One fitted data point: temperature and the quantity (bias g, or scale factor g/g).
struct TPoint {
    double t;
    double y;
};

// Outcome of a fit. ok = false with a message when the data cannot determine the model.
struct TFit {
    bool ok = false;
    std::string message;
    TModel model;
    int iterations = 0; // LM iterations (Lorentz kinds)
    bool converged = true;
};

// Least squares y = a + b*T over all points; t_ref/t_span = centre/half of the data range.
TFit fit_linear(const std::vector<TPoint> &pts);

// [ADI-EPB]'s three-point procedure on soak-point means: offset at the ambient point (the one
// nearest t_amb), linear term from the hottest point, parabolic term from the coldest point, so
// that the parabola passes through all three. Needs 3 distinct soak points.
TFit fit_three_point(const std::vector<TPoint> &soak_means, double t_amb);

// Lorentz y0 + H / (1 + (2(T-Tc)/w)^2), least squares. Initialisation: grid over (Tc, w) with
// (y0, H) solved linearly at each node (variable projection); then Levenberg-Marquardt on all
// four parameters with w in [1, 400] degC, Tc in [-100, 200] degC and |H| <= h_limit enforced
// by projection; converged when the relative SSE change and the step are below 1e-12 / 1e-9.
TFit fit_lorentz(const std::vector<TPoint> &pts, double h_limit);

// The same with a cubic background p4*u + p5*u^2 + p6*u^3 (u over the data range).
TFit fit_lorentz_cubic(const std::vector<TPoint> &pts, double h_limit);

// Piecewise-linear with n uniform knots from t0 with spacing dt, least squares (hat basis).
// Every knot interval must hold data, otherwise the fit is refused.
TFit fit_pwl(const std::vector<TPoint> &pts, double t0, double dt, int n);

} // namespace calstation

#endif
