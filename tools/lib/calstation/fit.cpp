// fit.cpp - see fit.hpp.
#include "inclino/calstation/fit.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <numeric>
#include <set>

namespace calstation
{

namespace
{

const char *const kAxis[3] = {"x", "y", "z"};

// Record limits (calrec.h), in physical units.
constexpr double kLimOffsetG = 0.5;
constexpr double kLimGainMin = 0.75, kLimGainMax = 1.25;
constexpr double kLimOffDiag = 0.125;
constexpr double kLimC01 = 0.0625, kLimC23 = 0.25;
constexpr double kLimTBiasG = 0.5;
constexpr double kLimTScale = 0.125;
constexpr double kLimGyroOffset = 30.0;
constexpr double kSoakGapC = 2.0;
// The placement check (FitMethod::Auto): placement errors are declared when the nominal fit's
// rms residual against the nominal directions exceeds kPlacementRatio times its rms residual
// against 1 g plus kPlacementFloorMg, or its residual against 1 g exceeds kPlacementRatio times
// the per-axis pair method's plus the floor. On the simulated positioner: 0.36 against 0.32 mg,
// and 0.32 against 0.37 mg; 2 deg of hand placement: about 22 against 10 mg, and 10 against
// 0.5 mg.
constexpr double kPlacementRatio = 2.0;
constexpr double kPlacementFloorMg = 0.05;

// a with `prec` significant digits (g) or, for prec < 0, -prec decimals (f).
std::string num(double a, int prec)
{
    char b[64];
    if (prec >= 0)
        std::snprintf(b, sizeof b, "%.*g", prec, a);
    else
        std::snprintf(b, sizeof b, "%.*f", -prec, a);
    return b;
}

bool is_face(const Row &r, int axis, int sign)
{
    return r.kind == RowKind::Acc && r.u[axis] * sign > 0.999;
}

double mean_of(const std::vector<double> &v)
{
    return v.empty() ? 0.0 : std::accumulate(v.begin(), v.end(), 0.0) / v.size();
}

std::string check_tmodel(const TModel &m, double ylim, const std::string &what)
{
    auto bad = [&](const std::string &s) { return "coefficient out of range: " + what + " " + s; };
    if (m.kind == TKind::None) return "";
    for (int k = 0; k < m.params(); k++) {
        if (tparam_is_degc(m.kind, k)) {
            continue; // the Lorentz width and centre: their own limits below
        }
        if (!(std::fabs(m.p[k]) <= ylim)) {
            return bad("parameter p" + std::to_string(k) + " = " + num(m.p[k], 6) + " (limit +-" +
                       num(ylim, 6) + ")");
        }
    }
    if (m.kind == TKind::Lorentz || m.kind == TKind::LorentzCubic) {
        if (!(m.p[2] >= 1.0 && m.p[2] <= 400.0))
            return bad("Lorentz width " + num(m.p[2], 6) + " degC (limit 1..400)");
        if (!(m.p[3] >= -100.0 && m.p[3] <= 200.0))
            return bad("Lorentz centre " + num(m.p[3], 6) + " degC (limit -100..200)");
    }
    if (m.kind != TKind::Lorentz) {
        if (!(m.t_ref >= -100.0 && m.t_ref <= 200.0)) return bad("t_ref " + num(m.t_ref, 6));
        if (!(m.t_span >= 1.0 && m.t_span <= 200.0))
            return bad("t_span " + num(m.t_span, 6) + " degC (limit 1..200)");
    }
    return "";
}

} // namespace

// Temperature model of B(T) or K(T) shifted/scaled into the record's deviation form.
TModel to_deviation(const TModel &m, double ref, bool relative)
{
    TModel d = m;
    std::vector<int> lin; // indices of the parameters the model is linear in
    switch (m.kind) {
    case TKind::None: return d;
    case TKind::Linear: lin = {0, 1}; break;
    case TKind::Parabola: lin = {0, 1, 2}; break;
    case TKind::Lorentz: lin = {0, 1}; break;
    case TKind::LorentzCubic: lin = {0, 1, 4, 5, 6}; break;
    case TKind::Pwl:
        for (int k = 0; k < m.n; k++)
            lin.push_back(k);
        break;
    }
    // The constant part: p0 for every kind but PWL, where every knot carries it.
    const bool pwl = m.kind == TKind::Pwl;
    if (relative) {
        for (int k : lin)
            d.p[k] /= ref;
        if (pwl)
            for (int k = 0; k < m.n; k++)
                d.p[k] -= 1.0;
        else
            d.p[0] -= 1.0;
    } else {
        if (pwl)
            for (int k = 0; k < m.n; k++)
                d.p[k] -= ref;
        else
            d.p[0] -= ref;
    }
    return d;
}

bool parse_tchoice(const std::string &s, TChoice &c)
{
    static const std::map<std::string, TChoice> m = {{"best", TChoice::Best},
                                                     {"none", TChoice::None},
                                                     {"linear", TChoice::Linear},
                                                     {"parabola", TChoice::Parabola},
                                                     {"three-point", TChoice::Parabola},
                                                     {"lorentz", TChoice::Lorentz},
                                                     {"pwl", TChoice::Pwl},
                                                     {"lorentz-cubic", TChoice::LorentzCubic}};
    const auto it = m.find(s);
    if (it == m.end()) return false;
    c = it->second;
    return true;
}

const char *tchoice_name(TChoice c)
{
    switch (c) {
    case TChoice::Best: return "best";
    case TChoice::None: return "none";
    case TChoice::Linear: return "linear";
    case TChoice::Parabola: return "three-point parabola";
    case TChoice::Lorentz: return "lorentz";
    case TChoice::Pwl: return "pwl";
    case TChoice::LorentzCubic: return "lorentz+cubic";
    }
    return "?";
}

const char *TemperatureFits::name(int k)
{
    static const char *const n[kKinds] = {"linear", "3-point", "lorentz", "pwl", "lorentz+cubic"};
    return n[k];
}

std::string block_measurements(const Station &st, std::vector<BlockMeas> &out)
{
    out.clear();
    std::map<long, std::vector<const Row *>> by_block;
    for (const auto &r : st.rows) {
        if (r.kind == RowKind::Acc) by_block[r.block].push_back(&r);
    }
    for (const auto &kv : by_block) {
        BlockMeas b;
        b.block = kv.first;
        std::vector<double> temps;
        for (int a = 0; a < 3; a++) {
            std::vector<double> pos, neg;
            int lp = 0, ln = 0;
            for (const Row *r : kv.second) {
                if (is_face(*r, a, +1)) {
                    pos.push_back(r->v[a] * st.acc_lsb_g);
                    lp = r->line;
                    temps.push_back(r->temp_c);
                }
                if (is_face(*r, a, -1)) {
                    neg.push_back(r->v[a] * st.acc_lsb_g);
                    ln = r->line;
                    temps.push_back(r->temp_c);
                }
            }
            if (pos.empty() || neg.empty()) continue;
            const double ap = mean_of(pos), an = mean_of(neg);
            if (!(ap > an)) {
                return "degenerate data: axis " + std::string(kAxis[a]) + ", block " +
                       std::to_string(b.block) + ": the +1 g face (line " + std::to_string(lp) +
                       ") reads " + num(ap, -4) + " g, not above the -1 g face (line " +
                       std::to_string(ln) + ", " + num(an, -4) +
                       " g): +1 g and -1 g swapped (or the axis is dead)";
            }
            b.have[a] = true;
            // [ADI-EPB]: offset = (A+ + A-)/2, gain = (A+ - A-)/2. [ADI-EPB] prints the gain as
            // 0.5 * (A+ - A-)/2; that extra 0.5 is a misprint (docs/references.md).
            b.bias[a] = 0.5 * (ap + an);
            b.scale[a] = 0.5 * (ap - an);
        }
        if (b.have[0] || b.have[1] || b.have[2]) {
            b.t = mean_of(temps);
            out.push_back(b);
        }
    }
    return "";
}

std::vector<std::vector<size_t>> soak_points(const std::vector<BlockMeas> &b)
{
    std::vector<size_t> idx(b.size());
    for (size_t i = 0; i < idx.size(); i++)
        idx[i] = i;
    std::sort(idx.begin(), idx.end(), [&](size_t x, size_t y) { return b[x].t < b[y].t; });
    std::vector<std::vector<size_t>> s;
    for (size_t k = 0; k < idx.size(); k++) {
        if (k == 0 || b[idx[k]].t - b[idx[k - 1]].t > kSoakGapC) s.emplace_back();
        s.back().push_back(idx[k]);
    }
    return s;
}

Spread spread(const std::vector<BlockMeas> &b, const std::vector<std::vector<size_t>> &soaks, int a,
              const TModel *bm, const TModel *sm)
{
    return spread_fn(
        b, soaks, a,
        bm ? std::function<double(double)>([bm](double t) { return bm->eval(t); }) : nullptr,
        sm ? std::function<double(double)>([sm](double t) { return sm->eval(t); }) : nullptr);
}

Spread spread_fn(const std::vector<BlockMeas> &b, const std::vector<std::vector<size_t>> &soaks,
                 int a, const std::function<double(double)> &bm,
                 const std::function<double(double)> &sm)
{
    Spread r;
    double blo = 1e300, bhi = -1e300, mlo = 1e300, mhi = -1e300;
    double klo = 1e300, khi = -1e300, ksum = 0.0, kmlo = 1e300, kmhi = -1e300, kmsum = 0.0;
    double tlo = 1e300, thi = -1e300;
    int nk = 0, nm = 0;
    for (const auto &s : soaks) {
        double bs = 0.0, ks = 0.0, ts = 0.0;
        int n = 0;
        for (size_t i : s) {
            if (!b[i].have[a]) continue;
            const double bb = b[i].bias[a] - (bm ? bm(b[i].t) : 0.0);
            const double kk = b[i].scale[a] / (sm ? sm(b[i].t) : 1.0);
            blo = std::min(blo, bb);
            bhi = std::max(bhi, bb);
            klo = std::min(klo, kk);
            khi = std::max(khi, kk);
            ksum += kk;
            nk++;
            bs += bb;
            ks += kk;
            ts += b[i].t;
            n++;
        }
        if (!n) continue;
        mlo = std::min(mlo, bs / n);
        mhi = std::max(mhi, bs / n);
        kmlo = std::min(kmlo, ks / n);
        kmhi = std::max(kmhi, ks / n);
        kmsum += ks / n;
        nm++;
        tlo = std::min(tlo, ts / n);
        thi = std::max(thi, ts / n);
    }
    if (nm < 1) return r;
    // [TEMP-LORENTZ] eq. (8)-(15): B = Bmax - Bmin; dK = (Kmax - Kmin) / Kmean * 1e6 / span, with the
    // span of the soak temperatures (80 degC in the paper).
    const double span = std::max(thi - tlo, 1e-9);
    r.bias_mean_mg = (mhi - mlo) * 1e3;
    r.bias_all_mg = (bhi - blo) * 1e3;
    r.scale_mean_ppm = (kmhi - kmlo) / (kmsum / nm) * 1e6 / span;
    r.scale_all_ppm = (khi - klo) / (ksum / nk) * 1e6 / span;
    return r;
}

TemperatureFits fit_temperature(const std::vector<BlockMeas> &b,
                                const std::vector<std::vector<size_t>> &soaks, double t_ref)
{
    TemperatureFits tf;
    for (int a = 0; a < 3; a++) {
        std::vector<TPoint> bp, sp, bmean, smean;
        for (const auto &s : soaks) {
            double bs = 0.0, ks = 0.0, ts = 0.0;
            int n = 0;
            for (size_t i : s) {
                if (!b[i].have[a]) continue;
                bp.push_back({b[i].t, b[i].bias[a]});
                sp.push_back({b[i].t, b[i].scale[a]});
                bs += b[i].bias[a];
                ks += b[i].scale[a];
                ts += b[i].t;
                n++;
            }
            if (n) {
                bmean.push_back({ts / n, bs / n});
                smean.push_back({ts / n, ks / n});
            }
        }
        // The Lorentz height limit: the record's y-format limit (bias in g; the scale factor's
        // height becomes a relative deviation of the same order, checked again at the end).
        tf.bias[0][a] = fit_linear(bp);
        tf.scale[0][a] = fit_linear(sp);
        tf.bias[1][a] = fit_three_point(bmean, t_ref);
        tf.scale[1][a] = fit_three_point(smean, t_ref);
        // The Lorentz height is bounded twice. By the record's limit of the deviation it becomes
        // (bias in g directly; the scale factor's height is divided by the reference scale
        // factor, about 1, so its bound keeps a 4 % margin below the 0.125 limit). And by four
        // times the spread of the data: a taller peak is not seen in the data at all, only its
        // flank, and with a cubic background it degenerates into a very wide Lorentz cancelled
        // by a large y0 (a parabola in disguise, at the parameter bounds).
        double kmin = 1.0, blo = 1e300, bhi = -1e300, klo = 1e300, khi = -1e300;
        for (const auto &q : sp) {
            kmin = std::min(kmin, q.y);
            klo = std::min(klo, q.y);
            khi = std::max(khi, q.y);
        }
        for (const auto &q : bp) {
            blo = std::min(blo, q.y);
            bhi = std::max(bhi, q.y);
        }
        const double hb = std::min(kLimTBiasG, 4.0 * (bhi - blo));
        const double hs = std::min(0.12 * kmin, 4.0 * (khi - klo));
        tf.bias[2][a] = fit_lorentz(bp, hb);
        tf.scale[2][a] = fit_lorentz(sp, hs);
        // PWL: uniform knots over the soak range at the most common soak spacing (the median
        // of consecutive differences: 10 degC for [TEMP-LORENTZ]'s schedule, which is not upset by an
        // extra ambient point), at most kTParams knots.
        if (bmean.size() >= 2) {
            std::vector<double> d;
            for (size_t i = 1; i < bmean.size(); i++)
                d.push_back(bmean[i].t - bmean[i - 1].t);
            std::sort(d.begin(), d.end());
            const double t0 = bmean.front().t, range = bmean.back().t - t0;
            const double med = d[d.size() / 2];
            const int n = static_cast<int>(
                std::clamp<long>(std::lround(range / med) + 1, 2, kTParams));
            const double dt = range / (n - 1);
            tf.bias[3][a] = fit_pwl(bp, t0, dt, n);
            tf.scale[3][a] = fit_pwl(sp, t0, dt, n);
        } else {
            tf.bias[3][a].message = tf.scale[3][a].message = "PWL fit needs 2 soak points";
        }
        tf.bias[4][a] = fit_lorentz_cubic(bp, hb);
        tf.scale[4][a] = fit_lorentz_cubic(sp, hs);
    }
    return tf;
}

static int choice_index(TChoice c)
{
    switch (c) {
    case TChoice::Linear: return 0;
    case TChoice::Parabola: return 1;
    case TChoice::Lorentz: return 2;
    case TChoice::Pwl: return 3;
    case TChoice::LorentzCubic:
    case TChoice::Best: return 4;
    case TChoice::None: return -1;
    }
    return -1;
}

std::array<double, 3> apply_double(const CalResult &c, const std::array<double, 3> &r, double t)
{
    std::array<double, 3> n{}, out{};
    for (int i = 0; i < 3; i++) {
        const double b = c.acc_offset[i] + c.acc_tbias[i].eval(t);
        const double k = c.acc_gain[i] * (1.0 + c.acc_tscale[i].eval(t));
        const double v = (r[i] - b) / k;
        const double x = std::clamp(v, -1.25, 1.25);
        const auto &q = c.acc_nonlin[i];
        n[i] = v + q[0] + x * (q[1] + x * (q[2] + x * q[3]));
    }
    for (int i = 0; i < 3; i++) {
        out[i] = c.acc_misalign[i][0] * n[0] + c.acc_misalign[i][1] * n[1] +
                 c.acc_misalign[i][2] * n[2];
    }
    return out;
}

namespace
{

std::string static_report(const Station &st, const CalResult &flip, const CalResult &lin,
                          const CalResult &c)
{
    // Static accuracy over the ambient-temperature rows, stage by stage.
    struct Acc {
        double max = 0.0, ss = 0.0;
        int n = 0;
    };
    Acc stage[3], tilt[3];
    // The rows of the soak nearest t_ref (the ambient rows; a session at one temperature: all).
    double t_near = st.t_ref_c, best = 1e300;
    for (const auto &r : st.rows) {
        if (r.kind == RowKind::Acc && std::fabs(r.temp_c - st.t_ref_c) < best) {
            best = std::fabs(r.temp_c - st.t_ref_c);
            t_near = r.temp_c;
        }
    }
    CalResult diag = flip;
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++)
            diag.acc_misalign[i][j] = (i == j);
        diag.acc_nonlin[i] = {0, 0, 0, 0};
    }
    for (const auto &r : st.rows) {
        if (r.kind != RowKind::Acc || std::fabs(r.temp_c - t_near) > kSoakGapC) continue;
        const std::array<double, 3> raw = {r.v[0] * st.acc_lsb_g, r.v[1] * st.acc_lsb_g,
                                           r.v[2] * st.acc_lsb_g};
        const CalResult *cs[3] = {&diag, &lin, &c};
        bool is_tilt = false;
        for (int a = 0; a < 3; a++)
            is_tilt |= std::fabs(r.u[a]) > 0.05 && std::fabs(r.u[a]) < 0.55;
        for (int s = 0; s < 3; s++) {
            const auto o = apply_double(*cs[s], raw, r.temp_c);
            for (int a = 0; a < 3; a++) {
                const double e = std::fabs(o[a] - r.u[a]) * 1e3;
                stage[s].max = std::max(stage[s].max, e);
                stage[s].ss += e * e;
                stage[s].n++;
                if (is_tilt && std::fabs(r.u[a]) <= 0.55) {
                    tilt[s].max = std::max(tilt[s].max, e);
                    tilt[s].ss += e * e;
                    tilt[s].n++;
                }
            }
        }
    }
    char b[240];
    std::snprintf(b, sizeof b,
                  "static accuracy of the nominal-direction fit at %.1f degC (the rows within "
                  "2 degC of the soak nearest t_ref_c = %.1f), |a_corrected - u| in mg:\n",
                  t_near, st.t_ref_c);
    std::string out = b;
    const char *names[3] = {"flip offset/gain + temp.", "+ misalignment (linear LS)",
                            "+ nonlinearity"};
    auto fig = [](const Acc &a, bool rms) {
        char f[32];
        if (!a.n) return std::string("    n/a");
        std::snprintf(f, sizeof f, "%7.3f", rms ? std::sqrt(a.ss / a.n) : a.max);
        return std::string(f);
    };
    for (int s = 0; s < 3; s++) {
        std::snprintf(b, sizeof b,
                      "  %-26s all rows: max %s rms %s | within +-30 deg: max %s rms %s\n",
                      names[s], fig(stage[s], false).c_str(), fig(stage[s], true).c_str(),
                      fig(tilt[s], false).c_str(), fig(tilt[s], true).c_str());
        out += b;
    }
    if (!tilt[0].n) out += "  (no tilt rows within +-30 deg: n/a)\n";
    return out;
}

} // namespace

