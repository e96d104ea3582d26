// dflash.cpp - see dflash.hpp.
#include "inclino/calstation/dflash.hpp"

extern "C" {
#include "inclino/calstore.h"
#include "inclino/calstore_ftfc.h"
#include "inclino/error.h"
#include "inclino/s32k_ftfc.h"
#include "inclino/simflash.h"
}

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <numeric>

namespace calstation
{

namespace
{

constexpr uint32_t kSpan = 2u * S32K_DFLASH_SECTOR;
constexpr size_t kLine = 32u; // data bytes per output line

uint8_t sum_bytes(const std::vector<uint8_t> &v)
{
    return static_cast<uint8_t>(std::accumulate(v.begin(), v.end(), 0u));
}

std::string hex_line(const char *lead, const std::vector<uint8_t> &v, uint8_t check)
{
    std::string s = lead;
    char b[3];
    for (uint8_t x : v) {
        std::snprintf(b, sizeof b, "%02X", x);
        s += b;
    }
    std::snprintf(b, sizeof b, "%02X", check);
    return s + b + "\n";
}

} // namespace

std::string dflash_image(const struct calrec &rec, std::vector<uint8_t> &bytes, uint32_t &addr)
{
    static uint8_t mem[kSpan]; // the two sectors, as a NOR flash (sim/flash)
    static simflash flash;
    static calstore st; // about 700 bytes: off the stack
    const simflash_geometry geo = {S32K_DFLASH_SECTOR, 2u, S32K_FTFC_PHRASE};
    calstore_config cfg{};
    calstore_info info{};
    int err = simflash_init(&flash, mem, sizeof mem, &geo); // erased: 0xFF
    if (err == INC_OK) err = simflash_calstore_config(&flash, &cfg);
    if (err == INC_OK) err = calstore_init(&st, &cfg);
    if (err == INC_OK) err = calstore_save(&st, &rec, &info);
    if (err != INC_OK) {
        return std::string("calstore_save refused the record (") + inc_err_name(err) + ")";
    }
    if (info.used_slot != 0 || info.seq != 1u) {
        return "calstore_save did not write slot 0 with sequence number 1";
    }
    bytes.assign(mem, mem + kSpan);
    addr = S32K_DFLASH_BASE + CALSTORE_FTFC_IMAGE_SECTOR * S32K_DFLASH_SECTOR;
    return "";
}

std::string to_srec(const std::vector<uint8_t> &bytes, uint32_t addr)
{
    // S0 header: count (2 address bytes + the text + the checksum), address 0, the text
    const std::vector<uint8_t> text = {'c', 'a', 'l', 'r', 'e', 'c'};
    std::vector<uint8_t> hdr = {static_cast<uint8_t>(text.size() + 3u), 0x00, 0x00};
    hdr.insert(hdr.end(), text.begin(), text.end());
    std::string out = hex_line("S0", hdr, static_cast<uint8_t>(~sum_bytes(hdr)));
    for (size_t off = 0; off < bytes.size(); off += kLine) {
        const size_t n = std::min(kLine, bytes.size() - off);
        const uint32_t a = addr + static_cast<uint32_t>(off);
        std::vector<uint8_t> rec = {static_cast<uint8_t>(n + 5u), static_cast<uint8_t>(a >> 24),
                                    static_cast<uint8_t>(a >> 16), static_cast<uint8_t>(a >> 8),
                                    static_cast<uint8_t>(a)};
        rec.insert(rec.end(), bytes.begin() + static_cast<long>(off),
                   bytes.begin() + static_cast<long>(off + n));
        out += hex_line("S3", rec, static_cast<uint8_t>(~sum_bytes(rec)));
    }
    // S7: end, the start address field is the first data address (no code to run here)
    const std::vector<uint8_t> end = {5, static_cast<uint8_t>(addr >> 24),
                                      static_cast<uint8_t>(addr >> 16),
                                      static_cast<uint8_t>(addr >> 8), static_cast<uint8_t>(addr)};
    return out + hex_line("S7", end, static_cast<uint8_t>(~sum_bytes(end)));
}

std::string to_ihex(const std::vector<uint8_t> &bytes, uint32_t addr)
{
    std::string out;
    uint32_t upper = 0xFFFFFFFFu;
    for (size_t off = 0; off < bytes.size();) {
        const uint32_t a = addr + static_cast<uint32_t>(off);
        if ((a >> 16) != upper) {
            upper = a >> 16;
            const std::vector<uint8_t> ela = {
                2, 0, 0, 4, static_cast<uint8_t>(upper >> 8), static_cast<uint8_t>(upper)};
            out += hex_line(":", ela, static_cast<uint8_t>(-sum_bytes(ela)));
        }
        // a line never crosses a 64 KiB boundary (its 16-bit offset would wrap)
        size_t n = std::min(kLine, bytes.size() - off);
        n = std::min<size_t>(n, 0x10000u - (a & 0xFFFFu));
        std::vector<uint8_t> rec = {static_cast<uint8_t>(n), static_cast<uint8_t>(a >> 8),
                                    static_cast<uint8_t>(a), 0};
        rec.insert(rec.end(), bytes.begin() + static_cast<long>(off),
                   bytes.begin() + static_cast<long>(off + n));
        out += hex_line(":", rec, static_cast<uint8_t>(-sum_bytes(rec)));
        off += n;
    }
    const std::vector<uint8_t> end = {0, 0, 0, 1};
    return out + hex_line(":", end, static_cast<uint8_t>(-sum_bytes(end)));
}

} // namespace calstation
