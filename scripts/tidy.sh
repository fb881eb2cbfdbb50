#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Runs clang-tidy with the checks of .clang-tidy (which the tree is kept clean of; any finding
# is an error) over the given .cpp files, or over every .cpp file of the repository that
# build/ compiles (so not fuzz/, built only by the sanitized build, nor bench/osmesa_bench.cpp
# without OSMesa), with the headers of the repository they include. Uses
# build/compile_commands.json (configured here when missing). Slow: each file compiles the
# CGAL headers it includes, one file per core at a time.
# Usage: scripts/tidy.sh [FILE.cpp...]
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh clang-tidy
if [[ ! -f build/compile_commands.json ]]; then
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DROOMCAD_WERROR=ON >/dev/null
fi
files=("$@")
if ((${#files[@]} == 0)); then
  mapfile -t files < <(git ls-files '*.cpp' |
    grep -Fxf <(sed -n "s|^ *\"file\": \"$(pwd)/\(.*\)\",\?$|\1|p" build/compile_commands.json))
fi
headers="^$(pwd)/[a-z_]+/"  # every header of the repository (modules, tests, bench)
printf '%s\n' "${files[@]}" |
  xargs -P "$(nproc)" -I{} clang-tidy -p build --quiet --header-filter="$headers" {} ||
  { echo "tidy: clang-tidy found problems (above)" >&2; exit 1; }
echo "tidy: ${#files[@]} files clean"
