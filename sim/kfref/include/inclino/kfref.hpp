// kfref.hpp - double-precision reference models of the Kalman filters (host only, C++17, Eigen).
//
// Module inclino_kfref (sim/kfref). Each class is the textbook form of one firmware filter, in
// double, written from the equations ([KF-SCA3000], [CN110567483], docs/kalman.md) and not from the
// fixed-point code, so that the tests in tests/kf can compare the two on the same inputs:
//   KfRef     inclino/kf.h        the five equations, sequential scalar updates, Joseph form
//   AdaptRef  inclino/kf_adapt.h  [CN110567483] steps 2-3 on one axis, sliding window
//   TiltRef   inclino/tilt.h      [CN110567483] step 4 (printed / feedback) and the two-state filter
// Units: KfRef works in the firmware's raw units (x raw, P raw^2); AdaptRef and TiltRef in
// physical units (g, deg, deg/s, s, unit^2). The from_fixed() helpers turn a firmware
// configuration into the reference's exactly (every parameter as the firmware sees it after its
// own quantisation), so that a difference between the two is arithmetic, not tuning.
#ifndef INCLINO_KFREF_HPP
#define INCLINO_KFREF_HPP

#include <Eigen/Dense>

#include <cstdint>
#include <deque>

extern "C" {
#include "inclino/kf.h"
#include "inclino/kf_adapt.h"
#include "inclino/tilt.h"
}

namespace inclino::ref
{

// P format (kf.h) <-> raw^2, and Q16 P format <-> unit^2.
inline double p_to_raw2(int64_t p)
{
    return static_cast<double>(p) / 65536.0;
}
inline double p_to_unit2(int64_t p)
{
    return static_cast<double>(p) / 281474976710656.0;
} // 2^48
inline double q30(int32_t v)
{
    return static_cast<double>(v) / 1073741824.0;
}
inline double q16(int32_t v)
{
    return static_cast<double>(v) / 65536.0;
}
// dt as the firmware quantises it: round(ns * 2^30 / 1e9) / 2^30 seconds.
double dt_seconds(uint32_t ns);

class KfRef
{
  public:
    Eigen::VectorXd x; // raw
    Eigen::MatrixXd P; // raw^2

    void init(const Eigen::VectorXd &x0, const Eigen::MatrixXd &p0);
    // (1), (2)
    void predict(const Eigen::MatrixXd &A, const Eigen::MatrixXd &B, const Eigen::VectorXd &u,
                 const Eigen::MatrixXd &Q);
    // (3)-(5) for one row h (1 x n), variance r, measurement z; Joseph form.
    void update_row(const Eigen::RowVectorXd &h, double r, double z);
};

// [CN110567483] steps 2-3 on one axis (physical units of the axis).
struct AdaptParams {
    unsigned window = 8;
    double C = 0, D = 0, A = 0, B = 0, p0 = 0;
    static AdaptParams from_fixed(const kf_adapt_config &c); // Q16 samples
};

class AdaptRef
{
  public:
    explicit AdaptRef(const AdaptParams &p) : p_(p)
    {
    }
    struct Step {
        double dz = 0, Q = 0, R = 0, K = 0;
    };
    double process(double z, Step *st = nullptr);
    double coast();
    double estimate() const
    {
        return x_;
    }
    double variance() const
    {
        return P_;
    }

  private:
    AdaptParams p_;
    std::deque<double> win_;
    double x_ = 0, P_ = 0;
    bool started_ = false;
};

// Roll/pitch (tilt.h) in double.
struct TiltAxisParams {
    double q_angle = 0, q_bias = 0, r_angle = 0, p0_angle = 0, p0_bias = 0, kb = 0, bias0 = 0;
};
struct TiltParams {
    int mode = TILT_MODE_FEEDBACK;
    TiltAxisParams axis[2];
    double accel_tol = 0.1, gyro_limit = 295, dt_max = 0.1;
    static TiltParams from_fixed(const tilt_config &c);
};

struct TiltOut {
    double angle[2] = {0, 0}, sigma[2] = {0, 0}, bias[2] = {0, 0}, accel_angle[2] = {0, 0};
    uint32_t flags = 0;
    bool valid = false;
};

class TiltRef
{
  public:
    explicit TiltRef(const TiltParams &p);
    // accel in g, gyro in deg/s, flags TILT_IN_*, dt in seconds (use dt_seconds()).
    TiltOut step(const double accel[3], const double gyro[3], uint32_t in_flags, double dt);
    static void accel_angles(const double a[3], double *roll, double *pitch);

  private:
    TiltParams p_;
    struct Axis {
        Eigen::Vector2d x{0, 0}; // angle, bias (KF2); seed forms use x(0) and off
        Eigen::Matrix2d P = Eigen::Matrix2d::Zero();
        double off = 0;
    } ax_[2];
    bool started_ = false;
    void start(int i, double angle);
};

} // namespace inclino::ref

#endif // INCLINO_KFREF_HPP
