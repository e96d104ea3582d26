// campaign.hpp - the EPB accuracy campaign (module inclino_campaign, docs/campaign.md): seeded
// Monte Carlo cases of the EPB application over the part-to-part spread of [ADI-EPB]'s error
// budget, road slope and cross slope within +-30 deg, -40..85 degC (steady or still changing
// after a cold start) and the disturbances of a parked car; and [ADI-EPB]'s Table 1 reproduced
// term by term beside the same table measured on this project's pipeline.
//
// One case: a part drawn from its seed (case_seed(campaign seed, index), so any case reruns
// alone), its end of line as the application does it (app_eol_face on the six faces at -40, 25
// and 85 degC and a tilt sweep at 25 degC, app_eol_six_position per soak, the station's cross-axis
// matrix, nonlinearity cubics and three-point models, app_eol_save into a RAM flash), a power
// cycle (app_init loads the record), then a parked scenario fed sample by sample to app_step;
// every estimate with its truth, error and bound.
//
// The part is simulated at sample level (not at pin level as sim/epb_rig does): the error model,
// the ADIS16405's quantisation (3.333 mg, 0.05 deg/s, 0.14 degC) and its 819.2 SPS, given to the
// application as a struct sensor. The application, the calibration and the slope are the
// firmware's own code. Host code: double precision is allowed here.
#ifndef INCLINO_CAMPAIGN_HPP
#define INCLINO_CAMPAIGN_HPP

extern "C" {
#include "inclino/app.h"
}

#include <cstdint>
#include <string>
#include <vector>

