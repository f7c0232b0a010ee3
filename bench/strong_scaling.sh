#!/usr/bin/env bash
# Strong scaling of whole rodnet-run processes on the welded square lattice
# of issue 37 (beams of 0.1 m in 10 segments, EA = 1e5, EI1 = 400,
# EI2 = 100, GJ = 67, pinned at its four corners, gravity on 0.05 kg/m in 2
# load steps, Line search = energy, Predictor = false, MUMPS, no VTU) at
# CELLS x CELLS cells, on the machine's two cores three ways, taking turns,
# REPEATS runs each:
#   1 x 1   one process, one thread;
#   1 x 2   one process, two threads (--threads 2: the assembly);
#   2 x 1   two processes under mpirun, one thread each.
# The energy line search: with full steps the first step of the 112 x 112
# lattice diverges and converges only from its buckling mode (266 s on one
# process, doc/performance.md). No predictor: on this stiffening lattice
# Newton starts better from the last equilibrium (doc/performance.md, "The
# predictor where the response stiffens").
# Prints a markdown table (configuration, median wall time, speed-up over
# 1 x 1) per lattice and draws doc/strong_scaling.png: the speed-ups against
# the DoFs, with the issue's goal of 1.7x.
#
# Usage: bench/strong_scaling.sh [RODNET_RUN] [OUTPUT_DIR] [REPEATS (3)]
#        [CELLS... (35 112)]
set -euo pipefail
source "$(dirname "$0")/chart_paths.sh"
source "$root/bench/process_timing.sh"
source "$root/bench/welded_lattice_scene.sh"
repeats=${3:-3}
cells=("${@:4}")
[ ${#cells[@]} -gt 0 ] || cells=(35 112)
mpirun=(mpirun --oversubscribe -np 2)
[ "$(id -u)" -eq 0 ] && mpirun=(mpirun --allow-run-as-root --oversubscribe -np 2)

: > "$work/speedups.dat"
for n in "${cells[@]}"; do
  welded_lattice_scene "$n" \
    $'  set Line search = energy\n  set Linear solver = mumps\n  set Predictor = false' \
    > "$work/lattice.prm"
  one=() threads=() processes=()
  for ((k = 0; k < repeats; ++k)); do
    one+=("$(seconds "$run" "$work/lattice.prm" --output "$work/a" --threads 1)")
    threads+=("$(seconds "$run" "$work/lattice.prm" --output "$work/b" --threads 2)")
    processes+=("$(seconds "${mpirun[@]}" "$run" "$work/lattice.prm" --output "$work/c" --threads 1)")
  done
  # The last run's log (process_timing.sh's $work/log) names the DoFs.
  dofs=$(sed -n 's/^rodnet: .* \([0-9]*\) DoFs, .*/\1/p' "$work/log" | head -1)
  t1=$(echo "${one[*]}" | median)
  t2=$(echo "${threads[*]}" | median)
  tp=$(echo "${processes[*]}" | median)
  echo
  echo "$n x $n cells, $dofs DoFs, median of $repeats runs each:"
  echo
  echo "| configuration | wall (s) | speed-up over 1 x 1 |"
  echo "|---|---|---|"
  awk -v a="$t1" -v b="$t2" -v c="$tp" 'BEGIN {
    printf "| 1 process x 1 thread | %.2f | 1 |\n", a
    printf "| 1 process x 2 threads | %.2f | %.2f |\n", b, a / b
    printf "| 2 processes x 1 thread | %.2f | %.2f |\n", c, a / c }'
  awk -v d="$dofs" -v a="$t1" -v b="$t2" -v c="$tp" \
    'BEGIN { print d, a / b, a / c }' >> "$work/speedups.dat"
done

gnuplot <<END
set terminal pngcairo size 640,440 font ",10"
set output "$out/strong_scaling.png"
set title "Welded lattice, whole runs on 2 cores: speed-up over 1 process x 1 thread"
set xlabel "DoFs"
set ylabel "speed-up (median of $repeats)"
set logscale x
set format x "10^{%L}"
set xrange [5e4:3e6]
set yrange [0.8:2.4]
set grid
set key top left box opaque
plot "$work/speedups.dat" using 1:3 with linespoints pt 7 lw 1.5 lc rgb "#1f77b4" title "2 processes x 1 thread", \
     "$work/speedups.dat" using 1:2 with linespoints pt 5 lw 1.5 lc rgb "#ff7f0e" title "1 process x 2 threads", \
     1.7 with lines dt 2 lc rgb "#d62728" title "goal at 1e6 DoFs (issue 37)", \
     2 with lines dt 3 lc rgb "black" title "ideal"
END
