// tmodel.cpp - see tmodel.hpp.
#include "inclino/calstation/tmodel.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>

namespace calstation
{

namespace
{

constexpr double kWMin = 1.0, kWMax = 400.0; // degC, the record's limits for w
constexpr double kTcMin = -100.0, kTcMax = 200.0;
constexpr int kLmMaxIter = 2000;

double clamp_u(double t, double t_ref, double t_span)
{
    const double u = (t - t_ref) / t_span;
    return u < -1.0 ? -1.0 : (u > 1.0 ? 1.0 : u);
}

double lorentz(double t, double tc, double w)
{
    const double r = 2.0 * (t - tc) / w;
    return 1.0 / (1.0 + r * r);
}

} // namespace

const char *tkind_name(TKind k)
{
    switch (k) {
    case TKind::None: return "none";
    case TKind::Linear: return "linear";
    case TKind::Parabola: return "parabola";
    case TKind::Lorentz: return "lorentz";
    case TKind::Pwl: return "pwl";
    case TKind::LorentzCubic: return "lorentz+cubic";
    }
    return "?";
}

int TModel::params() const
{
    switch (kind) {
    case TKind::None: return 0;
    case TKind::Linear: return 2;
    case TKind::Parabola: return 3;
    case TKind::Lorentz: return 4;
    case TKind::LorentzCubic: return 7;
    case TKind::Pwl: return n;
    }
    return 0;
}

bool tparam_is_degc(TKind kind, int k)
{
    return (kind == TKind::Lorentz || kind == TKind::LorentzCubic) && (k == 2 || k == 3);
}

double TModel::eval(double t) const
{
    switch (kind) {
    case TKind::None: return 0.0;
    case TKind::Linear: return p[0] + p[1] * clamp_u(t, t_ref, t_span);
    case TKind::Parabola: {
        const double u = clamp_u(t, t_ref, t_span);
        return p[0] + p[1] * u + p[2] * u * u;
    }
    case TKind::Lorentz: return p[0] + p[1] * lorentz(t, p[3], p[2]);
    case TKind::LorentzCubic: {
        // The whole model is held at the ends of the calibrated range: its Lorentz part and its
        // polynomial part may cancel inside the range and must not be extrapolated apart.
        const double u = clamp_u(t, t_ref, t_span);
        const double tc = t_ref + u * t_span;
        return p[0] + p[1] * lorentz(tc, p[3], p[2]) + u * (p[4] + u * (p[5] + u * p[6]));
    }
    case TKind::Pwl: {
        const double last = t_ref + (n - 1) * t_span;
        if (t <= t_ref) return p[0];
        if (t >= last) return p[n - 1];
        int i = static_cast<int>(std::floor((t - t_ref) / t_span));
        i = std::min(i, n - 2);
        const double f = (t - (t_ref + i * t_span)) / t_span;
        return p[i] + (p[i + 1] - p[i]) * f;
    }
    }
    return 0.0;
}

static void data_range(const std::vector<TPoint> &pts, double &lo, double &hi)
{
    lo = std::numeric_limits<double>::infinity();
    hi = -lo;
    for (const auto &q : pts) {
        lo = std::min(lo, q.t);
        hi = std::max(hi, q.t);
    }
}

TFit fit_linear(const std::vector<TPoint> &pts)
{
    TFit f;
    double lo, hi;
    data_range(pts, lo, hi);
    if (pts.size() < 2 || !(hi - lo >= 1.0)) {
        f.message = "linear fit needs data at two temperatures at least 1 degC apart";
        return f;
    }
    f.model.kind = TKind::Linear;
    f.model.t_ref = 0.5 * (lo + hi);
    f.model.t_span = 0.5 * (hi - lo);
    Eigen::MatrixXd a(pts.size(), 2);
    Eigen::VectorXd y(pts.size());
    for (size_t i = 0; i < pts.size(); i++) {
        a(i, 0) = 1.0;
        a(i, 1) = (pts[i].t - f.model.t_ref) / f.model.t_span;
        y(i) = pts[i].y;
    }
    const Eigen::VectorXd c = a.colPivHouseholderQr().solve(y);
    f.model.p[0] = c(0);
    f.model.p[1] = c(1);
    f.ok = true;
    return f;
}

TFit fit_three_point(const std::vector<TPoint> &m, double t_amb)
{
    TFit f;
    if (m.size() < 3) {
        f.message = "three-point fit needs 3 soak temperatures (cold, ambient, hot)";
        return f;
    }
    size_t ic = 0, ih = 0, ia = 0;
    for (size_t i = 1; i < m.size(); i++) {
        if (m[i].t < m[ic].t) ic = i;
        if (m[i].t > m[ih].t) ih = i;
    }
    double best = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < m.size(); i++) {
        if (i == ic || i == ih) continue;
        const double d = std::fabs(m[i].t - t_amb);
        if (d < best) {
            best = d;
            ia = i;
        }
    }
    const double tc = m[ic].t, ta = m[ia].t, th = m[ih].t;
    if (!(ta - tc >= 1.0) || !(th - ta >= 1.0)) {
        f.message = "three-point fit: cold, ambient and hot points must be at least 1 degC apart";
        return f;
    }
    // Step 1 ([ADI-EPB]): remove the ambient offset c = y(Ta). Step 2: linear term from the hot
    // point, b = (y(Th) - y(Ta)) / (Th - Ta). Step 3: the parabola through (Tc, dN2), (Ta, 0),
    // (Th, 0), dN2 = what steps 1 and 2 leave at the cold point.
    const double c = m[ia].y;
    const double b = (m[ih].y - c) / (th - ta);
    const double dn2 = m[ic].y - (c + b * (tc - ta));
    const double a = dn2 / ((tc - ta) * (tc - th));
    // y(T) = c + b (T - Ta) + a (T - Ta)(T - Th), rewritten in u = (T - t_ref) / t_span.
    f.model.kind = TKind::Parabola;
    f.model.t_ref = 0.5 * (tc + th);
    f.model.t_span = 0.5 * (th - tc);
    const double r = f.model.t_ref, s = f.model.t_span;
    // T = r + s u: y = c + b (r - Ta + s u) + a (r - Ta + s u)(r - Th + s u)
    const double d1 = r - ta, d2 = r - th;
    f.model.p[0] = c + b * d1 + a * d1 * d2;
    f.model.p[1] = b * s + a * s * (d1 + d2);
    f.model.p[2] = a * s * s;
    f.ok = true;
    return f;
}

