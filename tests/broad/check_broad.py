#!/usr/bin/env python3
"""check_broad.py - the BROAD trials in a directory match the committed hashes (test broad_data).

Usage: check_broad.py --dir DIR --sums CSV-SHA256SUMS [--howto TEXT]

For each line 'sha256  <trial>.csv' of the sums file, DIR/<trial>.csv.gz must exist and the
SHA-256 of its decompressed text must be the listed one (the .csv.gz bytes themselves may differ
with the zlib that wrote them). Standard library only. Exit status 0 when all match.
"""

import argparse
import gzip
import hashlib
import os
import sys
import zlib


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--dir", required=True)
    ap.add_argument("--sums", required=True)
    ap.add_argument("--howto", default="")
    args = ap.parse_args()

    entries = []
    with open(args.sums, encoding="utf-8") as f:
        for line in f:
            line = line.strip()
            if line and not line.startswith("#"):
                digest, name = line.split(None, 1)
                entries.append((name, digest.lower()))
    if not entries:
        print(f"FAIL: {args.sums} lists nothing")
        return 1

    bad = 0
    for name, want in entries:
        path = os.path.join(args.dir, name + ".gz")
        try:
            h = hashlib.sha256()
            with gzip.open(path, "rb") as f:
                for chunk in iter(lambda: f.read(1 << 20), b""):
                    h.update(chunk)
            got = h.hexdigest()
        except FileNotFoundError:
            print(f"FAIL: {path}: missing")
            bad += 1
            continue
        except (OSError, EOFError, zlib.error) as e:
            print(f"FAIL: {path}: unreadable ({e})")
            bad += 1
            continue
        if got == want:
            print(f"ok    {name}  {got}")
        else:
            print(f"FAIL: {path}: sha256 of the CSV text is {got}, expected {want}")
            bad += 1
    if bad:
        print(f"{bad} of {len(entries)} BROAD files missing or different in {args.dir}.")
        if args.howto:
            print(args.howto)
        return 1
    print(f"all {len(entries)} BROAD files match {args.sums}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
