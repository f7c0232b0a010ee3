# P1 chart: tip error in z against wall time, rodnet beside the peer codes
# of /work/shared/BENCHMARKS.md. Reads the CSV written by
# p1_gravity_cantilever; run from the directory that holds it:
#   gnuplot -e "csv='p1_gravity_cantilever.csv'; out='doc/p1_error_vs_time.png'" \
#     bench/p1_error_vs_time.gp
if (!exists("csv")) csv = 'p1_gravity_cantilever.csv'
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
set ylabel "|z_{tip} - z_{exact}| (m), z_{exact} = -0.7938299"
set title "P1 gravity cantilever (q L^3/EI = 15.7): tip error vs wall time"
set key top left box opaque
set grid xtics ytics mxtics mytics lc rgb "#dddddd"

# Peer figures of BENCHMARKS.md (re-measured 2026-12-01, DisMech tuned as a
# fair user would): time in process (s), tip error, N, whole process (s).
$dismech << EOD
0.061,5.0e-4,50,0.089
0.047,1.6e-6,200,0.083
0.212,3.3e-5,1000,0.279
EOD
# rodnet-run scenes/p1_gravity_cantilever.prm as a whole process (start-up
# included; doc/performance.md, "Start-up"): time (s), tip error, N.
$rodnet_process << EOD
0.551,3.36e-5,1000
EOD
$drm << EOD
7.25,2.6e-4,50
327,5e-5,200
EOD

is(v) = (strcol(1) eq v)
plot \
  $dismech using 1:2 with points pt 5 ps 1.4 lc rgb "#d62728" \
    title "DisMech tuned (implicit dynamics to rest, dt 0.1-2), in process", \
  $dismech using 4:2 with points pt 4 ps 1.4 lc rgb "#d62728" \
    title "DisMech tuned, whole process", \
  $dismech using 1:2:(sprintf("N=%d", $3)) with labels offset 0,1 \
    tc rgb "#d62728" notitle, \
  $drm using 1:2 with linespoints pt 9 ps 1.6 lc rgb "#2ca02c" \
    title "DRMSimulationModel (dynamic relaxation)", \
  $drm using 1:2:(sprintf("N=%d", $3)) with labels offset 0,-1 \
    tc rgb "#2ca02c" notitle, \
  csv skip 1 using (is("P1") ? $5 : NaN):10 with linespoints pt 7 ps 1.4 \
    lc rgb "#1f77b4" title "rodnet, static Newton (EA = 7854 N, as P1)", \
  csv skip 1 using (is("P1") ? $5 : NaN):10:(sprintf("%d", $2)) \
    with labels offset 0,1 tc rgb "#1f77b4" notitle, \
  $rodnet_process using 1:2 with points pt 6 ps 1.6 lc rgb "#1f77b4" \
    title "rodnet-run, whole process (N = 1000)", \
  csv skip 1 using (is("EA x 1e3") ? $5 : NaN):10 with linespoints pt 6 \
    ps 1.4 dt 2 lc rgb "#1f77b4" \
    title "rodnet, EA x 1e3 (check: near-inextensible)"
