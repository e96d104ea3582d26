#!/bin/sh
# Instructions per update of the filters on Cortex-M under QEMU, counted with -icount and SysTick
# (see bench_kf_cm.c and tests/fx/bench_fx_cm.sh). Usage:
#   tests/kf/bench_kf_cm.sh <cortex-m0plus or cortex-m3 build dir>      (machine mps2-an385)
# Prints a markdown table. instructions/update = (ticks - baseline ticks) * 40 / 2^SHIFT / N.
set -eu
elf="${1:?usage: bench_kf_cm.sh <cross build dir>}/tests/kf/bench_kf_cm.elf"
shift_n=6
[ -f "$elf" ] || { echo "$elf not built" >&2; exit 1; }
command -v qemu-system-arm >/dev/null || { echo "qemu-system-arm not found" >&2; exit 1; }
out=$(qemu-system-arm -M mps2-an385 -display none -monitor none -serial none \
    -semihosting-config enable=on,target=native -icount shift=$shift_n,align=off -kernel "$elf")
echo "$out" | awk -v sh=$shift_n '
    /^BENCH_N / { n = $2 }
    /^BENCH / { printf "| %s | %.0f |\n", $2, ($3 - $4) * 40 / (2 ^ sh) / n }
    BEGIN { print "| update | instructions / update |"; print "|---|---:|" }'
