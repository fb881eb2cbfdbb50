#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The modeling benchmark in one run: N x N grids of rooms (doors inside, windows outside) built
# by roomcad's fast path and CGAL path, and by the two outside references, plain CGAL Nef
# (balanced union, one batched subtraction) and Debian's openscad (only on grids up to
# --openscad-max-n, default 10: 10 x 10 takes about a minute). Writes a CSV and a Markdown
# table and prints the table.
#
#   bench/modeling_report.sh [BUILD_DIR] [OUT_PREFIX] [build_bench flags]
#     e.g. bench/modeling_report.sh build build/modeling --max-n 70 --cgal-max-n 10
#   -> OUT_PREFIX.csv, OUT_PREFIX.md (default build/modeling_report.*)
#
# CSV columns (stable; bench/report.md reads them), one row per scene, empty where a path
# did not run:
#   scene                 grid size, "NxN"
#   walls, openings       counts in the plan (2 N (N + 1) walls)
#   fast_ms, cgal_ms, nef_ms, openscad_ms
#                         wall time per build in ms: roomcad's fast path and --boolean cgal
#                         path (build the wall solid and write it as OFF), the plain Nef
#                         reference (build and convert), openscad (process run, -o out.off)
#   fast_triangles, cgal_triangles, nef_triangles, openscad_triangles
#                         triangles of the wall solid, each n-gon counted as n - 2
#   fast_volume_error, cgal_volume_error, nef_volume_error, openscad_volume_error
#                         |volume - analytic volume| / analytic volume
#   cgal_over_fast, nef_over_fast, openscad_over_fast
#                         time ratios to the fast path
#   fast_off_bytes        size of the fast path's OFF file
#   fast_build_ms         the fast path's build alone (fast_ms less the export and its fsync)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
prefix=${2:-$build/modeling_report}
shift $(( $# < 2 ? $# : 2 ))
command -v openscad >/dev/null || echo "modeling_report: openscad not installed: its columns stay empty" >&2
nice -n 10 cmake --build "$build" -j2 --target build_bench >/dev/null
"$build/bench/build_bench" --csv "$prefix.csv" --md "$prefix.md" "$@" >&2
cat "$prefix.md"
