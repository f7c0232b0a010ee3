#!/usr/bin/env bash
# Whole-process times of rodnet-run (start-up included), median (min-max) of
# repeated runs, taken in turn so that a drift of the machine's speed hits
# every figure alike:
#   1. rodnet-run --version
#   2. P1 (scenes/p1_gravity_cantilever.prm, 999 segments, one load step)
#   3. P1 at five meshes (49, 99, 199, 499, 999 segments) as one sweep in one
#      process, against the same five as five processes.
# Usage: bench/whole_process.sh [BUILD_DIR (build/release)] [REPEATS (5)]
# Writes whole_process.csv (figure, median_s, min_s, max_s) in the current
# directory; doc/performance.md ("Start-up") quotes it.
set -euo pipefail
source_dir="$(cd "$(dirname "$0")/.." && pwd)"
build="$(cd "${1:-$source_dir/build/release}" && pwd)"
repeats="${2:-5}"
run="$build/rodnet-run"
scene="$source_dir/scenes/p1_gravity_cantilever.prm"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
meshes=(49 99 199 499 999)

source "$source_dir/bench/process_timing.sh"

five_processes() {
  for n in "${meshes[@]}"; do
    sed "s/set Segments = 999/set Segments = $n/" "$scene" > "$work/p1_$n.prm"
    "$run" "$work/p1_$n.prm" --output "$work/out_$n" || return 1
  done
}

one_sweep() {
  "$run" "$scene" --sweep "Geometry/Segments=$(IFS=,; echo "${meshes[*]}")" \
    --output "$work/sweep"
}

declare -A samples
figures=(version p1_n1000 five_meshes_one_process five_meshes_five_processes)
for ((r = 0; r < repeats; ++r)); do
  samples[version]+=" $(seconds "$run" --version)"
  samples[p1_n1000]+=" $(seconds "$run" "$scene" --output "$work/p1")"
  samples[five_meshes_one_process]+=" $(seconds one_sweep)"
  samples[five_meshes_five_processes]+=" $(seconds five_processes)"
done

echo "figure,median_s,min_s,max_s" > whole_process.csv
for f in "${figures[@]}"; do
  sorted=($(tr ' ' '\n' <<< "${samples[$f]}" | sed '/^$/d' | sort -g))
  n=${#sorted[@]}
  median=${sorted[$((n / 2))]}
  printf "%-28s median %7.3f s  (%.3f-%.3f, %d runs)\n" "$f" "$median" \
    "${sorted[0]}" "${sorted[$((n - 1))]}" "$n"
  echo "$f,$median,${sorted[0]},${sorted[$((n - 1))]}" >> whole_process.csv
done
