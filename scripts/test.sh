#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds everything (roomcad, the tests, the benchmarks; warnings are errors) and runs the
# tests through CTest. Extra arguments go to ctest: `scripts/test.sh -L fast` runs the tests
# labelled fast only (the labels: docs/testing.md).
# Usage: scripts/test.sh [CTEST_ARGS...]
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j"$(nproc)" "$@"
