// station.hpp - the calibration-station measurement file (CSV) and the station simulator.
//
// File format 1 (docs/calibration.md has the full description and an example):
//   lines starting with "#@ " are settings "key=value"; other lines starting with '#' are
//   comments; blank lines are ignored; the first other line is the column header, exactly
//       block,kind,temp_c,ux,uy,uz,angle_deg,dur_s,n,x,y,z
//   and every following line one measurement row with those 12 fields:
//     block      soak / measurement group id (integer >= 0): the rows of one chamber soak
//     kind       acc | gyro_still | gyro_turn
//     temp_c     mean on-board temperature reading over the row, degC
//     ux,uy,uz   acc: the true specific force the station applied, sensor frame, g (gravity
//                only, so |u| = 1 g); gyro_turn: unit vector of the turn axis; gyro_still: 0
//     angle_deg  gyro_turn: the known turned angle about (ux,uy,uz), degrees; else 0
//     dur_s      gyro_turn: duration of the integration, s; else 0
//     n          samples averaged (acc, gyro_still) or integrated (gyro_turn), >= 1
//     x,y,z      acc, gyro_still: mean raw counts per axis; gyro_turn: integral of the raw
//                counts over the turn, counts*s
//   Settings: acc_lsb_g (required: nominal accelerometer LSB, g/count), gyro_lsb_dps (required
//   when there are gyro rows), t_ref_c (reference temperature, default 25), binding (six
//   integers family,product,revision,serial,lot_id1,lot_id2 of calrec_binding; required to
//   write a record).
#ifndef INCLINO_CALSTATION_STATION_HPP
#define INCLINO_CALSTATION_STATION_HPP

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace calstation
{

enum class RowKind { Acc, GyroStill, GyroTurn };

struct Row {
    int line = 0; // 1-based line in the file (0 when made in memory)
    long block = 0;
    RowKind kind = RowKind::Acc;
    double temp_c = 0.0;
    std::array<double, 3> u{};
    double angle_deg = 0.0;
    double dur_s = 0.0;
    long n = 1;
    std::array<double, 3> v{};
};

struct Station {
    // Simulated samples (SimConfig::keep_samples): acceleration g and temperature reading degC.
    std::vector<std::array<double, 3>> samples;
    std::vector<double> sample_temp_c;
    double sample_rate_sps = 0.0;
    double acc_lsb_g = 0.0;
    double gyro_lsb_dps = 0.0;
    double t_ref_c = 25.0;
    bool have_binding = false;
    std::array<uint32_t, 6> binding{};
    std::vector<Row> rows;
};

extern const char *const kCsvHeader;

// Parse a station file. Returns "" on success, otherwise a message naming the line and the
// problem (the file is rejected as a whole).
std::string parse_station(const std::string &text, Station &out);
std::string read_station_file(const std::string &path, Station &out);

// Write a station file (format 1).
std::string format_station(const Station &st);

// ---- Simulator ---------------------------------------------------------------------------

// Which simulated part (sim/calpart.h): 'A' = sim_calpart_paper, otherwise seeded(seed).
struct SimPart {
    bool paper = true;
    uint64_t curve_seed = 0;
};

enum class Schedule {
    Calibration, // ambient block (six faces, tilt sweeps, gyro), then -20..60 degC every 10 degC
    Validation,  // six faces at -15..55 degC every 10 degC, for held-out checks
    Ambient,     // the ambient block only (no chamber)
    Hand,        // six faces of a hand-placed cube at ambient (no tilts, no gyro, no chamber)
};

struct SimConfig {
    SimPart part;
    Schedule schedule = Schedule::Calibration;
    int cycles = 10;            // up/down chamber cycles ([TEMP-LORENTZ]: 10)
    int samples = 2000;         // samples averaged per acc position
    double rate_sps = 819.2;    // sample rate (ADIS1636x)
    double ramp_c_per_h = 10.0; // [TEMP-LORENTZ]: 10 degC/h
    double soak_s = 3600.0;     // [TEMP-LORENTZ]: 1 h soak per point
    double die_tau_s = 600.0;   // die temperature lag behind the chamber air
    double temp_noise_c = 0.05; // on-board temperature sensor noise, rms
    uint64_t noise_seed = 1;
    // Placement of the acc positions. The station file always records the nominal direction u;
    // the part feels u turned by up to placement_deg (each position its own random tilt of
    // 0.5..1 x placement_deg in a random direction, from placement_seed) and, on a cube whose
    // faces are not orthogonal, the fixed face-normal errors of nonortho_deg (the +y face
    // leans nonortho_deg toward +x, the +z face nonortho_deg toward +x and -nonortho_deg/2
    // toward +y; opposite faces parallel). 0, 0: a precise positioner.
    double placement_deg = 0.0;
    uint64_t placement_seed = 1;
    double nonortho_deg = 0.0;
    // Keep every accelerometer sample (g, as quantised) of the acc rows, with the moves between
    // positions (2 s each, the part carried by hand: a path between the two directions plus
    // 0.2 g of shaking), for a sample CSV (format_samples).
    bool keep_samples = false;
    bool have_binding = false; // override the simulated part's identity (default: an ADIS16364)
    std::array<uint32_t, 6> binding{};
};

// Counts scale of the simulated part (an ADIS16364-like IMU: docs/sensor-facts.md §3.x).
constexpr double kSimAccLsbG = 0.001;   // 1 mg/LSB, 14-bit
constexpr double kSimGyroLsbDps = 0.05; // 0.05 deg/s/LSB, 14-bit
constexpr double kSimTempLsbC = 0.136;  // 0.136 degC/LSB, 0 LSB = 25 degC

Station simulate_station(const SimConfig &cfg);

// The kept samples as a sample CSV (samples.hpp): t,ax,ay,az[,temp_c], acceleration in units of
// unit_per_g per g (1: g; 9.80665: m/s^2).
std::string format_samples(const Station &st, double unit_per_g, bool with_temp);

} // namespace calstation

#endif