namespace
{

// Step 3 on r (offset, gain and temperature models already set): per element i, least squares
// of P_i . f - c0 [- c2 v^2 - c3 v^3] = v over every acc row; folds c0 into the offset and sets
// M = P^-1 and the nonlinearity terms (only with allow_nl and >= 5 distinct positions).
std::string fit_elements(const Station &st, const std::vector<const Row *> &acc, CalResult &out,
                         bool allow_nl, bool fit_c0 = true)
{
    Eigen::Matrix3d p = Eigen::Matrix3d::Identity();
    for (int i = 0; i < 3; i++) {
        std::set<long> distinct;
        for (const Row *r : acc)
            distinct.insert(std::lround(r->u[i] * 100.0));
        const bool nl = allow_nl && distinct.size() >= 5;
        out.have_nonlin |= nl;
        const int nc0 = fit_c0 ? 4 : 3; // columns before the nonlinearity terms
        const int ncol = nl ? nc0 + 2 : nc0;
        Eigen::MatrixXd m(acc.size(), ncol);
        Eigen::VectorXd y(acc.size());
        for (size_t k = 0; k < acc.size(); k++) {
            const Row &r = *acc[k];
            const double b = out.acc_offset[i] + out.acc_tbias[i].eval(r.temp_c);
            const double g = out.acc_gain[i] * (1.0 + out.acc_tscale[i].eval(r.temp_c));
            const double v = (r.v[i] * st.acc_lsb_g - b) / g;
            m(k, 0) = r.u[0];
            m(k, 1) = r.u[1];
            m(k, 2) = r.u[2];
            if (fit_c0) m(k, 3) = -1.0;
            if (nl) {
                m(k, nc0) = -v * v;
                m(k, nc0 + 1) = -v * v * v;
            }
            y(k) = v;
        }
        Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(m);
        qr.setThreshold(1e-9);
        if (qr.rank() < ncol) {
            return "degenerate data: the positions do not determine axis " + std::string(kAxis[i]) +
                   " (the acc rows must include at least four non-coplanar directions, e.g. the six faces)";
        }
        const Eigen::VectorXd c = qr.solve(y);
        for (int j = 0; j < 3; j++)
            p(i, j) = c(j);
        // c0 folded into the offset (n = v + c0 == (r - (b - k c0)) / k; k(T) differs from the
        // gain at t_ref by the tscale deviation, < 1e-2 * c0).
        if (fit_c0) out.acc_offset[i] -= out.acc_gain[i] * c(3);
        out.acc_nonlin[i] = {0.0, 0.0, nl ? c(nc0) : 0.0, nl ? c(nc0 + 1) : 0.0};
    }
    if (std::fabs(p.determinant()) < 1e-6) {
        return "degenerate data: the sensed directions are (nearly) parallel; check the station positions";
    }
    const Eigen::Matrix3d minv = p.inverse();
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++)
            out.acc_misalign[i][j] = minv(i, j);
    }

    return "";
}


