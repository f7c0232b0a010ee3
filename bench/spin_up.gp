# Tip deflection in the hub's frame during and after the spin-up of a
# flexible beam (Kane, Ryan & Banerjee 1987; doc/dynamics.md, "Moving
# supports"): the rod against KRB's reduced model with the centrifugal
# stiffening, and the linear model without it, which diverges.
#   spin_up 20 0.01 30 "generalized alpha" > /tmp/spin_up.csv   (bench/spin_up.cc)
#   gnuplot -e "csv='/tmp/spin_up.csv'; out='doc/spin_up.png'" bench/spin_up.gp
if (!exists("csv")) csv = 'spin_up.csv'
if (!exists("out")) out = 'spin_up.png'

set terminal pngcairo size 900,520 font ",11"
set output out
set datafile separator comma
set xlabel "t (s)"
set ylabel "tip deflection in the hub's frame (m)"
set title "Spin-up to 6 rad/s in 15 s: L = 10 m, EI = 1.4e4 N m^2, rho A = 1.2 kg/m (N = 20, generalized alpha, h = 0.01 s)"
set grid
set key bottom right
set xrange [0:30]
set yrange [-1:0.4]
plot csv every ::1 using 1:4 with lines lw 1.5 dt 2 lc rgb "#999999" title "reduced model without stiffening (linear)", \
     csv every ::1 using 1:3 with lines lw 3 lc rgb "#ff7f0e" title "reduced model with centrifugal stiffening (KRB)", \
     csv every ::1 using 1:2 with lines lw 1.5 lc rgb "#1f77b4" title "rodnet (geometrically exact rod)"
