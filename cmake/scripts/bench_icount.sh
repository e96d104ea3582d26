#!/bin/sh
# bench_icount.sh - run a Cortex-M benchmark image under QEMU with -icount and print its figures
# as a markdown table. The image (tests/*/bench_*_cm.c) prints "BENCH_N <n>" and, per case,
# "BENCH <name...> <ticks> <baseline ticks>", SysTick ticks of the case and of the same loop
# around an empty function. With -icount shift=6 one instruction is 2^6 ns of virtual time and
# SysTick counts at 25 MHz (40 ns), so
#   instructions per iteration = (ticks - baseline) * 40 / 2^6 / n.
# Usage: cmake/scripts/bench_icount.sh <elf> <machine> <name column> <value column> [decimals]
set -eu
elf="${1:?usage: bench_icount.sh <elf> <machine> <name column> <value column> [decimals]}"
machine="${2:?machine, e.g. mps2-an385}"
name_col="${3:?name column title}"
value_col="${4:?value column title}"
decimals="${5:-1}"
shift_n=6
[ -f "$elf" ] || { echo "$elf not built" >&2; exit 1; }
command -v qemu-system-arm >/dev/null || { echo "qemu-system-arm not found" >&2; exit 1; }
out=$(qemu-system-arm -M "$machine" -display none -monitor none -serial none \
    -semihosting-config enable=on,target=native -icount shift=$shift_n,align=off -kernel "$elf")
echo "$out" | awk -v sh=$shift_n -v nc="$name_col" -v vc="$value_col" -v d="$decimals" '
    BEGIN { printf "| %s | %s |\n|---|---:|\n", nc, vc; fmt = "| %s | %." d "f |\n"; rows = 0 }
    $1 == "BENCH_N" { n = $2 }
    $1 == "BENCH" { name = $2; for (i = 3; i < NF - 1; i++) name = name " " $i;
        printf fmt, name, ($(NF - 1) - $NF) * 40 / (2 ^ sh) / n; rows++ }
    END { if (n == 0 || rows == 0) { print "bench_icount.sh: no BENCH_N or BENCH lines" > "/dev/stderr"; exit 1 } }'
