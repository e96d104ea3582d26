#!/bin/sh
# Instructions per sample of the 3D attitude estimator and the per-axis estimators on the host:
# callgrind counting only the wrapper around each function (and its callees) for BENCH_N = 100000
# steady-state samples after a 2000-sample warm-up (benches/att/bench_att.c).
#   benches/att/bench_att.sh <host build dir>
# Prints a markdown table for docs/benchmarks.md. Needs valgrind (fails if it is missing).
set -eu
bin="${1:?usage: bench_att.sh <host build dir>}/benches/att/bench_att"
count="$(dirname "$0")/../../cmake/scripts/callgrind_count.sh"
n=100000
echo "| function | instructions / call (x86-64) |"
echo "|---|---:|"
while read -r case fn what; do
    total=$("$count" "$fn" "$bin" "$case")
    awk -v w="$what" -v t="$total" -v n="$n" \
        'BEGIN { gsub(/~/, " ", w); printf "| %s | %.1f |\n", w, t / n }'
done <<LIST
update bench_att_update att_update~(motion,~steady~state)
quat bench_att_quat att_get_quat
euler bench_att_euler att_get_euler
tilt bench_tilt_step tilt_step~FEEDBACK
adapt bench_adapt_tilt_step adapt_tilt_step~(patented~method)
LIST
