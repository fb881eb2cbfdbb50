#!/usr/bin/env bash
# Times Debian's openscad on the benchmark's grids of rooms (the same scenes as build_bench):
# writes each grid as .scad (build_bench --scad) and times `openscad -o out.off`, capped.
#   bench/openscad_reference.sh [BUILD_DIR] [SIZES...]      e.g. build 2 5 10
set -euo pipefail
build=${1:-build}
shift || true
sizes=("${@:-2 5 10}")
cap=${OPENSCAD_TIMEOUT:-300}
command -v openscad >/dev/null || { echo "openscad not installed (apt-get install openscad)" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "| grid | openscad s | faces |"
echo "|---|---|---|"
for n in ${sizes[@]}; do
  "$build/bench/build_bench" --scad "$n" "$tmp/grid.scad"
  start=$(date +%s.%N)
  if timeout "$cap" openscad -o "$tmp/out.off" "$tmp/grid.scad" >/dev/null 2>&1; then
    end=$(date +%s.%N)
    # OpenSCAD writes "OFF V F E" on one line; its faces are triangles.
    faces=$(awk 'NR == 1 { if (NF >= 3) { print $3 } else { getline; print $2 } }' "$tmp/out.off")
    printf "| %sx%s | %.1f | %s |\n" "$n" "$n" "$(echo "$end - $start" | bc)" "$faces"
  else
    printf "| %sx%s | > %s (timed out) | - |\n" "$n" "$n" "$cap"
  fi
done
