#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The main job on a bundled example: set up, build the roomcad executables (roomcad and the
# window it runs for `roomcad view`, roomcad-view; no tests, no benchmarks), then validate the plan, describe it, build and check its 3D model
# (build/demo.obj), render a picture (build/demo.png) and draw its floor plan
# (build/demo-plan.svg). Prints how long the build and the run took.
# Usage: scripts/demo.sh [PLAN]   (default examples/house.json)
set -euo pipefail
cd "$(dirname "$0")/.."
plan=${1:-examples/house.json}
start=$SECONDS
bash scripts/build.sh roomcad roomcad-view
built=$SECONDS
roomcad=./build/roomcad
"$roomcad" validate "$plan"
"$roomcad" info "$plan"
"$roomcad" build "$plan" -o build/demo.obj --check
"$roomcad" render "$plan" -o build/demo.png --width 1280 --height 720 --ssaa 2
"$roomcad" draw "$plan" --view plan --scale 1:100 -o build/demo-plan.svg
echo "demo: wrote build/demo.obj (+ .mtl), build/demo.png and build/demo-plan.svg"
echo "demo: set up and built in $((built - start)) s, ran in $((SECONDS - built)) s"
