#!/bin/sh
# Plots energy against time for the three methods from the traces that
# `fairing_table1 --traces DIR` writes, with Debian's gnuplot (package gnuplot-nox).
#
#   plot_energy_time.sh DIR [CASE] [OUT]
#
# CASE names the traces, default L1_eps0.25 (the bunny Loop subdivided once, 301,632
# triangles, epsilon = 0.25 h); OUT defaults to DIR/energy_time_CASE.png.
set -eu
dir="$1"
case="${2:-L1_eps0.25}"
out="${3:-$dir/energy_time_$case.png}"
for method in quasi_newton newton gradient; do
  [ -f "$dir/trace_${case}_$method.csv" ] || { echo "missing $dir/trace_${case}_$method.csv" >&2; exit 1; }
done
title=$(echo "$case" | sed 's/^L\([0-9]*\)_eps\(.*\)$/bunny Loop subdivided \1 times, noise 0.25 h, epsilon \2 h/')
gnuplot <<PLOT
set terminal pngcairo size 900,600 font ",11"
set output "$out"
set title "$title"
set xlabel "time (s), including set-up"
set ylabel "bending energy"
set logscale xy
set grid
set key top right
plot "$dir/trace_${case}_quasi_newton.csv" using 2:3 with lines linewidth 2 title "quasi-Newton (default)", \
     "$dir/trace_${case}_newton.csv" using 2:3 with lines linewidth 2 title "active set Newton (paper)", \
     "$dir/trace_${case}_gradient.csv" using 2:3 with lines linewidth 2 title "projected gradient (paper)"
PLOT
echo "$out"
