#!/usr/bin/env python3
"""check_image.py - build checks of the cross targets, run as CTest tests (tests/build).

  check_image.py image --elf X.elf --map X.map --target T --nm NM --readelf RE --size SZ
      The image is well formed: no undefined symbol; the entry point is the reset code; on
      Cortex-M the vector table at the start of flash holds __stack_top__ and Reset_Handler; .data
      is loaded in FLASH and runs in RAM; the size report's totals match <prefix>size.

  check_image.py float --nm NM --objdump OD --target T [--elf X.elf] --archives A.a ...
      No floating point in freestanding code: no module references a soft-float helper of libgcc
      (__aeabi_fadd, __aeabi_d2iz, __addsf3, __floatsidf, ...), the image defines none, and no
      module contains an FPU instruction (VFP on the M4F: any v* mnemonic; F/D on RISC-V).

  check_image.py libc --nm NM --libgcc LIBGCC --archives A.a ...
      No C library: every symbol a module references is defined by a module or is an integer
      helper of libgcc (division, 64-bit shifts and multiplies). malloc, printf, strlen, ...
      anything else is reported with the module and object that references it.

  --expect-violation: invert (the checks' self-tests): pass only if violations are found.
Exit status 0 = pass, 1 = fail (the violations are listed).
"""
import argparse
import os
import re
import struct
import subprocess
import sys

FLOAT_HELPER = re.compile(
    r"^(__aeabi_(c?[fd][a-z0-9]*|u?[il]2[fd]|[fd]2.*|h2f.*|f2h.*)"
    r"|__gnu_(f2h|h2f|d2h).*"
    r"|__fix(uns)?(sf|df|tf|hf|xf).*"
    r"|__[a-z]+(sf|df|tf|hf|xf|sc|dc)[0-9]?)$")


def run(cmd):
    return subprocess.run(cmd, check=True, capture_output=True, text=True).stdout


def nm_archive(nm, archive):
    """[(member, symbol, type)] of an archive or object."""
    rows = []
    member = os.path.basename(archive)
    for line in run([nm, archive]).splitlines():
        if not line.strip():
            continue
        if line.endswith(":"):
            member = line[:-1]
            continue
        parts = line.split()
        if len(parts) == 2:          # "U symbol"
            rows.append((member, parts[1], parts[0]))
        elif len(parts) == 3:
            rows.append((member, parts[2], parts[1]))
    return rows


def module_name(archive):
    return re.sub(r"^lib", "", os.path.basename(archive)).rsplit(".a", 1)[0]


def check_float(args):
    bad = []
    for archive in args.archives:
        mod = module_name(archive)
        for member, sym, typ in nm_archive(args.nm, archive):
            if typ == "U" and FLOAT_HELPER.match(sym):
                bad.append(f"{mod} ({member}) calls the soft-float helper {sym}")
    if args.elf:
        for _m, sym, typ in nm_archive(args.nm, args.elf):
            if typ in "TtWw" and FLOAT_HELPER.match(sym):
                bad.append(f"{os.path.basename(args.elf)} links the soft-float helper {sym}")
    # FPU instructions: on the M4F (hard-float ABI) float code needs no helper at all. In Thumb
    # code every mnemonic that starts with "v" is VFP/SIMD; on RISC-V the F/D extensions'.
    if args.target.startswith("cortex-m"):
        fpu = re.compile(r"^v")
    else:
        fpu = re.compile(r"^f(l[wdq]|s[wdq]|add|sub|mul|div|sqrt|mv|cvt|sgnj|min|max|eq|lt|le|"
                         r"class|madd|msub|nmadd|nmsub|[rs]csr|[rs]rm|[rs]flags)")
    for path in list(args.archives) + ([args.elf] if args.elf else []):
        func = "?"
        for line in run([args.objdump, "-d", "--no-show-raw-insn", path]).splitlines():
            m = re.match(r"^[0-9a-f]+ <([^>]+)>:", line)
            if m:
                func = m.group(1)
                continue
            m = re.match(r"^\s*[0-9a-f]+:\s+(\S+)", line)
            if m and fpu.match(m.group(1)):
                bad.append(f"{os.path.basename(path)}: {func} uses the FPU: {line.strip()}")
    return bad


def check_libc(args):
    defined = set()
    undefined = []
    for archive in args.archives:
        mod = module_name(archive)
        for member, sym, typ in nm_archive(args.nm, archive):
            if typ == "U":
                undefined.append((mod, member, sym))
            elif typ not in "wv":
                defined.add(sym)
    libgcc = {sym for _m, sym, typ in nm_archive(args.nm, args.libgcc)
              if typ in "TtWw" and not FLOAT_HELPER.match(sym)}
    bad = []
    for mod, member, sym in undefined:
        if sym in defined or sym in libgcc:
            continue
        # The startup refers to main and to the linker script's __name__ symbols.
        if sym in ("main", "_GLOBAL_OFFSET_TABLE_", "__global_pointer$") or \
                re.match(r"^__[A-Za-z0-9_]+__$", sym):
            continue
        bad.append(f"{mod} ({member}) references {sym}, which no module defines "
                   "(a C library function?)")
    return bad


def elf_read(path):
    with open(path, "rb") as f:
        return f.read()


