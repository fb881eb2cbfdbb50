#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Optional check, not part of the test suite: are the Sweet Home 3D homes bundled in
# examples/sweethome3d/homes still byte-identical to the project's shared data set,
# ../shared/realdata/sweethome3d (its SHA256SUMS)? A clone has no such folder beside it: then
# the check says it skipped and exits 0. Exit 1 when a bundled home differs or is missing
# from SHA256SUMS, or a home listed there is not bundled.
# Usage: scripts/check-realdata.sh [REALDATA_DIR]   (default ../shared/realdata/sweethome3d)
set -euo pipefail
cd "$(dirname "$0")/.."
realdata=${1:-../shared/realdata/sweethome3d}
bundled=examples/sweethome3d/homes
sums=$realdata/SHA256SUMS
if [[ ! -f "$sums" ]]; then
  echo "check-realdata: SKIPPED: no $sums (nothing beside this clone to compare with)"
  exit 0
fi
declare -A expected
while read -r sum path; do
  [[ "$path" == *.Home.xml ]] && expected[$path]=$sum
done < "$sums"
failed=0 checked=0
for file in "$bundled"/*/*.Home.xml; do
  path=${file#"$bundled"/}
  actual=$(sha256sum "$file" | cut -d' ' -f1)
  if [[ -z "${expected[$path]:-}" ]]; then
    echo "check-realdata: $path is bundled but not listed in $sums" >&2; failed=1
  elif [[ "${expected[$path]}" != "$actual" ]]; then
    echo "check-realdata: $path differs from $realdata/$path" >&2; failed=1
  fi
  unset "expected[$path]"
  checked=$((checked + 1))
done
for path in "${!expected[@]}"; do
  echo "check-realdata: $path is listed in $sums but not bundled" >&2; failed=1
done
if ((failed)); then
  echo "check-realdata: FAILED" >&2
  exit 1
fi
echo "check-realdata: ok: the $checked bundled homes match $sums"
