#!/bin/sh
# Instructions per call of the firmware/cal per-sample and per-temperature functions on Cortex-M
# under QEMU, counted with -icount and SysTick (bench_cal.c, BENCH_CM). Usage:
#   tests/cal/bench_cal_cm.sh <cortex-m3 or cortex-m0plus build dir>   (machine mps2-an385)
#   tests/cal/bench_cal_cm.sh <cortex-m4f build dir> mps2-an386
# instructions/call = (ticks - baseline ticks) * 40 / 2^SHIFT / N (docs/benchmarks.md).
set -eu
elf="${1:?usage: bench_cal_cm.sh <cross build dir> [machine]}/tests/cal/bench_cal_cm.elf"
machine="${2:-mps2-an385}"
shift_n=6
[ -f "$elf" ] || { echo "$elf not built" >&2; exit 1; }
command -v qemu-system-arm >/dev/null || { echo "qemu-system-arm not found" >&2; exit 1; }
out=$(qemu-system-arm -M "$machine" -display none -monitor none -serial none \
    -semihosting-config enable=on,target=native -icount shift=$shift_n,align=off -kernel "$elf")
echo "$out" | awk -v sh=$shift_n '
    /^BENCH_N / { n = $2 }
    /^BENCH / && $1 == "BENCH" { name = $2; for (i = 3; i < NF - 1; i++) name = name " " $i;
        printf "| %s | %.1f |\n", name, ($(NF - 1) - $NF) * 40 / (2 ^ sh) / n }
    BEGIN { print "| function | instructions / call |"; print "|---|---:|" }'
