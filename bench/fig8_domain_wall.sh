#!/usr/bin/env bash
# The domain wall of Lestringant & Kochmann's Fig. 8b as a picture: runs
# scenes/fig8_pinned_lattice_b.prm with a VTU of its last state and the
# joint rotation tau_z of every junction, and draws with gnuplot the
# undeformed lattice (grey), the deformed one at eigenstrain 0.03 (black,
# displacements to scale) and every junction as a point coloured by its
# tau_z times (-1)^(i + j): the pattern's sign, +-0.29 rad in the two
# domains, less at the wall (the paper shows the rotations this way); the
# junctions of the two imperfection moments circled.
#
# Usage: bench/fig8_domain_wall.sh [RODNET_RUN] [PNG (doc/fig8_domain_wall.png)]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
run=${1:-$root/build/release/rodnet-run}
png=${2:-$root/doc/fig8_domain_wall.png}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cells=$(sed -n 's/^ *set Cells = \([0-9]*\),.*/\1/p' \
  "$root/scenes/fig8_pinned_lattice_b.prm")
probes=""
for ((i = 0; i <= cells; ++i)); do
  for ((j = 0; j <= cells; ++j)); do
    probes+="t_${i}_${j}: rotation n_${i}_${j} 0,0,1; "
  done
done
{
  cat "$root/scenes/fig8_pinned_lattice_b.prm"
  printf 'subsection Output\n  set Write VTU = true\n  set Plot = false\n'
  printf '  set Probes = %s\nend\n' "${probes%; }"
} > "$work/scene.prm"
"$run" "$work/scene.prm" --output "$work/out" > "$work/log" 2>&1 ||
  { cat "$work/log" >&2; exit 1; }

# The last VTU, as x y z ux uy uz rows, a blank line after every segment.
last=$(ls "$work"/out/solution-*.vtu | sort | tail -1)
python3 "$root/bench/vtu_table.py" "$last" displacement > "$work/beams.dat"
# Junction i j, its position and the pattern's sign of its rotation.
awk -F, -v n="$cells" 'NR == 1 { for (c = 1; c <= NF; ++c) col[$c] = c }
  END { for (i = 0; i <= n; ++i) for (j = 0; j <= n; ++j) {
          t = $(col["t_" i "_" j]); s = ((i + j) % 2 == 0) ? t : -t
          print i, j, s } }' "$work/out/probes.csv" > "$work/joints.dat"
lambda=$(tail -1 "$work/out/probes.csv" | cut -d, -f2)
# The junctions of the imperfection moments, circled.
sed -n 's/^ *set Moments = //p' "$root/scenes/fig8_pinned_lattice_b.prm" |
  grep -o 'n_[0-9]*_[0-9]*' | tr '_' ' ' | cut -d' ' -f2,3 > "$work/moments.dat"

gnuplot <<END
set terminal pngcairo size 640,600 font ",10"
set output "$png"
set size ratio -1
set title sprintf("Fig. 8b: %d x %d cells at eigenstrain %.3f; circled: the moments", $cells, $cells, 0.03 * $lambda)
set xlabel "x / L"
set ylabel "y / L"
set key off
set cbrange [-0.3:0.3]
set cblabel "tau_z (-1)^{i+j} (rad)"
set palette defined (-0.3 "#2166ac", 0 "#f7f7f7", 0.3 "#b2182b")
set xrange [-0.5:$cells + 0.5]
set yrange [-0.5:$cells + 0.5]
plot "$work/beams.dat" using 1:2 with lines lc rgb "#c8c8c8" lw 1, \
     "$work/beams.dat" using (\$1 + \$4):(\$2 + \$5) with lines lc rgb "black" lw 1.2, \
     "$work/joints.dat" using 1:2:3 with points pt 7 ps 1.3 lc palette, \
     "$work/moments.dat" using 1:2 with points pt 6 ps 2.4 lw 1.5 lc rgb "black"
END
echo "wrote $png ($(stat -c %s "$png") bytes)"
