// fit.hpp - the calibration station's fits, from a parsed station file to the coefficients of
// the calibration record, with a residual report per model.
//
// Pipeline (docs/calibration.md, "What the station fits"):
//  1. Per block (chamber soak) and axis, the +-1 g flip pair gives the bias (A+ + A-)/2 and the
//     scale factor (A+ - A-)/2 ([ADI-EPB], without its spurious 0.5), in g from the nominal LSB.
//  2. Blocks are grouped into soak points (temperatures within 2 degC). Bias and scale factor
//     against temperature are fitted with every model (linear, [ADI-EPB]'s three-point parabola,
//     Lorentz ([TEMP-LORENTZ]), piecewise-linear, Lorentz + cubic); the chosen model becomes
//     acc_offset/acc_gain (its value at t_ref) and acc_tbias/acc_tscale (the deviation from it).
//  3. Every acc row, temperature-corrected, gives v = (r - B(T)) / K(T) per element; per element
//     i a least-squares fit of  P_i . f - c0 - c2 v^2 - c3 v^3 = v  over all positions f gives
//     the sensed direction P_i (rows of P; misalignment and residual gain) and the element's
//     inverse nonlinearity (c2, c3 only with a tilt sweep of >= 5 distinct positions on that
//     axis). c0 is folded into acc_offset. The firmware applies a = M (v + c2 v^2 + c3 v^3),
//     M = P^-1.
//  4. Gyro: offset = mean of the still rows; scale = least squares of measured against known
//     turn angles (measured = integral - offset * duration).
//  5. Every coefficient is checked against the record's limits.
#ifndef INCLINO_CALSTATION_FIT_HPP
#define INCLINO_CALSTATION_FIT_HPP