namespace campaign
{

// [ADI-EPB]'s magnitudes (Table 1 and its text), g or relative.
constexpr double kSensitivity = 0.03;    // sensitivity error, +-3 %
constexpr double kInitialOffset = 0.015; // initial absolute offset (one standard deviation)
constexpr double kNonlinearity = 0.010;  // within +-500 mg (30 mg over +-2 g rescaled)
constexpr double kNonlinRange = 0.5;     // +-500 mg = +-1 g sin 30 deg
constexpr double kOffsetDrift = 0.050;   // total offset change over temperature
constexpr double kQuadShare = 0.8;       // of it the quadratic (rotated parabola) share
constexpr double kNoiseRms = 0.004;      // per sample: 0.4 mg after 100 samples at 1 kSPS
constexpr double kTMin = -40.0, kTMax = 85.0, kTAmb = 25.0;

// One part: per sensing element i, for the true specific force a (g, part frame):
//   x_i = sum_j axis[i][j] a_j;  h_i = x_i + nl2_i x_i^2 + nl3_i x_i^3;
//   out_i = bias_i(T) + gain_i (1 + scale_i(T)) h_i + noise;  with u = (T - 22.5) / 62.5
//   bias_i(T) = off_i + q_i (u^2 - u0^2) + l_i (u - u0) + c_i (u^3 - u0^3) + shift_i
//   scale_i(T) = sq_i (u^2 - u0^2) + sl_i (u - u0)   (u0: u at 25 degC)
// shift is an offset change that is not a function of temperature (stress, ageing): 0 in the
// campaign (the lifetime offset change is the fault campaign's bound term), used by Table 1's
// reproduction of [ADI-EPB]'s own assumption.
struct Part {
    double axis[3][3];
    double nl2[3], nl3[3];
    double off[3], gain[3];
    double q[3], l[3], c[3], shift[3];
    double sq[3], sl[3];
    double noise_g = kNoiseRms;
    double gyro_bias_dps[3], gyro_noise_dps = 0.05;
};

double tnorm(double t_c);                           // u of the model above
double part_bias(const Part &p, int i, double t_c); // bias_i(T), g
double part_gain(const Part &p, int i, double t_c); // gain_i (1 + scale_i(T))
void part_ideal(Part &p);                           // no error at all, no noise
void part_output(const Part &p, const double a[3], double t_c, double out[3]); // noiseless

// A part drawn from seed with [ADI-EPB]'s magnitudes: gain 1 +- 3 % (uniform), offset normal
// sd 15 mg (clipped at 3 sd), nonlinearity whose largest deviation from the end-point line within
// +-500 mg is 5..10 mg (x^3 coefficient within +-0.04 /g^2, the rest x^2), offset drift over -40..85 degC of 25..50 mg peak to
// peak of which 80 % a rotated parabola (vertex anywhere within +-1.3 of the range) and 20 % a
// cubic, scale drift up to 0.5 % (rotated parabola), misalignment within +-0.5 deg, noise 4 mg rms
// per sample, gyro bias within +-1 deg/s.
void draw_part(uint64_t seed, Part &p);

// A parked car. Truth: pitch p(t) (nose up +, the slope the application estimates) and roll
// r(t) of the body; specific force (sin p, cos p sin r, cos p cos r) + vibration.
struct Event {
    double t0;                            // start, s
    double amp_g;                         // z acceleration of the body bounce (or of the slam), g
    double pitch_deg;                     // pitch amplitude of the bounce
    double roll_deg;                      // roll amplitude of the bounce
    double freq_hz, zeta;                 // damped oscillation
    double step_pitch_deg, step_roll_deg; // a lasting attitude change (loading), reached in 0.5 s
    int kind;                             // 0 passenger, 1 door slam, 2 loading
};

struct Scenario {
    double slope_deg = 0.0, roll_deg = 0.0;
    double temp0_c = 25.0, temp_rate_c_per_s = 0.0; // temperature ramp (cold start: != 0)
    bool engine = true;
    double engine_scale = 1.0;
    double phase[4][3] = {};
    double wind_deg = 0.0, wind_hz = 0.0, wind_phase = 0.0; // sway in pitch and roll
    std::vector<Event> events;
    double length_s = 10.0;
    unsigned passengers = 0, doors = 0, loads = 0; // counts, for the CSV
    bool cold_start = false;
};

// A scenario drawn from seed: slope and cross slope uniform within +-30 deg, temperature
// uniform in -40..85 degC, 40 % of the cases a soak-free cold start (the temperature ramps at
// 1..6 degC/min while parked, inward from where it starts), engine idling (80 %), passengers
// moving (Poisson, up to 0.5/s), a door slam (30 %), loading (25 %: 0.05..0.3 deg of pitch and
// up to 0.1 deg of roll), wind sway (50 %: up to 0.03 deg at 0.3..2 Hz).
void draw_scenario(uint64_t seed, double length_s, Scenario &s);

// The configuration of a campaign (the same for every case).
struct Config {
    uint32_t n_face = 819; // samples per face and sweep position (1 s at 819.2 SPS)
    int blocks = 4;        // estimates per case (2.5 s each)
    bool sweep = true;     // the tilt sweep at 25 degC (nonlinearity correction)
    bool tcal = true;      // the three-point temperature step
    double t_cold = kTMin, t_hot = kTMax;
    bool two_axis = true; // slope method of app_cfg_default (false: single axis)
};

// The application's configuration: app_cfg_default at 819.2 SPS and the budget of the part
// type, characterised on a lot of noiseless parts drawn with lot_seed (the calibration model's
// residuals measured with cal_acc_apply over the range, times a 1.25 guard band) plus the
// end-of-line noise terms (k sigma / sqrt(N) of the flip, the three-point fits and the cubic's
// fit). terms: the same in g (relative for sensitivity), for the report.
struct Characterisation {
    app_cfg cfg{};
    double sensitivity = 0, offset = 0, nonlinearity = 0, temperature = 0, sigma = 0;
    double lot_static_g = 0; // the lot's largest model residual (before the guard band)
};
std::string characterise(const Config &c, uint64_t lot_seed, unsigned lot_parts,
                         Characterisation &out);

struct Estimate {
    uint64_t index = 0, seed = 0;
    int block = 0;
    double t_s = 0;                     // end of block, scenario time
    double true_deg = 0, true_roll = 0; // mean true pitch and roll over the block
    double true_temp_c = 0, temp_c = 0; // mean true temperature, the application's mean reading
    double slope_deg = 0, bound_deg = 0, error_deg = 0;
    bool valid = false, inside = false;
    uint32_t flags = 0, slope_flags = 0;
    double sigma_mg = 0;
    const Scenario *sc = nullptr;
};

// SplitMix64 of (campaign seed, index): the seed of case `index`.
uint64_t case_seed(uint64_t campaign_seed, uint64_t index);

// Run case `index` of campaign seed `seed`; its estimates are appended to out. "" or a message.
std::string run_case(const Config &c, const Characterisation &ch, uint64_t seed, uint64_t index,
                     std::vector<Estimate> &out, Scenario &sc);

// CSV: the header and one row per estimate.
std::string csv_header();
std::string csv_row(const Estimate &e);

// ---- [ADI-EPB] Table 1 -------------------------------------------------------------------
struct Table1Row {
    std::string term;
    double article_before = 0, article_after = 0; // printed in the article, g
    double sim_before = 0, sim_after = 0;         // the article's method, simulated, g
    double ours_before = 0, ours_after = 0;       // this pipeline, measured, g
    std::string method, note;
};
struct Table1 {
    std::vector<Table1Row> rows; // the five terms
    double article_total_before = 0, article_total_after = 0;
    double sim_total_before = 0, sim_total_after = 0, ours_total_before = 0, ours_total_after = 0;
    double deg(double g) const; // worst case at 0 deg: asin(total / 1 g), degrees
};
std::string table1(const Config &c, Table1 &t);

} // namespace campaign

#endif
