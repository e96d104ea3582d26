// Bad station input (tools/calstation): every case gets a clear error that names the
// problem (and the line where there is one), and no calibration result. Host only.
#include "inclino/calstation/fit.hpp"
#include "inclino/calstation/station.hpp"
#include "unit.h"

#include <cstdio>
#include <string>

using namespace calstation;

namespace
{

const std::string kHead =
    "#@ format=1\n#@ acc_lsb_g=0.001\nblock,kind,temp_c,ux,uy,uz,angle_deg,dur_s,n,x,y,z\n";

// Six +-1 g faces of an ideal part at one temperature (lines 4..9).
std::string faces(double t = 25.0, long block = 0, double gx = 1000.0, double ox = 0.0)
{
    char b[1024];
    std::snprintf(b, sizeof b,
                  "%ld,acc,%g,1,0,0,0,0,100,%g,0,0\n%ld,acc,%g,-1,0,0,0,0,100,%g,0,0\n"
                  "%ld,acc,%g,0,1,0,0,0,100,%g,1000,0\n%ld,acc,%g,0,-1,0,0,0,100,%g,-1000,0\n"
                  "%ld,acc,%g,0,0,1,0,0,100,%g,0,1000\n%ld,acc,%g,0,0,-1,0,0,100,%g,0,-1000\n",
                  block, t, ox + gx, block, t, ox - gx, block, t, ox, block, t, ox, block, t, ox,
                  block, t, ox);
    return b;
}

// Parse, then fit: the first error message, or "" when both pass.
std::string run(const std::string &text, TChoice tm = TChoice::None)
{
    Station st;
    std::string e = parse_station(text, st);
    if (!e.empty()) return e;
    CalResult c;
    FitOptions o;
    o.tmodel = tm;
    return fit_station(st, o, c);
}

bool has(const std::string &msg, const char *what)
{
    const bool ok = msg.find(what) != std::string::npos;
    if (!ok) std::printf("  message was: %s\n  expected to contain: %s\n", msg.c_str(), what);
    return ok;
}

} // namespace

static void test_valid_baseline()
{
    // The baseline the bad cases are made from is itself accepted.
    CHECK_EQ_INT(run(kHead + faces()).size(), 0);
}

static void test_empty_and_short()
{
    CHECK(has(run(""), "empty station file"));
    CHECK(has(run("# only a comment\n\n"), "empty station file"));
    CHECK(has(run(kHead), "no measurement rows"));
    CHECK(has(run("#@ acc_lsb_g=0.001\n0,acc,25,1,0,0,0,0,100,1000,0,0\n"),
              "line 2: expected the column header"));
    // A truncated row.
    CHECK(has(run(kHead + "0,acc,25,1,0,0,0,0,100\n"), "line 4: 9 fields, expected 12"));
    // Fewer rows than the six faces.
    std::string three = faces();
    three.resize(three.find("0,acc,25,0,-1"));
    CHECK(has(run(kHead + three), "too few measurements: 3 acc rows"));
    CHECK(has(run("block,kind,temp_c,ux,uy,uz,angle_deg,dur_s,n,x,y,z\n" + faces()),
              "missing setting '#@ acc_lsb_g"));
}

static void test_nan_and_garbage()
{
    std::string t = kHead + faces();
    const size_t p = t.find("100,1000,0,0");
    std::string nan = t;
    nan.replace(p + 4, 4, "nan");
    CHECK(has(run(nan), "line 4, column 'x': 'nan' is not a finite number"));
    std::string inf = t;
    inf.replace(p + 4, 4, "-inf");
    CHECK(has(run(inf), "line 4, column 'x': '-inf' is not a finite number"));
    std::string txt = t;
    txt.replace(p + 4, 4, "1e3x");
    CHECK(has(run(txt), "line 4, column 'x': '1e3x' is not a number"));
    std::string temp = t;
    temp.replace(temp.find("0,acc,25,0,1,0"), 8, "0,acc,NaN");
    CHECK(has(run(temp), "line 6, column 'temp_c'"));
    CHECK(has(run(kHead + "0,acc,25,1,0,0,0,0,0,1000,0,0\n"),
              "line 4, column 'n': sample count must be >= 1"));
    CHECK(has(run(kHead + "0,spin,25,1,0,0,0,0,1,1000,0,0\n"), "unknown kind 'spin'"));
    CHECK(has(run(kHead + "0,acc,25,0.5,0,0,0,0,1,1000,0,0\n"),
              "line 4: the applied specific force has magnitude"));
    CHECK(has(run("#@ acc_lsb_g=-1\n"), "line 1: acc_lsb_g must be > 0"));
    CHECK(has(run("#@ colour=red\n"), "line 1: unknown setting 'colour'"));
    CHECK(has(run(kHead + faces() + "0,gyro_still,25,0,0,0,0,0,10,1,2,3\n"),
              "line 10: gyro row but no setting"));
}

