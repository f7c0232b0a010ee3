#!/usr/bin/env bash
# The chart of doc/ribbons.md: scenes/ribbon_snapping.prm (w = 8 mm, 105
# points: past the fold to the bifurcation on the unstable branch) and the
# same ribbon 15 mm wide, by continuation in the end rotation phi. Top: the
# apex height y0 / R against phi, stable equilibria solid, unstable ones
# dashed; bottom: the lowest eigenvalue of the tangent.
#
# Usage: bench/ribbon_snapping_chart.sh [RODNET_RUN] [OUTPUT_DIR]
#        (defaults build/release/rodnet-run, doc/)
set -eu
source "$(dirname "$0")/chart_paths.sh"

for w in 8 15; do
  points=$([ "$w" = 8 ] && echo 105 || echo 500)
  cat "$root/scenes/ribbon_snapping.prm" - > "$work/w$w.prm" <<END
subsection Material
  subsection sano-wada ribbon
    set Width = ${w}e-3
  end
end
subsection Solver
  subsection Continuation
    set Max points = $points
  end
end
subsection Output
  set Plot = false
end
END
  "$run" "$work/w$w.prm" --output "$work/w$w" > "$work/w$w.log" 2>&1 || true
  grep -h "limit point at" "$work/w$w.log" | sed "s/^/w = $w mm: /" || true
done

# Columns: step, load_factor, apex_x, apex_y, apex_z, lowest, arclength,
# branch, negative_eigenvalues, stable, in_range; phi = 180 load_factor.
gnuplot <<GP
set terminal pngcairo size 900,800 font ",11"
set output "$out/ribbon_snapping.png"
set datafile separator ","
set multiplot layout 2,1 title "Bent ribbon, ends turned by phi in opposite senses (h = 0.2 mm, R = 108 mm, N = 100)"
set grid
set xrange [0:180]
set key top right
set ylabel "apex height y0 / R"
stable(c) = (column(10) == 1 ? c : 1/0)
unstable(c) = (column(10) == 0 ? c : 1/0)
plot "$work/w8/probes.csv" every ::1 using (180*\$2):(stable(\$4/0.108)) with lines lw 2 lc rgb "#c00000" title "w = 8 mm, stable", \
     "" every ::1 using (180*\$2):(unstable(\$4/0.108)) with lines lw 2 dt 2 lc rgb "#c00000" title "w = 8 mm, unstable", \
     "$work/w15/probes.csv" every ::1 using (180*\$2):(stable(\$4/0.108)) with lines lw 2 lc rgb "#0050c0" title "w = 15 mm, stable"
set xlabel "phi [deg]"
set ylabel "lowest eigenvalue of the tangent"
set key bottom left
set yrange [-4e-5:2.4e-4]
plot 0 with lines lc rgb "black" notitle, \
     "$work/w8/probes.csv" every ::1 using (180*\$2):(stable(\$6)) with lines lw 2 lc rgb "#c00000" title "w = 8 mm, stable", \
     "" every ::1 using (180*\$2):(unstable(\$6)) with lines lw 2 dt 2 lc rgb "#c00000" title "w = 8 mm, unstable", \
     "$work/w15/probes.csv" every ::1 using (180*\$2):(stable(\$6)) with lines lw 2 lc rgb "#0050c0" title "w = 15 mm, stable"
unset multiplot
GP
echo "wrote $out/ribbon_snapping.png"
