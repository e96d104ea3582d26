// dflash.hpp - a calibration record as the S32K1 data flash holds it, for the station's probe.
//
// The S32K1 images keep the record in the FlexNVM data flash through the calibration store
// (firmware/services/calstore_ftfc: two 2 KiB sectors from CALSTORE_FTFC_IMAGE_SECTOR, 8-byte
// phrases). dflash_image() runs the firmware's own calstore_save on an erased copy of those two
// sectors (the NOR emulation of sim/flash), so the bytes are the store's format exactly: slot 0
// holds the record, CRC and commit word, sequence number 1; slot 1 is erased (0xFF), so
// programming both sectors also wipes a record an earlier calibration left there. The writers
// give the two sectors at their address in the MCU's memory map (S32K_DFLASH_BASE + sector
// offset) as Motorola S-records (S3 data, S7 end) or Intel HEX (type 04 extended linear address,
// 00 data, 01 end), 32 data bytes a line, for the probe's flash tool (docs/boards.md,
// docs/calibration.md 4.6).
#ifndef INCLINO_CALSTATION_DFLASH_HPP
#define INCLINO_CALSTATION_DFLASH_HPP

#include "inclino/calrec.h"

#include <cstdint>
#include <string>
#include <vector>

namespace calstation
{

// The two sectors' bytes (2 x S32K_DFLASH_SECTOR) and the address of the first one in the
// memory map. "" or a message (calstore_save's refusal: binding, ranges).
std::string dflash_image(const struct calrec &rec, std::vector<uint8_t> &bytes, uint32_t &addr);

// The bytes at addr as S-record (srec) or Intel HEX (ihex) text. Throws nothing; the caller
// keeps bytes.size() + addr within 32 bits.
std::string to_srec(const std::vector<uint8_t> &bytes, uint32_t addr);
std::string to_ihex(const std::vector<uint8_t> &bytes, uint32_t addr);

} // namespace calstation

#endif
