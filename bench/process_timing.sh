# Sourced by the benchmark scripts that time whole rodnet-run processes.
# The sourcing script sets $work, a scratch directory.

# Seconds of one run of "$@" (its output thrown away; a failure stops all).
seconds() {
  local start end
  start=$(date +%s%N)
  "$@" > "$work/log" 2>&1 || { cat "$work/log" >&2; exit 1; }
  end=$(date +%s%N)
  awk -v a="$start" -v b="$end" 'BEGIN { printf "%.4f", (b - a) / 1e9 }'
}

# The median of the numbers on stdin, separated by blanks or newlines.
median() { tr ' ' '\n' | sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }

# in_turn RUN REPEATS A.prm B.prm: runs RUN on the two scenes in turn
# (output into $work/a and $work/b), REPEATS times, so that a drift of the
# machine's speed hits both alike; prints the two median seconds.
in_turn() {
  local run=$1 repeats=$2 k ta=() tb=()
  for ((k = 0; k < repeats; ++k)); do
    ta+=("$(seconds "$run" "$3" --output "$work/a")")
    tb+=("$(seconds "$run" "$4" --output "$work/b")")
  done
  echo "$(echo "${ta[*]}" | median) $(echo "${tb[*]}" | median)"
}

# plot_accuracy_cost PNG TITLE YLABEL DATA: the error (column 3 of DATA)
# against the wall time (column 2) on log axes, each point labelled with
# its segments per beam (column 1) and DoFs (column 4).
plot_accuracy_cost() {
  gnuplot <<END
set terminal pngcairo size 640,440 font ",10"
set output "$1"
set title "$2"
set xlabel "wall time (s), one core, whole rodnet-run process"
set ylabel "$3"
set logscale xy
set format y "10^{%L}"
set grid
set key off
set offsets graph 0.05, graph 0.3, graph 0.1, graph 0.1
plot "$4" using 2:3 with linespoints pt 7 lw 1.5 lc rgb "#2ca02c", \
     "$4" using 2:3:(sprintf("%d per beam, %d DoFs", \$1, \$4)) \
       with labels left offset 1,0.6
END
}
