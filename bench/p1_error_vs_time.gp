# P1 chart: tip error against wall time, rodnet beside the peer codes of
# /work/shared/BENCHMARKS.md. Reads the two CSV files p1_gravity_cantilever
# writes: its points, and the peer rows it read from BENCHMARKS.md
# (p1_peers.csv), each labelled with the date of its figure. Run from the
# directory that holds them:
#   gnuplot -e "csv='p1_gravity_cantilever.csv'; out='doc/p1_error_vs_time.png'" \
#     bench/p1_error_vs_time.gp
if (!exists("csv")) csv = 'p1_gravity_cantilever.csv'
if (!exists("peers")) peers = 'p1_peers.csv'
if (!exists("out")) out = 'p1_error_vs_time.png'

set terminal pngcairo size 900,620 font ",11"
set output out
set datafile separator comma
set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set xrange [1e-3:1e3]
set yrange [3e-7:5e-2]
set xlabel "wall time from model construction to equilibrium (s), 1 thread"
set ylabel "tip error |tip - exact| (m), exact (0.5157790, -0.7938299)"
set title "P1 gravity cantilever (q L^3/EI = 15.7): tip error vs wall time"
set key top left box opaque
set grid xtics ytics mxtics mytics lc rgb "#dddddd"

# rodnet-run scenes/p1_gravity_cantilever.prm as a whole process (start-up
# included; doc/performance.md, "Start-up", 2026-12-03): time (s), tip
# error, N.
$rodnet_process << EOD
0.551,3.40e-5,1000
EOD

is(v) = (strcol(1) eq v)
# p1_peers.csv: code, method, N, time_s, z_error, x_error, tip_error,
# whole_process_s, date; the tip error is the z error alone where
# BENCHMARKS.md gives no x error.
peer_label(c) = is(c) ? sprintf("N=%d\n%s", $3, strcol(9)) : ""
plot \
  peers skip 1 using (is("DisMech") ? $4 : NaN):7 with points pt 5 ps 1.4 \
    lc rgb "#d62728" \
    title "DisMech tuned (dynamics to rest, dt 0.1-2; dt 0.1: z error only), in process", \
  peers skip 1 using (is("DisMech") ? $8 : NaN):7 with points pt 4 ps 1.4 \
    lc rgb "#d62728" title "DisMech tuned, whole process", \
  peers skip 1 using (is("DisMech") ? $4 : NaN):7:(peer_label("DisMech")) \
    with labels offset 0,-1.5 font ",8" tc rgb "#d62728" notitle, \
  peers skip 1 using (is("DRMSimulationModel") ? $4 : NaN):7 \
    with linespoints pt 9 ps 1.6 lc rgb "#2ca02c" \
    title "DRMSimulationModel (dynamic relaxation; z error only)", \
  peers skip 1 using (is("DRMSimulationModel") ? $4 : NaN):7:\
    (peer_label("DRMSimulationModel")) with labels offset 0,-1.5 font ",8" \
    tc rgb "#2ca02c" notitle, \
  csv skip 1 using (is("P1") ? $5 : NaN):12 with linespoints pt 7 ps 1.4 \
    lc rgb "#1f77b4" title "rodnet, static Newton (EA = 7854 N, as P1)", \
  csv skip 1 using (is("P1") ? $5 : NaN):12:(sprintf("%d", $2)) \
    with labels offset 0,1 tc rgb "#1f77b4" notitle, \
  $rodnet_process using 1:2 with points pt 6 ps 1.6 lc rgb "#1f77b4" \
    title "rodnet-run, whole process (N = 1000)", \
  csv skip 1 using (is("EA x 1e3") ? $5 : NaN):12 with linespoints pt 6 \
    ps 1.4 dt 2 lc rgb "#1f77b4" \
    title "rodnet, EA x 1e3 (check: near-inextensible)"
