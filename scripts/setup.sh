#!/usr/bin/env bash
# Installs, from Debian's packages, whatever roomcad needs that this machine lacks (toolchain
# included). Idempotent and non-interactive: packages already installed are left alone, and
# nothing is fetched when nothing is missing. Run as root, or as a user with sudo.
# Usage: scripts/setup.sh [EXTRA_PACKAGE...]   (e.g. the sanitized build's clang)
set -euo pipefail

packages=(
  # toolchain
  g++ make cmake pkg-config
  # geometry, meshes, maths
  libcgal-dev libgmp-dev libmpfr-dev libboost-dev libopenmesh-dev libglm-dev libeigen3-dev
  # formats, command line, threads, images, windows, archives
  nlohmann-json3-dev libsimdjson-dev libcli11-dev libfmt-dev libpng-dev libtbb-dev libsdl2-dev libzip-dev libpugixml-dev
  # tests and benchmarks (Xvfb: a screen for the window tests of `roomcad view`; gnuplot draws
  # bench/report.sh's plots; admesh: an independent STL reader for the export tests)
  libgtest-dev libgmock-dev libbenchmark-dev xvfb xauth gnuplot-nox admesh
  "$@"
)

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done

if ((${#missing[@]} == 0)); then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi

sudo=()
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "setup: need root (or sudo) to install: ${missing[*]}" >&2; exit 2; }
  sudo=(sudo)
fi
echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
"${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
