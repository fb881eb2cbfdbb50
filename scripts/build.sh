#!/usr/bin/env bash
# Configures and builds roomcad (Release, warnings as errors: ROOMCAD_WERROR) in build/, using
# every core: the given targets, or everything (roomcad, the tests, the benchmarks) when none
# is given. The README's two commands share this one build.
# Usage: scripts/build.sh [TARGET...]   (e.g. scripts/build.sh roomcad)
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DROOMCAD_WERROR=ON
targets=()
for target in "$@"; do targets+=(--target "$target"); done
cmake --build build -j"$(nproc)" "${targets[@]}"
