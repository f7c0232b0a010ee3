#!/usr/bin/env bash
# The charts of doc/continuation.md: scenes/deep_arch.prm, the elastica
# (scenes/elastica.prm without imperfection, EI2 = 2 EI1, followed to
# P = 20 B/L^2) and scenes/lee_frame.prm by continuation, each drawn as load
# against displacement with stable equilibria solid and unstable ones
# dashed, the tangent's negative eigenvalues and the corrector iterations of
# every step; and the limit loads of Lee's frame at 100 and 200 segments per
# member (the shipped scene has 50). scenes/eigenstrain_column.prm: midspan
# deflection against the eigenstrain's load factor. scenes/rollup_lateral.prm:
# the end moment against the tip's out-of-plane displacement.
#
# Usage: bench/continuation_charts.sh [RODNET_RUN] [OUTPUT_DIR]
#        (defaults build/release/rodnet-run, doc/)
set -eu
source "$(dirname "$0")/chart_paths.sh"

"$run" "$root/scenes/deep_arch.prm" --output "$work/arch" > "$work/arch.log" 2>&1
cat "$root/scenes/elastica.prm" - > "$work/elastica.prm" <<'END'
subsection Material
  subsection linear elastic
    set EI2 = 2
  end
end
subsection Loads
  set Point forces = end: -1, 0, 0
end
subsection Solver
  set Method = continuation
  subsection Continuation
    set Load factor range = -1, 20
    set Initial step = 0.1
  end
end
subsection Output
  set Write VTU = false
  set Probes = tip_x: position end x; tip_y: position end y
end
END
"$run" "$work/elastica.prm" --output "$work/elastica" > "$work/elastica.log" 2>&1
"$run" "$root/scenes/lee_frame.prm" --output "$work/lee" > "$work/lee.log" 2>&1
"$run" "$root/scenes/eigenstrain_column.prm" --output "$work/column" \
  > "$work/column.log" 2>&1
cat "$root/scenes/rollup_lateral.prm" - > "$work/rollup.prm" <<'END'
subsection Output
  set Probes = tip_y: position end y; tip_z: position end z
end
END
"$run" "$work/rollup.prm" --output "$work/rollup" > "$work/rollup.log" 2>&1

# Lee's frame on finer meshes: the load stays at L/5 from the corner,
# vertex N/5 of the beam.
for n in 100 200; do
  { cat "$root/scenes/lee_frame.prm"
    printf 'subsection Geometry\n  set Segments = %d\n' "$n"
    printf '  set Network file = %s\nend\n' "$root/scenes/networks/lee_frame.net"
    printf 'subsection Loads\n  set Point forces = 1:%d: 0, -1, 0\nend\n' $((n / 5))
    printf 'subsection Output\n  set Probes = load_y: position 1:%d y\nend\n' $((n / 5))
  } > "$work/lee_$n.prm"
  "$run" "$work/lee_$n.prm" --output "$work/lee_$n" > "$work/lee_$n.log" 2>&1
  echo "Lee's frame, $n segments per member:"
  grep -h "limit point at" "$work/lee_$n.log"
done

# Iterations per step from the log ("step k: ..., n iteration(s)").
for case in arch elastica lee column rollup; do
  sed -n 's/^step \([0-9]*\): .*, \([0-9]*\) iteration(s).*/\1 \2/p' \
    "$work/$case.log" > "$work/$case.iterations"
done

# Columns: step, load_factor, probe 1, probe 2, arclength, branch,
# negative_eigenvalues, stable, in_range. A segment is drawn solid where
# both its ends are stable.
plot_path() { # csv, x (a gnuplot expression of the columns), x label, y scale, title, png
  gnuplot <<GP
set terminal pngcairo size 1200,420 font ",11"
set output "$6"
set datafile separator ","
set multiplot layout 1,3 title "$5"
set grid
set key bottom right
set xlabel "$3"
set ylabel "load factor"
plot "$1" every ::1 using ($2):(\$8 > 0 ? \$2 : 1/0) with lines lw 2 lc rgb "#1f77b4" title "stable", \
     "$1" every ::1 using ($2):(\$8 > 0 ? 1/0 : \$2) with lines dt 2 lw 2 lc rgb "#d62728" title "unstable"
set xlabel "arclength"
set ylabel "negative eigenvalues"
set yrange [-0.2:2.2]
plot "$1" every ::1 using 5:7 with steps lw 2 notitle
set autoscale y
set datafile separator whitespace
set xlabel "step"
set ylabel "corrector iterations"
plot "$7" using 1:2 with impulses lw 2 notitle
unset multiplot
GP
}
plot_path "$work/arch/probes.csv" '$3' "apex y [m]" 1 \
  "deep arch (DaDeppo and Schmidt): limit load 8.97 EI/R^2 at lambda = 0.897" \
  "$out/continuation_deep_arch.png" "$work/arch.iterations"
plot_path "$work/elastica/probes.csv" '$4' "tip deflection [L]" 1 \
  "elastica without imperfection: bifurcation at pi^2/4, switch to the buckled branch" \
  "$out/continuation_elastica.png" "$work/elastica.iterations"
plot_path "$work/lee/probes.csv" '120 - $4' "load point deflection (down) [-]" 1 \
  "Lee's frame: limit load 1.85 (Schweizerhof and Wriggers), snap-back, second limit point" \
  "$out/continuation_lee_frame.png" "$work/lee.iterations"
plot_path "$work/column/probes.csv" '$3' "midspan deflection [L]" 1 \
  "pinned column, eigenstrain = load factor x 10 x critical: bifurcation at the critical eigenstrain" \
  "$out/continuation_eigenstrain_column.png" "$work/column.iterations"
plot_path "$work/rollup/probes.csv" '-$4' "tip out of plane, -z [L]" 1 \
  "roll-up, isotropic: lateral bifurcation at M = 2 pi EI/L x 0.25 (a quarter circle)" \
  "$out/continuation_rollup.png" "$work/rollup.iterations"
grep -h "limit point at\|bifurcation at" "$work/arch.log" "$work/elastica.log" \
  "$work/lee.log" "$work/column.log" "$work/rollup.log"
echo "charts in $out: continuation_deep_arch.png, continuation_elastica.png," \
  "continuation_lee_frame.png, continuation_eigenstrain_column.png," \
  "continuation_rollup.png"
