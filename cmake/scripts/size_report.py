#!/usr/bin/env python3
"""size_report.py - text/data/bss per module of a cross-linked ELF, from the GNU ld map file.

Run after every cross link (cmake/inclino_cross.cmake). Every input section in the map is
charged to the module it came from:
  inclino_<m>   an object of the static library libinclino_<m>.a (one per module)
  startup       the image startup objects (hal/rt, target inclino_rt_startup)
  board         the QEMU test board objects (boards/qemu)
  libgcc, libc, ... other archives by name; <target> for the executable's own objects
  stack         the stack reserved by the linker script (.stack)
  (fill/align)  padding the linker inserted between input sections
In an image linked with link-time optimisation (-flto) the code and data come from the
link-time objects (*.ltrans*.o), not from a module's object: each such input section
(-ffunction-sections -fdata-sections: one per function or object, named after it) is charged to
the module whose archive (or the executable's own object) defines a symbol of that name, gcc's
suffixes (.constprop.0, .isra.0, .part.0, .lto_priv.0) stripped. The symbol tables are read
with readelf from the LOAD lines' inputs: for a module's link-time twin (<m>_lto, IR only) the
module's own archive, for the executable's own objects their machine code (-ffat-lto-objects).
What matches no module or several (merged constants, a static name two modules define) is its
own line, "(lto: unattributed)".
An output section counts as text when allocated and read-only, data when allocated, writable
and loaded, bss when allocated and not loaded (NOBITS): the rules of berkeley `size`. The totals
are cross-checked against `<prefix>size`; a mismatch fails the script (and the build).

Usage: size_report.py --map X.map --elf X.elf --size SIZE --readelf READELF --target T
                      --out X.size.txt [--print]
"""
import argparse
import glob
import os
import re
import subprocess
import sys

SHF_WRITE = 0x1
SHF_ALLOC = 0x2


def elf_sections(readelf, elf):
    """{name: (type, flags, size)} of the ELF's sections, from readelf -SW."""
    out = subprocess.run([readelf, "-SW", elf], check=True, capture_output=True,
                         text=True).stdout
    sections = {}
    rx = re.compile(r"^\s*\[\s*\d+\]\s+(\S+)\s+(\S+)\s+([0-9a-f]+)\s+([0-9a-f]+)\s+"
                    r"([0-9a-f]+)\s+([0-9a-f]+)\s+(\S*)\s+")
    for line in out.splitlines():
        m = rx.match(line)
        if not m or m.group(1) == "NULL":
            continue
        name, typ, size, flags = m.group(1), m.group(2), int(m.group(5), 16), m.group(7)
        f = 0
        if "W" in flags:
            f |= SHF_WRITE
        if "A" in flags:
            f |= SHF_ALLOC
        sections[name] = (typ, f, size)
    return sections


def berkeley(size_tool, elf):
    out = subprocess.run([size_tool, "-B", elf], check=True, capture_output=True,
                         text=True).stdout.splitlines()
    text, data, bss = (int(x) for x in out[1].split()[:3])
    return text, data, bss


def module_of(path, target):
    """The module an input file belongs to (see the docstring)."""
    m = re.match(r"^(.*?)\((.*)\)$", path)
    if m:
        archive = os.path.basename(m.group(1))
        name = re.sub(r"^lib", "", re.sub(r"\.a$", "", archive))
        if name.startswith("inclino_"):
            return re.sub(r"_lto$", "", name)  # a module's link-time twin counts as the module
        if name in ("gcc", "c", "c_nano", "m", "g_nano", "nosys", "rdimon", "rdimon_nano"):
            return {"c_nano": "libc", "g_nano": "libc", "rdimon_nano": "librdimon",
                    "rdimon": "librdimon"}.get(name, "lib" + name)
        return "lib" + name
    if "inclino_rt_startup.dir" in path:
        return "startup"
    if "inclino_qemu_board.dir" in path:
        return "board"
    if re.search(r"crt[a-z0-9]*\.o$", path):
        return "crt"
    m = re.search(r"CMakeFiles/([^/]+)\.dir/", path)
    if m:
        return m.group(1)
    return "(linker)"


LTO_UNATTRIBUTED = "(lto: unattributed)"


def is_lto_unit(path):
    return re.search(r"\.ltrans[0-9]*\.ltrans\.o$|\.ltrans[0-9]+\.o$", path) is not None


def original_archive(twin):
    """The module archive lib<m>.a of the build tree whose twin is lib<m>_lto.a (None if none)."""
    want = os.path.basename(twin)[:-len("_lto.a")] + ".a"
    root = os.path.dirname(twin)
    while root != os.path.dirname(root) and not os.path.exists(os.path.join(root,
                                                                            "CMakeCache.txt")):
        root = os.path.dirname(root)
    hits = glob.glob(os.path.join(root, "**", want), recursive=True)
    return hits[0] if len(hits) == 1 else None


