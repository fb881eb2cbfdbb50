#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Regenerates examples/sweethome3d/*.json from the Sweet Home 3D homes bundled in
# examples/sweethome3d/homes (the eTeks example homes, the edge case and the community homes;
# THIRD_PARTY.md) with `roomcad import` (build first: scripts/build.sh).
# Warnings about approximations go to examples/sweethome3d/<Name>.import.txt.
set -euo pipefail
cd "$(dirname "$0")/.."
data=examples/sweethome3d/homes
out=examples/sweethome3d
roomcad=${ROOMCAD:-}
if [[ -z "$roomcad" ]]; then
  for candidate in ./build/roomcad ./build/cli/roomcad; do
    [[ -x "$candidate" ]] && roomcad=$candidate && break
  done
fi
[[ -n "$roomcad" ]] || { echo "import-sweethome3d: build roomcad first (scripts/build.sh)" >&2; exit 2; }
for home in "$data"/eteks-example-homes/*.Home.xml "$data"/edge-cases/*.Home.xml "$data"/community-homes/*.Home.xml; do
  name=$(basename "$home" .Home.xml)
  "$roomcad" import "$home" -o "$out/$name.json" 2> "$out/$name.import.txt"
  echo "$name: $(grep -c 'warning' "$out/$name.import.txt" || true) import warnings"
done
