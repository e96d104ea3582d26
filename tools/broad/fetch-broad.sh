#!/bin/sh
# fetch-broad.sh - get the BROAD trials Inclino's tests read, as <DEST>/<trial>.csv.gz.
#
# Usage: tools/broad/fetch-broad.sh [--from-git DIR] DEST_DIR
#
# 1. Takes the nine trials' original files, data_mat/<trial>.mat, of the public repository
#    github.com/dlaidig/broad at the pinned commit below: downloaded over HTTPS (curl or wget),
#    or with --from-git DIR from a local clone, bare git directory or checkout of that repository.
# 2. Checks each file's SHA-256 against tools/broad/SHA256SUMS; any difference stops here.
# 3. Converts them (tools/broad/broad2csv.py) to DEST_DIR/<trial>.csv.gz, checking each CSV's
#    SHA-256 against tools/broad/CSV-SHA256SUMS, and writes DEST_DIR/SHA256SUMS (the .csv.gz
#    files, `sha256sum -c` format) and DEST_DIR/ATTRIBUTION.md.
# Then configure with -DINCLINO_BROAD_DIR=DEST_DIR (docs/data.md).
#
# Needs (Debian 12 packages; nothing is installed by this script): python3-scipy (brings
# python3-numpy), coreutils (sha256sum), curl (or wget) and ca-certificates for the download,
# git for --from-git. cmake/scripts/install-deps.sh installs python3-scipy, curl and
# ca-certificates. PYTHON=/path/to/python3 picks the interpreter.
set -eu

commit=7e2f8189bb4a3ac91eae32c69b6bc87f08a6e2ad
short=7e2f818
base_url="https://raw.githubusercontent.com/dlaidig/broad/$commit"
here=$(cd "$(dirname "$0")" && pwd)

usage() {
    echo "usage: $0 [--from-git DIR] DEST_DIR" >&2
    echo "  downloads dlaidig/broad@${commit} data_mat/<trial>.mat (or takes them from the git" >&2
    echo "  repository or checkout DIR), checks their SHA-256 and converts them to DEST_DIR/<trial>.csv.gz" >&2
    exit 2
}
die() {
    echo "fetch-broad: $*" >&2
    exit 1
}

from_git=""
dest=""
while [ $# -gt 0 ]; do
    case "$1" in
        --from-git) [ $# -ge 2 ] || usage; from_git=$2; shift 2 ;;
        --from-git=*) from_git=${1#--from-git=}; shift ;;
        -h|--help) usage ;;
        -*) usage ;;
        *) [ -z "$dest" ] || usage; dest=$1; shift ;;
    esac
done
[ -n "$dest" ] || usage

# --- what is needed, checked before anything is fetched --------------------------------------
command -v sha256sum >/dev/null 2>&1 || die "sha256sum not found (Debian package coreutils)"
need_py="python3-scipy (it brings python3-numpy): apt-get install --no-install-recommends python3-scipy, or cmake/scripts/install-deps.sh"
py=""
for cand in ${PYTHON:-} python3 /usr/bin/python3; do
    if command -v "$cand" >/dev/null 2>&1 && "$cand" -c 'import numpy, scipy.io' >/dev/null 2>&1; then
        py=$cand
        break
    fi
done
[ -n "$py" ] || die "no python3 that can import numpy and scipy.io; install the Debian package $need_py"
if [ -n "$from_git" ]; then
    [ -d "$from_git" ] || die "--from-git: '$from_git' is not a directory"
    command -v git >/dev/null 2>&1 || die "git not found (Debian package git)"
    fetcher=""
elif command -v curl >/dev/null 2>&1; then
    fetcher=curl
elif command -v wget >/dev/null 2>&1; then
    fetcher=wget
else
    die "neither curl nor wget found (Debian package curl or wget)"
fi

mkdir -p "$dest"
dest=$(cd "$dest" && pwd)
work=$(mktemp -d "$dest/.fetch-broad.XXXXXX")
trap 'rm -rf "$work"' EXIT
trap 'exit 1' INT TERM
mkdir "$work/mat" "$work/out"

# --- 1 + 2: the original files and their hashes -------------------------------------------------
failed=""
while read -r sum path; do
    case "$sum" in ''|'#'*) continue ;; esac
    name=$(basename "$path")
    out="$work/mat/$name"
    if [ -n "$from_git" ]; then
        # The pinned commit's blob if DIR's repository has it, else the checked-out file.
        if git -C "$from_git" cat-file -e "$commit:$path" 2>/dev/null; then
            git -C "$from_git" cat-file blob "$commit:$path" >"$out" \
                || die "git could not read $commit:$path in $from_git (incomplete clone?)"
            origin="$from_git @ $short"
        elif [ -f "$from_git/$path" ]; then
            cp "$from_git/$path" "$out"
            origin="$from_git/$path"
        else
            die "$from_git has neither commit $commit with $path nor a file $path"
        fi
    else
        url="$base_url/$path"
        origin=$url
        echo "fetch-broad: downloading $url"
        if [ "$fetcher" = curl ]; then
            curl --proto '=https' --tlsv1.2 -fsSL --retry 3 -o "$out" "$url" || die "download failed: $url"
        else
            wget --https-only -q --tries=3 -O "$out" "$url" || die "download failed: $url"
        fi
    fi
    got=$(sha256sum "$out" | cut -d' ' -f1)
    if [ "$got" = "$sum" ]; then
        echo "fetch-broad: $path sha256 ok ($origin)"
    else
        echo "fetch-broad: $path sha256 $got, expected $sum ($origin)" >&2
        failed="$failed $path"
    fi
done <"$here/SHA256SUMS"
[ -z "$failed" ] || die "hash mismatch for:$failed; nothing converted"

# --- 3: conversion, then move into place ------------------------------------------------------
"$py" "$here/broad2csv.py" --src "$work/mat" --dest "$work/out" --sums "$here/CSV-SHA256SUMS"
cat >"$work/out/ATTRIBUTION.md" <<EOF
# BROAD trials (converted)

Source: D. Laidig, M. Caruso, A. Cereatti, T. Seel, "BROAD - A Benchmark for Robust Inertial
Orientation Estimation", Data 6(7):72, 2021, https://doi.org/10.3390/data6070072; data from
https://github.com/dlaidig/broad at commit $commit (data_mat/*.mat).
License: Creative Commons Attribution 4.0 International (CC BY 4.0),
https://creativecommons.org/licenses/by/4.0/

Changes: converted by Inclino's tools/broad/broad2csv.py: only gyroscope (in deg/s),
accelerometer (in g, 9.80665 m/s^2), the optical orientation quaternion and the movement flag,
with a time column, rounded to the decimals of the CSV. Inclino's docs/data.md describes the
columns.
EOF
for f in "$work/out"/*; do
    mv -f "$f" "$dest/"
done
echo "fetch-broad: done; configure with -DINCLINO_BROAD_DIR=$dest (or export INCLINO_BROAD_DIR=$dest)"
