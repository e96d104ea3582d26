// simulate.cpp - a calibration station in the simulator: a chamber that ramps and soaks as in
// [TEMP-LORENTZ] (10 degC/h, 1 h soak, -20..60 degC every 10 degC, repeated up/down cycles), a
// positioner (six +-1 g faces, tilt sweeps within +-30 deg for the nonlinearity, [ADI-EPB]) and a
// rate table (still interval, +-360 deg turns), sampling a sim_calpart through its error-model
// hook and quantising like an ADIS16364-class IMU.
#include "inclino/calstation/station.hpp"

#include "inclino/sim/calpart.h"
#include "inclino/sim/inertial.h"

#include <cmath>
#include <cstdio>

namespace calstation
{

namespace
{

constexpr double kPi = 3.14159265358979323846;
constexpr double kThermalStepS = 10.0;

class Sim
{
  public:
    explicit Sim(const SimConfig &cfg) : cfg_(cfg)
    {
        sim_calpart_params prm;
        if (cfg.part.paper) {
            sim_calpart_paper(&prm);
        } else {
            sim_calpart_seeded(&prm, cfg.part.curve_seed);
        }
        sim_calpart_init(&part_, &prm, cfg.noise_seed);
        sim_rng_seed(&trng_, cfg.noise_seed ^ 0x54454D50ull);     // "TEMP"
        sim_rng_seed(&prng_, cfg.placement_seed ^ 0x504C4143ull); // "PLAC"
        st_.acc_lsb_g = kSimAccLsbG;
        st_.gyro_lsb_dps = kSimGyroLsbDps;
        st_.t_ref_c = 25.0;
        // An ADIS16364 (calrec family 3, PROD_ID 16364) with a serial number per part.
        st_.have_binding = true;
        st_.binding = {
            3u,
            16364u,
            0u,
            static_cast<uint32_t>(cfg.part.paper ? 0x0A01u : (0x0B00u + (cfg.part.curve_seed & 0xFFu))),
            0u,
            0u};
        if (cfg.have_binding) st_.binding = cfg.binding;
    }

    Station run()
    {
        switch (cfg_.schedule) {
        case Schedule::Ambient: ambient_block(); break;
        case Schedule::Calibration:
            ambient_block();
            chamber(-20.0, 60.0);
            break;
        case Schedule::Validation: chamber(-15.0, 55.0); break;
        case Schedule::Hand: six_faces(next_block_++); break;
        }
        return st_;
    }

  private:
    void sample(const double accel[3], const double rate[3], sim_inertial_input &out)
    {
        sim_inertial_input in;
        sim_inertial_at_rest(&in);
        for (int i = 0; i < 3; i++) {
            in.accel_g[i] = accel[i];
            in.rate_dps[i] = rate[i];
        }
        in.temp_c = die_;
        sim_calpart_apply(&part_, &in, &out, 0, 1.0 / cfg_.rate_sps);
    }

    double temp_reading()
    {
        // TEMP_OUT: 0.136 degC/LSB, 0 LSB = 25 degC, 12-bit two's complement (docs/sensor-facts.md §3.x).
        const int32_t q = sim_quantise(die_ - 25.0 + cfg_.temp_noise_c * sim_rng_gauss(&trng_),
                                       kSimTempLsbC, 12, nullptr);
        return 25.0 + q * kSimTempLsbC;
    }

    // Chamber air moves to `target` at the ramp rate, then holds for `hold_s`; the die follows
    // with a first-order lag; the part sees every step (its hysteresis state moves).
    void thermal(double target, double hold_s)
    {
        const double rate = cfg_.ramp_c_per_h / 3600.0;
        const double a = 1.0 - std::exp(-kThermalStepS / cfg_.die_tau_s);
        const double zero[3] = {0.0, 0.0, 1.0}, still[3] = {0.0, 0.0, 0.0};
        sim_inertial_input out;
        while (std::fabs(air_ - target) > 1e-9) {
            const double d = target - air_, stepc = rate * kThermalStepS;
            air_ += std::fabs(d) <= stepc ? d : (d > 0 ? stepc : -stepc);
            die_ += (air_ - die_) * a;
            sample(zero, still, out);
        }
        for (double t = 0.0; t < hold_s; t += kThermalStepS) {
            die_ += (air_ - die_) * a;
            sample(zero, still, out);
        }
    }

