# Dynamic relaxation against Newton: error against wall time, both methods,
# one chart per problem. Reads a CSV written by dr_vs_newton; run from the
# directory that holds it (once per problem):
#   gnuplot -e "problem='cantilever'; \
#     name='Cantilever, tip load P = 1e-3 EI/L^2'; \
#     ylabel='|w - PL^3/(3EI)| / (PL^3/(3EI))'" bench/dr_vs_newton.gp
#   gnuplot -e "problem='elastica'; name='Elastica, P = 3 EI/L^2'; \
#     ylabel='max(|x - x_{exact}|, |{/Symbol d} - {/Symbol d}_{exact}|) / L'" \
#     bench/dr_vs_newton.gp
#   gnuplot -e "problem='gridshell'; name='Gridshell (scenes/gridshell.prm)'; \
#     ylabel='error vs Newton, 16 segments per lath (m)'" bench/dr_vs_newton.gp
# Writes doc_dir/dr_vs_newton_<problem>.png (doc_dir defaults to ../../doc,
# the doc folder seen from build/<name>). Points with an error above 0.1
# (the elastica accepted straight, see doc/performance.md) are left out; so
# is the tolerance series' labelling (its points move right as the
# tolerance tightens; the CSV has the values).
if (!exists("problem")) problem = 'cantilever'
if (!exists("name")) name = problem
if (!exists("ylabel")) ylabel = 'error'
if (!exists("doc_dir")) doc_dir = '../../doc'
csv = 'dr_vs_newton_'.problem.'.csv'

set terminal pngcairo size 900,620 font ",11"
set output doc_dir.'/dr_vs_newton_'.problem.'.png'
set datafile separator comma
set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set xlabel "wall time, construction to equilibrium (s), 1 thread"
set ylabel ylabel
set title name." : error vs wall time"
set key top right box opaque font ",10"
set grid xtics ytics mxtics mytics lc rgb "#dddddd"
set offsets graph 0.05, graph 0.05, graph 0.1, graph 0.1

is(v) = (strcol(1) eq v) && ($11 < 0.1)
sweep = (problem ne 'gridshell')

plot \
  csv skip 1 using (is("newton") ? $7 : NaN):11 with linespoints pt 7 \
    ps 1.3 lc rgb "#1f77b4" title "Newton (discrete rods), N segments", \
  csv skip 1 using (is("newton") ? $7 : NaN):11:(sprintf("%d", $2)) \
    with labels offset 0,1 tc rgb "#1f77b4" notitle, \
  csv skip 1 using (is("dynamic relaxation") ? $7 : NaN):11 \
    with linespoints pt 5 ps 1.3 lc rgb "#d62728" \
    title "dynamic relaxation (bending-active element), N segments", \
  csv skip 1 using (is("dynamic relaxation") ? $7 : NaN):11:(sprintf("%d", $2)) \
    with labels offset 0,-1 tc rgb "#d62728" notitle, \
  csv skip 1 using (sweep && is("dynamic relaxation N = 20") ? $7 : NaN):11 \
    with linespoints pt 4 ps 1.6 dt 2 lc rgb "#ff7f0e" \
    title (sweep ? "dynamic relaxation, N = 20, residual tolerance 1e-2 ... 1e-8" : ""), \
  csv skip 1 using (!sweep && is("newton") ? $7 : NaN):12 with points \
    pt 6 ps 2.4 lc rgb "#1f77b4" \
    title (sweep ? "" : "Newton, largest node error"), \
  csv skip 1 using (!sweep && is("dynamic relaxation") ? $7 : NaN):12 \
    with points pt 4 ps 2.4 lc rgb "#d62728" \
    title (sweep ? "" : "dynamic relaxation, largest node error")
