# SPDX-License-Identifier: GPL-3.0-or-later
# Sourced by the bench scripts that time whole processes.
# median_ms COMMAND...: prints the median wall milliseconds of $runs runs of the command, after
# one run not counted (it warms the page cache).
median_ms() {
  "$@" > /dev/null 2>&1 || true
  local times=()
  for ((i = 0; i < runs; i++)); do
    local start=${EPOCHREALTIME/[.,]/}  # microseconds, read without starting a process
    "$@" > /dev/null 2>&1 || true
    local end=${EPOCHREALTIME/[.,]/}
    times+=($((end - start)))
  done
  printf '%s\n' "${times[@]}" | sort -n | awk '{t[NR] = $1} END {printf "%.1f", t[int((NR + 1) / 2)] / 1000}'
}