namespace
{

// Model with a Lorentz term and `npoly` polynomial terms u, u^2, ... over [t_ref +- t_span].
// Parameter vector: y0, H, w, Tc, poly...
struct LorentzProblem {
    const std::vector<TPoint> &pts;
    int npoly;
    double t_ref, t_span;

    double u(double t) const
    {
        return clamp_u(t, t_ref, t_span);
    }

    // Solve the linear parameters (y0, H, poly) for fixed (w, Tc); returns SSE.
    double project(double w, double tc, Eigen::VectorXd &lin) const
    {
        const int nl = 2 + npoly;
        Eigen::MatrixXd a(pts.size(), nl);
        Eigen::VectorXd y(pts.size());
        for (size_t i = 0; i < pts.size(); i++) {
            const double uu = u(pts[i].t);
            double pw = 1.0;
            a(i, 0) = 1.0;
            a(i, 1) = lorentz(pts[i].t, tc, w);
            for (int k = 0; k < npoly; k++) {
                pw *= uu;
                a(i, 2 + k) = pw;
            }
            y(i) = pts[i].y;
        }
        lin = a.colPivHouseholderQr().solve(y);
        return (a * lin - y).squaredNorm();
    }

    // Residuals r_i = model - y and the Jacobian for the full parameter vector.
    void residuals(const Eigen::VectorXd &x, Eigen::VectorXd &r, Eigen::MatrixXd *jac) const
    {
        const int np = 4 + npoly;
        r.resize(pts.size());
        if (jac) jac->resize(pts.size(), np);
        const double y0 = x(0), h = x(1), w = x(2), tc = x(3);
        for (size_t i = 0; i < pts.size(); i++) {
            const double t = pts[i].t, uu = u(t);
            const double l = lorentz(t, tc, w);
            double v = y0 + h * l, pw = 1.0;
            for (int k = 0; k < npoly; k++) {
                pw *= uu;
                v += x(4 + k) * pw;
            }
            r(i) = v - pts[i].y;
            if (jac) {
                // L = 1/(1+q), q = 4 (t-tc)^2 / w^2: dL/dtc = L^2 * 8 (t-tc) / w^2,
                // dL/dw = L^2 * 8 (t-tc)^2 / w^3.
                const double d = t - tc;
                (*jac)(i, 0) = 1.0;
                (*jac)(i, 1) = l;
                (*jac)(i, 2) = h * l * l * 8.0 * d * d / (w * w * w);
                (*jac)(i, 3) = h * l * l * 8.0 * d / (w * w);
                pw = 1.0;
                for (int k = 0; k < npoly; k++) {
                    pw *= uu;
                    (*jac)(i, 4 + k) = pw;
                }
            }
        }
    }
};

// Levenberg-Marquardt on the two nonlinear parameters (w, Tc) of the variable-projection
// residual r(w, Tc) = y - A(w, Tc) lin(w, Tc): the linear parameters (y0, H, poly) are solved
// exactly at every evaluation, so the search is 2-D and well conditioned even when the peak lies
// outside the data (a tail, where H, w and Tc trade off). Bounds by projection; a point where the
// projected height exceeds h_limit counts as infeasible (infinite SSE).
struct VarPro {
    const LorentzProblem &pb;
    double h_limit;