// The temperature-corrected element outputs v of every acc row (fit_elements' v).
std::vector<Eigen::Vector3d> element_outputs(const Station &st, const std::vector<const Row *> &acc,
                                             const CalResult &c)
{
    std::vector<Eigen::Vector3d> v(acc.size());
    for (size_t k = 0; k < acc.size(); k++) {
        for (int i = 0; i < 3; i++) {
            const double b = c.acc_offset[i] + c.acc_tbias[i].eval(acc[k]->temp_c);
            const double g = c.acc_gain[i] * (1.0 + c.acc_tscale[i].eval(acc[k]->temp_c));
            v[k](i) = (acc[k]->v[i] * st.acc_lsb_g - b) / g;
        }
    }
    return v;
}

// Step 3, magnitude form: starting from the nominal fit c (M = R0 S0, its polar decomposition),
// Gauss-Newton on r_k = |S n(v_k)| - 1 g over every acc row, with n = v + d0 + c2 x^2 + c3 x^3
// (x = v clamped as the firmware does), parameters d0 (3), the symmetric S (6) and, on the
// axes where the nominal fit had them, c2 and c3. Each step is the minimum-norm least-squares
// solution, so what the rows do not determine (e.g. the cross-axis terms from six faces only,
// or c2 against d0 on the faces) stays at the nominal fit's value. Then R = the rotation that
// best maps S n onto the nominal directions (orthogonal Procrustes), M = R S, d0 folded into
// acc_offset.
std::string fit_magnitude(const Station &st, const std::vector<const Row *> &acc, CalResult &c)
{
    const std::vector<Eigen::Vector3d> v = element_outputs(st, acc, c);
    Eigen::Matrix3d m0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            m0(i, j) = c.acc_misalign[i][j];
    Eigen::JacobiSVD<Eigen::Matrix3d> svd(m0, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Matrix3d s = svd.matrixV() * svd.singularValues().asDiagonal() *
                        svd.matrixV().transpose();
    if ((svd.matrixU() * svd.matrixV().transpose()).determinant() < 0.0)
        return "degenerate data: the nominal-direction matrix is a reflection (an axis swapped?)";
    std::array<bool, 3> nl{};
    std::array<double, 3> d0{}, c2{}, c3{};
    for (int i = 0; i < 3; i++) {
        c2[i] = c.acc_nonlin[i][2];
        c3[i] = c.acc_nonlin[i][3];
        nl[i] = false; // the nonlinearity stays the nominal fit's (see below)
    }
    static const int kSa[6] = {0, 1, 2, 0, 0, 1}, kSb[6] = {0, 1, 2, 1, 2, 2};
    // The symmetric part's off-diagonal terms stay the nominal fit's: |S n| sees them only through
    // n_i n_j, which is zero to first order on the faces and on single-axis tilt sweeps, so the
    // magnitudes cannot determine them (on the positioner they took any value the temperature
    // hysteresis wanted, 0.35 and more). The offsets and the diagonal are what placement moves.
    const int ns = 3;
    int np = 3 + ns;
    for (int i = 0; i < 3; i++)
        np += nl[i] ? 2 : 0;
    // n(v) and the clamped x of one row.
    struct Nx {
        Eigen::Vector3d n, x;
    };
    auto element = [&](const Eigen::Vector3d &vk) {
        Nx e;
        for (int i = 0; i < 3; i++) {
            e.x(i) = std::clamp(vk(i), -1.25, 1.25);
            e.n(i) = vk(i) + d0[i] + e.x(i) * e.x(i) * (c2[i] + e.x(i) * c3[i]);
        }
        return e;
    };
    for (int it = 0; it < 50; it++) {
        Eigen::MatrixXd jac(v.size(), np);
        Eigen::VectorXd r(v.size());
        for (size_t k = 0; k < v.size(); k++) {
            const Nx e = element(v[k]);
            const Eigen::Vector3d &n = e.n, &x = e.x;
            const Eigen::Vector3d a = s * n;
            const double mag = a.norm();
            if (!(mag > 0.1)) return "degenerate data: a corrected row has no magnitude";
            r(k) = mag - 1.0;
            const Eigen::RowVector3d g = a.transpose() / mag;
            const Eigen::RowVector3d gs = g * s; // d|a|/dn
            int col = 0;
            for (int j = 0; j < 3; j++)
                jac(k, col++) = gs(j);
            for (int q = 0; q < ns; q++) {
                const int ia = kSa[q], ib = kSb[q];
                jac(k, col++) = ia == ib ? g(ia) * n(ia) : g(ia) * n(ib) + g(ib) * n(ia);
            }
            for (int j = 0; j < 3; j++) {
                if (!nl[j]) continue;
                jac(k, col++) = gs(j) * x(j) * x(j);
                jac(k, col++) = gs(j) * x(j) * x(j) * x(j);
            }
        }
        Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(jac);
        cod.setThreshold(1e-9);
        const Eigen::VectorXd d = cod.solve(-r);
        if (!d.allFinite()) return "degenerate data: the magnitude fit diverged";
        int col = 0;
        for (int j = 0; j < 3; j++)
            d0[j] += d(col++);
        for (int q = 0; q < ns; q++) {
            const double dv = d(col++);
            s(kSa[q], kSb[q]) += dv;
            if (kSa[q] != kSb[q]) s(kSb[q], kSa[q]) += dv;
        }
        for (int j = 0; j < 3; j++) {
            if (!nl[j]) continue;
            c2[j] += d(col++);
            c3[j] += d(col++);
        }
        if (d.cwiseAbs().maxCoeff() < 1e-13) break;
    }

    // The rotation from the nominal directions.
    Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
    for (size_t k = 0; k < v.size(); k++) {
        const Eigen::Vector3d n = element(v[k]).n;
        const Eigen::Vector3d u(acc[k]->u[0], acc[k]->u[1], acc[k]->u[2]);
        h += u * (s * n).transpose();
    }
    Eigen::JacobiSVD<Eigen::Matrix3d> hs(h, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Matrix3d fix = Eigen::Matrix3d::Identity();
    if ((hs.matrixU() * hs.matrixV().transpose()).determinant() < 0.0) fix(2, 2) = -1.0;
    const Eigen::Matrix3d rot = hs.matrixU() * fix * hs.matrixV().transpose();
    const Eigen::Matrix3d m = rot * s;
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++)
            c.acc_misalign[i][j] = m(i, j);
        c.acc_offset[i] -= c.acc_gain[i] * d0[i];
        c.acc_nonlin[i] = {0.0, 0.0, c2[i], c3[i]};
    }
    return "";
}

