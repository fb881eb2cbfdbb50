#!/usr/bin/env bash
# Regenerates examples/sweethome3d/*.json from the Sweet Home 3D homes in
# ../shared/realdata/sweethome3d with `roomcad import` (build first: scripts/build.sh).
# Warnings about approximations go to examples/sweethome3d/<Name>.import.txt.
set -euo pipefail
cd "$(dirname "$0")/.."
data=../shared/realdata/sweethome3d
out=examples/sweethome3d
roomcad=${ROOMCAD:-}
if [[ -z "$roomcad" ]]; then
  for candidate in ./build/roomcad ./build/cli/roomcad; do
    [[ -x "$candidate" ]] && roomcad=$candidate && break
  done
fi
[[ -n "$roomcad" ]] || { echo "import-sweethome3d: build roomcad first (scripts/build.sh)" >&2; exit 2; }
for home in "$data"/eteks-example-homes/*.Home.xml "$data"/edge-cases/*.Home.xml; do
  name=$(basename "$home" .Home.xml)
  "$roomcad" import "$home" -o "$out/$name.json" 2> "$out/$name.import.txt"
  echo "$name: $(grep -c 'warning' "$out/$name.import.txt" || true) import warnings"
done
