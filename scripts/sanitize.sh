#!/usr/bin/env bash
# The Debug build with AddressSanitizer and UndefinedBehaviorSanitizer
# (gcc, against deal.II's Debug library libdeal.ii.g.so, whose internal
# checks are active too), and every test but the slow validation runs and
# seven slow tests (label "debug"; those seven: ctest -L slow_sanitized).
# Any sanitizer finding fails its test: UBSan stops at the
# first, ASan at the first error and LeakSanitizer at exit. Third-party
# leaks are suppressed in cmake/sanitizers/ (doc/sanitizers_and_fuzzing.md).
# Debugging information: line tables only, which the sanitizers' stack
# traces need; reconfigure with -DRODNET_DEBUG_INFO=full to debug in gdb.
# scripts/test.sh runs this after the Release suite.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
jobs=$(nproc)

cmake -S . -B build/debug -DCMAKE_BUILD_TYPE=Debug \
  -DRODNET_BUILD_TESTS=ON -DRODNET_BUILD_BENCHMARKS=OFF \
  -DRODNET_BUILD_VALIDATION_TESTS=OFF \
  -DRODNET_SANITIZE=address,undefined -DRODNET_DEBUG_INFO=lines
cmake --build build/debug -j "$jobs"
(cd build/debug && ctest --output-on-failure --no-tests=error -j "$jobs" -L debug)
