#!/bin/sh
# callgrind_count.sh - instructions executed inside one function (and its callees), counted by
# valgrind's callgrind with collection toggled on that function only. Prints the count.
# Usage: cmake/scripts/callgrind_count.sh <function> <program> [arguments...]
# Fails when valgrind is missing or callgrind reports no count.
set -eu
fn="${1:?usage: callgrind_count.sh <function> <program> [arguments...]}"
shift
[ $# -ge 1 ] || { echo "callgrind_count.sh: no program" >&2; exit 1; }
command -v valgrind >/dev/null || { echo "valgrind not found" >&2; exit 1; }
[ -x "$1" ] || { echo "$1 not built" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
valgrind --tool=callgrind --collect-atstart=no --toggle-collect="$fn" \
    --callgrind-out-file="$tmp/cg.out" "$@" >/dev/null 2>"$tmp/log"
total=$(sed -n 's/.*Collected : *\([0-9]*\).*/\1/p' "$tmp/log")
[ -n "$total" ] || { cat "$tmp/log" >&2; exit 1; }
echo "$total"
