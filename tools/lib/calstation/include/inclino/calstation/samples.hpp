// samples.hpp - raw sample CSVs (one row per sample, any IMU), their static positions, and the
// station rows made from them; the firmware correction applied to samples; the safe file I/O
// of the calstation tool.
//
// A sample CSV (docs/calibration.md 4.5): comment lines start with '#', the first other line is
// a header of column names, every later line one sample. Columns are matched by name, case and
// spaces ignored, and a unit suffix in brackets or parentheses dropped ("ax [m/s^2]"):
//   acceleration  ax,ay,az | acc_x,acc_y,acc_z | accel_x,.. | accx,.. | a_x,.. | x,y,z (required)
//   temperature   temp_c | temp | temperature | t_c, degC (optional)
//   time          t | time | time_s | timestamp, s (optional: sets the stillness window)
// Other columns are kept as they are (calstation apply passes them through).
#ifndef INCLINO_CALSTATION_SAMPLES_HPP
#define INCLINO_CALSTATION_SAMPLES_HPP

#include "inclino/calrec.h"
#include "inclino/calstation/station.hpp"

#include <array>
#include <string>
#include <vector>

namespace calstation
{

constexpr double kStandardGravity = 9.80665; // m/s^2 per g (the conventional standard value)

struct SampleFile {
    std::vector<std::string> header;              // column names as written
    std::vector<std::vector<std::string>> fields; // every sample row's fields
    std::vector<int> lines;                       // 1-based line of each row
    std::vector<std::string> comments;            // leading comment lines (kept by apply)
    int col[3] = {-1, -1, -1};
    int col_temp = -1, col_time = -1;
    std::vector<std::array<double, 3>> acc_g; // acceleration in g (converted from the unit)
    std::vector<double> temp_c, time_s;
};

// Whether the text is a station file (format 1: "#@" settings or the station header).
bool is_station_text(const std::string &text);

// Parse a sample CSV; acceleration in units of `unit_g` per g (1 for g, g_ms2 for m/s^2).
std::string parse_samples(const std::string &text, double unit_g, SampleFile &out);

// A still interval: [begin, end) sample indices, its mean in g and mean temperature.
struct Segment {
    size_t begin = 0, end = 0;
    std::array<double, 3> mean{};
    double temp_c = 0.0;
    int axis = -1, sign = 0; // the face: dominant axis and sign, or -1 when not near a face
};

// Still intervals: the moving standard deviation of the acceleration over `win` samples
// (0: from the time column, 0.5 s; without it 51 samples, 0.5 s at 102.4 Hz) below 4 times
// its 20th percentile (the noise of the still parts) plus 0.5 mg; one window trimmed at each
// end (settling); at least 2 windows long. A face: within 25 deg of an axis.
std::vector<Segment> find_segments(const SampleFile &s, size_t win);

// The station made from the face segments: one acc row per face segment, u the nominal face
// direction, x,y,z the mean in g (acc_lsb_g = 1), temperature from the column or t_ref.
std::string station_from_segments(const SampleFile &s, const std::vector<Segment> &seg,
                                  double t_ref, Station &out, size_t &skipped);

// Face-mean residual of samples acc (g): per face segment the mean of |a| - 1 g over its
// samples; rms and max |.| over the face segments, mg.
struct FaceResidual {
    size_t faces = 0;
    double rms_mg = 0.0, max_mg = 0.0;
    std::vector<double> per_face_mg;
};
FaceResidual face_residual(const std::vector<std::array<double, 3>> &acc,
                           const std::vector<Segment> &seg);

// ---- Files -------------------------------------------------------------------------------

// Read a whole input (a regular file or a FIFO; a directory or other kind is refused), at most
// max_bytes. "" on success, else the message.
std::string read_input(const std::string &path, size_t max_bytes, std::string &out);

// Write data to path without ever destroying an input or a non-regular file:
//  - the path (a symlink is followed: the link stays, its target is written) must not be one of
//    the inputs (same device and inode) nor a directory, block device or socket;
//  - a regular or new file is written to a temporary file beside it (mkstemp), flushed, closed
//    (each checked), and renamed over it only then: a failed write leaves the old file;
//  - a FIFO or character device (/dev/stdout, /dev/null, /dev/full) is written in place.
// "" on success, else the message (the cause from errno: "No space left on device").
std::string write_output(const std::string &path, const std::string &data,
                         const std::vector<std::string> &inputs);

} // namespace calstation

#endif
