// kfref.cpp - double-precision reference filters (see inclino/kfref.hpp).
#include "inclino/kfref.hpp"

#include <cmath>
#include <numeric>

namespace inclino::ref
{

double dt_seconds(uint32_t ns)
{
    // The firmware's dt: round(ns * 2^30 / 1e9) as Q30 seconds (exact in double: < 2^53).
    const double q = std::floor(static_cast<double>(ns) * 1073741824.0 / 1e9 + 0.5);
    return q / 1073741824.0;
}

// ---- generic filter --------------------------------------------------------------------------

void KfRef::init(const Eigen::VectorXd &x0, const Eigen::MatrixXd &p0)
{
    x = x0;
    P = p0;
}

void KfRef::predict(const Eigen::MatrixXd &A, const Eigen::MatrixXd &B, const Eigen::VectorXd &u,
                    const Eigen::MatrixXd &Q)
{
    if (B.cols() > 0) {
        x = A * x + B * u; // (1)
    } else {
        x = A * x;
    }
    P = A * P * A.transpose() + Q; // (2)
}

void KfRef::update_row(const Eigen::RowVectorXd &h, double r, double z)
{
    const Eigen::VectorXd ph = P * h.transpose();
    const double s = h.dot(ph) + r;
    const Eigen::VectorXd k = ph / s; // (4)
    x += k * (z - h.dot(x));          // (3)
    const Eigen::MatrixXd ikh = Eigen::MatrixXd::Identity(P.rows(), P.cols()) - k * h;
    P = ikh * P * ikh.transpose() + k * r * k.transpose(); // (5), Joseph form
}

// ---- adaptive per-axis filter ----------------------------------------------------------------

AdaptParams AdaptParams::from_fixed(const kf_adapt_config &c)
{
    AdaptParams p;
    p.window = c.window;
    p.C = p_to_unit2(c.c);
    p.D = static_cast<double>(c.d) / 4294967296.0; // raw * 2^16 with Q16 raw: unit * 2^32
    p.A = p_to_unit2(c.a);
    p.B = q16(c.b);
    p.p0 = p_to_unit2(c.p0);
    return p;
}

double AdaptRef::process(double z, Step *st)
{
    win_.push_back(z);
    if (win_.size() > p_.window) win_.pop_front();
    if (!started_) {
        started_ = true;
        x_ = z;
        P_ = p_.p0;
        if (st) *st = Step{0, 0, 0, 1};
        return x_;
    }
    // Step 2: the mean of the differences between z and the other samples in the window.
    const double n = static_cast<double>(win_.size());
    const double sum = std::accumulate(win_.begin(), win_.end(), 0.0);
    const double dz = (n * z - sum) / (n - 1);
    const double Q = p_.C + p_.D * std::fabs(dz);
    const double R = std::fabs(p_.A + p_.B * Q);
    // Step 3.
    const double pm = P_ + Q;
    const double K = pm / (pm + R);
    x_ = x_ + K * (z - x_);
    P_ = (1 - K) * pm;
    if (st) *st = Step{dz, Q, R, K};
    return x_;
}

double AdaptRef::coast()
{
    if (started_) P_ += p_.C;
    return x_;
}

// ---- tilt ------------------------------------------------------------------------------------

TiltParams TiltParams::from_fixed(const tilt_config &c)
{
    TiltParams p;
    p.mode = static_cast<int>(c.mode);
    for (int i = 0; i < 2; i++) {
        const tilt_axis_config &a = c.axis[i];
        p.axis[i].q_angle = p_to_unit2(a.q_angle);
        p.axis[i].q_bias = p_to_unit2(a.q_bias);
        p.axis[i].r_angle = p_to_unit2(a.r_angle);
        p.axis[i].p0_angle = p_to_unit2(a.p0_angle);
        p.axis[i].p0_bias = p_to_unit2(a.p0_bias);
        p.axis[i].kb = q30(a.bias_gain);
        p.axis[i].bias0 = q16(a.bias0_dps);
    }
    p.accel_tol = q16(c.accel_tol_g);
    p.gyro_limit = q16(c.gyro_limit_dps);
    p.dt_max = static_cast<double>(c.dt_max_ns) * 1e-9;
    return p;
}

TiltRef::TiltRef(const TiltParams &p) : p_(p)
{
    for (int i = 0; i < 2; i++) {
        ax_[i].x = Eigen::Vector2d(0, p.axis[i].bias0);
        ax_[i].P = Eigen::Matrix2d::Zero();
        ax_[i].P(0, 0) = p.axis[i].p0_angle;
        ax_[i].P(1, 1) = p.axis[i].p0_bias;
        ax_[i].off = p.axis[i].bias0;
    }
}

void TiltRef::accel_angles(const double a[3], double *roll, double *pitch)
{
    const double rad = 180.0 / M_PI;
    *roll = std::atan2(a[1], a[2]) * rad;
    *pitch = std::atan2(-a[0], std::sqrt(a[1] * a[1] + a[2] * a[2])) * rad;
}

void TiltRef::start(int i, double angle)
{
    Axis &s = ax_[i];
    s.x(0) = angle;
    const double pb = s.P(1, 1);
    s.P = Eigen::Matrix2d::Zero();
    s.P(0, 0) = p_.axis[i].p0_angle;
    s.P(1, 1) = pb; // KF2 keeps the bias and its variance; the seed forms keep off
}

static double wrap180(double a)
{
    while (a > 180.0)
        a -= 360.0;
    while (a <= -180.0)
        a += 360.0;
    return a;
}

TiltOut TiltRef::step(const double accel[3], const double gyro[3], uint32_t in_flags, double dt)
{
    TiltOut out;
    const double a2 = accel[0] * accel[0] + accel[1] * accel[1] + accel[2] * accel[2];
    const double lo = (1 - p_.accel_tol) * (1 - p_.accel_tol);
    const double hi = (1 + p_.accel_tol) * (1 + p_.accel_tol);
    const bool acc_ok = !(in_flags & TILT_IN_ACCEL_SAT) && a2 >= lo && a2 <= hi;
    double acc_angle[2] = {0, 0};
    if (acc_ok) {
        accel_angles(accel, &acc_angle[0], &acc_angle[1]);
        out.accel_angle[0] = acc_angle[0];
        out.accel_angle[1] = acc_angle[1];
    } else {
        out.flags |= TILT_F_ACCEL_REJECTED;
    }
    if (started_ && dt > p_.dt_max) {
        out.flags |= TILT_F_GAP_RESTART;
        started_ = false;
    }
    if (!started_) {
        if (!acc_ok) {
            out.flags |= TILT_F_NOT_STARTED;
            return out;
        }
        for (int i = 0; i < 2; i++)
            start(i, acc_angle[i]);
        started_ = true;
    } else {
        const double cap = 2025.0;
        for (int i = 0; i < 2; i++) {
            const TiltAxisParams &c = p_.axis[i];
            Axis &s = ax_[i];
            const double w = gyro[i];
            const uint32_t sat = i == 0 ? TILT_IN_GYRO_SAT_X : TILT_IN_GYRO_SAT_Y;
            const bool gyro_ok = !(in_flags & sat) && std::fabs(w) < p_.gyro_limit;
            if (!gyro_ok) out.flags |= i == 0 ? TILT_F_GYRO_REJ_ROLL : TILT_F_GYRO_REJ_PITCH;
            double q00 = c.q_angle * dt;
            if (!gyro_ok) q00 += (p_.gyro_limit * dt) * (p_.gyro_limit * dt);
            if (s.P(0, 0) + q00 > cap) q00 = cap - s.P(0, 0);
            if (q00 < 0) q00 = 0;
            double z = acc_angle[i];
            if (p_.mode == TILT_MODE_KF2) {
                Eigen::Matrix2d A;
                A << 1, gyro_ok ? -dt : 0, 0, 1;
                Eigen::Vector2d B(gyro_ok ? dt : 0, 0);
                Eigen::Matrix2d Q = Eigen::Matrix2d::Zero();
                Q(0, 0) = q00;
                Q(1, 1) = c.q_bias * dt;
                s.x = A * s.x + B * w;
                s.P = A * s.P * A.transpose() + Q;
                if (acc_ok) {
                    if (z - s.x(0) > 180.0) z -= 360.0;
                    if (z - s.x(0) < -180.0) z += 360.0;
                    const Eigen::RowVector2d h(1, 0);
                    const Eigen::Vector2d ph = s.P * h.transpose();
                    const double sv = h.dot(ph) + c.r_angle;
                    const Eigen::Vector2d k = ph / sv;
                    s.x += k * (z - s.x(0));
                    const Eigen::Matrix2d ikh = Eigen::Matrix2d::Identity() - k * h;
                    s.P = ikh * s.P * ikh.transpose() + k * c.r_angle * k.transpose();
                }
            } else {
                const double xp = s.x(0) + (gyro_ok ? (w - s.off) * dt : 0.0); // w_theta(k)
                double p = s.P(0, 0) + q00;
                double x = xp;
                if (acc_ok) {
                    if (z - xp > 180.0) z -= 360.0;
                    if (z - xp < -180.0) z += 360.0;
                    const double k2 = p / (p + c.r_angle);
                    x = xp + k2 * (z - xp);
                    p = (1 - k2) * p;
                }
                const double corr = x - xp;
                if (p_.mode == TILT_MODE_SEED_PRINTED) {
                    s.off = corr / dt;
                } else if (gyro_ok && acc_ok) {
                    s.off -= c.kb * corr / dt;
                }
                s.x(0) = x;
                s.P(0, 0) = p;
            }
            s.x(0) = wrap180(s.x(0));
        }
    }
    for (int i = 0; i < 2; i++) {
        out.angle[i] = ax_[i].x(0);
        out.sigma[i] = std::sqrt(std::max(0.0, ax_[i].P(0, 0)));
        out.bias[i] = p_.mode == TILT_MODE_KF2 ? ax_[i].x(1) : ax_[i].off;
    }
    out.valid = true;
    return out;
}

} // namespace inclino::ref
