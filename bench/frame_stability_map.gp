# Chart of bench/frame_stability_map (doc/dynamics.md, "Stability map on
# the frame"): error of the tip against the time step per integrator,
# runs that stopped early marked with a cross at the error of what they
# reached. Usage:
#   gnuplot -e "csv='frame_stability_map.csv'; out='doc/frame_stability_map.png'" bench/frame_stability_map.gp
if (!exists("csv")) csv = 'frame_stability_map.csv'
if (!exists("out")) out = 'frame_stability_map.png'

set terminal pngcairo size 800,520 font ",11"
set output out
set datafile separator comma
set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set grid
set key bottom right
set xlabel "time step h (s)"
set ylabel "largest tip error / L, t = 1 ... 6 s"
set title "Free-flying frame: accuracy and failures of the integrators"

# Series by the integrator name in column 1 (quoted in the CSV); column 6
# is 1 where the run stopped early.
completed(name, y) = (strcol(1) eq name && column(6) == 0) ? y : 1/0
stopped(name, y)   = (strcol(1) eq name && column(6) == 1) ? y : 1/0
n1 = "backward euler"; n2 = "newmark"; n3 = "midpoint"; n4 = "generalized alpha"
name(i) = value(sprintf("n%d", i))

plot for [i=1:4] csv skip 1 using 2:(completed(name(i), $3)) \
       with linespoints lw 2 pt 7 lc i title name(i), \
     for [i=1:4] csv skip 1 using 2:(stopped(name(i), $3)) \
       with points pt 2 ps 2 lw 2 lc i title name(i).", stopped"