    // The direction the part really feels for nominal direction n (see SimConfig).
    void placed(const double n[3], double u[3])
    {
        for (int i = 0; i < 3; i++)
            u[i] = n[i];
        if (cfg_.nonortho_deg != 0.0) {
            const double d = cfg_.nonortho_deg * kPi / 180.0;
            // The cube's face normals in the sensor frame: x exact, y leans toward x, z toward x
            // and away from y; u = the normal of the face pointing up, by its components.
            const double ex[3] = {1.0, 0.0, 0.0};
            const double ey[3] = {std::sin(d), std::cos(d), 0.0};
            const double ez[3] = {
                std::sin(d), -std::sin(d / 2.0),
                std::sqrt(1.0 - std::sin(d) * std::sin(d) - std::sin(d / 2.0) * std::sin(d / 2.0))};
            for (int i = 0; i < 3; i++)
                u[i] = n[0] * ex[i] + n[1] * ey[i] + n[2] * ez[i];
            const double m = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
            for (int i = 0; i < 3; i++)
                u[i] /= m;
        }
        if (cfg_.placement_deg > 0.0) {
            // A random unit vector p perpendicular to u; tilt u toward p by theta.
            double p[3];
            const double r[3] = {sim_rng_gauss(&prng_), sim_rng_gauss(&prng_),
                                 sim_rng_gauss(&prng_)};
            const double th = cfg_.placement_deg * (0.5 + 0.5 * sim_rng_uniform(&prng_)) * kPi /
                              180.0;
            const double d = r[0] * u[0] + r[1] * u[1] + r[2] * u[2];
            for (int i = 0; i < 3; i++)
                p[i] = r[i] - d * u[i];
            const double m = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
            for (int i = 0; i < 3; i++)
                u[i] = std::cos(th) * u[i] + std::sin(th) * p[i] / m;
        }
    }

    // The part carried by hand from direction a to b: 2 s along the normalised straight path
    // with 0.2 g of shaking (not still, so a sample CSV has clear moves between faces).
    void carry(const double a[3], const double b[3])
    {
        const int n = static_cast<int>(2.0 * cfg_.rate_sps);
        const double still[3] = {0.0, 0.0, 0.0};
        sim_inertial_input out;
        for (int k = 0; k < n; k++) {
            const double f = (k + 1.0) / (n + 1.0);
            double u[3], m = 0.0;
            for (int i = 0; i < 3; i++) {
                u[i] = (1.0 - f) * a[i] + f * b[i] + 0.2 * sim_rng_gauss(&prng_);
                m += u[i] * u[i];
            }
            m = std::sqrt(m);
            for (int i = 0; i < 3; i++)
                u[i] = m > 1e-6 ? u[i] / m : 0.0;
            sample(u, still, out);
            std::array<double, 3> g{};
            for (int i = 0; i < 3; i++)
                g[i] = sim_quantise(out.accel_g[i], kSimAccLsbG, 14, nullptr) * kSimAccLsbG;
            st_.samples.push_back(g);
            st_.sample_temp_c.push_back(temp_reading());
        }
    }

    void acc_row(long block, double ux, double uy, double uz)
    {
        const double nom[3] = {ux, uy, uz}, still[3] = {0.0, 0.0, 0.0};
        double u[3];
        placed(nom, u);
        double sum[3] = {0.0, 0.0, 0.0}, tsum = 0.0;
        sim_inertial_input out;
        if (cfg_.keep_samples && have_last_) carry(last_, u);
        for (int k = 0; k < cfg_.samples; k++) {
            sample(u, still, out);
            std::array<double, 3> g{};
            for (int i = 0; i < 3; i++) {
                const int32_t c = sim_quantise(out.accel_g[i], kSimAccLsbG, 14, nullptr);
                sum[i] += c;
                g[i] = c * kSimAccLsbG;
            }
            const double tr = temp_reading();
            tsum += tr;
            if (cfg_.keep_samples) {
                st_.samples.push_back(g);
                st_.sample_temp_c.push_back(tr);
            }
        }
        for (int i = 0; i < 3; i++)
            last_[i] = u[i];
        have_last_ = true;
        Row r;
        r.block = block;
        r.kind = RowKind::Acc;
        r.temp_c = tsum / cfg_.samples;
        r.u = {ux, uy, uz};
        r.n = cfg_.samples;
        for (int i = 0; i < 3; i++)
            r.v[i] = sum[i] / cfg_.samples;
        st_.rows.push_back(r);
    }

    void six_faces(long block)
    {
        for (int i = 0; i < 3; i++) {
            for (int s = 1; s >= -1; s -= 2) {
                double u[3] = {0.0, 0.0, 0.0};
                u[i] = s;
                acc_row(block, u[0], u[1], u[2]);
            }
        }
    }