def elf_section(data, name):
    """(addr, bytes) of a section of a little-endian ELF32 file."""
    e_shoff, = struct.unpack_from("<I", data, 0x20)
    e_shentsize, e_shnum, e_shstrndx = struct.unpack_from("<HHH", data, 0x2E)
    def hdr(i):
        return struct.unpack_from("<IIIIIIIIII", data, e_shoff + i * e_shentsize)
    strtab = hdr(e_shstrndx)
    for i in range(e_shnum):
        h = hdr(i)
        n = data[strtab[4] + h[0]:].split(b"\0", 1)[0].decode()
        if n == name:
            return h[3], data[h[4]:h[4] + h[5]]
    return None, None


def check_image(args):
    bad = []
    undefined = [s for _m, s, t in nm_archive(args.nm, args.elf) if t == "U"]
    if undefined:
        bad.append("undefined symbols: " + ", ".join(undefined))
    symbols = {s: t for _m, s, t in nm_archive(args.nm, args.elf)}
    addr = {}
    for line in run([args.nm, "--defined-only", args.elf]).splitlines():
        parts = line.split()
        if len(parts) == 3:
            addr[parts[2]] = int(parts[0], 16)
    header = run([args.readelf, "-h", args.elf])
    entry = int(re.search(r"Entry point address:\s+0x([0-9a-f]+)", header).group(1), 16)
    regions = {}
    with open(args.map, encoding="utf-8", errors="replace") as f:
        for line in f:
            m = re.match(r"^(FLASH|RAM)\s+0x([0-9a-f]+)\s+0x([0-9a-f]+)", line)
            if m:
                regions[m.group(1)] = (int(m.group(2), 16), int(m.group(3), 16))
    if set(regions) != {"FLASH", "RAM"}:
        return bad + ["map file: memory regions FLASH and RAM not found"]

    def inside(region, a):
        o, l = regions[region]
        return o <= a <= o + l

    data = elf_read(args.elf)
    if args.target.startswith("cortex-m"):
        reset = addr.get("Reset_Handler")
        if reset is None or entry != (reset | 1):
            bad.append(f"entry point 0x{entry:x} is not Reset_Handler")
        vaddr, vec = elf_section(data, ".isr_vector")
        if vaddr != regions["FLASH"][0]:
            bad.append(f".isr_vector not at the start of flash (0x{vaddr or 0:x})")
        elif len(vec) < 8:
            bad.append(".isr_vector is too short")
        else:
            sp, rv = struct.unpack_from("<II", vec, 0)
            if sp != addr.get("__stack_top__"):
                bad.append(f"vector 0 (initial sp) 0x{sp:x} != __stack_top__")
            if reset is None or rv != (reset | 1):
                bad.append(f"vector 1 0x{rv:x} != Reset_Handler | 1 (Thumb)")
            if sp % 8:
                bad.append("initial sp is not 8-byte aligned (AAPCS)")
    else:
        if entry != addr.get("_start") or entry != regions["FLASH"][0]:
            bad.append(f"entry point 0x{entry:x} is not _start at the start of flash")
    for sym, region in (("__data_load__", "FLASH"), ("__data_start__", "RAM"),
                        ("__bss_end__", "RAM"), ("__stack_top__", "RAM")):
        if sym not in addr:
            bad.append(f"symbol {sym} missing")
        elif not inside(region, addr[sym]):
            bad.append(f"{sym} = 0x{addr[sym]:x} is outside {region}")
    if "main" not in symbols and not any(s.startswith("main.") for s in symbols):
        bad.append("no main")  # main.isra.0 etc.: gcc's clone of it in an LTO image
    out = os.path.join(os.path.dirname(os.path.abspath(args.map)),
                       os.path.basename(args.elf) + ".check-size.txt")
    here = os.path.dirname(os.path.abspath(__file__))
    r = subprocess.run([sys.executable, os.path.join(here, "size_report.py"), "--map", args.map,
                        "--elf", args.elf, "--size", args.size, "--readelf", args.readelf,
                        "--target", args.target, "--out", out], capture_output=True, text=True)
    if r.returncode != 0:
        bad.append("size report: " + (r.stderr or r.stdout).strip())
    return bad


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("mode", choices=["image", "float", "libc"])
    ap.add_argument("--elf")
    ap.add_argument("--map")
    ap.add_argument("--target", default="")
    ap.add_argument("--nm", required=True)
    ap.add_argument("--objdump")
    ap.add_argument("--readelf")
    ap.add_argument("--size")
    ap.add_argument("--libgcc")
    ap.add_argument("--archives", nargs="*", default=[])
    ap.add_argument("--expect-violation", action="store_true")
    args = ap.parse_args()
    # CTest passes a generator expression's list ($<TARGET_OBJECTS:...>) as one ;-joined argument.
    args.archives = [p for a in args.archives for p in a.split(";") if p]

    bad = {"image": check_image, "float": check_float, "libc": check_libc}[args.mode](args)
    for b in bad:
        print(("found (expected): " if args.expect_violation else "FAIL: ") + b)
    if args.expect_violation:
        if not bad:
            print(f"FAIL: the {args.mode} check found nothing in code made to violate it")
            return 1
        return 0
    if not bad:
        what = {"image": f"{os.path.basename(args.elf or '')} is well formed",
                "float": f"no floating point in {len(args.archives)} archives",
                "libc": f"no C library symbol referenced by {len(args.archives)} archives"}
        print("OK: " + what[args.mode])
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