double row_mag_mg(const CalResult &c, const Station &st, const Row &r)
{
    const std::array<double, 3> raw = {r.v[0] * st.acc_lsb_g, r.v[1] * st.acc_lsb_g,
                                       r.v[2] * st.acc_lsb_g};
    const auto o = apply_double(c, raw, r.temp_c);
    return (std::sqrt(o[0] * o[0] + o[1] * o[1] + o[2] * o[2]) - 1.0) * 1e3;
}

} // namespace

Residuals residuals(const Station &st, const CalResult &c)
{
    Residuals r;
    double ms = 0.0, ds = 0.0, as = 0.0;
    for (const auto &row : st.rows) {
        if (row.kind != RowKind::Acc) continue;
        const std::array<double, 3> raw = {row.v[0] * st.acc_lsb_g, row.v[1] * st.acc_lsb_g,
                                           row.v[2] * st.acc_lsb_g};
        const auto o = apply_double(c, raw, row.temp_c);
        const double mag = std::sqrt(o[0] * o[0] + o[1] * o[1] + o[2] * o[2]);
        const double em = std::fabs(mag - 1.0) * 1e3;
        double e2 = 0.0, dot = 0.0, un = 0.0;
        for (int i = 0; i < 3; i++) {
            e2 += (o[i] - row.u[i]) * (o[i] - row.u[i]);
            dot += o[i] * row.u[i];
            un += row.u[i] * row.u[i];
        }
        const double ed = std::sqrt(e2) * 1e3;
        const double cosang = std::clamp(dot / (mag * std::sqrt(un)), -1.0, 1.0);
        const double ang = std::acos(cosang) * 180.0 / 3.14159265358979323846;
        r.mag_max_mg = std::max(r.mag_max_mg, em);
        r.dir_max_mg = std::max(r.dir_max_mg, ed);
        r.ang_max_deg = std::max(r.ang_max_deg, ang);
        ms += em * em;
        ds += ed * ed;
        as += ang * ang;
        r.rows++;
    }
    if (r.rows) {
        r.mag_rms_mg = std::sqrt(ms / r.rows);
        r.dir_rms_mg = std::sqrt(ds / r.rows);
        r.ang_rms_deg = std::sqrt(as / r.rows);
    }
    return r;
}

