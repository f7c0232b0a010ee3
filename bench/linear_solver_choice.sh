#!/usr/bin/env bash
# Where "auto" switches from KLU to MUMPS (Solver/Linear solver,
# TangentFactorization::min_auto_mumps_rows = 30000): whole rodnet-run
# processes on one core, the welded square lattice of issue 37 (beams of
# 0.1 m in 10 segments, EA = 1e5, EI1 = 400, EI2 = 100, GJ = 67, pinned at its
# four corners, gravity on 0.05 kg/m in 2 load steps, no VTU) at CELLS x CELLS
# cells, once with Linear solver = klu and once with mumps, in turn, median
# of REPEATS runs each.
# Prints a markdown table (cells, DoFs, the two medians, MUMPS over KLU) and
# draws doc/linear_solver_choice.png: the ratio against the DoFs, with the
# threshold.
#
# Usage: bench/linear_solver_choice.sh [RODNET_RUN] [OUTPUT_DIR] [REPEATS (3)]
#        [CELLS... (5 10 20 35 60)]
set -euo pipefail
source "$(dirname "$0")/chart_paths.sh"
source "$root/bench/process_timing.sh"
source "$root/bench/welded_lattice_scene.sh"
repeats=${3:-3}
cells=("${@:4}")
[ ${#cells[@]} -gt 0 ] || cells=(5 10 20 35 60)

echo "| cells | DoFs | KLU (s) | MUMPS (s) | MUMPS / KLU |"
echo "|---|---|---|---|---|"
: > "$work/ratios.dat"
for n in "${cells[@]}"; do
  welded_lattice_scene "$n" "  set Linear solver = klu" > "$work/klu.prm"
  welded_lattice_scene "$n" "  set Linear solver = mumps" > "$work/mumps.prm"
  read -r klu mumps <<< "$(in_turn "$run" "$repeats" "$work/klu.prm" "$work/mumps.prm")"
  "$run" "$work/klu.prm" --output "$work/a" > "$work/size.log" 2>&1
  dofs=$(sed -n 's/^rodnet: .* \([0-9]*\) DoFs, memory.*/\1/p' "$work/size.log")
  awk -v n="$n" -v d="$dofs" -v k="$klu" -v m="$mumps" 'BEGIN {
    printf "| %d x %d | %d | %.2f | %.2f | %.3f |\n", n, n, d, k, m, m / k }'
  echo "$dofs $(awk -v k="$klu" -v m="$mumps" 'BEGIN { print m / k }')" >> "$work/ratios.dat"
done

gnuplot <<END
set terminal pngcairo size 640,440 font ",10"
set output "$out/linear_solver_choice.png"
set title "Welded lattice, whole runs on one core: MUMPS against KLU"
set xlabel "DoFs"
set ylabel "wall time, MUMPS / KLU (median of $repeats)"
set logscale x
set format x "10^{%L}"
set grid
set key bottom left
set arrow from 30000, graph 0 to 30000, graph 1 nohead dt 2 lc rgb "#d62728"
set label "auto: MUMPS from 30000 DoFs" at 32000, graph 0.92 tc rgb "#d62728"
plot "$work/ratios.dat" using 1:2 with linespoints pt 7 lw 1.5 lc rgb "#1f77b4" title "MUMPS / KLU", \
     1 with lines dt 3 lc rgb "black" notitle
END
