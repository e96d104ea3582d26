#!/bin/sh
# The BROAD table of docs/benchmarks.md ("Attitude (3D estimator)"): every development trial
# through imu_replay with one estimator (its defaults otherwise) and scored by att_score against
# the optical truth. Prints a markdown table: RMS and max of the inclination error (deg), and the
# integrity keys of att_score (valid fraction, fraction of valid samples over the bound, max
# error / bound, median bound, max error while valid).
#   benches/att/broad_table.sh <host build dir> <BROAD dir> [att|adapt|tilt] [imu_replay options]
# The estimate CSVs go to a temporary directory that is removed afterwards.
set -eu
build="${1:?usage: broad_table.sh <host build dir> <BROAD dir> [att|adapt|tilt] [options]}"
data="${2:?BROAD directory (docs/data.md)}"
est="${3:-att}"
[ $# -ge 3 ] && shift 3 || shift $#
replay="$build/tools/imu_replay/imu_replay"
score="$build/tools/att_score/att_score"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "| trial | RMS | max | valid frac | over-bound frac | max err/bound | median bound | max err while valid |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|"
for f in "$data"/[0-9][0-9]_*.csv.gz; do
    id=$(basename "$f" | cut -c1-2)
    "$replay" --estimator "$est" "$@" -o "$tmp/e.csv" "$f" 2>/dev/null
    "$score" "$f" "$tmp/e.csv" --name "$id" | tee -a "$tmp/all.txt" | awk '{
        for (i = 1; i <= NF; i++) { split($i, kv, "="); v[kv[1]] = kv[2] }
        printf "| %s | %.3f | %.2f | %.3f | %.4f | %.2f | %.2f | %.2f |\n", v["name"], v["rms_deg"],
            v["max_deg"], v["valid_frac"], v["over_bound_frac"], v["max_err_over_bound"],
            v["median_bound_deg"], v["max_valid_err_deg"] }'
done
awk '{ for (i = 1; i <= NF; i++) { split($i, kv, "="); v[kv[1]] = kv[2] }
       s += v["rms_deg"]; n++; if (v["max_deg"] > m) m = v["max_deg"] }
     END { printf "| **mean RMS / max of max** | **%.3f** | **%.2f** | | | | | |\n", s / n, m }' "$tmp/all.txt"
