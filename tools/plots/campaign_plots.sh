#!/bin/sh
# campaign_plots.sh - the plots of docs/campaign.md from the EPB campaign's CSV files:
#   tools/plots/campaign_plots.sh <host build dir> <campaign.csv> <out dir>
# <campaign.csv> is written by `epb_campaign --csv` (one row per estimate); Table 1's CSV is made
# here with `epb_campaign --table1 --csv`. Writes into <out dir>:
#   campaign_vs_slope.png  error of every valid estimate and its bound (+-) against the true slope
#   campaign_vs_temp.png   the same against the true temperature
#   campaign_budget.png    [ADI-EPB]'s Table 1 terms as bars: the article's, and this pipeline's
#                          measured (before and after calibration), mg, log scale
# gnuplot (Debian gnuplot-nox, pngcairo). Data: simulated (tools/epb_campaign).
set -eu
build="${1:?usage: campaign_plots.sh <host build dir> <campaign.csv> <out dir>}"
csv="${2:?campaign CSV}"
out="${3:?output dir}"
command -v gnuplot >/dev/null || { echo "gnuplot not found (apt-get install gnuplot-nox)" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$build/tools/epb_campaign/epb_campaign" --table1 --csv "$tmp/table1.csv" > "$tmp/table1.txt"
n=$(awk -F, 'NR > 1 && $12 == 1 { v++ } END { print v + 0 }' "$csv")
cases=$(awk -F, 'NR > 1 { c[$1] = 1 } END { print length(c) }' "$csv")
gnuplot <<GP
set terminal pngcairo size 1000,520 font "DejaVu Sans,10" noenhanced
set datafile separator ","
set key top left
set grid
set ylabel "slope error, deg"
set yrange [-1.2:1.2]
set output "$out/campaign_vs_slope.png"
set title "EPB campaign: $n valid estimates of $cases cases (simulated, tools/epb_campaign): error and bound against the true slope"
set xlabel "true slope, deg (cross slope -30..30 deg, -40..85 degC)"
plot "$csv" every ::1 using (\$12 == 1 ? \$5 : 1/0):10 with points pt 7 ps 0.2 lc rgb "#a0a0a0" title "+bound", \
     "" every ::1 using (\$12 == 1 ? \$5 : 1/0):(-\$10) with points pt 7 ps 0.2 lc rgb "#a0a0a0" title "-bound", \
     "" every ::1 using (\$12 == 1 ? \$5 : 1/0):11 with points pt 7 ps 0.25 lc rgb "#1f5fbf" title "error (valid)", \
     0.25 with lines dt 2 lc rgb "#c03030" title "+-0.25 deg (the figure to reach)", -0.25 with lines dt 2 lc rgb "#c03030" notitle
set output "$out/campaign_vs_temp.png"
set title "EPB campaign: error and bound against the true temperature (cold starts: still changing)"
set xlabel "true temperature, degC"
plot "$csv" every ::1 using (\$12 == 1 ? \$7 : 1/0):10 with points pt 7 ps 0.2 lc rgb "#a0a0a0" title "+bound", \
     "" every ::1 using (\$12 == 1 ? \$7 : 1/0):(-\$10) with points pt 7 ps 0.2 lc rgb "#a0a0a0" title "-bound", \
     "" every ::1 using (\$12 == 1 && \$17 == 0 ? \$7 : 1/0):11 with points pt 7 ps 0.25 lc rgb "#1f5fbf" title "error, steady temperature", \
     "" every ::1 using (\$12 == 1 && \$17 == 1 ? \$7 : 1/0):11 with points pt 7 ps 0.25 lc rgb "#e08000" title "error, cold start", \
     0.25 with lines dt 2 lc rgb "#c03030" title "+-0.25 deg", -0.25 with lines dt 2 lc rgb "#c03030" notitle
set output "$out/campaign_budget.png"
set title "[ADI-EPB] Table 1 term by term: the article's figures and this pipeline's, each term measured alone"
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.8 border -1
set boxwidth 0.9
set logscale y
set yrange [0.005:2000]
unset xlabel
set ylabel "error term, mg (worst case, slope axis)"
set xtics rotate by -15
set key top left horizontal
plot "$tmp/table1.csv" every ::1 using 2:xticlabels(1) title "article, before" lc rgb "#f0a0a0", \
     "" every ::1 using 3 title "article, after" lc rgb "#c03030", \
     "" every ::1 using 6 title "ours (measured), before" lc rgb "#a0c0f0", \
     "" every ::1 using 7 title "ours (measured), after" lc rgb "#1f5fbf"
GP
echo "wrote $out/campaign_vs_slope.png $out/campaign_vs_temp.png $out/campaign_budget.png"
