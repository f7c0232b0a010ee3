#!/usr/bin/env bash
# Cost of a continuation point against DoFs up to 1e5, on a welded lattice:
# the gridshell of scenes/gridshell.prm with n x n cells (8 segments per
# lath, EA = 1000, EI1 = 4, EI2 = 1, GJ = 1), its two edges pushed together
# by 0.003 of the span with an uplift of 0.0003 per length: below its first
# bifurcation (at 6 x 6 cells about 1.7 times this), so that the path has
# no bisection and both methods do the same work. The continuation from
# load factor 0 to 1 (Solver/Method = continuation) against load stepping
# to 1 in as many equal steps as the continuation took points (Solver/
# Method = newton), in turn, median of REPEATS runs. Prints a markdown
# table: cells, DoFs, points, continuation s, s per point, load stepping s,
# s per step, ratio per point.
#
# Usage: bench/continuation_lattice_cost.sh [RODNET_RUN] [REPEATS (3)] [CELLS...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
run=${1:-$root/build/release/rodnet-run}
repeats=${2:-3}
shift $(($# > 2 ? 2 : $#))
cells_list=${*:-6 12 24 37}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

source "$root/bench/process_timing.sh"

scene() { # cells, solver block
  local n=$1 j supports=""
  for ((j = 0; j <= n; ++j)); do
    supports+="@n_0_${j}: x=0.003 y=0 z=0; @n_${n}_${j}: x=-0.003 y=0 z=0; "
  done
  cat <<END
subsection Geometry
  set Generator = square lattice
  set Cells = $n, $n
  set Beam length = $(awk -v n="$n" 'BEGIN { printf "%.17g", 1 / n }')
  set Segments = 8
end
subsection Material
  subsection linear elastic
    set Stiffness input = direct
    set EA = 1000
    set EI1 = 4
    set EI2 = 1
    set GJ = 1
  end
end
subsection Supports
  set Prescribed displacements = ${supports%; }
end
subsection Loads
  set Distributed force = 0, 0, 0.0003
$2
subsection Output
  set Write VTU = false
  set Plot = false
  set Probes = crown_z: position @n_$((n / 2))_$((n / 2)) z
end
END
}

echo "| cells | DoFs | points | continuation s | s per point | load steps s | s per step | ratio per point |"
echo "|---|---|---|---|---|---|---|---|"
for n in $cells_list; do
  scene "$n" "end
subsection Solver
  set Method = continuation
  subsection Continuation
    set Load factor range = -1, 1
  end
end" > "$work/cont.prm"
  "$run" "$work/cont.prm" --output "$work/c" > "$work/c.log" 2>&1
  points=$(($(wc -l < "$work/c/probes.csv") - 2))
  dofs=$(sed -n 's/.*rod(s), .*, \([0-9]*\) DoFs.*/\1/p' "$work/c.log" | head -1)
  scene "$n" "  set Steps = $points
end
subsection Solver
  set Method = newton
end" > "$work/steps.prm"
  read -r c s < <(in_turn "$run" "$repeats" "$work/cont.prm" "$work/steps.prm")
  awk -v n="$n" -v d="$dofs" -v p=$points -v c=$c -v s=$s 'BEGIN {
    printf "| %d x %d | %s | %d | %.3f | %.4f | %.3f | %.4f | %.2f |\n",
      n, n, d, p, c, c / p, s, s / p, c / s }'
done
