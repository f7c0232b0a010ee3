#!/usr/bin/env bash
# Lestringant & Kochmann's Fig. 7 (scenes/fig7_shrinking_lattice.prm: 4 x 4
# cells, out-of-plane natural curvature -kappa0 / L on the quarters of every
# beam next to its junctions, +kappa0 / L on its middle half): the in-plane
# shrinkage of the footprint, 1 - (x extent) / (4 L), against kappa0 for
# SEGMENTS per beam, with the closed form 1 - 4 sin(kappa0 / 4) / kappa0 of
# the stress-free lattice (each beam in its natural shape). Prints a
# markdown table of the shrinkage; at the paper's kappa0 = 5.745, for each
# mesh, the DoFs, the median wall time of REPEATS whole rodnet-run processes
# (one core, no VTU, no plot) and the error against the closed form (the
# accuracy against cost, drawn into COST_PNG); draws the curve into PNG and
# keeps the run at 30 segments per beam's picture (Picture field =
# curvature[2]) as PICTURE.
#
# Usage: bench/fig7_shrinkage.sh [RODNET_RUN] [REPEATS (5)] [PNG] [PICTURE]
#          [COST_PNG]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
run=${1:-$root/build/release/rodnet-run}
repeats=${2:-5}
png=${3:-$root/doc/fig7_shrinkage.png}
picture=${4:-$root/doc/fig7_lattice.png}
cost_png=${5:-$root/doc/fig7_accuracy_cost.png}
kappas="0 1 2 2.815 3.5 4.5 5.745"
segments_list="10 20 30 60"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

source "$root/bench/process_timing.sh"

# scene KAPPA0 SEGMENTS PLOT: the shipped scene at that curvature and mesh.
scene() {
  cat "$root/scenes/fig7_shrinking_lattice.prm"
  printf 'subsection Geometry\n  set Segments = %s\nend\n' "$2"
  printf 'subsection Group all\n  set Natural curvature = 0, %s on 0.25 to 0.75; 0, -%s on near ends 0.25\nend\n' "$1" "$1"
  printf 'subsection Output\n  set Plot = %s\nend\n' "$3"
}

# shrinkage DIR: 1 - x extent / (4 L) at the last row of DIR/probes.csv.
shrinkage() {
  awk -F, 'NR == 1 { for (c = 1; c <= NF; ++c) { if ($c == "west_x") w = c; if ($c == "east_x") e = c } }
           NR > 1 { s = 1 - ($e - $w) / 4 } END { printf "%.7f", s }' "$1/probes.csv"
}

header="| kappa0 | closed form |"
rule="|---|---|"
for n in $segments_list; do header+=" $n per beam |"; rule+="---|"; done
echo "$header"
echo "$rule"
: > "$work/curve.dat"
for k in $kappas; do
  exact=$(awk -v k="$k" 'BEGIN { printf "%.7f", k == 0 ? 0 : 1 - 4 * sin(k / 4) / k }')
  line="| $k | $exact |"
  values=""
  for n in $segments_list; do
    scene "$k" "$n" false > "$work/scene.prm"
    "$run" "$work/scene.prm" --output "$work/out" > "$work/run.log" 2>&1
    s=$(shrinkage "$work/out")
    line+=" $s |"
    values+=" $s"
  done
  echo "$line"
  echo "$k $exact$values" >> "$work/curve.dat"
done

# At kappa0 = 5.745: the cost of each mesh against its error.
exact=$(awk 'BEGIN { printf "%.9f", 1 - 4 * sin(5.745 / 4) / 5.745 }')
echo
echo "| segments per beam | DoFs | wall time s (median of $repeats) | shrinkage | error |"
echo "|---|---|---|---|---|"
: > "$work/cost.dat"
for n in $segments_list; do
  scene 5.745 "$n" false > "$work/paper.prm"
  times=()
  for ((r = 0; r < repeats; ++r)); do
    times+=("$(seconds "$run" "$work/paper.prm" --output "$work/out")")
  done
  dofs=$(sed -n 's/.*rod(s), .*, \([0-9]*\) DoFs.*/\1/p' "$work/log" | head -1)
  s=$(shrinkage "$work/out")
  t=$(echo "${times[*]}" | median)
  error=$(awk -v s="$s" -v e="$exact" 'BEGIN { d = s - e; printf "%.3e", d < 0 ? -d : d }')
  echo "| $n | $dofs | $t | $s | $error |"
  echo "$n $t $error $dofs" >> "$work/cost.dat"
done
scene 5.745 30 true > "$work/picture.prm"
"$run" "$work/picture.prm" --output "$work/pic" > "$work/run.log" 2>&1
cp "$work/pic/picture.png" "$picture"

plot_accuracy_cost "$cost_png" "Fig. 7 (4 x 4 cells, kappa_0 = 5.745): accuracy against cost" \
  "|shrinkage - closed form|" "$work/cost.dat"

gnuplot <<END
set terminal pngcairo size 640,440 font ",10"
set output "$png"
set xlabel "natural curvature kappa_0 (x 1/L)"
set ylabel "in-plane shrinkage of the footprint, 1 - W / W_0"
set title "Fig. 7 (4 x 4 cells): footprint against the activated curvature"
set key top left
set grid
f(k) = k == 0 ? 0 : 1 - 4 * sin(k / 4) / k
set samples 200
plot [0:6.2] f(x) with lines lw 1.5 lc rgb "#444444" title "closed form 1 - 4 sin(k/4)/k", \
     "$work/curve.dat" using 1:3 with points pt 6 ps 1.4 lc rgb "#d62728" title "10 segments per beam", \
     "$work/curve.dat" using 1:4 with points pt 4 ps 1.2 lc rgb "#ff7f0e" title "20", \
     "$work/curve.dat" using 1:5 with points pt 7 ps 0.9 lc rgb "#2ca02c" title "30 (the paper's)", \
     "$work/curve.dat" using 1:6 with points pt 1 ps 1.4 lc rgb "#1f77b4" title "60"
END
