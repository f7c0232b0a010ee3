#!/usr/bin/env bash
# Dynamic relaxation on one and on two processes: a square lattice of
# CELLS x CELLS cells (beams of 1 m in 4 segments, EA = 1e3, EI1 = EI2 =
# GJ = 1), its bottom row pinned and its top row pulled by 1e-3 m in y,
# relaxed in one load step to the default residual tolerance (no VTU).
# Each size runs REPEATS times per configuration, taking turns:
#   1   one process;
#   2   two processes under mpirun (DrProcessShare: each evaluates half of
#       the elements and moves the DoFs they touch).
# Prints a markdown table per lattice (median wall time of the whole run
# and of the relaxation alone, from the log's "DR step" line, and the
# speed-ups of two processes) and draws doc/dr_processes.png: the
# speed-ups against the DoFs.
#
# Usage: bench/dr_processes.sh [RODNET_RUN] [OUTPUT_DIR] [REPEATS (3)]
#        [CELLS... (30 60)]
set -euo pipefail
source "$(dirname "$0")/chart_paths.sh"
source "$root/bench/process_timing.sh"
repeats=${3:-3}
cells=("${@:4}")
[ ${#cells[@]} -gt 0 ] || cells=(30 60)
mkdir -p "$out"
mpirun=(mpirun --oversubscribe -np 2)
[ "$(id -u)" -eq 0 ] && mpirun=(mpirun --allow-run-as-root --oversubscribe -np 2)

# stretched_lattice_scene CELLS: the scene described above.
stretched_lattice_scene() {
  local n=$1 i pins=() pulls=()
  for ((i = 0; i <= n; ++i)); do
    pins+=("@n_${i}_0")
    pulls+=("@n_${i}_${n}: y=1e-3 z=0")
  done
  cat <<END
subsection Geometry
  set Generator = square lattice
  set Cells = $n, $n
  set Beam length = 1
  set Segments = 4
end
subsection Material
  subsection linear elastic
    set Stiffness input = direct
    set EA = 1e3
    set EI1 = 1
    set EI2 = 1
    set GJ = 1
  end
end
subsection Supports
  set Pinned vertices = $(IFS=,; echo "${pins[*]}")
  set Prescribed displacements = $(IFS=';'; echo "${pulls[*]}")
end
subsection Loads
  set Steps = 1
end
subsection Solver
  set Method = dynamic relaxation
end
subsection Output
  set Probes = corner_force_y: reaction @n_0_$n y
  set Write VTU = false
  set Plot = false
end
END
}

# The relaxation's seconds in the last run's log.
relaxation_seconds() { sed -n 's/^  DR step 1, .*, \([0-9.e+-]*\) s$/\1/p' "$work/log"; }

: > "$work/speedups.dat"
for n in "${cells[@]}"; do
  stretched_lattice_scene "$n" > "$work/lattice.prm"
  one=() one_dr=() two=() two_dr=()
  for ((k = 0; k < repeats; ++k)); do
    one+=("$(seconds "$run" "$work/lattice.prm" --output "$work/a")")
    one_dr+=("$(relaxation_seconds)")
    two+=("$(seconds "${mpirun[@]}" "$run" "$work/lattice.prm" --output "$work/b")")
    two_dr+=("$(relaxation_seconds)")
  done
  dofs=$(sed -n 's/^rodnet (dynamic relaxation): .* \([0-9]*\) DoFs, .*/\1/p' "$work/log")
  iterations=$(sed -n 's/^  DR step 1, [^:]*: \([0-9]*\) iterations.*/\1/p' "$work/log")
  t1=$(echo "${one[*]}" | median) d1=$(echo "${one_dr[*]}" | median)
  t2=$(echo "${two[*]}" | median) d2=$(echo "${two_dr[*]}" | median)
  echo
  echo "$n x $n cells, $dofs DoFs, $iterations iterations, median of $repeats runs each:"
  echo
  echo "| processes | whole run (s) | relaxation (s) | speed-up, whole run | speed-up, relaxation |"
  echo "|---|---|---|---|---|"
  awk -v a="$t1" -v b="$t2" -v c="$d1" -v d="$d2" 'BEGIN {
    printf "| 1 | %.2f | %.2f | 1 | 1 |\n", a, c
    printf "| 2 | %.2f | %.2f | %.2f | %.2f |\n", b, d, a / b, c / d }'
  awk -v n="$dofs" -v a="$t1" -v b="$t2" -v c="$d1" -v d="$d2" \
    'BEGIN { print n, a / b, c / d }' >> "$work/speedups.dat"
done

gnuplot <<END
set terminal pngcairo size 640,440 font ",10"
set output "$out/dr_processes.png"
set title "Dynamic relaxation of a stretched lattice: 2 processes over 1"
set xlabel "DoFs"
set ylabel "speed-up (median of $repeats)"
set logscale x
set format x "10^{%L}"
set yrange [0.8:2.4]
set grid
set key top left box opaque
plot "$work/speedups.dat" using 1:3 with linespoints pt 7 lw 1.5 lc rgb "#1f77b4" title "the relaxation", \
     "$work/speedups.dat" using 1:2 with linespoints pt 5 lw 1.5 lc rgb "#ff7f0e" title "whole run (set-up, output, mpirun)", \
     2 with lines dt 3 lc rgb "black" title "ideal"
END
