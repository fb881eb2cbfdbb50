#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Start-up as a user meets it: the wall time of whole roomcad processes (median of RUNS), beside
# a C++ hello world compiled and run in the same run, on the bundled Studio home.
# Usage: bench/startup_bench.sh [BUILD_DIR] [RUNS]   (default build, 21)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
runs=${2:-21}
roomcad=$build/roomcad
[[ -x $roomcad ]] || { echo "startup_bench: no $roomcad (bash scripts/build.sh roomcad)" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf '#include <cstdio>\nint main() { std::puts("hello"); }\n' > "$work/hello.cpp"
c++ -O2 "$work/hello.cpp" -o "$work/hello"
studio=examples/sweethome3d/Studio.json

source bench/median_ms.sh

echo "| command | median wall ms ($runs runs) |"
echo "| --- | --- |"
echo "| hello world (C++) | $(median_ms "$work/hello") |"
echo "| roomcad --version | $(median_ms "$roomcad" --version) |"
echo "| roomcad validate Studio.json | $(median_ms "$roomcad" validate "$studio") |"
echo "| roomcad build Studio.json -o x.obj | $(median_ms "$roomcad" build "$studio" -o "$work/x.obj") |"
