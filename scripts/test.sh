#!/usr/bin/env bash
# Quick start 2: set up, build, and pass every test: the whole suite against
# deal.II's Release library, then all but the slow validation tests and
# seven slow tests (label "slow_sanitized", tests/CMakeLists.txt)
# against its Debug library (libdeal.ii.g.so), where deal.II's internal checks are
# active, built with AddressSanitizer and UndefinedBehaviorSanitizer.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
jobs=$(nproc)

# The options are given explicitly: scripts/run_default.sh configures the
# same build tree with the tests off, and a cached OFF would otherwise skip
# the whole suite. --no-tests=error makes an empty test run fail. The
# programs in bench/ are no tests and are left out (doc/performance.md
# builds them).
cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release \
  -DRODNET_BUILD_TESTS=ON -DRODNET_BUILD_VALIDATION_TESTS=ON \
  -DRODNET_BUILD_BENCHMARKS=OFF
cmake --build build/release -j "$jobs"
(cd build/release && ctest --output-on-failure --no-tests=error -j "$jobs")

# Debug library and AddressSanitizer + UndefinedBehaviorSanitizer at once.
bash scripts/sanitize.sh
