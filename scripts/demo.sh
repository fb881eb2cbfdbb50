#!/usr/bin/env bash
# The main job on a bundled example: set up, build, validate the plan and describe it.
set -euo pipefail
cd "$(dirname "$0")/.."
plan=${1:-examples/house.json}
bash scripts/build.sh
./build/roomcad info "$plan"
