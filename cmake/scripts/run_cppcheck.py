#!/usr/bin/env python3
"""run_cppcheck.py - cppcheck over the project's C/C++ sources, as the CTest test "cppcheck".

Checks base/ hal/ drivers/ firmware/ boards/ sim/ tools/ benches/ tests/ with
  --enable=warning,style,performance,portability --error-exitcode=1
and explicit include directories: every include/ directory of a module, tests/support,
boards/qemu and the board headers of boards/s32k1 and boards/generic (found at run time, so a
new module needs no edit here). Explicit directories rather than the host's compile database, because the database holds only what the
host builds: the Cortex-M port, the cross run-time and the QEMU boards would go unchecked.

Suppressions live in cmake/scripts/cppcheck-suppressions.txt, each with a comment saying why.
"""
import argparse
import os
import subprocess
import sys

DIRS = ["base", "hal", "drivers", "firmware", "boards", "sim", "tools", "benches", "tests"]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cppcheck", default="cppcheck")
    ap.add_argument("--root", required=True)
    ap.add_argument("--jobs", default="2")
    args = ap.parse_args()

    includes = []
    for d in DIRS:
        for dirpath, dirnames, _files in os.walk(os.path.join(args.root, d)):
            dirnames.sort()
            if os.path.basename(dirpath) == "include" and "rv32" not in dirpath.split(os.sep):
                includes.append(dirpath)
    includes += [os.path.join(args.root, "tests", "support"),
                 os.path.join(args.root, "boards", "qemu"),
                 os.path.join(args.root, "boards", "s32k1"),
                 os.path.join(args.root, "boards", "generic")]
    sources = [os.path.join(args.root, d) for d in DIRS if os.path.isdir(os.path.join(args.root, d))]
    suppressions = os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "cppcheck-suppressions.txt")
    cmd = [args.cppcheck, "--enable=warning,style,performance,portability", "--error-exitcode=1",
           "--std=c11", "--inline-suppr", "--quiet", f"-j{args.jobs}",
           f"--suppressions-list={suppressions}",
           "--template={file}:{line}: {severity} ({id}): {message}"]
    cmd += [f"-I{i}" for i in includes] + sources
    print(" ".join(cmd), flush=True)
    r = subprocess.run(cmd)
    if r.returncode == 0:
        print(f"cppcheck: clean ({', '.join(DIRS)})")
    return r.returncode


if __name__ == "__main__":
    sys.exit(main())
