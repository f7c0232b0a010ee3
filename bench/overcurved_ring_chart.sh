#!/usr/bin/env bash
# The chart of doc/overcurved_ring.md: the least distance D between
# opposite points of the over-curved ring against the over-curvature O.
# Three continuation runs of scenes/overcurved_ring.prm (N = 400):
#  - as shipped: from the stress-free circle (O = 1 + lambda) through the
#    bifurcation at O_b onto the two-lobe branch, to the fold at O_d where
#    it ends on the triply covered ring, which it follows on to O = 3
#    (Limit points = snap);
#  - the same without switching: the circle's branch to O = 3.3;
#  - the triply covered ring of radius L / (6 pi) bent from a straight rod
#    (O = lambda), its branch followed from O = 0 to 3.3 without switching.
# Stable equilibria solid, unstable dashed; the shapes of the two-lobe
# branch at four points below.
#
# Usage: bench/overcurved_ring_chart.sh [RODNET_RUN] [OUTPUT_DIR]
#        (defaults build/release/rodnet-run, doc/)
set -eu
source "$(dirname "$0")/chart_paths.sh"
scene="$root/scenes/overcurved_ring.prm"
distance="$root/bench/overcurved_ring_distance.py"
length=0.314

# As shipped, to O = 3.
"$run" "$scene" --output "$work/lobes" > "$work/lobes.log" 2>&1
grep -h "bifurcation at\|limit point at\|jump at" "$work/lobes.log" || true
python3 "$distance" "$work/lobes" $length 1 > "$work/lobes.txt"

for covering in 1 3; do
  shape=$([ $covering = 1 ] && echo "initial geometry" || echo straight)
  offset=$([ $covering = 1 ] && echo 1 || echo 0)
  # Output points on the triply covered ring's stable stretch; finer steps
  # land near its bifurcations, where the corrector fails.
  points=$([ $covering = 1 ] && echo "0.5, 1, 1.5, 2" || echo "2.84, 2.9, 2.95, 3, 3.05, 3.1, 3.15")
  cat "$scene" - > "$work/ring$covering.prm" <<END
subsection Geometry
  set Radius = $(python3 -c "import math; print(repr($length / (2 * math.pi * $covering)))")
  set Turns = $covering
  set Natural shape = $shape
end
subsection Solver
  subsection Continuation
    set Load factor range = -0.5, $(python3 -c "print(3.3 - $offset)")
    set Switch branches = false
    set Output load factors = $points
    set Max points = 2000
  end
end
subsection Output
  set Plot = false
END
  printf '  set VTU interval = 1\nend\n' >> "$work/ring$covering.prm"
  "$run" "$work/ring$covering.prm" --output "$work/ring$covering" \
    > "$work/ring$covering.log" 2>&1
  grep -h "bifurcation at" "$work/ring$covering.log" | sed "s/^/covered $covering times, O = $offset + load factor: /"
  python3 "$distance" "$work/ring$covering" $length $offset > "$work/ring$covering.txt"
done

# Shapes of the two-lobe branch: the rows nearest O = 1.5, 2, 2.5 and the
# fold (the row before the jump).
shapes=""
for o in 1.5 2.0 2.5 fold; do
  row=$(awk -v o=$o 'BEGIN { best = -1 }
    { if (o == "fold") { if ($4 == 1 && best < 0) best = NR - 2 }
      else if (best < 0 || ($1 - o)^2 < bd) { bd = ($1 - o)^2; best = NR - 1 } }
    END { print best }' "$work/lobes.txt")
  python3 "$root/bench/vtu_table.py" "$(printf "$work/lobes/solution-%05d.vtu" $row)" > "$work/shape_$o.txt"
  shapes="$shapes $o:$(awk -v r=$((row + 1)) 'NR == r { printf "%.3f", $1 }' "$work/lobes.txt")"
done
echo "shapes at O =$shapes"

gnuplot <<GP
set terminal pngcairo size 1000,900 font ",11"
set output "$out/overcurved_ring.png"
set multiplot
set size 1, 0.62
set origin 0, 0.38
set title "Over-curved Slinky ring (w = 5 mm, t = 2 mm, L = 314 mm, nu = 0.41), N = 400, inextensible"
set grid
set xlabel "over-curvature O = kappa0 L / (2 pi)"
set ylabel "least distance of opposite points D / L"
set xrange [0:3.3]
set yrange [0:0.35]
set key at graph 0.99, 0.75 right
stable(s, v) = (s == 1 ? v : 1/0)
unstable(s, v) = (s == 0 ? v : 1/0)
# The shipped run before its jump (j = 0) and from it on (j = 1).
jumped = 0
stretch(j, v) = (jumped = jumped || column(4) == 1, jumped == j ? v : 1/0)
set arrow from 1.166920, 0 to 1.166920, 0.35 nohead dt 3 lc rgb "gray40"
set arrow from 2.833233, 0 to 2.833233, 0.35 nohead dt 3 lc rgb "gray40"
set arrow from 3.166881, 0 to 3.166881, 0.35 nohead dt 3 lc rgb "gray40"
set label "O_b" at 1.18, 0.34
set label "O_d" at 2.70, 0.34
set label "O_u" at 3.18, 0.34
plot "$work/ring1.txt" using 1:(stable(\$3, \$2)) with lines lw 2 lc rgb "#0050c0" title "circle, stable", \
     "" using 1:(unstable(\$3, \$2)) with lines lw 2 dt 2 lc rgb "#0050c0" title "circle, unstable", \
     jumped = 0, "$work/lobes.txt" using 1:(stretch(0, stable(\$3, \$2))) with lines lw 2 lc rgb "#c00000" title "as shipped: two lobes (from O_b), stable", \
     "$work/ring3.txt" using 1:(stable(\$3, \$2)) with lines lw 3 lc rgb "#008000" title "triply covered ring, stable", \
     "" using 1:(unstable(\$3, \$2)) with lines lw 2 dt 2 lc rgb "#008000" title "triply covered ring, unstable", \
     jumped = 0, "$work/lobes.txt" using 1:(stretch(1, \$2)) with points pt 7 ps 0.6 lc rgb "black" title "as shipped: past O_d (Limit points = snap)", \
     "< awk 'NR == 1 || \$1 > 1.49 && \$1 < 1.51 || \$1 > 1.99 && \$1 < 2.01 || \$1 > 2.49 && \$1 < 2.51' $work/lobes.txt" using 1:2 with points pt 7 ps 1.2 lc rgb "black" notitle
unset arrow
unset label
set size 0.25, 0.40
unset xlabel
unset ylabel
unset key
unset grid
set view 60, 30
set view equal xyz
set xyplane 0
unset tics
unset border
set xrange [-0.055:0.055]
set yrange [-0.055:0.055]
set zrange [-0.055:0.055]
i = 0
do for [o in "1.5 2.0 2.5 fold"] {
  set origin 0.25 * i, 0.0
  set title (o eq "fold" ? "fold, O = O_d" : "O = ".o)
  splot "$work/shape_".o.".txt" using 1:2:3 with lines lw 2 lc rgb "#c00000"
  i = i + 1
}
unset multiplot
GP
echo "wrote $out/overcurved_ring.png"
