# Displacement-time plot of the viscoelastic hexagonal truss
# (scenes/hexagonal_truss.prm, Lestringant & Kochmann Fig. 5): w(t)/L of
# the midpoint of the lower boundary after the release at t = 0.
#   build/release/rodnet-run scenes/hexagonal_truss.prm --output /tmp/hex
#   gnuplot -e "csv='/tmp/hex/probes.csv'; out='doc/hexagonal_truss.png'" \
#     bench/hexagonal_truss.gp
if (!exists("csv")) csv = 'probes.csv'
if (!exists("out")) out = 'hexagonal_truss.png'
L = 0.01

set terminal pngcairo size 900,520 font ",11"
set output out
set datafile separator comma
set xlabel "t (s)"
set ylabel "w / L"
set title "Viscoelastic hexagonal truss, held 5 s and released at t = 0 (Newmark, dt = t_e/20)"
set grid
set key off
set xrange [0:0.2]
plot csv every ::1 using 2:($2 >= 0 ? $3/L : 1/0) with lines lw 1.5 lc rgb "#1f77b4"
