# Junction convergence charts: relative error against the Richardson
# reference, vs mesh size and vs wall time, "simple" and "classic" kernels.
# Reads the CSVs written by junction_convergence; run from the directory
# that holds them (once per study):
#   gnuplot -e "csv='frame_convergence.csv'; out='doc/frame_convergence.png'; \
#     name='Frame (Fig. 3a), F at u_z/L = 1'; nlabel='segments per leg N'" \
#     bench/junction_convergence.gp
#   gnuplot -e "csv='windmill_convergence.csv'; \
#     out='doc/windmill_convergence.png'; \
#     name='Windmill (Fig. 3b), M at tau_z = 1.5 rad'; \
#     nlabel='segments per blade n (shaft 2n)'" bench/junction_convergence.gp
if (!exists("csv")) csv = 'frame_convergence.csv'
if (!exists("out")) out = 'frame_convergence.png'
if (!exists("name")) name = 'Frame (Fig. 3a)'
if (!exists("nlabel")) nlabel = 'N'

set terminal pngcairo size 1200,520 font ",11"
set output out
set datafile separator comma
set logscale xy
set format y "10^{%L}"
set key top right box opaque
set grid xtics ytics mxtics mytics lc rgb "#dddddd"
set ylabel "relative error vs Richardson reference"

is(v) = (strcol(1) eq v)
set multiplot layout 1,2 title name

set xlabel nlabel
set format x "%g"
plot \
  csv skip 1 using (is("simple") ? $2 : NaN):5 with linespoints pt 7 \
    ps 1.3 lc rgb "#1f77b4" title "simple", \
  csv skip 1 using (is("classic") ? $2 : NaN):5 with linespoints pt 5 \
    ps 1.3 lc rgb "#d62728" title "classic"

set xlabel "wall time, construction to equilibrium (s), 1 thread"
set format x "10^{%L}"
plot \
  csv skip 1 using (is("simple") ? $6 : NaN):5 with linespoints pt 7 \
    ps 1.3 lc rgb "#1f77b4" title "simple", \
  csv skip 1 using (is("simple") ? $6 : NaN):5:(sprintf("%d", $2)) \
    with labels offset 0,1 tc rgb "#1f77b4" notitle, \
  csv skip 1 using (is("classic") ? $6 : NaN):5 with linespoints pt 5 \
    ps 1.3 lc rgb "#d62728" title "classic", \
  csv skip 1 using (is("classic") ? $6 : NaN):5:(sprintf("%d", $2)) \
    with labels offset 0,-1 tc rgb "#d62728" notitle

unset multiplot
