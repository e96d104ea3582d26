#!/bin/sh
# fuzz_long.sh - the long libFuzzer run of docs/fuzzing.md: every target of the `fuzz` preset for
# RUNS executions (default 10^6) from its kept corpus, one after the other, at low priority;
# prints one Markdown row per target (executions, coverage, features, corpus, crashes, time).
#
#   cmake --preset fuzz && cmake --build build/fuzz -j2
#   cmake/scripts/fuzz_long.sh [RUNS] [target...]     (default: every lf_* in build/fuzz)
#
# New inputs and artifacts go to build/fuzz/long/<target>/; the kept corpus is not touched
# (minimise into it with -merge=1, docs/fuzzing.md). Exit status 1 when any target crashed.
set -eu
cd "$(dirname "$0")/../.."
runs="${1:-1000000}"
[ $# -gt 0 ] && shift
targets="${*:-$(cd build/fuzz/tests/fuzz && find . -maxdepth 1 -type f -perm -u+x -name 'lf_*' | sed 's|^./lf_||' | sort)}"
status=0
echo "| target | executions | cov | ft | corpus | crashes | seconds |"
echo "|---|---:|---:|---:|---:|---:|---:|"
for t in $targets; do
    work="build/fuzz/long/$t"
    rm -rf "$work"
    mkdir -p "$work/new" "$work/artifacts"
    t0=$(date +%s)
    rc=0
    nice -n 10 "build/fuzz/tests/fuzz/lf_$t" -runs="$runs" -seed=1 -max_len=4096 -timeout=10 \
        -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$work/artifacts/" \
        "$work/new" "tests/fuzz/corpus/$t" > "$work/log" 2>&1 || rc=$?
    secs=$(( $(date +%s) - t0 ))
    execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$work/log" | tail -1)
    cov=$(grep -o 'cov: [0-9]*' "$work/log" | tail -1 | cut -d' ' -f2)
    ft=$(grep -o 'ft: [0-9]*' "$work/log" | tail -1 | cut -d' ' -f2)
    corp=$(grep -o 'corp: [0-9]*' "$work/log" | tail -1 | cut -d' ' -f2)
    crashes=$(ls "$work/artifacts" | wc -l)
    [ "$rc" -ne 0 ] || [ "$crashes" -ne 0 ] && status=1
    echo "| $t | ${execs:-?} | ${cov:-?} | ${ft:-?} | ${corp:-?} | $crashes (exit $rc) | $secs |"
done
exit $status