    double sse(double w, double tc, Eigen::VectorXd *lin = nullptr) const
    {
        Eigen::VectorXd l;
        const double s = pb.project(w, tc, l);
        if (!std::isfinite(s) || std::fabs(l(1)) > h_limit)
            return std::numeric_limits<double>::infinity();
        if (lin) *lin = l;
        return s;
    }

    Eigen::VectorXd resid(double w, double tc) const
    {
        Eigen::VectorXd l;
        pb.project(w, tc, l);
        Eigen::VectorXd x(4 + pb.npoly);
        x << l(0), l(1), w, tc, l.tail(pb.npoly);
        Eigen::VectorXd r;
        pb.residuals(x, r, nullptr);
        return r;
    }
};

TFit fit_lorentz_n(const std::vector<TPoint> &pts, double h_limit, int npoly)
{
    TFit f;
    double lo, hi;
    data_range(pts, lo, hi);
    // Distinct temperatures: 4 + npoly parameters need at least that many soak points + 1.
    std::vector<double> ts(pts.size());
    std::transform(pts.begin(), pts.end(), ts.begin(), [](const TPoint &q) { return q.t; });
    std::sort(ts.begin(), ts.end());
    int distinct = ts.empty() ? 0 : 1;
    for (size_t i = 1; i < ts.size(); i++) {
        if (ts[i] - ts[i - 1] > 1.0) distinct++;
    }
    if (distinct < 5 + npoly) {
        f.message = "Lorentz fit needs at least " + std::to_string(5 + npoly) +
                    " soak temperatures (got " + std::to_string(distinct) + ")";
        return f;
    }
    const LorentzProblem pb{pts, npoly, 0.5 * (lo + hi), 0.5 * (hi - lo)};
    const VarPro vp{pb, h_limit};

    // Initialisation: a grid over centre and width, evaluated on the means of points closer
    // than 1 degC (the soak points: the same least-squares minimum for equal counts per soak,
    // at a fraction of the cost). The centre may lie well outside the measured range (a tail),
    // hence the wide grid.
    std::vector<TPoint> sorted = pts, means;
    std::sort(sorted.begin(), sorted.end(),
              [](const TPoint &a, const TPoint &b) { return a.t < b.t; });
    for (size_t i = 0; i < sorted.size();) {
        size_t j = i;
        double st = 0.0, sy = 0.0;
        while (j < sorted.size() && sorted[j].t - sorted[i].t <= 1.0) {
            st += sorted[j].t;
            sy += sorted[j].y;
            j++;
        }
        means.push_back({st / (j - i), sy / (j - i)});
        i = j;
    }
    const LorentzProblem pbm{means, npoly, pb.t_ref, pb.t_span};
    const VarPro vpm{pbm, h_limit};
    double best = std::numeric_limits<double>::infinity(), w = 0.0, tc = 0.0;
    for (double c = std::max(kTcMin, lo - 80.0); c <= std::min(kTcMax, hi + 80.0); c += 2.5) {
        for (double ww = 4.0; ww <= kWMax; ww *= 1.1) {
            const double s = vpm.sse(ww, c);
            if (s < best) {
                best = s;
                w = ww;
                tc = c;
            }
        }
    }
    best = vp.sse(w, tc);
    if (!std::isfinite(best)) {
        f.message = "Lorentz fit: no initial point within the parameter limits";
        return f;
    }

    double lambda = 1e-3, sse = best;
    bool converged = false;
    int it = 0;
    for (it = 0; it < kLmMaxIter; it++) {
        // Central-difference Jacobian of the projected residual in (w, Tc).
        const double hw = 1e-5 * std::max(w, 1.0), ht = 1e-5 * std::max(std::fabs(tc), 1.0);
        const Eigen::VectorXd r = vp.resid(w, tc);
        Eigen::MatrixXd j(r.size(), 2);
        j.col(0) = (vp.resid(w + hw, tc) - vp.resid(w - hw, tc)) / (2.0 * hw);
        j.col(1) = (vp.resid(w, tc + ht) - vp.resid(w, tc - ht)) / (2.0 * ht);
        const Eigen::Matrix2d jtj = j.transpose() * j;
        const Eigen::Vector2d g = j.transpose() * r;
        bool stepped = false;
        while (lambda <= 1e12) {
            Eigen::Matrix2d a = jtj;
            a(0, 0) += lambda * std::max(jtj(0, 0), 1e-300);
            a(1, 1) += lambda * std::max(jtj(1, 1), 1e-300);
            const Eigen::Vector2d d = a.ldlt().solve(-g);
            const double wn = std::clamp(w + d(0), kWMin, kWMax);
            const double tn = std::clamp(tc + d(1), kTcMin, kTcMax);
            const double sn = vp.sse(wn, tn);
            if (sn <= sse) {
                const double rel = (sse - sn) / std::max(sse, 1e-300);
                const double step = std::fabs(wn - w) / w +
                                    std::fabs(tn - tc) / std::max(std::fabs(tc), 1.0);
                w = wn;
                tc = tn;
                sse = sn;
                lambda = std::max(lambda * 0.3, 1e-12);
                stepped = true;
                if (rel < 1e-10 || step < 1e-9) converged = true;
                break;
            }
            lambda *= 10.0;
        }
        // No downhill step at any damping: a (possibly bounded) local minimum.
        if (!stepped) converged = true;
        if (converged) break;
    }
    f.iterations = it;
    f.converged = converged;
    if (!converged) {
        f.message = "Lorentz fit did not converge in " + std::to_string(kLmMaxIter) + " iterations";
        return f;
    }
    Eigen::VectorXd lin;
    if (!std::isfinite(vp.sse(w, tc, &lin))) {
        f.message = "Lorentz fit: the solution leaves the parameter limits";
        return f;
    }
    f.model.kind = npoly ? TKind::LorentzCubic : TKind::Lorentz;
    f.model.p[0] = lin(0);
    f.model.p[1] = lin(1);
    f.model.p[2] = w;
    f.model.p[3] = tc;
    if (npoly) {
        f.model.t_ref = pb.t_ref;
        f.model.t_span = pb.t_span;
        for (int k = 0; k < npoly; k++)
            f.model.p[4 + k] = lin(2 + k);
    }
    f.ok = true;
    return f;
}

} // namespace

