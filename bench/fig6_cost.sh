#!/usr/bin/env bash
# Time, DoFs and accuracy of Lestringant & Kochmann's Fig. 6
# (doc/morphing.md, "Fig. 6"). (a) scenes/fig6_building_block.prm: for
# SEGMENTS per horizontal beam (a sixth of them per strut; the paper's 60
# among them), the median wall time of REPEATS whole rodnet-run processes
# (one core, no VTU, no plot, no picture), the DoFs and the error of the
# right strut's position against the stress-free Z's closed form
#   X = 2 sin(t) / k + 0.8 cos(t), Y = 2 (1 - cos(t)) / k + 0.8 sin(t),
# k = 14.31, t = 1.431; a markdown table, and the error against the wall
# time drawn into PNG. (b) scenes/fig6_tessellation.prm as shipped: its
# DoFs and median wall time. Keeps both runs' pictures as BLOCK_PICTURE and
# TESSELLATION_PICTURE.
#
# Usage: bench/fig6_cost.sh [RODNET_RUN] [REPEATS (5)] [PNG] [BLOCK_PICTURE]
#          [TESSELLATION_PICTURE] [SEGMENTS...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
run=${1:-$root/build/release/rodnet-run}
repeats=${2:-5}
png=${3:-$root/doc/fig6_accuracy_cost.png}
block_picture=${4:-$root/doc/fig6_block.png}
tessellation_picture=${5:-$root/doc/fig6_tessellation.png}
shift $(($# > 5 ? 5 : $#))
segments_list=${*:-30 60 120 240}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

source "$root/bench/process_timing.sh"

# quiet SCENE: SCENE (a file of scenes/) read from there, without outputs
# but probes.csv.
quiet() {
  sed "s|^\(  set Block map file = \)|\1$root/scenes/|" "$root/scenes/$1"
  printf 'subsection Output\n  set Plot = false\n  set Picture field = none\nend\n'
}

# dofs LOG: the DoFs of the size line of a run's output.
dofs() { sed -n 's/.*rod(s), .*, \([0-9]*\) DoFs.*/\1/p' "$1" | head -1; }

# median_time SCENE: the median seconds of REPEATS runs of SCENE.
median_time() {
  local times=() k
  for ((k = 0; k < repeats; ++k)); do
    times+=("$(seconds "$run" "$1" --output "$work/out")")
  done
  echo "${times[*]}" | median
}

echo "| segments per beam (strut) | DoFs | wall time s (median of $repeats) | X / L | Y / L | error / L |"
echo "|---|---|---|---|---|---|"
: > "$work/table.dat"
for n in $segments_list; do
  {
    quiet fig6_building_block.prm
    printf 'subsection Group horizontal\n  set Segments = %s\nend\n' "$n"
    printf 'subsection Group vertical\n  set Segments = %s\nend\n' "$((n / 6))"
  } > "$work/block.prm"
  t=$(median_time "$work/block.prm")
  "$run" "$work/block.prm" --output "$work/out" > "$work/run.log" 2>&1
  awk -F, -v n="$n" -v d="$(dofs "$work/run.log")" -v t="$t" '
    NR == 1 { for (c = 1; c <= NF; ++c) { if ($c == "right_x") x = c; if ($c == "right_y") y = c } }
    NR > 1 { X = $x; Y = $y }
    END {
      k = 14.31; a = 0.1; th = k * a
      ex = 2 * sin(th) / k + (1 - 2 * a) * cos(th)
      ey = 2 * (1 - cos(th)) / k + (1 - 2 * a) * sin(th)
      e = sqrt((X - ex) ^ 2 + (Y - ey) ^ 2)
      printf "| %d (%d) | %d | %.2f | %.6f | %.6f | %.2e |\n", n, n / 6, d, t, X, Y, e
      printf "%d %.4f %.3e %d\n", n, t, e, d >> "'"$work/table.dat"'" }' "$work/out/probes.csv"
done
echo "closed form: X / L = 0.249872, Y / L = 0.912483"

quiet fig6_tessellation.prm > "$work/tessellation.prm"
t=$(median_time "$work/tessellation.prm")
"$run" "$work/tessellation.prm" --output "$work/out" > "$work/run.log" 2>&1
echo
echo "tessellation: $(dofs "$work/run.log") DoFs, $t s (median of $repeats)"

for scene in fig6_building_block fig6_tessellation; do
  "$run" "$root/scenes/$scene.prm" --output "$work/$scene" > "$work/run.log" 2>&1
done
cp "$work/fig6_building_block/picture.png" "$block_picture"
cp "$work/fig6_tessellation/picture.png" "$tessellation_picture"

# The error against the wall time, each point labelled with its mesh and
# DoFs; the block's error falls at second order in the segment length.
plot_accuracy_cost "$png" "Fig. 6 (a): the building block against the stress-free Z" \
  "|(X, Y) - closed form| / L" "$work/table.dat"