    void ambient_block()
    {
        const long block = next_block_++;
        six_faces(block);
        // Tilt sweeps within +-30 deg ([ADI-EPB]: road slopes stay within +-30 deg, +-500 mg):
        // axis i sees sin(theta), a second axis cos(theta).
        for (int i = 0; i < 3; i++) {
            const int j = (i == 2) ? 0 : 2;
            for (int k = -4; k <= 4; k++) {
                if (k == 0) continue;
                const double th = k * 7.5 * kPi / 180.0;
                double u[3] = {0.0, 0.0, 0.0};
                u[i] = std::sin(th);
                u[j] = std::cos(th);
                acc_row(block, u[0], u[1], u[2]);
            }
        }
        gyro_rows(block);
    }

    void gyro_rows(long block)
    {
        const double zero_g[3] = {0.0, 0.0, 1.0};
        sim_inertial_input out;
        // Still interval: about 100 s at 819.2 SPS ([ADI-IMU-QS]'s manual calibration: 82 000).
        {
            const long n = 82000;
            double sum[3] = {0.0, 0.0, 0.0}, tsum = 0.0;
            const double still[3] = {0.0, 0.0, 0.0};
            for (long k = 0; k < n; k++) {
                sample(zero_g, still, out);
                for (int i = 0; i < 3; i++)
                    sum[i] += sim_quantise(out.rate_dps[i], kSimGyroLsbDps, 14, nullptr);
                if (k % 64 == 0) tsum += temp_reading();
            }
            Row r;
            r.block = block;
            r.kind = RowKind::GyroStill;
            r.temp_c = tsum / ((n + 63) / 64);
            r.n = n;
            for (int i = 0; i < 3; i++)
                r.v[i] = sum[i] / n;
            st_.rows.push_back(r);
        }
        // Turns of +360 and -360 deg about each axis at 90 deg/s.
        for (int i = 0; i < 3; i++) {
            for (int s = 1; s >= -1; s -= 2) {
                const long n = std::lround(4.0 * cfg_.rate_sps);
                const double dt = 1.0 / cfg_.rate_sps, dur = n * dt;
                double rate[3] = {0.0, 0.0, 0.0}, integ[3] = {0.0, 0.0, 0.0}, tsum = 0.0;
                rate[i] = s * 360.0 / dur;
                for (long k = 0; k < n; k++) {
                    sample(zero_g, rate, out);
                    for (int a = 0; a < 3; a++)
                        integ[a] += sim_quantise(out.rate_dps[a], kSimGyroLsbDps, 14, nullptr) * dt;
                    tsum += temp_reading();
                }
                Row r;
                r.block = block;
                r.kind = RowKind::GyroTurn;
                r.temp_c = tsum / n;
                r.u = {0.0, 0.0, 0.0};
                r.u[i] = s;
                r.angle_deg = 360.0;
                r.dur_s = dur;
                r.n = n;
                r.v = {integ[0], integ[1], integ[2]};
                st_.rows.push_back(r);
            }
        }
    }

    void chamber(double lo, double hi)
    {
        std::vector<double> cycle;
        for (double t = lo; t <= hi + 1e-9; t += 10.0)
            cycle.push_back(t);
        for (double t = hi - 10.0; t >= lo - 1e-9; t -= 10.0)
            cycle.push_back(t);
        for (int c = 0; c < cfg_.cycles; c++) {
            for (size_t k = (c == 0 ? 0 : 1); k < cycle.size(); k++) {
                thermal(cycle[k], cfg_.soak_s);
                six_faces(next_block_++);
            }
        }
    }

    SimConfig cfg_;
    sim_calpart part_{};
    sim_rng trng_{};
    sim_rng prng_{};
    double last_[3] = {0.0, 0.0, 0.0};
    bool have_last_ = false;
    Station st_;
    double air_ = 25.0, die_ = 25.0;
    long next_block_ = 0;
};

} // namespace

Station simulate_station(const SimConfig &cfg)
{
    Sim s(cfg);
    Station st = s.run();
    if (cfg.keep_samples) st.sample_rate_sps = cfg.rate_sps;
    return st;
}

std::string format_samples(const Station &st, double unit_per_g, bool with_temp)
{
    std::string o = "# Inclino simulated IMU samples (calstation simulate --format samples)\n";
    o += with_temp ? "t,ax,ay,az,temp_c\n" : "t,ax,ay,az\n";
    char b[160];
    const double dt = st.sample_rate_sps > 0.0 ? 1.0 / st.sample_rate_sps : 0.0;
    for (size_t k = 0; k < st.samples.size(); k++) {
        const auto &g = st.samples[k];
        const int n = std::snprintf(b, sizeof b, "%.6f,%.7g,%.7g,%.7g", k * dt, g[0] * unit_per_g,
                                    g[1] * unit_per_g, g[2] * unit_per_g);
        o.append(b, static_cast<size_t>(n));
        if (with_temp) {
            std::snprintf(b, sizeof b, ",%.3f", st.sample_temp_c[k]);
            o += b;
        }
        o += "\n";
    }
    return o;
}

} // namespace calstation
