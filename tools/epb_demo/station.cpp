// station.cpp - see station.hpp.
#include "station.hpp"

extern "C" {
#include "inclino/sim/epb_rig.h"
}

#include "inclino/calstation/fit.hpp"
#include "inclino/calstation/record.hpp"
#include "inclino/calstation/tmodel.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace epb
{

namespace
{

constexpr double kQ16 = 65536.0, kQ30 = 1073741824.0;
constexpr double kPi = 3.14159265358979323846;

// [ADI-EPB], Table 1 (mg, relative): what the budget falls back on where nothing is corrected.
constexpr double kSeedNonlin = 0.010;
constexpr double kSeedTempUncomp = 0.050;
constexpr double kSeedSensUncal = 0.03;
constexpr double kSeedOffsetUncal = 0.015;

fx_q16_t up16(double g)
{
    return static_cast<fx_q16_t>(std::min(std::ceil(g * kQ16), 2147483647.0));
}

fx_q30_t up30(double r)
{
    return static_cast<fx_q30_t>(std::min(std::ceil(r * kQ30), 536870911.0));
}

// Element i's reading m after the soak's on-device offset and gain: v = (r - offset) / gain.
double element_v(const Soak &s, const app_face &m, int i)
{
    return (m.accel_g[i] / kQ16 - s.six.acc_offset[i] / kQ16) / (s.six.acc_gain[i] / kQ30);
}

// One row of the nonlinearity fit's design matrix.
Eigen::Vector4d cubic_row(double v)
{
    return Eigen::Vector4d(1.0, v, v * v, v * v * v);
}

// Fit c0..c3 per element (station.hpp) into c.acc_nonlin; records the points for the budget.
std::string fit_nonlinearity(const Soak &amb, const Eigen::Matrix3d &P, calstation::CalResult &c,
                             StationOut &out)
{
    for (int i = 0; i < 3; i++) {
        std::vector<double> vs, ts;
        auto add = [&](const app_face &m, const double *dir) {
            vs.push_back(element_v(amb, m, i));
            ts.push_back(P(i, 0) * dir[0] + P(i, 1) * dir[1] + P(i, 2) * dir[2]);
        };
        for (int f = 0; f < CAL_FACES; f++) {
            double dir[3];
            epb_rig_face_dir(f, dir);
            add(amb.faces[f], dir);
        }
        for (const SweepPoint &s : amb.sweep)
            add(s.meas, s.dir.data());
        const int n = static_cast<int>(vs.size());
        Eigen::MatrixXd X(n, 4);
        Eigen::VectorXd y(n);
        for (int k = 0; k < n; k++) {
            X.row(k) = cubic_row(vs[k]).transpose();
            y(k) = ts[k] - vs[k];
        }
        // Conditioned only when the element saw enough distinct levels: the faces give -1, 0, +1.
        Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(X);
        if (qr.rank() < 4)
            return "nonlinearity fit of element " + std::to_string(i) +
                   ": too few distinct positions";
        const Eigen::Vector4d cf = qr.solve(y);
        for (int k = 0; k < 4; k++)
            c.acc_nonlin[i][k] = cf(k);
        out.nl_v[i] = vs;
        out.nl_rms[i] = std::sqrt((X * cf - y).squaredNorm() / n);
    }
    c.have_nonlin = true;
    out.nonlin = true;
    return "";
}

} // namespace

std::string station_record(const std::vector<Soak> &soaks, const calrec_binding &id,
                           StationOut &out)
{
    if (soaks.empty()) return "no soak";
    const Soak &amb = soaks[0];
    calstation::CalResult c;
    // Cross-axis terms from the ambient faces: after the on-device offset and gain, element i
    // reads v_i = P_i . a; on the faces +-j the difference of the two readings is 2 P_ij (the
    // flip cancels offset and the even nonlinearity). P_ii = 1 by construction. M = P^-1.
    Eigen::Matrix3d P;
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) {
            P(i, j) = 0.5 * (element_v(amb, amb.faces[2 * j], i) -
                             element_v(amb, amb.faces[2 * j + 1], i));
        }
    }
    const Eigen::Matrix3d M = P.inverse();
    if (!amb.sweep.empty()) {
        const std::string e = fit_nonlinearity(amb, P, c, out);
        if (!e.empty()) return e;
    }
    for (int i = 0; i < 3; i++) {
        c.acc_offset[i] = amb.six.acc_offset[i] / kQ16;
        c.acc_gain[i] = amb.six.acc_gain[i] / kQ30;
        c.gyro_offset[i] = amb.six.gyro_offset[i] / kQ16;
        c.gyro_scale[i] = 1.0;
        for (int j = 0; j < 3; j++) {
            c.acc_misalign[i][j] = M(i, j);
            out.misalign[i][j] = M(i, j);
        }
    }
    out.tcal = soaks.size() >= 3;
    out.t_amb = amb.temp_c;
    if (out.tcal) {
        // [ADI-EPB]'s three-point procedure on the on-device flip results: offset(T) and
        // gain(T), as deviations from the ambient values the record holds.
        out.t_cold = out.t_hot = amb.temp_c;
        for (int a = 0; a < 3; a++) {
            std::vector<calstation::TPoint> bias, scale;
            for (const Soak &s : soaks) {
                bias.push_back({s.temp_c, s.six.acc_offset[a] / kQ16});
                scale.push_back({s.temp_c, s.six.acc_gain[a] / kQ30});
                out.t_cold = std::min(out.t_cold, s.temp_c);
                out.t_hot = std::max(out.t_hot, s.temp_c);
            }
            const calstation::TFit fb = calstation::fit_three_point(bias, amb.temp_c);
            const calstation::TFit fs = calstation::fit_three_point(scale, amb.temp_c);
            if (!fb.ok) return "three-point offset fit: " + fb.message;
            if (!fs.ok) return "three-point gain fit: " + fs.message;
            c.acc_tbias[a] = calstation::to_deviation(fb.model, c.acc_offset[a], false);
            c.acc_tscale[a] = calstation::to_deviation(fs.model, c.acc_gain[a], true);
        }
        c.tmodel = calstation::TChoice::Parabola;
    }
    calstation::Station st;
    st.have_binding = true;
    st.binding = {id.family, id.product, id.revision, id.serial, id.lot_id1, id.lot_id2};
    const std::string err = calstation::to_calrec(c, st, out.rec);
    if (!err.empty()) return err;
    // The on-device results stay exactly as the firmware computed them.
    for (int i = 0; i < 3; i++) {
        out.rec.acc_offset[i] = amb.six.acc_offset[i];
        out.rec.acc_gain[i] = amb.six.acc_gain[i];
        out.rec.gyro_offset[i] = amb.six.gyro_offset[i];
    }
    return calrec_check(&out.rec) == INC_OK ? "" : "record out of range after the on-device values";
}

