#!/usr/bin/env bash
# The main job on a bundled example: set up, build, validate the plan, describe it, and build
# its 3D model (written to build/<plan>.obj with its .mtl, the wall solid checked).
set -euo pipefail
cd "$(dirname "$0")/.."
plan=${1:-examples/house.json}
bash scripts/build.sh
./build/roomcad info "$plan"
./build/roomcad build "$plan" -o "build/$(basename "$plan" .json).obj" --check --stats
