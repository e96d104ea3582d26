// station.hpp - the host side of the EPB demo's end-of-line station (docs/epb-demo.md):
//  - the cross-axis (misalignment) matrix from the six faces the firmware averaged;
//  - the nonlinearity of each element: a cubic fitted to the faces and a tilt sweep within
//    +-30 deg (docs/calibration.md), which [ADI-EPB] leaves uncorrected;
//  - [ADI-EPB]'s three-point temperature models of offset and gain (calstation's
//    fit_three_point) from the on-device six-position results at the cold, ambient and hot soaks;
//  - the record, quantised with calstation's to_calrec (the on-device offsets, gains and gyro
//    offsets kept bit for bit);
//  - the error budget the application is configured with: the residuals this calibration
//    achieves on the part type (struct app_budget), each term with where it comes from.
// Host code: double precision is allowed here, never in the firmware.
#ifndef INCLINO_EPB_DEMO_STATION_HPP
#define INCLINO_EPB_DEMO_STATION_HPP

extern "C" {
#include "inclino/app.h"
#include "inclino/sim/calpart.h"
}

#include <array>
#include <string>
#include <vector>

namespace epb
{

// One position of the tilt sweep: the specific force the station applied (g, part frame) and
// the firmware's average there.
struct SweepPoint {
    std::array<double, 3> dir{};
    app_face meas{};
};

// The six faces of one soak as the firmware measured them, and its on-device result.
struct Soak {
    double chamber_c = 25.0; // chamber temperature (the truth)
    double temp_c = 25.0;    // the part's own reading, mean over the faces (what
                             // the firmware will compare with); the chamber value
                             // for a part without temperature output
    std::array<app_face, CAL_FACES> faces{};
    calrec six{};                  // acc_offset, acc_gain, gyro_offset from app_eol_six_position
    std::vector<SweepPoint> sweep; // the tilt sweep (ambient soak only; may be empty)
};

struct StationOut {
    calrec rec{}; // the record to store (binding set by the firmware)
    std::array<std::array<double, 3>, 3> misalign{};
    bool tcal = false;
    double t_cold = 0.0, t_amb = 25.0, t_hot = 0.0;
    bool nonlin = false;                     // the nonlinearity was fitted (a tilt sweep was given)
    std::array<std::vector<double>, 3> nl_v; // per element: the v values of the fit's points
    std::array<double, 3> nl_rms{};          // per element: rms residual of the fit, g
};

// Build the record from the soaks (soaks[0] = ambient; with three soaks the temperature models
// are fitted too; with a tilt sweep in soaks[0] the nonlinearity too). id: the identity the
// firmware read (calrec_check needs a valid binding). Returns "" or a message.
//
// Nonlinearity: per element i, v = (r - offset) / gain with the on-device flip results, the
// target t = P_i . f (f the station's direction, P from the faces), and a least-squares fit of
// c0 + c1 v + c2 v^2 + c3 v^3 = t - v over the six faces and the sweep; the firmware then applies
// y = v + c(v) per element before M (cal_acc_apply). c0 also removes the flip's offset error
// (the even nonlinearity at +-1 g).
std::string station_record(const std::vector<Soak> &soaks, const calrec_binding &id,
                           StationOut &out);

// One term of the budget with its origin, for the report.
struct Term {
    std::string name;
    double value = 0.0; // g, or relative for the sensitivity terms
    std::string origin;
};

struct Budget {
    app_budget b{};          // what the application is configured with (Q16/Q30)
    std::vector<Term> terms; // the same in physical units, explained
    double sigma_sample_g = 0.0;
    double char_nonlin_g = 0.0, char_temp_g = 0.0, char_scale = 0.0;
    double resid_nonlin_g = 0.0, fit_nonlin_g = 0.0; // with the sweep: model residual, k sigma_fit
};

// The residuals the calibration in `st` achieves on the part type `type` (the sim/calpart
// parameters the part was drawn from; its characterisation):
//   offset       k sigma / sqrt(N_face) (flip offset and cross-axis terms from N_face-sample face
//                means) + 4 LSB Q16 of firmware arithmetic;
//   sensitivity  k sigma / sqrt(2 N_face) (flip gain) + with the temperature models, their
//                largest scale residual over the calibrated range;
//   nonlinearity with the sweep: the largest |y(v(x)) - x| within +-max_slope_deg on the part
//                type (its element cubic seen through the flip line, then the record's cubic)
//                + k sigma_fit, sigma_fit the fitted curve's standard deviation there (the
//                points' noise sigma sqrt(2 / N_face): reading and target); without it:
//                max([ADI-EPB]'s 10 mg, the part type's largest flip-line deviation);
//   temperature  with the models: their largest offset residual against the part type's curves
//                over the calibrated range, both hysteresis branches; without: [ADI-EPB]'s 50 mg;
//   noise        sigma of one output sample = sqrt(element noise^2 + LSB^2 / 12);
//   uncalibrated max([ADI-EPB]'s 3 % / 15 mg, the part type's own at 25 degC).
// k_sigma from the application's lifetime rule (slope_sigma_factor(runs, E)).
// The temperature residual is evaluated over the calibrated range widened by the application's
// margin (temp_margin_c), with the part's reading off the truth by up to half a temperature LSB.
Budget derive_budget(const sim_calpart_params &type, const StationOut &st, double acc_lsb_g,
                     double temp_lsb_c, uint32_t n_face, const app_cfg &cfg);

} // namespace epb

#endif
