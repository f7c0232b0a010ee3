#!/usr/bin/env bash
# Accuracy against cost of the welded lattice of issue 37 (beams of 0.1 m,
# EA = 1e5, EI1 = 400, EI2 = 100, GJ = 67, pinned at its four corners,
# gravity on 0.05 kg/m in 2 load steps, no VTU) at CELLS x CELLS cells, for
# each solver configuration:
#   klu      one process, KLU;
#   mumps    one process, MUMPS;
#   mumps2   two processes under mpirun, MUMPS;
# and each number of segments per beam of SEGMENTS, at Newton's default
# tolerance. The error is that of the centre's deflection (position z of the
# middle junction) against a reference run of 32 segments per beam (MUMPS,
# tolerance 1e-12), relative to the deflection; the cost the median wall
# time of REPEATS whole rodnet-run processes. Then the other dial, the
# Newton tolerance (Solver/Relative tolerance of TOLERANCES, MUMPS on one
# process, 10 segments per beam): the error of the deflection against the
# same discretization at 1e-12 (the solver's error alone).
# Prints two markdown tables and draws doc/lattice_accuracy_cost.png: the
# discretization error against the wall time, one line per configuration,
# each point labelled with its segments per beam.
#
# Usage: bench/lattice_accuracy_cost.sh [RODNET_RUN] [OUTPUT_DIR]
#        [REPEATS (3)] [CELLS (35)] [SEGMENTS (2,4,8,16)]
#        [TOLERANCES (1e-2,1e-4,1e-6,1e-9)]
set -euo pipefail
source "$(dirname "$0")/chart_paths.sh"
source "$root/bench/process_timing.sh"
source "$root/bench/welded_lattice_scene.sh"
repeats=${3:-3}
n=${4:-35}
IFS=, read -r -a segments <<< "${5:-2,4,8,16}"
IFS=, read -r -a tolerances <<< "${6:-1e-2,1e-4,1e-6,1e-9}"
mkdir -p "$out"
mpirun=(mpirun --oversubscribe -np 2)
[ "$(id -u)" -eq 0 ] && mpirun=(mpirun --allow-run-as-root --oversubscribe -np 2)
centre="@n_$((n / 2))_$((n / 2))"

# scene SOLVER SEGMENTS [TOLERANCE]: the lattice with that linear solver,
# segments per beam and Newton tolerance, probing the centre's height.
scene() {
  welded_lattice_scene "$n" "  set Linear solver = $1${3:+
  set Relative tolerance = $3}" | sed "s/set Segments = 10/set Segments = $2/"
  printf 'subsection Output\n  set Probes = centre_z: position %s z\nend\n' "$centre"
}

# The centre's height in row ROW (default: the last) of probes.csv of the
# run in $1.
centre_z() {
  awk -F, -v row="${2:-0}" 'NR == 1 { for (k = 1; k <= NF; ++k) if ($k == "centre_z") c = k }
    NR > 1 { v[NR - 1] = $c; last = NR - 1 }
    END { printf "%.17g", (row > 0 ? v[row] : v[last]) }' "$1/probes.csv"
}

# median_seconds COMMAND... SCENE: the median wall time of REPEATS runs.
median_seconds() {
  local times=() k
  for ((k = 0; k < repeats; ++k)); do
    times+=("$(seconds "$@" --output "$work/run")")
  done
  echo "${times[*]}" | median
}

# relative_error Z REFERENCE Z0: |Z - REFERENCE| / |REFERENCE - Z0|.
relative_error() {
  awk -v z="$1" -v r="$2" -v z0="$3" \
    'BEGIN { e = (z - r) / (r - z0); e = e < 0 ? -e : e + 0; printf "%.3g", e }'
}

scene mumps 32 1e-12 > "$work/reference.prm"
"$run" "$work/reference.prm" --output "$work/reference" > "$work/log" 2>&1
reference=$(centre_z "$work/reference")
z0=$(centre_z "$work/reference" 1)

echo
echo "$n x $n cells; reference centre deflection $(awk -v a="$reference" -v b="$z0" 'BEGIN { printf "%.10g", a - b }') m (32 segments per beam, MUMPS, tolerance 1e-12); median of $repeats runs each:"
echo
echo "| configuration | segments per beam | DoFs | wall (s) | relative error of the deflection |"
echo "|---|---|---|---|---|"
for configuration in klu mumps mumps2; do
  solver=${configuration%2}
  launch=("$run")
  [ "$configuration" = mumps2 ] && launch=("${mpirun[@]}" "$run")
  : > "$work/$configuration.dat"
  for m in "${segments[@]}"; do
    scene "$solver" "$m" > "$work/run.prm"
    wall=$(median_seconds "${launch[@]}" "$work/run.prm")
    dofs=$(sed -n 's/^rodnet: .* \([0-9]*\) DoFs, .*/\1/p' "$work/log" | head -1)
    error=$(relative_error "$(centre_z "$work/run")" "$reference" "$z0")
    echo "| $configuration | $m | $dofs | $wall | $error |"
    echo "$m $wall $error" >> "$work/$configuration.dat"
  done
done

scene mumps 10 1e-12 > "$work/tight.prm"
"$run" "$work/tight.prm" --output "$work/tight" > "$work/log" 2>&1
echo
echo "The Newton tolerance, MUMPS on one process, 10 segments per beam; the error against the same at 1e-12:"
echo
echo "| tolerance | wall (s) | relative error of the deflection |"
echo "|---|---|---|"
for tolerance in "${tolerances[@]}"; do
  scene mumps 10 "$tolerance" > "$work/run.prm"
  wall=$(median_seconds "$run" "$work/run.prm")
  echo "| $tolerance | $wall | $(relative_error "$(centre_z "$work/run")" "$(centre_z "$work/tight")" "$z0") |"
done

gnuplot <<END
set terminal pngcairo size 720,480 font ",10"
set output "$out/lattice_accuracy_cost.png"
set title "Welded lattice, $n x $n cells: accuracy against cost"
set xlabel "wall time (s), whole rodnet-run process, median of $repeats"
set ylabel "relative error of the centre's deflection"
set logscale xy
set format y "10^{%L}"
set grid
set key top right box opaque
plot "$work/klu.dat" using 2:3 with linespoints pt 7 lw 1.5 lc rgb "#1f77b4" title "KLU, 1 process", \
     "$work/klu.dat" using 2:3:(sprintf("%d", \$1)) with labels left offset 1,0.4 tc rgb "#1f77b4" notitle, \
     "$work/mumps.dat" using 2:3 with linespoints pt 5 lw 1.5 lc rgb "#ff7f0e" title "MUMPS, 1 process", \
     "$work/mumps2.dat" using 2:3 with linespoints pt 9 lw 1.5 lc rgb "#2ca02c" title "MUMPS, 2 processes", \
     "$work/mumps2.dat" using 2:3:(sprintf("%d", \$1)) with labels right offset -1,-0.4 tc rgb "#2ca02c" notitle
END
