#!/bin/sh
# nav_track.sh - the plots of docs/navigation.md from nav_demo's CSVs:
#   tools/plots/nav_track.sh <host build dir> <drive> <track.png> <kcurve.png>
# 1. the drive's track: truth, the dead-reckoned track (every 13 ms) and the GPS fixes in the
#    east/north plane, and the track error against its bound over time;
# 2. the blend factor of [KF-SCA3000] (K after 0, 1, 2 and 3 rounds of K = K + (1 - K) K
#    against A, Q = 20) as the firmware's gpsb_factor computes it (nav_demo --kcurve).
# gnuplot (Debian gnuplot-nox, pngcairo). Temporary files are removed; only the PNGs are written.
set -eu
build="${1:?usage: nav_track.sh <host build dir> <drive> <track.png> <kcurve.png>}"
drive="${2:?drive}"
png="${3:?track PNG}"
kpng="${4:?kcurve PNG}"
command -v gnuplot >/dev/null || { echo "gnuplot not found (apt-get install gnuplot-nox)" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$build/tools/nav_demo/nav_demo" --drive "$drive" --csv "$tmp/t.csv" --fixes "$tmp/f.csv" \
    --kcurve "$tmp/k.csv" | tail -1
gnuplot <<GP
set terminal pngcairo noenhanced size 1100,520 font "sans,10"
set output "$png"
set datafile separator ","
set multiplot layout 1,2 title "nav_demo --drive $drive (simulated: sim/vehicle truth, sim/gps fixes)"
set xlabel "east (m)"; set ylabel "north (m)"; set size ratio -1; set key top left
plot "$tmp/t.csv" every ::1 using 2:3 with lines lw 2 lc rgb "black" title "truth", \
     "$tmp/t.csv" every ::1 using 4:5 with lines lw 1 lc rgb "#d62728" title "dead reckoning (13 ms)", \
     "$tmp/f.csv" every ::1 using (\$3 == 1 ? \$5 : 1/0):6 with points pt 7 ps 0.6 lc rgb "#1f77b4" title "GPS fixes"
set size noratio
set xlabel "t (s)"; set ylabel "m"; set key top left; set logscale y
plot "$tmp/t.csv" every ::1 using 1:(sqrt((\$4-\$2)**2+(\$5-\$3)**2)+0.001) with lines lc rgb "#d62728" title "|track - truth|", \
     "$tmp/t.csv" every ::1 using 1:(\$7 == 1 ? \$6 : 1/0) with lines lc rgb "#2ca02c" title "bound (valid)"
unset multiplot
GP
gnuplot <<GP
set terminal pngcairo size 800,480 font "sans,10"
set output "$kpng"
set datafile separator ","
set title "Blend factor K against A (Q = 20), firmware gpsb\\\\_factor"
set xlabel "A (same unit as Q)"; set ylabel "K"; set key bottom right; set yrange [0:1.05]
set arrow from 20,0 to 20,1.05 nohead dt 2 lc rgb "black"
plot "$tmp/k.csv" every ::1 using 1:2 with lines lw 2 lc rgb "#1f77b4" title "sqrt(A^2/(A^2+Q^2))", \
     "$tmp/k.csv" every ::1 using 1:3 with lines lw 2 lc rgb "#d62728" title "1 round of K = K + (1-K) K", \
     "$tmp/k.csv" every ::1 using 1:4 with lines lw 2 lc rgb "#2ca02c" title "2 rounds", \
     "$tmp/k.csv" every ::1 using 1:5 with lines lw 2 lc rgb "#9467bd" title "3 rounds"
GP
