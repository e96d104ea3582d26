#!/bin/sh
# install-deps.sh - install everything Inclino's README commands need on Debian 12 (bookworm).
#
# Host build and tools: cmake make gcc g++ libeigen3-dev zlib1g-dev python3 (scripts, size reports)
# Cross builds:         gcc-arm-none-eabi libnewlib-arm-none-eabi gcc-riscv64-unknown-elf
# Tests under QEMU:     qemu-system-arm (Cortex-M) qemu-system-misc (riscv32)
# Checks and tools:     cppcheck clang-format valgrind (instruction counts) sigrok-cli (decoding VCDs)
# BROAD test data:      python3-numpy python3-scipy (tools/broad/broad2csv.py), curl ca-certificates
#                       (tools/broad/fetch-broad.sh downloads over HTTPS; docs/data.md)
# Plots:                gnuplot-nox (tools/plots/att_error_bound.sh; docs/attitude.md)
# Fuzzing:              clang-14 libclang-rt-14-dev (the `fuzz` preset: clang -fsanitize=fuzzer,
#                       address,undefined needs libclang-rt-14-dev's runtimes, only a Recommends
#                       of clang-14, so not pulled in with --no-install-recommends), llvm-14
#                       (llvm-symbolizer: readable sanitizer stack traces; docs/fuzzing.md)
#
# --no-install-recommends keeps QEMU from pulling in its GUI and firmware packages.
# Uses sudo only when not already root.
set -eu

packages="cmake make gcc g++ python3 libeigen3-dev \
    gcc-arm-none-eabi libnewlib-arm-none-eabi gcc-riscv64-unknown-elf \
    qemu-system-arm qemu-system-misc zlib1g-dev \
    cppcheck clang-format valgrind sigrok-cli \
    python3-numpy python3-scipy curl ca-certificates gnuplot-nox \
    clang-14 libclang-rt-14-dev llvm-14"
# CAN log checks: python3-canmatrix (decodes the candump log with the DBC; the Debian interpreter
# /usr/bin/python3), can-utils (log2asc validates the candump format); docs/can.md
packages="$packages python3-canmatrix can-utils"

if [ "$(id -u)" -eq 0 ]; then
    sudo=""
else
    sudo="sudo"
fi

$sudo apt-get update
# shellcheck disable=SC2086 # the package list is meant to split into words
$sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends $packages
