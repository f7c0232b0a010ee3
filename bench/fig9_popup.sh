#!/usr/bin/env bash
# Lestringant & Kochmann's Figs. 9-10 (scenes/fig9_popup.prm: a cross and a
# six-branch star of the paper's ribbon bonded to a substrate released to a
# compressive strain of 60 %): the apex height z/L of each layer against
# the strain at 6, 10, 20, 40 segments per beam (even: the star's highest
# point, the midpoint of a side of its ring, is then a vertex) (meshes by
# bench/fig9_popup_mesh.py), the median wall time of REPEATS whole
# rodnet-run processes (no VTU, no plot, no picture) and the DoFs at each
# resolution, and the apex error against wall time (accuracy against
# cost) at 40 % strain, the error taken against the Richardson
# extrapolation of 20 and 40 (second order, validation/popup_two_layer).
# Draws the curves into APEX_PNG, the error against time into COST_PNG and
# keeps the popped-up picture at 10 segments as PICTURE.
#
# Usage: bench/fig9_popup.sh [RODNET_RUN] [REPEATS (5)] [APEX_PNG]
#                            [COST_PNG] [PICTURE]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
run=${1:-$root/build/release/rodnet-run}
repeats=${2:-5}
apex_png=${3:-$root/doc/fig10_apex.png}
cost_png=${4:-$root/doc/fig9_accuracy_cost.png}
picture=${5:-$root/doc/fig9_popup.png}
segments_list="6 10 20 40"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

source "$root/bench/process_timing.sh"

# scene SEGMENTS PLOT: the shipped scene on the mesh of SEGMENTS per beam,
# its probes.png and picture.png drawn where PLOT is true.
scene() {
  python3 "$root/bench/fig9_popup_mesh.py" "$1" > "$work/popup_$1.msh"
  sed "s|meshes/fig9_popup.msh|$work/popup_$1.msh|" "$root/scenes/fig9_popup.prm"
  printf 'subsection Output\n  set Write VTU = false\n  set Plot = %s\nend\n' "$2"
}

# apexes DIR: strain, apex1, apex2, junction2 of every row of DIR/probes.csv.
apexes() {
  awk -F, 'NR == 1 { for (c = 1; c <= NF; ++c) { if ($c == "apex1") a = c; if ($c == "apex2") b = c; if ($c == "junction2") j = c } }
           NR > 1 { printf "%.6f %.7f %.7f %.7f\n", 0.6 * $2, $a, $b, $j }' "$1/probes.csv"
}

# at FILE STRAIN COLUMN: the value of COLUMN at STRAIN in FILE.
at() { awk -v s="$2" -v c="$3" '($1 - s) ^ 2 < 1e-12 { print $c }' "$1"; }

echo "| segments per beam | DoFs | wall time s (median of $repeats) | cross centre at 20, 40, 60 % | star's highest point | star's junction |"
echo "|---|---|---|---|---|---|"
for n in $segments_list; do
  scene "$n" false > "$work/scene_$n.prm"
  times=()
  for ((r = 0; r < repeats; ++r)); do
    times+=("$(seconds "$run" "$work/scene_$n.prm" --output "$work/out_$n")")
  done
  echo "$(echo "${times[*]}" | median)" > "$work/time_$n"
  dofs=$(sed -n 's/.*rod(s), .*, \([0-9]*\) DoFs.*/\1/p' "$work/log" | head -1)
  apexes "$work/out_$n" > "$work/apex_$n.dat"
  a1="" a2="" a3=""
  for s in 0.2 0.4 0.6; do
    a1+=" $(at "$work/apex_$n.dat" $s 2)"
    a2+=" $(at "$work/apex_$n.dat" $s 3)"
    a3+=" $(at "$work/apex_$n.dat" $s 4)"
  done
  echo "| $n | $dofs | $(cat "$work/time_$n") |$a1 |$a2 |$a3 |"
done

# Accuracy against cost at 40 %: errors against the extrapolation of 20, 40.
: > "$work/cost.dat"
for c in 2 3; do
  f20=$(at "$work/apex_20.dat" 0.4 $c)
  f40=$(at "$work/apex_40.dat" 0.4 $c)
  for n in 6 10 20; do
    a=$(at "$work/apex_$n.dat" 0.4 $c)
    awk -v a="$a" -v p="$f20" -v q="$f40" -v t="$(cat "$work/time_$n")" \
      -v n="$n" -v c="$c" 'BEGIN { e = a - (q + (q - p) / 3); printf "%d %s %s %.3e\n", c - 1, n, t, e < 0 ? -e : e }' >> "$work/cost.dat"
  done
  printf '\n\n' >> "$work/cost.dat"
done
echo
echo "apex error at 40 % against the extrapolation of 20 and 40 (layer, segments, s, error):"
grep . "$work/cost.dat"

scene 10 true > "$work/picture.prm"
"$run" "$work/picture.prm" --output "$work/pic" > "$work/run.log" 2>&1
cp "$work/pic/picture.png" "$picture"

gnuplot <<END
set terminal pngcairo size 640,440 font ",10"
set output "$apex_png"
set xlabel "compressive strain |eps|"
set ylabel "apex height u_z / L"
set title "Fig. 10: apex of each layer against the substrate's strain"
set key top left
set grid
plot [0:0.6] "$work/apex_10.dat" using 1:2 with lines lw 2 lc rgb "#d62728" title "layer 1 (cross), 10 per beam", \
     "$work/apex_40.dat" using 1:2 with points pt 6 ps 0.8 lc rgb "#d62728" title "layer 1, 40 per beam", \
     "$work/apex_10.dat" using 1:3 with lines lw 2 lc rgb "#1f77b4" title "layer 2 (star), 10 per beam", \
     "$work/apex_40.dat" using 1:3 with points pt 4 ps 0.8 lc rgb "#1f77b4" title "layer 2, 40 per beam"
set output "$cost_png"
set xlabel "wall time of the whole run, s"
set ylabel "apex error at 40 % strain, / L"
set title "Figs. 9-10: accuracy against cost (6, 10, 20 segments per beam)"
set logscale xy
set format y "%.0e"
set key top right
plot "$work/cost.dat" index 0 using 3:4 with linespoints pt 7 lc rgb "#d62728" title "layer 1 (cross)", \
     "$work/cost.dat" index 1 using 3:4 with linespoints pt 5 lc rgb "#1f77b4" title "layer 2 (star)"
END
