// Mutation sweep of the calibration-station file reader (calstation::parse_station,
// tools/lib/calstation/csv.cpp), plain host build and ASan+UBSan.
//
// Seeds: a chamber file with two soaks of six faces, a gyro_still and a gyro_turn row, all four
// settings; and the ambient file of tests/cal (six faces, no gyro). A station that parses is
// checked against the bytes of the mutated file: as many rows as data lines counted here; every
// row's line re-read field by field (strtol base 10, strtod, whole field) gives exactly the
// stored values (a NUL or an octal reading cannot pass unseen); ranges of docs/calibration.md
// 4.2 hold (temp, |u|, n >= 1, block >= 0, turn >= 90 deg, LSBs > 0). Certainly broken cases must
// be refused with a message naming the line: NaN/inf/empty/underflowing numbers in a row, an extra
// field on any non-comment line, a duplicated header, a row cut before its last field, a NUL/0xFF/'n'
// byte in a row, a 5000-character run of anything but blanks.
#include "fuzz_mut.h"
#include "inclino/calstation/station.hpp"
#include "unit.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

using namespace calstation;

namespace
{

std::string trim(const std::string &s)
{
    size_t a = 0, b = s.size();
    while (a < b && (s[a] == ' ' || s[a] == '\t' || s[a] == '\r'))
        a++;
    while (b > a && (s[b - 1] == ' ' || s[b - 1] == '\t' || s[b - 1] == '\r'))
        b--;
    return s.substr(a, b - a);
}

std::vector<std::string> lines_of(const std::string &t)
{
    std::vector<std::string> out;
    size_t s = 0;
    while (s < t.size()) {
        size_t e = t.find('\n', s);
        if (e == std::string::npos) e = t.size();
        out.push_back(t.substr(s, e - s));
        s = e + 1;
    }
    return out;
}

std::vector<std::string> fields_of(const std::string &s)
{
    std::vector<std::string> f;
    size_t a = 0;
    for (;;) {
        const size_t c = s.find(',', a);
        f.push_back(trim(s.substr(a, c == std::string::npos ? std::string::npos : c - a)));
        if (c == std::string::npos) return f;
        a = c + 1;
    }
}

bool dec_long(const std::string &s, long &v)
{
    if (s.empty() || s.find('\0') != std::string::npos) return false;
    char *end = nullptr;
    errno = 0;
    v = std::strtol(s.c_str(), &end, 10);
    return *end == '\0' && errno == 0;
}

bool num(const std::string &s, double &v)
{
    if (s.empty() || s.find('\0') != std::string::npos) return false;
    char *end = nullptr;
    errno = 0;
    v = std::strtod(s.c_str(), &end);
    return *end == '\0' && std::isfinite(v) && errno == 0;
}

enum class LineKind { Blank, Comment, Setting, Header, Row };

// What each line of the seed is (the first content line is the header).
std::vector<LineKind> classify(const std::string &t)
{
    std::vector<LineKind> k;
    bool header = false;
    for (const auto &l : lines_of(t)) {
        const std::string s = trim(l);
        if (s.empty())
            k.push_back(LineKind::Blank);
        else if (s.rfind("#@", 0) == 0)
            k.push_back(LineKind::Setting);
        else if (s[0] == '#')
            k.push_back(LineKind::Comment);
        else if (!header) {
            header = true;
            k.push_back(LineKind::Header);
        } else
            k.push_back(LineKind::Row);
    }
    return k;
}

size_t line_of(const std::string &t, size_t pos)
{
    size_t n = 0;
    for (size_t i = 0; i < pos && i < t.size(); i++)
        n += t[i] == '\n';
    return n;
}

unsigned n_cases, n_ok, n_must;

void check_station(const std::string &label, unsigned long k, const fuzz_case &c, const Station &st)
{
    const std::string text(c.data, c.len);
    const auto lines = lines_of(text);
    const auto kinds = classify(text);
    const size_t rows = static_cast<size_t>(std::count(kinds.begin(), kinds.end(), LineKind::Row));
    bool ok = st.rows.size() == rows && st.acc_lsb_g > 0.0 && st.acc_lsb_g <= 1e3 &&
              st.t_ref_c >= -100.0 && st.t_ref_c <= 200.0;
    std::string why = ok ? "" : "row count or settings";
    for (size_t i = 0; ok && i < st.rows.size(); i++) {
        const Row &r = st.rows[i];
        if (r.line < 1 || static_cast<size_t>(r.line) > lines.size() ||
            (i > 0 && r.line <= st.rows[i - 1].line)) {
            ok = false;
            why = "line number";
            break;
        }
        const auto f = fields_of(trim(lines[r.line - 1]));
        long b = 0, n = 0;
        double v[10];
        const double *got[10] = {&r.temp_c, &r.u[0], &r.u[1], &r.u[2], &r.angle_deg,
                                 &r.dur_s,  nullptr, &r.v[0], &r.v[1], &r.v[2]};
        ok = f.size() == 12 && dec_long(f[0], b) && b == r.block && b >= 0 && dec_long(f[8], n) &&
             n == r.n && n >= 1;
        const char *kname = r.kind == RowKind::Acc
                                ? "acc"
                                : (r.kind == RowKind::GyroStill ? "gyro_still" : "gyro_turn");
        ok = ok && f[1] == kname;
        for (int j = 0; ok && j < 10; j++) {
            if (j == 6) continue;
            ok = num(f[j + 2], v[j]) && v[j] == *got[j];
        }
        const double un = std::sqrt(r.u[0] * r.u[0] + r.u[1] * r.u[1] + r.u[2] * r.u[2]);
        ok = ok && r.temp_c >= -100.0 && r.temp_c <= 200.0;
        ok = ok && (r.kind != RowKind::Acc || (un >= 0.98 && un <= 1.02));
        ok = ok && (r.kind != RowKind::GyroTurn ||
                    (un >= 0.99 && un <= 1.01 && std::fabs(r.angle_deg) >= 90.0 && r.dur_s > 0.0 &&
                     st.gyro_lsb_dps > 0.0));
        ok = ok && (r.kind != RowKind::GyroStill || st.gyro_lsb_dps > 0.0);
        if (!ok)
            why = "row " + std::to_string(i) + " (line " + std::to_string(r.line) +
                  ") does not match its line";
    }
    unit_checks++;
    if (!ok) {
        unit_fail(__FILE__, __LINE__, "%s case %lu (%s at %zu, arg %u): accepted, but %s",
                  label.c_str(), k, fuzz_family_name(c.family), c.where, c.arg, why.c_str());
    }
}

bool must_fail(const std::string &seed, const std::vector<LineKind> &kinds, const fuzz_case &c)
{
    auto kind_at = [&](size_t line) { return line < kinds.size() ? kinds[line] : LineKind::Blank; };
    switch (c.family) {
    case FUZZ_BYTE: {
        const unsigned char b = fuzz_bytes[c.arg];
        if (static_cast<unsigned char>(seed[c.where]) == b) return false;
        return (b == 0u || b == 0xFFu || b == 'n') &&
               kind_at(line_of(seed, c.where)) == LineKind::Row;
    }
    case FUZZ_TRUNC: {
        if (c.where == 0 || seed[c.where - 1] == '\n') return false;
        const size_t l = line_of(seed, c.where - 1);
        const size_t last_comma = seed.rfind(',', seed.find('\n', c.where - 1));
        return kind_at(l) == LineKind::Row && last_comma != std::string::npos &&
               line_of(seed, last_comma) == l && c.where <= last_comma + 1;
    }
    case FUZZ_TOKEN: {
        const std::string t = fuzz_tokens[c.arg];
        return kind_at(line_of(seed, c.where)) == LineKind::Row &&
               (t == "nan" || t == "inf" || t == "-inf" || t.empty() || t == "1e-400");
    }
    case FUZZ_EXTRA: {
        const LineKind kd = kind_at(c.where);
        return kd == LineKind::Row || kd == LineKind::Header || kd == LineKind::Setting;
    }
    case FUZZ_DUPLINE: return kind_at(c.where) == LineKind::Header;
    case FUZZ_LONG: return c.arg != ' ';
    default: return false;
    }
}

void sweep(const std::string &label, const std::string &seed)
{
    fuzz_case c = {nullptr, 0, FUZZ_END, 0, 0};
    const auto kinds = classify(seed);
    Station st;
    REQUIRE(parse_station(seed, st).empty());
    size_t stride = UNIT_SIZE(seed.size() / 300u, seed.size() / 150u);
    if (stride == 0) stride = 1;
    for (unsigned long k = 0;
         fuzz_mutate(seed.data(), seed.size(), k, stride, UNIT_SIZE(300u, 60u), &c) != FUZZ_END;
         k++) {
        const std::string text(c.data, c.len);
        const std::string e = parse_station(text, st);
        n_cases++;
        if (e.empty()) {
            n_ok++;
            check_station(label, k, c, st);
        } else {
            unit_checks++;
            if (e.find("line ") == std::string::npos &&
                e.find("empty station file") == std::string::npos &&
                e.find("no column header") == std::string::npos &&
                e.find("missing setting") == std::string::npos) {
                unit_fail(__FILE__, __LINE__, "%s case %lu: message names no line: %s",
                          label.c_str(), k, e.c_str());
            }
        }
        if (must_fail(seed, kinds, c)) {
            n_must++;
            unit_checks++;
            if (e.empty()) {
                unit_fail(__FILE__, __LINE__,
                          "%s case %lu (%s at %zu, arg %u): a certainly broken file was accepted",
                          label.c_str(), k, fuzz_family_name(c.family), c.where, c.arg);
            }
        }
    }
    fuzz_case_free(&c);
}

std::string faces(double t, long block, double ox)
{
    char b[1024];
    std::snprintf(b, sizeof b,
                  "%ld,acc,%g,1,0,0,0,0,100,%g,0,0\n%ld,acc,%g,-1,0,0,0,0,100,%g,0,0\n"
                  "%ld,acc,%g,0,1,0,0,0,100,%g,1000,0\n%ld,acc,%g,0,-1,0,0,0,100,%g,-1000,0\n"
                  "%ld,acc,%g,0,0,1,0,0,100,%g,0,1000\n%ld,acc,%g,0,0,-1,0,0,100,%g,0,-1000\n",
                  block, t, ox + 1000.0, block, t, ox - 1000.0, block, t, ox, block, t, ox, block,
                  t, ox, block, t, ox);
    return b;
}

} // namespace

