// compare.hpp - [TEMP-LORENTZ]'s comparison reproduced in the simulator (docs/benchmarks.md,
// "Calibration"): a simulated part is measured as the paper did (10 degC points, 1 h soaks,
// repeated up/down cycles, noise), every temperature model is fitted, and the residual spreads
// are reported in-sample (the paper's way) and held out (a second run at the mid-points
// -15..55 degC, other noise, never seen by the fit).
#ifndef INCLINO_CALSTATION_COMPARE_HPP
#define INCLINO_CALSTATION_COMPARE_HPP

#include "inclino/calstation/fit.hpp"
#include "inclino/calstation/station.hpp"

#include <array>
#include <string>
#include <vector>

namespace calstation
{

// One quantity of one axis: index 0 = raw (no compensation), 1 + k = TemperatureFits kind k,
// and the last = the best model (Lorentz + cubic) quantised into the record and evaluated by the
// firmware (cal_tmodel_eval, fixed point).
struct CompareCell {
    bool ok = false;
    double in_sample = 0.0; // soak-point means, paper's definition (mg or ppm/degC)
    double in_all = 0.0;    // every soak
    double held_out = 0.0;  // soak-point means of the validation run
};

struct CompareAxis {
    std::string part;
    int axis = 0;
    static constexpr int kCells = 2 + TemperatureFits::kKinds;
    std::array<CompareCell, kCells> bias, scale;
};

struct CompareConfig {
    int cycles = 10; // calibration run ([TEMP-LORENTZ]: 10)
    int validation_cycles = 3;
    uint64_t noise_seed = 1;
};

// Simulate, fit and evaluate one part. Returns "" or an error message.
std::string compare_part(const SimPart &part, const CompareConfig &cfg,
                         std::vector<CompareAxis> &out);

// The report: one table per quantity, worst axis per part and model, plus per-axis detail.
std::string format_compare(const std::vector<CompareAxis> &rows);

} // namespace calstation

#endif
