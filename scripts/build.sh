#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Configures and builds roomcad (Release, warnings as errors: ROOMCAD_WERROR) in build/, using
# every core: the given targets, or everything (roomcad, the tests, the benchmarks) when none
# is given. The README's two commands share this one build.
# Usage: scripts/build.sh [TARGET...]   (e.g. scripts/build.sh roomcad)
set -euo pipefail
cd "$(dirname "$0")/.."
# Everything includes the tests, so their independent readers too (setup.sh --tests).
if (($# == 0)); then bash scripts/setup.sh --tests; else bash scripts/setup.sh; fi
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DROOMCAD_WERROR=ON
targets=()
for target in "$@"; do targets+=(--target "$target"); done
cmake --build build -j"$(nproc)" "${targets[@]}"
