#!/usr/bin/env python3
"""broad2csv.py - convert BROAD trials (MATLAB .mat files of dlaidig/broad) to Inclino's CSVs.

Usage: broad2csv.py --src DIR --dest DIR [--sums CSV-SHA256SUMS] [--no-check]

Reads DIR/<trial>.mat for every trial named in the sums file (default: CSV-SHA256SUMS next to
this script) and writes DEST/<trial>.csv.gz, one per trial, and DEST/SHA256SUMS (the SHA-256 of
each written .csv.gz, `sha256sum -c` format). Unless --no-check is given, the SHA-256 of every
CSV's text (before compression) must equal the one in the sums file, or nothing is written.
Normally run by fetch-broad.sh, which first checks the .mat files against SHA256SUMS.

Needs Debian's python3-scipy (which brings python3-numpy); it installs nothing.

The .mat files (MATLAB 5.0, scipy.io.loadmat) hold, per sample: imu_gyr (rad/s), imu_acc
(m/s^2), imu_mag (uT, not used), opt_quat (w, x, y, z: IMU frame w.r.t. ENU, sensor to earth;
NaN where the optical system lost track), opt_pos (m, not used), movement (uint8 0/1), and the
scalar sampling_rate (2000/7 Hz). The CSV columns and their text format:

  t_s                    index / sampling_rate                        %.6f
  gyr_{x,y,z}_dps        imu_gyr in deg/s (numpy.rad2deg)             %.6g (*)
  acc_{x,y,z}_g          imu_acc / 9.80665                            %.7g (*)
  truth_q{w,x,y,z}       opt_quat unchanged (no sign change)          %.7f ("nan" stays nan)
  movement               movement                                     %d

(*) of the value first rounded to 10 significant digits. The sensor's values are decimal (gyro
in steps of 0.0001 deg/s), and rad -> deg lands a few ulp above or below ties such as 114.6275;
rounding first settles them as the reference copy does, which this reproduces exactly.

BROAD: D. Laidig, M. Caruso, A. Cereatti, T. Seel, "BROAD - A Benchmark for Robust Inertial
Orientation Estimation", Data 6(7):72, 2021, doi:10.3390/data6070072; data CC BY 4.0. See
docs/data.md.
"""

import argparse
import gzip
import hashlib
import io
import os
import sys

G = 9.80665  # m/s^2 per g

HEADER = ("t_s,gyr_x_dps,gyr_y_dps,gyr_z_dps,acc_x_g,acc_y_g,acc_z_g,"
          "truth_qw,truth_qx,truth_qy,truth_qz,movement\n")

# The gzip header's time stamp of each file of the reference copy (../shared/data/broad-dev).
# With it, and Python's gzip at level 9 fed through a TextIOWrapper as below, the .csv.gz
# come out byte-identical to that copy (checked with Python 3.11 and zlib 1.2.13, Debian 12).
# Only the CSV text is checked; other zlib builds may compress differently.
GZIP_MTIME = {
    "01_undisturbed_slow_rotation_A": 1796146572,
    "04_undisturbed_slow_rotation_with_breaks_A": 1796146574,
    "06_undisturbed_fast_rotation_A": 1796146577,
    "08_undisturbed_fast_rotation_with_breaks_A": 1796146581,
    "14_undisturbed_slow_translation_with_breaks_B": 1796146586,
    "15_undisturbed_fast_translation_A": 1796146589,
    "16_undisturbed_fast_translation_B": 1796146591,
    "25_disturbed_tapping_B": 1796146593,
    "26_disturbed_phone_vibration_A": 1796146595,
}


def die(msg):
    print(f"broad2csv: {msg}", file=sys.stderr)
    sys.exit(1)


def read_sums(path):
    """Lines 'sha256  <trial>.csv' -> [(trial, sha256)]."""
    out = []
    with open(path, encoding="utf-8") as f:
        for line in f:
            line = line.strip()
            if not line or line.startswith("#"):
                continue
            digest, name = line.split(None, 1)
            name = name.lstrip("*")
            if not name.endswith(".csv"):
                die(f"{path}: '{name}' is not a .csv")
            out.append((name[:-len(".csv")], digest.lower()))
    if not out:
        die(f"{path}: no entries")
    return out


