#!/usr/bin/env python3
"""overall.py - the test att_real_overall: the mean of the per-trial RMS and the largest
per-trial max over the att_<id>.score files that the att_real_<id> tests wrote (att_score's
key=value lines). Fails when a trial is missing or a figure is over its limit."""
import argparse
import glob
import os
import sys


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--dir", required=True)
    ap.add_argument("--trials", type=int, required=True)
    ap.add_argument("--max-mean-rms", type=float, required=True)
    ap.add_argument("--max-max", type=float, required=True)
    a = ap.parse_args()
    rows = []
    for path in sorted(glob.glob(os.path.join(a.dir, "att_*.score"))):
        with open(path, encoding="ascii") as f:
            kv = dict(p.split("=", 1) for p in f.read().split())
        rows.append((kv["name"], float(kv["rms_deg"]), float(kv["max_deg"])))
    if len(rows) != a.trials:
        print(f"overall: {len(rows)} trial scores in {a.dir}, expected {a.trials}")
        return 1
    mean_rms = sum(r[1] for r in rows) / len(rows)
    max_max = max(r[2] for r in rows)
    ok = mean_rms <= a.max_mean_rms and max_max <= a.max_max
    print(f"trials={len(rows)} mean_rms_deg={mean_rms:.4f} max_max_deg={max_max:.4f} "
          f"limit_mean_rms_deg={a.max_mean_rms} limit_max_deg={a.max_max} "
          f"result={'pass' if ok else 'fail'}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
