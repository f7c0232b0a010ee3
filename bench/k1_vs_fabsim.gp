# K1 chart: hinges per second of rodnet's kernels against fabsim
# (/work/shared/BENCHMARKS.md) and the goals of issue 13, for the energy,
# gradient and Hessian assembled into a sparse matrix and for the gradient
# alone, at N = 1e3 and 1e5, one thread. Reads the two CSV files
# kernel_throughput writes: its rates, and fabsim's it read from
# BENCHMARKS.md (kernel_throughput_peers.csv), each bar labelled with the
# date of its figure. Run from the directory that holds them:
#   gnuplot -e "csv='kernel_throughput.csv'; out='doc/k1_vs_fabsim.png'" \
#     bench/k1_vs_fabsim.gp
if (!exists("csv")) csv = 'kernel_throughput.csv'
if (!exists("peers")) peers = 'kernel_throughput_peers.csv'
if (!exists("out")) out = 'k1_vs_fabsim.png'

set terminal pngcairo size 900,560 font ",11"
set output out
set datafile separator comma
set logscale y
set format y "10^{%L}"
set yrange [1e4:1e8]
set ylabel "hinges per second (log scale)"
set title "K1 hinge kernel throughput, one thread: rodnet against fabsim"
set key top left box opaque
set grid ytics lc rgb "#dddddd"
set style fill solid 0.85 border -1
set boxwidth 0.2
set xrange [-0.6:3.6]
set bmargin 4
set xtics ("E+g+H assembled\nN = 1e3" 0, "E+g+H assembled\nN = 1e5" 1, \
           "gradient assembled\nN = 1e3" 2, "gradient assembled\nN = 1e5" 3)

# Goals of issue 13: 3x fabsim for E+g+H (>= 1e6), 2x for the gradient
# (>= 9e6).
$goal << EOD
0,1e6
1,1e6
2,9e6
3,9e6
EOD

slot(n, figure) = (figure eq "assembled_egh" ? 0 : \
                   figure eq "assembled_gradient" ? 2 : -10) + (n == 100000 ? 1 : 0)
row(kernel) = (strcol(2) eq kernel && strcol(3) eq "1") ? \
              slot(column(1), strcol(4)) : NaN

# kernel_throughput_peers.csv: N, code, figure, hinges_per_s, date.
peer(code) = (strcol(2) eq code ? slot(column(1), strcol(3)) - 0.22 : NaN)
plot peers using (peer("fabsim")):4 every ::1 with boxes lc rgb "#888888" \
         title "fabsim (BENCHMARKS.md, date above each bar)", \
     peers using (peer("fabsim")):4:(strcol(5)) every ::1 with labels \
         rotate by 90 left offset 0,0.5 font ",8" notitle, \
     csv using (row("simple")):5 every ::1 with boxes lc rgb "#1f77b4" \
         title "rodnet, simple kernel", \
     csv using (row("classic") + 0.22):5 every ::1 with boxes lc rgb "#ff7f0e" \
         title "rodnet, classic kernel", \
     $goal using ($1 - 0.35):2:(0.7):(0) with vectors nohead dt 2 lw 2 \
         lc rgb "#d62728" title "goal of issue 13"
