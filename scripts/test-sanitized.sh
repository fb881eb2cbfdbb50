#!/usr/bin/env bash
# Builds roomcad and its tests with AddressSanitizer and UndefinedBehaviorSanitizer (one build,
# GCC) in build-asan/ and runs CTest there. Any sanitizer report fails the test that made it
# (-fno-sanitize-recover=all; leaks are reported at exit). Prints the time it took.
#
# Built -O1 -g1 (line tables only, so reports still name file and line) without benchmarks or
# fuzzers: the build is most of the cost on CI's 2 cores, and -O1 keeps ASan's checks exact.
# Usage: scripts/test-sanitized.sh [CTEST_REGEX]   (default: every test)
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
bash scripts/setup.sh
cmake -S . -B build-asan -DROOMCAD_SANITIZE=address,undefined -DCMAKE_BUILD_TYPE=None \
  -DCMAKE_CXX_FLAGS="-O1 -g1" -DROOMCAD_BENCH=OFF -DROOMCAD_FUZZ=OFF >/dev/null
cmake --build build-asan -j"$(nproc)"
built=$SECONDS
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1:suppressions=$PWD/scripts/ubsan.supp
export LSAN_OPTIONS=suppressions=$PWD/scripts/lsan.supp
ctest --test-dir build-asan --output-on-failure -j"$(nproc)" --timeout 1500 ${1:+-R "$1"}
echo "test-sanitized: built in $((built - start)) s, tested in $((SECONDS - built)) s"
