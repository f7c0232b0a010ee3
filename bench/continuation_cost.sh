#!/usr/bin/env bash
# Cost of a continuation point against DoFs: the elastica (EI2 = 2 EI1,
# no imperfection) at N = 1e2, 1e3, 1e4 segments, followed from
# P = 0 through its bifurcation to P = 3 B/L^2 with output points at
# 2.6, 2.8 (Solver/Method = continuation), against the same scene by load
# stepping to P = 3 in as many equal steps as the continuation took points
# (Solver/Method = newton, the baseline), in turn, median of REPEATS runs.
# Prints a markdown table: N, DoFs, points, continuation s, s per point,
# load stepping s, s per step, ratio per point.
# Not 1e5 segments: a single rod's tangent there has a condition number of
# about N^4 = 1e20, so the signs of its smallest pivots are rounding and
# no stability count (continuation's or load stepping's) means anything
# (doc/continuation.md, "Limits").
#
# Usage: bench/continuation_cost.sh [RODNET_RUN] [REPEATS (3)]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
run=${1:-$root/build/release/rodnet-run}
repeats=${2:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

source "$root/bench/process_timing.sh"
source "$root/bench/elastica_scene.sh"

scene() { # N, loads and solver subsections
  elastica_scene "$1" false 1e7 "$2" "tip_x: position end x"
}

echo "| N | DoFs | points | continuation s | s per point | load steps s | s per step | ratio per point |"
echo "|---|---|---|---|---|---|---|---|"
for n in 100 1000 10000; do
  scene $n "subsection Loads
  set Point forces = end: -1, 0, 0
end
subsection Solver
  set Method = continuation
  subsection Continuation
    set Load factor range = -1, 3
    set Output load factors = 2.6, 2.8
    set Initial step = 0.1
  end
end" > "$work/cont.prm"
  "$run" "$work/cont.prm" --output "$work/c" > "$work/c.log" 2>&1
  points=$(($(wc -l < "$work/c/probes.csv") - 2))
  dofs=$(sed -n 's/.*segments, \([0-9]*\) DoFs.*/\1/p' "$work/c.log" | head -1)
  scene $n "subsection Loads
  set Steps = $points
  set Point forces = end: -3, 3e-6, 0
end
subsection Solver
  set Method = newton
end" > "$work/steps.prm"
  read -r c s < <(in_turn "$run" "$repeats" "$work/cont.prm" "$work/steps.prm")
  awk -v n=$n -v d="$dofs" -v p=$points -v c=$c -v s=$s 'BEGIN {
    printf "| %d | %s | %d | %.3f | %.4f | %.3f | %.4f | %.2f |\n",
      n, d, p, c, c / p, s, s / p, c / s }'
done