static void test_degenerate()
{
    // All positions equal.
    std::string same;
    for (int i = 0; i < 8; i++)
        same += "0,acc,25,0,0,1,0,0,100,0,0,1000\n";
    CHECK(has(run(kHead + same),
              "degenerate data: all 8 acc rows (lines 4..11) are at the same position (0,0,1)"));
    // +1 g and -1 g swapped on x (the station wrote the faces the wrong way round).
    std::string sw = faces();
    sw.replace(sw.find("1,0,0,0,0,100,1000"), 18, "1,0,0,0,0,100,-1000");
    sw.replace(sw.find("-1,0,0,0,0,100,-1000"), 20, "-1,0,0,0,0,100,1000");
    CHECK(has(run(kHead + sw),
              "axis x, block 0: the +1 g face (line 4) reads -1.0000 g, not above the -1 g face "
              "(line 5, 1.0000 g): +1 g and -1 g swapped"));
    // One temperature only, with temperature models asked for.
    CHECK(has(run(kHead + faces(), TChoice::Best), "one temperature only (25.0 degC)"));
    CHECK(has(run(kHead + faces(), TChoice::Lorentz), "one temperature only"));
    // Two temperatures: a Lorentz needs five.
    CHECK(has(run(kHead + faces(20.0, 0) + faces(40.0, 1), TChoice::Lorentz),
              "at least 5 soak temperatures (got 2)"));
    // A missing face pair for one axis.
    std::string noy = faces();
    noy.erase(noy.find("0,acc,25,0,-1"), std::string("0,acc,25,0,-1,0,0,0,100,0,-1000,0\n").size());
    noy += "0,acc,25,0.6,0.8,0,0,0,100,600,800,0\n";
    CHECK(has(run(kHead + noy), "axis y has no +1 g / -1 g face pair"));
}

static void test_out_of_range()
{
    // Gain 2 (wrong nominal LSB), offset 0.6 g, a gyro that turns the wrong way.
    CHECK(has(run(kHead + faces(25.0, 0, 2000.0)),
              "coefficient out of range: acc_gain[x] = 2 (limit 0.75..1.25)"));
    CHECK(has(run(kHead + faces(25.0, 0, 1000.0, 600.0)),
              "coefficient out of range: acc_offset[x] = 0.6 (limit +-0.5 g)"));
    const std::string gyro = "#@ gyro_lsb_dps=0.05\n0,gyro_still,25,0,0,0,0,0,1000,10,0,0\n"
                             "0,gyro_turn,25,1,0,0,360,4,3277,-28840,0,0\n";
    CHECK(has(run(kHead + faces() + gyro), "gyro axis x: the measured turn has the opposite sign"));
    const std::string gyro_off = "#@ gyro_lsb_dps=0.05\n0,gyro_still,25,0,0,0,0,0,1000,700,0,0\n";
    CHECK(has(run(kHead + faces() + gyro_off),
              "coefficient out of range: gyro_offset[x] = 35 (limit +-30 deg/s)"));
}

int main()
{
    UNIT_RUN(test_valid_baseline);
    UNIT_RUN(test_empty_and_short);
    UNIT_RUN(test_nan_and_garbage);
    UNIT_RUN(test_degenerate);
    UNIT_RUN(test_out_of_range);
    return unit_report();
}
