#!/usr/bin/env bash
# Runs the whole test suite built with AddressSanitizer and UndefinedBehaviorSanitizer (clang,
# -O1, build-san/, built by scripts/build-sanitized.sh, shared with scripts/fuzz.sh) through
# CTest. Any sanitizer report fails the test that made it. Prints the time each half took.
#
# The random-plan stress tests run ROOMCAD_STRESS_PLANS plans (default here 100, the normal
# suite's 1000 take over 20 min under ASan); each prints the count it used.
# Usage: scripts/test-sanitized.sh [CTEST_REGEX]   (default: every test)
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
bash scripts/build-sanitized.sh
built=$SECONDS
source scripts/sanitizer-env.sh
export ROOMCAD_STRESS_PLANS=${ROOMCAD_STRESS_PLANS:-100}
echo "test-sanitized: ROOMCAD_STRESS_PLANS=$ROOMCAD_STRESS_PLANS"
ctest --test-dir build-san --output-on-failure -j"$(nproc)" --timeout 1500 ${1:+-R "$1"}
echo "test-sanitized: built in $((built - start)) s, tested in $((SECONDS - built)) s"
