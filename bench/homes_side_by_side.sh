#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Two builds of homes_bench (before and after a change) timed side by side on the automatic
# build of every home: for each home, ROUNDS rounds in which each binary builds it for SECONDS
# in one process (homes_bench's mean time per build), the two taking turns (which one goes
# first alternates), so that the machine's drift between minutes falls on both alike. Prints
# per home the best round of each binary and the median over rounds of after / before: quote
# the ratio; on a shared machine one process's times can sit 10-40% above another's.
#
# Usage: bench/homes_side_by_side.sh BEFORE_HOMES_BENCH AFTER_HOMES_BENCH [ROUNDS] [SECONDS]
#   e.g. (a homes_bench built at the commit before, copied aside):
#   bench/homes_side_by_side.sh /tmp/homes_bench.before build/bench/homes_bench 4 1
# Homes and threads are homes_bench's defaults (examples/sweethome3d/ and the tower, 2 threads).
set -euo pipefail
if (($# < 2)); then
  sed -n '2,/^set -euo/p' "$0" | sed '$d' | sed 's/^# \{0,1\}//'
  exit 2
fi
before=$1 after=$2 rounds=${3:-4} seconds=${4:-1}
for binary in "$before" "$after"; do
  [[ -x $binary ]] || { echo "homes_side_by_side: not an executable: $binary" >&2; exit 2; }
done

# The mean real time (ms) of the automatic build of one home, built for SECONDS.
json=$(mktemp)
trap 'rm -f "$json"' EXIT
mean_ms() {
  "$1" --benchmark_filter="^auto/$2/" --benchmark_min_time="$seconds" --benchmark_out="$json" \
    --benchmark_out_format=json >/dev/null 2>&1
  python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["benchmarks"][0]["real_time"])' "$json"
}

homes=$("$after" --benchmark_list_tests 2>/dev/null | sed -n 's|^auto/\([^/]*\)/.*|\1|p')
for home in $homes; do
  b=() a=()
  for ((r = 0; r < rounds; ++r)); do
    if ((r % 2 == 0)); then
      b+=("$(mean_ms "$before" "$home")") a+=("$(mean_ms "$after" "$home")")
    else
      a+=("$(mean_ms "$after" "$home")") b+=("$(mean_ms "$before" "$home")")
    fi
  done
  python3 - "$home" "${b[*]}" "${a[*]}" <<'EOF'
import statistics, sys
home, before, after = sys.argv[1], list(map(float, sys.argv[2].split())), list(map(float, sys.argv[3].split()))
ratios = [y / x for x, y in zip(before, after)]
print(f"{home}: {min(before):.2f} -> {min(after):.2f} ms, median ratio {statistics.median(ratios):.3f} "
      f"(rounds: {' '.join(f'{r:.2f}' for r in ratios)})")
EOF
done
