// record.hpp - from the station's fitted coefficients (CalResult, physical units) to the
// calibration record of the firmware (firmware/signal/calrec, format version 2) and its byte image, and
// the firmware cross-check: the fixed-point correction (firmware/signal/cal) run on the station's own
// rows against the double-precision model of the same quantised record.
#ifndef INCLINO_CALSTATION_RECORD_HPP
#define INCLINO_CALSTATION_RECORD_HPP

#include "inclino/calrec.h"
#include "inclino/calstation/fit.hpp"
#include "inclino/calstation/station.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace calstation
{

// Quantise every coefficient (round to nearest: Q16.16 for g, deg/s, degC; Q30 for gains,
// ratios and the scale-factor deviation) and bind the record to the station's part. Fails with a
// message when the station file has no binding or calrec_check refuses the result (a limit,
// named).
std::string to_calrec(const CalResult &c, const Station &st, struct calrec &out);

// The record back in physical units (for the double-precision reference of the firmware).
CalResult from_calrec(const struct calrec &r);

// calrec_encode with sequence number seq into a CALREC_IMAGE_SIZE buffer.
std::string encode_record(const struct calrec &r, uint32_t seq, std::vector<uint8_t> &img);

struct FwCheck {
    size_t rows = 0;
    double max_lsb = 0.0;         // max |firmware - double model of the quantised record|, Q16 LSB
    double max_err_mg = 0.0;      // max |firmware - true specific force| over the rows, mg
    double max_tilt_err_mg = 0.0; // the same over the rows within +-30 deg (|u| <= 0.5 g on x, y)
    double mag_rms_mg = 0.0;      // rms over the rows of ||firmware output| - 1 g|
    double mag_max_mg = 0.0;
    std::vector<double> row_mag_mg; // |firmware output| - 1 g per acc row, in file order
};

// The firmware's fixed-point correction (cal_acc_init / cal_acc_set_temp / cal_acc_apply) on
// any samples: in_g in g (rounded to Q16), temperature per sample (temp_c, or t_default for
// every sample when temp_c is empty; cal_acc_set_temp runs when it changes), out_g in g (the
// Q16 output). range counts the samples cal_acc_apply flagged INC_ERR_RANGE (beyond +-64 g).
std::string apply_firmware(const struct calrec &r, const std::vector<std::array<double, 3>> &in_g,
                           const std::vector<double> &temp_c, double t_default,
                           std::vector<std::array<double, 3>> &out_g, size_t &range);

// Whether any accelerometer temperature model of the record is not NONE.
bool record_has_tmodel(const struct calrec &r);

// Run cal_acc_init/set_temp/apply on every acc row (reading = counts * lsb in Q16).
std::string firmware_check(const Station &st, const struct calrec &r, FwCheck &out);

} // namespace calstation

#endif
