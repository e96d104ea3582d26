#!/bin/sh
# Instructions per sample of firmware/signal/avg and firmware/signal/still on Cortex-M under QEMU, counted with
# -icount and SysTick (bench_avg_cm.c; method in cmake/scripts/bench_icount.sh). Usage:
#   benches/avg/bench_avg_cm.sh <cortex-m3 or cortex-m0plus build dir>   (machine mps2-an385)
#   benches/avg/bench_avg_cm.sh <cortex-m4f build dir> mps2-an386
set -eu
dir="${1:?usage: bench_avg_cm.sh <cross build dir> [machine]}"
exec "$(dirname "$0")/../../cmake/scripts/bench_icount.sh" "$dir/benches/avg/bench_avg_cm.elf" \
    "${2:-mps2-an385}" "function (configuration)" "instructions / sample"
