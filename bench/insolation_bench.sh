#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Insolation as a user runs it: the wall time of `roomcad insolation` for one day (median of
# RUNS whole processes: reading, validating, building the solid, the sun and the rays) at 1
# and 2 threads, on the largest bundled home (arif-putra-pertama-1: 17 levels, 109 openings,
# its Sweet Home 3D compass in Jakarta) and on the 4-bedroom house (Paris); and `roomcad sun`.
# Usage: bench/insolation_bench.sh [BUILD_DIR] [RUNS]   (default build, 11)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
runs=${2:-11}
roomcad=$build/roomcad
[[ -x $roomcad ]] || { echo "insolation_bench: no $roomcad (bash scripts/build.sh roomcad)" >&2; exit 2; }
source bench/median_ms.sh

echo "| command | threads | median wall ms ($runs runs) |"
echo "| --- | --- | --- |"
for home in arif-putra-pertama-1 4-BedroomHouse; do
  plan=examples/sweethome3d/$home.json
  for threads in 1 2; do
    echo "| insolation $home --date 2026-03-21 | $threads | $(median_ms "$roomcad" insolation "$plan" --date 2026-03-21 --force --threads "$threads") |"
  done
done
echo "| sun --latitude 55.75 --longitude 37.62 --at 2026-04-22T14:30 | 1 | $(median_ms "$roomcad" sun --latitude 55.75 --longitude 37.62 --at 2026-04-22T14:30) |"
