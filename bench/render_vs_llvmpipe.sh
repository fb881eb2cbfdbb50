#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Runs the render benchmark and the OSMesa/llvmpipe harness side by side, size by size, and
# prints one CSV table of frame times at 1920 x 1080 in ms. The *_cpu columns run both sides
# single-threaded (LP_NUM_THREADS=0 makes llvmpipe rasterise in the calling thread; roomcad
# --threads 1) and compare CPU time, which a busy machine disturbs far less than wall time; the
# *_2t_wall columns are wall times with 2 threads (llvmpipe: its default, all cores), meaningful
# only on an idle machine.
#
# Output (stable; columns are only ever appended): one header line, then per size
#   rooms,triangles,llvmpipe_cpu,pcf_cpu,pcf/llvmpipe,noshadow_cpu,llvmpipe_2t_wall,
#   pcf_2t_wall,noshadow_2t_wall,hard_cpu,hard_2t_wall
# Each time is the minimum over REPS repetitions (default 3) of Google Benchmark's per-frame
# mean. RENDER_BENCH=path measures another render_bench binary (an older build, say).
# Usage: bash bench/render_vs_llvmpipe.sh [BUILD_DIR] [ROOMS_PER_SIDE...]
set -euo pipefail
build=${1:-build}
shift || true
sizes=("$@")
((${#sizes[@]})) || sizes=(2 10 25 50 82)
ours=${RENDER_BENCH:-"$build/bench/render_bench"}
theirs="$build/bench/osmesa_bench"
reps=${REPS:-3}
[[ -x "$ours" && -x "$theirs" ]] || { echo "build render_bench and osmesa_bench first" >&2; exit 2; }
# One benchmark as "real_ms cpu_ms triangles", each time the minimum over the repetitions
# (google-benchmark CSV; aggregate rows skipped).
measure() {
  "$@" --benchmark_format=csv --benchmark_repetitions="$reps" 2>/dev/null | awk -F, '
    NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "\"triangles\"") t = i }
    $1 ~ /BM_/ && $1 !~ /_(mean|median|stddev|cv)"$/ {
      if (n == 0 || $3 < real) real = $3
      if (n == 0 || $4 < cpu) cpu = $4
      tris = $t; ++n
    }
    END { printf "%s %s %d\n", real, cpu, tris }'
}
echo "rooms,triangles,llvmpipe_cpu,pcf_cpu,pcf/llvmpipe,noshadow_cpu,llvmpipe_2t_wall,pcf_2t_wall,noshadow_2t_wall,hard_cpu,hard_2t_wall"
for n in "${sizes[@]}"; do
  read -r _ llvm_cpu tris < <(LP_NUM_THREADS=0 measure "$theirs" --benchmark_filter="BM_LlvmpipeFrame1080p/$n/")
  read -r _ pcf_cpu _ < <(measure "$ours" --benchmark_filter="BM_Frame1080p/$n/1/1/")
  read -r _ plain_cpu _ < <(measure "$ours" --benchmark_filter="BM_Frame1080p/$n/0/1/")
  read -r _ hard_cpu _ < <(measure "$ours" --benchmark_filter="BM_Frame1080p/$n/2/1/")
  read -r llvm_wall _ _ < <(measure "$theirs" --benchmark_filter="BM_LlvmpipeFrame1080p/$n/")
  read -r pcf_wall _ _ < <(measure "$ours" --benchmark_filter="BM_Frame1080p/$n/1/2/")
  read -r plain_wall _ _ < <(measure "$ours" --benchmark_filter="BM_Frame1080p/$n/0/2/")
  read -r hard_wall _ _ < <(measure "$ours" --benchmark_filter="BM_Frame1080p/$n/2/2/")
  ratio=$(awk -v a="$pcf_cpu" -v b="$llvm_cpu" 'BEGIN { printf "%.2f", a / b }')
  printf '%s,%s,%.1f,%.1f,%s,%.1f,%.1f,%.1f,%.1f,%.1f,%.1f\n' "$n" "$tris" "$llvm_cpu" "$pcf_cpu" \
    "$ratio" "$plain_cpu" "$llvm_wall" "$pcf_wall" "$plain_wall" "$hard_cpu" "$hard_wall"
done
