#!/bin/sh
# att_error_bound.sh - plot the inclination error of the attitude estimate and its stated bound
# against time for one recording with truth (docs/attitude.md, "Plots").
#   tools/plots/att_error_bound.sh <host build dir> <trial.csv[.gz]> <out.png> [imu_replay options]
# Steps: imu_replay (its defaults: the 3D estimator att; any option after out.png is passed on,
# e.g. --estimator adapt) writes the estimate; att_score prints the trial's key=value summary;
# a small python3 step computes the per-sample inclination error of the BROAD metric
# (q_err = q_est * inverse(q_truth), 2 acos(min(1, sqrt(w^2 + z^2))), as tools/lib/attscore);
# gnuplot (Debian gnuplot-nox, pngcairo) draws error, bound and the valid flag. The temporary
# files are removed; only the PNG is written. A plot of BROAD data must carry its attribution
# (BROAD, Laidig et al. 2021, CC BY 4.0); the title does. For other data set DATA_NOTE, e.g.
# DATA_NOTE="Data: simulated, tools/vehicle_sim --scenario cornering".
set -eu
build="${1:?usage: att_error_bound.sh <host build dir> <trial.csv[.gz]> <out.png> [imu_replay options]}"
trial="${2:?trial CSV}"
png="${3:?output PNG}"
shift 3
command -v gnuplot >/dev/null || { echo "gnuplot not found (apt-get install gnuplot-nox)" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$build/tools/imu_replay/imu_replay" "$@" -o "$tmp/est.csv" "$trial" 2>"$tmp/replay.log"
"$build/tools/att_score/att_score" "$trial" "$tmp/est.csv" --name "$(basename "$trial" .csv.gz)" \
    | tee "$tmp/score.txt"
python3 - "$trial" "$tmp/est.csv" "$tmp/plot.dat" <<'PY'
import csv, gzip, math, sys
truth_path, est_path, out_path = sys.argv[1:4]
op = gzip.open if truth_path.endswith(".gz") else open
with op(truth_path, "rt") as ft, open(est_path) as fe, open(out_path, "w") as fo:
    rt, re_ = csv.DictReader(ft), csv.DictReader(fe)
    fo.write("# t_s err_deg bound_deg valid scored\n")
    for a, b in zip(rt, re_):
        t = float(a["t_s"])
        qt = [float(a[k]) for k in ("truth_qw", "truth_qx", "truth_qy", "truth_qz")]
        qe = [float(b[k]) for k in ("q_w", "q_x", "q_y", "q_z")]
        if not all(math.isfinite(v) for v in qt):
            continue
        # q_err = qe * conj(qt); only its w and z components are needed
        w = qe[0] * qt[0] + qe[1] * qt[1] + qe[2] * qt[2] + qe[3] * qt[3]
        z = -qe[0] * qt[3] - qe[1] * qt[2] + qe[2] * qt[1] + qe[3] * qt[0]
        n = math.sqrt(sum(v * v for v in qe) * sum(v * v for v in qt))
        err = math.degrees(2 * math.acos(min(1.0, math.sqrt(w * w + z * z) / n)))
        scored = 1 if (a["movement"] == "1" and t >= 5) else 0
        fo.write("%.4f %.4f %.4f %s %d\n" % (t, err, float(b["att_bound_deg"]), b["att_valid"], scored))
PY
name=$(basename "$(basename "$trial" .gz)" .csv)
note="${DATA_NOTE:-Data: BROAD, Laidig et al. 2021, CC BY 4.0}"
opts="${*:-defaults (att)}"
gnuplot <<GP
set terminal pngcairo size 1100,520 font "DejaVu Sans,10" noenhanced
set output "$png"
set title "Inclination error and its stated bound, imu_replay $opts, $name\n$note"
set xlabel "time (s)"
set ylabel "deg"
set yrange [0:10]
set key outside bottom center horizontal
set grid
plot "$tmp/plot.dat" using 1:(\$4 > 0 ? 9.6 : 1/0) with points pt 5 ps 0.3 lc rgb "#2ca02c" title "att_valid (drawn at 9.6 where 1)", \
     "" using 1:3 with lines lw 1.5 lc rgb "#d62728" title "bound (99.9 %)", \
     "" using 1:2 with lines lw 1 lc rgb "#1f77b4" title "inclination error"
GP
echo "wrote $png"
