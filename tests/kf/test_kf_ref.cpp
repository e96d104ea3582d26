// test_kf_ref.cpp - the fixed-point filters against the double-precision Eigen reference
// (sim/kfref) on the same inputs, over long runs (host only).
//
// Each case feeds identical quantised inputs to both (the reference gets every parameter as the
// firmware quantised it: KfRef/AdaptParams/TiltParams::from_fixed), runs 10^6 steps (10^5 in the
// sanitizer build) and checks: the largest state difference after convergence, that the
// firmware never saturates (no overflow flag), and for the generic filter that P stays
// symmetric positive semi-definite (smallest eigenvalue >= -4 LSB, checked every 1000 steps).
// The measured maxima are printed; docs/kalman.md quotes them.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>

#include <Eigen/Dense>

#include "inclino/kfref.hpp"
#include "unit.h"

using inclino::ref::AdaptParams;
using inclino::ref::AdaptRef;
using inclino::ref::KfRef;
using inclino::ref::TiltOut;
using inclino::ref::TiltParams;
using inclino::ref::TiltRef;

namespace
{

// The 10^6-step runs prove the bounds on the host build; the sanitizer build looks for undefined
// behaviour on the same paths in a shorter run.
constexpr long kSteps = UNIT_SIZE(1000000L, 30000L);

constexpr double kQ16 = 65536.0;
constexpr double kP = 281474976710656.0; // 2^48: Q16 P format per unit^2

int32_t q16(double v)
{
    return static_cast<int32_t>(std::lround(v * kQ16));
}
int32_t q30(double v)
{
    return static_cast<int32_t>(std::lround(v * 1073741824.0));
}
int64_t pf(double v)
{
    return static_cast<int64_t>(std::llround(v * kP));
}

// ---- generic filter -------------------------------------------------------------------------

struct GenericCase {
    const char *name;
    unsigned n, nu, m;
    std::vector<int32_t> a, b, h;  // Q30
    std::vector<int64_t> q, r, p0; // P format
};

Eigen::MatrixXd mat_q30(const std::vector<int32_t> &v, unsigned rows, unsigned cols)
{
    Eigen::MatrixXd m(rows, cols);
    for (unsigned i = 0; i < rows; i++)
        for (unsigned j = 0; j < cols; j++)
            m(i, j) = v[i * cols + j] / 1073741824.0;
    return m;
}
Eigen::MatrixXd mat_p(const std::vector<int64_t> &v, unsigned n)
{
    Eigen::MatrixXd m(n, n);
    for (unsigned i = 0; i < n; i++)
        for (unsigned j = 0; j < n; j++)
            m(i, j) = inclino::ref::p_to_raw2(v[i * n + j]);
    return m;
}

// Runs the case on a simulated truth (the model itself with process noise), returns the largest
// |x_fw - x_ref| in raw units over the second half.
void run_generic(const GenericCase &c, double *max_dx, double *max_rel_p, double *min_eig)
{
    *max_dx = 0;
    *max_rel_p = 0;
    *min_eig = 1e300;
    std::mt19937_64 gen(42 + c.n);
    std::normal_distribution<double> nd(0.0, 1.0);
    kf f;

    if (kf_init(&f, c.n, nullptr, c.p0.data()) != INC_OK) {
        CHECK(false);
        return;
    }
    KfRef r;
    r.init(Eigen::VectorXd::Zero(c.n), mat_p(c.p0, c.n));
    const Eigen::MatrixXd A = mat_q30(c.a, c.n, c.n), B = mat_q30(c.b, c.n, c.nu);
    const Eigen::MatrixXd Q = mat_p(c.q, c.n), H = mat_q30(c.h, c.m, c.n);
    kf_model mdl{static_cast<uint8_t>(c.n), static_cast<uint8_t>(c.nu), c.a.data(),
                 c.nu ? c.b.data() : nullptr, c.q.data()};
    kf_meas ms{static_cast<uint8_t>(c.n), static_cast<uint8_t>(c.m), c.h.data(), c.r.data()};
    // truth: x_t' = A x_t + B u + w, z = H x_t + v (raw units)
    Eigen::LLT<Eigen::MatrixXd> lq(Q + 1e-30 * Eigen::MatrixXd::Identity(c.n, c.n));
    Eigen::VectorXd xt = Eigen::VectorXd::Zero(c.n);
    *max_dx = 0;
    *max_rel_p = 0;
    *min_eig = 1e300;
    unsigned errors = 0;
    for (long k = 0; k < kSteps; k++) {
        std::vector<int32_t> u(c.nu > 0 ? c.nu : 1), z(c.m);
        Eigen::VectorXd ud(c.nu);
        for (unsigned i = 0; i < c.nu; i++) {
            u[i] = static_cast<int32_t>(std::lround(2000.0 * std::sin(k * 1e-3 * (i + 1))));
            ud(i) = u[i];
        }
        Eigen::VectorXd w(c.n);
        for (unsigned i = 0; i < c.n; i++)
            w(i) = nd(gen);
        xt = A * xt + (c.nu ? Eigen::VectorXd(B * ud) : Eigen::VectorXd::Zero(c.n)) +
             lq.matrixL() * w;
        for (unsigned i = 0; i < c.m; i++) {
            const double sd = std::sqrt(inclino::ref::p_to_raw2(c.r[i]));
            const double zz = H.row(i).dot(xt) + sd * nd(gen);
            z[i] = static_cast<int32_t>(std::lround(std::max(-2e9, std::min(2e9, zz))));
        }
        if (kf_predict(&f, &mdl, c.nu ? u.data() : nullptr) != INC_OK) errors++;
        r.predict(A, B, ud, Q);
        const uint32_t mask = (k % 5 == 4) ? 1u : (1u << c.m) - 1u; // a row left out sometimes
        if (kf_update(&f, &ms, z.data(), mask) != INC_OK) errors++;
        for (unsigned i = 0; i < c.m; i++)
            if (mask & (1u << i)) r.update_row(H.row(i), inclino::ref::p_to_raw2(c.r[i]), z[i]);
        if (k >= kSteps / 2) {
            for (unsigned i = 0; i < c.n; i++) {
                const double dx = std::fabs(f.x[i] / 65536.0 - r.x(i));
                if (dx > *max_dx) *max_dx = dx;
            }
        }
        if (k % 1000 == 999) {
            Eigen::MatrixXd pf_(c.n, c.n);
            for (unsigned i = 0; i < c.n; i++)
                for (unsigned j = 0; j < c.n; j++) {
                    pf_(i, j) = static_cast<double>(f.p[i][j]);
                    if (f.p[i][j] != f.p[j][i]) errors++;
                }
            Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(pf_);
            *min_eig = std::min(*min_eig, es.eigenvalues().minCoeff()); // P format LSB
            const double rel = (pf_ / 65536.0 - r.P).norm() / r.P.norm();
            if (k >= kSteps / 2) *max_rel_p = std::max(*max_rel_p, rel);
        }
    }
    CHECK_EQ_INT(errors, 0);
    CHECK(!f.overflow);
}

void test_generic_vs_reference()
{
    const int32_t one = 1 << 30;
    const double dt = 5.0 / 4096.0; // 819.2 Hz
    std::vector<GenericCase> cases;
    // n = 1: random walk, Q16 unit, R = 0.25, Q = 1e-6 per step
    cases.push_back(
        {"n1 random walk", 1, 0, 1, {one}, {}, {one}, {pf(1e-6)}, {pf(0.25)}, {pf(1.0)}});
    // n = 2: angle/bias at 819.2 Hz (deg, deg/s): the tilt model with u = gyro
    cases.push_back({"n2 angle+bias",
                     2,
                     1,
                     1,
                     {one, -q30(dt), 0, one},
                     {q30(dt), 0},
                     {one, 0},
                     {pf(1e-3 * dt), 0, 0, pf(2e-7 * dt)},
                     {pf(0.25)},
                     {pf(1.0), 0, 0, pf(1.0)}});
    // n = 3: constant acceleration, dt = 2^-6
    {
        const double h = 1.0 / 64;
        cases.push_back({"n3 const accel",
                         3,
                         0,
                         1,
                         {one, q30(h), q30(h * h / 2), 0, one, q30(h), 0, 0, one},
                         {},
                         {one, 0, 0},
                         {pf(1e-8), 0, 0, 0, pf(1e-6), 0, 0, 0, pf(1e-4)},
                         {pf(0.01)},
                         {pf(1), 0, 0, 0, pf(1), 0, 0, 0, pf(1)}});
    }
    // n = 4: 2-D constant velocity, two rows (x, y), one control per axis
    {
        const double h = 0.01;
        cases.push_back(
            {"n4 2-D cv",
             4,
             2,
             2,
             {one, 0, q30(h), 0, 0, one, 0, q30(h), 0, 0, one, 0, 0, 0, 0, one},
             {0, 0, 0, 0, q30(h), 0, 0, q30(h)},
             {one, 0, 0, 0, 0, one, 0, 0},
             {pf(1e-7), 0, 0, 0, 0, pf(1e-7), 0, 0, 0, 0, pf(1e-5), 0, 0, 0, 0, pf(1e-5)},
             {pf(0.04), pf(0.09)},
             {pf(4), 0, 0, 0, 0, pf(4), 0, 0, 0, 0, pf(4), 0, 0, 0, 0, pf(4)}});
    }
    for (const auto &c : cases) {
        double dx = 0, rp = 0, me = 0;
        run_generic(c, &dx, &rp, &me);
        std::printf("%-16s %ld steps: max |x_fw - x_ref| = %.3g raw (%.3g unit), max rel |P| diff "
                    "= %.3g, min eigenvalue of P = %.3g LSB\n",
                    c.name, kSteps, dx, dx / 65536.0, rp, me);
        CHECK(dx <= 2.0); // raw LSB of the state (Q16: 3e-5 unit)
        CHECK(rp <= 1e-5);
        CHECK(me >= -4.0);
    }
}

// ---- adaptive filter ------------------------------------------------------------------------

void test_adapt_vs_reference()
{
    kf_adapt_config c{};
    c.window = 8;
    c.c = pf(1e-6);
    c.d = static_cast<int64_t>(std::llround(0.02 * 4294967296.0)); // 0.02 g per g of |dz|
    c.a = pf(4e-3); // R in [3.1e-3, 4e-3] g^2: B < 0 lowers R while the signal moves
    c.b = -q16(0.5);
    c.p0 = pf(1e-2);
    kf_adapt f;
    REQUIRE(kf_adapt_init(&f, &c) == INC_OK);
    AdaptRef r(AdaptParams::from_fixed(c));
    std::mt19937_64 gen(7);
    std::normal_distribution<double> nd(0.0, 1.0);
    double max_d = 0, max_rel_p = 0;
    unsigned errors = 0;
    for (long k = 0; k < kSteps; k++) {
        // steps of 0.09 g every 5000 samples, a slow sine, noise 0.02 g, vibration 25 Hz
        const double truth = 0.09 * ((k / 5000) % 3) + 0.05 * std::sin(k * 2e-4);
        const double zd = truth + 0.02 * nd(gen) + 0.03 * std::sin(k * 2 * M_PI * 25 / 819.2);
        const int32_t z = q16(zd);
        int32_t est;
        kf_adapt_step st;
        AdaptRef::Step rs;
        if (kf_adapt_process(&f, z, &est, &st) != INC_OK) errors++;
        const double re = r.process(z / kQ16, &rs);
        if (k >= 1000) {
            max_d = std::max(max_d, std::fabs(f.x / 4294967296.0 - re));
            max_rel_p = std::max(max_rel_p, std::fabs(f.p / kP - r.variance()) / r.variance());
        }
    }
    std::printf(
        "adaptive         %ld steps: max |est_fw - est_ref| = %.3g g (%.3g LSB Q16), max rel "
        "P diff = %.3g\n",
        kSteps, max_d, max_d * kQ16, max_rel_p);
    CHECK_EQ_INT(errors, 0);
    CHECK(max_d * kQ16 <= 1.0); // within one LSB of the Q16 output
    CHECK(max_rel_p <= 1e-3);
}

// ---- tilt -----------------------------------------------------------------------------------

// 10^6 samples (20 min at 819.2 Hz): slow tilt changes and steps, engine-idle vibration, gyro
// noise and a slowly drifting bias, an accelerating vehicle now and then (rejected), gyro
// saturation bursts, missed samples (dt of 2 or 3 periods).
void run_tilt(uint32_t mode, double *max_da, double *max_db, unsigned *flag_diffs)
{
    tilt_config c;
    REQUIRE(tilt_config_default(&c, 1220703u) == INC_OK);
    c.mode = mode;
    tilt t;
    REQUIRE(tilt_init(&t, &c) == INC_OK);
    TiltRef r(TiltParams::from_fixed(c));
    std::mt19937_64 gen(11 + mode);
    std::normal_distribution<double> nd(0.0, 1.0);
    double roll = 2, pitch = -3, bias[2] = {0.3, -0.2};
    *max_da = 0;
    *max_db = 0;
    *flag_diffs = 0;
    unsigned errors = 0;
    const double fs = 819.2;
    for (long k = 0; k < kSteps; k++) {
        const double ts = k / fs;
        uint32_t dt_ns = 1220703u;
        if (k % 997 == 500) dt_ns = 2 * 1220703u + 1; // missed data-ready
        if (k % 4099 == 100) dt_ns = 3 * 1220703u + 1;
        // truth: slow motion and occasional tilt steps (a wheel onto a kerb)
        double wr = 0.5 * std::sin(ts * 0.05), wp = 0.3 * std::cos(ts * 0.031);
        if (k % 50000 >= 40000 && k % 50000 < 40041) wr += 50.0; // 4 deg in 0.05 s
        roll += wr * dt_ns * 1e-9;
        pitch += wp * dt_ns * 1e-9;
        bias[0] += 1e-4 * nd(gen) * 0.03;
        bias[1] += 1e-4 * nd(gen) * 0.03;
        const double rr = roll * M_PI / 180, pp = pitch * M_PI / 180;
        double a[3] = {-std::sin(pp), std::sin(rr) * std::cos(pp), std::cos(rr) * std::cos(pp)};
        for (int i = 0; i < 3; i++)
            a[i] += 0.006 * nd(gen) + 0.02 * std::sin(2 * M_PI * (24.0 + 3 * i) * ts + i);
        if (k % 80000 >= 60000 && k % 80000 < 62000) a[0] += 0.25; // accelerating: rejected
        double w[2] = {wr + bias[0] + 0.9 * nd(gen), wp + bias[1] + 0.9 * nd(gen)};
        uint32_t in_flags = 0;
        if (k % 123457 >= 1000 && k % 123457 < 1020) { // a saturation burst on x
            w[0] = 300.0;
            in_flags |= TILT_IN_GYRO_SAT_X;
        }
        tilt_input in{};
        for (int i = 0; i < 3; i++)
            in.accel_g[i] = q16(a[i]);
        in.gyro_dps[0] = q16(w[0]);
        in.gyro_dps[1] = q16(w[1]);
        in.flags = in_flags;
        tilt_output o;
        if (tilt_step(&t, &in, dt_ns, &o) != INC_OK) errors++;
        const double aq[3] = {in.accel_g[0] / kQ16, in.accel_g[1] / kQ16, in.accel_g[2] / kQ16};
        const double gq[3] = {in.gyro_dps[0] / kQ16, in.gyro_dps[1] / kQ16, 0};
        const TiltOut ro = r.step(aq, gq, in_flags, inclino::ref::dt_seconds(dt_ns));
        if (ro.flags != o.flags) (*flag_diffs)++;
        if (!o.valid) errors++;
        if (k >= kSteps / 10) { // after convergence (2 min; 12 s in the sanitizer build)
            for (int i = 0; i < 2; i++) {
                double d = t.ax[i].kf.x[0] / 4294967296.0 - ro.angle[i];
                if (d > 180) d -= 360;
                if (d < -180) d += 360;
                *max_da = std::max(*max_da, std::fabs(d));
                *max_db = std::max(*max_db, std::fabs(o.bias_dps[i] / kQ16 - ro.bias[i]));
            }
        }
    }
    CHECK_EQ_INT(errors, 0);
}

void test_tilt_vs_reference()
{
    const char *names[3] = {"feedback", "seed printed", "kf2"};
    for (uint32_t m = 0; m < 3; m++) {
        double da = 0, db = 0;
        unsigned fd = 0;
        run_tilt(m, &da, &db, &fd);
        std::printf("tilt %-12s %ld steps: max |angle_fw - angle_ref| = %.3g deg, max |bias diff| "
                    "= %.3g deg/s, flag differences %u\n",
                    names[m], kSteps, da, db, fd);
        CHECK(da <= 0.005); // issue 6: angle within 0.005 deg of the reference
        // The printed form's offset is the last correction divided by dt: it magnifies the
        // angle difference by 1/dt = 819 (and is no bias estimate anyway).
        CHECK(db <= (m == TILT_MODE_SEED_PRINTED ? 0.1 : 0.001));
        CHECK_EQ_INT(fd, 0);
    }
}

} // namespace

int main()
{
    UNIT_RUN(test_generic_vs_reference);
    UNIT_RUN(test_adapt_vs_reference);
    UNIT_RUN(test_tilt_vs_reference);
    return unit_report();
}
