#!/bin/sh
# Instructions per update of the 3D attitude estimator (and tilt_step FEEDBACK, adapt_tilt_step on
# the same inputs) on Cortex-M under QEMU, counted with -icount and SysTick (bench_att_cm.c;
# method in cmake/scripts/bench_icount.sh). Usage:
#   benches/att/bench_att_cm.sh <cortex-m0plus or cortex-m3 build dir>     (machine mps2-an385)
#   benches/att/bench_att_cm.sh <cortex-m4f build dir> mps2-an386
set -eu
dir="${1:?usage: bench_att_cm.sh <cross build dir> [machine]}"
exec "$(dirname "$0")/../../cmake/scripts/bench_icount.sh" "$dir/benches/att/bench_att_cm.elf" \
    "${2:-mps2-an385}" "function" "instructions / call" 0
