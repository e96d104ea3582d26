#!/bin/sh
# Instruction counts per call of every base/fx function on the host, with callgrind counting
# only the function itself (and its callees). Usage:
#   benches/fx/bench_fx.sh <build-dir>      (the host preset's build directory)
# Prints a markdown table for docs/benchmarks.md. Needs valgrind (fails if it is missing).
set -eu
bin="${1:?usage: bench_fx.sh <host build dir>}/benches/fx/bench_fx"
count="$(dirname "$0")/../../cmake/scripts/callgrind_count.sh"
n=100000
echo "| function | instructions / call |"
echo "|---|---:|"
for fn in bench_fx_add bench_fx_asr32 bench_fx_abs fx_rshift_round32 fx_rshift_round64 \
          fx_mul_q16 fx_mul_q30 fx_mul_shift fx_div fx_sum_add fx_sum_mean fx_isqrt32 fx_isqrt64 \
          fx_isqrt64_round fx_sqrt_q16 fx_sqrt_q30 fx_atan2_deg fx_asin_deg fx_sin_deg fx_cos_deg \
          fx_sincos_deg; do
    total=$("$count" "$fn" "$bin" "$fn")
    awk -v f="$fn" -v t="$total" -v n="$n" 'BEGIN { printf "| %s | %.1f |\n", f, t / n }'
done
