#!/usr/bin/env bash
# Fuzzes the input readers with libFuzzer (clang, AddressSanitizer and
# UndefinedBehaviorSanitizer), one target after the other, each for SECONDS
# (default 600) at nice 19, then merges what it grew into the corpus
# tests/input/fuzz/<target>/, minimized: only inputs that add coverage stay.
# A finding stops the script; its input is in build/fuzz/artifacts/<target>/.
#
#   bash scripts/fuzz.sh [SECONDS [TARGET...]]
#   targets: scene network_file gmsh_network gmsh_rods (default: all)
#
# See doc/sanitizers_and_fuzzing.md.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh clang-14 libclang-rt-14-dev
seconds=${1:-600}
targets=("${@:2}")
[ ${#targets[@]} -gt 0 ] || targets=(scene network_file gmsh_network gmsh_rods)

cmake -S . -B build/fuzz -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_COMPILER=clang++-14 -DRODNET_BUILD_TESTS=OFF \
  -DRODNET_BUILD_BENCHMARKS=OFF -DRODNET_SANITIZE=address,undefined \
  -DRODNET_BUILD_FUZZERS=ON
# The linker warns about every local symbol of the ASan runtime: to a log.
cmake --build build/fuzz -j "$(nproc)" --target "${targets[@]/#/fuzz_}" \
  > build/fuzz/build.log 2>&1 || { tail -n 40 build/fuzz/build.log; exit 1; }

supp=$PWD/cmake/sanitizers
export ASAN_OPTIONS=detect_leaks=1:strict_string_checks=1
export LSAN_OPTIONS=suppressions=$supp/lsan.supp:print_suppressions=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1:suppressions=$supp/ubsan.supp

# The repository's inputs of each target, and its dictionary.
seeds() {
  case $1 in
    scene) ls scenes/*.prm ;;
    network_file) ls tests/input/data/*.net ;;
    gmsh_*) ls tests/input/data/*.msh ;;
  esac
}
dictionary() {
  case $1 in
    gmsh_*) echo fuzz/gmsh.dict ;;
    *) echo "fuzz/$1.dict" ;;
  esac
}

for t in "${targets[@]}"; do
  fuzzer=build/fuzz/fuzz/fuzz_$t
  grown=build/fuzz/grown/$t seed=build/fuzz/seeds/$t
  artifacts=build/fuzz/artifacts/$t/ corpus=tests/input/fuzz/$t
  log=build/fuzz/$t.log
  mkdir -p "$grown" "$seed" "$artifacts" "$corpus"
  cp $(seeds "$t") "$seed/"
  echo "fuzz: $t for $seconds s (log $log)"
  # -timeout (wall clock): an input that takes 60 s is a hang; at nice 19
  # on a busy machine a unit of 1 s CPU can take 10 s. -rss_limit_mb: memory.
  if ! nice -n 19 "$fuzzer" -max_total_time="$seconds" -timeout=60 \
      -rss_limit_mb=2048 -max_len=4096 -dict="$(dictionary "$t")" \
      -print_final_stats=1 -artifact_prefix="$artifacts" \
      "$grown" "$corpus" "$seed" > "$log" 2>&1; then
    tail -n 40 "$log"
    echo "fuzz: $t found something: the input is in $artifacts" >&2
    exit 1
  fi
  grep -E "^#[0-9]+ +DONE|^stat::" "$log"
  # Minimize: a fresh directory gets the inputs that add coverage.
  merged=build/fuzz/merged/$t
  rm -rf "$merged" && mkdir -p "$merged"
  nice -n 19 "$fuzzer" -merge=1 "$merged" "$corpus" "$grown" "$seed" \
    > "build/fuzz/$t.merge.log" 2>&1
  rm -rf "$corpus" && mv "$merged" "$corpus"
  echo "fuzz: $t corpus: $(ls "$corpus" | wc -l) files"
done
