#!/bin/sh
# Instructions per call of the CAN packing, the E2E protection and the speed receiver on
# Cortex-M under QEMU, counted with -icount and SysTick (bench_can_cm.c; method in
# cmake/scripts/bench_icount.sh). Usage:
#   benches/can/bench_can_cm.sh <cortex-m0plus or cortex-m3 build dir>   (machine mps2-an385)
set -eu
dir="${1:?usage: bench_can_cm.sh <cross build dir> [machine]}"
exec "$(dirname "$0")/../../cmake/scripts/bench_icount.sh" "$dir/benches/can/bench_can_cm.elf" \
    "${2:-mps2-an385}" "function (what)" "instructions / call"
