#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds roomcad, its tests and its libFuzzer targets once, in build-san/, with clang and
# AddressSanitizer + UndefinedBehaviorSanitizer; every library also carries libFuzzer's
# coverage hooks, so scripts/test-sanitized.sh and scripts/fuzz.sh share one compile of the
# modules (the CGAL translation units are most of the cost). No benchmarks.
#
# -O1 keeps ASan's checks exact and the build short; -gline-tables-only keeps file and line in
# every report. clang rather than GCC because libFuzzer needs it, and it is the faster of the
# two here (bench/report.md gives both measured times). Warnings are errors here too
# (ROOMCAD_WERROR): clang warns where GCC does not.
# Usage: scripts/build-sanitized.sh [CMAKE_BUILD_ARGS...]   (e.g. --target fuzzers)
set -euo pipefail
cd "$(dirname "$0")/.."
# clang and its runtime (libFuzzer, sanitizers) are needed here only, not by the normal build.
# No Python module: a sanitized shared object loads only into a Python started with the
# sanitizer runtime preloaded.
bash scripts/setup.sh clang libclang-rt-14-dev
cmake -S . -B build-san -DCMAKE_CXX_COMPILER=clang++ -DROOMCAD_FUZZ=ON -DCMAKE_BUILD_TYPE=None \
  -DCMAKE_CXX_FLAGS="-O1 -gline-tables-only" -DROOMCAD_BENCH=OFF -DROOMCAD_WERROR=ON \
  -DROOMCAD_PYTHON=OFF >/dev/null
cmake --build build-san -j"$(nproc)" "$@"