bool parse_fit_method(const std::string &s, FitMethod &m)
{
    if (s == "auto")
        m = FitMethod::Auto;
    else if (s == "nominal")
        m = FitMethod::Nominal;
    else if (s == "pair")
        m = FitMethod::Pair;
    else if (s == "magnitude")
        m = FitMethod::Magnitude;
    else
        return false;
    return true;
}

const char *fit_method_name(FitMethod m)
{
    switch (m) {
    case FitMethod::Auto: return "auto";
    case FitMethod::Nominal: return "nominal";
    case FitMethod::Pair: return "pair";
    case FitMethod::Magnitude: return "magnitude";
    }
    return "?";
}

std::string fit_station(const Station &st, const FitOptions &opt, CalResult &out)
{
    out = CalResult{};
    TChoice tm = opt.tmodel;
    // ---- Sanity of the data set ----
    std::vector<const Row *> acc;
    for (const auto &r : st.rows) {
        if (r.kind == RowKind::Acc) acc.push_back(&r);
    }
    if (acc.size() < 6) {
        return "too few measurements: " + std::to_string(acc.size()) +
               " acc rows; a calibration needs at least the six +-1 g faces";
    }
    {
        bool all_equal = true;
        for (const Row *r : acc) {
            for (int a = 0; a < 3; a++)
                all_equal &= std::fabs(r->u[a] - acc[0]->u[a]) < 1e-6;
        }
        if (all_equal) {
            return "degenerate data: all " + std::to_string(acc.size()) + " acc rows (lines " +
                   std::to_string(acc.front()->line) + ".." + std::to_string(acc.back()->line) +
                   ") are at the same position (" + num(acc[0]->u[0], 6) + "," +
                   num(acc[0]->u[1], 6) + "," + num(acc[0]->u[2], 6) +
                   "): offsets, gains and cross-axis terms cannot be separated";
        }
    }
    {
        // A placeholder temperature (every row the same exact value, far from t_ref) would
        // otherwise put every row outside the t_ref soak: refused, not reported as zeros.
        bool same_t = true;
        for (const Row *r : acc)
            same_t &= r->temp_c == acc[0]->temp_c;
        if (same_t && std::fabs(acc[0]->temp_c - st.t_ref_c) > kSoakGapC) {
            return "placeholder temperature: every acc row (lines " +
                   std::to_string(acc.front()->line) + ".." + std::to_string(acc.back()->line) +
                   ") has temp_c = " + num(acc[0]->temp_c, 6) + " exactly, " +
                   num(std::fabs(acc[0]->temp_c - st.t_ref_c), 4) +
                   " degC from t_ref_c = " + num(st.t_ref_c, 6) +
                   ": give the measured temperature, or set '#@ t_ref_c=' (calstation fit "
                   "--t-ref) to the temperature of the session";
        }
    }
    // ---- 1. flip pairs per block ----
    std::string e = block_measurements(st, out.blocks);
    if (!e.empty()) return e;
    for (int a = 0; a < 3; a++) {
        bool any = false;
        for (const auto &b : out.blocks)
            any |= b.have[a];
        if (!any) {
            return "degenerate data: axis " + std::string(kAxis[a]) +
                   " has no +1 g / -1 g face pair in any block (the six faces are needed)";
        }
    }
    out.soaks = soak_points(out.blocks);
    const double t_ref = st.t_ref_c;
    out.one_temperature = out.soaks.size() < 2;
    if (out.one_temperature && opt.tmodel_auto && tm != TChoice::None) tm = TChoice::None;

    // ---- 2. temperature ----
    out.tmodel = tm;
    std::array<TModel, 3> bmodel{}, smodel{};
    if (tm == TChoice::None) {
        for (int a = 0; a < 3; a++) {
            std::vector<double> bs, ks;
            for (const auto &b : out.blocks) {
                if (b.have[a]) {
                    bs.push_back(b.bias[a]);
                    ks.push_back(b.scale[a]);
                }
            }
            bmodel[a].kind = smodel[a].kind = TKind::Linear; // constant: p1 = 0
            bmodel[a].t_ref = smodel[a].t_ref = t_ref;
            bmodel[a].t_span = smodel[a].t_span = 1.0;
            bmodel[a].p[0] = mean_of(bs);
            smodel[a].p[0] = mean_of(ks);
        }
    } else {
        if (out.soaks.size() < 2) {
            return "degenerate data: one temperature only (" + num(out.blocks.front().t, -1) +
                   " degC): temperature models need soaks at two or more temperatures (three for the "
                   "three-point parabola, five for Lorentz, eight for Lorentz + cubic); use --tmodel none "
                   "for an ambient-only calibration";
        }
        out.tfits = fit_temperature(out.blocks, out.soaks, t_ref);
        const int k = choice_index(tm);
        for (int a = 0; a < 3; a++) {
            const TFit &fb = out.tfits.bias[k][a], &fs = out.tfits.scale[k][a];
            if (!fb.ok)
                return "temperature model (" + std::string(tchoice_name(tm)) + "), bias axis " +
                       kAxis[a] + ": " + fb.message;
            if (!fs.ok)
                return "temperature model (" + std::string(tchoice_name(tm)) +
                       "), scale factor axis " + kAxis[a] + ": " + fs.message;
            bmodel[a] = fb.model;
            smodel[a] = fs.model;
        }
    }
    for (int a = 0; a < 3; a++) {
        out.acc_offset[a] = bmodel[a].eval(t_ref);
        out.acc_gain[a] = smodel[a].eval(t_ref);
        if (tm == TChoice::None) {
            out.acc_tbias[a] = TModel{};
            out.acc_tscale[a] = TModel{};
        } else {
            out.acc_tbias[a] = to_deviation(bmodel[a], out.acc_offset[a], false);
            out.acc_tscale[a] = to_deviation(smodel[a], out.acc_gain[a], true);
        }
    }

    // ---- 3. misalignment and nonlinearity, per element ----
    // Run twice: linear only (for the report's middle stage) and with the nonlinearity terms
    // where a tilt sweep allows them (the record).
    const CalResult stage_flip = out;
    CalResult stage_lin = out, pair = out, nominal_for_report;
    e = fit_elements(st, acc, stage_lin, false);
    if (e.empty()) e = fit_elements(st, acc, out, true);
    if (e.empty()) e = fit_elements(st, acc, pair, true, false);
    if (!e.empty()) return e;
    nominal_for_report = out;
    CalResult mag = out;
    e = fit_magnitude(st, acc, mag);
    if (!e.empty()) return e;
    {
        CalResult raw = out;
        for (int i = 0; i < 3; i++) {
            raw.acc_offset[i] = 0.0;
            raw.acc_gain[i] = 1.0;
            raw.acc_tbias[i] = TModel{};
            raw.acc_tscale[i] = TModel{};
            raw.acc_nonlin[i] = {0, 0, 0, 0};
            for (int j = 0; j < 3; j++)
                raw.acc_misalign[i][j] = (i == j);
        }
        out.res_raw = residuals(st, raw);
        out.res_pair = residuals(st, pair);
        out.res_nominal = residuals(st, out);
        out.res_magnitude = residuals(st, mag);
        // The placement check: on a precise positioner the nominal fit's residual against the
        // nominal directions is about its residual against 1 g (noise, hysteresis and model
        // residue show in both); rows placed off their nominal directions add to the first only.
        // A second sign: the nominal fit misses 1 g by more than the per-axis pair method, whose
        // offsets are not moved by placement to first order.
        const bool placement = out.res_nominal.dir_rms_mg >
                                   kPlacementRatio * out.res_nominal.mag_rms_mg +
                                       kPlacementFloorMg ||
                               out.res_nominal.mag_rms_mg >
                                   kPlacementRatio * out.res_pair.mag_rms_mg + kPlacementFloorMg;
        FitMethod method = opt.method;
        if (method == FitMethod::Auto)
            method = placement ? FitMethod::Magnitude : FitMethod::Nominal;
        for (const Row *r : acc) {
            RowResidual rr;
            rr.line = r->line;
            rr.block = r->block;
            rr.temp_c = r->temp_c;
            rr.u = r->u;
            rr.raw_mg = row_mag_mg(raw, st, *r);
            rr.pair_mg = row_mag_mg(pair, st, *r);
            rr.nominal_mg = row_mag_mg(out, st, *r);
            rr.magnitude_mg = row_mag_mg(mag, st, *r);
            out.rows.push_back(rr);
        }
        const Residuals rn = out.res_nominal, rm = out.res_magnitude, rp = out.res_pair,
                        r0 = out.res_raw;
        const std::vector<RowResidual> rows = out.rows;
        const std::vector<BlockMeas> blocks = out.blocks;
        const auto soaks = out.soaks;
        const TemperatureFits tfits = out.tfits;
        if (method == FitMethod::Magnitude) out = mag;
        if (method == FitMethod::Pair) out = pair;
        out.method = method;
        out.res_raw = r0;
        out.res_pair = rp;
        out.res_nominal = rn;
        out.res_magnitude = rm;
        out.rows = rows;
        out.blocks = blocks;
        out.soaks = soaks;
        out.tfits = tfits;
        out.one_temperature = stage_flip.one_temperature;
        out.res_chosen = residuals(st, out);
        for (auto &rr : out.rows) {
            rr.chosen_mg = method == FitMethod::Magnitude ? rr.magnitude_mg
                           : method == FitMethod::Pair    ? rr.pair_mg
                                                          : rr.nominal_mg;
        }
        for (size_t k = 0; k < acc.size(); k++) {
            const Row &r = *acc[k];
            const std::array<double, 3> raw3 = {r.v[0] * st.acc_lsb_g, r.v[1] * st.acc_lsb_g,
                                                r.v[2] * st.acc_lsb_g};
            const auto o = apply_double(out, raw3, r.temp_c);
            double dot = 0.0, on = 0.0, un = 0.0;
            for (int i = 0; i < 3; i++) {
                dot += o[i] * r.u[i];
                on += o[i] * o[i];
                un += r.u[i] * r.u[i];
            }
            out.rows[k].angle_deg = std::acos(std::clamp(dot / std::sqrt(on * un), -1.0, 1.0)) *
                                    180.0 / 3.14159265358979323846;
        }
        const Residuals &rc = out.res_chosen;
        if (placement) {
            char w[480];
            std::snprintf(
                w, sizeof w,
                "the nominal-direction fit's residual against the nominal directions (rms "
                "%.3f mg) is %.1f times its residual against 1 g (rms %.3f mg): the rows "
                "were not where the file says (placement against the %s fit: rms %.2f "
                "deg, max %.2f deg; a hand-placed cube?). Judge the calibration by the "
                "||a|-1g| column",
                rn.dir_rms_mg, rn.dir_rms_mg / std::max(rn.mag_rms_mg, 1e-4), rn.mag_rms_mg,
                fit_method_name(method), rc.ang_rms_deg, rc.ang_max_deg);
            out.warnings.push_back(w);
            if (method != FitMethod::Magnitude) {
                std::snprintf(w, sizeof w,
                              "the record uses the %s fit (--fit %s), which misses 1 g by rms %.3f "
                              "mg where the magnitude fit reaches %.3f mg; --fit auto chooses the "
                              "magnitude fit here",
                              fit_method_name(method), fit_method_name(opt.method), rc.mag_rms_mg,
                              rm.mag_rms_mg);
                out.warnings.push_back(w);
            }
        }
    }

    // ---- 4. gyro ----
    {
        std::vector<const Row *> still, turn;
        for (const auto &r : st.rows) {
            if (r.kind == RowKind::GyroStill) still.push_back(&r);
            if (r.kind == RowKind::GyroTurn) turn.push_back(&r);
        }
        if (!still.empty() || !turn.empty()) {
            if (still.empty()) return "gyro: turn rows but no gyro_still row to give the offset";
            out.have_gyro = true;
            double n = 0.0;
            std::array<double, 3> s{};
            for (const Row *r : still) {
                for (int a = 0; a < 3; a++)
                    s[a] += r->v[a] * r->n;
                n += r->n;
            }
            for (int a = 0; a < 3; a++)
                out.gyro_offset[a] = s[a] / n * st.gyro_lsb_dps;
            for (int a = 0; a < 3; a++) {
                double num = 0.0, den = 0.0;
                for (const Row *r : turn) {
                    if (std::fabs(std::fabs(r->u[a]) - 1.0) > 1e-3) continue;
                    const double known = r->angle_deg * (r->u[a] > 0 ? 1.0 : -1.0);
                    const double meas = r->v[a] * st.gyro_lsb_dps - out.gyro_offset[a] * r->dur_s;
                    num += meas * known;
                    den += known * known;
                }
                if (den > 0.0) {
                    out.gyro_scale[a] = num / den;
                    out.gyro_scale_fitted = true;
                    if (!(out.gyro_scale[a] > 0.0)) {
                        return "degenerate data: gyro axis " + std::string(kAxis[a]) +
                               ": the measured turn has the opposite sign of the known angle (axis or direction swapped)";
                    }
                }
            }
        }
    }

    // ---- 5. limits ----
    for (int a = 0; a < 3; a++) {
        const std::string ax = kAxis[a];
        auto bad = [&](const std::string &what, double v, const std::string &lim) {
            return "coefficient out of range: " + what + "[" + ax + "] = " + num(v, 6) +
                   " (limit " + lim + ")";
        };
        if (!(std::fabs(out.acc_offset[a]) <= kLimOffsetG))
            return bad("acc_offset", out.acc_offset[a], "+-0.5 g");
        if (!(out.acc_gain[a] >= kLimGainMin && out.acc_gain[a] <= kLimGainMax))
            return bad("acc_gain", out.acc_gain[a], "0.75..1.25");
        for (int j = 0; j < 3; j++) {
            const double v = out.acc_misalign[a][j];
            if (a == j ? !(v >= kLimGainMin && v <= kLimGainMax) : !(std::fabs(v) <= kLimOffDiag)) {
                return bad("acc_misalign[" + std::string(kAxis[j]) + "]", v,
                           a == j ? "0.75..1.25" : "+-0.125");
            }
        }
        for (int k = 0; k < 4; k++) {
            const double lim = k < 2 ? kLimC01 : kLimC23;
            if (!(std::fabs(out.acc_nonlin[a][k]) <= lim))
                return bad("acc_nonlin c" + std::to_string(k), out.acc_nonlin[a][k],
                           "+-" + num(lim, 6));
        }
        e = check_tmodel(out.acc_tbias[a], kLimTBiasG, "acc_tbias[" + ax + "]");
        if (!e.empty()) return e;
        e = check_tmodel(out.acc_tscale[a], kLimTScale, "acc_tscale[" + ax + "]");
        if (!e.empty()) return e;
        if (!(std::fabs(out.gyro_offset[a]) <= kLimGyroOffset))
            return bad("gyro_offset", out.gyro_offset[a], "+-30 deg/s");
        if (!(out.gyro_scale[a] >= kLimGainMin && out.gyro_scale[a] <= kLimGainMax))
            return bad("gyro_scale", out.gyro_scale[a], "0.75..1.25");
    }

    // ---- Report ----
    std::string rep;
    char b[256];
    std::snprintf(b, sizeof b,
                  "station: %zu rows, %zu acc rows, %zu blocks, %zu soak points %.1f..%.1f degC\n",
                  st.rows.size(), acc.size(), out.blocks.size(), out.soaks.size(),
                  out.blocks[out.soaks.front().front()].t, out.blocks[out.soaks.back().front()].t);
    rep += b;
    if (out.tmodel != TChoice::None) {
        rep +=
            "temperature compensation: residual spread per model ([TEMP-LORENTZ] definitions)\n"
            "  bias: Bmax-Bmin of soak-point means, mg [over every soak]\n"
            "  scale factor: (Kmax-Kmin)/Kmean*1e6/span of soak-point means, ppm/degC [over every soak]\n";
        std::snprintf(b, sizeof b, "  %-4s %-6s %17s", "axis", "", "raw");
        rep += b;
        for (int k = 0; k < TemperatureFits::kKinds; k++) {
            std::snprintf(b, sizeof b, " %17s", TemperatureFits::name(k));
            rep += b;
        }
        rep += "\n";
        for (int a = 0; a < 3; a++) {
            for (int q = 0; q < 2; q++) {
                std::snprintf(b, sizeof b, "  %-4s %-6s", kAxis[a], q ? "scale" : "bias");
                rep += b;
                for (int k = -1; k < TemperatureFits::kKinds; k++) {
                    const TFit *fb = k >= 0 ? &out.tfits.bias[k][a] : nullptr;
                    const TFit *fs = k >= 0 ? &out.tfits.scale[k][a] : nullptr;
                    if (k >= 0 && !(q ? fs->ok : fb->ok)) {
                        std::snprintf(b, sizeof b, " %17s", "n/a");
                        rep += b;
                        continue;
                    }
                    const Spread sp = spread(out.blocks, out.soaks, a, fb ? &fb->model : nullptr,
                                             fs ? &fs->model : nullptr);
                    std::snprintf(b, sizeof b, " %7.3f [%7.3f]",
                                  q ? sp.scale_mean_ppm : sp.bias_mean_mg,
                                  q ? sp.scale_all_ppm : sp.bias_all_mg);
                    rep += b;
                }
                rep += "\n";
            }
        }
        rep += std::string("  chosen for the record: ") + tchoice_name(out.tmodel) +
               (out.tmodel == TChoice::Best ? " (= lorentz+cubic)" : "") + "\n";
    }
    if (out.one_temperature && opt.tmodel_auto && opt.tmodel != TChoice::None &&
        out.tmodel == TChoice::None)
        rep +=
            "temperature: one soak temperature only: no temperature model (as --tmodel none); the "
            "record holds the offsets and gains of this temperature\n";
    rep += static_report(st, stage_flip, stage_lin, nominal_for_report);
    if (!out.have_nonlin)
        rep += "nonlinearity: not fitted (needs a tilt sweep of >= 5 positions per axis)\n";
    rep += "fit of offsets, gains and cross-axis: residuals over every static row (position "
           "means), mg\n"
           "  method                      ||a|-1g| rms      max |  |a-u| rms      max | angle to u "
           "rms  max deg\n";
    auto line = [&](const char *name, const Residuals &r) {
        std::snprintf(b, sizeof b, "  %-26s %9.4f %9.4f | %9.4f %9.4f | %9.3f %6.3f\n", name,
                      r.mag_rms_mg, r.mag_max_mg, r.dir_rms_mg, r.dir_max_mg, r.ang_rms_deg,
                      r.ang_max_deg);
        rep += b;
    };
    line("none (nominal scale)", out.res_raw);
    line("per-axis pair", out.res_pair);
    line("nominal directions", out.res_nominal);
    line("magnitude + rotation", out.res_magnitude);
    std::snprintf(b, sizeof b, "  chosen for the record: %s (--fit %s)\n",
                  fit_method_name(out.method), fit_method_name(opt.method));
    rep += b;
    rep += "  ||a|-1g| needs no placement; |a-u| and the angle also hold every error of where the "
           "rows were placed\n";
    for (const auto &w : out.warnings)
        rep += "WARNING: " + w + "\n";
    if (!out.have_gyro) {
        rep += "gyro: not calibrated (no gyro_still or gyro_turn rows): the record holds offset 0 "
               "and scale 1\n";
    } else {
        std::snprintf(b, sizeof b, "gyro: offset %.4f %.4f %.4f deg/s, scale %.6f %.6f %.6f%s\n",
                      out.gyro_offset[0], out.gyro_offset[1], out.gyro_offset[2], out.gyro_scale[0],
                      out.gyro_scale[1], out.gyro_scale[2],
                      out.gyro_scale_fitted ? "" : " (scale not calibrated: no turns)");
        rep += b;
    }
    out.report = rep;
    return "";
}

} // namespace calstation