Budget derive_budget(const sim_calpart_params &type, const StationOut &st, double acc_lsb_g,
                     double temp_lsb_c, uint32_t n_face, const app_cfg &cfg)
{
    Budget out;
    const uint32_t runs = cfg.budget.lifetime_runs;
    const fx_q16_t exceed = cfg.budget.exceed_expected;
    const double max_slope_deg = cfg.slope.max_slope_deg / kQ16;
    const double margin = cfg.temp_margin_c / kQ16;
    fx_q16_t kq = FX_Q16_INT(6);
    (void)slope_sigma_factor(runs, exceed, &kq);
    const double k = kq / kQ16;
    const double sigma = std::sqrt(type.acc_noise_g * type.acc_noise_g +
                                   acc_lsb_g * acc_lsb_g / 12.0);
    out.sigma_sample_g = sigma;
    const calstation::CalResult rec = calstation::from_calrec(st.rec);
    const double n = static_cast<double>(n_face);

    // Flip line of the part type at (T, hysteresis m): offset b + K nl2, gain K (1 + nl3).
    auto flip_off = [&](int a, double t, double m) {
        return sim_calpart_tcurve_eval(&type.acc_bias[a], t, m) +
               sim_calpart_tcurve_eval(&type.acc_scale[a], t, m) * type.acc_nl2[a];
    };
    auto flip_gain = [&](int a, double t, double m) {
        return sim_calpart_tcurve_eval(&type.acc_scale[a], t, m) * (1.0 + type.acc_nl3[a]);
    };

    // Nonlinearity left by the flip line within +-max_slope: e(x) = (nl2 (x^2 - 1) + nl3 (x^3 - x)) / (1 + nl3).
    const double xmax = std::sin(max_slope_deg * kPi / 180.0);
    double nl = 0.0;
    for (int a = 0; a < 3; a++) {
        for (int i = 0; i <= 1000; i++) {
            const double x = -xmax + 2.0 * xmax * i / 1000.0;
            const double e = (type.acc_nl2[a] * (x * x - 1.0) + type.acc_nl3[a] * (x * x * x - x)) /
                             (1.0 + type.acc_nl3[a]);
            nl = std::max(nl, std::fabs(e));
        }
    }
    out.char_nonlin_g = nl;

    // With the sweep: what the record's cubic leaves of the part type's nonlinearity, and the
    // fit's own noise (k sigma_fit), both within +-max_slope.
    if (st.nonlin) {
        double resid = 0.0, fitsd = 0.0;
        const double sig_pt = sigma * std::sqrt(2.0 / static_cast<double>(n_face));
        for (int a = 0; a < 3; a++) {
            const int32_t *cq = st.rec.acc_nonlin[a];
            const std::vector<double> &vs = st.nl_v[a];
            Eigen::MatrixXd X(static_cast<Eigen::Index>(vs.size()), 4);
            for (size_t r = 0; r < vs.size(); r++)
                X.row(static_cast<Eigen::Index>(r)) = cubic_row(vs[r]).transpose();
            const Eigen::Matrix4d cov = (X.transpose() * X).inverse();
            for (int i = 0; i <= 1000; i++) {
                const double x = -xmax + 2.0 * xmax * i / 1000.0;
                const double nl2 = type.acc_nl2[a], nl3 = type.acc_nl3[a];
                const double v = (x + nl2 * x * x + nl3 * x * x * x - nl2) / (1.0 + nl3);
                const double y = v + cq[0] / kQ30 +
                                 v * (cq[1] / kQ30 + v * (cq[2] / kQ30 + v * (cq[3] / kQ30)));
                resid = std::max(resid, std::fabs(y - x));
                fitsd = std::max(fitsd, std::sqrt(cubic_row(v).dot(cov * cubic_row(v))));
            }
        }
        out.resid_nonlin_g = resid;
        out.fit_nonlin_g = k * sig_pt * fitsd;
    }

    // Temperature: the record's models against the part type's flip line, both branches.
    double tres = 0.0, sres = 0.0, sdrift = 0.0;
    const double tlo = st.tcal ? st.t_cold - margin : SIM_CALPART_T_MIN;
    const double thi = st.tcal ? st.t_hot + margin : SIM_CALPART_T_MAX;
    const double half = 0.5 * temp_lsb_c;
    for (int a = 0; a < 3; a++) {
        const double g25 = flip_gain(a, st.t_amb, 0.0);
        for (int i = 0; i <= 400; i++) {
            const double t = tlo + (thi - tlo) * i / 400.0; // true temperature
            for (double m : {-1.0, 0.0, 1.0}) {
                sdrift = std::max(sdrift, std::fabs(flip_gain(a, t, m) / g25 - 1.0));
                if (!st.tcal) continue;
                for (double d : {-half, 0.0, half}) { // the reading the firmware evaluates at
                    const double off = rec.acc_offset[a] + rec.acc_tbias[a].eval(t + d);
                    const double gain = rec.acc_gain[a] * (1.0 + rec.acc_tscale[a].eval(t + d));
                    tres = std::max(tres, std::fabs(flip_off(a, t, m) - off));
                    sres = std::max(sres, std::fabs(flip_gain(a, t, m) / gain - 1.0));
                }
            }
        }
    }
    out.char_temp_g = tres;
    out.char_scale = st.tcal ? sres : sdrift;

    double off_uncal = 0.0, sens_uncal = 0.0;
    for (int a = 0; a < 3; a++) {
        off_uncal = std::max(off_uncal, std::fabs(flip_off(a, 25.0, 0.0)));
        sens_uncal = std::max(sens_uncal, std::fabs(flip_gain(a, 25.0, 0.0) - 1.0));
    }

    const double arith = 4.0 / kQ16; // cal_acc_apply: <= 3.5 LSB Q16 (cal.h)
    const double offset = k * sigma / std::sqrt(n) + arith;
    const double sens = k * sigma / std::sqrt(2.0 * n) + (st.tcal ? sres : 0.0);
    const double nonlin = st.nonlin ? out.resid_nonlin_g + out.fit_nonlin_g
                                    : std::max(kSeedNonlin, nl);
    const double tcomp = st.tcal ? tres : kSeedTempUncomp;

    app_budget &b = out.b;
    b.sensitivity = up30(sens);
    b.offset_g = up16(offset);
    b.offset_drift_g = cfg.budget.offset_drift_g; // the part type's, not the station's
    b.nonlinearity_g = up16(nonlin);
    b.temp_comp_g = up16(tcomp);
    b.temp_uncomp_g = up16(kSeedTempUncomp);
    b.tscale_uncomp = up30(sdrift);
    b.sensitivity_uncal = up30(std::max(kSeedSensUncal, sens_uncal));
    b.offset_uncal_g = up16(std::max(kSeedOffsetUncal, off_uncal));
    b.noise_sigma_g = up16(sigma);
    b.lifetime_runs = runs;
    b.exceed_expected = exceed;

    char buf[256];
    out.terms.push_back({"sensitivity", sens, ""});
    std::snprintf(buf, sizeof buf, "flip gain from %u-sample faces, k sigma/sqrt(2N)%s", n_face,
                  st.tcal ? " + three-point scale residual" : "");
    out.terms.back().origin = buf;
    std::snprintf(
        buf, sizeof buf,
        "flip offset and cross-axis from %u-sample faces, k sigma/sqrt(N), + 4 LSB arithmetic, "
        "+ %.1f mg offset change after calibration ([ADI-EPB], checked: docs/safety.md)",
        n_face, cfg.budget.offset_drift_g / kQ16 * 1e3);
    out.terms.push_back({"offset", offset + cfg.budget.offset_drift_g / kQ16, buf});
    if (st.nonlin) {
        std::snprintf(
            buf, sizeof buf,
            "cubic from faces + %zu-point tilt sweep: part type residual %.3f mg + k sigma_fit %.3f mg "
            "within +-%.0f deg (uncorrected %.2f mg)",
            st.nl_v[0].size() - CAL_FACES, out.resid_nonlin_g * 1e3, out.fit_nonlin_g * 1e3,
            max_slope_deg, nl * 1e3);
    } else {
        std::snprintf(buf, sizeof buf,
                      "not corrected: max([ADI-EPB] 10 mg, part type %.2f mg within +-%.0f deg)",
                      nl * 1e3, max_slope_deg);
    }
    out.terms.push_back({"nonlinearity", nonlin, buf});
    if (st.tcal) {
        std::snprintf(buf, sizeof buf,
                      "three-point models vs the part type over %.1f..%.1f degC (+-%.1f margin), "
                      "both hysteresis branches",
                      st.t_cold, st.t_hot, margin);
    } else {
        std::snprintf(buf, sizeof buf, "no temperature model: [ADI-EPB]'s 50 mg");
    }
    out.terms.push_back({"temperature", tcomp, buf});
    std::snprintf(buf, sizeof buf, "rated per sample: sqrt(%.2f mg element^2 + LSB^2/12), k = %.2f",
                  type.acc_noise_g * 1e3, k);
    out.terms.push_back({"noise sigma", sigma, buf});
    return out;
}

} // namespace epb
