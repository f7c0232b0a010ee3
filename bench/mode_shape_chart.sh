#!/usr/bin/env bash
# The mode shape chart of doc/continuation.md: the 4 lowest eigenpairs that
# Output/Mode shapes writes for the elastica's column (scenes/elastica.prm:
# clamped-free, EI = 1, L = 1) under the axial end load P = 2, just below
# its buckling load pi^2/4, read back from modes-NNNNN.vtu as users get
# them, each drawn against the beam-column's analytic mode
# (bench/beam_column_modes.py) and titled with its eigenvalue.
#
# Usage: bench/mode_shape_chart.sh [RODNET_RUN] [OUTPUT_DIR]
#        (defaults build/release/rodnet-run, doc/)
set -eu
source "$(dirname "$0")/chart_paths.sh"
load=2

# Out of the plane and in torsion the column is made 1e4 times stiffer, so
# that the 4 lowest modes are the in-plane bending ones (with EI2 = 10 and
# GJ = 1 four twist modes and an out-of-plane one come between the first
# two); no imperfection, so the column stays straight.
cat "$root/scenes/elastica.prm" - > "$work/column.prm" <<END
subsection Material
  subsection linear elastic
    set EI2 = 1e4
    set GJ = 1e4
  end
end
subsection Loads
  set Steps = 1
  set Point forces = end: -$load, 0, 0
end
subsection Solver
  set Critical load search = false
end
subsection Output
  set Plot = false
  set Mode shapes = 4
end
END
"$run" "$work/column.prm" --output "$work/column" > "$work/column.log" 2>&1
python3 "$root/bench/beam_column_modes.py" "$load" 4 > "$work/reference.txt"
for k in 1 2 3 4; do
  python3 "$root/bench/vtu_table.py" "$work/column/modes-0000$k.vtu" \
    displacement > "$work/mode$k.txt"
done

# The eigenvalues are h mu (h the segment length): their ratios to the
# first are free of h and of how the norm weighs the tip vertex.
lambda=($(sed 1d "$work/column/modes.csv" | cut -d, -f2))
mu=($(sed -n 's/^# mode [0-9]* //p' "$work/reference.txt"))
echo "mode  lambda (rodnet)  lambda/lambda_1  mu/mu_1 (beam-column)"
for k in 0 1 2 3; do
  awk -v k=$((k + 1)) -v l="${lambda[k]}" -v l1="${lambda[0]}" \
    -v m="${mu[k]}" -v m1="${mu[0]}" \
    'BEGIN { printf "%4d  %15.6g  %15.6g  %15.6g\n", k, l, l / l1, m / m1 }'
done

# Columns of a mode's table: position x y z, then the displacement from
# the unloaded rod (x y z); the mode is the y displacement (the equilibrium
# is straight), scaled to +1 at its largest, the tip, like the reference.
gnuplot <<GP
set terminal pngcairo size 1400,380 font ",11"
set output "$out/mode_shapes.png"
set multiplot layout 1,4 title "elastica column (clamped-free) under P = $load EI/L^2, 0.81 of its buckling load: the 4 lowest eigenpairs of Output/Mode shapes"
set xrange [-0.1:1.15]
set yrange [-1.3:1.3]
set xlabel "x / L"
set grid
set key bottom left font ",9"
set object 1 rectangle from -0.06,-0.6 to 0,0.6 fillstyle pattern 4 fillcolor rgb "gray40"
set arrow 1 from 1.14,0 to 1.02,0 lw 2 lc rgb "#d62728" front
array lambda[4] = [${lambda[*]/%/,}]
array mu[4] = [${mu[*]/%/,}]
do for [k = 1:4] {
  stats "$work/mode".k.".txt" using 5 nooutput
  scale = abs(STATS_max) > abs(STATS_min) ? STATS_max : STATS_min
  set title sprintf("mode %d: lambda = %.4g\nlambda/lambda_1 = %.4g (theory %.4g)", \
    k, lambda[k], lambda[k] / lambda[1], mu[k] / mu[1])
  set ylabel (k == 1 ? "w / w(L)" : "")
  plot 0 with lines lw 4 lc rgb "gray70" title "undeformed", \
       "$work/mode".k.".txt" using (\$1 - \$4):(\$5 / scale) with lines lw 3 lc rgb "#1f77b4" title "rodnet (VTU)", \
       "$work/reference.txt" index (k - 1) using 1:2 with lines dt 2 lw 2 lc rgb "black" title "beam-column"
}
unset multiplot
GP
echo "chart in $out: mode_shapes.png"
