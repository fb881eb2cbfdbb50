#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The lost-edit experiment (issue #17): SHELLS shells at once, each running K
# `roomcad add PLAN wall --id ...` one after the other on the same plan. At the end every
# command that exited 0 must have its wall in the file; one that is missing is a lost edit (the
# command said it was done, and it is not). Run it against two builds to compare them:
#
#   scripts/lost-edits.sh build-old/roomcad 30 2
#   scripts/lost-edits.sh build/roomcad 30 2
#
# Usage: scripts/lost-edits.sh [ROOMCAD] [K] [SHELLS]   (defaults: build/roomcad 30 2)
# Prints one line: commands, exited 0, failed, walls in the file, lost. Exits 1 if any was lost.
set -euo pipefail
roomcad=$(realpath "${1:-build/roomcad}")
k=${2:-30}
shells=${3:-2}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
plan=$dir/plan.json

# Shell s adds its walls along the row y = 1 + 2s, one metre long and half a metre apart, so
# every add is valid in any order and each wall is told apart by its id.
width=$((3 * k / 2 + 3))
height=$((2 * shells + 2))
cat >"$plan" <<EOF
{ "format": "roomcad-plan", "version": 1, "units": "m",
  "site": { "origin": [0, 0], "cells": [$width, $height], "cell_size": 1.0 } }
EOF

add_walls() {  # shell number: K adds, the exit status of each in $dir/codes-<s>
  local s=$1 y=$((1 + 2 * $1)) i x
  for ((i = 0; i < k; i++)); do
    x=$(awk -v i="$i" 'BEGIN { print 1 + 1.5 * i }')
    if "$roomcad" add "$plan" wall --id "s$s-w$i" --from "$x,$y" --to "$(awk -v x="$x" 'BEGIN { print x + 1 }'),$y" \
        --thickness 0.1 >/dev/null 2>>"$dir/stderr-$s"; then
      echo "s$s-w$i 0" >>"$dir/codes-$s"
    else
      echo "s$s-w$i $?" >>"$dir/codes-$s"
    fi
  done
}

start=$SECONDS
for ((s = 0; s < shells; s++)); do add_walls "$s" & done
wait
seconds=$((SECONDS - start))

commands=0 ok=0 failed=0 lost=0
while read -r id status; do
  commands=$((commands + 1))
  if [[ $status == 0 ]]; then
    ok=$((ok + 1))
    grep -q "\"id\": \"$id\"" "$plan" || lost=$((lost + 1))
  else
    failed=$((failed + 1))
  fi
done < <(cat "$dir"/codes-*)
walls=$(grep -c '"id": "s[0-9]*-w[0-9]*"' "$plan" || true)
echo "lost-edits: $roomcad: $shells shells x $k adds = $commands commands in ${seconds} s;" \
     "exited 0: $ok, failed: $failed; walls in the file: $walls; lost: $lost"
if ((failed > 0)); then
  echo "lost-edits: what the failed commands said (first 5 lines):"
  cat "$dir"/stderr-* | head -5
fi
((lost == 0))
