#!/usr/bin/env bash
# Quick start 1: set up, build Release and run the default scene (the
# elastica). Prints where the outputs are.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release -DRODNET_BUILD_TESTS=OFF > build.log
cmake --build build/release --target rodnet-run -j "$(nproc)" >> build.log
./build/release/rodnet-run scenes/elastica.prm --output output/elastica
