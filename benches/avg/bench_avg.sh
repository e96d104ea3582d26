#!/bin/sh
# Instructions per sample of the averaging filters and the stillness/thermal detectors on the
# host: callgrind counting only the push function (and its callees), BENCH_N = 100000 samples.
#   benches/avg/bench_avg.sh <host build dir>
# Prints a markdown table for docs/benchmarks.md. Needs valgrind (fails if it is missing).
set -eu
bin="${1:?usage: bench_avg.sh <host build dir>}/benches/avg/bench_avg"
count="$(dirname "$0")/../../cmake/scripts/callgrind_count.sh"
n=100000
echo "| filter | configuration | function | instructions / sample |"
echo "|---|---|---|---:|"
while read -r case fn what; do
    total=$("$count" "$fn" "$bin" "$case")
    awk -v c="$case" -v f="$fn" -v w="$what" -v t="$total" -v n="$n" \
        'BEGIN { gsub(/_/, " ", w); printf "| %s | %s | %s | %.1f |\n", c, w, f, t / n }'
done <<LIST
block avg_block_push N=1024_(one_division_per_block)
moving64 avg_moving_push W=64_(power_of_two:_shift)
moving50 avg_moving_push W=50_(64-bit_division_per_output)
cascade16x4 avg_cascade_push W=16,_P=4_(shift)
cascade10x2 avg_cascade_push W=10,_P=2_(division)
bartlett6d1 avg_bartlett_push M=6_(64_taps),_D=1
bartlett4d16 avg_bartlett_push M=4_(16_taps),_D=16
still still_push 6_axes,_W=819,_all_tests_on
thermal still_thermal_push avg_n=819,_span=30
LIST
