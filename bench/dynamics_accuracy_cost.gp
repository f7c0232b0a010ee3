# Chart of bench/dynamics_accuracy (doc/dynamics.md, "Cost of a step, and
# accuracy against cost"): the cantilever's first-period error against the
# DoFs and against the wall time per simulated period, per integrator, space
# and time refined together (T / (2N) steps). Run from the directory holding
# dynamics_accuracy.csv:
#   gnuplot -e "doc_dir='/path/to/doc'" /path/to/bench/dynamics_accuracy_cost.gp
# Writes doc_dir/dynamics_accuracy_cost.png.
if (!exists("doc_dir")) doc_dir = '../../doc'

set terminal pngcairo size 1100,480 font ",11"
set datafile separator comma
set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set grid
set key top right

# The CSV goes by N; each integrator's rows, in that order, are read
# through grep (names with a blank cannot be words of a "for [name in
# ...]" list, hence n1..n3). A run that stopped has no error: no point.
n1 = "newmark"; n2 = "midpoint"; n3 = "backward euler"
name(i) = value(sprintf("n%d", i))
csv = 'dynamics_accuracy.csv'
rows(i) = sprintf("< grep '^%s,' %s", name(i), csv)

set output doc_dir.'/dynamics_accuracy_cost.png'
set multiplot layout 1,2 title \
  "Cantilever's first period against Euler-Bernoulli, N segments, steps of T/(2N)"
set ylabel "relative period error"
set xlabel "DoFs"
plot for [i=1:3] rows(i) using 3:5 with linespoints pt 7 title name(i), \
     rows(1) using 3:6 with lines dt 2 lc rgb "gray40" \
       title "space alone (discrete mode)"
set xlabel "wall time per simulated period (s), median of repeats"
plot for [i=1:3] rows(i) using 7:5 with linespoints pt 7 title name(i)
unset multiplot
