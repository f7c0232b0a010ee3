#!/usr/bin/env bash
# Cost of an equilibrium of an inextensible rod (Material/Inextensible:
# a multiplier per segment, Newton on the KKT system) against DoFs: the
# elastica (B = L = 1, EI2 = 2 EI1, no imperfection) followed by
# continuation from P = 0 through its bifurcation to P = 5 B/L^2 (the
# tool for post-buckling of inextensible rods, doc/inextensible_rods.md) at
# N = 1e2, 1e3 segments, and a cantilever bent by a transverse tip load
# (P = 5 B/L^2, 20 Newton load steps, no bifurcation) at N = 1e2, 1e3, 1e4,
# each against the same scene with EA = 1e7 (the
# baseline, no multipliers), in turn, median of REPEATS whole runs (process
# start-up included). Korner et al. report "about 0.1 s for each
# equilibrium" at N = 100 (their SQP with Eigen's SimplicialLDLT, on a
# personal computer).
# Prints two markdown tables: N, DoFs, then per model the points (converged
# states), the seconds and the seconds per point; the ratio per point. Where
# the baseline stops (at 1e4 segments EA = 1e7 is at its round-off floor from
# the first step), the inextensible rod alone.
# Not the elastica at 1e4 segments: there the rounding of the tangent
# (condition ~N^4) makes the stability count report false bifurcations,
# for the extensible rod (at P = 1.7) and the inextensible one (at 0.7,
# where its continuation then stops) alike (doc/inextensible_rods.md).
#
# Usage: bench/inextensible_cost.sh [RODNET_RUN] [REPEATS (3)]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
run=${1:-$root/build/release/rodnet-run}
repeats=${2:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

source "$root/bench/process_timing.sh"
source "$root/bench/elastica_scene.sh"

scene() { # N, Inextensible, loads and solver subsections
  elastica_scene "$1" "$2" 1e7 "$3" "tip_x: position end x"
}

elastica="subsection Loads
  set Point forces = end: -1, 0, 0
end
subsection Solver
  set Method = continuation
  subsection Continuation
    set Load factor range = -1, 5
    set Output load factors = 3, 4
    set Initial step = 0.1
  end
end"
bending="subsection Loads
  set Steps = 20
  set Point forces = end: 0, 5, 0
end"

# table CASE SEGMENTS...: per N the points (rows of probes.csv), seconds
# and seconds per point of both models, and the ratio per point.
table() {
  local case=$1
  shift
  echo "| N | DoFs | inextensible points | s | s per point | extensible points | s | s per point | ratio per point |"
  echo "|---|---|---|---|---|---|---|---|---|"
  for n in "$@"; do
    scene $n true "$case" > "$work/inextensible.prm"
    scene $n false "$case" > "$work/extensible.prm"
    "$run" "$work/inextensible.prm" --output "$work/i" > "$work/i.log" 2>&1
    if ! "$run" "$work/extensible.prm" --output "$work/e" > "$work/e.log" 2>&1; then
      # The baseline stops (the round-off floor of a stiff EA at 1e4
      # segments): the inextensible rod alone.
      local t=()
      for ((k = 0; k < repeats; ++k)); do
        t+=("$(seconds "$run" "$work/inextensible.prm" --output "$work/a")")
      done
      pi=$(($(wc -l < "$work/i/probes.csv") - 2))
      awk -v n=$n -v a="$(echo "${t[*]}" | median)" -v pi=$pi 'BEGIN {
        printf "| %d | %d | %d | %.3f | %.4f | stops | - | - | - |\n",
               n, 5 * n + 3, pi, a, a / pi }'
      continue
    fi
    dofs=$(sed -n 's/^rodnet[a-z ()]*: 1 rod(s), \([0-9]*\) DoFs.*/\1/p' "$work/i.log" | head -1)
    pi=$(($(wc -l < "$work/i/probes.csv") - 2))
    pe=$(($(wc -l < "$work/e/probes.csv") - 2))
    read -r a b < <(in_turn "$run" "$repeats" "$work/inextensible.prm" "$work/extensible.prm")
    awk -v n=$n -v d="$dofs" -v a=$a -v b=$b -v pi=$pi -v pe=$pe 'BEGIN {
      printf "| %d | %s | %d | %.3f | %.4f | %d | %.3f | %.4f | %.2f |\n",
             n, d, pi, a, a / pi, pe, b, b / pe, (a / pi) / (b / pe) }'
  done
}

echo "Elastica followed by continuation to P = 5 B/L^2:"
echo
table "$elastica" 100 1000
echo
echo "Cantilever under a transverse tip load P = 5 B/L^2, 20 Newton load steps:"
echo
table "$bending" 100 1000 10000
