// samples.cpp - see samples.hpp.
#include "inclino/calstation/samples.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include <fcntl.h>
#include <limits.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

namespace calstation
{

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

std::vector<std::string> split(const std::string &s)
{
    std::vector<std::string> out;
    size_t p = 0;
    while (true) {
        const size_t c = s.find(',', p);
        out.push_back(trim(s.substr(p, c == std::string::npos ? std::string::npos : c - p)));
        if (c == std::string::npos) break;
        p = c + 1;
    }
    return out;
}

// The column name without case, spaces and a unit suffix.
std::string key_of(const std::string &name)
{
    std::string k;
    for (char c : name) {
        if (c == '[' || c == '(') break;
        if (c == ' ' || c == '\t' || c == '"') continue;
        k += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    // A unit written into the name: acc_x_mps2, ax_g, accel_x_ms2.
    for (const char *suf : {"_mps2", "_ms2", "_m/s^2", "_m/s2", "_ms^2", "_g"}) {
        const size_t n = std::strlen(suf);
        if (k.size() > n + 1 && k.compare(k.size() - n, n, suf) == 0) {
            k.erase(k.size() - n);
            break;
        }
    }
    return k;
}

bool number(const std::string &s, double &v)
{
    if (s.empty()) return false;
    char *end = nullptr;
    errno = 0;
    v = std::strtod(s.c_str(), &end);
    return end == s.c_str() + s.size() && std::isfinite(v) && errno != ERANGE;
}

} // namespace

bool is_station_text(const std::string &text)
{
    size_t p = 0;
    while (p < text.size()) {
        const size_t e = text.find('\n', p);
        const std::string l = trim(
            text.substr(p, e == std::string::npos ? std::string::npos : e - p));
        if (l.rfind("#@", 0) == 0) return true;
        if (!l.empty() && l[0] != '#') return l.rfind("block,kind,", 0) == 0;
        if (e == std::string::npos) break;
        p = e + 1;
    }
    return false;
}

std::string parse_samples(const std::string &text, double unit_g, SampleFile &out)
{
    out = SampleFile{};
    if (text.find('\0') != std::string::npos) return "a NUL byte in the sample file";
    size_t p = 0;
    int line = 0;
    bool have_header = false;
    static const char *const names[][6] = {
        {"ax", "acc_x", "accel_x", "accx", "a_x", "x"},
        {"ay", "acc_y", "accel_y", "accy", "a_y", "y"},
        {"az", "acc_z", "accel_z", "accz", "a_z", "z"},
    };
    while (p < text.size()) {
        const size_t e = text.find('\n', p);
        const std::string l = trim(
            text.substr(p, e == std::string::npos ? std::string::npos : e - p));
        p = e == std::string::npos ? text.size() : e + 1;
        line++;
        if (l.empty()) continue;
        if (l[0] == '#') {
            if (!have_header) out.comments.push_back(l);
            continue;
        }
        std::vector<std::string> f = split(l);
        if (!have_header) {
            have_header = true;
            out.header = f;
            for (int a = 0; a < 3; a++) {
                for (int n = 0; n < 6 && out.col[a] < 0; n++) {
                    for (size_t c = 0; c < f.size(); c++) {
                        if (key_of(f[c]) == names[a][n]) {
                            out.col[a] = static_cast<int>(c);
                            break;
                        }
                    }
                }
                if (out.col[a] < 0) {
                    return "line " + std::to_string(line) + ": no acceleration column for axis " +
                           std::string(1, "xyz"[a]) +
                           " in the header (ax/acc_x/accel_x/x ...: docs/calibration.md 4.5)";
                }
            }
            for (size_t c = 0; c < f.size(); c++) {
                const std::string k = key_of(f[c]);
                if (out.col_temp < 0 &&
                    (k == "temp_c" || k == "temp" || k == "temperature" || k == "t_c"))
                    out.col_temp = static_cast<int>(c);
                if (out.col_time < 0 &&
                    (k == "t" || k == "time" || k == "time_s" || k == "timestamp"))
                    out.col_time = static_cast<int>(c);
            }
            continue;
        }
        if (f.size() != out.header.size()) {
            return "line " + std::to_string(line) + ": " + std::to_string(f.size()) +
                   " fields, expected " + std::to_string(out.header.size()) + " (the header's)";
        }
        std::array<double, 3> a{};
        for (int k = 0; k < 3; k++) {
            if (!number(f[out.col[k]], a[k])) {
                return "line " + std::to_string(line) + ", column '" + out.header[out.col[k]] +
                       "': '" + f[out.col[k]] + "' is not a finite number";
            }
            a[k] /= unit_g;
            if (!(std::fabs(a[k]) <= 64.0))
                return "line " + std::to_string(line) + ", column '" + out.header[out.col[k]] +
                       "': beyond +-64 g (wrong --units?)";
        }
        if (out.col_temp >= 0) {
            double t = 0.0;
            if (!number(f[out.col_temp], t) || t < -100.0 || t > 200.0)
                return "line " + std::to_string(line) + ", column '" + out.header[out.col_temp] +
                       "': '" + f[out.col_temp] + "' is not a temperature in -100..200 degC";
            out.temp_c.push_back(t);
        }
        if (out.col_time >= 0) {
            double tm = 0.0;
            if (!number(f[out.col_time], tm))
                return "line " + std::to_string(line) + ", column '" + out.header[out.col_time] +
                       "': '" + f[out.col_time] + "' is not a finite number";
            out.time_s.push_back(tm);
        }
        out.acc_g.push_back(a);
        out.fields.push_back(std::move(f));
        out.lines.push_back(line);
    }
    if (!have_header) return "empty sample file: no column header and no samples";
    if (out.acc_g.empty()) return "no samples after the header";
    return "";
}

std::vector<Segment> find_segments(const SampleFile &s, size_t win)
{
    const size_t n = s.acc_g.size();
    if (win == 0) {
        win = 51;
        if (s.time_s.size() == n && n > 2) {
            std::vector<double> dt;
            for (size_t k = 1; k < n; k++)
                dt.push_back(s.time_s[k] - s.time_s[k - 1]);
            std::nth_element(dt.begin(), dt.begin() + dt.size() / 2, dt.end());
            const double d = dt[dt.size() / 2];
            if (d > 0.0 && d < 1.0)
                win = static_cast<size_t>(std::clamp(std::lround(0.5 / d), 5L, 100000L));
        }
    }
    std::vector<Segment> out;
    if (n < 2 * win) return out;
    // Moving variance over [k - h, k + h] from prefix sums (relative to the first sample).
    const size_t h = win / 2;
    std::vector<std::array<double, 3>> s1(n + 1), s2(n + 1);
    s1[0] = s2[0] = {0, 0, 0};
    for (size_t k = 0; k < n; k++) {
        for (int a = 0; a < 3; a++) {
            const double d = s.acc_g[k][a] - s.acc_g[0][a];
            s1[k + 1][a] = s1[k][a] + d;
            s2[k + 1][a] = s2[k][a] + d * d;
        }
    }
    std::vector<double> sd(n, 1e9);
    for (size_t k = h; k + h < n; k++) {
        const double m = static_cast<double>(2 * h + 1);
        double v = 0.0;
        for (int a = 0; a < 3; a++) {
            const double mu = (s1[k + h + 1][a] - s1[k - h][a]) / m;
            v += std::max(0.0, (s2[k + h + 1][a] - s2[k - h][a]) / m - mu * mu);
        }
        sd[k] = std::sqrt(v);
    }
    std::vector<double> sorted(sd.begin() + static_cast<long>(h), sd.end() - static_cast<long>(h));
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 5, sorted.end());
    const double thr = 4.0 * sorted[sorted.size() / 5] + 0.0005;
    size_t k = 0;
    while (k < n) {
        if (!(sd[k] < thr)) {
            k++;
            continue;
        }
        size_t e = k;
        while (e < n && sd[e] < thr)
            e++;
        // [k, e) still centres: the still samples are [k - h, e + h); trim one window each end.
        const size_t b0 = k + win, e0 = e > win ? e - win : 0;
        if (e0 > b0 && e0 - b0 >= 2 * win) {
            Segment g;
            g.begin = b0;
            g.end = e0;
            double t = 0.0;
            for (size_t q = b0; q < e0; q++) {
                for (int a = 0; a < 3; a++)
                    g.mean[a] += s.acc_g[q][a];
                if (!s.temp_c.empty()) t += s.temp_c[q];
            }
            for (int a = 0; a < 3; a++)
                g.mean[a] /= static_cast<double>(e0 - b0);
            g.temp_c = s.temp_c.empty() ? 0.0 : t / static_cast<double>(e0 - b0);
            const double m = std::sqrt(g.mean[0] * g.mean[0] + g.mean[1] * g.mean[1] +
                                       g.mean[2] * g.mean[2]);
            for (int a = 0; a < 3; a++) {
                if (m > 0.5 &&
                    std::fabs(g.mean[a]) > std::cos(25.0 * 3.14159265358979323846 / 180.0) * m) {
                    g.axis = a;
                    g.sign = g.mean[a] > 0 ? 1 : -1;
                }
            }
            out.push_back(g);
        }
        k = e;
    }
    return out;
}

