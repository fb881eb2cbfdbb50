#!/usr/bin/env bash
# The main job on a bundled example: set up, build, validate the plan, describe it and render
# a picture of it (build/demo.png).
set -euo pipefail
cd "$(dirname "$0")/.."
plan=${1:-examples/house.json}
bash scripts/build.sh
./build/roomcad info "$plan"
./build/roomcad render "$plan" -o build/demo.png --width 1280 --height 720 --ssaa 2
echo "demo: wrote build/demo.png"
