#!/usr/bin/env bash
# Cost of an equilibrium of the Wunderlich Moebius band
# (scenes/moebius_band.prm: continuation of the clamp's turn from 0 to pi)
# against N, and what the ribbon's DoFs and constraints cost: the same
# scene with an inextensible Kirchhoff rod (linear elastic, EI1 = D w, EI2 =
# 1e3 EI1, GJ = D w: no developability, no eta) as the baseline, in turn,
# median of REPEATS whole runs (process start-up included) at N = 1e2 and
# 1e3, both to 0.9 of the clamp's turn (the rod has a fold just before the
# full turn that its continuation at N = 1e3 does not get past); one run of
# the band alone at N = 1e4 over the first 5 % of the turn (90 points, where
# the whole turn would take some 1500). Korner et al. report "about 0.1 s
# for each equilibrium" at N = 100.
# Prints a markdown table: N, DoFs, then per model the continuation points,
# the seconds and the seconds per point; the ratio per point.
#
# Usage: bench/moebius_cost.sh [RODNET_RUN] [REPEATS (3)]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
run=${1:-$root/build/release/rodnet-run}
repeats=${2:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source "$root/bench/process_timing.sh"

source "$root/bench/moebius_scene.sh"

scene() { # N, "ribbon" or "rod" (both to 0.9 of the turn), or "alone" (5 %)
  local range=0.9 material=""
  [ "$2" = alone ] && range=0.05
  [ "$2" = rod ] && material="subsection Material
  set Model = linear elastic
  set Inextensible = true
  subsection linear elastic
    set Stiffness input = direct
    set EA = 1
    set EI1 = 0.20943951023931953
    set EI2 = 209.43951023931953
    set GJ = 0.20943951023931953
  end
end"
  moebius_scene "$1" "subsection Solver
  subsection Continuation
    set Max points = 5000
    set Load factor range = -0.01, $range
  end
end
subsection Output
  set Plot = false
  set Write VTU = false
end
$material"
}

points() { echo $(($(wc -l < "$1/probes.csv") - 2)); }
dofs() { grep -o "[0-9]* DoFs" "$1" | tail -1 | cut -d' ' -f1; }

echo "| N | ribbon DoFs | ribbon points | s | s per point | rod points | s | s per point | ratio per point |"
echo "|---|---|---|---|---|---|---|---|---|"
for n in 100 1000; do
  scene $n ribbon > "$work/ribbon.prm"
  scene $n rod > "$work/rod.prm"
  read -r ta tb < <(in_turn "$run" "$repeats" "$work/ribbon.prm" "$work/rod.prm")
  "$run" "$work/ribbon.prm" --output "$work/a" > "$work/a.log" 2>&1
  pa=$(points "$work/a"); pb=$(points "$work/b")
  awk -v n=$n -v d="$(dofs "$work/a.log")" -v pa=$pa -v ta=$ta -v pb=$pb -v tb=$tb \
    'BEGIN { printf "| %d | %s | %d | %.3f | %.4f | %d | %.3f | %.4f | %.2f |\n",
             n, d, pa, ta, ta / pa, pb, tb, tb / pb, (ta / pa) / (tb / pb) }'
done
scene 10000 alone > "$work/ribbon.prm"
t=$(seconds "$run" "$work/ribbon.prm" --output "$work/a")
"$run" "$work/ribbon.prm" --output "$work/a" > "$work/a.log" 2>&1 || true
p=$(points "$work/a")
awk -v d="$(dofs "$work/a.log")" -v p=$p -v t=$t \
  'BEGIN { printf "| 10000 | %s | %d | %.3f | %.4f | - | - | - | - |\n", d, p, t, t / p }'