std::string station_from_segments(const SampleFile &s, const std::vector<Segment> &seg,
                                  double t_ref, Station &st, size_t &skipped)
{
    st = Station{};
    st.acc_lsb_g = 1.0;
    st.t_ref_c = t_ref;
    skipped = 0;
    for (const auto &g : seg) {
        if (g.axis < 0) {
            skipped++;
            continue;
        }
        Row r;
        r.line = s.lines[g.begin];
        r.block = 0;
        r.kind = RowKind::Acc;
        r.temp_c = s.temp_c.empty() ? t_ref : g.temp_c;
        r.u = {0.0, 0.0, 0.0};
        r.u[g.axis] = g.sign;
        r.n = static_cast<long>(g.end - g.begin);
        r.v = g.mean;
        st.rows.push_back(r);
    }
    if (st.rows.empty()) {
        return "no still face found in the samples (" + std::to_string(seg.size()) +
               " still intervals, none within 25 deg of an axis): is the acceleration column "
               "right, and the unit (--units)?";
    }
    return "";
}

FaceResidual face_residual(const std::vector<std::array<double, 3>> &acc,
                           const std::vector<Segment> &seg)
{
    FaceResidual r;
    double ss = 0.0;
    for (const auto &g : seg) {
        if (g.axis < 0 || g.end > acc.size()) continue;
        double m = 0.0;
        for (size_t k = g.begin; k < g.end; k++)
            m += std::sqrt(acc[k][0] * acc[k][0] + acc[k][1] * acc[k][1] + acc[k][2] * acc[k][2]) -
                 1.0;
        m = m / static_cast<double>(g.end - g.begin) * 1e3;
        r.per_face_mg.push_back(m);
        ss += m * m;
        r.max_mg = std::max(r.max_mg, std::fabs(m));
        r.faces++;
    }
    if (r.faces) r.rms_mg = std::sqrt(ss / static_cast<double>(r.faces));
    return r;
}

