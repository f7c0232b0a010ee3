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
