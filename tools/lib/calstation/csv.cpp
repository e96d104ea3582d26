// csv.cpp - reading and writing the station file (format in station.hpp).
#include "inclino/calstation/station.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace calstation
{

const char *const kCsvHeader = "block,kind,temp_c,ux,uy,uz,angle_deg,dur_s,n,x,y,z";

namespace
{

const char *const kCols[12] = {"block",     "kind",  "temp_c", "ux", "uy", "uz",
                               "angle_deg", "dur_s", "n",      "x",  "y",  "z"};

std::string trim(const std::string &s)
{
    size_t a = 0, b = s.size();
    while (a < b && (s[a] == ' ' || s[a] == '\t' || s[a] == '\r'))
        a++;
    while (b > a && (s[b - 1] == ' ' || s[b - 1] == '\t' || s[b - 1] == '\r'))
        b--;
    return s.substr(a, b - a);
}

std::vector<std::string> split(const std::string &s, char sep)
{
    std::vector<std::string> out;
    std::string cur;
    for (char c : s) {
        if (c == sep) {
            out.push_back(trim(cur));
            cur.clear();
        } else {
            cur += c;
        }
    }
    out.push_back(trim(cur));
    return out;
}

std::string at(int line)
{
    return "line " + std::to_string(line) + ": ";
}

std::string col_at(int line, int col)
{
    return "line " + std::to_string(line) + ", column '" + kCols[col] + "': ";
}

// A finite decimal number taking the whole field. The end is compared with the field's size, not
// with a NUL: a NUL byte inside the field ("1\0 500") used to end it and pass as 1.
bool to_double(const std::string &s, double &v, std::string &why)
{
    if (s.empty()) {
        why = "empty field";
        return false;
    }
    char *end = nullptr;
    errno = 0;
    v = std::strtod(s.c_str(), &end);
    if (end == s.c_str() || end != s.c_str() + s.size()) {
        why = "'" + s + "' is not a number";
        return false;
    }
    if (!std::isfinite(v) || errno == ERANGE) {
        why = "'" + s + "' is not a finite number (NaN and infinity are refused)";
        return false;
    }
    return true;
}

// A decimal integer taking the whole field; with hex_ok also 0x... (the binding words are chip
// ids). strtol with base 0 used to read "010" as octal 8: a leading zero is now refused as
// ambiguous, and the end is compared with the field's size (a NUL byte inside cannot end it).
bool to_long(const std::string &s, long &v, std::string &why, bool hex_ok)
{
    if (s.empty()) {
        why = "empty field";
        return false;
    }
    const size_t i = (s[0] == '-' || s[0] == '+') ? 1u : 0u;
    int base = 10;
    if (hex_ok && s.size() > i + 2u && s[i] == '0' && (s[i + 1u] == 'x' || s[i + 1u] == 'X')) {
        base = 16;
    } else if (s.size() > i + 1u && s[i] == '0') {
        why = "'" + s + "' has a leading zero (octal or decimal?)";
        return false;
    }
    char *end = nullptr;
    errno = 0;
    v = std::strtol(s.c_str(), &end, base);
    if (end == s.c_str() || end != s.c_str() + s.size() || errno == ERANGE) {
        why = "'" + s + "' is not an integer";
        return false;
    }
    return true;
}

std::string parse_setting(const std::string &body, int line, Station &st)
{
    const size_t eq = body.find('=');
    if (eq == std::string::npos) {
        return at(line) + "setting '" + body + "' is not key=value";
    }
    const std::string key = trim(body.substr(0, eq)), val = trim(body.substr(eq + 1));
    std::string why;
    double d = 0.0;
    if (key == "format") {
        if (val != "1")
            return at(line) + "unsupported station file format '" + val + "' (this tool reads 1)";
        return "";
    }
    if (key == "acc_lsb_g" || key == "gyro_lsb_dps") {
        if (!to_double(val, d, why)) return at(line) + key + ": " + why;
        if (!(d > 0.0) || d > 1.0e3) return at(line) + key + " must be > 0 (got " + val + ")";
        (key == "acc_lsb_g" ? st.acc_lsb_g : st.gyro_lsb_dps) = d;
        return "";
    }
    if (key == "t_ref_c") {
        if (!to_double(val, d, why)) return at(line) + key + ": " + why;
        if (d < -100.0 || d > 200.0) return at(line) + "t_ref_c outside -100..200 degC";
        st.t_ref_c = d;
        return "";
    }
    if (key == "binding") {
        const auto f = split(val, ',');
        if (f.size() != 6)
            return at(line) +
                   "binding needs 6 integers (family,product,revision,serial,lot_id1,lot_id2)";
        for (size_t i = 0; i < 6; i++) {
            long v = 0;
            if (!to_long(f[i], v, why, true) || v < 0 || v > 0xFFFFFFFFL) {
                return at(line) + "binding field " + std::to_string(i + 1) + ": " +
                       (why.empty() ? "out of range" : why);
            }
            st.binding[i] = static_cast<uint32_t>(v);
        }
        st.have_binding = true;
        return "";
    }
    return at(line) + "unknown setting '" + key + "'";
}

double norm3(const std::array<double, 3> &u)
{
    return std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
}

std::string parse_row(const std::vector<std::string> &f, int line, Row &r)
{
    std::string why;
    r.line = line;
    if (!to_long(f[0], r.block, why, false)) return col_at(line, 0) + why;
    if (r.block < 0) return col_at(line, 0) + "block id must be >= 0";
    if (f[1] == "acc")
        r.kind = RowKind::Acc;
    else if (f[1] == "gyro_still")
        r.kind = RowKind::GyroStill;
    else if (f[1] == "gyro_turn")
        r.kind = RowKind::GyroTurn;
    else
        return col_at(line, 1) + "unknown kind '" + f[1] + "' (acc, gyro_still, gyro_turn)";
    double *dst[10] = {&r.temp_c, &r.u[0], &r.u[1], &r.u[2], &r.angle_deg,
                       &r.dur_s,  nullptr, &r.v[0], &r.v[1], &r.v[2]};
    for (int c = 2; c < 12; c++) {
        if (c == 8) {
            if (!to_long(f[c], r.n, why, false)) return col_at(line, c) + why;
            if (r.n < 1) return col_at(line, c) + "sample count must be >= 1";
            continue;
        }
        if (!to_double(f[c], *dst[c - 2], why)) return col_at(line, c) + why;
    }
    if (r.temp_c < -100.0 || r.temp_c > 200.0) {
        return col_at(line, 2) + "temperature outside -100..200 degC";
    }
    const double un = norm3(r.u);
    if (r.kind == RowKind::Acc && (un < 0.98 || un > 1.02)) {
        return at(line) + "the applied specific force has magnitude " + std::to_string(un) +
               " g; a station position applies gravity only (1 g)";
    }
    if (r.kind == RowKind::GyroTurn) {
        if (un < 0.99 || un > 1.01)
            return at(line) + "the turn axis (ux,uy,uz) must be a unit vector";
        if (!(std::fabs(r.angle_deg) >= 90.0))
            return col_at(line, 6) + "a turn must be at least 90 degrees";
        if (!(r.dur_s > 0.0)) return col_at(line, 7) + "the turn duration must be > 0 s";
    }
    return "";
}

} // namespace

std::string parse_station(const std::string &text, Station &st)
{
    st = Station{};
    std::istringstream in(text);
    std::string raw;
    int line = 0;
    bool have_header = false;
    while (std::getline(in, raw)) {
        line++;
        const std::string s = trim(raw);
        if (s.empty()) continue;
        if (s.rfind("#@", 0) == 0) {
            const std::string e = parse_setting(trim(s.substr(2)), line, st);
            if (!e.empty()) return e;
            continue;
        }
        if (s[0] == '#') continue;
        const auto f = split(s, ',');
        if (!have_header) {
            if (s != kCsvHeader) {
                std::string norm;
                for (size_t i = 0; i < f.size(); i++)
                    norm += (i ? "," : "") + f[i];
                if (norm != kCsvHeader) {
                    return at(line) + "expected the column header '" + kCsvHeader + "'";
                }
            }
            have_header = true;
            continue;
        }
        if (f.size() != 12) {
            return at(line) + std::to_string(f.size()) + " fields, expected 12 (" + kCsvHeader +
                   ")";
        }
        Row r;
        const std::string e = parse_row(f, line, r);
        if (!e.empty()) return e;
        st.rows.push_back(r);
    }
    if (line == 0 || (!have_header && st.rows.empty())) {
        return "empty station file: no column header and no measurement rows";
    }
    if (!have_header) return "no column header line ('" + std::string(kCsvHeader) + "')";
    if (st.rows.empty())
        return "no measurement rows after the header (line " + std::to_string(line) + ")";
    if (!(st.acc_lsb_g > 0.0)) return "missing setting '#@ acc_lsb_g=<g per count>'";
    const auto g = std::find_if(st.rows.begin(), st.rows.end(),
                                [](const Row &r) { return r.kind != RowKind::Acc; });
    if (g != st.rows.end() && !(st.gyro_lsb_dps > 0.0)) {
        return at(g->line) + "gyro row but no setting '#@ gyro_lsb_dps=<deg/s per count>'";
    }
    return "";
}

std::string read_station_file(const std::string &path, Station &st)
{
    std::ifstream f(path, std::ios::binary);
    if (!f) return "cannot open '" + path + "'";
    std::ostringstream ss;
    ss << f.rdbuf();
    const std::string e = parse_station(ss.str(), st);
    return e.empty() ? e : path + ": " + e;
}

std::string format_station(const Station &st)
{
    std::string out =
        "# Inclino calibration-station measurements (docs/calibration.md)\n#@ format=1\n";
    char buf[512];
    std::snprintf(buf, sizeof buf, "#@ acc_lsb_g=%.9g\n", st.acc_lsb_g);
    out += buf;
    if (st.gyro_lsb_dps > 0.0) {
        std::snprintf(buf, sizeof buf, "#@ gyro_lsb_dps=%.9g\n", st.gyro_lsb_dps);
        out += buf;
    }
    std::snprintf(buf, sizeof buf, "#@ t_ref_c=%.6g\n", st.t_ref_c);
    out += buf;
    if (st.have_binding) {
        std::snprintf(buf, sizeof buf, "#@ binding=%u,%u,%u,%u,%u,%u\n", st.binding[0],
                      st.binding[1], st.binding[2], st.binding[3], st.binding[4], st.binding[5]);
        out += buf;
    }
    out += kCsvHeader;
    out += '\n';
    for (const auto &r : st.rows) {
        const char *k = r.kind == RowKind::Acc
                            ? "acc"
                            : (r.kind == RowKind::GyroStill ? "gyro_still" : "gyro_turn");
        std::snprintf(buf, sizeof buf, "%ld,%s,%.4f,%.9f,%.9f,%.9f,%.6f,%.6f,%ld,%.5f,%.5f,%.5f\n",
                      r.block, k, r.temp_c, r.u[0], r.u[1], r.u[2], r.angle_deg, r.dur_s, r.n,
                      r.v[0], r.v[1], r.v[2]);
        out += buf;
    }
    return out;
}

} // namespace calstation
