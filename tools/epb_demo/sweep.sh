#!/bin/sh
# sweep.sh - the EPB demo over a grid of parts, part seeds, slopes and temperatures: is every
# valid estimate's true slope within its bound? (docs/benchmarks.md, "EPB demo")
#
#   tools/epb_demo/sweep.sh BUILD_DIR [PART_SEEDS]
#
# Grid: parts adis16405, adis16364, adis16362, sca3000-d01; part seeds 0 (part A) and 1..N-1
# (default 10 seeds: 0..9); grades -30, -8, 0, 10, 30, 50 %; 25 degC... -20, 5, 25, 40, 60 degC;
# two 2.5 s estimates each (--length 5). Prints one line per run whose last estimate is not
# valid, and the totals: estimates, valid ones, valid ones with the true slope outside the bound
# (must be 0), and the largest |error| / bound among the valid ones.
set -eu
build=${1:?usage: sweep.sh BUILD_DIR [PART_SEEDS]}
seeds=${2:-10}
demo="$build/tools/epb_demo/epb_demo"
tmp=$(mktemp)
trap 'rm -f "$tmp"' EXIT
: > "$tmp.all"
ps=0
while [ "$ps" -lt "$seeds" ]; do
    for part in adis16405 adis16364 adis16362 sca3000-d01; do
        for g in -30 -8 0 10 30 50; do
            for t in -20 5 25 40 60; do
                "$demo" --part "$part" --part-seed "$ps" --seed $((ps * 7 + 3)) --grade "$g" --temp "$t" \
                    --length 5 --est-csv "$tmp" > /dev/null || \
                    echo "not valid at the end: --part $part --part-seed $ps --grade $g --temp $t"
                tail -n +2 "$tmp" >> "$tmp.all"
            done
        done
    done
    ps=$((ps + 1))
done
# est-csv columns: 5 bound_deg, 7 valid, 11 error_deg, 12 within
awk -F, '{ n++; if ($7 == 1) { v++; r = ($11 < 0 ? -$11 : $11) / $5; if (r > m) m = r; if ($12 != 1) out++ } }
     END { printf "estimates %d, valid %d, valid with the true slope outside the bound %d, largest |error|/bound %.3f\n", n, v, out + 0, m }' "$tmp.all"
rm -f "$tmp.all"
