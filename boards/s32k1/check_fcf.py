#!/usr/bin/env python3
"""check_fcf.py - the flash configuration field of a built S32K1 image (CTest image_fcf_*).

  check_fcf.py --bin IMAGE.bin [--hex IMAGE.hex] [--srec IMAGE.srec]

The .bin starts at flash address 0 (objcopy -O binary of an image whose first section is the
vector table at 0). Fails unless the 16 bytes at 0x400 are the unsecured field of
boards/s32k1/startup_s32k1.c: backdoor key, FPROT, FOPT, FEPROT, FDPROT 0xFF and FSEC 0xFE
(SEC = 10b unsecured; any other SEC value locks the part). The .hex and .srec, when given, must
hold the same 16 bytes at 0x400 (each output is checked, not assumed).
"""
import argparse
import sys

FCF_ADDR = 0x400
EXPECTED = bytes([0xFF] * 12 + [0xFE, 0xFF, 0xFF, 0xFF])


def from_hex(path):
    mem, base = {}, 0
    for line in open(path):
        line = line.strip()
        if not line.startswith(":"):
            continue
        raw = bytes.fromhex(line[1:])
        n, addr, kind, data = raw[0], (raw[1] << 8) | raw[2], raw[3], raw[4:4 + raw[0]]
        if kind == 0:
            for i in range(n):
                mem[base + addr + i] = data[i]
        elif kind == 4:
            base = ((data[0] << 8) | data[1]) << 16
        elif kind == 2:
            base = ((data[0] << 8) | data[1]) << 4
    return mem


def from_srec(path):
    mem = {}
    alen = {"1": 2, "2": 3, "3": 4}
    for line in open(path):
        line = line.strip()
        if len(line) < 4 or line[0] != "S" or line[1] not in alen:
            continue
        raw = bytes.fromhex(line[2:])
        a = alen[line[1]]
        addr = int.from_bytes(raw[1:1 + a], "big")
        data = raw[1 + a:-1]
        for i, b in enumerate(data):
            mem[addr + i] = b
    return mem


def check(name, field):
    if field != EXPECTED:
        got = " ".join("%02X" % b for b in field)
        print("%s: FCF at 0x400 is [%s], expected [%s]" % (
            name, got, " ".join("%02X" % b for b in EXPECTED)))
        if len(field) > 12 and field[12] & 0x03 != 0x02:
            print("%s: FSEC 0x%02X SECURES the part (SEC bits != 10b)" % (name, field[12]))
        return False
    print("%s: FCF ok (FSEC 0x%02X unsecured)" % (name, field[12]))
    return True


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", required=True)
    ap.add_argument("--hex")
    ap.add_argument("--srec")
    ap.add_argument("--selftest", action="store_true")
    a = ap.parse_args()
    ok = True
    data = open(a.bin, "rb").read()
    if len(data) < FCF_ADDR + 16:
        print("%s: only %d bytes, no FCF at 0x400" % (a.bin, len(data)))
        return 1
    ok &= check(a.bin, data[FCF_ADDR:FCF_ADDR + 16])
    for path, reader in ((a.hex, from_hex), (a.srec, from_srec)):
        if path:
            mem = reader(path)
            addrs = range(FCF_ADDR, FCF_ADDR + 16)
            field = bytes(mem[x] for x in addrs) if all(x in mem for x in addrs) else b""
            ok &= check(path, field)
    if a.selftest:
        # The check must be able to fail: the same image with FSEC = 0xFF (secured) is refused.
        bad = bytearray(data[FCF_ADDR:FCF_ADDR + 16])
        bad[12] = 0xFF
        if check("selftest (FSEC 0xFF)", bytes(bad)):
            print("selftest: a securing FSEC was accepted")
            ok = False
        else:
            print("selftest: a securing FSEC is refused, as it must be")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
