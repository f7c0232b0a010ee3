#!/usr/bin/env bash
# Which Newton globalization converges where: every problem of the map
# (scenes of scenes/ with entries changed) solved with each line search of
# Solver/Line search, one process each. Prints a markdown table: the
# outcome, the load steps that converged and those that were cut, the
# Newton iterations of the converged steps, the wall time, the tip and
# whether the last equilibrium is stable (the probes' "stable" column).
#
# Usage: [LINE_SEARCHES="trust region,energy"] bench/line_search_map.sh [RODNET_RUN]
#        (default build/release/rodnet-run; LINE_SEARCHES: a comma-separated
#        subset of the line searches, default all)
set -u
root=$(cd "$(dirname "$0")/.." && pwd)
run=${1:-$root/build/release/rodnet-run}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# name | scene | entries appended to it (subsection blocks, ';' for newlines)
problems=(
  "P1, N = 1000, 1 load step|p1_gravity_cantilever|"
  "P1, N = 1000, 10 load steps|p1_gravity_cantilever|subsection Loads;set Steps = 10;end"
  "elastica EI2 = 10 EI1, imperfection, 20 steps|elastica|"
  "elastica EI1 = EI2, no imperfection, 20 steps|elastica|subsection Material;subsection linear elastic;set EI2 = 1;end;end;subsection Loads;set Point forces = end: -5, 0, 0;end"
  "elastica EI2 = 10 EI1, imperfection, 1 step|elastica|subsection Loads;set Steps = 1;end;subsection Solver;set Critical load search = false;set Branch switching amplitude = 0;end"
  "arc, out-of-plane end load, 1 step|arc|"
  "helical spring, 1 step|helical_spring|"
  "square lattice|square_lattice|"
  "P1, N = 4000 (short stiff segments), 1 load step|p1_gravity_cantilever|subsection Geometry;set Segments = 3999;end"
  "deep arch past its limit point (0.897), 10 load steps to 1|deep_arch|subsection Solver;set Method = newton;end;subsection Loads;set Steps = 10;end"
)
IFS=, read -r -a searches <<<"${LINE_SEARCHES:-}"
[ ${#searches[@]} -gt 0 ] || searches=("full step" "energy" "trust region" "backtrack" "polynomial")

echo "| problem | line search | outcome | steps converged / cut | Newton iterations | wall s | tip x, y, z | stable |"
echo "|---|---|---|---|---|---|---|---|"
for problem in "${problems[@]}"; do
  IFS='|' read -r name scene entries <<<"$problem"
  for search in "${searches[@]}"; do
    prm=$work/scene.prm
    cp "$root/scenes/$scene.prm" "$prm"
    tr ';' '\n' <<<"$entries" >>"$prm"
    printf 'subsection Solver\nset Line search = %s\nend\n' "$search" >>"$prm"
    printf 'subsection Output\nset Write VTU = false\nset Plot = false\n' >>"$prm"
    printf 'set Probes = x: position end x; y: position end y; z: position end z\nend\n' >>"$prm"
    start=$(date +%s.%N)
    "$run" "$prm" --output "$work/out" >"$work/log" 2>&1
    code=$?
    end=$(date +%s.%N)
    outcome=$([ $code -eq 0 ] && echo done || echo "stopped (exit $code)")
    converged=$(grep -c '^step ' "$work/log")
    cut=$(grep -c 'failed .*cutting the step' "$work/log")
    iterations=$(grep '^step ' "$work/log" |
      sed -n 's/.*iterations *\([0-9]*\).*/\1/p' | awk '{s += $1} END {print s + 0}')
    last=$(tail -n 1 "$work/out/probes.csv" 2>/dev/null)
    tip=$(awk -F, '{printf "%.6g, %.6g, %.6g", $3, $4, $5}' <<<"$last")
    stable=$(awk -F, '{print ($6 == 1 ? "yes" : "no")}' <<<"$last")
    printf '| %s | %s | %s | %s / %s | %s | %.2f | %s | %s |\n' "$name" \
      "$search" "$outcome" "$converged" "$cut" "${iterations:-0}" \
      "$(awk -v a="$start" -v b="$end" 'BEGIN {print b - a}')" "$tip" "$stable"
    rm -rf "$work/out"
  done
done
