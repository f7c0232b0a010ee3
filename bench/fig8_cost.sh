#!/usr/bin/env bash
# Time, DoFs and accuracy of Lestringant & Kochmann's Fig. 8a
# (scenes/fig8_pinned_lattice_a.prm: 11 x 11 cells, every junction pinned,
# axial eigenstrain ramped to 0.03 by continuation, one imperfection
# moment): for SEGMENTS per beam (the paper's 10 among them), the median
# wall time of REPEATS whole rodnet-run processes (one core, no VTU, no
# plot), the DoFs, the continuation points and the joint rotation tau_z at
# n_2_2 (three cells from the moment) at eigenstrain 0.03, with its error
# against the continuous pinned-pinned column's end rotation 0.2964641124
# (the shooting solution of tests/validation/pinned_lattice.cc). Prints a
# markdown table and draws the error against the wall time into PNG.
#
# Usage: bench/fig8_cost.sh [RODNET_RUN] [REPEATS (5)] [PNG] [SEGMENTS...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
run=${1:-$root/build/release/rodnet-run}
repeats=${2:-5}
png=${3:-$root/doc/fig8_accuracy_cost.png}
shift $(($# > 3 ? 3 : $#))
segments_list=${*:-5 10 20 40}
reference=0.2964641124
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

source "$root/bench/process_timing.sh"

echo "| segments per beam | DoFs | points | wall time s (median of $repeats) | tau_z at 0.03 | error |"
echo "|---|---|---|---|---|---|"
: > "$work/table.dat"
for n in $segments_list; do
  {
    cat "$root/scenes/fig8_pinned_lattice_a.prm"
    printf 'subsection Geometry\n  set Segments = %s\nend\n' "$n"
    printf 'subsection Output\n  set Write VTU = false\n  set Plot = false\nend\n'
  } > "$work/scene.prm"
  times=()
  for ((k = 0; k < repeats; ++k)); do
    times+=("$(seconds "$run" "$work/scene.prm" --output "$work/out")")
  done
  "$run" "$work/scene.prm" --output "$work/out" > "$work/run.log" 2>&1
  dofs=$(sed -n 's/.*rod(s), .*, \([0-9]*\) DoFs.*/\1/p' "$work/run.log" | head -1)
  points=$(($(wc -l < "$work/out/probes.csv") - 2))
  tau=$(awk -F, 'NR == 1 { for (c = 1; c <= NF; ++c) if ($c == "tau_2_2") t = c }
                 END { print $t }' "$work/out/probes.csv")
  t=$(echo "${times[*]}" | median)
  awk -v n="$n" -v d="$dofs" -v p="$points" -v t="$t" -v tau="$tau" \
      -v r="$reference" 'BEGIN {
    e = (tau < 0 ? -tau : tau) / r - 1; if (e < 0) e = -e
    printf "| %d | %d | %d | %.2f | %.6f | %.2e |\n", n, d, p, t, tau, e
    printf "%d %.4f %.3e\n", n, t, e >> "'"$work/table.dat"'" }'
done

gnuplot <<END
set terminal pngcairo size 640,440 font ",10"
set output "$png"
set logscale xy
set format y "10^{%L}"
set xlabel "wall time (s), one core, whole rodnet-run process"
set ylabel "relative error of tau_z at eigenstrain 0.03"
set title "Fig. 8a (11 x 11 cells): joint rotation against the continuous column"
set key off
set grid
plot "$work/table.dat" using 2:3 with linespoints pt 7 lw 1.5 lc rgb "#1f77b4", \
     "$work/table.dat" using 2:3:(sprintf("%d per beam", \$1)) with labels offset 0,1
END