#include "inclino/calstation/station.hpp"
#include "inclino/calstation/tmodel.hpp"

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace calstation
{

// Temperature-model choice of the fit. Best = LorentzCubic (see docs/calibration.md for why).
enum class TChoice { Best, None, Linear, Parabola, Lorentz, Pwl, LorentzCubic };

bool parse_tchoice(const std::string &s, TChoice &c);
const char *tchoice_name(TChoice c);

// How the offsets, gains and cross-axis matrix are fitted (step 3; docs/calibration.md 4.3):
//   Nominal    least squares against the nominal directions u of the rows (offset c0, the
//              sensed directions P, M = P^-1): exact on a precise positioner, but every face
//              placed off its nominal direction moves the offsets (a hand-placed cube);
//   Pair       the per-axis pair method: each axis's offset from its own +-1 g face pair only,
//              then P by least squares against the nominal directions with that offset fixed;
//   Magnitude  |S n(v)| = 1 g over every static row (offsets, the symmetric part S of the
//              matrix and the nonlinearity), which assumes nothing about where the rows were
//              placed; then the rotation R (M = R S) from the nominal directions (orthogonal
//              Procrustes), the only part of M the magnitudes cannot see;
//   Auto       the placement check: Magnitude when the nominal fit's residual against the
//              nominal directions is more than 2 x its residual against 1 g + 0.05 mg, or its
//              residual against 1 g more than 2 x the pair method's + 0.05 mg (rms over the
//              rows); else Nominal (a precise positioner: its result is kept).
//   The magnitude fit adjusts the offsets and the diagonal of S only: the off-diagonal terms
//   enter |S n| through n_i n_j, which vanishes to first order on faces and single-axis tilt
//   sweeps, so they stay the nominal fit's, as does the nonlinearity.
enum class FitMethod { Auto, Nominal, Pair, Magnitude };
bool parse_fit_method(const std::string &s, FitMethod &m);
const char *fit_method_name(FitMethod m);

struct FitOptions {
    TChoice tmodel = TChoice::Best;
    // true: the model was not chosen by the user; one soak temperature then means TChoice::None
    // (said in the report) instead of a refusal.
    bool tmodel_auto = false;
    FitMethod method = FitMethod::Auto;
};

// Residuals of a correction over the static acc rows (each row is a position mean), mg / deg.
struct Residuals {
    size_t rows = 0;
    double mag_rms_mg = 0.0, mag_max_mg = 0.0;   // | |a| - 1 g |: needs no placement
    double dir_rms_mg = 0.0, dir_max_mg = 0.0;   // | a - u |: against the nominal directions
    double ang_rms_deg = 0.0, ang_max_deg = 0.0; // angle between a and u
};

// One static row's residual | |a| - 1 g | (mg) before and after the chosen correction, for the
// per-face plot (calstation fit --faces-csv).
struct RowResidual {
    int line = 0;
    long block = 0;
    double temp_c = 0.0;
    std::array<double, 3> u{};
    double raw_mg = 0.0, pair_mg = 0.0, nominal_mg = 0.0, magnitude_mg = 0.0, chosen_mg = 0.0;
    double angle_deg = 0.0; // chosen correction against u
};

// One block's flip-pair measurement (step 1).
struct BlockMeas {
    long block = 0;
    double t = 0.0;                // mean temperature of its face rows, degC
    std::array<bool, 3> have{};    // axis has a +-1 g pair in this block
    std::array<double, 3> bias{};  // g
    std::array<double, 3> scale{}; // g/g
};

// The residual spreads of one model on one axis ([TEMP-LORENTZ] definitions).
struct Spread {
    double bias_mean_mg = 0.0;   // Bmax - Bmin of soak-point means of the residual bias
    double bias_all_mg = 0.0;    // the same over every block (includes hysteresis and noise)
    double scale_mean_ppm = 0.0; // (Kmax - Kmin)/Kmean * 1e6 / span over soak-point means
    double scale_all_ppm = 0.0;  // the same over every block
};

// The models of every kind for one data set.
struct TemperatureFits {
    // index: 0 linear, 1 three-point parabola, 2 Lorentz, 3 PWL, 4 Lorentz + cubic
    static constexpr int kKinds = 5;
    std::array<std::array<TFit, 3>, kKinds> bias;
    std::array<std::array<TFit, 3>, kKinds> scale;
    static const char *name(int k);
};

struct CalResult {
    // Coefficients in physical units, as the record stores them before quantisation.
    std::array<double, 3> acc_offset{};                  // g
    std::array<double, 3> acc_gain{};                    // g/g
    std::array<std::array<double, 3>, 3> acc_misalign{}; // M
    std::array<std::array<double, 4>, 3> acc_nonlin{};   // c0..c3
    std::array<TModel, 3> acc_tbias{};                   // g
    std::array<TModel, 3> acc_tscale{};                  // relative deviation
    std::array<double, 3> gyro_offset{};                 // deg/s
    std::array<double, 3> gyro_scale{1.0, 1.0, 1.0};
    bool have_gyro = false;
    bool have_nonlin = false;
    TChoice tmodel = TChoice::None;
    FitMethod method = FitMethod::Nominal; // the one the coefficients come from
    bool gyro_scale_fitted = false;        // turns present (else the gyro scale is 1)

    // For the reports.
    Residuals res_raw, res_pair, res_nominal, res_magnitude, res_chosen;
    std::vector<RowResidual> rows;
    std::vector<std::string> warnings; // also in the report
    bool one_temperature = false;      // the soaks span one temperature only
    std::vector<BlockMeas> blocks;
    std::vector<std::vector<size_t>> soaks; // indices into blocks, by temperature
    TemperatureFits tfits;
    std::string report; // human-readable residual report
};

// Steps 1 and 2 helpers, public for the comparison and the tests.
std::string block_measurements(const Station &st, std::vector<BlockMeas> &out);
std::vector<std::vector<size_t>> soak_points(const std::vector<BlockMeas> &b);
Spread spread(const std::vector<BlockMeas> &b, const std::vector<std::vector<size_t>> &soaks,
              int axis, const TModel *bias_model, const TModel *scale_model);
// The same with any evaluators of B(T) (g) and K(T) (g/g); an empty function means "none".
Spread spread_fn(const std::vector<BlockMeas> &b, const std::vector<std::vector<size_t>> &soaks,
                 int axis, const std::function<double(double)> &bias_model,
                 const std::function<double(double)> &scale_model);
// Fit every kind on the blocks (t_ref only matters for the three-point ambient point).
TemperatureFits fit_temperature(const std::vector<BlockMeas> &b,
                                const std::vector<std::vector<size_t>> &soaks, double t_ref);

// B(T) (relative = false) or K(T) (relative = true) turned into the record's deviation form:
// B - ref, or K / ref - 1 (ref = the model's value at t_ref).
TModel to_deviation(const TModel &m, double ref, bool relative);

// The whole pipeline. Returns "" on success, else a message naming the problem (and the line
// where there is one); then `out` must not be used.
std::string fit_station(const Station &st, const FitOptions &opt, CalResult &out);

// Corrected acceleration for one raw reading (counts * lsb = r, g) at temperature t with the
// result's coefficients in double precision (the reference the firmware is compared with).
std::array<double, 3> apply_double(const CalResult &c, const std::array<double, 3> &r, double t);

// Residuals of correction c over the acc rows of st (double precision).
Residuals residuals(const Station &st, const CalResult &c);

} // namespace calstation

#endif
