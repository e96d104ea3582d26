// record.cpp - see record.hpp.
#include "inclino/error.h"
#include "inclino/calstation/record.hpp"

#include "inclino/cal.h"

#include <cmath>
#include <cstdio>

namespace calstation
{

namespace
{

int32_t q(double v, double scale)
{
    const double r = std::round(v * scale);
    if (!(r >= -2147483648.0 && r <= 2147483647.0)) return r > 0 ? INT32_MAX : INT32_MIN;
    return static_cast<int32_t>(r);
}

constexpr double kQ16 = 65536.0, kQ30 = 1073741824.0;

void put_tmodel(const TModel &m, double yscale, struct calrec_tmodel &o)
{
    o = calrec_tmodel{};
    o.kind = static_cast<int32_t>(m.kind);
    if (m.kind == TKind::None) return;
    o.n = m.kind == TKind::Pwl ? m.n : 0;
    if (m.kind != TKind::Lorentz) {
        o.t_ref = q(m.t_ref, kQ16);
        o.t_span = q(m.t_span, kQ16);
    }
    for (int k = 0; k < m.params(); k++) {
        o.p[k] = q(m.p[k], tparam_is_degc(m.kind, k) ? kQ16 : yscale);
    }
}

TModel get_tmodel(const struct calrec_tmodel &o, double yscale)
{
    TModel m;
    m.kind = static_cast<TKind>(o.kind);
    m.n = o.n;
    m.t_ref = o.t_ref / kQ16;
    m.t_span = o.t_span / kQ16;
    for (int k = 0; k < kTParams; k++) {
        m.p[k] = o.p[k] / (tparam_is_degc(m.kind, k) ? kQ16 : yscale);
    }
    return m;
}

} // namespace

std::string to_calrec(const CalResult &c, const Station &st, struct calrec &r)
{
    calrec_set_default(&r);
    if (!st.have_binding) {
        return "no binding: the station file needs '#@ binding=family,product,revision,serial,lot_id1,lot_id2' "
               "(the identity read from the part) to write a record";
    }
    r.binding.family = st.binding[0];
    r.binding.product = st.binding[1];
    r.binding.revision = st.binding[2];
    r.binding.serial = st.binding[3];
    r.binding.lot_id1 = st.binding[4];
    r.binding.lot_id2 = st.binding[5];
    if (calrec_check_binding(&r.binding) != INC_OK) {
        return "binding out of range (calrec_check_binding): family 1..4 (4 generic), product 1..0xFFFF, ...";
    }
    for (int a = 0; a < 3; a++) {
        r.acc_offset[a] = q(c.acc_offset[a], kQ16);
        r.acc_gain[a] = q(c.acc_gain[a], kQ30);
        for (int j = 0; j < 3; j++)
            r.acc_misalign[a][j] = q(c.acc_misalign[a][j], kQ30);
        for (int k = 0; k < 4; k++)
            r.acc_nonlin[a][k] = q(c.acc_nonlin[a][k], kQ30);
        put_tmodel(c.acc_tbias[a], kQ16, r.acc_tbias[a]);
        put_tmodel(c.acc_tscale[a], kQ30, r.acc_tscale[a]);
        r.gyro_offset[a] = q(c.gyro_offset[a], kQ16);
        r.gyro_scale[a] = q(c.gyro_scale[a], kQ30);
    }
    const int e = calrec_check(&r);
    if (e != INC_OK) {
        return std::string("the quantised record fails calrec_check (") + inc_err_name(e) + ")";
    }
    return "";
}

CalResult from_calrec(const struct calrec &r)
{
    CalResult c;
    for (int a = 0; a < 3; a++) {
        c.acc_offset[a] = r.acc_offset[a] / kQ16;
        c.acc_gain[a] = r.acc_gain[a] / kQ30;
        for (int j = 0; j < 3; j++)
            c.acc_misalign[a][j] = r.acc_misalign[a][j] / kQ30;
        for (int k = 0; k < 4; k++)
            c.acc_nonlin[a][k] = r.acc_nonlin[a][k] / kQ30;
        c.acc_tbias[a] = get_tmodel(r.acc_tbias[a], kQ16);
        c.acc_tscale[a] = get_tmodel(r.acc_tscale[a], kQ30);
        c.gyro_offset[a] = r.gyro_offset[a] / kQ16;
        c.gyro_scale[a] = r.gyro_scale[a] / kQ30;
    }
    return c;
}

std::string encode_record(const struct calrec &r, uint32_t seq, std::vector<uint8_t> &img)
{
    img.assign(CALREC_IMAGE_SIZE, 0);
    const int e = calrec_encode(&r, seq, img.data(), img.size());
    if (e != INC_OK) {
        img.clear();
        return std::string("calrec_encode failed (") + inc_err_name(e) + ")";
    }
    return "";
}

std::string firmware_check(const Station &st, const struct calrec &rec, FwCheck &out)
{
    out = FwCheck{};
    struct calrec r = rec;
    r.valid = true; // as calstore_load would hand it over
    const CalResult d = from_calrec(r);
    struct cal_acc acc;
    int e = cal_acc_init(&acc, &r, FX_Q16_INT(25));
    if (e != INC_OK) return std::string("firmware: cal_acc_init failed (") + inc_err_name(e) + ")";
    for (const auto &row : st.rows) {
        if (row.kind != RowKind::Acc) continue;
        const fx_q16_t t = q(row.temp_c, kQ16);
        e = cal_acc_set_temp(&acc, t);
        if (e != INC_OK)
            return std::string("firmware: cal_acc_set_temp failed at line ") +
                   std::to_string(row.line);
        fx_q16_t in[3], o[3];
        std::array<double, 3> rin{};
        for (int i = 0; i < 3; i++) {
            in[i] = q(row.v[i] * st.acc_lsb_g, kQ16);
            rin[i] = in[i] / kQ16;
        }
        e = cal_acc_apply(&acc, in, o);
        if (e != INC_OK)
            return std::string("firmware: cal_acc_apply failed at line ") +
                   std::to_string(row.line);
        const auto ref = apply_double(d, rin, t / kQ16);
        // A tilt-sweep row: one axis sees sin(theta) with 3 deg < |theta| <= 30 deg.
        bool within30 = false;
        for (int i = 0; i < 3; i++)
            within30 |= std::fabs(row.u[i]) > 0.05 && std::fabs(row.u[i]) <= 0.51;
        const double mag = std::sqrt(static_cast<double>(o[0]) * o[0] +
                                     static_cast<double>(o[1]) * o[1] +
                                     static_cast<double>(o[2]) * o[2]) /
                           kQ16;
        const double em = std::fabs(mag - 1.0) * 1e3;
        out.row_mag_mg.push_back((mag - 1.0) * 1e3);
        out.mag_max_mg = std::fmax(out.mag_max_mg, em);
        out.mag_rms_mg += em * em;
        for (int i = 0; i < 3; i++) {
            out.max_lsb = std::fmax(out.max_lsb, std::fabs(o[i] - ref[i] * kQ16));
            const double err = std::fabs(o[i] / kQ16 - row.u[i]) * 1e3;
            out.max_err_mg = std::fmax(out.max_err_mg, err);
            if (within30) out.max_tilt_err_mg = std::fmax(out.max_tilt_err_mg, err);
        }
        out.rows++;
    }
    if (out.rows) out.mag_rms_mg = std::sqrt(out.mag_rms_mg / static_cast<double>(out.rows));
    return "";
}

bool record_has_tmodel(const struct calrec &r)
{
    for (int a = 0; a < 3; a++) {
        if (r.acc_tbias[a].kind != CALREC_TM_NONE || r.acc_tscale[a].kind != CALREC_TM_NONE)
            return true;
    }
    return false;
}

std::string apply_firmware(const struct calrec &rec, const std::vector<std::array<double, 3>> &in_g,
                           const std::vector<double> &temp_c, double t_default,
                           std::vector<std::array<double, 3>> &out_g, size_t &range)
{
    out_g.assign(in_g.size(), {0.0, 0.0, 0.0});
    range = 0;
    struct calrec r = rec;
    r.valid = true;
    struct cal_acc acc;
    fx_q16_t t = q(temp_c.empty() ? t_default : temp_c[0], kQ16);
    int e = cal_acc_init(&acc, &r, t);
    if (e != INC_OK)
        return std::string("firmware: cal_acc_init refused the record (") + inc_err_name(e) + ")";
    for (size_t k = 0; k < in_g.size(); k++) {
        if (!temp_c.empty()) {
            const fx_q16_t tk = q(temp_c[k], kQ16);
            if (tk != t) {
                t = tk;
                e = cal_acc_set_temp(&acc, t);
                if (e != INC_OK)
                    return "firmware: cal_acc_set_temp refused sample " + std::to_string(k + 1) +
                           " at " + std::to_string(temp_c[k]) + " degC (" + inc_err_name(e) + ")";
            }
        }
        fx_q16_t in[3], o[3];
        for (int i = 0; i < 3; i++)
            in[i] = q(in_g[k][i], kQ16);
        e = cal_acc_apply(&acc, in, o);
        if (e == INC_ERR_RANGE) {
            range++;
        } else if (e != INC_OK) {
            return std::string("firmware: cal_acc_apply failed (") + inc_err_name(e) + ")";
        }
        for (int i = 0; i < 3; i++)
            out_g[k][i] = o[i] / kQ16;
    }
    return "";
}

} // namespace calstation