def defining_modules(readelf, map_path, target):
    """{symbol: set of modules} of the module archives and objects in the map's LOAD lines."""
    base = os.path.dirname(os.path.abspath(map_path))
    table = {}
    with open(map_path, encoding="utf-8", errors="replace") as f:
        loads = [m.group(1) for m in re.finditer(r"^LOAD (.+)$", f.read(), re.M)]
    for path in loads:
        if path == "linker stubs" or is_lto_unit(path):
            continue
        full = path if os.path.isabs(path) else os.path.normpath(os.path.join(base, path))
        if not os.path.exists(full):
            continue
        if full.endswith("_lto.a"):
            # a module's link-time twin (cmake/inclino_cross.cmake) holds IR only: the symbols
            # are read from the module's own archive, the same sources compiled to machine code
            full = original_archive(full)
            if full is None:
                continue
        mod = module_of(full + "(x)" if full.endswith(".a") else full, target)
        if not (mod.startswith("inclino_") or mod == "startup" or mod == target):
            continue
        # readelf, not nm: nm reads an LTO object's IR symbol table through the LTO plugin,
        # which lists no static function or object; the fat object's ELF table has them all.
        out = subprocess.run([readelf, "-sW", full], capture_output=True, text=True).stdout
        for line in out.splitlines():
            parts = line.split()
            if (len(parts) == 8 and parts[3] in ("FUNC", "OBJECT") and parts[6] != "UND"):
                table.setdefault(parts[7].split(".", 1)[0], set()).add(mod)
    return table


def lto_module(section, table):
    """The module of an input section of a link-time object, from the symbol in its name."""
    parts = section.split(".")[2:] if section.count(".") >= 2 else []
    for part in parts:
        mods = table.get(part)
        if mods:
            return next(iter(mods)) if len(mods) == 1 else LTO_UNATTRIBUTED
    return LTO_UNATTRIBUTED


def parse_map(path):
    """Memory regions and, per output section, its size and the input sections in it."""
    with open(path, encoding="utf-8", errors="replace") as f:
        lines = f.read().splitlines()

    regions = {}
    i = 0
    while i < len(lines) and lines[i].strip() != "Memory Configuration":
        i += 1
    for line in lines[i + 1:]:
        if line.startswith("Linker script and memory map"):
            break
        m = re.match(r"^(\S+)\s+0x([0-9a-f]+)\s+0x([0-9a-f]+)", line)
        if m and m.group(1) != "*default*" and m.group(1) != "Name":
            regions[m.group(1)] = (int(m.group(2), 16), int(m.group(3), 16))

    while i < len(lines) and not lines[i].startswith("Linker script and memory map"):
        i += 1

    outputs = {}  # name -> {"addr": a, "size": n, "inputs": [(file, addr, size)]}
    current = None
    pending_out = None
    pending_in = None
    addr_size = re.compile(r"^\s+0x([0-9a-f]+)\s+0x([0-9a-f]+)(?:\s+(.*))?$")
    for line in lines[i + 1:]:
        if not line.strip():
            continue
        if pending_out is not None:
            m = addr_size.match(line)
            pending, pending_out = pending_out, None
            if m:
                outputs[pending] = {"addr": int(m.group(1), 16), "size": int(m.group(2), 16),
                                    "inputs": []}
                current = pending
                continue
        if pending_in is not None:
            m = addr_size.match(line)
            pending, pending_in = pending_in, None
            if m and m.group(3) and current is not None:
                outputs[current]["inputs"].append((m.group(3).strip(), int(m.group(1), 16),
                                                   int(m.group(2), 16), pending))
                continue
        if line[0] != " ":
            # Column 0: an output section (".text  0xaddr  0xsize"), possibly wrapped.
            m = re.match(r"^(\.\S+|/DISCARD/)\s+0x([0-9a-f]+)\s+0x([0-9a-f]+)", line)
            if m:
                outputs[m.group(1)] = {"addr": int(m.group(2), 16), "size": int(m.group(3), 16),
                                       "inputs": []}
                current = m.group(1)
                continue
            m = re.match(r"^(\.\S+)\s*$", line)
            if m:
                pending_out = m.group(1)
                continue
            current = None  # LOAD, OUTPUT(...), START GROUP, ...
            continue
        if current is None:
            continue
        m = re.match(r"^ \*fill\*\s+0x([0-9a-f]+)\s+0x([0-9a-f]+)", line)
        if m:
            continue  # padding: whatever no input section covers is charged to (fill/align)
        m = re.match(r"^ ((?:\.|COMMON)\S*)\s+0x([0-9a-f]+)\s+0x([0-9a-f]+)\s+(.*)$", line)
        if m:
            outputs[current]["inputs"].append((m.group(4).strip(), int(m.group(2), 16),
                                               int(m.group(3), 16), m.group(1)))
            continue
        m = re.match(r"^ ((?:\.|COMMON)\S*)\s*$", line)
        if m:
            pending_in = m.group(1)
            continue
    return regions, outputs


