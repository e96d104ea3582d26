#!/bin/sh
# test-all.sh - run every test of Inclino: the seven workflow presets (configure from scratch,
# build, test), stopping at the first failure.
#
#   host           gcc, every test (unit, sim, drivers, tools) + cppcheck
#   host-sanitize  the whole host suite again under ASan + UBSan
#   cortex-m0plus  firmware/driver/HAL/sim tests under qemu-system-arm (mps2-an385), images,
#   cortex-m3      size and stack reports, no-float/no-libc checks
#   cortex-m4f     (mps2-an386)
#   rv32imac       every module compiled and linked, images, checks; board tests under
#                  qemu-system-riscv32
#   fuzz           clang-14 libFuzzer targets of every parser, a bounded run each (-runs,
#                  ASan + UBSan; docs/fuzzing.md)
#
# Usage: cmake/scripts/test-all.sh [preset...]   (default: all seven, in that order)
# Build directories: build/<preset> in the source tree (CMakePresets.json).
set -eu

cd "$(dirname "$0")/../.."

presets="${*:-host host-sanitize cortex-m0plus cortex-m3 cortex-m4f rv32imac fuzz}"
start=$(date +%s)
for preset in $presets; do
    t0=$(date +%s)
    echo "=== workflow preset $preset"
    if ! cmake --workflow --preset "$preset" --fresh; then
        echo "=== FAILED: $preset" >&2
        exit 1
    fi
    echo "=== $preset passed in $(( $(date +%s) - t0 )) s"
done
echo "=== all presets passed ($presets) in $(( $(date +%s) - start )) s"