// ---- Files -------------------------------------------------------------------------------

std::string read_input(const std::string &path, size_t max_bytes, std::string &out)
{
    out.clear();
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return "cannot open '" + path + "': " + std::strerror(errno);
    struct stat sb;
    if (fstat(fd, &sb) != 0 ||
        !(S_ISREG(sb.st_mode) || S_ISFIFO(sb.st_mode) || S_ISCHR(sb.st_mode))) {
        const bool dir = S_ISDIR(sb.st_mode);
        ::close(fd);
        return "cannot open '" + path + "': " + (dir ? "a directory" : "not a regular file");
    }
    char buf[65536];
    while (true) {
        const ssize_t r = ::read(fd, buf, sizeof buf);
        if (r < 0) {
            if (errno == EINTR) continue;
            const std::string e = std::strerror(errno);
            ::close(fd);
            return "cannot read '" + path + "': " + e;
        }
        if (r == 0) break;
        if (out.size() + static_cast<size_t>(r) > max_bytes) {
            ::close(fd);
            return "cannot read '" + path + "': larger than " + std::to_string(max_bytes) +
                   " bytes";
        }
        out.append(buf, static_cast<size_t>(r));
    }
    ::close(fd);
    return "";
}

namespace
{

std::string write_all(int fd, const std::string &data, const std::string &what)
{
    size_t off = 0;
    while (off < data.size()) {
        const ssize_t w = ::write(fd, data.data() + off, data.size() - off);
        if (w < 0) {
            if (errno == EINTR) continue;
            return "cannot write '" + what + "': " + std::strerror(errno);
        }
        off += static_cast<size_t>(w);
    }
    return "";
}

} // namespace

