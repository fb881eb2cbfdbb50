#!/usr/bin/env bash
# Builds roomcad and its tests with AddressSanitizer and UndefinedBehaviorSanitizer in
# build-asan/ and runs the whole CTest suite there. Any sanitizer report fails the test that
# made it (-fno-sanitize-recover=all; leaks are reported at exit). Prints the time it took.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
bash scripts/setup.sh
cmake -S . -B build-asan -DROOMCAD_SANITIZE=address,undefined -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DROOMCAD_BENCH=OFF >/dev/null
cmake --build build-asan -j"$(nproc)"
built=$SECONDS
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --test-dir build-asan --output-on-failure -j"$(nproc)" --timeout 1500
echo "test-sanitized: built in $((built - start)) s, tested in $((SECONDS - built)) s"
