#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# IFC import as a user runs it, beside web-ifc: the wall time (median of RUNS whole processes)
# of `roomcad import MODEL.ifc -o plan.json` followed by `roomcad validate plan.json`, and of
# web-ifc opening the same file and making every product's mesh (node
# tests/readers/ifc_check.cjs, which also sums the meshes' volumes), on each bundled IFC model,
# largest first.
# Usage: bench/ifc_import_bench.sh [BUILD_DIR] [RUNS]   (default build, 5; web-ifc is installed
# by scripts/setup.sh --tests)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
runs=${2:-5}
roomcad=$build/roomcad
[[ -x $roomcad ]] || { echo "ifc_import_bench: no $roomcad (bash scripts/build.sh roomcad)" >&2; exit 2; }
[[ -d tests/readers/node_modules/web-ifc ]] ||
  { echo "ifc_import_bench: no web-ifc (bash scripts/setup.sh --tests)" >&2; exit 2; }
source bench/median_ms.sh
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

echo "| model | size kB | roomcad import + validate, ms | web-ifc open + meshes, ms | ratio |"
echo "| --- | --- | --- | --- | --- |"
for model in $(ls -S examples/ifc/*.ifc); do
  ours=$(median_ms bash -c "'$roomcad' import '$model' -o '$work/plan.json' && '$roomcad' validate '$work/plan.json'")
  theirs=$(median_ms node tests/readers/ifc_check.cjs "$model")
  echo "| $(basename "$model") | $(( $(stat -c %s "$model") / 1024 )) | $ours | $theirs | $(awk -v a="$ours" -v b="$theirs" 'BEGIN {printf "%.2f", a / b}') |"
done
