#!/bin/sh
# cal_faces.sh - the residual | |a| - 1 g | per static row (face) before and after the
# calibration, from `calstation fit --faces-csv` (docs/calibration.md, "Plots").
#   tools/plots/cal_faces.sh <faces.csv> <out.png> [title]
# Left: before (nominal scale only). Right: after, for the per-axis pair method and the
# nominal-direction fit (double-precision models) and the record through the firmware's
# fixed-point correction (firmware_mg: the fit the record holds, --fit auto's choice).
# gnuplot (Debian gnuplot-nox, pngcairo).
set -eu
csv="${1:?usage: cal_faces.sh <faces.csv> <out.png> [title]}"
png="${2:?output PNG}"
title="${3:-calstation fit: residual per face}"
command -v gnuplot >/dev/null || { echo "gnuplot not found (apt-get install gnuplot-nox)" >&2; exit 1; }
gnuplot <<GP
set terminal pngcairo size 1100,420 font ",10"
set output "$png"
set datafile separator ","
set multiplot layout 1,2 title "$title"
set key top left
set xlabel "static row (face)"
set ylabel "| |a| - 1 g |, mg"
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.8 border -1
set boxwidth 0.9
set grid ytics
set title "before: nominal scale"
plot "$csv" every ::1 using (abs(\$8)):xtic(1) title "none"
set title "after"
set logscale y
set yrange [1e-4:*]
set ylabel "| |a| - 1 g |, mg (log)"
plot "$csv" every ::1 using (abs(\$9)+1e-5):xtic(1) title "per-axis pair", \
     "" every ::1 using (abs(\$10)+1e-5) title "nominal directions", \
     "" every ::1 using (abs(\$14)+1e-5) title "the record, through the firmware"
unset multiplot
GP
echo "wrote $png"
