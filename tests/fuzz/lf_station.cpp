// lf_station.cpp - libFuzzer target: the calibration-station file reader
// (tools/lib/calstation, calstation::parse_station). Properties: no exception escapes; a file
// that parses has rows in the ranges docs/calibration.md states (n >= 1, block >= 0, finite
// values) and, written back with format_station, parses again to the same rows; a refused
// file is refused with a message.
#include "inclino/calstation/station.hpp"

#include <cmath>
#include <cstdlib>
#include <string>

using calstation::Station;

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const std::string text(reinterpret_cast<const char *>(data), size);
    Station st, again;
    std::string err;
    try {
        err = calstation::parse_station(text, st);
    } catch (...) {
        std::abort(); // the reader reports errors by message, never by exception
    }
    if (!err.empty()) return 0;
    for (const auto &r : st.rows) {
        if (r.n < 1 || r.block < 0 || !std::isfinite(r.temp_c)) std::abort();
        for (double v : r.v)
            if (!std::isfinite(v)) std::abort();
        for (double v : r.u)
            if (!std::isfinite(v)) std::abort();
    }
    try {
        const std::string back = calstation::format_station(st);
        err = calstation::parse_station(back, again);
    } catch (...) {
        std::abort();
    }
    if (!err.empty() || again.rows.size() != st.rows.size()) std::abort();
    for (size_t i = 0; i < st.rows.size(); i++) {
        const auto &a = st.rows[i], &b = again.rows[i];
        if (a.kind != b.kind || a.block != b.block || a.n != b.n) std::abort();
    }
    return 0;
}