def fmt_kib(n):
    return f"{n / 1024:.1f} KiB"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--map", required=True)
    ap.add_argument("--elf", required=True)
    ap.add_argument("--size", required=True, help="the target's size tool")
    ap.add_argument("--readelf", required=True)
    ap.add_argument("--target", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--print", action="store_true", help="also print the report")
    args = ap.parse_args()

    name = os.path.splitext(os.path.basename(args.elf))[0]
    sections = elf_sections(args.readelf, args.elf)
    regions, outputs = parse_map(args.map)

    lto_table = None
    if any(is_lto_unit(e[0]) for o in outputs.values() for e in o["inputs"]):
        lto_table = defining_modules(args.readelf, args.map, name)

    rows = {}  # module -> [text, data, bss]
    totals = [0, 0, 0]
    for sec, info in outputs.items():
        if sec not in sections:
            continue  # discarded, empty, or not in the ELF
        typ, flags, elf_size = sections[sec]
        if not flags & SHF_ALLOC:
            continue
        if elf_size != info["size"]:
            sys.exit(f"size_report: {sec} is {info['size']} bytes in the map but {elf_size} "
                     f"in the ELF")
        if typ == "NOBITS":
            col = 2
        elif flags & SHF_WRITE:
            col = 1
        else:
            col = 0
        # Charge every byte of the output section to the first input section covering it.
        # Merged string sections (.rodata.str1.1) overlap in the map, so sizes cannot simply
        # be added; bytes no input covers are padding.
        accounted = 0
        start, end = info["addr"], info["addr"] + info["size"]
        covered = start
        for path, addr, size, insec in sorted(info["inputs"], key=lambda e: (e[1], -e[2])):
            lo = max(addr, covered)
            hi = min(addr + size, end)
            if hi > lo:
                if lto_table is not None and is_lto_unit(path):
                    mod = lto_module(insec, lto_table)
                else:
                    mod = module_of(path, name)
                rows.setdefault(mod, [0, 0, 0])[col] += hi - lo
                accounted += hi - lo
                covered = hi
        rest = info["size"] - accounted
        if rest:
            mod = "stack" if sec == ".stack" else "(fill/align)"
            rows.setdefault(mod, [0, 0, 0])[col] += rest
        totals[col] += info["size"]

    ref = berkeley(args.size, args.elf)
    if tuple(totals) != ref:
        sys.exit(f"size_report: {name}: map gives text/data/bss {totals}, "
                 f"{os.path.basename(args.size)} gives {list(ref)}")

    def order(item):
        mod = item[0]
        rank = 0 if mod.startswith("inclino_") else 2 if mod in ("stack", "(fill/align)") else 1
        return (rank, mod)

    lines = [f"Size report: {name} ({args.target})",
             f"{'module':<28}{'text':>9}{'data':>9}{'bss':>9}{'total':>9}"]
    for mod, (t, d, b) in sorted(rows.items(), key=order):
        if t or d or b:
            lines.append(f"{mod:<28}{t:>9}{d:>9}{b:>9}{t + d + b:>9}")
    lines.append(f"{'total':<28}{totals[0]:>9}{totals[1]:>9}{totals[2]:>9}{sum(totals):>9}")
    lines.append(f"cross-check: {os.path.basename(args.size)} -B gives text {ref[0]}, "
                 f"data {ref[1]}, bss {ref[2]}: matches")
    flash_used = totals[0] + totals[1]
    ram_used = totals[1] + totals[2]
    for region, used in (("FLASH", flash_used), ("RAM", ram_used)):
        if region in regions:
            origin, length = regions[region]
            lines.append(f"{region:<6} {used:>8} of {length:>8} bytes "
                         f"({100.0 * used / length:5.1f} %, {fmt_kib(used)} of "
                         f"{fmt_kib(length)} at 0x{origin:08x})")
    lines.append("text = code + read-only data + vectors; flash = text + data (load image);"
                 " RAM = data + bss (bss includes the reserved stack).")
    report = "\n".join(lines) + "\n"
    with open(args.out, "w", encoding="utf-8") as f:
        f.write(report)
    if args.print:
        sys.stdout.write(report)


if __name__ == "__main__":
    main()
