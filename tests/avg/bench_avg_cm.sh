#!/bin/sh
# Instructions per sample of firmware/avg and firmware/still on Cortex-M under QEMU, counted with
# -icount and SysTick (see bench_avg_cm.c). Usage:
#   tests/avg/bench_avg_cm.sh <cortex-m3 or cortex-m0plus build dir>   (machine mps2-an385)
#   tests/avg/bench_avg_cm.sh <cortex-m4f build dir> mps2-an386
# Prints a markdown table. instructions/sample = (ticks - baseline ticks) * 40 / 2^SHIFT / N.
set -eu
elf="${1:?usage: bench_avg_cm.sh <cross build dir> [machine]}/tests/avg/bench_avg_cm.elf"
machine="${2:-mps2-an385}"
shift_n=6
[ -f "$elf" ] || { echo "$elf not built" >&2; exit 1; }
command -v qemu-system-arm >/dev/null || { echo "qemu-system-arm not found" >&2; exit 1; }
out=$(qemu-system-arm -M "$machine" -display none -monitor none -serial none \
    -semihosting-config enable=on,target=native -icount shift=$shift_n,align=off -kernel "$elf")
echo "$out" | awk -v sh=$shift_n '
    /^BENCH_N / { n = $2 }
    /^BENCH / { printf "| %s | %.1f |\n", $2, ($3 - $4) * 40 / (2 ^ sh) / n }
    BEGIN { print "| function (configuration) | instructions / sample |"; print "|---|---:|" }'
