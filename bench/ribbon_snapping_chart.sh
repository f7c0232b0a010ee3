#!/usr/bin/env bash
# The chart of doc/ribbons.md: scenes/ribbon_snapping.prm as shipped
# (w = 8 mm; Limit points = snap: it snaps at the fold onto the mirror
# image of its own path and goes on to phi = 180 degrees), the same path
# followed back through its fold instead (Limit points = follow, 105
# points: the unstable branch to its bifurcation), and the same ribbon
# 15 mm wide, by continuation in the end rotation phi. Top: the apex
# height y0 / R against phi, stable equilibria solid, unstable ones
# dashed, the snap a dashed black line; bottom: the lowest eigenvalue of
# the tangent.
#
# Usage: bench/ribbon_snapping_chart.sh [RODNET_RUN] [OUTPUT_DIR]
#        (defaults build/release/rodnet-run, doc/)
set -eu
source "$(dirname "$0")/chart_paths.sh"

for run_name in w8 w8follow w15; do
  w=$([ "$run_name" = w15 ] && echo 15 || echo 8)
  limit_points=$([ "$run_name" = w8follow ] && echo follow || echo snap)
  points=$([ "$run_name" = w8follow ] && echo 105 || echo 500)
  cat "$root/scenes/ribbon_snapping.prm" - > "$work/$run_name.prm" <<END
subsection Material
  subsection sano-wada ribbon
    set Width = ${w}e-3
  end
end
subsection Solver
  subsection Continuation
    set Limit points = $limit_points
    set Max points = $points
  end
end
subsection Output
  set Plot = false
end
END
  "$run" "$work/$run_name.prm" --output "$work/$run_name" > "$work/$run_name.log" 2>&1 || true
  grep -h "limit point at\|jump at" "$work/$run_name.log" | sed "s/^/$run_name: /" || true
done

# Columns: step, load_factor, apex_x, apex_y, apex_z, lowest, arclength,
# branch, negative_eigenvalues, stable, in_range, jump; phi = 180
# load_factor. The snap: the row before the one with jump = 1, and that one.
jump="< awk -F, 'NR > 1 && \$12 == 1 { print previous; print } { previous = \$0 }' $work/w8/probes.csv"
gnuplot <<GP
set terminal pngcairo size 900,800 font ",11"
set output "$out/ribbon_snapping.png"
set datafile separator ","
set multiplot layout 2,1 title "Bent ribbon, ends turned by phi in opposite senses (h = 0.2 mm, R = 108 mm, N = 100)"
set grid
set xrange [0:180]
set key bottom left
set ylabel "apex height y0 / R"
stable(c, b) = (column(10) == 1 && column(8) == b ? c : 1/0)
unstable(c) = (column(10) == 0 ? c : 1/0)
plot "$work/w8/probes.csv" every ::1 using (180*\$2):(stable(\$4/0.108, 0)) with lines lw 2 lc rgb "#c00000" title "w = 8 mm, stable", \
     "" every ::1 using (180*\$2):(stable(\$4/0.108, 1)) with lines lw 2 lc rgb "#c00000" notitle, \
     "$jump" using (180*\$2):(\$4/0.108) with lines lw 2 dt 2 lc rgb "black" title "w = 8 mm, snap", \
     "$work/w8follow/probes.csv" every ::1 using (180*\$2):(unstable(\$4/0.108)) with lines lw 2 dt 2 lc rgb "#c00000" title "w = 8 mm, unstable (followed back)", \
     "$work/w15/probes.csv" every ::1 using (180*\$2):(stable(\$4/0.108, 0)) with lines lw 2 lc rgb "#0050c0" title "w = 15 mm, stable"
set xlabel "phi [deg]"
set ylabel "lowest eigenvalue of the tangent"
set key bottom left
set yrange [-4e-5:2.4e-4]
plot 0 with lines lc rgb "black" notitle, \
     "$work/w8/probes.csv" every ::1 using (180*\$2):(stable(\$6, 0)) with lines lw 2 lc rgb "#c00000" title "w = 8 mm, stable", \
     "" every ::1 using (180*\$2):(stable(\$6, 1)) with lines lw 2 lc rgb "#c00000" notitle, \
     "$jump" using (180*\$2):6 with lines lw 2 dt 2 lc rgb "black" title "w = 8 mm, snap", \
     "$work/w8follow/probes.csv" every ::1 using (180*\$2):(unstable(\$6)) with lines lw 2 dt 2 lc rgb "#c00000" title "w = 8 mm, unstable (followed back)", \
     "$work/w15/probes.csv" every ::1 using (180*\$2):(stable(\$6, 0)) with lines lw 2 lc rgb "#0050c0" title "w = 15 mm, stable"
unset multiplot
GP
echo "wrote $out/ribbon_snapping.png"
