// compare.cpp - see compare.hpp.
#include "inclino/calstation/compare.hpp"

#include "inclino/cal.h"
#include "inclino/calstation/record.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace calstation
{

std::string compare_part(const SimPart &part, const CompareConfig &cfg,
                         std::vector<CompareAxis> &out)
{
    SimConfig sc;
    sc.part = part;
    sc.schedule = Schedule::Calibration;
    sc.cycles = cfg.cycles;
    sc.noise_seed = cfg.noise_seed;
    const Station cal = simulate_station(sc);
    sc.schedule = Schedule::Validation;
    sc.cycles = cfg.validation_cycles;
    sc.noise_seed = cfg.noise_seed + 1000;
    const Station val = simulate_station(sc);

    std::vector<BlockMeas> cb, vb;
    std::string e = block_measurements(cal, cb);
    if (e.empty()) e = block_measurements(val, vb);
    if (!e.empty()) return e;
    const auto cs = soak_points(cb), vs = soak_points(vb);
    const TemperatureFits tf = fit_temperature(cb, cs, cal.t_ref_c);
    const std::string name = part.paper ? "A" : "seed " + std::to_string(part.curve_seed);
    for (int a = 0; a < 3; a++) {
        CompareAxis ca;
        ca.part = name;
        ca.axis = a;
        for (int k = -1; k < TemperatureFits::kKinds; k++) {
            const TFit *fb = k >= 0 ? &tf.bias[k][a] : nullptr,
                       *fs = k >= 0 ? &tf.scale[k][a] : nullptr;
            CompareCell &b = ca.bias[k + 1], &s = ca.scale[k + 1];
            b.ok = !fb || fb->ok;
            s.ok = !fs || fs->ok;
            const TModel *mb = fb && fb->ok ? &fb->model : nullptr;
            const TModel *ms = fs && fs->ok ? &fs->model : nullptr;
            const Spread in = spread(cb, cs, a, mb, ms), ho = spread(vb, vs, a, mb, ms);
            b.in_sample = in.bias_mean_mg;
            b.in_all = in.bias_all_mg;
            b.held_out = ho.bias_mean_mg;
            s.in_sample = in.scale_mean_ppm;
            s.in_all = in.scale_all_ppm;
            s.held_out = ho.scale_mean_ppm;
        }
        // The best model as the firmware evaluates it: quantised into a record (the same path as
        // calstation fit --out), B(T) = offset + tbias(T), K(T) = gain * (1 + tscale(T)).
        {
            const TFit &fb = tf.bias[4][a], &fs = tf.scale[4][a];
            CompareCell &b = ca.bias[CompareAxis::kCells - 1],
                        &s = ca.scale[CompareAxis::kCells - 1];
            b.ok = s.ok = fb.ok && fs.ok;
            if (b.ok) {
                CalResult c;
                c.acc_offset[a] = fb.model.eval(cal.t_ref_c);
                c.acc_gain[a] = fs.model.eval(cal.t_ref_c);
                c.acc_tbias[a] = to_deviation(fb.model, c.acc_offset[a], false);
                c.acc_tscale[a] = to_deviation(fs.model, c.acc_gain[a], true);
                for (int i = 0; i < 3; i++) {
                    c.acc_misalign[i][i] = 1.0;
                    if (i != a) c.acc_gain[i] = 1.0;
                }
                struct calrec r;
                Station bind = cal;
                b.ok = s.ok = to_calrec(c, bind, r).empty();
                if (b.ok) {
                    const auto fw_b = [&r, a](double t) {
                        int32_t y = 0;
                        (void)cal_tmodel_eval(&r.acc_tbias[a],
                                              static_cast<fx_q16_t>(std::lround(t * 65536.0)), &y);
                        return (r.acc_offset[a] + y) / 65536.0;
                    };
                    const auto fw_k = [&r, a](double t) {
                        int32_t y = 0;
                        (void)cal_tmodel_eval(&r.acc_tscale[a],
                                              static_cast<fx_q16_t>(std::lround(t * 65536.0)), &y);
                        return r.acc_gain[a] / 1073741824.0 * (1.0 + y / 1073741824.0);
                    };
                    const Spread in = spread_fn(cb, cs, a, fw_b, fw_k),
                                 ho = spread_fn(vb, vs, a, fw_b, fw_k);
                    b.in_sample = in.bias_mean_mg;
                    b.in_all = in.bias_all_mg;
                    b.held_out = ho.bias_mean_mg;
                    s.in_sample = in.scale_mean_ppm;
                    s.in_all = in.scale_all_ppm;
                    s.held_out = ho.scale_mean_ppm;
                }
            }
        }
        out.push_back(ca);
    }
    return "";
}

std::string format_compare(const std::vector<CompareAxis> &rows)
{
    static const char *const ax[3] = {"x", "y", "z"};
    std::string o;
    char b[256];
    for (int q = 0; q < 2; q++) {
        o +=
            q ? "\nScale factor, (Kmax-Kmin)/Kmean*1e6/span in ppm/degC (paper: 151.6 -> 45.89 linear -> 11.8 Lorentz)\n"
              : "Bias, Bmax-Bmin in mg (paper: 14 -> 6.91 linear -> 1.3 Lorentz)\n";
        o +=
            "worst axis per part; in-sample soak-point means (paper's definition) / every soak / held out at -15..55 degC\n\n";
        o +=
            "| part | raw | linear | 3-point parabola | Lorentz | PWL (10 degC knots) | Lorentz + cubic (best) | best, firmware fixed point |\n";
        o += "|---|---|---|---|---|---|---|---|\n";
        std::map<std::string, std::array<CompareCell, CompareAxis::kCells>> worst;
        std::vector<std::string> order;
        for (const auto &r : rows) {
            const bool first = !worst.count(r.part);
            if (first) order.push_back(r.part);
            auto &w = worst[r.part];
            const auto &cells = q ? r.scale : r.bias;
            for (size_t k = 0; k < cells.size(); k++) {
                w[k].ok = cells[k].ok && (first || w[k].ok); // n/a when any axis of the part failed
                w[k].in_sample = std::max(w[k].in_sample, cells[k].in_sample);
                w[k].in_all = std::max(w[k].in_all, cells[k].in_all);
                w[k].held_out = std::max(w[k].held_out, cells[k].held_out);
            }
        }
        for (const auto &p : order) {
            o += "| " + p + " |";
            for (const auto &c : worst[p]) {
                if (!c.ok) {
                    o += " n/a |";
                    continue;
                }
                std::snprintf(b, sizeof b, q ? " %.2f / %.2f / %.2f |" : " %.3f / %.3f / %.3f |",
                              c.in_sample, c.in_all, c.held_out);
                o += b;
            }
            o += "\n";
        }
    }
    o +=
        "\nPer axis (in-sample means / held out):\n\n| part | axis | quantity | raw | linear | 3-point | Lorentz | PWL | Lorentz + cubic | firmware |\n|---|---|---|---|---|---|---|---|---|---|\n";
    for (const auto &r : rows) {
        for (int q = 0; q < 2; q++) {
            std::snprintf(b, sizeof b, "| %s | %s | %s |", r.part.c_str(), ax[r.axis],
                          q ? "scale ppm/degC" : "bias mg");
            o += b;
            for (const auto &c : (q ? r.scale : r.bias)) {
                if (!c.ok) {
                    o += " n/a |";
                    continue;
                }
                std::snprintf(b, sizeof b, q ? " %.2f / %.2f |" : " %.3f / %.3f |", c.in_sample,
                              c.held_out);
                o += b;
            }
            o += "\n";
        }
    }
    return o;
}

} // namespace calstation
