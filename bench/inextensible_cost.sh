#!/usr/bin/env bash
# Cost of an equilibrium of an inextensible rod (Material/Inextensible:
# a multiplier per segment, Newton on the KKT system) against DoFs: the
# elastica (B = L = 1, EI2 = 2 EI1, no imperfection) followed by
# continuation from P = 0 through its bifurcation to P = 5 B/L^2 (the
# tool for post-buckling of inextensible rods, doc/inextensible_rods.md) at
# N = 1e2, 1e3, 1e4 segments, against the same scene with EA = 1e7 (the
# baseline, no multipliers), in turn, median of REPEATS whole runs (process
# start-up included). Korner et al. report "about 0.1 s for each
# equilibrium" at N = 100 (their SQP with Eigen's SimplicialLDLT, on a
# personal computer).
# Prints a markdown table: N, DoFs, then per model the points of the path,
# the seconds and the seconds per point; the ratio per point.
#
# Usage: bench/inextensible_cost.sh [RODNET_RUN] [REPEATS (3)]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
run=${1:-$root/build/release/rodnet-run}
repeats=${2:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

source "$root/bench/process_timing.sh"

scene() { # N, Inextensible
  cat <<END
subsection Geometry
  set Generator = straight
  set Segments = $1
  set Clamp at first segment midpoint = true
  set Director d1 = 0, 0, 1
end
subsection Material
  set Inextensible = $2
  subsection linear elastic
    set Stiffness input = direct
    set EA = 1e7
    set EI1 = 1
    set EI2 = 2
    set GJ = 1
  end
end
subsection Supports
  set Clamped ends = start
end
subsection Loads
  set Point forces = end: -1, 0, 0
end
subsection Solver
  set Method = continuation
  subsection Continuation
    set Load factor range = -1, 5
    set Output load factors = 3, 4
    set Initial step = 0.1
  end
end
subsection Output
  set Write VTU = false
  set Plot = false
  set Probes = tip_x: position end x
end
END
}

echo "| N | DoFs | inextensible points | s | s per point | extensible points | s | s per point | ratio per point |"
echo "|---|---|---|---|---|---|---|---|---|"
for n in 100 1000 10000; do
  scene $n true > "$work/inextensible.prm"
  scene $n false > "$work/extensible.prm"
  "$run" "$work/inextensible.prm" --output "$work/i" > "$work/i.log" 2>&1
  "$run" "$work/extensible.prm" --output "$work/e" > "$work/e.log" 2>&1
  dofs=$(sed -n 's/^rodnet: 1 rod(s), \([0-9]*\) DoFs,.*/\1/p' "$work/i.log" | head -1)
  pi=$(($(wc -l < "$work/i/probes.csv") - 2))
  pe=$(($(wc -l < "$work/e/probes.csv") - 2))
  read -r a b < <(in_turn "$run" "$repeats" "$work/inextensible.prm" "$work/extensible.prm")
  awk -v n=$n -v d="$dofs" -v a=$a -v b=$b -v pi=$pi -v pe=$pe 'BEGIN {
    printf "| %d | %s | %d | %.3f | %.4f | %d | %.3f | %.4f | %.2f |\n",
           n, d, pi, a, a / pi, pe, b, b / pe, (a / pi) / (b / pe) }'
done