static void test_sweep()
{
    const std::string chamber =
        "# station run 7\n#@ format=1\n#@ acc_lsb_g=0.001\n#@ gyro_lsb_dps=0.05\n#@ t_ref_c=25\n"
        "#@ binding=3,16364,0,2561,0,0\n\nblock,kind,temp_c,ux,uy,uz,angle_deg,dur_s,n,x,y,z\n" +
        faces(25.0, 0, 1.5) + "# soak 2\n" + faces(60.25, 1, -2.0) +
        "0,gyro_still,25,0,0,0,0,0,200,1.25,-0.5,3\n0,gyro_turn,25,0,0,1,360,7.5,750,3.5,-1.25,54000\n";
    const std::string ambient =
        "#@ format=1\n#@ acc_lsb_g=0.001\nblock,kind,temp_c,ux,uy,uz,angle_deg,dur_s,n,x,y,z\n" +
        faces(23.5, 0, 0.0);
    sweep("chamber", chamber);
    sweep("ambient", ambient);
    std::printf("station: %u cases, %u accepted, %u that must be refused\n", n_cases, n_ok, n_must);
    CHECK(n_cases > UNIT_SIZE(8000u, 4000u));
    CHECK(n_must > n_cases / 10u);
    CHECK(n_ok > n_cases / 10u);
}

