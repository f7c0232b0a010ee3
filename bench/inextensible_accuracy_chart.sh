#!/usr/bin/env bash
# Accuracy against cost of exact inextensibility: the elastica (B = L = 1,
# EI2 = 2 EI1, no imperfection) followed by continuation to P = 5 at
# N = 25 ... 800 segments, inextensible and extensible (EA = 1e7, and
# EA = 4e4, a solid circular section of L/r = 100), each run timed (median
# of REPEATS whole runs of rodnet-run). Error: the largest distance of the
# tip (x, deflection) from the exact inextensible elastica at P = 3, 4, 5
# (VALIDATION.md). Writes doc/inextensible_accuracy_cost.png and prints the
# table.
#
# Usage: bench/inextensible_accuracy_chart.sh [RODNET_RUN] [OUTPUT_DIR]
#        [REPEATS (3)]
set -euo pipefail
source "$(dirname "$0")/chart_paths.sh"
source "$root/bench/process_timing.sh"
source "$root/bench/elastica_scene.sh"
repeats=${3:-3}

scene() { # N, Inextensible, EA
  elastica_scene "$1" "$2" "$3" "subsection Loads
  set Point forces = end: -1, 0, 0
end
subsection Solver
  set Method = continuation
  subsection Continuation
    set Load factor range = -1, 5
    set Output load factors = 3, 4, 5
    set Initial step = 0.1
  end
end" "x: position end x; y: position end y; z: position end z"
}

# Largest tip error at P = 3, 4, 5 in probes.csv $1 (exact values from
# VALIDATION.md).
tip_error() {
  awk -F, 'NR > 1 {
    ex[3] = 0.653178; ed[3] = 0.663629; ex[4] = 0.274180; ed[4] = 0.802407
    ex[5] = 0.059784; ed[5] = 0.795217
    p = $2 + 0
    if (p == 3 || p == 4 || p == 5) {
      d = sqrt($4 * $4 + $5 * $5); e1 = $3 - ex[p]; e2 = d - ed[p]
      e = (e1 < 0 ? -e1 : e1); e2 = (e2 < 0 ? -e2 : e2); if (e2 > e) e = e2
      if (e > worst) worst = e
    }
  } END { printf "%.3e", worst }' "$1"
}

models=("true 1e7 inextensible" "false 1e7 EA=1e7" "false 4e4 EA=4e4")
echo "| model | N | seconds | tip error / L |"
echo "|---|---|---|---|"
for m in "${models[@]}"; do
  read -r inextensible ea name <<< "$m"
  : > "$work/$name.dat"
  for n in 25 50 100 200 400 800; do
    scene $n $inextensible $ea > "$work/s.prm"
    times=()
    for ((k = 0; k < repeats; ++k)); do
      times+=("$(seconds "$run" "$work/s.prm" --output "$work/o")")
    done
    t=$(echo "${times[*]}" | median)
    e=$(tip_error "$work/o/probes.csv")
    echo "$t $e $n" >> "$work/$name.dat"
    echo "| $name | $n | $t | $e |"
  done
done

gnuplot <<END
set terminal pngcairo size 760,520 font ",11"
set output "$out/inextensible_accuracy_cost.png"
set logscale xy
set format y "10^{%T}"
set xlabel "seconds per path to P = 5 B/L^2 (continuation, whole run)"
set ylabel "largest tip error / L at P = 3, 4, 5"
set title "Elastica: exact inextensibility against extensible rods (N = 25 ... 800)"
set key top right
set grid
plot "$work/inextensible.dat" using 1:2 with linespoints lw 2 pt 7 title "inextensible (multipliers)", \
     "$work/EA=1e7.dat" using 1:2 with linespoints lw 2 pt 5 title "extensible, EA = 1e7 EI/L^2", \
     "$work/EA=4e4.dat" using 1:2 with linespoints lw 2 pt 9 title "extensible, EA = 4e4 EI/L^2 (L/r = 100)"
END
