#!/bin/sh
# Instruction counts per call of the firmware/signal/cal functions on the host, callgrind counting only
# the function itself (and its callees: fx). Usage:
#   benches/cal/bench_cal.sh <host build dir>
# Prints a markdown table for docs/benchmarks.md (Calibration). Needs valgrind.
set -eu
bin="${1:?usage: bench_cal.sh <host build dir>}/benches/cal/bench_cal"
count="$(dirname "$0")/../../cmake/scripts/callgrind_count.sh"
n=100000
echo "| function | case | instructions / call |"
echo "|---|---|---:|"
while read -r fn case; do
    total=$("$count" "$fn" "$bin" "$case")
    awk -v f="$fn" -v c="$case" -v t="$total" -v n="$n" 'BEGIN { printf "| %s | %s | %.1f |\n", f, c, t / n }'
done <<LIST
cal_acc_apply acc_apply
cal_gyro_apply gyro_apply
cal_acc_set_temp acc_set_temp
cal_tmodel_eval tmodel_linear
cal_tmodel_eval tmodel_parabola
cal_tmodel_eval tmodel_lorentz
cal_tmodel_eval tmodel_pwl
cal_tmodel_eval tmodel_lorentz_cubic
cal_flip flip
cal_avg_add avg_add
cal_turn_add turn_add
LIST
