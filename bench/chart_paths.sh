# Sourced by the chart scripts of doc/ (Usage: SCRIPT [RODNET_RUN]
# [OUTPUT_DIR]): $root the source tree, $run the rodnet-run to use
# (default build/release/rodnet-run), $out where the PNGs go (default
# doc/), $work a scratch directory removed when the script exits.
root=$(cd "$(dirname "${BASH_SOURCE[1]}")/.." && pwd)
run=${1:-$root/build/release/rodnet-run}
out=${2:-$root/doc}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
