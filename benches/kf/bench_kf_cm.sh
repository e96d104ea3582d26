#!/bin/sh
# Instructions per update of the filters on Cortex-M under QEMU, counted with -icount and SysTick
# (bench_kf_cm.c; method in cmake/scripts/bench_icount.sh). Usage:
#   benches/kf/bench_kf_cm.sh <cortex-m0plus or cortex-m3 build dir>      (machine mps2-an385)
set -eu
dir="${1:?usage: bench_kf_cm.sh <cross build dir>}"
exec "$(dirname "$0")/../../cmake/scripts/bench_icount.sh" "$dir/benches/kf/bench_kf_cm.elf" \
    mps2-an385 "update" "instructions / update" 0
