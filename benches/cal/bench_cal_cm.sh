#!/bin/sh
# Instructions per call of the firmware/signal/cal per-sample and per-temperature functions on Cortex-M
# under QEMU, counted with -icount and SysTick (bench_cal.c, BENCH_CM; method in
# cmake/scripts/bench_icount.sh). Usage:
#   benches/cal/bench_cal_cm.sh <cortex-m3 or cortex-m0plus build dir>   (machine mps2-an385)
#   benches/cal/bench_cal_cm.sh <cortex-m4f build dir> mps2-an386
set -eu
dir="${1:?usage: bench_cal_cm.sh <cross build dir> [machine]}"
exec "$(dirname "$0")/../../cmake/scripts/bench_icount.sh" "$dir/benches/cal/bench_cal_cm.elf" \
    "${2:-mps2-an385}" "function" "instructions / call"
