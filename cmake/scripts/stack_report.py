#!/usr/bin/env python3
"""stack_report.py - stack use of a cross-linked image, from gcc's -fstack-usage and
-fcallgraph-info=su output.

Every freestanding module (and the image startup) is compiled with -fstack-usage
-fcallgraph-info=su (cmake/inclino_cross.cmake), so gcc writes next to each object a .su file
(frame size per function: static, dynamic, or dynamic,bounded) and a .ci file (the call graph
of that translation unit, in VCG). This script finds the objects the linker used (LOAD lines of
the map file; for an archive, the objects of its CMake target directory), keeps the functions
present in the ELF, and reports:
  - the largest frames;
  - the worst-case stack depth from main() and from Reset_Handler/_start, with the path, and of
    each interrupt handler, and an estimate for the whole image: reset path + deepest handler +
    the hardware exception frame (Cortex-M: 32 bytes; 104 with an FPU context on the M4F).
Limits, stated in the report: calls through function pointers (the HAL ops table, callbacks)
are not followed - each is listed as an indirect call of its caller; recursion is reported and
cut; functions without stack information (libgcc, assembly) count as 0 bytes and are listed.

With --indirect FILE (a board's list of what its calls through function pointers reach: lines
"caller: callee callee ...", '#' comments), the report gives the depth a second time with those
edges added, and names every function of the image that calls through a pointer and is not in
the list (its pointer calls then still count as 0).

With --lto PREFIX (an image linked with link-time optimisation, -flto-partition=one): the code
is the link-time unit's, so its PREFIX.su/.ci (written at link time, cmake/inclino_cross.cmake)
replace the objects' files, and only the objects linked as machine code (compiled -fno-lto:
mem.c, ...) are read besides. gcc's clone and local suffixes (.constprop.0, .isra.0, .part.0,
.lto_priv.0) are kept in the names shown; the ELF and --indirect are matched on the name
without them (a C name has no dot), every clone of a listed callee counting.

Usage: stack_report.py --map X.map --elf X.elf --nm NM --target T --out X.stack.txt [--print]
       [--indirect FILE] [--lto PREFIX]
"""
import argparse
import glob
import os
import re
import subprocess
import sys

INDIRECT = "__indirect_call"


def base_name(name):
    """A function's C name without gcc's suffixes (foo.constprop.0, foo.lto_priv.1 -> foo)."""
    return name.split(".", 1)[0]


def load_objects(map_path):
    """Object files the link used, with the .ci/.su prefix (path without its last extension)."""
    base = os.path.dirname(os.path.abspath(map_path))
    prefixes = []
    with open(map_path, encoding="utf-8", errors="replace") as f:
        for line in f:
            m = re.match(r"^LOAD (.+)$", line.rstrip("\n"))
            if not m or m.group(1) == "linker stubs":
                continue
            path = m.group(1)
            if not os.path.isabs(path):
                path = os.path.normpath(os.path.join(base, path))
            if path.endswith(".a"):
                lib = re.sub(r"^lib", "", os.path.basename(path)[:-2])
                tdir = os.path.join(os.path.dirname(path), "CMakeFiles", lib + ".dir")
                for ci in glob.glob(os.path.join(tdir, "**", "*.ci"), recursive=True):
                    prefixes.append(ci[:-3])
            else:
                prefixes.append(os.path.splitext(path)[0])
    return sorted(set(prefixes))


def machine_code_objects(map_path, prefixes):
    """Of prefixes, those whose object gave the link machine code (a non-empty input section in
    the memory map): in an LTO link the objects compiled -fno-lto, not the link-time ones."""
    used = set()
    with open(map_path, encoding="utf-8", errors="replace") as f:
        text = f.read()
    text = text.split("Linker script and memory map", 1)[-1]
    for m in re.finditer(r"^\s+(?:\S+\s+)?0x[0-9a-f]+\s+0x([0-9a-f]+)\s+(\S+)$", text, re.M):
        if int(m.group(1), 16) == 0:
            continue
        am = re.match(r"^.*\((.+)\)$", m.group(2))
        used.add(os.path.basename(am.group(1) if am else m.group(2)))
    out = []
    for prefix in prefixes:
        if os.path.basename(prefix) + ".obj" in used or os.path.basename(prefix) + ".o" in used:
            out.append(prefix)
    return out


def module_of(prefix):
    m = re.search(r"CMakeFiles/([^/]+)\.dir/", prefix)
    if not m:
        return "?"
    name = m.group(1)
    return "startup" if name == "inclino_rt_startup" else name