std::string write_output(const std::string &path, const std::string &data,
                         const std::vector<std::string> &inputs)
{
    if (path.empty()) return "cannot write '': empty path";
    // Follow a symlink to what it names (the link itself is never replaced).
    std::string target = path;
    struct stat sb;
    bool exists = false;
    if (lstat(path.c_str(), &sb) == 0) {
        exists = true;
        if (S_ISLNK(sb.st_mode)) {
            char *rp = realpath(path.c_str(), nullptr);
            if (rp == nullptr)
                return "cannot write '" + path + "': a symlink to nothing (" +
                       std::strerror(errno) + ")";
            target = rp;
            std::free(rp);
            exists = stat(target.c_str(), &sb) == 0;
        }
    } else if (errno != ENOENT) {
        return "cannot write '" + path + "': " + std::strerror(errno);
    }
    if (exists) {
        for (const auto &in : inputs) {
            struct stat ib;
            if (stat(in.c_str(), &ib) == 0 && ib.st_dev == sb.st_dev && ib.st_ino == sb.st_ino)
                return "cannot write '" + path + "': it is the input '" + in + "'";
        }
        if (S_ISFIFO(sb.st_mode) || S_ISCHR(sb.st_mode)) {
            const int fd = ::open(target.c_str(), O_WRONLY | O_CLOEXEC);
            if (fd < 0) return "cannot write '" + path + "': " + std::strerror(errno);
            std::string e = write_all(fd, data, path);
            if (::close(fd) != 0 && e.empty())
                e = "cannot write '" + path + "': " + std::strerror(errno);
            return e;
        }
        if (!S_ISREG(sb.st_mode))
            return "cannot write '" + path +
                   "': " + (S_ISDIR(sb.st_mode) ? "a directory" : "not a regular file");
    }
    std::string tmpl = target + ".tmp-XXXXXX";
    std::vector<char> tb(tmpl.begin(), tmpl.end());
    tb.push_back('\0');
    const int fd = mkstemp(tb.data());
    if (fd < 0) return "cannot write '" + path + "': " + std::strerror(errno);
    const std::string tmp = tb.data();
    std::string e = write_all(fd, data, path);
    if (e.empty() && fsync(fd) != 0 && errno != EINVAL && errno != EROFS)
        e = "cannot write '" + path + "': " + std::strerror(errno);
    if (::close(fd) != 0 && e.empty()) e = "cannot write '" + path + "': " + std::strerror(errno);
    if (e.empty()) {
        // mkstemp makes 0600: give the file the mode it had, or a new file's (0666 - umask).
        mode_t mode = sb.st_mode & 07777;
        if (!exists) {
            const mode_t um = umask(022);
            umask(um);
            mode = 0666 & ~um;
        }
        (void)chmod(tmp.c_str(), mode);
    }
    if (e.empty() && std::rename(tmp.c_str(), target.c_str()) != 0)
        e = "cannot write '" + path + "': " + std::strerror(errno);
    if (!e.empty()) (void)::unlink(tmp.c_str());
    return e;
}

} // namespace calstation
