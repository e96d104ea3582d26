#!/bin/sh
# cal_tmodel.sh - the temperature models against the soak data of one axis, from
# `calstation fit --tcsv` (docs/calibration.md, "Plots").
#   tools/plots/cal_tmodel.sh <tfits.csv> <axis x|y|z> <out.png> [title]
# Left: bias B(T), mg; right: scale-factor deviation, ppm; points: the flip of every block
# (soak); lines: each fitted model (linear, 3-point, lorentz, pwl, lorentz+cubic).
set -eu
csv="${1:?usage: cal_tmodel.sh <tfits.csv> <axis> <out.png> [title]}"
axis="${2:?axis x, y or z}"
png="${3:?output PNG}"
title="${4:-calstation fit: temperature models, axis $axis}"
command -v gnuplot >/dev/null || { echo "gnuplot not found (apt-get install gnuplot-nox)" >&2; exit 1; }
gnuplot <<GP
set terminal pngcairo size 1100,420 font ",10"
set output "$png"
set datafile separator ","
set multiplot layout 1,2 title "$title"
set key bottom right font ",8"
set grid
set xlabel "temperature, degC"
sel(src, col) = (strcol(1) eq src && strcol(2) eq "$axis") ? column(col) : NaN
models = "linear 3-point lorentz pwl lorentz+cubic"
set ylabel "bias, mg"
plot "$csv" using 3:(sel("data", 4)) with points pt 7 ps 0.4 lc rgb "black" title "soak data (every block)", \
     for [m in models] "$csv" using 3:(sel(m, 4)) with lines lw 1.5 title m
set ylabel "(K(T) - K(tref)) / K(tref), ppm"
plot "$csv" using 3:(sel("data", 5)) with points pt 7 ps 0.4 lc rgb "black" title "soak data (every block)", \
     for [m in models] "$csv" using 3:(sel(m, 5)) with lines lw 1.5 title m
unset multiplot
GP
echo "wrote $png"