def r10(x):
    return float("%.10g" % x)


def csv_lines(mat_path):
    try:
        import numpy as np
        import scipy.io
    except ImportError as e:
        die(f"{e}: install the Debian package python3-scipy (it brings python3-numpy)")
    m = scipy.io.loadmat(mat_path, squeeze_me=True)
    for key in ("imu_gyr", "imu_acc", "opt_quat", "movement", "sampling_rate"):
        if key not in m:
            die(f"{mat_path}: no variable '{key}'")
    fs = float(m["sampling_rate"])
    gyr = np.rad2deg(np.asarray(m["imu_gyr"], dtype=np.float64))
    acc = np.asarray(m["imu_acc"], dtype=np.float64) / G
    quat = np.asarray(m["opt_quat"], dtype=np.float64)
    mov = np.asarray(m["movement"]).astype(np.int64)
    n = gyr.shape[0]
    if gyr.shape != (n, 3) or acc.shape != (n, 3) or quat.shape != (n, 4) or mov.shape != (n,):
        die(f"{mat_path}: unexpected shapes {gyr.shape} {acc.shape} {quat.shape} {mov.shape}")
    yield HEADER
    for i in range(n):
        g = gyr[i].tolist()
        a = acc[i].tolist()
        q = quat[i].tolist()
        yield ("%.6f,%.6g,%.6g,%.6g,%.7g,%.7g,%.7g,%.7f,%.7f,%.7f,%.7f,%d\n"
               % (i / fs, r10(g[0]), r10(g[1]), r10(g[2]), r10(a[0]), r10(a[1]), r10(a[2]),
                  q[0], q[1], q[2], q[3], int(mov[i])))


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--src", required=True, help="directory holding <trial>.mat")
    ap.add_argument("--dest", required=True, help="output directory (created)")
    ap.add_argument("--sums", default=os.path.join(here, "CSV-SHA256SUMS"),
                    help="trials and the SHA-256 of their CSV text")
    ap.add_argument("--no-check", action="store_true",
                    help="write even when a CSV's SHA-256 differs from the sums file")
    args = ap.parse_args()

    trials = read_sums(args.sums)
    results = []  # (trial, gz bytes)
    bad = []
    for trial, want in trials:
        src = os.path.join(args.src, trial + ".mat")
        if not os.path.isfile(src):
            die(f"missing {src}")
        lines = list(csv_lines(src))
        got = hashlib.sha256("".join(lines).encode("utf-8")).hexdigest()
        status = "ok" if got == want else "MISMATCH"
        print(f"broad2csv: {trial}.csv sha256 {got} {status}")
        if got != want:
            bad.append(trial)
        buf = io.BytesIO()
        with gzip.GzipFile(filename=trial + ".csv", mode="wb", fileobj=buf, compresslevel=9,
                           mtime=GZIP_MTIME.get(trial, 0)) as gz:
            # Line by line through the wrapper's 8 KiB buffer, as the reference copy was written
            # (one big write compresses to other, equally valid, bytes).
            w = io.TextIOWrapper(gz, encoding="utf-8", newline="")
            for line in lines:
                w.write(line)
            w.flush()
            w.detach()
        results.append((trial, buf.getvalue()))
    if bad and not args.no_check:
        die("CSV text differs from " + args.sums + " for: " + ", ".join(bad) + "; nothing written")

    os.makedirs(args.dest, exist_ok=True)
    sums = []
    for trial, data in results:
        name = trial + ".csv.gz"
        tmp = os.path.join(args.dest, "." + name + ".tmp")
        with open(tmp, "wb") as f:
            f.write(data)
        os.replace(tmp, os.path.join(args.dest, name))
        sums.append(f"{hashlib.sha256(data).hexdigest()}  {name}\n")
    with open(os.path.join(args.dest, "SHA256SUMS"), "w", encoding="utf-8") as f:
        f.writelines(sums)
    print(f"broad2csv: wrote {len(results)} files and SHA256SUMS to {args.dest}")


if __name__ == "__main__":
    main()
