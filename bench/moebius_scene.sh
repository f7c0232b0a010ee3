# Sourced by the benchmark scripts that run scenes/moebius_band.prm.
#
# moebius_scene N [BLOCKS]: the shipped scene with N segments (its arc from
# -Delta/2 to 360 + Delta/2 degrees, Delta = 360 / (N - 1), so that the
# last segment lies on the first), followed by the subsections BLOCKS.
# Needs $root, the source tree.
moebius_scene() {
  cat "$root/scenes/moebius_band.prm"
  awk -v n="$1" 'BEGIN {
    d = 360 / (n - 1)
    printf "subsection Geometry\n  set Segments = %d\n", n
    printf "  set Start angle = %.17g\n  set End angle = %.17g\nend\n", -d / 2, 360 + d / 2
  }'
  printf '%s\n' "${2:-}"
}
