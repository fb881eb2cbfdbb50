#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/) with clang in build-fuzz/ and runs each for a bounded
# time, seeded from fuzz/corpus/<target>/. Fails if any target finds a crash, leak, timeout or
# out-of-memory; the input that did it is left in build-fuzz/findings/<target>/.
# Usage: scripts/fuzz.sh [SECONDS_PER_TARGET (default 60)] [TARGET...]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shift || true

# clang and its runtime (libFuzzer, sanitizers) are needed here only, not by the normal build.
fuzz_packages=(clang libclang-rt-14-dev)
missing=()
for p in "${fuzz_packages[@]}"; do
  [[ $(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true) == "install ok installed" ]] ||
    missing+=("$p")
done
if ((${#missing[@]})); then
  sudo=(); [[ $(id -u) -eq 0 ]] || sudo=(sudo)
  export DEBIAN_FRONTEND=noninteractive
  "${sudo[@]}" apt-get update -qq
  "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
bash scripts/setup.sh

cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DROOMCAD_FUZZ=ON -DBUILD_TESTING=OFF -DROOMCAD_BENCH=OFF >/dev/null
cmake --build build-fuzz -j"$(nproc)" --target fuzzers

targets=("$@")
if ((${#targets[@]} == 0)); then
  for source in fuzz/fuzz_*.cpp; do targets+=("$(basename "$source" .cpp)"); done
fi
failed=()
for target in "${targets[@]}"; do
  name=${target#fuzz_}
  corpus=fuzz/corpus/$name
  findings=build-fuzz/findings/$name
  work=build-fuzz/corpus/$name  # new inputs found go here, the committed corpus stays as is
  mkdir -p "$findings" "$work"
  options=(-max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 -max_len=65536
           -artifact_prefix="$findings/" -print_final_stats=1)
  [[ -f fuzz/$name.dict ]] && options+=(-dict="fuzz/$name.dict")
  echo "fuzz: $target for ${seconds}s"
  if ! "build-fuzz/fuzz/$target" "${options[@]}" "$work" "$corpus" \
       >"build-fuzz/$target.log" 2>&1; then
    failed+=("$target")
    tail -n 40 "build-fuzz/$target.log" >&2
  fi
  grep -h "stat::number_of_executed_units\|stat::peak_rss_mb" "build-fuzz/$target.log" |
    sed "s/^/  /" || true
done
if ((${#failed[@]})); then
  echo "fuzz: FAILED: ${failed[*]} (inputs in build-fuzz/findings/)" >&2
  exit 1
fi
echo "fuzz: ${#targets[@]} targets ran ${seconds}s each, nothing found"