def parse_ci(path):
    """Nodes {title: (name, bytes, qualifier, location)} and edges [(src, dst)] of one .ci."""
    nodes, edges = {}, []
    node_rx = re.compile(r'^node: \{ title: "([^"]+)" label: "([^"]*)"')
    edge_rx = re.compile(r'^edge: \{ sourcename: "([^"]+)" targetname: "([^"]+)"')
    with open(path, encoding="utf-8", errors="replace") as f:
        for line in f:
            m = node_rx.match(line)
            if m:
                parts = m.group(2).split("\\n")
                size, qual, loc = None, None, parts[1] if len(parts) > 1 else ""
                if len(parts) > 2:
                    sm = re.match(r"(\d+) bytes \(([^)]*)\)", parts[2])
                    if sm:
                        size, qual = int(sm.group(1)), sm.group(2)
                nodes[m.group(1)] = (parts[0], size, qual, loc)
                continue
            m = edge_rx.match(line)
            if m:
                edges.append((m.group(1), m.group(2)))
    return nodes, edges


def elf_functions(nm, elf):
    out = subprocess.run([nm, "--defined-only", elf], check=True, capture_output=True,
                         text=True).stdout
    names = set()
    for line in out.splitlines():
        parts = line.split()
        if len(parts) == 3 and parts[1] in "TtWw":
            names.add(parts[2])
    return names


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--map", required=True)
    ap.add_argument("--elf", required=True)
    ap.add_argument("--nm", required=True)
    ap.add_argument("--target", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--print", action="store_true")
    ap.add_argument("--top", type=int, default=10)
    ap.add_argument("--indirect", help="caller: callees ... reached through function pointers")
    ap.add_argument("--lto", help="prefix of the link-time unit's .su/.ci (LTO image)")
    ap.add_argument("--limit", type=int, help="with --indirect: exit 1 when the worst case "
                    "exceeds this many bytes (the image's reserved stack), or when a pointer call "
                    "of the image is not in the list")
    args = ap.parse_args()

    image = os.path.splitext(os.path.basename(args.elf))[0]
    in_elf = elf_functions(args.nm, args.elf)
    if args.lto:
        in_elf |= {base_name(n) for n in in_elf}

    # Functions with stack information, keyed by .ci title (plain name, or "file:name" for static
    # functions, which gcc qualifies so that equal names in two files stay apart).
    funcs = {}     # title -> dict(name, size, qual, module, file)
    calls = {}     # title -> list of callee titles (as written in the .ci)
    objects = load_objects(args.map)
    units = [(p, module_of(p)) for p in objects]
    if args.lto:
        if not os.path.exists(args.lto + ".ci"):
            sys.exit(f"stack_report.py: {args.lto}.ci not found (link-time unit)")
        # The module of a function of the link-time unit: the one whose object's .ci has a
        # function defined in the same source file.
        module_of_file = {}
        for prefix, mod in units:
            if os.path.exists(prefix + ".ci"):
                for _t, (_n, _s, _q, loc) in parse_ci(prefix + ".ci")[0].items():
                    module_of_file.setdefault(loc.rsplit(":", 2)[0], mod)
        # the objects of the modules' link-time twins (<module>_lto, cmake/inclino_cross.cmake)
        # have no .ci: their module from the object's path (CMakeFiles/<module>_lto.dir/<source>.obj)
        twin_sources = []
        mapdir = os.path.dirname(os.path.abspath(args.map))
        with open(args.map, encoding="utf-8", errors="replace") as f:
            maptext = f.read()
        loads = re.findall(r"^LOAD (\S+_lto\.a)$", maptext, re.M)
        # and the image's own objects (link-time code as well)
        for m in re.finditer(r"^LOAD \S*CMakeFiles/([^/]+)\.dir/(\S+)\.obj$", maptext, re.M):
            twin_sources.append((m.group(2).replace("__/", ""), m.group(1)))
        for path in loads:
            path = os.path.normpath(os.path.join(mapdir, path))
            lib = re.sub(r"^lib", "", os.path.basename(path)[:-2])
            tdir = os.path.join(os.path.dirname(path), "CMakeFiles", lib + ".dir")
            for obj in glob.glob(os.path.join(tdir, "**", "*.c.obj"), recursive=True):
                rel = os.path.relpath(obj, tdir)[:-len(".obj")].replace("__/", "")
                twin_sources.append((rel, lib[:-len("_lto")]))

        def module_of_source(src):
            if src in module_of_file:
                return module_of_file[src]
            hits = {mod for rel, mod in twin_sources if src.endswith("/" + rel)}
            return hits.pop() if len(hits) == 1 else "?"
        units = [(p, m) for p, m in units if p in machine_code_objects(args.map, objects)]
        units.insert(0, (args.lto, None))
    for prefix, mod in units:
        ci = prefix + ".ci"
        if not os.path.exists(ci):
            continue
        nodes, edges = parse_ci(ci)
        for title, (name, size, qual, loc) in nodes.items():
            if mod is None:  # the link-time unit: the name with its suffix, from the title
                name = title.rsplit(":", 1)[-1]
            if size is None or name not in in_elf:
                continue
            src = loc.rsplit(":", 2)[0]
            funcs[title] = {"name": name, "size": size, "qual": qual, "file": src,
                            "module": mod if mod is not None else module_of_source(src)}
        for src, dst in edges:
            calls.setdefault(src, []).append(dst)

    by_name = {}   # name, and in an LTO image the name without suffix -> titles
    for title, f in sorted(funcs.items()):
        by_name.setdefault(f["name"], []).append(title)
        if args.lto and base_name(f["name"]) != f["name"]:
            by_name.setdefault(base_name(f["name"]), []).append(title)

    def resolve_all(title):
        if title in funcs:
            return [title]
        name = title.rsplit(":", 1)[-1]
        hits = by_name.get(name, [])
        if not hits and args.lto:
            # a clone the link-time unit gave no node (its code folded into an identical one,
            # e.g. fx_add.lto_priv.2 at the address of fx_add.lto_priv.0): the largest frame of
            # that name, conservatively
            hits = sorted(by_name.get(base_name(name), []), key=lambda t: -funcs[t]["size"])
        return hits

    def resolve(title):
        hits = resolve_all(title)
        return hits[0] if hits else None

    unknown = set()
    recursion = set()
    memo = {}

    def depth(title, stack):
        """(bytes, path, indirect callers on the path) of the deepest chain from title."""
        if title in memo:
            return memo[title]
        if title in stack:
            recursion.add(funcs[title]["name"])
            return (0, [], [])
        stack.add(title)
        best = (0, [], [])
        indirect = False
        for callee in calls.get(title, []):
            if callee == INDIRECT:
                indirect = True
                continue
            r = resolve(callee)
            if r is None:
                unknown.add(callee.rsplit(":", 1)[-1])
                continue
            d = depth(r, stack)
            if (d[0], len(d[1])) > (best[0], len(best[1])):
                best = d
        stack.discard(title)
        f = funcs[title]
        ind = ([f["name"]] if indirect else []) + best[2]
        memo[title] = (f["size"] + best[0], [title] + best[1], ind)
        return memo[title]

    failed = []
    lines = [f"Stack report: {image} ({args.target})"]
    lines.append(f"Largest frames ({min(args.top, len(funcs))} of {len(funcs)} functions with "
                 "stack information):")
    lines.append(f"  {'bytes':>6}  {'function':<32} {'module':<24} kind")
    for title, f in sorted(funcs.items(), key=lambda kv: (-kv[1]["size"], kv[1]["name"]))[:args.top]:
        lines.append(f"  {f['size']:>6}  {f['name']:<32} {f['module']:<24} {f['qual']}")

    def chain(root_name):
        t = resolve(root_name)
        if t is None:
            return None
        return depth(t, set())

    lines.append("Worst-case depth (frames along the deepest static call chain):")
    roots = []
    for root in ("main", "Reset_Handler", "_start"):
        r = chain(root)
        if r is not None:
            roots.append((root, r))
    isr_names = sorted({f["name"] for f in funcs.values()
                        if (f["name"].endswith("Handler") and f["name"] not in
                            ("Reset_Handler", "Default_Handler")) or f["name"] == "rt_irq_handler"})
    isrs = [(n, chain(n)) for n in isr_names]
    for name, (total, path, ind) in roots + isrs:
        names = " > ".join(funcs[t]["name"] for t in path)
        lines.append(f"  {name:<20} {total:>6} bytes: {names}")
        if ind:
            lines.append(f"  {'':<20}        indirect calls not followed, in: "
                         + ", ".join(dict.fromkeys(ind)))
    reset = next((r for n, r in roots if n in ("Reset_Handler", "_start")), None)
    if reset is not None:
        frame = 0
        if args.target.startswith("cortex-m"):
            frame = 104 if args.target == "cortex-m4f" else 32
        deepest_isr = max((r[0] for _n, r in isrs), default=0)
        lines.append(f"  estimate: reset path {reset[0]} + deepest handler {deepest_isr} + "
                     f"exception frame {frame} = {reset[0] + deepest_isr + frame} bytes "
                     "(one interrupt level; nesting adds per level)")
    if args.indirect:
        extra = {}
        with open(args.indirect, encoding="utf-8") as f:
            for raw in f:
                line = raw.split("#", 1)[0].strip()
                if not line:
                    continue
                caller, _sep, rest = line.partition(":")
                if not _sep:
                    sys.exit(f"stack_report.py: {args.indirect}: not 'caller: callees': {raw!r}")
                extra.setdefault(caller.strip(), []).extend(rest.split())
        ind_callers = sorted({base_name(funcs[t]["name"]) for t, cs in calls.items()
                              if INDIRECT in cs and t in funcs})
        listed = {c for cs in extra.values() for c in cs}

        def resolve_listed(name):
            """A listed callee: 'name', or 'file.c:name' for a static function; every clone
            of it in an LTO image."""
            if ":" not in name:
                return resolve_all(name)
            file, _sep, fname = name.rpartition(":")
            hits = [t for t in funcs if t.endswith("/" + name) or t == name]
            if not hits and args.lto:
                hits = [t for t, f in funcs.items() if base_name(f["name"]) == fname
                        and (f["file"] == file or f["file"].endswith("/" + file))]
                return sorted(hits)
            return hits if len(hits) == 1 else []
        memo2 = {}

        def depth_ind(title, stack):
            if title in memo2:
                return memo2[title]
            if title in stack:
                recursion.add(funcs[title]["name"])
                return (0, [])
            stack.add(title)
            best = (0, [])
            callees = [(c, False) for c in calls.get(title, []) if c != INDIRECT]
            callees += [(c, True) for c in extra.get(base_name(funcs[title]["name"]), [])]
            for callee, via_list in callees:
                if via_list:
                    targets = resolve_listed(callee)
                else:
                    r = resolve(callee)
                    targets = [r] if r is not None else []
                for r in targets:
                    d = depth_ind(r, stack)
                    if (d[0], len(d[1])) > (best[0], len(best[1])):
                        best = d
            stack.discard(title)
            memo2[title] = (funcs[title]["size"] + best[0], [title] + best[1])
            return memo2[title]

        lines.append("Worst-case depth with the calls through function pointers of "
                     f"{os.path.basename(args.indirect)}:")
        res = []
        for name, _r in roots + isrs:
            d = depth_ind(resolve(name), set())
            res.append((name, d))
            lines.append(f"  {name:<20} {d[0]:>6} bytes: "
                         + " > ".join(funcs[x]["name"] for x in d[1]))
        r2 = next((d for n, d in res if n in ("Reset_Handler", "_start")), None)
        if r2 is None:  # an assembly entry (rv32 _start) has no stack information: from main
            r2 = next((d for n, d in res if n == "main"), None)
        if r2 is not None:
            frame = 0
            if args.target.startswith("cortex-m"):
                frame = 104 if args.target == "cortex-m4f" else 32
            deepest2 = max((d[0] for n, d in res if n in isr_names), default=0)
            lines.append(f"  worst case: reset path {r2[0]} + deepest handler {deepest2} + "
                         f"exception frame {frame} = {r2[0] + deepest2 + frame} bytes "
                         "(one interrupt level)")
        missing = [n for n in ind_callers if n not in extra]
        if args.limit is not None:
            worst = r2[0] + deepest2 + frame if r2 is not None else None
            if worst is None or worst > args.limit or missing:
                failed.append(f"worst case {worst} bytes against {args.limit} reserved"
                              + (", pointer calls not listed: " + ", ".join(missing)
                                 if missing else ""))
        unknown_targets = sorted(c for c in listed if not resolve_listed(c))
        lines.append("  pointer calls not in the list (counted as 0): "
                     + (", ".join(missing) if missing else "none"))
        if unknown_targets:
            lines.append("  listed callees not in the image: " + ", ".join(unknown_targets))
    if recursion:
        lines.append("  recursion (cut, depth not bounded by this analysis): "
                     + ", ".join(sorted(recursion)))
    if unknown:
        lines.append("  no stack information (counted as 0; libgcc helpers, assembly): "
                     + ", ".join(sorted(unknown)))
    lines.append("Calls through function pointers (the HAL ops table, callbacks) are not "
                 "followed: a HAL call adds the port's frame (see the largest frames above).")
    report = "\n".join(lines) + "\n"
    with open(args.out, "w", encoding="utf-8") as f:
        f.write(report)
    if args.print:
        sys.stdout.write(report)
    if failed:
        sys.exit("stack_report.py: " + image + ": " + "; ".join(failed))


if __name__ == "__main__":
    main()
