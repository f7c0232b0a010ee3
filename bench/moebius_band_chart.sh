#!/usr/bin/env bash
# The charts of the Moebius band in doc/ribbons.md, from
# scenes/moebius_band.prm (Wunderlich ribbon, L = 2 pi, D = 1, clamped
# closure, one clamp turned by pi):
#  - doc/moebius_energy.png: the normalized energy V / (D w) against the
#    half-width w (Starostin & van der Heijden's w) at N = 100 and 200;
#  - doc/moebius_strains.png: the strain densities kappa_1 / l (bending)
#    and kappa_3 / l (twist) along the band at N = 250 for three widths.
# Prints the table of V / (D w) and the widths where the band fails.
#
# Usage: bench/moebius_band_chart.sh [RODNET_RUN] [OUTPUT_DIR]
#        (defaults build/release/rodnet-run, doc/)
set -eu
source "$(dirname "$0")/chart_paths.sh"

source "$root/bench/moebius_scene.sh"

# The scene at N segments and half-width w, D = 1 (h = w, Y = 12 / h^3);
# VTU output at N = 250 only.
scene() {
  local vtu=false
  [ "$1" = 250 ] && vtu=true
  moebius_scene "$1" "$(awk -v w="$2" -v vtu=$vtu 'BEGIN {
    printf "subsection Material\n  subsection wunderlich ribbon\n"
    printf "    set Width = %.17g\n    set Thickness = %.17g\n", 2 * w, w
    printf "    set Young'"'"'s modulus = %.17g\n  end\nend\n", 12 / w ^ 3
    printf "subsection Output\n  set Plot = false\n  set Write VTU = %s\nend\n", vtu
  }')"
}

widths="0.02 0.05 0.1047197551 0.2 0.3 0.4 0.5 0.6 0.7 0.8 0.9 1.0 1.1 1.2 1.3 1.4 1.5 1.6 1.7 1.75 1.8"
for n in 100 200; do
  : > "$work/energy$n.dat"
  for w in $widths; do
    scene $n $w > "$work/m.prm"
    if "$run" "$work/m.prm" --output "$work/m" > "$work/m.log" 2>&1; then
      v=$(tail -1 "$work/m/probes.csv" | cut -d, -f3)
      echo "$w $(python3 -c "print($v / $w)")" >> "$work/energy$n.dat"
    else
      echo "N = $n, w = $w: $(tail -1 "$work/m.log")"
    fi
  done
done
echo "half-width w, V/(D w) at N = 100 and N = 200:"
join "$work/energy100.dat" "$work/energy200.dat"

for w in 0.1047197551 0.5 1.0; do
  scene 250 $w > "$work/s.prm"
  "$run" "$work/s.prm" --output "$work/s$w" > "$work/s.log" 2>&1
  last=$(ls "$work/s$w"/solution-*.vtu | sort | tail -1)
  python3 - "$last" > "$work/strains$w.dat" <<PY
import math, sys
sys.path.insert(0, "$root/bench")
from vtu_fields import read
f = read(sys.argv[1])
x = f["points"][0][1]
k = f["curvature"][0][1]
t = f["twist_rate"][0][1]
cells = len(x) // 6
s = 0.0
# The hinge at the end of each cell but the last (the clamped copy of the
# first), at the arclength from the middle of the clamped segment.
for c in range(cells - 1):
    s += math.dist(x[6 * c:6 * c + 3], x[6 * c + 3:6 * c + 6]) * (0.5 if c == 0 else 1)
    print(s, k[3 * (2 * c + 1)], t[2 * c + 1])
PY
done

gnuplot <<GP
set terminal pngcairo size 900,600 font ",11"
set output "$out/moebius_energy.png"
set title "Moebius band, Wunderlich ribbon (L = 2 pi, clamped closure)"
set xlabel "half-width w (Starostin & van der Heijden)"
set ylabel "V / (D w)"
set grid
set key top left
set arrow from pi/sqrt(3), graph 0 to pi/sqrt(3), graph 1 nohead dt 2
set label "w = pi / sqrt(3)" at pi/sqrt(3), graph 0.9 right offset -0.5,0
plot "$work/energy100.dat" using 1:2 with linespoints lw 2 title "N = 100", \
     "$work/energy200.dat" using 1:2 with linespoints lw 2 title "N = 200"
GP

gnuplot <<GP
set terminal pngcairo size 900,700 font ",11"
set output "$out/moebius_strains.png"
set multiplot layout 2,1 title "Moebius band: strains along the band, N = 250"
set grid
set key top right
set xrange [0:2*pi]
set ylabel "kappa_1 / l (bending)"
plot "$work/strains0.1047197551.dat" using 1:2 with lines lw 2 title "w = pi/30", \
     "$work/strains0.5.dat" using 1:2 with lines lw 2 title "w = 0.5", \
     "$work/strains1.0.dat" using 1:2 with lines lw 2 title "w = 1"
set xlabel "s, from the middle of the clamped segment"
set ylabel "kappa_3 / l (twist)"
plot "$work/strains0.1047197551.dat" using 1:3 with lines lw 2 title "w = pi/30", \
     "$work/strains0.5.dat" using 1:3 with lines lw 2 title "w = 0.5", \
     "$work/strains1.0.dat" using 1:3 with lines lw 2 title "w = 1"
unset multiplot
GP
echo "wrote $out/moebius_energy.png and $out/moebius_strains.png"
