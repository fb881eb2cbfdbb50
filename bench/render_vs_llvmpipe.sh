#!/usr/bin/env bash
# Runs the render benchmark and the OSMesa/llvmpipe harness side by side, size by size, and
# prints one table of frame times at 1920 x 1080 in ms. Both sides run single-threaded
# (LP_NUM_THREADS=0 makes llvmpipe rasterise in the calling thread; roomcad --threads 1) and are
# compared on CPU time, which a busy machine disturbs far less than wall time; the 2-thread
# columns are wall times, meaningful only on an idle machine.
# Usage: bash bench/render_vs_llvmpipe.sh [BUILD_DIR] [ROOMS_PER_SIDE...]
set -euo pipefail
build=${1:-build}
shift || true
sizes=("$@")
((${#sizes[@]})) || sizes=(2 10 25 50 82)
ours="$build/bench/render_bench"
theirs="$build/bench/osmesa_bench"
[[ -x "$ours" && -x "$theirs" ]] || { echo "build render_bench and osmesa_bench first" >&2; exit 2; }
# One benchmark row as "real_ms cpu_ms triangles" (google-benchmark CSV).
measure() {
  "$@" --benchmark_format=csv 2>/dev/null | awk -F, '
    NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "\"triangles\"") t = i }
    $1 ~ /BM_/ { printf "%s %s %d\n", $3, $4, $t }'
}
echo "rooms,triangles,llvmpipe_cpu,pcf_cpu,pcf/llvmpipe,noshadow_cpu,llvmpipe_2t_wall,pcf_2t_wall,noshadow_2t_wall"
for n in "${sizes[@]}"; do
  read -r _ llvm_cpu tris < <(LP_NUM_THREADS=0 measure "$theirs" --benchmark_filter="BM_LlvmpipeFrame1080p/$n/")
  read -r _ pcf_cpu _ < <(measure "$ours" --benchmark_filter="BM_Frame1080p/$n/1/1/")
  read -r _ plain_cpu _ < <(measure "$ours" --benchmark_filter="BM_Frame1080p/$n/0/1/")
  read -r llvm_wall _ _ < <(measure "$theirs" --benchmark_filter="BM_LlvmpipeFrame1080p/$n/")
  read -r pcf_wall _ _ < <(measure "$ours" --benchmark_filter="BM_Frame1080p/$n/1/2/")
  read -r plain_wall _ _ < <(measure "$ours" --benchmark_filter="BM_Frame1080p/$n/0/2/")
  ratio=$(awk -v a="$pcf_cpu" -v b="$llvm_cpu" 'BEGIN { printf "%.2f", a / b }')
  printf '%s,%s,%.1f,%.1f,%s,%.1f,%.1f,%.1f,%.1f\n' "$n" "$tris" "$llvm_cpu" "$pcf_cpu" "$ratio" \
    "$plain_cpu" "$llvm_wall" "$pcf_wall" "$plain_wall"
done