TFit fit_lorentz(const std::vector<TPoint> &pts, double h_limit)
{
    return fit_lorentz_n(pts, h_limit, 0);
}

TFit fit_lorentz_cubic(const std::vector<TPoint> &pts, double h_limit)
{
    return fit_lorentz_n(pts, h_limit, 3);
}

TFit fit_pwl(const std::vector<TPoint> &pts, double t0, double dt, int n)
{
    TFit f;
    if (n < 2 || n > kTParams || !(dt > 0.0)) {
        f.message = "PWL fit needs 2.." + std::to_string(kTParams) +
                    " knots and a positive spacing";
        return f;
    }
    TModel m;
    m.kind = TKind::Pwl;
    m.n = n;
    m.t_ref = t0;
    m.t_span = dt;
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(pts.size(), n);
    Eigen::VectorXd y(pts.size());
    std::vector<int> used(n, 0);
    for (size_t i = 0; i < pts.size(); i++) {
        const double s = std::clamp((pts[i].t - t0) / dt, 0.0, static_cast<double>(n - 1));
        int k = std::min(static_cast<int>(std::floor(s)), n - 2);
        const double fr = s - k;
        a(i, k) = 1.0 - fr;
        a(i, k + 1) = fr;
        used[k] |= fr < 1.0;
        used[k + 1] |= fr > 0.0;
        y(i) = pts[i].y;
    }
    for (int k = 0; k < n; k++) {
        if (!used[k]) {
            f.message = "PWL fit: no data near knot " + std::to_string(k) + " (" +
                        std::to_string(t0 + k * dt) + " degC)";
            return f;
        }
    }
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
    if (qr.rank() < n) {
        f.message = "PWL fit: the knots are not determined by the data";
        return f;
    }
    const Eigen::VectorXd c = qr.solve(y);
    for (int k = 0; k < n; k++)
        m.p[k] = c(k);
    f.model = m;
    f.ok = true;
    return f;
}

} // namespace calstation