// A string literal with its embedded NUL bytes.
#define LIT(s) std::string((s), sizeof(s) - 1u)

// Named regression inputs: each was accepted with a wrong value before the fix.
static void test_regressions()
{
    const std::string head =
        "#@ format=1\n#@ acc_lsb_g=0.001\nblock,kind,temp_c,ux,uy,uz,angle_deg,dur_s,n,x,y,z\n";
    const struct {
        std::string row;
        const char *msg;
    } cases[] = {
        // a NUL inside a field: strtod stopped there, "1\0 5" read as 1
        {LIT("0,acc,25,1,0,0,0,0,100,1\0"
             "500,0,0\n"),
         "line 4, column 'x'"},
        {LIT("0,acc,25,1,0,0,0,0,1\0"
             "00,1000,0,0\n"),
         "line 4, column 'n'"},
        // a leading zero made an integer octal: n=010 read as 8, block=010 as 8
        {"0,acc,25,1,0,0,0,0,010,1000,0,0\n", "line 4, column 'n'"},
        {"010,acc,25,1,0,0,0,0,100,1000,0,0\n", "line 4, column 'block'"},
        {"0x1,acc,25,1,0,0,0,0,100,1000,0,0\n", "line 4, column 'block'"},
    };
    for (const auto &cs : cases) {
        Station st;
        const std::string e = parse_station(head + cs.row, st);
        if (e.find(cs.msg) == std::string::npos) {
            unit_fail(__FILE__, __LINE__, "message '%s', want '%s'", e.c_str(), cs.msg);
        }
        unit_checks++;
    }
    // still accepted: decimal with leading zeros in doubles, hex binding words (calrec ids)
    Station st;
    CHECK(parse_station("#@ binding=0x3,16364,0,0xA01,0,0\n" + head +
                            "0,acc,025.0,1,0,0,0,0,100,1000,0,0\n",
                        st)
              .empty());
    CHECK_EQ_INT(st.binding[0], 3);
    CHECK_EQ_INT(st.binding[3], 0xA01);
    CHECK_NEAR(st.rows.at(0).temp_c, 25.0, 0.0);
    CHECK(!parse_station(
               "#@ binding=3,16364,0,010,0,0\n" + head + "0,acc,25,1,0,0,0,0,100,1000,0,0\n", st)
               .empty());
}

int main()
{
    UNIT_RUN(test_regressions);
    UNIT_RUN(test_sweep);
    return unit_report();
}
