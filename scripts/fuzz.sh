#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Runs each libFuzzer target (fuzz/) for a bounded time, seeded from fuzz/corpus/<target>/.
# The targets are built in build-san/ by scripts/build-sanitized.sh (clang, ASan + UBSan),
# sharing the libraries' compile with scripts/test-sanitized.sh. Fails if any target finds a
# crash, sanitizer report, leak, timeout or out-of-memory; the input that did it is left in
# build-san/findings/<target>/. Runs as many targets at once as there are cores; prints each
# target's executions and peak RSS.
# Usage: scripts/fuzz.sh [SECONDS_PER_TARGET (default 60)] [TARGET...]
#
# Without TARGETs: every target, the readers' and fuzz_build and fuzz_render (degenerate plans
# through the build and the renderer; the inputs of the bugs they found are in
# fuzz/corpus/{build,render}/crash-*, docs/stress-findings.md says what they were). Their seed corpora
# also run in CTest (FuzzSeeds.*, RenderFuzzSeeds.*).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shift || true
bash scripts/build-sanitized.sh --target fuzzers
source scripts/sanitizer-env.sh

targets=("$@")
if ((${#targets[@]} == 0)); then
  for source in fuzz/fuzz_*.cpp; do targets+=("$(basename "$source" .cpp)"); done
fi
jobs=$(nproc)  # libFuzzer runs one thread: one target per core at a time

# Runs one target (arguments: its name), its log in build-san/<target>.log. @return its status.
run_target() {
  local target=$1 name=${1#fuzz_}
  local corpus=fuzz/corpus/$name findings=build-san/findings/$name
  local work=build-san/corpus/$name  # new inputs found go here, the committed corpus stays as is
  mkdir -p "$findings" "$work"
  local options=(-max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 -max_len=65536
                 -artifact_prefix="$findings/" -print_final_stats=1)
  [[ -f fuzz/$name.dict ]] && options+=(-dict="fuzz/$name.dict")
  "build-san/fuzz/$target" "${options[@]}" "$work" "$corpus" >"build-san/$target.log" 2>&1
}

echo "fuzz: ${#targets[@]} targets, ${seconds}s each, $jobs at a time"
declare -A pid_of
for target in "${targets[@]}"; do
  while (($(jobs -rp | wc -l) >= jobs)); do wait -n || true; done
  run_target "$target" &
  pid_of[$target]=$!
done
failed=()
for target in "${targets[@]}"; do  # in a fixed order, whichever finished first
  wait "${pid_of[$target]}" || { failed+=("$target"); tail -n 40 "build-san/$target.log" >&2; }
  echo "fuzz: $target"
  grep -h "stat::number_of_executed_units\|stat::peak_rss_mb" "build-san/$target.log" |
    sed "s/^/  /" || true
done
if ((${#failed[@]})); then
  echo "fuzz: FAILED: ${failed[*]} (inputs in build-san/findings/)" >&2
  exit 1
fi
echo "fuzz: ${#targets[@]} targets ran ${seconds}s each, nothing found"
