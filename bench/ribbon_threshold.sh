#!/usr/bin/env bash
# The threshold width of twist-induced snapping of scenes/ribbon_snapping.prm
# (doc/ribbons.md): a ribbon snaps if the path of the shipped scene, with
# its width changed, has a limit point below phi = 180 degrees (load
# factor 1). Bisection on the width between 8 mm (snaps) and 15 mm (does
# not) down to 0.05 mm, then the comparison with w* = 1.24 sqrt(L h)
# (Sano & Wada, quoted by Korner et al. section 5(c)).
#
# Usage: bench/ribbon_threshold.sh [RODNET_RUN] [SEGMENTS]
#        (defaults build/release/rodnet-run, 100)
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
run=${1:-$root/build/release/rodnet-run}
segments=${2:-100}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The fold's load factor at width $1 (m), or "none" below load factor 1.
fold() {
  local start end
  start=$(awk -v n="$segments" 'BEGIN { printf "%.15g", -90 / (n - 1) }')
  end=$(awk -v n="$segments" 'BEGIN { printf "%.15g", 180 + 90 / (n - 1) }')
  cat "$root/scenes/ribbon_snapping.prm" - > "$work/ribbon.prm" <<END
subsection Geometry
  set Segments = $segments
  set Start angle = $start
  set End angle = $end
end
subsection Material
  subsection sano-wada ribbon
    set Width = $1
  end
end
subsection Solver
  subsection Continuation
    set Max points = 400
  end
end
subsection Output
  set Plot = false
end
END
  "$run" "$work/ribbon.prm" --output "$work/out" > "$work/log" 2>&1 || true
  grep -m1 -o "limit point at load factor [0-9.e+-]*" "$work/log" |
    awk '{ if ($6 < 0.999) print $6; else print "none" }' |
    grep . || echo none
}

low=0.008
high=0.015
for w in $low $high; do
  echo "width $w m: fold at load factor $(fold $w)"
done
while awk -v a="$low" -v b="$high" 'BEGIN { exit !(b - a > 5e-5) }'; do
  mid=$(awk -v a="$low" -v b="$high" 'BEGIN { printf "%.6f", (a + b) / 2 }')
  f=$(fold "$mid")
  printf "width %.5f m: fold at load factor %s\n" "$mid" "$f"
  if [ "$f" = none ]; then high=$mid; else low=$mid; fi
done
printf "threshold width between %.5f and %.5f m (N = %s)\n" "$low" "$high" \
  "$segments"
awk 'BEGIN { printf "Sano & Wada: w* = 1.24 sqrt(L h) = %.5f m\n",
             1.24 * sqrt(3.141592653589793 * 0.108 * 2e-4) }'
